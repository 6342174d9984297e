/* POV-Ray 3.7's surface of revolution (source/backend/shape/sor.cpp): in
 * its own space, the squared radius x^2 + z^2 a cubic in the height y per
 * segment, capped by discs at its lowest and highest heights unless open.
 * Along a ray each segment gives a cubic in the distance, solved by
 * POV-Ray's solver (polynomial_solver.h; sturm where the scene asks) and
 * kept within the segment's heights. POV-Ray's bounding cylinders per
 * segment only spare it tests: here too only the segments whose heights
 * and radii the ray reaches are solved for, which finds the same
 * crossings. */
#ifndef HST_SOR_H
#define HST_SOR_H

#include "shape.h"

/* The overall bounding cylinder and the base and cap discs' squared
 * radii (Compute_Sor) into s->u.sor. */
void sor_place(Shape *s);

/* Sor::Intersect along org + t dir (dir of unit length), nearest first;
 * a crossing's part: SOR_BASE, SOR_CAP, or SOR_CURVE + its segment. */
int sor_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits);
enum { SOR_BASE = 0, SOR_CAP = 1, SOR_CURVE = 2 };

/* Sor::Inside: within the heights and the first segment there whose
 * squared radius is at least the point's. */
int sor_inside(const Shape *s, Vec3 p);

/* Sor::Normal at p on part `part`, in world space, unit. */
Vec3 sor_normal(const Shape *s, Vec3 p, int part);

/* Sor::UVCoord: u the angle about y from +x, v up the segments (the
 * part found again from the point: its height, and the discs at the
 * ends). */
Vec3 sor_uv(const Shape *s, Vec3 p);

#endif
