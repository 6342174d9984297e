/* POV-Ray 3.7's prism (source/backend/shape/prism.cpp): an outline of
 * spline segments in the x-z plane of its own space (scene.h's
 * PrismSegment, each a cubic in its parameter t in [0, 1]) swept along y
 * between two heights, straight (linear_sweep) or scaled by the height
 * through the apex at the origin (conic_sweep), capped unless open. A ray
 * meets a segment's side where the segment's cubic in t (degree 1, 2 or 3
 * for linear, quadratic and cubic or Bezier splines) has a root in [0, 1],
 * solved by POV-Ray's solver (polynomial_solver.h); a cap where the point
 * lies inside an odd number of the outlines. */
#ifndef HST_PRISM_H
#define HST_PRISM_H

#include "shape.h"

/* A crossing's part: the caps (whose normal is y), or segment j as
 * PRISM_SEGMENT_PART + j. */
enum { PRISM_CAPS_PART = 0, PRISM_SEGMENT_PART = 1 };

/* Prism::All_Intersections along org + t dir (dir of unit length):
 * crossings beyond DEPTH_TOLERANCE and before MAX_DISTANCE and tmax,
 * nearest first (the nearest s->max_hits where there are more). */
int prism_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits);

/* Prism::Inside: between the heights (below the upper one) and inside
 * the outlines there. */
int prism_inside(const Shape *s, Vec3 p);

/* Prism::Normal at p on part `part`, in world space, unit. */
Vec3 prism_normal(const Shape *s, Vec3 p, int part);

#endif
