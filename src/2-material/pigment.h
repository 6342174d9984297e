/* Pigments: POV-Ray 3.7's checker, hexagon, gradient, noise (bozo, granite,
 * wrinkles, agate, marble, wood) and spiral patterns with turbulence and
 * colour maps, evaluated at a point (pattern.cpp, warps.cpp and pigment.cpp
 * there). */
#ifndef HST_PIGMENT_H
#define HST_PIGMENT_H

#include "scene.h"
#include "world.h"

/* The pattern's value at a point in pattern space (after the pigment's
 * transforms, before its turbulence), after frequency, phase and wave:
 * checker 0 or 1, hexagon 0, 1 or 2, the others in [0, 1]. A noise
 * generator of 0 stands for POV-Ray's default, 2. */
double pattern_value(const Pigment *pig, Vec3 p);

/* pattern_value in two steps, as POV-Ray's normals take it: the point
 * displaced by the pattern's turbulence (Warp_EPoint after the transform),
 * then the value at a point so displaced (Evaluate_TPat), with the noise
 * generator `default_generator` where the pattern names none. */
Vec3 pattern_warp(const Pigment *pig, Vec3 p);
double pattern_value_warped(const Pigment *pig, Vec3 p, int default_generator);

/* An image_map's or bump_map's picture (map_type 0): where point p of
 * pattern space falls on it, in pixels from its top left (POV-Ray's
 * map_pos); 0 when off a picture used `once`. */
int image_map_position(const Pigment *pig, Vec3 p, double *x, double *y);
/* Its colour there, interpolated as the pigment says. */
Colour image_colour_at(const Pigment *pig, double x, double y);

/* The colour at a point in pattern space (solid pigments: their colour). */
Colour pigment_at(const Pigment *pig, Vec3 p);

/* The uv coordinates (u, v, 0) of a world-space point on a polygon (its
 * mesh uv vectors or box mapping), or, for a polygon without them (-1) and
 * for planes, POV-Ray's default: the point's world x and y. */
Vec3 surface_uv(const World *w, int polygon, Vec3 world_point);

/* A material's colour at a world-space point on polygon `polygon` (-1: an
 * infinite plane). */
Colour material_colour_at(const World *w, const Material *m, int polygon, Vec3 world_point);

/* What a sky sphere and the background show in direction `dir` (unit),
 * without an alpha channel (POV-Ray 3.7's ComputeSky, version >= 3.7). */
RGB sky_colour(const World *w, Vec3 dir);
/* The same over another opaque background colour: with an alpha channel
 * POV-Ray 3.7 keeps the background's colour as given, and reflected rays
 * see it opaque, not composited on black. */
RGB sky_colour_over(const World *w, Vec3 dir, RGB below);
/* The same seen with an alpha channel (+UA): the background with its own
 * filter and transmit, and what the sky and background together let
 * through, as POV-Ray 3.7 gives it (POV-Ray 3.6's scenes: nothing at all,
 * transmit 1). */
RGB sky_colour_alpha(const World *w, Vec3 dir, double *transmit);

#endif
