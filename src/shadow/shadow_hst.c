/* Shadow volumes with depth counts ("volume") and the paper's hybrid
 * ("hst"): per shading point and light,
 *   sustain       N_s == 0: nothing was crossed, P1's condition holds at P2;
 *   self-shadow   the point faces away from the light: in shadow, depth unknown;
 *   shadow volume N_s <= N_th and (P1 lit or its depth known): count crossings;
 *   conventional  otherwise: fire the shadow ray, depth unknown (0 when lit).
 * N_s is the size of the segment's shadow bucket (shadow polygons in the
 * cells it pierced), plus one when the segment passes through the polygon
 * it starts on into that polygon's shadow.
 *
 * Where a count cannot be trusted the answer comes from the shadow ray
 * instead: a crossing within the tolerance of a shadow polygon's border or
 * plane (counted in statistics as "unsure"), a segment ending outside the
 * grid box, or one arriving on a polygon from the side away from the light
 * (its own volume would be counted at P2, where the shadow ray excludes it). */
#include "shadow.h"

#include <limits.h>

#include "cost_model.h"
#include "shadow_bucket.h"
#include "shadow_coherence.h"
#include "shadow_volumes.h"

static int condition_from_depth(int opaque, int transparent)
{
    return opaque > 0 ? COND_BLOCKED : transparent > 0 ? COND_FILTERED : COND_LIT;
}

static LightState eye_state(const LightVolumes *lv)
{
    LightState s = { COND_UNKNOWN, 0, 0, 0, 0 };
    if (lv->eye_known) {
        s.depth_known = 1;
        s.depth_opaque = lv->eye_opaque;
        s.depth_transparent = lv->eye_transparent;
        s.condition = (int8_t)condition_from_depth(lv->eye_opaque, lv->eye_transparent);
    }
    return s;
}

/* Positive when v points to the light's side of polygon p. */
static double toward_light(const Polygon *p, const OccluderSide *o, Vec3 v)
{
    return o->light_side * v3_dot(p->normal, v);
}

typedef struct {
    LightState from;             /* at P1 */
    uint32_t registrations;      /* of the light's shadow polygons in the pierced cells */
    int cap_opaque, cap_transparent; /* the segment enters the shadow of P1's own polygon */
    int countable;               /* a count can be carried from P1 to P2 */
} SegmentView;

static void view_segment(ShadowContext *ctx, const ShadowQuery *q, SegmentView *v)
{
    const World *w = ctx->tracer->world;
    const LightVolumes *lv = &ctx->volumes->light[q->light];
    const Segment *seg = q->segment;
    v->from = seg->from_state ? seg->from_state[q->light] : eye_state(lv);
    v->registrations = shadow_bucket_registrations(ctx, q->light);
    v->cap_opaque = v->cap_transparent = 0;
    v->countable = ctx->tracer->segment_in_box;
    if (seg->from->kind == HIT_POLYGON) {
        const Polygon *a = &w->polygons[seg->from->index];
        /* A segment running in the plane of the polygon it starts on stays
         * on that polygon's cap: where it crosses an edge cancelled against
         * a bent neighbour the count would be off by one. Rare (grazing
         * rays); the shadow ray decides. */
        if (fabs(v3_dot(a->normal, q->point) - a->d) <= ctx->volumes->tolerance) {
            v->countable = 0;
            ctx->stats.shadow_in_plane++;
        }
        const OccluderSide *o = &lv->occluder[seg->from->index];
        if (o->channel && toward_light(&w->polygons[seg->from->index], o, seg->dir) < 0.0) {
            if (o->channel == 1)
                v->cap_opaque = 1;
            else
                v->cap_transparent = 1;
        }
    }
    if (q->surface->kind == HIT_POLYGON) {
        const OccluderSide *o = &lv->occluder[q->surface->index];
        if (o->channel && toward_light(&w->polygons[q->surface->index], o, seg->dir) > 0.0)
            v->countable = 0;
    }
}

/* depth(P2) = depth(P1) + signed crossings of the n shadow polygons in
 * ctx->bucket. Returns 0 when undecidable. */
static int count_crossings(ShadowContext *ctx, const ShadowQuery *q, const SegmentView *v, int n, LightState *out)
{
    int opaque = v->cap_opaque, transparent = v->cap_transparent;
    if (v->from.depth_known) {
        opaque += v->from.depth_opaque;
        transparent += v->from.depth_transparent;
    } /* else P1 is lit: both counts are 0 there */
    ctx->stats.shadow_volume_tests += (uint64_t)n;
    if (!shadow_bucket_crossings(ctx->volumes, ctx->bucket, n, q->segment->org, q->point, &opaque, &transparent))
        return 0;
    if (opaque < 0 || transparent < 0)
        return 0; /* cannot happen with exact crossings: do not trust it */
    out->depth_known = 1;
    out->self = 0;
    out->depth_opaque = opaque;
    out->depth_transparent = transparent;
    out->condition = (int8_t)condition_from_depth(opaque, transparent);
    return 1;
}

/* The answer for a known polygon condition: planes are tested as the
 * shadow ray tests them, and filtered light is filtered by the ray. */
static void answer(ShadowContext *ctx, const ShadowQuery *q, int condition, RGB *light)
{
    light->r = light->g = light->b = 1.0;
    if (shadow_planes_test(ctx, q, light)) {
        ctx->stats.shadow_blocked++;
        return;
    }
    if (condition == COND_BLOCKED) {
        light->r = light->g = light->b = 0.0;
        ctx->stats.shadow_blocked++;
    } else if (condition == COND_FILTERED) {
        if (shadow_polygons_test(ctx, q, light))
            ctx->stats.shadow_blocked++;
    }
}

/* The shadow ray, and what it tells about the polygons; counts the
 * decision. Where the context has the lights' light buffers (hst's, as
 * its preparation found them worth it), the light's buffer decides the
 * polygon part: the shadow ray's answer, by its cell (shadow_light_buffer.c). */
static void conventional(ShadowContext *ctx, const ShadowQuery *q, LightState *out, RGB *light)
{
    ctx->last_scheme = SCHEME_CONVENTIONAL;
    light->r = light->g = light->b = 1.0;
    out->depth_known = 0;
    out->self = 0;
    out->condition = COND_UNKNOWN;
    int blocked;
    if (ctx->light_buffers) {
        /* (the polygons' part counts its scheme and blocked) */
        int surfaces_blocked;
        ctx->last_filtered = 0;
        blocked = shadow_light_buffer_decide(ctx, q, light, &surfaces_blocked);
        if (surfaces_blocked) {
            ctx->stats.shadow_schemes[SCHEME_CONVENTIONAL]++;
            ctx->stats.shadow_blocked++;
            return;
        }
    } else {
        if (shadow_planes_test(ctx, q, light)) {
            ctx->stats.shadow_schemes[SCHEME_CONVENTIONAL]++;
            ctx->stats.shadow_blocked++;
            return;
        }
        ctx->last_filtered = 0;
        ctx->stats.shadow_schemes[SCHEME_CONVENTIONAL]++;
        blocked = shadow_polygons_test(ctx, q, light);
        ctx->stats.shadow_blocked += (uint64_t)blocked;
    }
    if (blocked) {
        out->condition = COND_BLOCKED;
    } else if (ctx->last_filtered) {
        out->condition = COND_FILTERED;
    } else {
        out->condition = COND_LIT; /* and the counts are 0 */
        out->depth_known = 1;
        out->depth_opaque = out->depth_transparent = 0;
    }
}

/* Self-shadow: the point faces away from the light. Its own polygon then
 * stands between the light and every point behind it that the next
 * segments reach before they cross a shadow polygon, but only if the
 * polygon itself faces away (a smooth normal can disagree with it) and is
 * opaque; `self` records that the blocker is the point's own polygon. */
static void self_shadow(ShadowContext *ctx, const ShadowQuery *q, LightState *out)
{
    ctx->last_scheme = SCHEME_SELF_SHADOW;
    ctx->stats.shadow_schemes[SCHEME_SELF_SHADOW]++;
    out->depth_known = 0;
    out->self = 0;
    out->condition = COND_UNKNOWN;
    if (q->surface->kind != HIT_POLYGON)
        return;
    const LightVolumes *lv = &ctx->volumes->light[q->light];
    const OccluderSide *o = &lv->occluder[q->surface->index];
    /* The ray arrived on the side away from the light. */
    if (o->channel == 1 && toward_light(&ctx->tracer->world->polygons[q->surface->index], o, q->segment->dir) > 0.0) {
        out->condition = COND_BLOCKED;
        out->self = 1;
    }
}

/* A depth count decided: the shadow volume sub-scheme. */
static void decided_by_count(ShadowContext *ctx, const ShadowQuery *q, const LightState *out, RGB *light)
{
    ctx->last_scheme = SCHEME_VOLUME;
    ctx->stats.shadow_schemes[SCHEME_VOLUME]++;
    if (light)
        answer(ctx, q, out->condition, light);
}

typedef enum { MODE_VOLUME, MODE_HYBRID } Mode;

static void decide(ShadowContext *ctx, const ShadowQuery *q, Mode mode, int faces_away, RGB *light)
{
    LightState scratch;
    LightState *out = q->segment->state ? &q->segment->state[q->light] : &scratch;
    if (!ctx->volumes || !ctx->volumes->light[q->light].usable) {
        /* No volumes for this light (none built, or none that pay:
         * volume_plan.h): the shadow ray decides, always. */
        out->depth_known = 0;
        out->self = 0;
        out->condition = COND_UNKNOWN;
        if (light)
            conventional(ctx, q, out, light);
        return;
    }
    SegmentView v;
    view_segment(ctx, q, &v);
    /* A point lying on a polygon besides its own has no count the shadow
     * ray would agree with: decide it by the ray, and keep no count there. */
    int touching = trace_point_touches_other(ctx->tracer, q->surface, ctx->volumes->tolerance);
    if (touching) {
        v.countable = 0;
        ctx->stats.shadow_touching++;
    }
    int from_usable = v.from.condition == COND_LIT || v.from.depth_known;

    if (mode == MODE_HYBRID) {
        /* Sustain. Entering the shadow of P1's own polygon keeps a blocked
         * point blocked; leaving P1's polygon toward the light does not
         * when that polygon was the blocker (self-shadow). */
        int cap = v.cap_opaque || v.cap_transparent;
        int bucket_empty = v.registrations == 0;
        if (bucket_empty && v.countable &&
            ((v.from.condition == COND_LIT && !cap) || (v.from.condition == COND_BLOCKED && (cap || !v.from.self)))) {
            *out = v.from;
            out->self = 0;
            out->depth_opaque += v.cap_opaque;
            out->depth_transparent += v.cap_transparent;
            ctx->last_scheme = SCHEME_SUSTAIN;
            ctx->stats.shadow_schemes[SCHEME_SUSTAIN]++;
            if (light)
                answer(ctx, q, out->condition, light);
            return;
        }
        if (faces_away) {
            self_shadow(ctx, q, out);
            return;
        }
    }
    double nth = HUGE_VAL;
    if (mode == MODE_HYBRID) {
        nth = ctx->nth;
        if (nth < 0.0)
            nth = cost_model_threshold(ctx->cost, cost_model_cells_to_light(ctx->tracer->grid, q->point,
                                                                           &ctx->tracer->world->lights[q->light]));
        /* Pixel coherence: count from the previous pixel's hit when that
         * is cheaper than counting from the eye. */
        if (ctx->coherence && q->segment->from->kind == HIT_NONE && !touching) {
            uint32_t eye_cost = v.countable && from_usable ? v.registrations : UINT32_MAX;
            int r = pixel_coherence_count(ctx, q, nth, eye_cost, out);
            if (r > 0) {
                decided_by_count(ctx, q, out, light);
                return;
            }
            if (r < 0)
                ctx->stats.shadow_coherence_unsure++;
        }
    }
    /* N_s: the bucket, plus the crossing of P1's own polygon. The bucket
     * is filled only when a count may follow. */
    int counted = 0; /* 1 counted, -1 undecidable, 0 not tried */
    if (v.countable && from_usable) {
        int n = shadow_bucket_fill(ctx, q->light, shadow_bucket_limit(nth - v.cap_opaque - v.cap_transparent));
        if (n + v.cap_opaque + v.cap_transparent <= nth)
            counted = count_crossings(ctx, q, &v, n, out) ? 1 : -1;
    }
    if (counted) {
        if (counted > 0) {
            decided_by_count(ctx, q, out, light);
            return;
        }
        ctx->stats.shadow_unsure++;
    } else if (mode == MODE_VOLUME) {
        ctx->stats.shadow_no_count++;
    }
    if (!light) {
        /* Nobody needs the answer here; firing a ray only to keep the state
         * would cost more than it saves later. */
        out->condition = COND_UNKNOWN;
        out->depth_known = 0;
        ctx->stats.shadow_deferred++;
        return;
    }
    conventional(ctx, q, out, light);
    if (touching) {
        out->depth_known = 0;
        out->condition = COND_UNKNOWN;
    }
}

void shadow_volume_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    decide(ctx, q, MODE_VOLUME, 0, light);
}

void shadow_volume_skip(ShadowContext *ctx, const ShadowQuery *q, int faces_away)
{
    (void)faces_away; /* the pure method counts everywhere to keep its depth */
    decide(ctx, q, MODE_VOLUME, 0, NULL);
}

void shadow_hst_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    decide(ctx, q, MODE_HYBRID, 0, light);
}

void shadow_hst_skip(ShadowContext *ctx, const ShadowQuery *q, int faces_away)
{
    decide(ctx, q, MODE_HYBRID, faces_away, NULL);
}
