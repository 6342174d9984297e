/* Area lights' shadows as POV-Ray 3.7 samples them
 * (Trace::TraceAreaLightShadowRay, TraceAreaLightSubsetShadowRay and
 * ComputeFullAreaDiffuseLight): each sample of the light's grid
 * (area_light_samples.h) a shadow decision of its own. The grid's four
 * corners are decided first; a region is split in four while it is wider than one
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
 * sample's ray is tested against the beam's candidates only. */
#ifndef HST_AREA_LIGHT_H
#define HST_AREA_LIGHT_H

#include "area_light_samples.h"
#include "shadow.h"

/* An area light with a beam to build for hst: at least 2 x 2 samples. */
static inline int light_has_beam(const Light *l) { return l->area.size1 > 1 && l->area.size2 > 1; }

/* area_light_sample_offset through ctx's table when the light has one:
 * the same value, without the grid's divisions. */
static inline Vec3 area_light_offset(const ShadowContext *ctx, const Light *l, int light, Vec3 p, Vec3 axis1,
                                     Vec3 axis2, int u, int v, int stream)
{
    const double(*fixed)[2] = ctx->area_fixed_factors ? ctx->area_fixed_factors[light] : NULL;
    return fixed ? area_light_offset_of(l, axis1, axis2, fixed[u * l->area.size2 + v])
                 : area_light_sample_offset(l, light, p, axis1, axis2, u, v, stream);
}

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
