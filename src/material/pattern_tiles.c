/* Tilings (POV-Ray 3.7's brick_pattern, square_pattern, triangular_pattern
 * and cubic_pattern): the value names the tile, 0 (mortar) or 1 (brick),
 * 0 to 3, 0 to 5. The same small offsets and comparisons, so that tile
 * borders fall where POV-Ray puts them. */
#include <math.h>

#include "convert.h"
#include "patterns.h"

#define SQRT3 1.7320508075688772935274463415059   /* POV-Ray's constants */
#define SQRT3_2 0.86602540378443864676372317075294

/* The fraction of v in a row of period 1 as brick_pattern takes it:
 * truncated toward zero, then lifted into [0, 1). */
static double brick_fraction(double v)
{
    double f = v - (double)int_as_povray(v);
    return f < 0.0 ? f + 1.0 : f;
}

/* Courses of bricks brick_size wide, high and deep, each course shifted
 * half a brick from the one below, with mortar between. */
double brick_value(const Pigment *pig, Vec3 p)
{
    const double fudge = POV_EPSILON + pig->mortar;
    const double x = p.x + fudge, y = p.y + fudge, z = p.z + fudge;
    const double width = pig->brick_size.x, height = pig->brick_size.y, depth = pig->brick_size.z;
    const double mortar_width = pig->mortar / width, mortar_height = pig->mortar / height,
                 mortar_depth = pig->mortar / depth;
    /* the mortar between courses */
    if (brick_fraction(y / height) <= mortar_height)
        return 0.0;
    /* which of a pair of courses: the odd ones are shifted */
    const double course = brick_fraction((y / height) * 0.5);
    if (brick_fraction(x / width) <= mortar_width && course <= 0.5)
        return 0.0;
    if (brick_fraction(x / width + 0.5) <= mortar_width && course > 0.5)
        return 0.0;
    if (brick_fraction(z / depth) <= mortar_depth && course > 0.5)
        return 0.0;
    if (brick_fraction(z / depth + 0.5) <= mortar_depth && course <= 0.5)
        return 0.0;
    return 1.0;
}

double square_value(Vec3 p)
{
    int x = int_as_povray(floor(p.x)), z = int_as_povray(floor(p.z));
    if (x & 1)
        return (z & 1) ? 2.0 : 3.0;
    return (z & 1) ? 1.0 : 0.0;
}

/* Equilateral triangles of side 1 in x-z, six around each vertex: the
 * plane folds into a rectangle 3 by sqrt(3), mirrored about its middle. */
double triangular_value(Vec3 p)
{
    double xs = p.x - 3.0 * floor(p.x / 3.0);
    double zs = p.z - SQRT3 * floor(p.z / SQRT3);
    int a = int_as_povray(floor(xs));
    xs -= a;
    int mirrored = zs < SQRT3_2 ? 0 : 1;
    if (mirrored)
        zs = SQRT3 - zs;
    double k = 1.0 - xs, answer = 1.0;
    if (xs != 0.0 && k != 0.0) {
        double slope1 = zs / xs, slope2 = zs / k;
        switch ((slope1 < SQRT3 ? 1 : 0) + (slope2 < SQRT3 ? 2 : 0)) {
        case 3: answer = 0.0; break;
        case 2: answer = 1.0; break;
        case 1: answer = 3.0; break;
        default: answer = 0.0; break; /* POV-Ray leaves it unset; no point reaches it */
        }
    }
    int mask = (int)answer;
    answer = (mask & 1) ? fmod(answer + 2.0 * a, 6.0) : fmod(6.0 + answer - 2.0 * a, 6.0);
    if (mirrored)
        answer = 5.0 - answer;
    return answer;
}

/* The six pyramids from the origin to the faces of a cube: +x, +y, +z,
 * -x, -y, -z. */
double cubic_value(Vec3 p)
{
    const double ax = fabs(p.x), ay = fabs(p.y), az = fabs(p.z);
    if (p.x >= 0 && p.x >= ay && p.x >= az)
        return 0.0;
    if (p.y >= 0 && p.y >= ax && p.y >= az)
        return 1.0;
    if (p.z >= 0 && p.z >= ax && p.z >= ay)
        return 2.0;
    if (p.x < 0 && p.x <= -ay && p.x <= -az)
        return 3.0;
    if (p.y < 0 && p.y <= -ax && p.y <= -az)
        return 4.0;
    return 5.0;
}
