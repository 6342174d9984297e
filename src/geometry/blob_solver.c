/* POV-Ray 3.7's polynomial solver for degree <= 4 (blob_solver.h), written
 * anew from reading polysolv.cpp: the same steps, constants and order of
 * arithmetic, its quirks kept where they change which roots are found. */
#include "blob_solver.h"

#include <math.h>

#define SMALL_ENOUGH 1.0e-10   /* a coefficient this small counts as 0 */
#define RELERROR 1.0e-12       /* the relative error the Sturm solver stops at */
#define MAX_ITERATIONS 50
#define MAX_DISTANCE 1.0e7     /* the Sturm solver's roots lie in [0, MAX_DISTANCE] */
#define FUDGE_FACTOR1 1.0e12   /* coefficients this far apart call for the Sturm solver */
#define TWO_PI_3 2.0943951023931954923084
#define FOUR_PI_3 4.1887902047863909846168

/* A polynomial by ascending powers: coef[i] multiplies x^i. */
typedef struct {
    int ord;
    double coef[BLOB_SOLVER_MAX_DEGREE + 1];
} Poly;

/* ---- closed formulas --------------------------------------------------- */

/* x[0] t^2 + x[1] t + x[2] (solve_quadratic; roots near a double one merge). */
static int quadratic(const double *x, double *y)
{
    double a = x[0], b = -x[1], c = x[2];
    if (a == 0.0) {
        if (b == 0.0)
            return 0;
        y[0] = c / b;
        return 1;
    }
    b /= a;
    c /= a;
    a = 1.0;
    double d = b * b - 4.0 * a * c;
    if (d > -SMALL_ENOUGH && d < SMALL_ENOUGH) {
        y[0] = 0.5 * b / a;
        return 1;
    }
    if (d < 0.0)
        return 0;
    d = sqrt(d);
    double t = 2.0 * a;
    y[0] = (b + d) / t;
    y[1] = (b - d) / t;
    return 2;
}

/* solve_cubic: trigonometric for three real roots, else Cardano's one. */
static int cubic(const double *x, double *y)
{
    double a0 = x[0], a1, a2, a3;
    if (a0 == 0.0)
        return quadratic(&x[1], y);
    if (a0 != 1.0) {
        a1 = x[1] / a0;
        a2 = x[2] / a0;
        a3 = x[3] / a0;
    } else {
        a1 = x[1];
        a2 = x[2];
        a3 = x[3];
    }
    double A2 = a1 * a1;
    double Q = (A2 - 3.0 * a2) / 9.0;
    double R = (a1 * (A2 - 4.5 * a2) + 13.5 * a3) / 27.0;
    double Q3 = Q * Q * Q, R2 = R * R;
    double d = Q3 - R2, an = a1 / 3.0;
    if (d >= 0.0) {
        d = R / sqrt(Q3);
        double theta = acos(d) / 3.0;
        double sQ = -2.0 * sqrt(Q);
        y[0] = sQ * cos(theta) - an;
        y[1] = sQ * cos(theta + TWO_PI_3) - an;
        y[2] = sQ * cos(theta + FOUR_PI_3) - an;
        return 3;
    }
    double sQ = pow(sqrt(R2 - Q3) + fabs(R), 1.0 / 3.0);
    if (R < 0)
        y[0] = (sQ + Q / sQ) - an;
    else
        y[0] = -(sQ + Q / sQ) - an;
    return 1;
}

/* solve_quartic (the release's, not its TEST_SOLVER one): the depressed
 * quartic factored into two quadratics through a root of its resolvent. */
static int quartic(const double *x, double *results)
{
    double c0 = x[0], c1, c2, c3, c4;
    if (c0 != 1.0) {
        c1 = x[1] / c0;
        c2 = x[2] / c0;
        c3 = x[3] / c0;
        c4 = x[4] / c0;
    } else {
        c1 = x[1];
        c2 = x[2];
        c3 = x[3];
        c4 = x[4];
    }
    double c12 = c1 * c1;
    double p = -0.375 * c12 + c2;
    double q = 0.125 * c12 * c1 - 0.5 * c1 * c2 + c3;
    double r = -0.01171875 * c12 * c12 + 0.0625 * c12 * c2 - 0.25 * c1 * c3 + c4;
    double resolvent[4] = { 1.0, -0.5 * p, -r, 0.5 * r * p - 0.125 * q * q };
    double roots[3];
    if (cubic(resolvent, roots) <= 0)
        return 0;
    double z = roots[0];
    double d1 = 2.0 * z - p, d2;
    if (d1 < 0.0) {
        if (d1 > -SMALL_ENOUGH)
            d1 = 0.0;
        else
            return 0;
    }
    if (d1 < SMALL_ENOUGH) {
        d2 = z * z - r;
        if (d2 < 0.0)
            return 0;
        d2 = sqrt(d2);
    } else {
        d1 = sqrt(d1);
        d2 = 0.5 * q / d1;
    }
    double q1 = d1 * d1, q2 = -0.25 * c1;
    int i = 0;
    p = q1 - 4.0 * (z - d2);
    if (p == 0) {
        results[i++] = -0.5 * d1 - q2;
    } else if (p > 0) {
        p = sqrt(p);
        results[i++] = -0.5 * (d1 + p) + q2;
        results[i++] = -0.5 * (d1 - p) + q2;
    }
    p = q1 - 4.0 * (z + d2);
    if (p == 0) {
        results[i++] = 0.5 * d1 - q2;
    } else if (p > 0) {
        p = sqrt(p);
        results[i++] = 0.5 * (d1 + p) + q2;
        results[i++] = 0.5 * (d1 - p) + q2;
    }
    return i;
}

/* difficult_coeffs (the release's): the largest is taken with its sign, as
 * there, so a negative largest coefficient never calls for Sturm. */
static int difficult(int n, const double *x)
{
    double biggest = 0.0;
    for (int i = 0; i <= n; i++)
        if (fabs(x[i]) > biggest)
            biggest = x[i];
    if (biggest == 0.0)
        return 0;
    for (int i = 0; i <= n; i++)
        if (x[i] != 0.0 && fabs(biggest / x[i]) > FUDGE_FACTOR1)
            return 1;
    return 0;
}

/* ---- Sturm sequences ---------------------------------------------------- */

static double poly_eval(double x, int n, const double *c)
{
    double v = c[n];
    for (int i = n - 1; i >= 0; i--)
        v = v * x + c[i];
    return v;
}

/* modp: r = the remainder of u divided by v; returns its order. */
static int poly_mod(const Poly *u, const Poly *v, Poly *r)
{
    *r = *u;
    if (v->coef[v->ord] < 0.0) {
        for (int k = u->ord - v->ord - 1; k >= 0; k -= 2)
            r->coef[k] = -r->coef[k];
        for (int k = u->ord - v->ord; k >= 0; k--)
            for (int j = v->ord + k - 1; j >= k; j--)
                r->coef[j] = -r->coef[j] - r->coef[v->ord + k] * v->coef[j - k];
    } else {
        for (int k = u->ord - v->ord; k >= 0; k--)
            for (int j = v->ord + k - 1; j >= k; j--)
                r->coef[j] -= r->coef[v->ord + k] * v->coef[j - k];
    }
    int k = v->ord - 1;
    while (k >= 0 && fabs(r->coef[k]) < SMALL_ENOUGH) {
        r->coef[k] = 0.0;
        k--;
    }
    r->ord = k < 0 ? 0 : k;
    return r->ord;
}

/* buildsturm: the sequence from seq[0]; returns the index of its last. */
static int sturm_build(int ord, Poly *seq)
{
    seq[0].ord = ord;
    seq[1].ord = ord - 1;
    double f = fabs(seq[0].coef[ord] * ord);
    for (int i = 1; i <= ord; i++)
        seq[1].coef[i - 1] = seq[0].coef[i] * i / f;
    Poly *sp;
    for (sp = seq + 2; poly_mod(sp - 2, sp - 1, sp); sp++) {
        f = -fabs(sp->coef[sp->ord]);
        for (int i = sp->ord; i >= 0; i--)
            sp->coef[i] /= f;
    }
    sp->coef[0] = -sp->coef[0];
    return (int)(sp - seq);
}

/* visible_roots: sign changes at 0 less those at +infinity. */
static int sturm_visible(int np, const Poly *seq)
{
    int at_inf = 0, at_zero = 0;
    double lf = seq[0].coef[seq[0].ord];
    for (int s = 1; s <= np; s++) {
        double f = seq[s].coef[seq[s].ord];
        if (lf == 0.0 || lf * f < 0)
            at_inf++;
        lf = f;
    }
    lf = seq[0].coef[0];
    for (int s = 1; s <= np; s++) {
        double f = seq[s].coef[0];
        if (lf == 0.0 || lf * f < 0)
            at_zero++;
        lf = f;
    }
    return at_zero - at_inf;
}

static int sturm_changes(int np, const Poly *seq, double a)
{
    int changes = 0;
    double lf = poly_eval(a, seq[0].ord, seq[0].coef);
    for (int s = 1; s <= np; s++) {
        double f = poly_eval(a, seq[s].ord, seq[s].coef);
        if (lf == 0.0 || lf * f < 0)
            changes++;
        lf = f;
    }
    return changes;
}

/* regula_falsa: the one root of coef in [a, b] (the Illinois variant). */
static int regula_falsi(int order, const double *coef, double a, double b, double *val)
{
    double fa = poly_eval(a, order, coef), fb = poly_eval(b, order, coef);
    if (fa * fb > 0.0)
        return 0;
    if (fabs(fa) < SMALL_ENOUGH) {
        *val = a;
        return 1;
    }
    if (fabs(fb) < SMALL_ENOUGH) {
        *val = b;
        return 1;
    }
    double lfx = fa;
    for (int its = 0; its < MAX_ITERATIONS; its++) {
        double x = (fb * a - fa * b) / (fb - fa);
        double fx = poly_eval(x, order, coef);
        if (fabs(x) > RELERROR) {
            if (fabs(fx / x) < RELERROR) {
                *val = x;
                return 1;
            }
        } else if (fabs(fx) < RELERROR) {
            *val = x;
            return 1;
        }
        if (fa < 0) {
            if (fx < 0) {
                a = x;
                fa = fx;
                if (lfx * fx > 0)
                    fb /= 2;
            } else {
                b = x;
                fb = fx;
                if (lfx * fx > 0)
                    fa /= 2;
            }
        } else {
            if (fx < 0) {
                b = x;
                fb = fx;
                if (lfx * fx > 0)
                    fa /= 2;
            } else {
                a = x;
                fa = fx;
                if (lfx * fx > 0)
                    fb /= 2;
            }
        }
        if (fabs(b - a) < RELERROR) {
            *val = x;
            return 1;
        }
        lfx = fx;
    }
    return 0;
}

/* Whether bisection has closed in on mid (sbisect's test). */
static int close_enough(double lo, double hi, double mid)
{
    if (fabs(mid) > RELERROR)
        return fabs((hi - lo) / mid) < RELERROR;
    return fabs(hi - lo) < RELERROR;
}

/* sbisect: the roots in [lo, hi], given the sign changes at both ends. */
static int sturm_bisect(int np, const Poly *seq, double lo, double hi, int atmin, int atmax, double *roots)
{
    double mid = lo;
    if (atmin - atmax == 1) {
        if (regula_falsi(seq->ord, seq->coef, lo, hi, roots))
            return 1;
        for (int its = 0; its < MAX_ITERATIONS; its++) {
            mid = (lo + hi) / 2;
            int atmid = sturm_changes(np, seq, mid);
            if (atmid < atmax || atmid > atmin) /* POV-Ray's own guard */
                return 0;
            if (close_enough(lo, hi, mid)) {
                roots[0] = mid;
                return 1;
            }
            if (atmin - atmid == 0)
                lo = mid;
            else
                hi = mid;
        }
        roots[0] = mid;
        return 1;
    }
    for (int its = 0; its < MAX_ITERATIONS; its++) {
        mid = (lo + hi) / 2;
        int atmid = sturm_changes(np, seq, mid);
        if (atmid < atmax || atmid > atmin)
            return 0;
        if (close_enough(lo, hi, mid)) {
            roots[0] = mid;
            return 1;
        }
        int n1 = atmin - atmid, n2 = atmid - atmax;
        if (n1 != 0 && n2 != 0) {
            n1 = sturm_bisect(np, seq, lo, mid, atmin, atmid, roots);
            n2 = sturm_bisect(np, seq, mid, hi, atmid, atmax, &roots[n1]);
            return n1 + n2;
        }
        if (n1 == 0)
            lo = mid;
        else
            hi = mid;
    }
    roots[0] = mid;
    return 1;
}

/* polysolve: the roots in [0, MAX_DISTANCE] by Sturm sequences. */
static int sturm_solve(int order, const double *c, double *roots)
{
    Poly seq[BLOB_SOLVER_MAX_DEGREE + 2];
    for (int i = 0; i <= order; i++)
        seq[0].coef[order - i] = c[i] / c[0];
    int np = sturm_build(order, seq);
    if (sturm_visible(np, seq) == 0)
        return 0;
    int atmin = sturm_changes(np, seq, 0.0), atmax = sturm_changes(np, seq, MAX_DISTANCE);
    if (atmin - atmax == 0)
        return 0;
    return sturm_bisect(np, seq, 0.0, MAX_DISTANCE, atmin, atmax, roots);
}

int blob_solve_polynomial(int n, const double *c0, double *r, int sturm, double epsilon)
{
    int i = 0;
    while (i < n && fabs(c0[i]) < SMALL_ENOUGH)
        i++;
    n -= i;
    const double *c = &c0[i];
    switch (n) {
    case 0:
        return 0;
    case 1:
        if (c[0] != 0.0) {
            r[0] = -c[1] / c[0];
            return 1;
        }
        return 0;
    case 2:
        return quadratic(c, r);
    case 3:
        /* root elimination: a constant this small against the linear
         * coefficient takes 0 for a root, the rest one degree lower */
        if (epsilon > 0.0 && c[2] != 0.0 && fabs(c[3] / c[2]) < epsilon)
            return quadratic(c, r);
        return sturm ? sturm_solve(3, c, r) : cubic(c, r);
    default:
        if (epsilon > 0.0 && c[3] != 0.0 && fabs(c[4] / c[3]) < epsilon)
            return sturm ? sturm_solve(3, c, r) : cubic(c, r);
        if (difficult(4, c))
            sturm = 1;
        return sturm ? sturm_solve(4, c, r) : quartic(c, r);
    }
}
