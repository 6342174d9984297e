/* The conventional (Whitted) shadow test: a shadow ray from the shading
 * point toward the light, through the hierarchy (or the grid), stopped by
 * the first opaque polygon. Transparent polygons on the way filter the light
 * (POV-Ray multiplies rgb*filter + transmit of each, a texture_map's
 * textures' blended), in the order the light passes them, and fade by
 * the way they travel inside fading interiors (shadow_fold_filtered). */
#include "shadow.h"

#include <math.h>
#include <stdlib.h>

#include "fade.h"
#include "intersect.h"
#include "pigment.h"
#include "light.h"

#define FOLD_INSERTION_MAX 16 /* see-through hits sorted by insertion up to this many */
#define POV_SMALL_TOLERANCE 1.0e-3 /* POV-Ray's SMALL_TOLERANCE (and SHADOW_TOLERANCE) */

/* The surface id the material code looks uv coordinates up by. */
static int uv_surface_of(const World *w, int surface, const InfinitePlane *plane)
{
    return plane ? -1 : surface < -1 ? surface : world_uv_polygon(w, surface);
}

/* What a see-through surface with POV-Ray's fake caustics lets through
 * (ComputeShadowTexture): each texture's rgb * filter + transmit times
 * 1 + |cos|^caustics, cos between the texture's normal and the shadow
 * ray, blended by weight; the light brightens where the ray crosses the
 * surface head-on. The normal is the surface's (a smooth triangle's
 * interpolated one) turned against the ray, then perturbed by the
 * texture's normal pattern where the render perturbs normals, as POV-Ray
 * does (ComputeShadowColour, Perturb_Normal). */
/* The surface's normal at a blocker's point `at`, as the shading takes it
 * (before it is turned against the ray). polygon: a surface id (world.h):
 * a polygon's id (instance.h; an instance's normal carried out) or a
 * shape's. */
static Vec3 blocker_normal(const World *w, int polygon, int part, const InfinitePlane *plane, Vec3 at)
{
    return plane         ? plane->normal
         : polygon < -1  ? shape_normal(&w->shapes[surface_shape(polygon)], at, part)
                         : world_polygon_shading_normal(w, polygon, -1, at);
}

static RGB caustics_filter_at(const ShadowContext *ctx, const Material *m, int polygon, int part,
                              const InfinitePlane *plane, const ShadowQuery *q, Vec3 at, int *blocks)
{
    const World *w = ctx->tracer->world;
    Vec3 n = blocker_normal(w, polygon, part, plane, at);
    if (v3_dot(n, q->to_light) > 0.0)
        n = v3_neg(n);
    if (m->below >= 0 && (polygon < 0 || w->polygons[polygon].vertex_materials < 0)) {
        /* a layered texture: each layer's filter and caustics, multiplied */
        SurfaceTexture layer[MAX_TEXTURE_LAYERS];
        int nl = material_layers_at(w, m, uv_surface_of(w, polygon, plane), at, n, ctx->perturb_normals, layer);
        RGB through = { 1, 1, 1 };
        *blocks = 0;
        for (int i = 0; i < nl; i++) {
            const Colour *c = &layer[i].colour;
            double k = 1.0 + pow(fabs(v3_dot(layer[i].normal, q->to_light)), m->caustics);
            through.r *= k * (c->r * c->filter + c->transmit);
            through.g *= k * (c->g * c->filter + c->transmit);
            through.b *= k * (c->b * c->filter + c->transmit);
            *blocks |= c->filter == 0.0 && c->transmit == 0.0;
        }
        return through;
    }
    SurfaceTexture tx[MAX_SURFACE_TEXTURES];
    int nt = material_textures_normals_at(w, m, uv_surface_of(w, polygon, plane), at, n, ctx->perturb_normals, tx);
    RGB through = { 0, 0, 0 };
    *blocks = 1;
    for (int i = 0; i < nt; i++) {
        const Colour *c = &tx[i].colour;
        double k = tx[i].weight * (1.0 + pow(fabs(v3_dot(tx[i].normal, q->to_light)), m->caustics));
        through.r += k * (c->r * c->filter + c->transmit);
        through.g += k * (c->g * c->filter + c->transmit);
        through.b += k * (c->b * c->filter + c->transmit);
        *blocks &= c->filter == 0.0 && c->transmit == 0.0;
    }
    return through;
}

/* Folds one blocker (a polygon by its id (instance.h), a shape by its
 * surface id (world.h) and the part of it hit, or an infinite plane), hit
 * at distance t, into the light that gets through; returns 1 when the
 * light is now fully blocked. */
static int pass_through(const ShadowContext *ctx, const Material *m, int polygon, int part,
                        const InfinitePlane *plane, const ShadowQuery *q, double t, RGB *light)
{
    int blocks = 1;
    RGB through = { 0, 0, 0 };
    Vec3 at = v3_add(q->point, v3_scale(q->to_light, t));
    /* met from inside (the shadow ray runs toward the light; POV-Ray's
     * normal turned away from it, Material.inside_turned): the interior
     * texture's filter (ComputeShadowColour) */
    if (m->inside >= 0 &&
        (v3_dot(blocker_normal(ctx->tracer->world, polygon, part, plane, at), q->to_light) > 0.0) !=
            (m->inside_turned != 0))
        m = &ctx->tracer->world->materials[m->inside];
    if (!m->opaque)
        through = m->caustics != 0.0 ? caustics_filter_at(ctx, m, polygon, part, plane, q, at, &blocks)
                                     : material_filter_at(ctx->tracer->world, m,
                                                          uv_surface_of(ctx->tracer->world, polygon, plane), at,
                                                          &blocks);
    if (blocks) {
        light->r = light->g = light->b = 0.0;
        return 1;
    }
    light->r *= through.r;
    light->g *= through.g;
    light->b *= through.b;
    return 0;
}

static int segment_inside(const ShadowQuery *q, const void *key);
static double plane_leg_start(ShadowContext *ctx, const ShadowQuery *q, double tmin, double t);

/* The nearest see-through infinite plane the shadow ray passes between
 * `from` and t (beyond tmin), or from: the planes are tested apart from the
 * polygons, but a leg inside a fading interior starts at the last surface
 * the light was filtered by, which may be one of them. */
static double last_plane_between(const ShadowContext *ctx, const ShadowQuery *q, double tmin, double from, double t)
{
    const World *w = ctx->tracer->world;
    for (int i = 0; i < w->nplanes; i++) {
        const InfinitePlane *pl = &w->planes[i];
        if ((q->surface->kind == HIT_PLANE && q->surface->index == i) || w->materials[pl->material].no_shadow)
            continue;
        double tp = intersect_plane(pl, q->point, q->to_light);
        if (tp > tmin && tp > from && tp < t)
            from = tp;
    }
    return from;
}

int shadow_plane_test(ShadowContext *ctx, const ShadowQuery *q, int i, double tmin, RGB *light)
{
    const World *w = ctx->tracer->world;
    if (q->surface->kind == HIT_PLANE && q->surface->index == i)
        return 0;
    const InfinitePlane *pl = &w->planes[i];
    const Material *m = &w->materials[pl->material];
    if (m->no_shadow)
        return 0;
    double t = intersect_plane(pl, q->point, q->to_light);
    if (!(t > tmin && t < q->distance))
        return 0;
    if (pass_through(ctx, m, -1, 0, pl, q, t, light))
        return 1;
    /* A plane is crossed once: the shadow ray fades at it where it starts
     * inside its interior (under water, seen through its surface), over
     * the leg from the last see-through polygon before it, which only the
     * polygons in the way tell: looked up here, so that every method, which
     * tests the planes through this function, gets the same light. */
    if (interior_fades_shadows(m) && segment_inside(q, m->interior_key)) {
        RGB f = interior_fade(m, t - last_plane_between(ctx, q, tmin, plane_leg_start(ctx, q, tmin, t), t));
        light->r *= f.r;
        light->g *= f.g;
        light->b *= f.b;
    }
    return 0;
}

int shadow_planes_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    double tmin = trace_min_distance(q->point);
    for (int i = 0; i < ctx->tracer->world->nplanes; i++)
        if (shadow_plane_test(ctx, q, i, tmin, light))
            return 1;
    return shadow_shapes_test(ctx, q, light);
}

/* The crossings of shape i that q's shadow ray counts, in order along
 * it (their number, at most SHAPE_MAX_HITS): none where the shape casts no
 * shadow or the segment misses its box. */
static int shape_shadow_crossings(ShadowContext *ctx, const ShadowQuery *q, int i, ShapeHit *hits)
{
    const World *w = ctx->tracer->world;
    const Shape *s = &w->shapes[i];
    /* The point's own shape is tested too: POV-Ray's shadow ray leaves
     * no object out; its window (shadow_shape_window) keeps it off the
     * surface it starts on (a sphere's far side still shadows). */
    double tmin, tlimit;
    shadow_shape_window(q->distance, &tmin, &tlimit);
    if (w->materials[s->material].no_shadow || !shape_box_hit(s, q->point, q->to_light, tlimit))
        return 0;
    ctx->stats.shadow_shape_tests++;
    /* those past the window's start kept in place, in order */
    int nall = shape_intersect_all(s, q->point, q->to_light, tlimit, hits), n = 0;
    for (int k = 0; k < nall; k++)
        if (hits[k].t > tmin)
            hits[n++] = hits[k];
    return n;
}

ShapeCrossing shadow_shape_crossing(ShadowContext *ctx, const ShadowQuery *q, int i, ShadowSphereRay *sr)
{
    const World *w = ctx->tracer->world;
    if (shadow_sphere_fast(&w->shapes[i]))
        return shadow_sphere_crossing(ctx, q, &w->shapes[i], sr);
    ShapeHit hits[SHAPE_MAX_HITS];
    int n = shape_shadow_crossings(ctx, q, i, hits);
    for (int k = 0; k < n; k++) {
        const int leaf = hits[k].leaf ? (int)(hits[k].leaf - w->shapes) : i;
        if (w->materials[w->shapes[leaf].material].opaque)
            return SHAPE_CROSSED_OPAQUE;
    }
    return n > 0 ? SHAPE_CROSSED_SEE_THROUGH : SHAPE_NOT_CROSSED;
}

static int fold_crossings(ShadowContext *ctx, const ShadowQuery *q, int i, const ShapeHit *hits, int n, RGB *light);

/* One shape's part of shadow_shapes_test; 1 when the light is now fully
 * blocked. */
typedef struct {
    ShadowContext *ctx;
    const ShadowQuery *q;
    RGB *light;
} ShapeShadow;

static int shadow_shape_test(void *user, int i, int boxed, double *tmax)
{
    /* every crossing up to the light counts; the shape's own box is
     * tested whatever the walk's, so that every method's shadow ray
     * (whose lists of shapes are not the hierarchy's) crosses the same
     * shapes, bit for bit */
    (void)boxed;
    (void)tmax;
    ShapeShadow *ss = user;
    ShadowContext *ctx = ss->ctx;
    const ShadowQuery *q = ss->q;
    ShapeHit hits[SHAPE_MAX_HITS];
    int n = shape_shadow_crossings(ctx, q, i, hits);
    return fold_crossings(ctx, q, i, hits, n, ss->light);
}

/* Shape i's n crossings (hits, in order along q's shadow ray) folded into
 * *light; 1 when it is now fully blocked. */
static int fold_crossings(ShadowContext *ctx, const ShadowQuery *q, int i, const ShapeHit *hits, int n, RGB *light)
{
    const World *w = ctx->tracer->world;
    const Material *m = &w->materials[w->shapes[i].material];
    /* a fading interior fades the light over the legs the shadow ray
     * runs inside it: from the point (where it starts inside) or the
     * shape's last surface, to the next (the legs as the shape alone
     * bounds them: surfaces of other objects inside it do not split
     * them) */
    int inside = n > 0 && interior_fades_shadows(m) && segment_inside(q, m->interior_key);
    double from = 0.0;
    for (int k = 0; k < n; k++) {
        /* a CSG object's crossing is on one of its parts, with its texture */
        const int leaf = hits[k].leaf ? (int)(hits[k].leaf - w->shapes) : i;
        if (pass_through(ctx, &w->materials[w->shapes[leaf].material], surface_of_shape(leaf), hits[k].part, NULL,
                         q, hits[k].t, light))
            return 1;
        if (inside) {
            RGB f = interior_fade(m, hits[k].t - from);
            light->r *= f.r;
            light->g *= f.g;
            light->b *= f.b;
        }
        inside = !inside && interior_fades_shadows(m);
        from = hits[k].t;
    }
    return 0;
}

int shadow_shape_fold(ShadowContext *ctx, const ShadowQuery *q, int i, RGB *light)
{
    ShapeShadow ss = { ctx, q, light };
    double unused = q->distance;
    return shadow_shape_test(&ss, i, 0, &unused);
}

int shadow_sphere_fold(ShadowContext *ctx, const ShadowQuery *q, int i, const double *t, int n, RGB *light)
{
    ShapeHit hits[2]; /* shape_intersect_all's, less what fold_crossings does not read */
    for (int k = 0; k < n; k++)
        hits[k] = (ShapeHit){ .t = t[k], .part = SHAPE_SIDE, .leaf = NULL };
    return fold_crossings(ctx, q, i, hits, n, light);
}

int shadow_shapes_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    const World *w = ctx->tracer->world;
    if (w->nshapes == 0)
        return 0;
    ShapeShadow ss = { ctx, q, light };
    const Bvh *bvh = ctx->tracer->bvh;
    if (bvh && bvh->shapes) { /* the shapes whose boxes the segment meets */
        double tmax = q->distance;
        uint64_t nodes = 0;
        return bvh_shapes_walk(bvh->shapes, q->point, q->to_light, &tmax, HIDE_NO_SHADOW, shadow_shape_test, &ss,
                               &nodes, ctx->tracer->avx2);
    }
    for (int i = 0; i < w->nshapes; i++) {
        double tmax = q->distance;
        if (shadow_shape_test(&ss, i, 0, &tmax))
            return 1;
    }
    return 0;
}

/* What a shadow ray has met so far: transparent polygons are kept, to be
 * folded in the order the light passes them (by distance, then index), so
 * that the colour does not depend on the order the query found them in. */
typedef struct {
    ShadowContext *ctx;
    const ShadowQuery *q;
    int blocker;          /* the opaque polygon that blocked, or -1 */
    int side_known;       /* 1: the polygon met is known not to be edge-on to q's source */
} ShadowWalk;

static int meet_polygon(void *user, uint32_t pi, double t)
{
    ShadowWalk *sw = user;
    ShadowContext *ctx = sw->ctx;
    const World *w = ctx->tracer->world;
    Polygon scratch;
    /* the walk's instance, when it is one's polygon: no search */
    const int hint = ctx->tracer->visiting;
    /* A polygon edge-on to the light (the light in its plane) casts no
     * shadow: the ray can only graze it, or meet it at the light itself.
     * The same rule as the shadow volumes'. (An instance's polygon: its
     * plane carried to world space, the same for every method.) */
    if (!sw->side_known &&
        light_side_of(world_polygon_plane(w, (int)pi, hint, &scratch), sw->q->source,
                      grid_tolerance(ctx->tracer->grid)) == 0)
        return 0;
    const Material *m = &w->materials[world_polygon_material_hinted(w, (int)pi, hint)];
    if (m->opaque) {
        sw->blocker = (int)pi;
        return 1;
    }
    /* Room for every see-through polygon of the world (shadow_context_init),
     * each met at most once. */
    ctx->filtered[ctx->nfiltered].t = t;
    ctx->filtered[ctx->nfiltered].polygon = pi;
    ctx->nfiltered++;
    return 0;
}

static int by_distance(const void *a, const void *b)
{
    const FilteredHit *x = a, *y = b;
    if (x->t != y->t)
        return x->t < y->t ? -1 : 1;
    return x->polygon < y->polygon ? -1 : x->polygon > y->polygon;
}

int shadow_polygons_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    ctx->stats.shadow_rays++;
    double tmin = trace_min_distance(q->point);
    int exclude = q->surface->kind == HIT_POLYGON ? q->surface->index : -1;
    ShadowWalk sw = { ctx, q, -1, 0 };
    ctx->nfiltered = 0;
    if (trace_segment_hits(ctx->tracer, q->point, q->to_light, tmin, q->distance, exclude, HIDE_NO_SHADOW,
                           meet_polygon, &sw, &ctx->stats.shadow_polygon_tests)) {
        light->r = light->g = light->b = 0.0;
        ctx->last_blocker = sw.blocker;
        return 1;
    }
    return shadow_fold_filtered(ctx, q, light);
}

void shadow_list_begin(ShadowListWalk *lw, ShadowContext *ctx, const ShadowQuery *q)
{
    ctx->stats.shadow_rays++;
    ctx->nfiltered = 0;
    lw->ctx = ctx;
    lw->q = q;
    lw->frame = ray_frame(q->point, q->to_light);
    lw->tmin = trace_min_distance(q->point);
    lw->own = q->surface->kind == HIT_POLYGON ? (uint32_t)q->surface->index : UINT32_MAX;
    lw->sides_known = 0;
}

/* The polygon met at t (no hit: t <= tmin): 1 when it blocks fully. */
static int list_met(ShadowListWalk *lw, uint32_t polygon, double t, int side_known)
{
    ShadowWalk sw = { lw->ctx, lw->q, -1, side_known };
    if (t > lw->tmin && meet_polygon(&sw, polygon, t)) {
        lw->ctx->last_blocker = sw.blocker;
        return 1;
    }
    return 0;
}

int shadow_list_meet(ShadowListWalk *lw, uint32_t polygon)
{
    if (polygon == lw->own)
        return 0;
    ShadowContext *ctx = lw->ctx;
    const World *w = ctx->tracer->world;
    /* the hierarchy's leaf test, polygon by polygon (bvh_traverse.h) */
    ctx->stats.shadow_polygon_tests++;
    return list_met(lw, polygon, intersect_polygon_in(w, &w->polygons[polygon], &lw->frame, lw->q->distance), 0);
}

int shadow_list_meet_crossed(ShadowListWalk *lw, uint32_t polygon)
{
    ShadowContext *ctx = lw->ctx;
    ctx->stats.shadow_polygon_tests++;
    /* the test's own distance to the plane, and its range (intersect.c) */
    double t = intersect_plane_distance(&ctx->tracer->world->polygons[polygon], &lw->frame);
    return list_met(lw, polygon, t > 0.0 && t < lw->q->distance ? t : -1.0, lw->sides_known);
}

/* The visitor of an instance's walk for a list: list_met. */
static int list_visit(void *user, uint32_t polygon, double t)
{
    return list_met(user, polygon, t, 0); /* an instance's polygon: its side asked */
}

int shadow_list_meet_item(ShadowListWalk *lw, const Bvh *b, uint32_t item)
{
    uint32_t polygon = b->items[item];
    if (polygon & BVH_INSTANCE) {
        /* an instance: its polygons met by the shadow ray's own walk of it
         * (trace_segment_hits's), its own polygon left out there */
        ShadowContext *ctx = lw->ctx;
        return trace_instance_hits(ctx->tracer, (int)(polygon & ~BVH_INSTANCE), lw->q->point, lw->q->to_light,
                                   lw->tmin, lw->q->distance, lw->own == UINT32_MAX ? -1 : (int)lw->own,
                                   HIDE_NO_SHADOW, list_visit, lw, &ctx->stats.shadow_polygon_tests);
    }
    if (polygon == lw->own)
        return 0;
    ShadowContext *ctx = lw->ctx;
    ctx->stats.shadow_polygon_tests++;
    return list_met(lw, polygon, bvh_item_test(ctx->tracer->world, b, item, &lw->frame, lw->q->distance),
                    lw->sides_known);
}

int shadow_list_end(ShadowListWalk *lw, RGB *light)
{
    return shadow_fold_filtered(lw->ctx, lw->q, light);
}

int shadow_polygons_test_among(ShadowContext *ctx, const ShadowQuery *q, const uint32_t *candidates, int n,
                               RGB *light)
{
    ShadowListWalk lw;
    shadow_list_begin(&lw, ctx, q);
    for (int i = 0; i < n; i++)
        if (shadow_list_meet(&lw, candidates[i])) {
            light->r = light->g = light->b = 0.0;
            return 1;
        }
    return shadow_list_end(&lw, light);
}

/* The fading interiors a shadow ray is inside, kept as POV-Ray keeps them:
 * its shadow ray is a copy of the ray that found the point, so it starts
 * inside that ray's interiors (ComputeOneDiffuseLight), and each
 * see-through surface it passes toggles the surface's interior, whichever
 * way the surface faces (ComputeShadowMedia: leaves it when inside, else
 * enters). Only interiors that fade need keeping: a key's membership
 * changes only at its own surfaces, which all share its fade. */
#define FADE_NESTING_MAX 32

typedef struct {
    int n;
    const void *key[FADE_NESTING_MAX];
} FadeInside;

static void fade_inside_begin(FadeInside *in, const ShadowQuery *q)
{
    in->n = 0;
    const Segment *seg = q->segment;
    for (int i = 0; seg && i < seg->ninside && in->n < FADE_NESTING_MAX; i++)
        in->key[in->n++] = seg->inside[i];
}

/* Toggles key; 1 when the ray was inside it (and has now left). Deeper
 * nesting than FADE_NESTING_MAX interiors at once is not kept. */
static int fade_inside_toggle(FadeInside *in, const void *key)
{
    for (int i = 0; i < in->n; i++)
        if (in->key[i] == key) {
            in->key[i] = in->key[--in->n];
            return 1;
        }
    if (in->n < FADE_NESTING_MAX)
        in->key[in->n++] = key;
    return 0;
}

static int segment_inside(const ShadowQuery *q, const void *key)
{
    for (int i = 0; q->segment && i < q->segment->ninside; i++)
        if (q->segment->inside[i] == key)
            return 1;
    return 0;
}

/* ctx->filtered in the order the light passes them. */
static void sort_filtered(ShadowContext *ctx)
{
    if (ctx->nfiltered > FOLD_INSERTION_MAX) {
        qsort(ctx->filtered, (size_t)ctx->nfiltered, sizeof *ctx->filtered, by_distance);
    } else {
        /* a shadow ray meets a few see-through polygons: insertion sort by
         * the same order (distance, then index: a total order, so the
         * result is qsort's) without a call per comparison */
        for (int i = 1; i < ctx->nfiltered; i++) {
            FilteredHit h = ctx->filtered[i];
            int j = i;
            while (j > 0 && by_distance(&h, &ctx->filtered[j - 1]) < 0) {
                ctx->filtered[j] = ctx->filtered[j - 1];
                j--;
            }
            ctx->filtered[j] = h;
        }
    }
}

/* Where the shadow ray's leg to a plane hit at t starts: at the last
 * see-through polygon it filters by before t (the same rule as
 * shadow_fold_filtered's), or at the point. With an opaque polygon in the
 * way the light is blocked anyway: the point then. The walk leaves
 * ctx->filtered to the polygon test that follows, which starts it afresh. */
static double plane_leg_start(ShadowContext *ctx, const ShadowQuery *q, double tmin, double t)
{
    int exclude = q->surface->kind == HIT_POLYGON ? q->surface->index : -1;
    ShadowWalk sw = { ctx, q, -1, 0 };
    ctx->nfiltered = 0;
    uint64_t tests = 0;
    if (trace_segment_hits(ctx->tracer, q->point, q->to_light, tmin, t, exclude, HIDE_NO_SHADOW, meet_polygon, &sw,
                           &tests))
        return 0.0;
    sort_filtered(ctx);
    double last = 0.0;
    for (int i = 0; i < ctx->nfiltered; i++)
        if (i == 0 || ctx->filtered[i].t - last > POV_SMALL_TOLERANCE)
            last = ctx->filtered[i].t;
    ctx->nfiltered = 0;
    return last;
}

int shadow_fold_filtered(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    const World *w = ctx->tracer->world;
    sort_filtered(ctx);
    FadeInside inside;
    fade_inside_begin(&inside, q);
    double last = 0.0;
    for (int i = 0; i < ctx->nfiltered; i++) {
        /* POV-Ray's shadow ray starts again at each see-through surface it
         * filters by and takes the next only beyond SMALL_TOLERANCE of it:
         * surfaces within that of the last one filtered (two triangles'
         * shared edge, coplanar panes) filter once. */
        if (i > 0 && ctx->filtered[i].t - last <= POV_SMALL_TOLERANCE)
            continue;
        double from = last; /* the point, or the last surface filtered: where this leg starts */
        last = ctx->filtered[i].t;
        uint32_t pi = ctx->filtered[i].polygon;
        const Material *m = &w->materials[world_polygon_material(w, (int)pi)];
        if (pass_through(ctx, m, (int)pi, 0, NULL, q, ctx->filtered[i].t, light)) {
            /* a patterned see-through polygon blocks only where it is opaque:
             * not one for the cache, which takes a hit anywhere as blocked */
            ctx->last_blocker = -1;
            return 1;
        }
        /* Light that crossed a fading interior to reach this surface of
         * it fades by the length of the leg (ComputeShadowTexture): the
         * legs between surfaces, in order, as POV-Ray restarts the ray at
         * each. */
        if (interior_fades_shadows(m) && fade_inside_toggle(&inside, m->interior_key)) {
            if (w->nplanes)
                from = last_plane_between(ctx, q, trace_min_distance(q->point), from, last);
            RGB f = interior_fade(m, last - from);
            light->r *= f.r;
            light->g *= f.g;
            light->b *= f.b;
        }
        ctx->last_filtered++;
    }
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

const ShadowMethod shadow_conventional_method = {
    .name = "conventional",
    .summary = "a shadow ray per light through the grid (exact reference)",
    .test = shadow_conventional_test,
    .instances = 1,
};
