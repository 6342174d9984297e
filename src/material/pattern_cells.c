/* Patterns of random points, one per unit cube: cells (a random value per
 * cube) and crackle (the distances to the nearest such points), as POV-Ray
 * 3.7's cells_pattern and crackle_pattern compute them, with its hashing of
 * cubes (Hash3d over the noise's hash table) and its table of random
 * numbers (PatternRands). */
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>

#include "convert.h"
#include "noise.h"
#include "patterns.h"

/* ---- POV-Ray's PatternRands ------------------------------------------------
 * 32768 doubles in [0, 1) drawn from a Mersenne Twister (mt19937, its
 * default seed 5489) through boost's uniform_real (each 32-bit output over
 * 2^32), as POV-Ray's RandomDoubleSequence makes them. Made once, on first
 * use, and only read after. */

#define PATTERN_RANDS 32768

static double pattern_rands[PATTERN_RANDS];
static pthread_once_t rands_once = PTHREAD_ONCE_INIT;

static void make_pattern_rands(void)
{
    enum { N = 624, M = 397 };
    uint32_t mt[N];
    mt[0] = 5489u;
    for (int i = 1; i < N; i++)
        mt[i] = 1812433253u * (mt[i - 1] ^ (mt[i - 1] >> 30)) + (uint32_t)i;
    int index = N;
    for (int k = 0; k < PATTERN_RANDS; k++) {
        if (index >= N) { /* the next 624 words at once */
            for (int i = 0; i < N; i++) {
                uint32_t y = (mt[i] & 0x80000000u) | (mt[(i + 1) % N] & 0x7fffffffu);
                mt[i] = mt[(i + M) % N] ^ (y >> 1) ^ ((y & 1u) ? 0x9908b0dfu : 0u);
            }
            index = 0;
        }
        uint32_t y = mt[index++];
        y ^= y >> 11;
        y ^= (y << 7) & 0x9d2c5680u;
        y ^= (y << 15) & 0xefc60000u;
        y ^= y >> 18;
        pattern_rands[k] = (double)y / 4294967296.0;
    }
}

static double pattern_rand(unsigned seed)
{
    pthread_once(&rands_once, make_pattern_rands);
    return pattern_rands[seed % PATTERN_RANDS];
}

/* POV-Ray's Hash3d: a cube's number in 0..4095 from its three coordinates. */
static unsigned hash3d(int a, int b, int c)
{
    unsigned h = noise_hash((unsigned)a & 0xfffu);
    h = noise_hash(h ^ ((unsigned)b & 0xfffu));
    return noise_hash(h ^ ((unsigned)c & 0xfffu));
}

double cells_value(Vec3 p)
{
    /* floor, not truncation: no doubled cells about the axes */
    unsigned h = hash3d(int_as_povray(floor(p.x + POV_EPSILON)), int_as_povray(floor(p.y + POV_EPSILON)),
                        int_as_povray(floor(p.z + POV_EPSILON)));
    return fmin(pattern_rand(h), 1.0);
}

/* ---- crackle ---------------------------------------------------------------- */

/* The cubes whose point may be among the three nearest to a point of the
 * centre cube: the offsets -2..2 on each axis with at most one of them 2
 * away (POV-Ray's CrackleCubeTable, in its order). */
static int crackle_cubes[81][3];
static pthread_once_t cubes_once = PTHREAD_ONCE_INIT;

static void make_crackle_cubes(void)
{
    int n = 0;
    for (int x = -2; x <= 2; x++)
        for (int y = -2; y <= 2; y++)
            for (int z = -2; z <= 2; z++)
                if ((abs(x) == 2) + (abs(y) == 2) + (abs(z) == 2) <= 1) {
                    crackle_cubes[n][0] = x;
                    crackle_cubes[n][1] = y;
                    crackle_cubes[n][2] = z;
                    n++;
                }
}

/* a + b as POV-Ray's int arithmetic gives it on its machines, wrapping
 * past INT_MIN and INT_MAX (a point far beyond the range of int, whose
 * cube is held to its edge), without C's undefined overflow: in unsigned
 * arithmetic, back to int as GCC converts (modulo 2^32). */
static int wrapping_add(int a, int b)
{
    return (int)((unsigned)a + (unsigned)b);
}

/* The random point of the unit cube at (x, y, z) (IntPickInCube). */
static Vec3 point_in_cube(int x, int y, int z)
{
    unsigned seed = hash3d(x, y, z);
    return v3(x + pattern_rand(seed), y + pattern_rand(seed + 1), z + pattern_rand(seed + 2));
}

/* The distance of d in the pattern's metric, before its root. */
static double metric_sum(Vec3 d, double metric)
{
    if (metric == 2.0)
        return d.x * d.x + d.y * d.y + d.z * d.z;
    if (metric == 1.0)
        return fabs(d.x) + fabs(d.y) + fabs(d.z);
    return pow(fabs(d.x), metric) + pow(fabs(d.y), metric) + pow(fabs(d.z), metric);
}

/* form.x, .y, .z times the distances to the nearest, second and third
 * nearest points (each plus offset), or with `solid` the noise at the
 * nearest point; held to [0, 1]. */
double crackle_value(const Pigment *pig, Vec3 p, int generator)
{
    pthread_once(&cubes_once, make_crackle_cubes);
    const double metric = pig->crackle_metric, offset = pig->crackle_offset;
    /* floor, not FLOOR: no mirror image about zero */
    const int fx = int_as_povray(floor(p.x - POV_EPSILON)), fy = int_as_povray(floor(p.y - POV_EPSILON)),
              fz = int_as_povray(floor(p.z - POV_EPSILON));
    Vec3 points[81];
    for (int i = 0; i < 81; i++)
        points[i] = point_in_cube(wrapping_add(fx, crackle_cubes[i][0]), wrapping_add(fy, crackle_cubes[i][1]),
                                  wrapping_add(fz, crackle_cubes[i][2]));

    double d1 = metric_sum(v3_sub(points[0], p), metric);
    double d2 = metric_sum(v3_sub(points[1], p), metric);
    double d3 = metric_sum(v3_sub(points[2], p), metric);
    int nearest = 0;
    double t;
    if (d2 < d1) {
        t = d1; d1 = d2; d2 = t;
        nearest = 1;
    }
    if (d3 < d1) {
        t = d1; d1 = d3; d3 = t;
        nearest = 2;
    }
    if (d3 < d2) {
        t = d2; d2 = d3; d3 = t;
    }
    for (int i = 3; i < 81; i++) {
        double sum = metric_sum(v3_sub(points[i], p), metric);
        if (sum < d1) {
            d3 = d2;
            d2 = d1;
            d1 = sum;
            nearest = i;
        } else if (sum < d2) {
            d3 = d2;
            d2 = sum;
        } else if (sum < d3) {
            d3 = sum;
        }
    }
    if (offset != 0.0) {
        double o = metric == 2.0 ? offset * offset : metric == 1.0 ? offset : pow(offset, metric);
        d1 += o;
        d2 += o;
        d3 += o;
    }
    const Vec3 form = pig->crackle_form;
    double v;
    if (pig->crackle_solid)
        v = noise_value(points[nearest], generator);
    else if (metric == 2.0)
        v = form.x * sqrt(d1) + form.y * sqrt(d2) + form.z * sqrt(d3);
    else if (metric == 1.0)
        v = form.x * d1 + form.y * d2 + form.z * d3;
    else
        v = form.x * pow(d1, 1.0 / metric) + form.y * pow(d2, 1.0 / metric) + form.z * pow(d3, 1.0 / metric);
    return fmax(fmin(v, 1.0), 0.0);
}
