/* The registry of shadow methods, and a thread's shadow-testing context. */
#include "shadow.h"

#include "area_light.h"

#include <stdlib.h>
#include <string.h>

#include "shadow_embree.h"
#include "shadow_volumes.h"

/* Enough for max_trace_level reflections plus continued (same-ior) rays;
 * deeper points keep no state and their methods use the shadow ray. */
#define STATE_DEPTH 64

int shadow_context_init(ShadowContext *ctx, const World *w, const Grid *g, const ShadowMethod *method,
                        const ShadowVolumes *volumes)
{
    memset(ctx, 0, sizeof *ctx);
    if (tracer_init(&ctx->tracer, w, g))
        return -1;
    ctx->method = method;
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
        /* method NULL: a context that only gathers (the cost model's
         * timing of C_g), which shades no area light */
        if (method && method->area_beam) {
            ctx->area_candidates = malloc(AREA_BEAM_CAP * sizeof *ctx->area_candidates);
            if (!ctx->area_candidates)
                return -1;
        }
    }
    if (volumes) {
        ctx->volumes = volumes;
        int most = 1;
        for (int i = 0; i < volumes->nlights; i++)
            if (volumes->light[i].count > most)
                most = volumes->light[i].count;
        ctx->sp_stamp = calloc((size_t)(volumes->npolygons > 0 ? volumes->npolygons : 1), sizeof(uint32_t));
        ctx->bucket = malloc(sizeof(uint32_t) * (size_t)most);
        ctx->states = calloc((size_t)nl * STATE_DEPTH, sizeof(LightState));
        if (tracer_record_cells(&ctx->tracer, volumes->box_min, volumes->box_max) || !ctx->sp_stamp ||
            !ctx->bucket || !ctx->states)
            return -1;
        ctx->state_capacity = STATE_DEPTH;
    }
    return 0;
}

void shadow_context_free(ShadowContext *ctx)
{
    const int nlights = ctx->tracer.world ? ctx->tracer.world->nlights : 0; /* before the tracer goes */
    tracer_free(&ctx->tracer);
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
    free(ctx->bucket);
    free(ctx->sp_stamp);
    free(ctx->states);
    ctx->light_cache = NULL;
    ctx->filtered = NULL;
    ctx->bucket = NULL;
    ctx->sp_stamp = NULL;
    ctx->states = NULL;
}

void shadow_counters_add(ShadowCounters *t, const ShadowCounters *p)
{
    t->shadow_queries += p->shadow_queries;
    t->shadow_rays += p->shadow_rays;
    t->shadow_blocked += p->shadow_blocked;
    t->shadow_polygon_tests += p->shadow_polygon_tests;
    for (int i = 0; i < SCHEME_COUNT; i++) {
        t->shadow_schemes[i] += p->shadow_schemes[i];
        t->shadow_disagreements_by_scheme[i] += p->shadow_disagreements_by_scheme[i];
    }
    t->shadow_volume_tests += p->shadow_volume_tests;
    t->shadow_bucket_polygons += p->shadow_bucket_polygons;
    t->shadow_unsure += p->shadow_unsure;
    t->shadow_coherent += p->shadow_coherent;
    t->shadow_touching += p->shadow_touching;
    t->area_points += p->area_points;
    t->area_samples += p->area_samples;
    t->area_beams += p->area_beams;
    t->area_beam_lit += p->area_beam_lit;
    t->area_beam_umbra += p->area_beam_umbra;
    t->area_beam_candidates += p->area_beam_candidates;
    t->area_beam_overflows += p->area_beam_overflows;
    t->shadow_in_plane += p->shadow_in_plane;
    t->shadow_coherence_unsure += p->shadow_coherence_unsure;
    t->shadow_no_count += p->shadow_no_count;
    t->shadow_deferred += p->shadow_deferred;
    t->shadow_verified += p->shadow_verified;
    t->shadow_disagreements += p->shadow_disagreements;
    t->reference_ties += p->reference_ties;
    t->reference_wrong += p->reference_wrong;
    t->reference_ray_wrong += p->reference_ray_wrong;
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

/* The first is the default. */
static const ShadowMethod methods[] = {
    { "hst", "the paper's hybrid: sustain, self-shadow, shadow volume or shadow ray, switched by N_th", 1,
      shadow_hst_test, shadow_hst_skip, 0, 1 },
    { "conventional", "a shadow ray per light through the grid (exact reference)", 0, shadow_conventional_test, NULL, 0, 0 },
    { "cache", "shadow rays that first try the light's last opaque blocker (as POV-Ray does)", 0, shadow_cache_test,
      NULL, 0, 0 },
    { "volume", "shadow volumes: a depth count carried along every segment", 1, shadow_volume_test,
      shadow_volume_skip, 0, 0 },
    { "embree", "Embree 3's float shadow ray with the shadow ray's rules (not exact: for comparison)", 0,
      shadow_embree_test, NULL, 1, 0 },
    { "none", "no shadows: every light reaches every point", 0, shadow_none_test, NULL, 0, 0 },
};

const ShadowMethod *shadow_method_find(const char *name)
{
    for (size_t i = 0; i < sizeof methods / sizeof methods[0]; i++)
        if (strcmp(methods[i].name, name) == 0)
            return &methods[i];
    return NULL;
}

const char *shadow_method_unavailable(const ShadowMethod *m)
{
    if (m->test == shadow_embree_test && !shadow_embree_built())
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
