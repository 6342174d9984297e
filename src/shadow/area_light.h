/* Area lights as POV-Ray 3.7 samples them (Trace::TraceAreaLightShadowRay,
 * TraceAreaLightSubsetShadowRay and ComputeFullAreaDiffuseLight): a grid
 * of size1 x size2 point lights spanning axis1 x axis2 around the light's
 * location, each a shadow decision of its own. The grid's four corners are
 * decided first; a region is split in four while it is wider than one
 * sample and either its level is below `adaptive` (100 unless given: every
 * sample) or two neighbouring corners differ by more than 0.1 (the sum of
 * the channels' differences); a region's light is the mean of its four
 * corners' (a corner shared by regions counts in each). Samples decided
 * once per shading point are kept and reused, as POV-Ray's lightGrid
 * (ShadowContext.area_colour).
 *
 * Every sample is decided by the render's method's test and counted and
 * verified as shadow_decide does, so --verify-shadows checks each against
 * the shadow ray; the shadow-testing time is the whole sampling's, point
 * by point, for every method alike. The shadow
 * volumes belong to point lights: an area light has none, and the
 * methods that keep them decide its samples by the shadow ray. hst builds
 * a beam from the point to the whole light instead (area_light_beam.h):
 * where it proves every sample lit, or every one blocked, no sample's ray
 * is traced (with --verify-shadows each is still checked); elsewhere each
 * sample's ray is tested against the beam's candidates only.
 *
 * jitter: POV-Ray moves each sample by a random offset of up to half a
 * cell along each axis, from a random number generator, so its images
 * differ from run to run. hstrace draws the offsets from a hash of the
 * shading point, the light and the sample, so that its image is the same
 * for any thread count and every run; it matches POV-Ray's statistically. */
#ifndef HST_AREA_LIGHT_H
#define HST_AREA_LIGHT_H

#include "shadow.h"

static inline int light_is_area(const Light *l) { return l->area.size1 > 0; }
/* An area light with a beam to build for hst: at least 2 x 2 samples. */
static inline int light_has_beam(const Light *l) { return l->area.size1 > 1 && l->area.size2 > 1; }

/* The axes the grid spans seen from a point whose unit direction toward
 * the light's centre is centre_dir: the light's own, or with orient,
 * turned to face the point (a square of axis1's length). */
void area_light_axes(const Light *l, Vec3 centre_dir, Vec3 *axis1, Vec3 *axis2);

/* The offset from the light's centre of sample (u, v) of light `light`
 * as seen from p, along axes axis1, axis2 (area_light_axes): the grid
 * position, with jitter moved by up to half a cell along each axis. The
 * jitter is POV-Ray's random offset, here drawn from a hash of p, the
 * light and the sample; stream tells apart the shadow's samples (0) and
 * area_illumination's (1), which POV-Ray draws afresh. */
Vec3 area_light_sample_offset(const Light *l, int light, Vec3 p, Vec3 axis1, Vec3 axis2, int u, int v, int stream);

/* The offset of the sample whose place on the grid is f (the factors of
 * axis1 and axis2, POV-Ray's grid and circular mapping), along the axes
 * seen from a point. */
Vec3 area_light_offset_of(const Light *l, Vec3 axis1, Vec3 axis2, const double f[2]);
/* The most samples of a light whose places a thread keeps
 * (ShadowContext.area_fixed_factors). */
#define AREA_FIXED_CAP 65536
/* *factors: light l's samples' places on the grid (index u * size2 + v)
 * when no point moves them (no jitter; orient turns the axes only) and
 * they are few enough, malloc'd; NULL otherwise. Returns 0, -1 out of
 * memory. */
int area_light_fixed_factors(const Light *l, double (**factors)[2]);
/* area_light_sample_offset through ctx's table when the light has one:
 * the same value, without the grid's divisions. */
static inline Vec3 area_light_offset(const ShadowContext *ctx, const Light *l, int light, Vec3 p, Vec3 axis1,
                                     Vec3 axis2, int u, int v, int stream)
{
    const double(*fixed)[2] = ctx->area_fixed_factors ? ctx->area_fixed_factors[light] : NULL;
    return fixed ? area_light_offset_of(l, axis1, axis2, fixed[u * l->area.size2 + v])
                 : area_light_sample_offset(l, light, p, axis1, axis2, u, v, stream);
}

/* The shadow ray from p toward the light's centre moved by offset: the
 * unit direction toward it, and the distance (parallel: to its plane), as
 * POV-Ray's ComputeOneWhiteLightRay. */
double area_light_sample_ray(const Light *l, Vec3 offset, Vec3 p, Vec3 *to_light);
/* *sample, a copy of l, moved there: the point light that ray is aimed at
 * (a parallel light's direction that ray's). */
void area_light_sample_light(const Light *l, Vec3 offset, Vec3 to_light, Light *sample);

/* The samples an area light's sampling visits when they all agree (the
 * corners of every region it is split into, by level alone), and the
 * levels of means that makes; scratch: room for its samples. */
void area_light_uniform_shape(const Light *l, unsigned char *scratch, int *visits, int *levels);

/* The most polygons an hst beam gathers before it gives up (its samples
 * then decided by the shadow ray through the hierarchy). */
#define AREA_BEAM_CAP 256

/* hst's beam for light l: the method asks for it, and the light has a
 * beam to build (at least 2 x 2 samples). */
static inline int area_light_beamed(const ShadowContext *ctx, const Light *l)
{
    return ctx->area_candidates && light_has_beam(l);
}

/* Some light of w would have hst's beam (at +Q5 and above). */
static inline int world_has_beams(const World *w)
{
    for (int i = 0; i < w->nlights; i++) {
        const Light *l = &w->lights[i];
        if (!l->shadowless && light_has_beam(l))
            return 1;
    }
    return 0;
}

/* The light of colour lc (already attenuated by beam and distance at the
 * centre) that arrives at q's point from area light q->light, sampled as
 * POV-Ray samples it; q asks about the centre (to_light, distance). */
RGB area_light_shadow(ShadowContext *ctx, const ShadowQuery *q, RGB lc);

#endif
