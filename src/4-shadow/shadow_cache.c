/* The conventional test plus a last-blocker cache per light, as POV-Ray
 * keeps one: the opaque polygon that last blocked a light is tried first,
 * since neighbouring shading points are often shadowed by the same one.
 * A cache hit is the shadow ray's own intersection inside the segment to
 * the light, so the answer is the conventional one. The cache lives in the thread's
 * context (one per thread, nothing shared). */
#include "shadow.h"

#include "intersect.h"
#include "shadow_volumes.h"

int shadow_cached_blocker_hits(ShadowContext *ctx, const ShadowQuery *q)
{
    int pi = ctx->light_cache[q->light];
    if (pi < 0 || (q->surface->kind == HIT_POLYGON && q->surface->index == pi))
        return 0;
    const World *w = ctx->tracer.world;
    const Polygon *p = &w->polygons[pi];
    /* The shadow ray's own rule for a polygon edge-on to the light (an area
     * light's sample may see edge-on what blocked another sample). */
    if (shadow_light_side(p, q->source, grid_tolerance(ctx->tracer.grid)) == 0)
        return 0;
    ctx->stats.shadow_polygon_tests++;
    /* The shadow ray's test on the shadow ray's frame (the same numbers,
     * so the same answer): a hit inside the segment is one the shadow ray
     * meets too, the hierarchy's boxes being conservative. The polygon is
     * opaque, not no_shadow, and not q's own, so that ray is blocked: the
     * answer is its answer, wherever in the polygon (border included) the
     * hit lies. */
    double t = intersect_polygon(w, p, q->point, q->to_light);
    return t > trace_min_distance(q->point) && t < q->distance;
}

void shadow_cache_remember(ShadowContext *ctx, const ShadowQuery *q, const RGB *light)
{
    /* Only opaque blockers are cached: a hit must mean "no light". */
    if (ctx->last_blocker >= 0 && light->r == 0.0 && light->g == 0.0 && light->b == 0.0)
        ctx->light_cache[q->light] = ctx->last_blocker;
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
    if (shadow_cached_blocker_hits(ctx, q)) {
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
        shadow_cache_remember(ctx, q, light);
    }
}
