/* A thread's shadow-testing context, the render loop's hooks into its
 * method, the counters' sums and the record of a decision (shadow.h). */
#include "shadow.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "area_light_samples.h"
#include "clock.h"
#include "light.h"
#include "shadow_reference.h"

/* The cache method's memory is the context's, which starts it empty and
 * empties it at every tile (shadow_cache.c reads and fills it). */
void shadow_cache_forget(ShadowContext *ctx, int nlights)
{
    for (int i = 0; i < nlights; i++)
        ctx->light_cache[i] = (LightCache){ .blocker = -1 };
}

/* The least interval two back-to-back reads of the clock show: the
 * clock's own part of a timed decision (shadow_decide.h). */
static double clock_floor(void)
{
    double least = HUGE_VAL;
    for (int i = 0; i < 64; i++) {
        double a = clock_wall(), b = clock_wall();
        if (b - a < least)
            least = b - a;
    }
    return least < 1e-6 ? least : 0.0;
}

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
    ctx->light_buffers = p->light_buffers;
    ctx->cost = p->cost;
    ctx->nth = p->nth;
    ctx->verify = verify;
    ctx->reference_eps = shadow_reference_eps(g);
    ctx->last_blocker = -1;
    ctx->clock_floor = clock_floor();
    int nl = w->nlights > 0 ? w->nlights : 1;
    ctx->light_cache = malloc(sizeof *ctx->light_cache * (size_t)nl);
    if (!ctx->light_cache)
        return -1;
    shadow_cache_forget(ctx, nl);
    if (p->light_buffers) {
        ctx->light_buffer_memo = calloc(2 * LB_MEMO_CELLS * (size_t)nl, sizeof *ctx->light_buffer_memo);
        if (!ctx->light_buffer_memo)
            return -1;
    }
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
    free(ctx->light_buffer_memo);
    ctx->light_buffer_memo = NULL;
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
    t->shadow_seconds_secondary += p->shadow_seconds_secondary;
}

const char *const shadow_scheme_names[SCHEME_COUNT] = { "sustain",  "self-shadow", "volume",    "conventional",
                                                        "cache hit", "area lit",   "area umbra", "area beam",
                                                        "buffer lit", "buffer cover", "buffer list" };

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
