/* POV-Ray 3.7's solid noise, the source of its bozo, granite, wrinkles,
 * agate ... patterns and of turbulence: Noise(), DNoise(), Turbulence() and
 * DTurbulence() of its texture.cpp, computed the same way (same tables from
 * the same pseudo-random sequence, same interpolation, same order of
 * additions), so that a colour map's borders fall on the pixels where
 * POV-Ray puts them.
 *
 * The tables are built once, on first use (pthread_once), and never
 * written again: any thread may call these functions at any time. */
#ifndef HST_NOISE_H
#define HST_NOISE_H

#include "vecmath.h"

/* POV-Ray's noise_generator: 1 the original (3.1) noise, 2 the same with
 * its range corrected to about [0, 1] (the default of #version 3.5 and
 * later), 3 Perlin's improved gradient noise. */
enum { NOISE_ORIGINAL = 1, NOISE_RANGE_CORRECTED = 2, NOISE_PERLIN = 3 };

/* The noise at p, in [0, 1]. */
double noise_value(Vec3 p, int generator);

/* The vector-valued noise at p (POV-Ray's DNoise: there is one generator
 * for it), each component in about [-1, 1]. */
Vec3 noise_vector(Vec3 p);

/* Fractal sums of octaves of noise: octave i (from 1) samples the point
 * scaled by lambda^(i-1) and weighs it by omega^(i-1). */
double noise_turbulence(Vec3 p, int octaves, double omega, double lambda, int generator);
Vec3 noise_vector_turbulence(Vec3 p, int octaves, double omega, double lambda);

/* POV-Ray's hash table (a permutation of 0..4095) at i & 0xfff, which its
 * anti-aliasing's jitter also reads. */
unsigned noise_hash(unsigned i);

#endif
