/* Where an area light's samples lie, as POV-Ray 3.7 places them
 * (Trace::TraceAreaLightShadowRay and ComputeFullAreaDiffuseLight): a grid
 * of size1 x size2 point lights spanning axis1 x axis2 around the light's
 * location (circular: the square's shells mapped onto circles), turned to
 * face the point with orient, each sample moved by jitter. What the shadows
 * of area lights (src/shadow/area_light.h) and area_illumination's diffuse
 * sum (src/shading/area_diffuse.h) both sample.
 *
 * jitter: POV-Ray moves each sample by a random offset of up to half a
 * cell along each axis, from a random number generator, so its images
 * differ from run to run. hstrace draws the offsets from a hash of the
 * shading point, the light and the sample, so that its image is the same
 * for any thread count and every run; it matches POV-Ray's statistically. */
#ifndef HST_AREA_LIGHT_SAMPLES_H
#define HST_AREA_LIGHT_SAMPLES_H

#include <math.h>

#include "world.h"

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

/* The shadow ray from p toward the light's centre moved by offset: the
 * unit direction toward it, and the distance (parallel: to its plane), as
 * POV-Ray's ComputeOneWhiteLightRay. */
double area_light_sample_ray(const Light *l, Vec3 offset, Vec3 p, Vec3 *to_light);
/* *sample, a copy of l, moved there: the point light that ray is aimed at
 * (a parallel light's direction that ray's). */
void area_light_sample_light(const Light *l, Vec3 offset, Vec3 to_light, Light *sample);

/* POV-Ray's halves of [a, b] when its sampling splits a region of the
 * grid: [a, floor of the midpoint] and [its ceiling, b] (so a region one
 * sample wide splits into its two columns). */
static inline void area_light_halves(int a, int b, int *low_end, int *high_start)
{
    *low_end = (int)floor((a + b) / 2.0);
    *high_start = (int)ceil((a + b) / 2.0);
}

/* The samples an area light's sampling visits when they all agree (the
 * corners of every region it is split into, by level alone), and the
 * levels of means that makes; scratch: room for its samples. */
void area_light_uniform_shape(const Light *l, unsigned char *scratch, int *visits, int *levels);

#endif
