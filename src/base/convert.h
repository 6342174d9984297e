/* Doubles to integers, checked. A C cast of NaN, of an infinity or of a
 * value the integer type cannot hold is undefined behaviour (and
 * -fsanitize=float-cast-overflow, which the sanitizer build enables, reports
 * it), so every conversion of a double that the scene gives or the renderer
 * computes -- counts, levels, indices, characters, cell coordinates -- goes
 * through one of these. The parser words its own message when a value is
 * refused (expr_checked_int in parser/expressions/expressions.h). */
#ifndef HST_CONVERT_H
#define HST_CONVERT_H

#include <limits.h>
#include <math.h>

/* v truncated toward zero, as a cast does, when the result lies in
 * [lo, hi]: returns 1 and sets *out. NaN, infinities and values outside the
 * range return 0 and leave *out as it was. */
static inline int int_from_double(double v, int lo, int hi, int *out)
{
    double t = trunc(v);
    if (!(t >= (double)lo && t <= (double)hi))
        return 0;
    *out = (int)t;
    return 1;
}

/* v truncated toward zero and held to [lo, hi]; NaN gives lo. For the
 * values POV-Ray clamps (octaves, max_trace_level), and for quantities the
 * renderer computes that may run off (a grid resolution). */
static inline int int_clamped(double v, int lo, int hi)
{
    double t = trunc(v);
    if (!(t >= (double)lo))
        return lo;
    if (t > (double)hi)
        return hi;
    return (int)t;
}

/* floor(v) held to [lo, hi], NaN giving lo: the cell of a coordinate on a
 * grid of hi + 1 cells, for points anywhere (a plane's hit near the horizon
 * lies 1e16 units away, far outside a grid that holds the geometry). */
static inline int int_floor_clamped(double v, int lo, int hi)
{
    return int_clamped(floor(v), lo, hi);
}

/* POV-Ray's `(int)v` as its x86 builds compute it (cvttsd2si): truncation
 * within int's range, INT_MIN (the "integer indefinite") for NaN, the
 * infinities and anything beyond. For patterns that must land where
 * POV-Ray's land at any coordinate (checker, hexagon). */
static inline int int_as_povray(double v)
{
    int i;
    return int_from_double(v, INT_MIN, INT_MAX, &i) ? i : INT_MIN;
}

#endif
