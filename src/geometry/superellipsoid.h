/* POV-Ray 3.7's superellipsoid (source/backend/shape/super.cpp): the solid
 * (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) <= 1 in its own space, reached
 * through its transform, intersected by POV-Ray's own root finder: the
 * ray cut by its box (+-1.01) and by nine planes through the centre into
 * pieces, each piece's ends tested for a change of sign and solved by a
 * mix of secant and bisection (solve_hit1), or walked by secant steps
 * where a piece might touch the surface without a change of sign
 * (check_hit2), with its tolerances. */
#ifndef HST_SUPERELLIPSOID_H
#define HST_SUPERELLIPSOID_H

#include "shape.h"

/* Superellipsoid::Intersect along org + t dir (dir of unit length): the
 * crossings beyond DEPTH_TOLERANCE and before MAX_DISTANCE and tmax,
 * nearest first. */
int superellipsoid_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits);

/* Superellipsoid::Inside: the function below EPSILON (inverse swaps). */
int superellipsoid_inside(const Shape *s, Vec3 p);

/* Superellipsoid::Normal, carried to world space and made unit. */
Vec3 superellipsoid_normal(const Shape *s, Vec3 p);

#endif
