/* POV-Ray 3.7's lathe (source/backend/shape/lathe.cpp): a spline in the
 * x-y plane of its own space (x the radius, y the height) turned about the
 * y axis; each segment's crossings are the roots in [0, 1] of a polynomial
 * in the spline's parameter (degree 2, 4 or 6 for linear, quadratic and
 * cubic or Bezier splines), solved by POV-Ray's solver
 * (polynomial_solver.h; sturm where the scene asks). POV-Ray's bounding
 * cylinders per segment only spare it tests: here too only the segments
 * whose heights and radii the ray reaches are solved for, which finds the
 * same crossings. */
#ifndef HST_LATHE_H
#define HST_LATHE_H

#include "shape.h"

/* The lathe's overall bounding cylinder (Compute_Lathe: the segments'
 * extreme radii and heights) into s->u.lathe, and its box. */
void lathe_place(Shape *s);

/* Lathe::Intersect along org + t dir (dir of unit length): crossings
 * beyond DEPTH_TOLERANCE and before MAX_DISTANCE and tmax, nearest first,
 * each with its segment as its part. */
int lathe_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits);

/* Lathe::Inside: an odd number of segments outward of the point at its
 * height. */
int lathe_inside(const Shape *s, Vec3 p);

/* Lathe::Normal at p on segment `part`, in world space, unit. */
Vec3 lathe_normal(const Shape *s, Vec3 p, int part);

/* Lathe::UVCoord: u the angle about y from +x, v the spline parameter
 * over the segments (of the segment p lies nearest). */
Vec3 lathe_uv(const Shape *s, Vec3 p);

#endif
