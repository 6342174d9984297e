/* The registry of shadow methods, and a thread's shadow-testing context. */
#include "shadow.h"

#include "area_light.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "light.h"
#include "shadow_embree.h"
#include "shadow_reference.h"
#include "shadow_volumes.h"
#include "volume_plan.h"

int shadow_context_init(ShadowContext *ctx, Tracer *tracer, const World *w, const Grid *g, const ShadowPrepared *p,
                        int verify, int pixel_coherence)
{
    memset(ctx, 0, sizeof *ctx);
    if (tracer) {
        ctx->tracer = tracer;
    } else {
        ctx->tracer = &ctx->own_tracer;
        ctx->owns_tracer = 1;
        if (tracer_init(ctx->tracer, w, g))
            return -1;
    }
    const ShadowMethod *method = p->decider;
    ctx->method = method;
    ctx->embree = p->embree;
    ctx->cost = p->cost;
    ctx->nth = p->nth;
    ctx->verify = verify;
    ctx->reference_eps = shadow_reference_eps(g);
    ctx->last_blocker = -1;
    int nl = w->nlights > 0 ? w->nlights : 1;
    ctx->light_cache = malloc(sizeof *ctx->light_cache * (size_t)nl);
    if (!ctx->light_cache)
        return -1;
    shadow_cache_forget(ctx, nl);
    /* counted once, by world_build: a context per thread, and the plan's */
    ctx->filtered = malloc(sizeof *ctx->filtered * (size_t)(w->nsee_through + 1));
    if (!ctx->filtered)
        return -1;
    size_t samples = 0;
    for (int i = 0; i < w->nlights; i++)
        if ((size_t)w->lights[i].area.size1 * (size_t)w->lights[i].area.size2 > samples)
            samples = (size_t)w->lights[i].area.size1 * (size_t)w->lights[i].area.size2;
    if (samples) {
        ctx->area_colour = malloc(samples * sizeof *ctx->area_colour);
        ctx->area_known = malloc(samples);
        ctx->area_uniform_visits = calloc((size_t)nl, sizeof *ctx->area_uniform_visits);
        ctx->area_uniform_levels = calloc((size_t)nl, sizeof *ctx->area_uniform_levels);
        ctx->area_fixed_factors = calloc((size_t)nl, sizeof *ctx->area_fixed_factors);
        if (!ctx->area_colour || !ctx->area_known || !ctx->area_uniform_visits || !ctx->area_uniform_levels ||
            !ctx->area_fixed_factors)
            return -1;
        for (int i = 0; i < w->nlights; i++)
            if (area_light_fixed_factors(&w->lights[i], &ctx->area_fixed_factors[i]))
                return -1;
        for (int i = 0; i < w->nlights; i++)
            if (light_is_area(&w->lights[i]))
                area_light_uniform_shape(&w->lights[i], ctx->area_known, &ctx->area_uniform_visits[i],
                                         &ctx->area_uniform_levels[i]);
        if (method && method->area_beam) {
            ctx->area_candidates = malloc(AREA_BEAM_CAP * sizeof *ctx->area_candidates);
            if (!ctx->area_candidates)
                return -1;
        }
    }
    return method && method->thread_init ? method->thread_init(ctx, p, pixel_coherence) : 0;
}

void shadow_context_free(ShadowContext *ctx)
{
    if (ctx->method && ctx->method->thread_free)
        ctx->method->thread_free(ctx);
    const int nlights = ctx->tracer && ctx->tracer->world ? ctx->tracer->world->nlights : 0;
    if (ctx->owns_tracer)
        tracer_free(&ctx->own_tracer);
    ctx->tracer = NULL;
    free(ctx->light_cache);
    free(ctx->area_colour);
    free(ctx->area_known);
    free(ctx->area_candidates);
    free(ctx->area_uniform_visits);
    free(ctx->area_uniform_levels);
    if (ctx->area_fixed_factors)
        for (int i = 0; i < nlights; i++)
            free(ctx->area_fixed_factors[i]);
    free(ctx->area_fixed_factors);
    free(ctx->filtered);
    ctx->light_cache = NULL;
    ctx->filtered = NULL;
}

void shadow_tile_begin(ShadowContext *ctx)
{
    shadow_cache_forget(ctx, ctx->tracer->world->nlights);
}

void shadow_pixel_begin(ShadowContext *ctx, int first_in_row, int first_row)
{
    if (ctx->method->pixel_begin)
        ctx->method->pixel_begin(ctx, first_in_row, first_row);
}

void shadow_pixel_end(ShadowContext *ctx, int first_in_row)
{
    if (ctx->method->pixel_end)
        ctx->method->pixel_end(ctx, first_in_row);
}

LightState *shadow_segment_begin(ShadowContext *ctx, const Hit *hit, int from_eye)
{
    return ctx->method->segment_begin ? ctx->method->segment_begin(ctx, hit, from_eye) : NULL;
}

void shadow_segment_end(ShadowContext *ctx)
{
    if (ctx->method->segment_end)
        ctx->method->segment_end(ctx);
}

void shadow_counters_add(ShadowCounters *t, const ShadowCounters *p)
{
#define SHADOW_COUNTER(field, line, label, key, meaning) t->field += p->field;
#include "shadow_counters.def"
#undef SHADOW_COUNTER
    for (int i = 0; i < SCHEME_COUNT; i++) {
        t->shadow_schemes[i] += p->shadow_schemes[i];
        t->shadow_disagreements_by_scheme[i] += p->shadow_disagreements_by_scheme[i];
    }
    t->shadow_seconds += p->shadow_seconds;
}

/* --shadows=none: every light reaches every point (POV-Ray's +Q3 look). */
static void shadow_none_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    (void)q;
    ctx->last_scheme = SCHEME_CONVENTIONAL;
    light->r = light->g = light->b = 1.0;
}

const char *const shadow_scheme_names[SCHEME_COUNT] = { "sustain",  "self-shadow", "volume",    "conventional",
                                                        "cache hit", "area lit",   "area umbra", "area beam" };

/* The registry: every method, each a row; the first is the default. Only
 * here are methods named; the rest of the program finds them by name
 * (--shadows) and uses them through the row. */
static const ShadowMethod hst_row = {
    .name = "hst",
    .summary = "the paper's hybrid: sustain, self-shadow, shadow volume or shadow ray, switched by N_th",
    .uses_volumes = 1,
    .prepare = shadow_hst_prepare,
    .thread_init = shadow_hst_thread_init,
    .thread_free = shadow_volume_thread_free,
    .pixel_begin = shadow_volume_pixel_begin,
    .pixel_end = shadow_volume_pixel_end,
    .segment_begin = shadow_volume_segment_begin,
    .segment_end = shadow_volume_segment_end,
    .test = shadow_hst_test,
    .skip = shadow_hst_skip,
    .area_beam = 1,
};
static const ShadowMethod conventional_row = {
    .name = "conventional",
    .summary = "a shadow ray per light through the grid (exact reference)",
    .test = shadow_conventional_test,
};
static const ShadowMethod cache_row = {
    .name = "cache",
    .summary = "shadow rays that first try the light's last opaque blocker (as POV-Ray does)",
    .test = shadow_cache_test,
};
static const ShadowMethod volume_row = {
    .name = "volume",
    .summary = "shadow volumes: a depth count carried along every segment",
    .uses_volumes = 1,
    .prepare = shadow_volume_prepare,
    .thread_init = shadow_volume_thread_init,
    .thread_free = shadow_volume_thread_free,
    .segment_begin = shadow_volume_segment_begin,
    .segment_end = shadow_volume_segment_end,
    .test = shadow_volume_test,
    .skip = shadow_volume_skip,
};
static const ShadowMethod embree_row = {
    .name = "embree",
    .summary = "Embree 3's float shadow ray with the shadow ray's rules (not exact: for comparison)",
    .prepare = shadow_embree_prepare,
    .test = shadow_embree_test,
    .inexact = 1,
};
static const ShadowMethod none_row = {
    .name = "none",
    .summary = "no shadows: every light reaches every point",
    .test = shadow_none_test,
    .blind = 1,
};

/* The registry's rows, the first the default; a method is its file (its
 * functions) and one row here. */
static const ShadowMethod *const methods[] = {
    &hst_row, &conventional_row, &cache_row, &volume_row, &embree_row, &none_row, &shadow_every_lit_method,
};

const ShadowMethod *shadow_method_fallback(void)
{
    for (size_t i = 0; i < sizeof methods / sizeof methods[0]; i++)
        if (methods[i]->test == shadow_cache_test)
            return methods[i];
    return methods[0];
}

int shadow_method_prepare(const ShadowMethod *m, const ShadowSetup *s, ShadowPrepared *out, char *err, int errlen)
{
    memset(out, 0, sizeof *out);
    out->decider = m;
    out->nth = s->nth.mode == NTH_PER_POINT ? -1.0 : s->nth.mode == NTH_AUTO ? 0.0 : s->nth.value;
    out->nth_mode = s->nth.mode == NTH_PER_POINT ? "per-point"
                    : s->nth.mode == NTH_AUTO    ? "auto (C_ray / (C_s + C_g))"
                                                 : "fixed";
    out->cost = calloc(1, sizeof *out->cost);
    if (!out->cost) {
        snprintf(err, (size_t)errlen, "out of memory");
        return -1;
    }
    return m->prepare ? m->prepare(m, s, out, err, errlen) : 0;
}

void shadow_prepared_free(ShadowPrepared *p)
{
    if (p->volumes)
        shadow_volumes_free(p->volumes);
    free(p->volumes);
    if (p->plan)
        volume_plan_free(p->plan);
    free(p->plan);
    free(p->cost);
    shadow_embree_free(p->embree);
    memset(p, 0, sizeof *p);
}

const ShadowMethod *shadow_method_find(const char *name)
{
    for (size_t i = 0; i < sizeof methods / sizeof methods[0]; i++)
        if (strcmp(methods[i]->name, name) == 0)
            return methods[i];
    return NULL;
}

const char *shadow_method_unavailable(const ShadowMethod *m)
{
    if (m->prepare == shadow_embree_prepare && !shadow_embree_built())
        return "this hstrace was built without Embree (install the Debian package libembree-dev, then "
               "configure and make again)";
    return NULL;
}

const char *shadow_method_names(void)
{
    return "hst, conventional, cache, volume, embree, none";
}

ShadowRecord shadow_record(const ShadowContext *ctx, const ShadowQuery *q, const RGB *answer)
{
    ShadowRecord r = { ctx->last_scheme, -1 };
    if (r.scheme == SCHEME_NONE)
        return r;
    if (q->segment->state) {
        const LightState *s = &q->segment->state[q->light];
        if (s->depth_known)
            r.depth = s->depth_opaque;
    } else if (answer && !ctx->method->uses_volumes && (answer->r > 0.0 || answer->g > 0.0 || answer->b > 0.0)) {
        r.depth = 0;
    }
    return r;
}
