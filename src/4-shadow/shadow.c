/* The registry of shadow methods. */
#include "shadow.h"

#include <string.h>

/* --shadows=none: every light reaches every point (POV-Ray's +Q3 look). */
static void shadow_none_test(TraceContext *ctx, const ShadowQuery *q, RGB *light)
{
    (void)q;
    ctx->last_scheme = SCHEME_CONVENTIONAL;
    light->r = light->g = light->b = 1.0;
}

_Static_assert(SCHEME_COUNT == STATS_SCHEMES, "stats.h counts every scheme");

const char *const shadow_scheme_names[SCHEME_COUNT] = { "sustain", "self-shadow", "volume", "conventional",
                                                        "cache hit" };

/* The first is the default. */
static const ShadowMethod methods[] = {
    { "hst", "the paper's hybrid: sustain, self-shadow, shadow volume or shadow ray, switched by N_th", 1,
      shadow_hst_test, shadow_hst_skip },
    { "conventional", "a shadow ray per light through the grid (exact reference)", 0, shadow_conventional_test, NULL },
    { "cache", "shadow rays that first try the light's last opaque blocker (as POV-Ray does)", 0, shadow_cache_test,
      NULL },
    { "volume", "shadow volumes: a depth count carried along every segment", 1, shadow_volume_test,
      shadow_volume_skip },
    { "none", "no shadows: every light reaches every point", 0, shadow_none_test, NULL },
};

const ShadowMethod *shadow_method_find(const char *name)
{
    for (size_t i = 0; i < sizeof methods / sizeof methods[0]; i++)
        if (strcmp(methods[i].name, name) == 0)
            return &methods[i];
    return NULL;
}

const char *shadow_method_names(void)
{
    return "hst, conventional, cache, volume, none";
}

ShadowRecord shadow_record(const TraceContext *ctx, const ShadowQuery *q, const RGB *answer)
{
    ShadowRecord r = { ctx->last_scheme, -1 };
    if (r.scheme == SCHEME_NONE)
        return r;
    if (q->segment->state) {
        const LightState *s = &q->segment->state[q->light];
        if (s->depth_known)
            r.depth = s->depth_opaque;
    } else if (answer && !ctx->shadow->uses_volumes && (answer->r > 0.0 || answer->g > 0.0 || answer->b > 0.0)) {
        r.depth = 0;
    }
    return r;
}
