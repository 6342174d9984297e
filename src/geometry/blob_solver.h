/* POV-Ray 3.7's Solve_Polynomial (source/backend/math/polysolv.cpp) for
 * polynomials of degree 4 at most: its closed formulas (quadratic, cubic,
 * quartic by the cubic resolvent), its root elimination, its test for
 * "difficult" coefficients and its Sturm-sequence solver (bisection and
 * regula falsi between 0 and MAX_DISTANCE), with its constants, so that a
 * blob finds the roots POV-Ray's finds, its misses and spurious roots
 * included. The blob's own copy: the polynomial shapes' solver
 * (polynomial.h) isolates roots its own way; the two may be unified once
 * both follow POV-Ray. */
#ifndef HST_BLOB_SOLVER_H
#define HST_BLOB_SOLVER_H

#define BLOB_SOLVER_MAX_DEGREE 4

/* The real roots of c[0] x^n + c[1] x^(n-1) + ... + c[n] (n <= 4), in
 * Solve_Polynomial's order (not sorted), into roots (room for n). sturm:
 * the Sturm solver rather than the closed formulas; epsilon: the root
 * elimination's bound (0: none). Returns how many. */
int blob_solve_polynomial(int n, const double *c, double *roots, int sturm, double epsilon);

#endif
