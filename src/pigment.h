/* Pigments: POV-Ray 3.7's checker, hexagon and gradient patterns and colour
 * maps, evaluated at a point (pattern.cpp and pigment.cpp there). */
#ifndef HST_PIGMENT_H
#define HST_PIGMENT_H

#include "scene.h"
#include "world.h"

/* The colour of a map at `value` (POV-Ray's Search_Blend_Map, then linear
 * interpolation between the two entries around the value). */
Colour colour_map_at(const ColourMapEntry *map, int n, double value);

/* The pattern's value at a point in pattern space, after frequency, phase
 * and wave: checker 0 or 1, hexagon 0, 1 or 2, gradient in [0, 1]. */
double pattern_value(const Pigment *pig, Vec3 p);

/* The colour at a point in pattern space (solid pigments: their colour). */
Colour pigment_at(const Pigment *pig, Vec3 p);

/* Whether every colour the pigment can give is opaque (no filter, no
 * transmit): then it blocks light fully wherever it is hit. */
int pigment_is_opaque(const Pigment *pig);

/* A material's colour at a world-space point on it. */
Colour material_colour_at(const Material *m, Vec3 world_point);

/* What a sky sphere and the background show in direction `dir` (unit),
 * without an alpha channel (POV-Ray 3.7's ComputeSky, version >= 3.7). */
RGB sky_colour(const World *w, Vec3 dir);

#endif
