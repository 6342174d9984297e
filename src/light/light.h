/* What the shadow methods and the shading ask of a light before any shadow
 * is decided: is it an area light, and on which side of a polygon does it
 * stand. Below every shadow method (tests/layering.sh), so that the exact
 * shadow ray, the shadow volumes and Embree's filter ask it alike. */
#ifndef HST_LIGHT_H
#define HST_LIGHT_H

#include "world.h"

static inline int light_is_area(const Light *l) { return l->area.size1 > 0; }

/* Which side of polygon p light l is on (a point light by its location, a
 * parallel light by its unit direction toward the light): +1 the normal's
 * side, -1 the other, 0 within tol of p's plane (edge-on). */
int light_side_of(const Polygon *p, const Light *l, double tol);

#endif
