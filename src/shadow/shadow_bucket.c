/* Shadow buckets (shadow_bucket.h). */
#include "shadow_bucket.h"

#include <limits.h>

#include "convert.h"
#include "shadow_volumes.h"

int shadow_bucket_limit(double nth)
{
    return nth < 0.0 ? -1 : int_clamped(nth, 0, INT_MAX); /* NaN: 0, no polygon counts as under it */
}

int shadow_bucket_fill(ShadowContext *ctx, int light, int limit)
{
    return shadow_bucket_fill_in(ctx, light, ctx->tracer->segment_cells, ctx->tracer->segment_ncells, limit);
}

uint32_t shadow_bucket_registrations(const ShadowContext *ctx, int light)
{
    return shadow_bucket_registrations_in(ctx, light, ctx->tracer->segment_cells, ctx->tracer->segment_ncells);
}

int shadow_bucket_fill_in(ShadowContext *ctx, int light, const uint32_t *cells, int ncells, int limit)
{
    const LightVolumes *lv = &ctx->volumes->light[light];
    if (!cell_lists_built(&lv->cells))
        return 0;
    uint32_t id = stamp_next(ctx->sp_stamp, ctx->volumes->npolygons, &ctx->sp_id);
    int n = 0;
    for (int k = 0; k < ncells; k++) {
        uint32_t begin, end;
        cell_lists_get(&lv->cells, cells[k], &begin, &end);
        for (uint32_t j = begin; j < end; j++) {
            uint32_t s = lv->cells.items[j];
            if (ctx->sp_stamp[s] == id)
                continue;
            ctx->sp_stamp[s] = id;
            ctx->bucket[n++] = s;
        }
        if (n > limit)
            break; /* too many to count: the caller fires the shadow ray */
    }
    ctx->stats.shadow_bucket_polygons += (uint64_t)n;
    return n;
}

uint32_t shadow_bucket_registrations_in(const ShadowContext *ctx, int light, const uint32_t *cells, int ncells)
{
    const LightVolumes *lv = &ctx->volumes->light[light];
    if (!cell_lists_built(&lv->cells))
        return 0;
    uint32_t n = 0;
    for (int k = 0; k < ncells; k++) {
        uint32_t begin, end;
        cell_lists_get(&lv->cells, cells[k], &begin, &end);
        n += end - begin;
    }
    return n;
}
