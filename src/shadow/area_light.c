/* Area lights sampled as POV-Ray 3.7 samples them (area_light.h). */
#include "area_light.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "area_light_beam.h"
#include "clock.h"
#include "shadow_decide.h"

/* How the samples are decided: by the method's test, by a shadow ray
 * against the beam's candidates, or (under --verify-shadows) already
 * proved, the proof checked sample by sample. */
typedef enum { BY_METHOD, BY_BEAM, BY_PROOF } Decider;

/* What one sampling of an area light at one point shares. */
typedef struct {
    ShadowContext *ctx;
    const ShadowQuery *q;
    const Light *light;
    Vec3 axis1, axis2;
    RGB lc;
    Decider by;
    const uint32_t *candidates; /* BY_BEAM */
    int ncandidates;
    int planes_clear;           /* BY_BEAM: no infinite plane can come between the point and a sample */
    int scheme;                 /* BY_PROOF: SCHEME_AREA_LIT or SCHEME_AREA_UMBRA */
    double verify_seconds;      /* spent checking decisions made here */
    Light sample;               /* the light moved to the current sample */
} Sampling;

/* One sample's decision, counted as shadow_decide counts one, and
 * verified; its time is the whole point's (area_light_shadow), so that
 * every method's figure holds the same work. */
static void decide(Sampling *s, const ShadowQuery *q, RGB *through)
{
    ShadowContext *ctx = s->ctx;
    if (s->by == BY_METHOD) {
        ctx->method->test(ctx, q, through);
    } else if (s->by == BY_BEAM) {
        *through = (RGB){ 1.0, 1.0, 1.0 };
        if ((!s->planes_clear && shadow_planes_test(ctx, q, through)) ||
            shadow_polygons_test_among(ctx, q, s->candidates, s->ncandidates, through))
            ctx->stats.shadow_blocked++;
        ctx->last_scheme = SCHEME_AREA_BEAM;
    } else {
        double v = s->scheme == SCHEME_AREA_LIT ? 1.0 : 0.0;
        *through = (RGB){ v, v, v };
        ctx->last_scheme = s->scheme;
    }
    if (s->by != BY_METHOD)
        ctx->stats.shadow_schemes[ctx->last_scheme]++; /* the method's test counts its own */
    ctx->stats.shadow_queries++;
    if (ctx->verify) {
        double t0 = clock_wall(); /* the check's time is not the method's */
        shadow_verify(ctx, q, *through);
        s->verify_seconds += clock_wall() - t0;
    }
}

static RGB sample_at(Sampling *s, int u, int v)
{
    const Light *l = s->light;
    int at = u * l->area.size2 + v;
    if (s->ctx->area_known[at])
        return s->ctx->area_colour[at];
    ShadowQuery q = *s->q;
    Vec3 offset = area_light_offset(s->ctx, l, q.light, q.point, s->axis1, s->axis2, u, v, 0);
    q.distance = area_light_sample_ray(l, offset, q.point, &q.to_light);
    area_light_sample_light(l, offset, q.to_light, &s->sample);
    q.source = &s->sample;
    RGB through;
    decide(s, &q, &through);
    s->ctx->stats.area_samples++;
    RGB c = { s->lc.r * through.r, s->lc.g * through.g, s->lc.b * through.b };
    s->ctx->area_colour[at] = c;
    s->ctx->area_known[at] = 1;
    return c;
}

static double colour_distance(RGB a, RGB b) { return fabs(a.r - b.r) + fabs(a.g - b.g) + fabs(a.b - b.b); }

/* POV-Ray's mean of a region's four corners */
static double mean4(double a, double b, double c, double d) { return (a + b + c + d) * 0.25; }

/* The region [u1, u2] x [v1, v2] of the grid at subdivision level `level`. */
static RGB sample_region(Sampling *s, int u1, int v1, int u2, int v2, int level)
{
    RGB c[4] = { sample_at(s, u1, v1), sample_at(s, u2, v1), sample_at(s, u1, v2), sample_at(s, u2, v2) };
    if ((u2 - u1 > 1 || v2 - v1 > 1) &&
        (level < s->light->area.adaptive || colour_distance(c[0], c[1]) > 0.1 || colour_distance(c[1], c[3]) > 0.1 ||
         colour_distance(c[3], c[2]) > 0.1 || colour_distance(c[2], c[0]) > 0.1)) {
        int ul, uh, vl, vh;
        area_light_halves(u1, u2, &ul, &uh);
        area_light_halves(v1, v2, &vl, &vh);
        c[0] = sample_region(s, u1, v1, ul, vl, level + 1);
        c[1] = sample_region(s, uh, v1, u2, vl, level + 1);
        c[2] = sample_region(s, u1, vh, ul, v2, level + 1);
        c[3] = sample_region(s, uh, vh, u2, v2, level + 1);
    }
    RGB mean = { mean4(c[0].r, c[1].r, c[2].r, c[3].r), mean4(c[0].g, c[1].g, c[2].g, c[3].g),
                 mean4(c[0].b, c[1].b, c[2].b, c[3].b) };
    return mean;
}

/* The whole grid sampled, from no sample known. */
static RGB sample_grid(Sampling *s)
{
    const Light *l = s->light;
    memset(s->ctx->area_known, 0, (size_t)l->area.size1 * (size_t)l->area.size2);
    return sample_region(s, 0, 0, l->area.size1 - 1, l->area.size2 - 1, 0);
}

/* The sampling's answer when every sample is lc: the chain of means. */
static RGB uniform_answer(RGB lc, int levels)
{
    for (int i = 0; i < levels; i++) {
        lc.r = mean4(lc.r, lc.r, lc.r, lc.r);
        lc.g = mean4(lc.g, lc.g, lc.g, lc.g);
        lc.b = mean4(lc.b, lc.b, lc.b, lc.b);
    }
    return lc;
}

/* hst: the beam's proofs, else its candidates (area_light_beam.h). */
static RGB beam_sampling(Sampling *s)
{
    ShadowContext *ctx = s->ctx;
    const World *w = ctx->tracer->world;
    const ShadowQuery *q = s->q;
    int li = q->light;
    AreaBeam beam;
    if (area_beam_init(&beam, s->light, q->point, s->axis1, s->axis2, grid_tolerance(ctx->tracer->grid)))
        return sample_grid(s);
    int exclude = q->surface->kind == HIT_POLYGON ? q->surface->index : -1;
    int n = area_beam_gather(&beam, w, ctx->tracer->bvh, exclude, ctx->area_candidates, AREA_BEAM_CAP,
                             &ctx->tracer->stats.nodes_visited);
    if (n < 0) {
        ctx->stats.area_beam_overflows++;
        s->by = BY_METHOD;
        return sample_grid(s);
    }
    ctx->stats.area_beams++;
    ctx->stats.area_beam_candidates += (uint64_t)n;
    /* the candidates the beam passes wholly beside are none; one it
     * passes wholly through, opaque, blocks every sample */
    int scheme = -1, kept = 0;
    for (int i = 0; i < n; i++) {
        uint32_t pi = ctx->area_candidates[i];
        int how = area_beam_classify(&beam, w, pi);
        if (how == BEAM_COVERED && w->materials[w->polygons[pi].material].opaque) {
            scheme = SCHEME_AREA_UMBRA;
            break;
        }
        if (how != BEAM_MISSES)
            ctx->area_candidates[kept++] = pi;
    }
    int planes_clear = 0;
    if (scheme < 0) {
        n = kept;
        /* what proves a point lit also spares each sample's ray the planes */
        planes_clear = area_beam_planes_clear(&beam, w, q->surface->kind == HIT_PLANE ? q->surface->index : -1);
        if (n == 0 && planes_clear)
            scheme = SCHEME_AREA_LIT;
    }
    if (scheme >= 0) {
        if (scheme == SCHEME_AREA_LIT)
            ctx->stats.area_beam_lit++;
        else
            ctx->stats.area_beam_umbra++;
        RGB none = { 0.0, 0.0, 0.0 };
        RGB answer = scheme == SCHEME_AREA_LIT ? uniform_answer(s->lc, ctx->area_uniform_levels[li]) : none;
        if (ctx->verify) {
            /* every sample the sampling visits, checked against its ray */
            s->by = BY_PROOF;
            s->scheme = scheme;
            (void)sample_grid(s);
            return answer;
        }
        uint64_t visits = (uint64_t)ctx->area_uniform_visits[li];
        ctx->stats.shadow_queries += visits;
        ctx->stats.shadow_schemes[scheme] += visits;
        ctx->stats.area_samples += visits;
        ctx->last_scheme = scheme;
        return answer;
    }
    s->by = BY_BEAM;
    s->planes_clear = planes_clear;
    s->candidates = ctx->area_candidates;
    s->ncandidates = n;
    return sample_grid(s);
}

RGB area_light_shadow(ShadowContext *ctx, const ShadowQuery *q, RGB lc)
{
    const Light *l = &ctx->tracer->world->lights[q->light];
    Sampling s = { ctx, q, l, l->area.axis1, l->area.axis2, lc, BY_METHOD, NULL, 0, 0, 0, 0.0, *l };
    area_light_axes(l, q->to_light, &s.axis1, &s.axis2);
    ctx->stats.area_points++;
    double t0 = shadow_timer_start(ctx);
    RGB c = area_light_beamed(ctx, l) ? beam_sampling(&s) : sample_grid(&s);
    shadow_timer_stop(ctx, t0, s.verify_seconds);
    return c;
}
