/* Timed, counted and verified shadow decisions (shadow_decide.h). */
#include "shadow_decide.h"

#include "shadow_reference.h"

/* --verify-shadows: the shadow ray's answer beside the method's;
 * --verify-reference: and the long-double reference's beside both. */
void shadow_verify(ShadowContext *ctx, const ShadowQuery *q, RGB got)
{
    int scheme = ctx->last_scheme;
    RGB want;
    /* The check's own work is not the method's: its counts are put back. */
    RayCounters keep_rays = ctx->tracer->stats;
    ShadowCounters keep = ctx->stats;
    shadow_conventional_test(ctx, q, &want);
    ctx->tracer->stats = keep_rays;
    ctx->stats = keep;
    ctx->stats.shadow_verified++;
    if (want.r != got.r || want.g != got.g || want.b != got.b) {
        ctx->stats.shadow_disagreements++;
        ctx->stats.shadow_disagreements_by_scheme[scheme]++;
    }
    if (ctx->verify > 1) {
        /* The verdicts compared: is any light taken away? */
        const World *w = ctx->tracer->world;
        RefAnswer ref = shadow_reference(w, q->surface, q->source, ctx->reference_eps);
        int got_blocked = got.r != 1.0 || got.g != 1.0 || got.b != 1.0;
        int ray_blocked = want.r != 1.0 || want.g != 1.0 || want.b != 1.0;
        if (ref == REF_TIE)
            ctx->stats.reference_ties++;
        else {
            ctx->stats.reference_wrong += got_blocked != (ref == REF_BLOCKED);
            ctx->stats.reference_ray_wrong += ray_blocked != (ref == REF_BLOCKED);
        }
    }
    ctx->last_scheme = scheme;
}

void shadow_decide(ShadowContext *ctx, const ShadowQuery *q, RGB *through)
{
    double before = ctx->stats.shadow_seconds;
    double t0 = shadow_timer_start(ctx);
    ctx->method->test(ctx, q, through);
    shadow_timer_stop(ctx, t0, ctx->untimed_seconds);
    ctx->untimed_seconds = 0.0;
    ctx->stats.shadow_queries++;
    /* Points at the hits of reflected, refracted and transmitted rays
     * counted apart (their time too: the sampled share and any cell built
     * for them), since their coherence differs from the camera's hits. */
    if (shadow_query_secondary(q)) {
        ctx->stats.shadow_queries_secondary++;
        ctx->stats.shadow_seconds_secondary += ctx->stats.shadow_seconds - before;
    }
    if (ctx->verify)
        shadow_verify(ctx, q, *through);
}

void shadow_decide_skip(ShadowContext *ctx, const ShadowQuery *q, int faces_away)
{
    double t0 = shadow_timer_start(ctx);
    ctx->last_scheme = SCHEME_NONE;
    ctx->method->skip(ctx, q, faces_away);
    shadow_timer_stop(ctx, t0, 0.0);
}
