/* Fog: what POV-Ray 3.7's fog does to the colour seen along a ray through
 * the atmosphere (its ComputeFog, with constant and ground fog). */
#ifndef HST_FOG_H
#define HST_FOG_H

#include "shade.h"
#include "world.h"

/* Blends every fog of w into *seen, the colour found at `depth` along the
 * ray org + t dir (HUGE_VAL: the ray hit nothing). */
void fog_apply(const World *w, Vec3 org, Vec3 dir, double depth, Radiance *seen);

#endif
