/* POV-Ray 3.7's polynomial solver (src/geometry/polynomial_solver.h)
 * against polynomials of known roots: the closed formulas for the
 * quadratic, cubic and quartic, the Sturm sequence (only roots in
 * [0, MAX_DISTANCE]), Solve_Polynomial's dropping of small leading
 * coefficients, its root elimination and its switch to Sturm for a
 * quartic whose coefficients span more than 1e12. */
#include <math.h>
#include <stdlib.h>

#include "polynomial_solver.h"
#include "tap.h"

/* c (degree n, highest power first) = the product of (x - r[i]). */
static void from_roots(const double *r, int n, double *c)
{
    c[0] = 1.0;
    for (int i = 1; i <= n; i++)
        c[i] = 0.0;
    for (int k = 0; k < n; k++)
        for (int i = k + 1; i >= 1; i--)
            c[i] -= r[k] * c[i - 1];
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* got (n of them, any order) are want (m, ascending) within tol each. */
static int roots_are(double *got, int n, const double *want, int m, double tol)
{
    if (n != m)
        return 0;
    qsort(got, (size_t)n, sizeof *got, cmp_double);
    for (int i = 0; i < n; i++)
        if (!(fabs(got[i] - want[i]) <= tol * (1.0 + fabs(want[i]))))
            return 0;
    return 1;
}

static void check(const char *what, int n, double *got, const double *want, int m, double tol)
{
    int ok = roots_are(got, n, want, m, tol);
    tap_ok(ok, "%s: %d roots as known", what, m);
    if (!ok) {
        for (int i = 0; i < n; i++)
            tap_diag("root %d: %.17g", i, got[i]);
    }
}

int main(void)
{
    double c[POLY_SOLVER_MAX_ORDER + 1], r[POLY_SOLVER_MAX_ORDER];

    /* quadratics: two roots, a double root (discriminant within 1e-10 of 0), none */
    const double q2[] = { 1.0, 3.0 };
    from_roots(q2, 2, c);
    check("quadratic (x-1)(x-3)", poly_solve_quadratic(c, r), r, q2, 2, 1e-15);
    const double dbl[] = { 2.0 };
    const double c_dbl[] = { 1.0, -4.0, 4.0 };
    check("quadratic (x-2)^2: one root", poly_solve_quadratic(c_dbl, r), r, dbl, 1, 0.0);
    const double c_none[] = { 1.0, 0.0, 1.0 };
    tap_ok(poly_solve_quadratic(c_none, r) == 0, "quadratic x^2+1: no root");

    /* cubics: three real roots (trigonometric form), one (Cardano's) */
    const double q3[] = { -1.5, 0.25, 4.0 };
    from_roots(q3, 3, c);
    check("cubic of roots -1.5, 0.25, 4", poly_solve_cubic(c, r), r, q3, 3, 1e-12);
    const double c_one[] = { 1.0, -2.0, 1.0, -2.0 }; /* (x-2)(x^2+1) */
    const double two[] = { 2.0 };
    check("cubic (x-2)(x^2+1)", poly_solve_cubic(c_one, r), r, two, 1, 1e-14);

    /* quartics by the resolvent: four roots, two, none */
    const double q4[] = { -3.0, 1.0, 2.0, 5.0 };
    from_roots(q4, 4, c);
    check("quartic of roots -3, 1, 2, 5", poly_solve_quartic(c, r), r, q4, 4, 1e-9);
    const double c_two[] = { 1.0, 0.0, 0.0, 0.0, -1.0 }; /* x^4 - 1 */
    const double pm1[] = { -1.0, 1.0 };
    check("quartic x^4-1", poly_solve_quartic(c_two, r), r, pm1, 2, 1e-14);
    const double c_zero[] = { 1.0, 0.0, 0.0, 0.0, 1.0 };
    tap_ok(poly_solve_quartic(c_zero, r) == 0, "quartic x^4+1: no root");

    /* Sturm: only the roots in [0, MAX_DISTANCE], each to RELERROR */
    from_roots(q4, 4, c);
    const double q4_pos[] = { 1.0, 2.0, 5.0 };
    check("Sturm on the quartic of roots -3, 1, 2, 5: the three >= 0", poly_solve_sturm(4, c, r), r, q4_pos, 3,
          1e-11);
    const double q6[] = { 0.5, 1.0, 2.0, 3.0, 4.0, 6.0 };
    from_roots(q6, 6, c);
    check("poly of degree 6 (Sturm)", poly_solve(6, c, r, 0, 0.0), r, q6, 6, 1e-11);
    const double cfar[] = { 1.0, -(10.0 + 2.0e7 - 7.0), (10.0 * 2.0e7 - 7.0 * (10.0 + 2.0e7)), 7.0 * 10.0 * 2.0e7 };
    const double ten[] = { 10.0 };
    check("Sturm on (x+7)(x-10)(x-2e7): the root beyond MAX_DISTANCE left out", poly_solve_sturm(3, cfar, r), r,
          ten, 1, 1e-11);

    /* Solve_Polynomial: a leading coefficient below 1e-10 is dropped */
    const double c_lead[] = { 1e-12, 1.0, -3.0, 2.0 };
    const double one_two[] = { 1.0, 2.0 };
    check("1e-12 x^3 + (x-1)(x-2): solved as the quadratic", poly_solve(3, c_lead, r, 0, 0.0), r, one_two, 2, 1e-15);
    /* root elimination: x(x-1)(x-2)(x-3) + 1e-9, the constant 1e-9 / 6 of
     * the linear term: the root at 0 is taken out, the cubic solved */
    const double q4z[] = { 0.0, 1.0, 2.0, 3.0 };
    from_roots(q4z, 4, c);
    c[4] = 1e-9;
    const double q4z_rest[] = { 1.0, 2.0, 3.0 };
    check("x(x-1)(x-2)(x-3) + 1e-9, root elimination 1e-4", poly_solve(4, c, r, 0, 1e-4), r, q4z_rest, 3, 1e-12);
    /* without elimination the quartic's four roots (the smallest near -1.7e-10) */
    int n = poly_solve(4, c, r, 0, 0.0);
    tap_ok(n == 4, "the same without elimination: 4 roots (%d)", n);
    /* a quartic whose coefficients span more than 1e12 goes to Sturm: its
     * negative root is not returned */
    const double q4d[] = { -2.0, 1e-13, 1.0, 3.0 };
    from_roots(q4d, 4, c);
    n = poly_solve(4, c, r, 0, 0.0);
    int negative = 0, near1 = 0, near3 = 0;
    for (int i = 0; i < n; i++) {
        negative += r[i] < 0.0;
        near1 += fabs(r[i] - 1.0) < 1e-9;
        near3 += fabs(r[i] - 3.0) < 1e-9;
    }
    tap_ok(negative == 0 && near1 == 1 && near3 == 1,
           "quartic of roots -2, 1e-13, 1, 3 (coefficients 1e13 apart): Sturm's roots >= 0 alone (%d roots)", n);
    /* the Sturm flag on a cubic: the same roots >= 0 */
    from_roots(q3, 3, c);
    const double q3_pos[] = { 0.25, 4.0 };
    check("cubic with sturm: the roots >= 0", poly_solve(3, c, r, 1, 0.0), r, q3_pos, 2, 1e-11);
    return tap_done();
}
