/* CSG objects as POV-Ray 3.7 computes them (csg.cpp): an intersection,
 * merge or union (inside another CSG object) of solids, and an object
 * clipped_by others. A crossing of a part is one of the object's when the
 * point is inside every other part (intersection), inside none of them
 * (merge), or always (union); a clipped object's crossings are its first
 * part's inside every clipping solid (Point_In_Clip), which are never
 * crossings themselves; a bounded object's are its first part's along a
 * line that meets every bounding solid or starts inside it (POV-Ray's
 * Ray_In_Bound, before it tests the object), its inside the first part's; a
 * difference is an intersection whose later parts are inverted, and an
 * inverted CSG object swaps intersection and merge over inverted parts,
 * as POV-Ray's parser and Invert rewrite them. The parts are shapes
 * (shape.h), CSG objects among them, so CSG nests. */
#ifndef HST_CSG_H
#define HST_CSG_H

#include "shape.h"

/* Every crossing of CSG object s at t in (0, tmax) along org + t dir (dir
 * of unit length), nearest first; hits has room for s->max_hits. Each
 * names its primitive (ShapeHit.leaf). */
int csg_intersect_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits);

/* POV-Ray's Inside of the CSG object: inside every part (intersection,
 * and a clipped object: Inside_Object), or some part (merge, union). */
int csg_inside(const Shape *s, Vec3 p);

/* s's world box from its parts' (POV-Ray's CSG::Compute_BBox): the
 * overlap of the boxes of the parts that are not inverted for an
 * intersection (and a clipped object, within its first part's), the box
 * around them all for a merge or union. */
void csg_compute_bounds(Shape *s);

#endif
