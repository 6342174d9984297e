/* POV-Ray 3.7's poly, cubic and quartic (source/backend/shape/poly.cpp):
 * the solid where a polynomial in x, y, z of degree 2 to 35 is below
 * INSIDE_TOLERANCE, in its own space (reached through its transform, as
 * Poly keeps a Trans). A ray's polynomial in its distance is built term by
 * term as Poly::intersect builds it and solved by POV-Ray's own solver
 * (polynomial_solver.h); a poly is unbounded (Poly::Compute_BBox). */
#ifndef HST_POLY_H
#define HST_POLY_H

#include "shape.h"

/* The number of coefficients of a polynomial of this order in three
 * variables (POV-Ray's term_counts). */
int poly_term_count(int order);

/* Poly::All_Intersections along org + t dir (dir of unit length): the
 * roots beyond DEPTH_TOLERANCE in its own space, equal roots once, before
 * tmax, nearest first. */
int poly_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits);

/* Poly::Inside: the polynomial below INSIDE_TOLERANCE (inverse swaps). */
int poly_inside(const Shape *s, Vec3 p);

/* Poly::Normal: the gradient in its own space carried to world space and
 * made unit (x where it vanishes). */
Vec3 poly_normal(const Shape *s, Vec3 p);

#endif
