/* A shadow decision as the shading asks for it: the method's test (or its
 * skip), timed, counted, and checked against the shadow ray when
 * --verify-shadows is on (and against the long-double reference with
 * --verify-reference). Every method is called through here, so that the
 * statistics and the verification are the same for all of them. */
#ifndef HST_SHADOW_DECIDE_H
#define HST_SHADOW_DECIDE_H

#include "shadow.h"

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
