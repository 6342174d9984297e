/* The conventional test plus a last-blocker cache per light, as POV-Ray
 * keeps one: the opaque polygon that last blocked a light is tried first,
 * since neighbouring shading points are often shadowed by the same one.
 * A cache hit is the shadow ray's own intersection inside the segment to
 * the light, so the answer is the conventional one. The cache lives in the thread's
 * context (one per thread, nothing shared).
 *
 * A try that misses costs a polygon test and a hit saves a walk through
 * the hierarchy (on the paper scenes and meshes some 5 to 10 polygon
 * tests' worth), so the cache pays while at least one try in
 * CACHE_PAYS_ONE_IN hits. Where it does not (a mesh of small triangles:
 * 36 hits in 380,973 queries on make-mesh.sh 10^6 8 at 320x240, shadow
 * testing 7% slower than the plain shadow ray), the light's cache sits
 * out all but one query in CACHE_PROBE_EVERY, and those probes let it
 * back in when the hits return. And a light's cache is not tried right
 * after a decision that found no polygon blocking the light: lit points
 * mostly neighbour lit points, where every try misses (make-mesh 10^5 x 4
 * at 640x480: shadow testing 1.5% fewer instructions, and the cache hits
 * 50,086 -> 63,064, the tally no longer diluted by lit points). Which
 * queries try it changes how a decision is reached, never the decision. */
#include "shadow.h"

#include "intersect.h"
#include "light.h"

#define CACHE_WARM_UP 16     /* tries before the tally is believed */
#define CACHE_PAYS_ONE_IN 8  /* the hit rate below which trying first costs more than it saves */
#define CACHE_PROBE_EVERY 16 /* a cache that does not pay is still tried this often */
/* A cache that hits less than once in CACHE_FUTILE_ONE_IN tries (make-mesh
 * 10^6 x 8: 1,675 hits in 79,247 probes, 1 in 47) is probed only once in
 * CACHE_PROBE_FUTILE: its probes cost more than its hits save (28 M
 * instructions for 1,675 walks of some 1,300 each there). */
#define CACHE_FUTILE_ONE_IN 32
#define CACHE_PROBE_FUTILE 128

/* Whether this query tries light c's cache, by the tally so far. */
static inline int cache_worth_trying(LightCache *c)
{
    if (c->tries < CACHE_WARM_UP || c->hits * CACHE_PAYS_ONE_IN >= c->tries)
        return 1;
    unsigned every = c->hits * CACHE_FUTILE_ONE_IN >= c->tries ? CACHE_PROBE_EVERY : CACHE_PROBE_FUTILE;
    if (++c->skipped < every)
        return 0;
    c->skipped = 0;
    return 1;
}

/* The try itself, out of line: the queries the cache sits out (on a big
 * mesh nearly all) cost the checks of shadow_cached_blocker_hits alone. */
static __attribute__((noinline)) int cached_blocker_try(ShadowContext *ctx, const ShadowQuery *q, LightCache *c,
                                                        int pi)
{
    const World *w = ctx->tracer->world;
    if (!c->plane_made) {
        const Polygon *p = world_polygon_plane(w, pi, -1, &c->plane);
        if (p != &c->plane)
            c->plane = *p;
        (void)world_polygon_hinted(w, pi, -1, &c->instance);
        c->plane_made = 1;
    }
    /* The shadow ray's own rule for a polygon edge-on to the light (an area
     * light's sample may see edge-on what blocked another sample), on the
     * plane the shadow ray's walk takes (world_polygon_plane's, kept). */
    if (light_side_of(&c->plane, q->source, grid_tolerance(ctx->tracer->grid)) == 0)
        return 0;
    ctx->stats.shadow_polygon_tests++;
    /* The shadow ray's test on the shadow ray's frame (the same numbers,
     * so the same answer): a hit inside the segment is one the shadow ray
     * meets too, the hierarchy's boxes being conservative. The polygon is
     * opaque, not no_shadow, and not q's own, so that ray is blocked: the
     * answer is its answer, wherever in the polygon (border included) the
     * hit lies. */
    c->tries++;
    double t = world_polygon_hit(w, pi, c->instance, q->point, q->to_light); /* an instance's: on instance_ray's ray, as the walk */
    int hit = t > trace_min_distance(q->point) && t < q->distance;
    c->hits += (unsigned)hit;
    return hit;
}

static inline int cached_blocker_hits(ShadowContext *ctx, const ShadowQuery *q)
{
    LightCache *c = &ctx->light_cache[q->light];
    int pi = c->blocker;
    if (pi < 0 || c->lit_last || (q->surface->kind == HIT_POLYGON && q->surface->index == pi) || !cache_worth_trying(c))
        return 0;
    return cached_blocker_try(ctx, q, c, pi);
}

int shadow_cached_blocker_hits(ShadowContext *ctx, const ShadowQuery *q) { return cached_blocker_hits(ctx, q); }

void shadow_cache_remember(ShadowContext *ctx, const ShadowQuery *q, const RGB *light)
{
    /* Only opaque blockers are cached: a hit must mean "no light". */
    LightCache *c = &ctx->light_cache[q->light];
    if (ctx->last_blocker >= 0 && light->r == 0.0 && light->g == 0.0 && light->b == 0.0 &&
        c->blocker != ctx->last_blocker) {
        c->blocker = ctx->last_blocker;
        c->plane_made = 0; /* made at its first try */
    }
}

/* The polygon part of q's decision: the cache's try, then the shadow ray. */
static inline int cache_polygons_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    if (cached_blocker_hits(ctx, q)) {
        light->r = light->g = light->b = 0.0;
        ctx->last_scheme = SCHEME_CACHE_HIT;
        ctx->stats.shadow_schemes[SCHEME_CACHE_HIT]++;
        ctx->stats.shadow_blocked++;
        return 1;
    }
    ctx->last_blocker = -1;
    ctx->last_scheme = SCHEME_CONVENTIONAL;
    ctx->stats.shadow_schemes[SCHEME_CONVENTIONAL]++;
    if (shadow_polygons_test(ctx, q, light)) {
        ctx->stats.shadow_blocked++;
        shadow_cache_remember(ctx, q, light);
        ctx->light_cache[q->light].lit_last = 0;
        return 1;
    }
    ctx->light_cache[q->light].lit_last = 1;
    return 0;
}

int shadow_cache_polygons_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    return cache_polygons_test(ctx, q, light);
}

/* The planes' part, then, unless a plane blocks, the cache's polygon part,
 * inlined (this is every decision of hst on a big mesh, where a call
 * through a pointer counted against the cache). */
void shadow_cache_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    light->r = light->g = light->b = 1.0;
    ctx->last_scheme = SCHEME_CONVENTIONAL;
    if (shadow_planes_test(ctx, q, light)) {
        ctx->stats.shadow_schemes[SCHEME_CONVENTIONAL]++;
        ctx->stats.shadow_blocked++;
        return;
    }
    cache_polygons_test(ctx, q, light);
}

const ShadowMethod shadow_cache_method = {
    .name = "cache",
    .summary = "shadow rays that first try the light's last opaque blocker (as POV-Ray does)",
    .test = shadow_cache_test,
    .instances = 1,
};
