/* Three-component vectors in double precision, as POV-Ray's DBL vectors.
 * Everything is inline: these run per ray and per polygon test. */
#ifndef HST_VECMATH_H
#define HST_VECMATH_H

#include <math.h>

#ifndef M_PI /* not in strict C11 */
#define M_PI 3.14159265358979323846
#endif

typedef struct { double x, y, z; } Vec3;

#define POV_EPSILON 1.0e-10 /* POV-Ray's EPSILON */

static inline Vec3 v3(double x, double y, double z) { Vec3 r = { x, y, z }; return r; }
static inline Vec3 v3_add(Vec3 a, Vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline Vec3 v3_sub(Vec3 a, Vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline Vec3 v3_mul(Vec3 a, Vec3 b) { return v3(a.x * b.x, a.y * b.y, a.z * b.z); }
static inline Vec3 v3_scale(Vec3 a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static inline Vec3 v3_neg(Vec3 a) { return v3(-a.x, -a.y, -a.z); }
static inline double v3_dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline Vec3 v3_cross(Vec3 a, Vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double v3_length(Vec3 a) { return sqrt(v3_dot(a, a)); }
/* Divides rather than multiplying by 1/l, so an axis-aligned vector comes
 * out exactly unit (x * (1/x) is not always 1 in floating point). */
static inline Vec3 v3_normalize(Vec3 a)
{
    double l = v3_length(a);
    return l > 0.0 ? v3(a.x / l, a.y / l, a.z / l) : a;
}
/* a + b * s: the ray-point idiom. */
static inline Vec3 v3_madd(Vec3 a, Vec3 b, double s) { return v3(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s); }
/* fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z))), the same value (a NaN
 * component is ignored, as fmax ignores it), inline: fmax is a call into
 * libm, and this runs several times per ray. */
static inline double v3_max_abs(Vec3 a)
{
    double x = fabs(a.x), y = fabs(a.y), z = fabs(a.z);
    double m = (y > z || z != z) ? y : z;
    return (x > m || m != m) ? x : m;
}
static inline double v3_comp(Vec3 a, int axis) { return axis == 0 ? a.x : axis == 1 ? a.y : a.z; }
/* fmin and fmax as C defines them (a NaN loses to a number; of two equal
 * values, +0 and -0, b), written out: the compiler calls the library for
 * fmin and fmax, and on 10^6 polygons' boxes the calls were 2% of the
 * set-up. */
static inline double min_of(double a, double b) { return (a < b || b != b) ? a : b; }
static inline double max_of(double a, double b) { return (a > b || b != b) ? a : b; }
static inline Vec3 v3_min(Vec3 a, Vec3 b) { return v3(min_of(a.x, b.x), min_of(a.y, b.y), min_of(a.z, b.z)); }
static inline Vec3 v3_max(Vec3 a, Vec3 b) { return v3(max_of(a.x, b.x), max_of(a.y, b.y), max_of(a.z, b.z)); }

#endif
