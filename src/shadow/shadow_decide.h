/* A shadow decision as the shading asks for it: the method's test (or its
 * skip), timed, counted, and checked against the shadow ray when
 * --verify-shadows is on (and against the long-double reference with
 * --verify-reference). Every method is called through here, so that the
 * statistics and the verification are the same for all of them. */
#ifndef HST_SHADOW_DECIDE_H
#define HST_SHADOW_DECIDE_H

#include "clock.h"
#include "shadow.h"

/* Shadow-testing time is estimated from every 31st decision (or area
 * light's sampling at one point), timed and scaled: reading the clock
 * around each one would cost as much as a cheap decision (sustain)
 * itself, and would inflate every method's figure. The monotonic clock is
 * read in user space (vDSO); the thread CPU clock would be a system call.
 * The stride is prime so that it does not keep step with a shading point's
 * lights (with 8, a scene of 4 or 8 lights timed the same light's
 * decisions over and over); at 31 the clock costs about 1.5 ns a decision
 * instead of 6.
 *
 * A timed sample's interval also holds the clock's own read (some 20 ns
 * on this project's machines, as much as a cheap decision), which would
 * stand in every method's figure as a floor: each sample is taken less the
 * least interval two reads back to back show (ShadowContext.clock_floor,
 * measured when the context is made), so that the figure is the
 * deciding's. */
#define SHADOW_TIMING_STRIDE 31

/* The clock when this decision is one to time, else -1. */
static inline double shadow_timer_start(ShadowContext *ctx)
{
    if (ctx->shadow_timer) {
        ctx->shadow_timer--;
        return -1.0;
    }
    ctx->shadow_timer = SHADOW_TIMING_STRIDE - 1;
    return clock_wall();
}

/* A timed decision's time since t0, less `excluded` seconds spent in it on
 * other work (verification), scaled by the stride into the statistics. */
static inline void shadow_timer_stop(ShadowContext *ctx, double t0, double excluded)
{
    if (t0 >= 0.0)
        ctx->stats.shadow_seconds += SHADOW_TIMING_STRIDE * (clock_wall() - t0 - excluded - ctx->clock_floor);
}

/* How much of q's light arrives (shadow.h); sets ctx->last_scheme. */
void shadow_decide(ShadowContext *ctx, const ShadowQuery *q, RGB *through);

/* --verify-shadows for a decision made without the method's test (hst's
 * area lights): `got` against the shadow ray's answer (and the reference's
 * with --verify-reference), by ctx->last_scheme. */
void shadow_verify(ShadowContext *ctx, const ShadowQuery *q, RGB got);

/* The shading needs no answer for q's light: the method keeps its states
 * consistent (ShadowMethod.skip, which must not be NULL here). */
void shadow_decide_skip(ShadowContext *ctx, const ShadowQuery *q, int faces_away);

#endif
