/* The conventional (Whitted) shadow test: a shadow ray from the shading
 * point toward the light, walked cell by cell through the grid, stopped by
 * the first opaque polygon. Transparent polygons on the way filter the light
 * (POV-Ray multiplies rgb*filter + transmit of each), in any order. */
#include "shadow.h"

#include "intersect.h"
#include "pigment.h"
#include "shadow_volumes.h"

/* Folds one blocker, hit at `at`, into the light that gets through; returns
 * 1 when the light is now fully blocked. */
static int pass_through(const World *w, const Material *m, int polygon, const ShadowQuery *q, double t, RGB *light)
{
    Colour here = m->opaque ? m->pigment
                            : material_colour_at(w, m, polygon, v3_add(q->point, v3_scale(q->to_light, t)));
    if (m->opaque || (here.filter == 0.0 && here.transmit == 0.0)) {
        light->r = light->g = light->b = 0.0;
        return 1;
    }
    const Colour *c = &here;
    light->r *= c->r * c->filter + c->transmit;
    light->g *= c->g * c->filter + c->transmit;
    light->b *= c->b * c->filter + c->transmit;
    return 0;
}

int shadow_planes_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    const World *w = ctx->tracer.world;
    double tmin = trace_min_distance(q->point);
    for (int i = 0; i < w->nplanes; i++) {
        if (q->surface->kind == HIT_PLANE && q->surface->index == i)
            continue;
        const InfinitePlane *pl = &w->planes[i];
        if (w->materials[pl->material].no_shadow)
            continue;
        double t = intersect_plane(pl, q->point, q->to_light);
        if (t > tmin && t < q->distance && pass_through(w, &w->materials[pl->material], -1, q, t, light))
            return 1;
    }
    return 0;
}

int shadow_polygons_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    const World *w = ctx->tracer.world;
    const Grid *g = ctx->tracer.grid;
    ctx->stats.shadow_rays++;
    double tmin = trace_min_distance(q->point);
    double tmax = q->distance;
    GridWalk walk;
    if (w->npolygons == 0 || !grid_walk_begin(g, q->point, q->to_light, 0.0, tmax, &walk))
        return 0;
    uint32_t id = trace_new_segment(&ctx->tracer);
    RayFrame frame = ray_frame(q->point, q->to_light);
    if (q->surface->kind == HIT_POLYGON)
        ctx->tracer.stamp[q->surface->index] = id;
    do {
        int c = grid_cell_index(g, walk.cell);
        for (uint32_t k = g->cell_start[c]; k < g->cell_start[c + 1]; k++) {
            uint32_t pi = g->items[k];
            if (!bucket_admit(&ctx->tracer, id, pi))
                continue;
            const Polygon *p = &w->polygons[pi];
            const Material *m = &w->materials[p->material];
            if (m->no_shadow)
                continue;
            ctx->stats.shadow_polygon_tests++;
            double t = intersect_polygon_in(w, p, &frame, tmax); /* negative at tmax or beyond */
            if (t > tmin) {
                /* A polygon edge-on to the light (the light in its plane)
                 * casts no shadow: the ray can only graze it, or meet it at
                 * the light itself. The same rule as the shadow volumes'. */
                if (shadow_light_side(p, &w->lights[q->light], grid_tolerance(g)) == 0)
                    continue;
                if (pass_through(w, m, (int)pi, q, t, light)) {
                    /* a patterned see-through polygon blocks only where it is opaque:
                     * not one for the cache, which takes a hit anywhere as blocked */
                    ctx->last_blocker = m->opaque ? (int)pi : -1;
                    return 1;
                }
                ctx->last_filtered++;
            }
        }
    } while (grid_walk_next(g, &walk));
    return 0;
}

void shadow_conventional_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    light->r = light->g = light->b = 1.0;
    ctx->last_scheme = SCHEME_CONVENTIONAL;
    ctx->stats.shadow_schemes[SCHEME_CONVENTIONAL]++;
    if (shadow_planes_test(ctx, q, light) || shadow_polygons_test(ctx, q, light))
        ctx->stats.shadow_blocked++;
}
