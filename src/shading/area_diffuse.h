/* area_illumination's diffuse light (POV-Ray's ComputeFullAreaDiffuseLight):
 * each of an area light's size1 x size2 samples lights the point from
 * where it is, with its share of the light that arrived. A 17 x 17 light
 * is 289 directions, each a square root and a division, per shading
 * point: on scenes/soft.pov that loop was two thirds of the render.
 *
 * This is the loop for the common case, a light whose every sample is
 * seen with the same strength (no spotlight cone, no fading, not
 * parallel, not jittered) over finishes that take only diffuse light
 * with brilliance 1. Two versions: the plain one (what shade.c's general
 * loop computes, sample by sample) and a fast one that forms two samples'
 * directions in one SSE2 operation each, with the same operations in the
 * same order per lane, and adds the samples' light into each texture in
 * the plain one's order: the same sums bit for bit
 * (tests/test_area_diffuse.c compares the two). Without SSE2 the fast one
 * is the plain one. */
#ifndef HST_AREA_DIFFUSE_H
#define HST_AREA_DIFFUSE_H

#include "world.h"

/* One texture that takes the light: its shading normal, its pigment, its
 * finish's diffuse and its own share of the light (1 - filter - transmit),
 * and where its light adds up. */
typedef struct {
    Vec3 normal;
    RGB pigment;
    double diffuse; /* > 0 */
    double att;
    RGB *acc;
} AreaDiffuseTexture;

/* The samples' places and what they light: l's location moved by
 * axis1 * f[k][0] + axis2 * f[k][1] (area_light_offset_of) for sample
 * k = u * size2 + v, taken v by v and u by u within; share is each
 * sample's part of the light; a texture takes a sample when it faces it
 * (normal . direction >= POV_EPSILON) or the material is lit on both sides. */
typedef struct {
    const Light *light;
    const double (*factors)[2];
    Vec3 axis1, axis2;
    Vec3 point;
    RGB share;
    int both_sides;
} AreaDiffuseSamples;

/* Whether area_diffuse may stand in for the general loop: a light of
 * constant strength over its samples (a point light, no cone, no fade),
 * its samples' places known (factors), and finishes of diffuse only with
 * brilliance 1. */
int area_diffuse_applies(const Light *l, const double (*factors)[2]);

void area_diffuse_plain(const AreaDiffuseSamples *s, const AreaDiffuseTexture *t, int n);
void area_diffuse(const AreaDiffuseSamples *s, const AreaDiffuseTexture *t, int n);

#endif
