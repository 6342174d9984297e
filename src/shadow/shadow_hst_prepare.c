/* Preparing the volume methods, hst and volume (shadow.h): the volume plan
 * builds the lights' shadow volumes (every light's, or only those that
 * pay: volume_plan.h), calibrates the cost model and settles N_th; in a
 * render spread over processes the leader's choices are handed to the
 * others; and hst with nothing built hands its decisions to the fallback. */
#include "shadow.h"

#include "area_light.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clock.h"
#include "volume_plan.h"

/* What the leader's plan chose, for the other processes. */
typedef struct {
    int have_volumes;
    double nth;
    CostModel cost;
} VolumeChoice;

/* The leader sends, the others rebuild: the lights built, then the same
 * ones dropped, with the same planes, cost model and N_th. Returns 0, or
 * -1 when out of memory (in this process). */
static int share_volume_choices(const ShadowSetup *s, ShadowPrepared *out)
{
    VolumeChoice c;
    memset(&c, 0, sizeof c);
    const World *w = s->world;
    int n = w->nlights;
    int8_t *flags = calloc((size_t)(2 * n + 1), 1); /* per light: built, then dropped */
    if (!flags)
        return -1;
    ShadowVolumes *sv = out->volumes;
    if (s->leader) {
        c.have_volumes = sv->light != NULL;
        c.nth = out->nth;
        c.cost = *out->cost;
        for (int li = 0; c.have_volumes && li < n; li++) {
            flags[li] = !sv->light[li].not_wanted;
            flags[n + li] = (int8_t)sv->light[li].dropped;
        }
    }
    s->broadcast(&c, sizeof c);
    s->broadcast(flags, (size_t)(2 * n));
    int status = 0;
    if (!s->leader) {
        out->nth = c.nth;
        *out->cost = c.cost;
        if (c.have_volumes) {
            /* the registrations pixel coherence reads (the leader's plan made its own) */
            status = grid_register(s->grid, w, s->threads) ||
                     shadow_volumes_build(sv, w, s->grid, s->eye, s->threads, flags) ||
                     shadow_volumes_set_precision(sv, (PlanePrecision)s->precision);
            for (int li = 0; status == 0 && li < n; li++)
                if (flags[n + li])
                    shadow_volumes_drop_light(sv, li);
        }
    }
    free(flags);
    return status ? -1 : 0;
}

static int prepare_volumes(const ShadowSetup *s, VolumesMode mode, ShadowPrepared *out, char *err, int errlen)
{
    if (!s->shadows_on)
        return 0;
    out->volumes = calloc(1, sizeof *out->volumes);
    if (!out->volumes) {
        snprintf(err, (size_t)errlen, "out of memory");
        return -1;
    }
    if (!s->broadcast || s->leader) {
        out->plan = calloc(1, sizeof *out->plan);
        if (!out->plan) {
            snprintf(err, (size_t)errlen, "out of memory");
            return -1;
        }
        VolumePlanOptions po = { mode, s->width, s->height, s->threads, s->precision, s->nth };
        double t_plan = clock_wall();
        int failed = volume_plan_build(out->plan, out->volumes, out->cost, s->world, s->grid, s->bvh, s->eye, &po);
        out->plan_seconds = clock_wall() - t_plan;
        if (failed) {
            snprintf(err, (size_t)errlen, "out of memory while building shadow volumes");
            return -1;
        }
        out->volumes_seconds = out->plan->build_seconds;
        if (out->volumes->light && s->nth.mode == NTH_AUTO)
            out->nth = out->cost->nth_ray;
    }
    if (s->broadcast && share_volume_choices(s, out)) {
        snprintf(err, (size_t)errlen, "out of memory while building shadow volumes");
        return -1;
    }
    if (!out->volumes->light) { /* none built, or none usable */
        shadow_volumes_free(out->volumes);
        free(out->volumes);
        out->volumes = NULL;
    }
    return 0;
}

int shadow_volume_prepare(const ShadowMethod *self, const ShadowSetup *s, ShadowPrepared *out, char *err,
                          int errlen)
{
    (void)self;
    return prepare_volumes(s, VOLUMES_ALWAYS, out, err, errlen);
}

/* Whether hst keeps light buffers: where their building and their memory,
 * which grow with the polygons the lights see, are repaid by the decisions,
 * which grow with the pixels. Measured (ns per decision, 640x480, 1
 * thread, the light buffer against the shadow ray and the cache method,
 * which hst uses without buffers): the paper's scenes (0.0006 to 0.03
 * polygons per pixel) 0.49x to 0.86x the shadow ray's; make-mesh x 4
 * lights, 10^4 triangles (0.033) 104.6 ns against the shadow ray's 141.1
 * and the cache's 121.6, 2x10^4 (0.065) 163.1 against 158.0 and 142.0,
 * 3x10^4 (0.098) 200.7 against 177.8 and 170.1 (medians of 3). So up to
 * one polygon in 20 pixels; the cache method beyond. */
#define HST_LIGHT_BUFFER_POLYGONS_PER_PIXEL 0.05

static int light_buffers_pay(const ShadowSetup *s)
{
    int point_lights = 0;
    for (int i = 0; i < s->world->nlights; i++)
        point_lights += s->world->lights[i].kind == LIGHT_POINT && !s->world->lights[i].shadowless;
    /* the polygons the lights see: instances' too (instance.h) */
    const World *w = s->world;
    double polygons = w->nids > w->npolygons ? w->nids : w->npolygons;
    return point_lights > 0 && polygons <= HST_LIGHT_BUFFER_POLYGONS_PER_PIXEL * (double)s->width * (double)s->height;
}

/* Whether hst tries the lights' last blockers first (the cache method)
 * rather than the shadow ray alone: where a blocker is likely to block the
 * next points too, which polygons much smaller than a pixel are not (the
 * neighbouring pixels' shadow rays pass other ones). Measured (callgrind,
 * 640x480, 1 thread, the cache method against the shadow ray): make-mesh
 * 10^5 triangles x 4 lights (0.33 polygons a pixel) 0.987x, its 63,064
 * hits repaying the tries; 10^6 x 8 (3.3 a pixel) 1.026x in shadow
 * testing, 1,553 hits in 1,526,077 decisions. So below one polygon a
 * pixel. */
#define HST_CACHE_POLYGONS_PER_PIXEL 1.0

static int cache_pays(const ShadowSetup *s)
{
    const World *w = s->world;
    double polygons = w->nids > w->npolygons ? w->nids : w->npolygons;
    return polygons < HST_CACHE_POLYGONS_PER_PIXEL * (double)s->width * (double)s->height;
}

int shadow_hst_prepare(const ShadowMethod *self, const ShadowSetup *s, ShadowPrepared *out, char *err, int errlen)
{
    /* A world with instances (shadow_method_takes_instances) gets no
     * volumes, which want world-space polygons: its decisions are the
     * light buffer's or the cache method's, as below. */
    if (s->world->ninstances == 0 &&
        prepare_volumes(s, s->volumes_always ? VOLUMES_ALWAYS : VOLUMES_AUTO, out, err, errlen))
        return -1;
    /* The lights' light buffers, where they pay: hst's decisions by the
     * shadow ray (lights without volumes, and where a count does not
     * pay) are then the light buffer's, exactly the same answers. */
    if (s->shadows_on && light_buffers_pay(s) && shadow_light_buffer_prepare(self, s, out, err, errlen))
        return -1;
    /* hst with no light whose volumes pay (and no area light for its
     * beams) hands its decisions to the light buffer's method, or without
     * buffers to the cache method's (the shadow ray with the light's last
     * opaque blocker tried first, shadow_cache.c), without hst's
     * per-decision wrapper: the same decisions and images. */
    if (!out->volumes && !world_has_beams(s->world))
        out->decider = out->light_buffers ? &shadow_light_buffer_method
                       : cache_pays(s)    ? &shadow_cache_method
                                          : &shadow_conventional_method;
    return 0;
}
