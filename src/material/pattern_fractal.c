/* The fractal patterns of POV-Ray 3.7 (mandel_pattern ... magnet2j_pattern
 * in pattern.cpp): z is iterated from the point (x, y) until it escapes or
 * max_iteration is reached, and the value is then the exterior or the
 * interior colouring of the last z. The steps are written out per exponent
 * as POV-Ray writes them, so that the last bits agree. */
#include <math.h>

#include "deadline.h"
#include "patterns.h"

/* The iterations between two looks at the thread's deadline (a mask:
 * every 2^16, a few hundred microseconds). */
#define DEADLINE_MASK 0xFFFF

/* POV-Ray's fractal_exterior_color: after `iters` iterations, escaped at
 * (a, b). */
static double exterior(const Pigment *pig, int iters, double a, double b)
{
    const double f = pig->exterior_factor;
    switch (pig->exterior_type) {
    case 0: return f;
    case 1: return (double)iters / (double)pig->iterations;
    case 2: return a * f;
    case 3: return b * f;
    case 4: return a * a * f;
    case 5: return b * b * f;
    case 6: return sqrt(a * a + b * b) * f;
    case 7: { /* 0 to (n - 1) / n; a factor below 1 (POV-Ray divides by zero) gives 0 */
        unsigned n = f >= 1.0 && f < 4294967296.0 ? (unsigned)f : 0u;
        return n ? (double)((unsigned)iters % n) / f : 0.0;
    }
    case 8: { /* 0 to 1 */
        unsigned n = f >= 0.0 && f < 4294967295.0 ? (unsigned)(1.0 + f) : 0u;
        return n ? (double)((unsigned)iters % n) / f : 0.0;
    }
    default: return 0.0;
    }
}

/* POV-Ray's fractal_interior_color: still bounded at (a, b), nearest the
 * origin at squared distance mindist2. */
static double interior(const Pigment *pig, double a, double b, double mindist2)
{
    const double f = pig->interior_factor;
    switch (pig->interior_type) {
    case 0: return f;
    case 1: return sqrt(mindist2) * f;
    case 2: return a * f;
    case 3: return b * f;
    case 4: return a * a * f;
    case 5: return b * b * f;
    case 6: return a * a + b * b * f; /* sic: POV-Ray scales b * b alone */
    default: return 0.0;
    }
}

/* z^n + c from z = (x, y), c = (cr, ci): mandel (c the point) and julia
 * (c its constant). */
static double power_fractal(const Pigment *pig, double x, double y, double cr, double ci)
{
    const int it_max = pig->iterations, n = pig->exponent;
    double a = x, b = y, a2 = a * a, b2 = b * b;
    double mindist2 = a2 + b2;
    /* exponents above 4: the binomial expansion, the coefficients of i^k's
     * sign (POV-Ray's BinomialCoefficients) */
    int coeff[34] = { 1 };
    if (n > 4) {
        for (int k = 1; k <= n; k++)
            coeff[k] = 0;
        for (int row = 1; row <= n; row++)
            for (int k = row; k >= 1; k--)
                coeff[k] += coeff[k - 1];
        for (int k = 1; k <= n; k++)
            if (k & 2)
                coeff[k] = -coeff[k];
    }
    int col;
    for (col = 0; col < it_max; col++) {
        double dist2;
        if (n == 3) {
            b = 3.0 * a2 * b - b2 * b + ci;
            a = a2 * a - 3.0 * a * b2 + cr;
            a2 = a * a;
            b2 = b * b;
            dist2 = a2 + b2;
        } else if (n == 4) {
            b = 4.0 * (a2 * a * b - a * b2 * b) + ci;
            a = a2 * a2 - 6.0 * a2 * b2 + b2 * b2 + cr;
            a2 = a * a;
            b2 = b * b;
            dist2 = a2 + b2;
        } else if (n > 4) {
            double new_a = pow(a, n), new_b = 0.0;
            for (int k = 2; k <= n; k += 2)
                new_a += coeff[k] * pow(a, n - k) * pow(b, k);
            for (int k = 1; k <= n; k += 2)
                new_b += coeff[k] * pow(a, n - k) * pow(b, k);
            a = new_a + cr;
            b = new_b + ci;
            dist2 = a * a + b * b;
        } else {
            b = 2.0 * a * b + ci;
            a = a2 - b2 + cr;
            a2 = a * a;
            b2 = b * b;
            dist2 = a2 + b2;
        }
        if (dist2 < mindist2)
            mindist2 = dist2;
        if (dist2 > 4.0)
            return exterior(pig, col, a, b);
        /* max_iteration may be 2^31: past --max-render-seconds, stop */
        if ((col & DEADLINE_MASK) == DEADLINE_MASK && deadline_passed())
            break;
    }
    return interior(pig, a, b, mindist2);
}

/* The magnet fractals: z = ((z^2 + c - 1) / (2z + c - 2))^2 (type 1) or its
 * cubic counterpart (type 2), escaping far away or near 1. mandel: z from
 * 0, c the point; julia: z from the point, c the constant. */
static double magnet_fractal(const Pigment *pig, int type2, int julia, double x, double y)
{
    const int it_max = pig->iterations;
    double cr = x, ci = y, a = 0.0, b = 0.0, a2 = 0.0, b2 = 0.0, mindist2 = 10000.0;
    if (julia) {
        cr = pig->fractal_u;
        ci = pig->fractal_v;
        a = x;
        b = y;
        a2 = a * a;
        b2 = b * b;
        mindist2 = a2 + b2;
    }
    const double c1r = cr - 1, c2r = cr - 2, c1c2r = c1r * c2r - ci * ci, c1c2i = (c1r + c2r) * ci;
    int col;
    for (col = 0; col < it_max; col++) {
        double t1r, t1i, t2r, t2i;
        if (type2) {
            t1r = a2 * a - 3 * a * b2 + 3 * (a * c1r - b * ci) + c1c2r;
            t1i = 3 * a2 * b - b2 * b + 3 * (a * ci + b * c1r) + c1c2i;
            t2r = 3 * (a2 - b2) + 3 * (a * c2r - b * ci) + c1c2r + 1;
            t2i = 6 * a * b + 3 * (a * ci + b * c2r) + c1c2i;
        } else {
            t1r = a2 - b2 + cr - 1;
            t1i = 2 * a * b + ci;
            t2r = 2 * a + cr - 2;
            t2i = 2 * b + ci;
        }
        double t = t2r * t2r + t2i * t2i;
        a = (t1r * t2r + t1i * t2i) / t;
        b = (t1i * t2r - t1r * t2i) / t;
        b2 = b * b;
        b = 2 * a * b;
        a = a * a - b2;
        a2 = a * a;
        b2 = b * b;
        double dist2 = a2 + b2;
        if (dist2 < mindist2)
            mindist2 = dist2;
        double am1 = a - 1;
        if (dist2 > 10000.0 || am1 * am1 + b2 < 1 / 10000.0)
            return exterior(pig, col, a, b);
        if ((col & DEADLINE_MASK) == DEADLINE_MASK && deadline_passed())
            break;
    }
    return interior(pig, a, b, mindist2);
}

double fractal_value(const Pigment *pig, Vec3 p)
{
    switch (pig->fractal) {
    case FRACTAL_MANDEL: return power_fractal(pig, p.x, p.y, p.x, p.y);
    case FRACTAL_JULIA: return power_fractal(pig, p.x, p.y, pig->fractal_u, pig->fractal_v);
    case FRACTAL_MAGNET1M: return magnet_fractal(pig, 0, 0, p.x, p.y);
    case FRACTAL_MAGNET1J: return magnet_fractal(pig, 0, 1, p.x, p.y);
    case FRACTAL_MAGNET2M: return magnet_fractal(pig, 1, 0, p.x, p.y);
    case FRACTAL_MAGNET2J: return magnet_fractal(pig, 1, 1, p.x, p.y);
    }
    return 0.0;
}
