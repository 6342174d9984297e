/* The high-precision reference for shadow decisions: the segment from a
 * point to a light tested against every polygon and infinite plane by
 * brute force, in long double, with borders inclusive (a shared edge
 * blocks, as the shadow ray's tie rule says). It knows when it cannot
 * tell: a polygon or plane met within `eps` of its border, of the
 * segment's ends, or edge-on is a tie. Used by --verify-reference and by
 * the randomized agreement test; far too slow to render with. */
#ifndef HST_SHADOW_REFERENCE_H
#define HST_SHADOW_REFERENCE_H

#include "grid.h"
#include "tracer.h"
#include "world.h"

typedef enum { REF_LIT, REF_BLOCKED, REF_TIE } RefAnswer;

/* The margin of ties: 1e-12 of the grid box's largest coordinate (plus 1),
 * a thousand times finer than the engine's default margin. */
long double shadow_reference_eps(const Grid *g);

/* Is light l blocked from the point `at` lies on (at's own polygon or plane
 * excluded)? Transparent objects block too (the answer is only whether
 * any light is taken away); no_shadow objects do not. A clear blocker
 * decides even when some other polygon is a tie. */
RefAnswer shadow_reference(const World *w, const Hit *at, const Light *l, long double eps);

/* Polygon i alone against the segment from p toward l, hits within tmin of
 * p excluded (trace_min_distance). */
RefAnswer shadow_reference_polygon(const World *w, int i, Vec3 p, const Light *l, long double tmin, long double eps);

/* Polygons met (ties count as met) on the way from `at` to the light. */
int shadow_reference_count(const World *w, const Hit *at, const Light *l, long double eps);

#endif
