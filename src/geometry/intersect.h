/* Ray/polygon and ray/plane intersection, and the point-in-polygon test. */
#ifndef HST_INTERSECT_H
#define HST_INTERSECT_H

#include "world.h"

/* Distance along `dir` (not necessarily unit) from `org` to polygon `p`, or a
 * negative value when the line misses it or runs parallel to its plane. */
double intersect_polygon(const World *w, const Polygon *p, Vec3 org, Vec3 dir);

/* The ray's own frame (Woop, Benthin and Wald, JCGT 2013): axes permuted so
 * the ray runs along z, then sheared so it becomes the z axis itself. A
 * point's 2-D position in that frame depends only on the ray and the point,
 * so an edge shared by two polygons is seen the same way from both: the
 * inside tests made in it are watertight. Made once per ray. */
typedef struct {
    int kx, ky, kz;
    double sx, sy;
    Vec3 org, dir;
    double ox, oy, oz;  /* the origin's coordinates on kx, ky, kz */
    double org_scale;   /* 1 + the origin's largest coordinate, for plane_distance */
} RayFrame;

RayFrame ray_frame(Vec3 org, Vec3 dir);
/* intersect_polygon for a ray whose frame is already made; hits at tmax or
 * beyond are not looked at (negative). */
double intersect_polygon_in(const World *w, const Polygon *p, const RayFrame *f, double tmax);

/* A polygon's plane and points side by side, copied from the polygon and
 * its points, so that a test reads one record instead of the polygon, then
 * its outline's start, then its points (the hierarchy keeps one per leaf
 * item, bvh.h): triangles, and polygons of one outline of up to
 * PACKED_POINTS points (a box's faces). */
#define PACKED_POINTS 4
typedef struct {
    Vec3 v[PACKED_POINTS];
    Vec3 normal;
    double d;
    int n;                /* 3: a triangle; more: one outline of n points */
} PackedPolygon;

/* Packs p when it is such a polygon (1), else 0. */
int polygon_pack(const World *w, const Polygon *p, PackedPolygon *pp);

/* intersect_polygon_in for the polygon pp was packed from: the same
 * arithmetic on the same numbers, so the same answer, bit for bit. */
double intersect_packed(const PackedPolygon *pp, const RayFrame *f, double tmax);

/* The distance along the frame's ray to p's plane, as intersect_polygon_in
 * computes it (bit for bit), or -1 when the ray runs parallel to the plane
 * or starts in it. For tests made elsewhere (Embree's, in float) that need
 * the shadow ray's distance of a hit they found. */
double intersect_plane_distance(const Polygon *p, const RayFrame *f);

/* Distance to an infinite plane, or negative when parallel or behind. */
double intersect_plane(const InfinitePlane *pl, Vec3 org, Vec3 dir);

/* Is the point (already on the plane of p) inside p? Even-odd over all of
 * p's outlines, so later outlines cut holes, as in POV-Ray. */
int polygon_contains(const World *w, const Polygon *p, Vec3 q);

/* The outlines of polygon p: how many (a triangle has one), and the points
 * of outline k (closed implicitly: the last point joins the first). */
static inline int polygon_outline_count(const Polygon *p) { return p->first_outline < 0 ? 1 : p->noutlines; }
static inline const Vec3 *polygon_outline(const World *w, const Polygon *p, int k, int *n)
{
    if (p->first_outline < 0) {
        *n = 3;
        return &w->points[p->first_point];
    }
    const int *start = &w->outline_start[p->first_outline];
    *n = start[k + 1] - start[k];
    return &w->points[start[k]];
}

/* Where point x (taken to lie in p's plane) is against polygon p, projected
 * onto p's two kept axes: 1 inside, 0 outside, -1 within `margin` of its
 * border (an edge or vertex). Projection only shortens distances, so a 2-D
 * margin is at least that margin in 3-D. */
int polygon_classify_point(const World *w, const Polygon *p, Vec3 x, double margin);

/* Squared distance from (qu, qv) to the segment (au, av)-(bu, bv) in 2-D. */
double segment_distance2_2d(double au, double av, double bu, double bv, double qu, double qv);

/* Crossing-number test of the point (qu, qv) against one closed outline of
 * n points, projected onto axes iu and iv. */
int outline_contains(const Vec3 *pts, int n, int iu, int iv, double qu, double qv);

/* The shading normal of p at q: the plane normal, or the interpolated
 * vertex normal of a smooth triangle. Not yet flipped toward the viewer. */
Vec3 polygon_shading_normal(const World *w, const Polygon *p, Vec3 q);
/* The barycentric weights b[0..2] of point q (in the plane) in triangle p,
 * one per point; 0 when the triangle has no area in its projection. */
int polygon_barycentric(const World *w, const Polygon *p, Vec3 q, double b[3]);

#endif
