/* The registry of shadow methods (shadow_registry.h). */
#include "shadow_registry.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "light_buffer.h"
#include "shadow_embree.h"
#include "shadow_volumes.h"
#include "volume_plan.h"

/* --shadows=none: every light reaches every point (POV-Ray's +Q3 look). */
static void shadow_none_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light)
{
    (void)q;
    ctx->last_scheme = SCHEME_CONVENTIONAL;
    light->r = light->g = light->b = 1.0;
}

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
    .instances = 1,
};
static const ShadowMethod none_row = {
    .name = "none",
    .summary = "no shadows: every light reaches every point",
    .test = shadow_none_test,
    .blind = 1,
    .instances = 1,
};

/* The registry's rows, the first the default; a method is its file (its
 * functions) and one row here (the cache's and the test-only method's rows
 * stand in their files: hst hands its decisions to the cache's). */
static const ShadowMethod *const methods[] = {
    &hst_row, &shadow_conventional_method, &shadow_cache_method, &volume_row, &embree_row, &shadow_light_buffer_method, &none_row,
    &shadow_every_lit_method,
};

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
    if (p->light_buffers)
        light_buffers_free(p->light_buffers);
    free(p->light_buffers);
    memset(p, 0, sizeof *p);
}

const ShadowMethod *shadow_method_find(const char *name)
{
    for (size_t i = 0; i < sizeof methods / sizeof methods[0]; i++)
        if (strcmp(methods[i]->name, name) == 0)
            return methods[i];
    return NULL;
}

int shadow_method_takes_instances(const ShadowMethod *m, int volumes_always, int area_lights)
{
    /* hst with no volumes (they want world-space polygons) and no area
     * light (its beams read polygons' planes) decides as the cache does */
    if (m == &hst_row)
        return !volumes_always && !area_lights;
    return m->instances;
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
    return "hst, conventional, cache, volume, embree, light-buffer, none";
}
