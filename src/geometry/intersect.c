/* Intersections: the distance from the plane, then a watertight inside test
 * in the ray's own frame (triangles: three edge functions; polygons with
 * outlines: an even-odd crossing count). Point-in-polygon tests for points
 * already in a polygon's plane use the projection that drops the normal's
 * dominant axis. */
#include "intersect.h"
#include "planar_shapes.h"

#include <string.h>

static inline double comp(Vec3 a, int axis) { return axis == 0 ? a.x : axis == 1 ? a.y : a.z; }

/* Twice the signed area of (a, b, q) in the projection. */
static inline double edge_side(double au, double av, double bu, double bv, double qu, double qv)
{
    return (bu - au) * (qv - av) - (bv - av) * (qu - au);
}

static int triangle_contains(const Vec3 *v, int iu, int iv, double qu, double qv)
{
    double s0 = edge_side(comp(v[0], iu), comp(v[0], iv), comp(v[1], iu), comp(v[1], iv), qu, qv);
    double s1 = edge_side(comp(v[1], iu), comp(v[1], iv), comp(v[2], iu), comp(v[2], iv), qu, qv);
    double s2 = edge_side(comp(v[2], iu), comp(v[2], iv), comp(v[0], iu), comp(v[0], iv), qu, qv);
    /* Points on an edge count as inside, so a ray through the shared edge of
     * two triangles hits at least one of them (no light leaks). */
    return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

int outline_contains(const Vec3 *pts, int n, int iu, int iv, double qu, double qv)
{
    int inside = 0;
    for (int i = 0; i < n; i++) {
        Vec3 a = pts[i], b = pts[i + 1 < n ? i + 1 : 0];
        double au = comp(a, iu), av = comp(a, iv);
        double bu = comp(b, iu), bv = comp(b, iv);
        if ((av >= qv) != (bv >= qv)) {
            /* u of the edge at height qv, compared without division. */
            double lhs = (qu - au) * (bv - av), rhs = (qv - av) * (bu - au);
            if ((bv > av) ? lhs < rhs : lhs > rhs)
                inside = !inside;
        }
    }
    return inside;
}

/* Even-odd over all outlines: a point inside an odd number of them is inside. */
static int outlines_contain(const World *w, const Polygon *p, double qu, double qv)
{
    int inside = 0;
    const int *start = &w->outline_start[p->first_outline];
    for (int k = 0; k < p->noutlines; k++)
        inside ^= outline_contains(&w->points[start[k]], start[k + 1] - start[k], p->axis_u, p->axis_v, qu, qv);
    return inside;
}

int polygon_contains(const World *w, const Polygon *p, Vec3 q)
{
    double qu = comp(q, p->axis_u), qv = comp(q, p->axis_v);
    if (p->first_outline < 0)
        return triangle_contains(&w->points[p->first_point], p->axis_u, p->axis_v, qu, qv);
    return outlines_contain(w, p, qu, qv);
}

/* Distance along dir from org to p's plane; -1 when the ray runs parallel
 * to it, or starts in it (to within rounding of the coordinates): such a
 * ray meets the polygon at its own start point or only grazes it edge-on,
 * and a distance computed from two rounding errors would be arbitrary (a
 * camera in the plane of a polygon would see it at random points). */
static inline double plane_distance_nd(Vec3 normal, double d, const RayFrame *f)
{
    double num = d - v3_dot(normal, f->org);
    double denom = v3_dot(normal, f->dir);
    if (denom == 0.0 || fabs(num) <= 1e-12 * (f->org_scale + fabs(d)))
        return -1.0;
    return num / denom;
}

static inline double plane_distance(const Polygon *p, const RayFrame *f)
{
    return plane_distance_nd(p->normal, p->d, f);
}

RayFrame ray_frame(Vec3 org, Vec3 dir)
{
    /* Made once per ray, shadow rays included: components by index and the
     * next axis from a table rather than comp()'s branches and a modulo. */
    static const int next_axis[3] = { 1, 2, 0 };
    const double d[3] = { dir.x, dir.y, dir.z }, o[3] = { org.x, org.y, org.z };
    RayFrame f;
    f.kz = fabs(d[0]) > fabs(d[1]) ? (fabs(d[0]) > fabs(d[2]) ? 0 : 2) : (fabs(d[1]) > fabs(d[2]) ? 1 : 2);
    f.kx = next_axis[f.kz];
    f.ky = next_axis[f.kx];
    if (d[f.kz] < 0.0) { /* keep the winding */
        int swap = f.kx;
        f.kx = f.ky;
        f.ky = swap;
    }
    f.sx = d[f.kx] / d[f.kz];
    f.sy = d[f.ky] / d[f.kz];
    f.org = org;
    f.dir = dir;
    f.ox = o[f.kx];
    f.oy = o[f.ky];
    f.oz = o[f.kz];
    f.org_scale = 1.0 + v3_max_abs(org);
    return f;
}

/* A point's coordinate at byte offset `at` (axis * sizeof(double)) of
 * its Vec3: one load. Copying the point into an array to index it, as
 * this did, cost a store and a reload per coordinate, and the polygon
 * tests run per shadow ray. */
_Static_assert(sizeof(Vec3) == 3 * sizeof(double), "a Vec3 is three doubles, unpadded");
static inline double coord_at(const Vec3 *p, size_t at)
{
    double c;
    memcpy(&c, (const unsigned char *)p + at, sizeof c);
    return c;
}

/* The frame's axes as byte offsets into a Vec3, and its shear, read once
 * per polygon rather than per point. */
typedef struct {
    size_t x, y, z;
    double ox, oy, oz, sx, sy;
} FrameAxes;

static inline FrameAxes frame_axes(const RayFrame *f)
{
    FrameAxes a = { (size_t)f->kx * sizeof(double), (size_t)f->ky * sizeof(double), (size_t)f->kz * sizeof(double),
                    f->ox, f->oy, f->oz, f->sx, f->sy };
    return a;
}

static inline void frame_project(const FrameAxes *a, const Vec3 *p, double *x, double *y)
{
    double z = coord_at(p, a->z) - a->oz;
    *x = (coord_at(p, a->x) - a->ox) - a->sx * z;
    *y = (coord_at(p, a->y) - a->oy) - a->sy * z;
}

/* Twice the signed area of (origin, a, b) in the frame: where the ray passes
 * the edge a-b. Computed from the same numbers for every polygon holding
 * the edge, so swapping a and b gives exactly the negated value; an exact
 * zero is refined in long double (still exactly antisymmetric). */
static inline double edge_function(double ax, double ay, double bx, double by)
{
    double e = ax * by - ay * bx;
    if (e == 0.0)
        e = (double)((long double)ax * by - (long double)ay * bx);
    return e;
}

/* Watertight ray/triangle test: a ray through a shared edge or vertex hits
 * at least one of the triangles holding it, whatever the rounding (no light
 * leaks, and no camera ray slips into a closed mesh between its faces).
 * Points on an edge count as inside. The distance comes from the plane, as
 * for other polygons. */
static inline double intersect_triangle_nd(Vec3 normal, double d, const Vec3 *v, const RayFrame *f, double tmax)
{
    double t = plane_distance_nd(normal, d, f);
    if (!(t > 0.0 && t < tmax))
        return -1.0;
    double ax, ay, bx, by, cx, cy;
    const FrameAxes axes = frame_axes(f);
    frame_project(&axes, &v[0], &ax, &ay);
    frame_project(&axes, &v[1], &bx, &by);
    frame_project(&axes, &v[2], &cx, &cy);
    double u = edge_function(bx, by, cx, cy), vv = edge_function(cx, cy, ax, ay), ww = edge_function(ax, ay, bx, by);
    if ((u < 0.0 || vv < 0.0 || ww < 0.0) && (u > 0.0 || vv > 0.0 || ww > 0.0))
        return -1.0;
    if (u + vv + ww == 0.0)
        return -1.0; /* the ray runs in the triangle's plane */
    return t;
}

static double intersect_triangle(const Polygon *p, const Vec3 *v, const RayFrame *f, double tmax)
{
    return intersect_triangle_nd(p->normal, p->d, v, f, tmax);
}

/* Polygons with outlines (holes cut by later outlines, even-odd): the same
 * frame, and a crossing count along the frame's +x half-line. Each edge's
 * crossing is decided by its end points' sides of the x axis (half-open, so
 * a vertex on the axis is counted once) and the sign of its edge function,
 * so two polygons sharing an edge see it cross or not alike, and a ray
 * through a shared edge is inside one of them. A ray meeting an edge or
 * vertex exactly is inside (inclusive, as for triangles). */
/* One outline's part of that count: flips *inside at each crossing;
 * returns 1 when the ray meets the outline's border. */
static inline int outline_crossings(const Vec3 *pts, int n, const RayFrame *f, int *inside)
{
    const FrameAxes axes = frame_axes(f);
    int in = *inside; /* a local, so that its stores do not make the frame's fields be read again */
    double px, py;
    frame_project(&axes, &pts[n - 1], &px, &py);
    for (int i = 0; i < n; i++) {
        double qx, qy;
        frame_project(&axes, &pts[i], &qx, &qy);
        double e = edge_function(px, py, qx, qy);
        if (e == 0.0 && fmin(px, qx) <= 0.0 && fmax(px, qx) >= 0.0 && fmin(py, qy) <= 0.0 && fmax(py, qy) >= 0.0 &&
            (px != qx || py != qy))
            return 1; /* on the border */
        if ((py > 0.0) != (qy > 0.0) && (e > 0.0) == (qy > py))
            in = !in;
        px = qx;
        py = qy;
    }
    *inside = in;
    return 0;
}

/* Whether every point of an outline inside box b lies on one side of the
 * ray in its frame (x < 0, x > 0, y > 0 or y < 0), as frame_project
 * computes the points: then the outline cannot flip the count, and the
 * ray is not on its border, so it can be passed over. Where all x < 0, no
 * edge crosses +x: an edge from y < 0 to y > 0 has an edge function that
 * is a sum of two terms <= 0 (and the long double refinement keeps that
 * sign where the products underflow), and the other way >= 0, both the
 * sign that puts the crossing on -x. Where all x > 0, every edge that
 * changes sides crosses +x, and a closed outline changes sides an even
 * number of times. Where all y > 0, or all y < 0, no edge changes sides.
 * Exact, not a margin: the rounded projection is monotone in each
 * coordinate (each operation rounds monotonically), so the box's corner
 * furthest that way bounds every point's projection as computed. */
static inline int frame_box_outside(const FrameAxes *a, const OutlineBox *b)
{
    double zlo = coord_at(&b->lo, a->z) - a->oz, zhi = coord_at(&b->hi, a->z) - a->oz;
    double ymin = (coord_at(&b->lo, a->y) - a->oy) - a->sy * (a->sy >= 0.0 ? zhi : zlo);
    double ymax = (coord_at(&b->hi, a->y) - a->oy) - a->sy * (a->sy >= 0.0 ? zlo : zhi);
    if (ymin > 0.0 || ymax < 0.0)
        return 1;
    double xmin = (coord_at(&b->lo, a->x) - a->ox) - a->sx * (a->sx >= 0.0 ? zhi : zlo);
    double xmax = (coord_at(&b->hi, a->x) - a->ox) - a->sx * (a->sx >= 0.0 ? zlo : zhi);
    return xmin > 0.0 || xmax < 0.0;
}

static double intersect_outlines(const World *w, const Polygon *p, const RayFrame *f, double tmax)
{
    double t = plane_distance(p, f);
    if (!(t > 0.0 && t < tmax))
        return -1.0;
    const FrameAxes axes = frame_axes(f);
    const OutlineBox *boxes =
        w->outline_box && polygon_has_outline_boxes(p->noutlines, p->npoints) ? &w->outline_box[p->first_outline] : NULL;
    int inside = 0;
    for (int k = 0; k < p->noutlines; k++) {
        int n;
        const Vec3 *pts = polygon_outline(w, p, k, &n);
        if (boxes && frame_box_outside(&axes, &boxes[k]))
            continue;
        if (outline_crossings(pts, n, f, &inside))
            return t; /* on the border */
    }
    return inside ? t : -1.0;
}

double intersect_packed(const PackedPolygon *pp, const RayFrame *f, double tmax)
{
    if (pp->n == 3)
        return intersect_triangle_nd(pp->normal, pp->d, pp->v, f, tmax);
    double t = plane_distance_nd(pp->normal, pp->d, f);
    if (!(t > 0.0 && t < tmax))
        return -1.0;
    int inside = 0;
    if (outline_crossings(pp->v, pp->n, f, &inside))
        return t; /* on the border */
    return inside ? t : -1.0;
}

int polygon_pack(const World *w, const Polygon *p, PackedPolygon *pp)
{
    int n;
    const Vec3 *pts = polygon_outline(w, p, 0, &n);
    if (polygon_outline_count(p) != 1 || n > PACKED_POINTS || n < 3)
        return 0;
    /* A one-outline polygon of three points is only ever a triangle
     * (flatten.c), and tested as one. */
    if (n == 3 && p->first_outline >= 0)
        return 0;
    for (int i = 0; i < n; i++)
        pp->v[i] = pts[i];
    pp->n = n;
    pp->normal = p->normal;
    pp->d = p->d;
    return 1;
}

double intersect_polygon_in(const World *w, const Polygon *p, const RayFrame *f, double tmax)
{
    if (p->first_outline < 0)
        return intersect_triangle(p, &w->points[p->first_point], f, tmax);
    return intersect_outlines(w, p, f, tmax);
}

double intersect_plane_distance(const Polygon *p, const RayFrame *f)
{
    return plane_distance(p, f);
}

double intersect_polygon(const World *w, const Polygon *p, Vec3 org, Vec3 dir)
{
    RayFrame f = ray_frame(org, dir);
    return intersect_polygon_in(w, p, &f, HUGE_VAL);
}

double intersect_plane(const InfinitePlane *pl, Vec3 org, Vec3 dir)
{
    double denom = v3_dot(pl->normal, dir);
    if (denom == 0.0)
        return -1.0;
    double t = (pl->d - v3_dot(pl->normal, org)) / denom;
    return t > 0.0 ? t : -1.0;
}

int polygon_barycentric(const World *w, const Polygon *p, Vec3 q, double b[3])
{
    /* From sub-triangle areas in the projection: the weights POV-Ray's
     * smooth triangles and mesh faces compute (Calculate_Smooth_T), written
     * plainly. */
    const Vec3 *v = &w->points[p->first_point];
    int iu = p->axis_u, iv = p->axis_v;
    double qu = comp(q, iu), qv = comp(q, iv);
    double area = edge_side(comp(v[0], iu), comp(v[0], iv), comp(v[1], iu), comp(v[1], iv), comp(v[2], iu), comp(v[2], iv));
    if (area == 0.0)
        return 0;
    b[0] = edge_side(comp(v[1], iu), comp(v[1], iv), comp(v[2], iu), comp(v[2], iv), qu, qv) / area;
    b[1] = edge_side(comp(v[2], iu), comp(v[2], iv), comp(v[0], iu), comp(v[0], iv), qu, qv) / area;
    b[2] = 1.0 - b[0] - b[1];
    return 1;
}

Vec3 polygon_shading_normal(const World *w, const Polygon *p, Vec3 q)
{
    if (p->smooth_normals < 0)
        return p->normal;
    if (p->cell_normals)
        return cell_normal_at(&w->vertex_normals[p->smooth_normals], q, p->normal);
    const Vec3 *n = &w->vertex_normals[p->smooth_normals];
    double b[3];
    if (!polygon_barycentric(w, p, q, b))
        return p->normal;
    Vec3 r = v3_add(v3_add(v3_scale(n[0], b[0]), v3_scale(n[1], b[1])), v3_scale(n[2], b[2]));
    double len = v3_length(r);
    return len > 0.0 ? v3_scale(r, 1.0 / len) : p->normal;
}

static double sq(double x) { return x * x; }

double segment_distance2_2d(double au, double av, double bu, double bv, double qu, double qv)
{
    double eu = bu - au, ev = bv - av;
    double len2 = eu * eu + ev * ev;
    double t = len2 > 0.0 ? ((qu - au) * eu + (qv - av) * ev) / len2 : 0.0;
    t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
    return sq(qu - (au + t * eu)) + sq(qv - (av + t * ev));
}

static int outline_near(const Vec3 *pts, int n, int iu, int iv, double qu, double qv, double margin2)
{
    for (int i = 0; i < n; i++) {
        Vec3 a = pts[i], b = pts[i + 1 < n ? i + 1 : 0];
        if (segment_distance2_2d(v3_comp(a, iu), v3_comp(a, iv), v3_comp(b, iu), v3_comp(b, iv), qu, qv) <= margin2)
            return 1;
    }
    return 0;
}

int polygon_classify_point(const World *w, const Polygon *p, Vec3 x, double margin)
{
    int iu = p->axis_u, iv = p->axis_v;
    double qu = v3_comp(x, iu), qv = v3_comp(x, iv);
    double m2 = margin * margin;
    /* Far outside the bounding box: no border nearby. */
    if (qu < v3_comp(p->bbox_min, iu) - margin || qu > v3_comp(p->bbox_max, iu) + margin ||
        qv < v3_comp(p->bbox_min, iv) - margin || qv > v3_comp(p->bbox_max, iv) + margin)
        return 0;
    for (int k = 0; k < polygon_outline_count(p); k++) {
        int n;
        const Vec3 *pts = polygon_outline(w, p, k, &n);
        if (outline_near(pts, n, iu, iv, qu, qv, m2))
            return -1;
    }
    return polygon_contains(w, p, x);
}
