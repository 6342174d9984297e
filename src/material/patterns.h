/* The patterns of POV-Ray 3.7's pattern.cpp beyond pigment.c's own
 * (checker, hexagon, gradient, the noise patterns, the spirals): each
 * pattern's raw value at a point of pattern space, after the warps and
 * before frequency, phase and wave (Evaluate_TPat applies those, as
 * pattern_value_warped does). One file per family:
 *
 *   pattern_shapes.c   leopard, onion, radial, planar, spherical,
 *                      cylindrical, boxed, quilted: closed forms of the point
 *   pattern_tiles.c    brick, square, triangular, cubic: tilings
 *   pattern_waves.c    ripples and waves, and their wave sources
 *   pattern_cells.c    cells and crackle: random points per unit cube
 *   pattern_fractal.c  mandel, julia, magnet
 *
 * dents (noise cubed) and pigment_pattern (another pigment's grey) are
 * pigment.c's, beside the noise and the pigments they use. */
#ifndef HST_PATTERNS_H
#define HST_PATTERNS_H

#include "scene.h"

/* POV-Ray's FLOOR macro: floor() written so that exact negative integers
 * land one lower (FLOOR(-2) is -3), as POV-Ray's do. */
double pattern_floor(double x);

double leopard_value(Vec3 p);
double onion_value(Vec3 p);
double radial_value(Vec3 p);
double planar_value(Vec3 p);
double spherical_value(Vec3 p);
double cylindrical_value(Vec3 p);
double boxed_value(Vec3 p);
double quilted_value(const Pigment *pig, Vec3 p);
/* POV-Ray's quilt_cubic: the rounding of quilted's cubes, its pattern and
 * its normal. */
double quilt_cubic(double t, double control0, double control1);

double brick_value(const Pigment *pig, Vec3 p);
double square_value(Vec3 p);
double triangular_value(Vec3 p);
double cubic_value(Vec3 p);

/* The wave sources that ripples and waves sum (POV-Ray's
 * Initialize_Waves), for MAX_NUMBER_OF_WAVES sources, made once on first
 * use and read-only after: source i and its frequency. */
Vec3 wave_source(int i);
double wave_frequency(int i);
double ripples_value(const Pigment *pig, Vec3 p, int nwaves);
double waves_value(const Pigment *pig, Vec3 p, int nwaves);

double cells_value(Vec3 p);
double crackle_value(const Pigment *pig, Vec3 p, int generator);

double fractal_value(const Pigment *pig, Vec3 p);

#endif
