/* The conventional test plus a last-blocker cache per light, as POV-Ray
 * keeps one: the opaque polygon that last blocked a light is tried first,
 * since neighbouring shading points are often shadowed by the same one.
 * A cache hit is a real intersection inside the segment to the light,
 * clearly inside the polygon, so the answer is the conventional one. The cache lives in the thread's
 * context (one per thread, nothing shared). */
#include "shadow.h"

#include "intersect.h"

static int cached_blocker_hits(ShadowContext *ctx, const ShadowQuery *q)
{
    int pi = ctx->light_cache[q->light];
    if (pi < 0 || (q->surface->kind == HIT_POLYGON && q->surface->index == pi))
        return 0;
    const World *w = ctx->tracer.world;
    ctx->stats.shadow_polygon_tests++;
    const Polygon *p = &w->polygons[pi];
    double t = intersect_polygon(w, p, q->point, q->to_light);
    if (!(t > trace_min_distance(q->point) && t < q->distance))
        return 0;
    /* Only a hit clearly inside the polygon is taken: on its border the
     * shadow ray's own walk decides (it may find the neighbour instead, or
     * nothing, by the same tie rules as every other test). */
    return polygon_classify_point(w, p, v3_madd(q->point, q->to_light, t), grid_tolerance(ctx->tracer.grid)) == 1;
}

void shadow_cache_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    light->r = light->g = light->b = 1.0;
    ctx->last_scheme = SCHEME_CONVENTIONAL;
    if (shadow_planes_test(ctx, q, light)) {
        ctx->stats.shadow_schemes[SCHEME_CONVENTIONAL]++;
        ctx->stats.shadow_blocked++;
        return;
    }
    if (cached_blocker_hits(ctx, q)) {
        light->r = light->g = light->b = 0.0;
        ctx->last_scheme = SCHEME_CACHE_HIT;
        ctx->stats.shadow_schemes[SCHEME_CACHE_HIT]++;
        ctx->stats.shadow_blocked++;
        return;
    }
    ctx->last_blocker = -1;
    ctx->stats.shadow_schemes[SCHEME_CONVENTIONAL]++;
    if (shadow_polygons_test(ctx, q, light)) {
        ctx->stats.shadow_blocked++;
        /* Only opaque blockers are cached: a hit must mean "no light". */
        if (ctx->last_blocker >= 0 && light->r == 0.0 && light->g == 0.0 && light->b == 0.0)
            ctx->light_cache[q->light] = ctx->last_blocker;
    }
}
