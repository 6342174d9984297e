/* Shadow buckets (the paper's N_s): the distinct shadow polygons of one
 * light registered in the cells a ray segment pierced, gathered from the
 * cells the tracer recorded while it walked the segment. */
#ifndef HST_SHADOW_BUCKET_H
#define HST_SHADOW_BUCKET_H

#include "shadow.h"

/* The current segment's shadow bucket for a light: fills ctx->bucket with
 * the distinct shadow polygons registered in the cells the segment pierced
 * and returns how many (the paper's N_s). Stops early, returning more than
 * `limit`, once there are more than `limit` of them. */
int shadow_bucket_fill(ShadowContext *ctx, int light, int limit);
/* Registrations of the light's shadow polygons in those cells: 0 exactly
 * when the bucket is empty, never less than its size. Cheap. */
uint32_t shadow_bucket_registrations(const ShadowContext *ctx, int light);
/* The same for any list of cells (another segment's walk). */
int shadow_bucket_fill_in(ShadowContext *ctx, int light, const uint32_t *cells, int ncells, int limit);
uint32_t shadow_bucket_registrations_in(const ShadowContext *ctx, int light, const uint32_t *cells, int ncells);

/* The most shadow polygons a bucket may hold for a count under N_th. */
int shadow_bucket_limit(double nth);

#endif
