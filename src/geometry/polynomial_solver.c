/* POV-Ray 3.7's Solve_Polynomial (polysolv.cpp), written anew from reading
 * it: each step's arithmetic kept in its order, since the roots a closed
 * formula loses or moves are part of the image POV-Ray makes. */
#include "polynomial_solver.h"

#include <math.h>

#define SMALL_ENOUGH 1.0e-10    /* a coefficient this small is zero */
#define RELERROR 1.0e-12        /* the relative precision the Sturm solver stops at */
#define MAX_ITERATIONS 50       /* its bisection and regula falsi steps */
#define DIFFICULT_SPREAD 1.0e12 /* FUDGE_FACTOR1: coefficients this far apart go to Sturm */

static const double TWO_PI_3 = 2.0943951023931954923084;
static const double FOUR_PI_3 = 4.1887902047863909846168;

/* ---- closed formulas ------------------------------------------------------ */

int poly_solve_quadratic(const double *c, double *roots)
{
    double a = c[0], b = -c[1], k = c[2];
    if (a == 0.0) {
        if (b == 0.0)
            return 0;
        roots[0] = k / b;
        return 1;
    }
    b /= a;
    k /= a;
    double d = b * b - 4.0 * k;
    /* a discriminant within SMALL_ENOUGH of 0 is one (double) root */
    if (d > -SMALL_ENOUGH && d < SMALL_ENOUGH) {
        roots[0] = 0.5 * b;
        return 1;
    }
    if (d < 0.0)
        return 0;
    d = sqrt(d);
    roots[0] = (b + d) / 2.0;
    roots[1] = (b - d) / 2.0;
    return 2;
}

int poly_solve_cubic(const double *c, double *roots)
{
    double a0 = c[0];
    if (a0 == 0.0)
        return poly_solve_quadratic(c + 1, roots);
    double a1 = c[1], a2 = c[2], a3 = c[3];
    if (a0 != 1.0) {
        a1 /= a0;
        a2 /= a0;
        a3 /= a0;
    }
    double a1sq = a1 * a1;
    double Q = (a1sq - 3.0 * a2) / 9.0;
    double R = (a1 * (a1sq - 4.5 * a2) + 13.5 * a3) / 27.0;
    double Q3 = Q * Q * Q, R2 = R * R;
    double shift = a1 / 3.0;
    if (Q3 - R2 >= 0.0) { /* three real roots, by the trigonometric form */
        double theta = acos(R / sqrt(Q3)) / 3.0;
        double m = -2.0 * sqrt(Q);
        roots[0] = m * cos(theta) - shift;
        roots[1] = m * cos(theta + TWO_PI_3) - shift;
        roots[2] = m * cos(theta + FOUR_PI_3) - shift;
        return 3;
    }
    double s = pow(sqrt(R2 - Q3) + fabs(R), 1.0 / 3.0);
    roots[0] = (R < 0 ? (s + Q / s) : -(s + Q / s)) - shift;
    return 1;
}

/* POV-Ray 3.7's default solve_quartic: the depressed quartic's cubic
 * resolvent, one of its roots z, and the two quadratic factors. */
int poly_solve_quartic(const double *c, double *roots)
{
    double c1 = c[1], c2 = c[2], c3 = c[3], c4 = c[4];
    if (c[0] != 1.0) {
        c1 /= c[0];
        c2 /= c[0];
        c3 /= c[0];
        c4 /= c[0];
    }
    double c1sq = c1 * c1;
    double p = -0.375 * c1sq + c2;
    double q = 0.125 * c1sq * c1 - 0.5 * c1 * c2 + c3;
    double r = -0.01171875 * c1sq * c1sq + 0.0625 * c1sq * c2 - 0.25 * c1 * c3 + c4;
    const double resolvent[4] = { 1.0, -0.5 * p, -r, 0.5 * r * p - 0.125 * q * q };
    double z3[3];
    if (poly_solve_cubic(resolvent, z3) <= 0)
        return 0;
    double z = z3[0];
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
    double d1sq = d1 * d1, shift = -0.25 * c1;
    int n = 0;
    double disc = d1sq - 4.0 * (z - d2);
    if (disc == 0) {
        roots[n++] = -0.5 * d1 - shift;
    } else if (disc > 0) {
        disc = sqrt(disc);
        roots[n++] = -0.5 * (d1 + disc) + shift;
        roots[n++] = -0.5 * (d1 - disc) + shift;
    }
    disc = d1sq - 4.0 * (z + d2);
    if (disc == 0) {
        roots[n++] = 0.5 * d1 - shift;
    } else if (disc > 0) {
        disc = sqrt(disc);
        roots[n++] = 0.5 * (d1 + disc) + shift;
        roots[n++] = 0.5 * (d1 - disc) + shift;
    }
    return n;
}

/* difficult_coeffs as POV-Ray 3.7 compiles it: the "biggest" coefficient
 * is kept with its sign, and a later one replaces it whenever its
 * magnitude exceeds that signed value (so it is not always the largest);
 * a nonzero coefficient more than DIFFICULT_SPREAD times smaller than it
 * makes the quartic difficult. */
static int difficult_coeffs(int n, const double *c)
{
    double biggest = 0.0;
    for (int i = 0; i <= n; i++)
        if (fabs(c[i]) > biggest)
            biggest = c[i];
    if (biggest == 0.0)
        return 0;
    for (int i = 0; i <= n; i++)
        if (c[i] != 0.0 && fabs(biggest / c[i]) > DIFFICULT_SPREAD)
            return 1;
    return 0;
}

/* ---- the Sturm sequence ----------------------------------------------------- */

/* A polynomial stored lowest power first, as polysolve keeps them. */
typedef struct {
    int ord;
    double coef[POLY_SOLVER_MAX_ORDER + 1];
} SturmPoly;

static double eval_low_first(double x, int n, const double *c)
{
    double v = c[n];
    for (int i = n - 1; i >= 0; i--)
        v = v * x + c[i];
    return v;
}

/* modp: r = the remainder of u divided by v (its sign pattern where v's
 * leading coefficient is negative as POV-Ray's), small coefficients
 * zeroed; returns its order. */
static int remainder_of(const SturmPoly *u, const SturmPoly *v, SturmPoly *r)
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

/* buildsturm: the derivative (normalised) and the negated remainders,
 * until a remainder of order 0; returns the index of the last. */
static int build_sturm(int ord, SturmPoly *seq)
{
    seq[0].ord = ord;
    seq[1].ord = ord - 1;
    double f = fabs(seq[0].coef[ord] * ord);
    for (int i = 1; i <= ord; i++)
        seq[1].coef[i - 1] = seq[0].coef[i] * i / f;
    SturmPoly *sp = seq + 2;
    while (remainder_of(sp - 2, sp - 1, sp)) {
        f = -fabs(sp->coef[sp->ord]);
        for (int i = sp->ord; i >= 0; i--)
            sp->coef[i] /= f;
        sp++;
    }
    sp->coef[0] = -sp->coef[0];
    return (int)(sp - seq);
}

/* Sign changes along the sequence at x (numchanges): a zero counts as
 * one, as POV-Ray counts it. */
static int sign_changes(int np, const SturmPoly *seq, double x)
{
    int changes = 0;
    double lf = eval_low_first(x, seq[0].ord, seq[0].coef);
    for (int i = 1; i <= np; i++) {
        double f = eval_low_first(x, seq[i].ord, seq[i].coef);
        if (lf == 0.0 || lf * f < 0)
            changes++;
        lf = f;
    }
    return changes;
}

/* visible_roots: the sign changes at 0 minus those at +infinity (the
 * leading coefficients' signs). */
static int visible_roots(int np, const SturmPoly *seq)
{
    int at_inf = 0, at_zero = 0;
    double lf = seq[0].coef[seq[0].ord];
    for (int i = 1; i <= np; i++) {
        double f = seq[i].coef[seq[i].ord];
        if (lf == 0.0 || lf * f < 0)
            at_inf++;
        lf = f;
    }
    lf = seq[0].coef[0];
    for (int i = 1; i <= np; i++) {
        double f = seq[i].coef[0];
        if (lf == 0.0 || lf * f < 0)
            at_zero++;
        lf = f;
    }
    return at_zero - at_inf;
}

/* regula_falsa (the Illinois variant: the end that stays has its value
 * halved); 0 when the ends do not bracket a sign change or it takes too
 * long. */
static int regula_falsi(int order, const double *coef, double a, double b, double *root)
{
    double fa = eval_low_first(a, order, coef), fb = eval_low_first(b, order, coef);
    if (fa * fb > 0.0)
        return 0;
    if (fabs(fa) < SMALL_ENOUGH) {
        *root = a;
        return 1;
    }
    if (fabs(fb) < SMALL_ENOUGH) {
        *root = b;
        return 1;
    }
    double lfx = fa;
    for (int its = 0; its < MAX_ITERATIONS; its++) {
        double x = (fb * a - fa * b) / (fb - fa);
        double fx = eval_low_first(x, order, coef);
        if (fabs(x) > RELERROR ? fabs(fx / x) < RELERROR : fabs(fx) < RELERROR) {
            *root = x;
            return 1;
        }
        /* the end whose value has fx's sign moves to x */
        int move_a = (fa < 0) == (fx < 0);
        if (move_a) {
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
        if (fabs(b - a) < RELERROR) {
            *root = x;
            return 1;
        }
        lfx = fx;
    }
    return 0;
}

/* Is the interval [lo, hi] around mid narrow enough (RELERROR, relative
 * away from 0)? */
static int narrow(double lo, double hi, double mid)
{
    return fabs(mid) > RELERROR ? fabs((hi - lo) / mid) < RELERROR : fabs(hi - lo) < RELERROR;
}

/* sbisect: the roots in [lo, hi], where the sign changes fall from at_lo
 * to at_hi: one root by regula falsi (else bisection), several by
 * bisecting until they are apart. */
static int sturm_bisect(int np, const SturmPoly *seq, double lo, double hi, int at_lo, int at_hi, double *roots)
{
    double mid = lo;
    if (at_lo - at_hi == 1) {
        if (regula_falsi(seq->ord, seq->coef, lo, hi, roots))
            return 1;
        for (int its = 0; its < MAX_ITERATIONS; its++) {
            mid = (lo + hi) / 2;
            int at_mid = sign_changes(np, seq, mid);
            if (at_mid < at_hi || at_mid > at_lo) /* POV-Ray's guard against its own inconsistency */
                return 0;
            if (narrow(lo, hi, mid)) {
                roots[0] = mid;
                return 1;
            }
            if (at_lo - at_mid == 0)
                lo = mid;
            else
                hi = mid;
        }
        roots[0] = mid;
        return 1;
    }
    for (int its = 0; its < MAX_ITERATIONS; its++) {
        mid = (lo + hi) / 2;
        int at_mid = sign_changes(np, seq, mid);
        if (at_mid < at_hi || at_mid > at_lo)
            return 0;
        if (narrow(lo, hi, mid)) {
            roots[0] = mid;
            return 1;
        }
        int below = at_lo - at_mid, above = at_mid - at_hi;
        if (below != 0 && above != 0) {
            int n1 = sturm_bisect(np, seq, lo, mid, at_lo, at_mid, roots);
            int n2 = sturm_bisect(np, seq, mid, hi, at_mid, at_hi, roots + n1);
            return n1 + n2;
        }
        if (below == 0)
            lo = mid;
        else
            hi = mid;
    }
    roots[0] = mid;
    return 1;
}

int poly_solve_sturm(int order, const double *c, double *roots)
{
    SturmPoly seq[POLY_SOLVER_MAX_ORDER + 1];
    for (int i = 0; i <= order; i++)
        seq[0].coef[order - i] = c[i] / c[0];
    int np = build_sturm(order, seq);
    if (visible_roots(np, seq) == 0)
        return 0;
    int at_lo = sign_changes(np, seq, 0.0), at_hi = sign_changes(np, seq, POLY_SOLVER_MAX_DISTANCE);
    if (at_lo - at_hi == 0)
        return 0;
    return sturm_bisect(np, seq, 0.0, POLY_SOLVER_MAX_DISTANCE, at_lo, at_hi, roots);
}

/* ---- Solve_Polynomial --------------------------------------------------------- */

int poly_solve(int n, const double *c0, double *roots, int sturm, double epsilon)
{
    int i = 0;
    while (fabs(c0[i]) < SMALL_ENOUGH && i < n)
        i++;
    n -= i;
    const double *c = c0 + i;
    switch (n) {
    case 0:
        return 0;
    case 1:
        if (c[0] == 0.0)
            return 0;
        roots[0] = -c[1] / c[0];
        return 1;
    case 2:
        return poly_solve_quadratic(c, roots);
    case 3:
        if (epsilon > 0.0 && c[2] != 0.0 && fabs(c[3] / c[2]) < epsilon)
            return poly_solve_quadratic(c, roots); /* a root at 0 taken out */
        return sturm ? poly_solve_sturm(3, c, roots) : poly_solve_cubic(c, roots);
    case 4:
        if (epsilon > 0.0 && c[3] != 0.0 && fabs(c[4] / c[3]) < epsilon)
            return sturm ? poly_solve_sturm(3, c, roots) : poly_solve_cubic(c, roots);
        if (sturm || difficult_coeffs(4, c))
            return poly_solve_sturm(4, c, roots);
        return poly_solve_quartic(c, roots);
    default:
        /* POV-Ray 3.7 solves the eliminated degree too, then overwrites
         * those roots with the full degree's: only the latter count */
        return poly_solve_sturm(n, c, roots);
    }
}
