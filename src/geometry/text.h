/* A glyph of a text object as POV-Ray 3.7 intersects it (truetype.cpp):
 * its outline of lines and quadratic Beziers in the z = 0 plane of its own
 * space, swept to z = depth. A ray meets its front (z = 0) and back
 * (z = depth) where the point is inside the outline (Inside_Glyph's
 * crossing count), and its walls where its projection crosses an outline
 * segment between the two depths (GlyphIntersect). Parts of a crossing:
 * GLYPH_FRONT, GLYPH_BACK, or GLYPH_WALL + the index of the segment's last
 * point (a line's end, a curve's control point) among the glyph's points. */
#ifndef HST_TEXT_H
#define HST_TEXT_H

#include "shape.h"

enum { GLYPH_FRONT = 1, GLYPH_BACK = 2, GLYPH_WALL = 3 };

/* The most crossings a line can have with the glyph: front, back, one per
 * line segment and two per curve. */
int glyph_max_hits(const struct SceneGlyph *g);

/* TrueType::All_Intersections along org + t dir (dir of unit length in
 * world space), t in (TTF_Tolerance, tmax), nearest first. */
int glyph_intersect_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits);

/* TrueType::Inside: between the faces and inside the outline. */
int glyph_inside(const Shape *s, Vec3 p);

/* The normal POV-Ray computes at the crossing (GlyphIntersect's), of part
 * `part` at world point p. */
Vec3 glyph_normal(const Shape *s, Vec3 p, int part);

/* Its box in its own space, from the glyph header (Compute_BBox). */
void glyph_local_bounds(const Shape *s, Vec3 *lo, Vec3 *hi);

#endif
