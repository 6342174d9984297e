/* The volume methods' per-thread state and the render loop's hooks for it
 * (shadow.h): the light states along the ray tree (one row of a light's
 * states per ray segment the shading follows), the shadow buckets (stamps
 * and room for any light's shadow polygons), the cells each camera segment
 * pierces (recorded by the tracer), and hst's pixel coherence (counts
 * carried from the neighbouring pixel's hit, shadow_coherence.h). Nothing
 * outside these hooks moves the rows or the coherence's neighbours. */
#include "shadow.h"

#include <stdlib.h>

#include "shadow_coherence.h"
#include "shadow_volumes.h"

/* Enough for max_trace_level reflections plus continued (same-ior) rays;
 * deeper points keep no state and their methods use the shadow ray. */
#define STATE_DEPTH 64

int shadow_volume_thread_init(ShadowContext *ctx, const ShadowPrepared *p, int pixel_coherence)
{
    (void)pixel_coherence;
    const ShadowVolumes *volumes = p->volumes;
    if (!volumes)
        return 0;
    ctx->volumes = volumes;
    int nl = ctx->tracer->world->nlights > 0 ? ctx->tracer->world->nlights : 1;
    int most = 1;
    for (int i = 0; i < volumes->nlights; i++)
        if (volumes->light[i].count > most)
            most = volumes->light[i].count;
    ctx->sp_stamp = calloc((size_t)(volumes->npolygons > 0 ? volumes->npolygons : 1), sizeof(uint32_t));
    ctx->bucket = malloc(sizeof(uint32_t) * (size_t)most);
    ctx->states = calloc((size_t)nl * STATE_DEPTH, sizeof(LightState));
    if (tracer_record_cells(ctx->tracer, volumes->box_min, volumes->box_max) || !ctx->sp_stamp || !ctx->bucket ||
        !ctx->states)
        return -1;
    ctx->state_capacity = STATE_DEPTH;
    return 0;
}

int shadow_hst_thread_init(ShadowContext *ctx, const ShadowPrepared *p, int pixel_coherence)
{
    if (shadow_volume_thread_init(ctx, p, pixel_coherence))
        return -1;
    if (!pixel_coherence || !p->volumes)
        return 0;
    ctx->coherence = calloc(1, sizeof *ctx->coherence);
    return !ctx->coherence || pixel_coherence_init(ctx->coherence, ctx->tracer->world, ctx->tracer->grid) ? -1 : 0;
}

void shadow_volume_thread_free(ShadowContext *ctx)
{
    if (ctx->coherence)
        pixel_coherence_free(ctx->coherence);
    free(ctx->coherence);
    free(ctx->bucket);
    free(ctx->sp_stamp);
    free(ctx->states);
    ctx->coherence = NULL;
    ctx->bucket = NULL;
    ctx->sp_stamp = NULL;
    ctx->states = NULL;
}

void shadow_volume_pixel_begin(ShadowContext *ctx, int first_in_row, int first_row)
{
    if (ctx->coherence)
        pixel_coherence_begin(ctx->coherence, first_in_row, first_row);
}

void shadow_volume_pixel_end(ShadowContext *ctx, int first_in_row)
{
    PixelCoherence *pc = ctx->coherence;
    if (pc)
        pixel_coherence_end(pc, pc->have_hit ? &pc->hit : NULL, ctx->states, first_in_row);
}

LightState *shadow_volume_segment_begin(ShadowContext *ctx, const Hit *hit, int from_eye)
{
    /* The camera ray's hit: the next pixel's neighbour. */
    if (ctx->coherence && ctx->state_depth == 0 && from_eye) {
        ctx->coherence->hit = *hit;
        ctx->coherence->have_hit = 1;
    }
    LightState *row = NULL;
    if (ctx->states && ctx->state_depth < ctx->state_capacity)
        row = ctx->states + (size_t)ctx->state_depth * (size_t)ctx->tracer->world->nlights;
    ctx->state_depth++;
    return row;
}

void shadow_volume_segment_end(ShadowContext *ctx)
{
    ctx->state_depth--;
}
