/* POV-Ray 3.7's polynomial solver (source/backend/math/polysolv.cpp,
 * Solve_Polynomial), for the shapes whose surfaces it intersects with it
 * (poly, cubic, quartic, torus, ...): the same closed formulas for the quadratic,
 * cubic and quartic, the same switch to its Sturm-sequence solver (asked
 * for by `sturm`, or forced where a quartic's coefficients span more than
 * 1e12), the same root elimination and tolerances, so that the roots
 * found, missed and misplaced are POV-Ray's own. */
#ifndef HST_POLYNOMIAL_SOLVER_H
#define HST_POLYNOMIAL_SOLVER_H

/* The highest degree POV-Ray solves (its MAX_ORDER). */
#define POLY_SOLVER_MAX_ORDER 35

/* POV-Ray's MAX_DISTANCE: its Sturm solver brackets roots in [0, this]. */
#define POLY_SOLVER_MAX_DISTANCE 1.0e7

/* Solve_Polynomial: the real roots of c[0] x^n + c[1] x^(n-1) + ... +
 * c[n] (n <= POLY_SOLVER_MAX_ORDER) into roots (room for n), in no
 * particular order (the closed formulas may return negative roots, the
 * Sturm solver only those in [0, MAX_DISTANCE]); leading coefficients
 * below 1e-10 are dropped first. epsilon > 0: where the constant is that
 * small against the linear coefficient, 0 is taken for a root and the
 * lower degree left over solved (POV-Ray's root elimination). Returns how
 * many. */
int poly_solve(int n, const double *c, double *roots, int sturm, double epsilon);

/* Its parts, for the unit tests: solve_quadratic, solve_cubic and
 * solve_quartic (c[0] x^2 ..., highest power first), and polysolve (the
 * Sturm sequence, roots in [0, MAX_DISTANCE]). */
int poly_solve_quadratic(const double *c, double *roots);
int poly_solve_cubic(const double *c, double *roots);
int poly_solve_quartic(const double *c, double *roots);
int poly_solve_sturm(int order, const double *c, double *roots);

#endif
