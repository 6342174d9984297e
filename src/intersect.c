/* Intersections: the plane first, then an inside test in the 2-D projection
 * that drops the normal's dominant axis. */
#include "intersect.h"

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

double intersect_polygon(const World *w, const Polygon *p, Vec3 org, Vec3 dir)
{
    double denom = v3_dot(p->normal, dir);
    if (denom == 0.0)
        return -1.0;
    double t = (p->d - v3_dot(p->normal, org)) / denom;
    if (!(t > 0.0))
        return -1.0;
    Vec3 q = v3_madd(org, dir, t);
    return polygon_contains(w, p, q) ? t : -1.0;
}

double intersect_plane(const InfinitePlane *pl, Vec3 org, Vec3 dir)
{
    double denom = v3_dot(pl->normal, dir);
    if (denom == 0.0)
        return -1.0;
    double t = (pl->d - v3_dot(pl->normal, org)) / denom;
    return t > 0.0 ? t : -1.0;
}

Vec3 polygon_shading_normal(const World *w, const Polygon *p, Vec3 q)
{
    if (p->smooth_normals < 0)
        return p->normal;
    /* Barycentric weights from sub-triangle areas in the projection; this is
     * the same interpolation POV-Ray's smooth triangles use, written plainly. */
    const Vec3 *v = &w->points[p->first_point];
    const Vec3 *n = &w->vertex_normals[p->smooth_normals];
    int iu = p->axis_u, iv = p->axis_v;
    double qu = comp(q, iu), qv = comp(q, iv);
    double area = edge_side(comp(v[0], iu), comp(v[0], iv), comp(v[1], iu), comp(v[1], iv), comp(v[2], iu), comp(v[2], iv));
    if (area == 0.0)
        return p->normal;
    double b0 = edge_side(comp(v[1], iu), comp(v[1], iv), comp(v[2], iu), comp(v[2], iv), qu, qv) / area;
    double b1 = edge_side(comp(v[2], iu), comp(v[2], iv), comp(v[0], iu), comp(v[0], iv), qu, qv) / area;
    double b2 = 1.0 - b0 - b1;
    Vec3 r = v3_add(v3_add(v3_scale(n[0], b0), v3_scale(n[1], b1)), v3_scale(n[2], b2));
    double len = v3_length(r);
    return len > 0.0 ? v3_scale(r, 1.0 / len) : p->normal;
}
