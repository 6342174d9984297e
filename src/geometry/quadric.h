/* POV-Ray 3.7's quadric (source/backend/shape/quadrics.cpp): the solid
 * where A x^2 + E y^2 + H z^2 + B xy + C xz + F yz + D x + G y + I z + J
 * <= 0, its coefficients carried into world space by its transforms (as
 * Quadric::Transform carries them: the 4x4 matrix of the form multiplied
 * by the inverse transform on both sides), so that a ray is tested in
 * world space as POV-Ray tests it. Often infinite: its bounds are
 * Quadric::Compute_BBox's where the form is an axis-aligned ellipsoid or
 * cylinder, else unbounded (the shapes' hierarchy holds such a shape as it
 * holds any other, in a box of +-1e30). */
#ifndef HST_QUADRIC_H
#define HST_QUADRIC_H

#include "shape.h"

/* Makes s (of kind SHAPE_QUADRIC) the quadric of the coefficients as
 * written (square <A,E,H>, mixed <B,C,F>, terms <D,G,I>, constant J),
 * moved by to_world and inverted where `inverse` (every coefficient
 * negated, as Quadric::Invert), with its bounds. */
void quadric_place(Shape *s, Vec3 square, Vec3 mixed, Vec3 terms, double constant, const Transform *to_world,
                   int inverse);

/* Quadric::All_Intersections along org + t dir, dir of unit length: both
 * roots beyond DEPTH_TOLERANCE and before MAX_DISTANCE and tmax, nearest
 * first. */
int quadric_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits);

/* Quadric::Inside: the form at p is <= 0. */
int quadric_inside(const Shape *s, Vec3 p);

/* Quadric::Normal: the form's gradient at p made unit (x where it
 * vanishes). */
Vec3 quadric_normal(const Shape *s, Vec3 p);

/* Quadric::Compute_BBox's Automatic_Bounds for the quadric as written
 * (before its transforms and clips, as Parse_Quadric calls it): its form
 * has no mixed terms and its box came out smaller than the object's first
 * (BOUND_HUGE on each side). POV-Ray then drops the object's bounded_by
 * as unnecessary; without it, it keeps the bound and tests it first. */
int quadric_automatic_bounds(Vec3 square, Vec3 mixed, Vec3 terms, double constant);

#endif
