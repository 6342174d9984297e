/* POV-Ray 3.7's prism (prism.cpp), written anew from reading it: its
 * bounding rectangles, the segment equations and the cap tests of
 * Prism::All_Intersections, in_curve, Inside and Normal, with POV-Ray's
 * tolerances, solved by POV-Ray's own solver. */
#include "prism.h"

#include <math.h>

#include "polynomial_solver.h"
#include "scene.h"

#define POV_EPSILON 1.0e-10          /* POV-Ray's EPSILON */
#define POV_MAX_DISTANCE 1.0e7       /* POV-Ray's MAX_DISTANCE */
#define POV_BOUND_HUGE 2.0e10        /* POV-Ray's BOUND_HUGE */
#define PRISM_DEPTH_TOLERANCE 1.0e-4 /* prism.cpp's DEPTH_TOLERANCE */

/* Coordinate a (0: x, 1: z) of segment e at parameter w. */
static double segment_at(const PrismSegment *e, int a, double w)
{
    return w * (w * (w * e->a[a] + e->b[a]) + e->c[a]) + e->d[a];
}

/* in_curve: is (u, v) inside the outlines? The crossings of the ray from
 * it toward +u, counted. */
static int in_curve(const Shape *s, double u, double v)
{
    if (!(u >= s->u.prism.u1 && u <= s->u.prism.u2 && v >= s->u.prism.v1 && v <= s->u.prism.v2))
        return 0;
    int crossings = 0;
    for (int i = 0; i < s->u.prism.nsegments; i++) {
        const PrismSegment *e = &s->u.prism.segments[i];
        if (!(v >= e->v1 && v <= e->v2 && u <= e->u2))
            continue;
        const double c[4] = { e->a[1], e->b[1], e->c[1], e->d[1] - v };
        double w[3];
        int n = poly_solve(3, c, w, s->u.prism.sturm, 0.0);
        while (n--)
            if (w[n] >= 0.0 && w[n] <= 1.0 && segment_at(e, 0, w[n]) - u >= 0.0)
                crossings++;
    }
    return crossings & 1;
}

/* test_rectangle: might the ray P + t D (x and z) meet the rectangle
 * x1..x2, z1..z2 ahead of P? POV-Ray's own test, which its cubic and
 * Bezier segments of a linear sweep pass before their cubic is solved. */
static int test_rectangle(Vec3 P, Vec3 D, double x1, double z1, double x2, double z2)
{
    double dmin, dmax;
    if (fabs(D.x) > POV_EPSILON) {
        if (D.x > 0.0) {
            dmin = (x1 - P.x) / D.x;
            dmax = (x2 - P.x) / D.x;
        } else {
            dmax = (x1 - P.x) / D.x;
            dmin = (x2 - P.x) / D.x;
        }
        if (dmax < POV_EPSILON || dmin > dmax)
            return 0;
    } else {
        if (P.x < x1 || P.x > x2)
            return 0;
        dmin = -POV_BOUND_HUGE;
        dmax = POV_BOUND_HUGE;
    }
    if (fabs(D.z) > POV_EPSILON) {
        double tmin, tmax;
        if (D.z > 0.0) {
            tmin = (z1 - P.z) / D.z;
            tmax = (z2 - P.z) / D.z;
        } else {
            tmax = (z1 - P.z) / D.z;
            tmin = (z2 - P.z) / D.z;
        }
        if (tmax < dmax) {
            if (tmax < POV_EPSILON)
                return 0;
            if (tmin > dmin ? tmin > tmax : dmin > tmax)
                return 0;
        } else if (tmin > dmin && tmin > dmax) {
            return 0;
        }
    } else if (P.z < z1 || P.z > z2) {
        return 0;
    }
    return 1;
}

/* The normal in the prism's own space at q on segment e, parameter w
 * (Prism::Normal's SPLINE_HIT). */
static Vec3 local_normal(const Shape *s, const PrismSegment *e, Vec3 q, double w)
{
    const double nx = w * (3.0 * e->a[1] * w + 2.0 * e->b[1]) + e->c[1];
    const double nz = -(w * (3.0 * e->a[0] * w + 2.0 * e->b[0]) + e->c[0]);
    if (!s->u.prism.conic)
        return v3(nx, 0.0, nz);
    if (!(fabs(q.y) > POV_EPSILON))
        return v3(0.0, 1.0, 0.0);
    return v3(nx, -(q.x * nx + q.z * nz) / q.y, nz);
}

/* A crossing at world distance d kept where POV-Ray keeps it; entering
 * by the normal's side (which is outward for outlines running
 * counter-clockwise seen from +y; hstrace's CSG asks Inside alone). */
static void keep(const Shape *s, ShapeHit *hits, int *n, double d, double tmax, int part, Vec3 nrm, Vec3 D)
{
    if (!(d > PRISM_DEPTH_TOLERANCE && d < POV_MAX_DISTANCE && d < tmax))
        return;
    int at = shape_hit_slot(s, hits, n, d);
    if (at < 0)
        return;
    hits[at].t = d;
    hits[at].part = part;
    hits[at].entering = (v3_dot(nrm, D) < 0.0) != (s->inverse != 0);
}

/* The caps of a closed prism: the planes at both heights, where the point
 * (scaled back by the height for a conic sweep) is inside the outlines. */
static void caps(const Shape *s, Vec3 P, Vec3 D, double len, double tmax, ShapeHit *hits, int *n)
{
    const double heights[2] = { s->u.prism.height2, s->u.prism.height1 }; /* POV-Ray's order: cap, base */
    for (int i = 0; i < 2; i++) {
        const double h = heights[i];
        if (s->u.prism.conic && !(fabs(h) > POV_EPSILON))
            continue;
        const double k = (h - P.y) / D.y;
        if (!(k > PRISM_DEPTH_TOLERANCE && k < POV_MAX_DISTANCE))
            continue;
        double u = P.x + k * D.x, v = P.z + k * D.z;
        if (s->u.prism.conic) {
            u /= h;
            v /= h;
        }
        if (in_curve(s, u, v))
            keep(s, hits, n, k / len, tmax, PRISM_CAPS_PART, v3(0.0, i == 0 ? 1.0 : -1.0, 0.0), D);
    }
}

/* The roots of segment e's equation along the ray (linear sweep: the ray's
 * line in x-z meets the outline; conic: the plane through the apex and the
 * ray meets it), into y; how many. */
static int segment_roots(const Shape *s, const PrismSegment *e, Vec3 P, Vec3 D, double y[3])
{
    /* linear sweep: D.z (fx(t) - Px) - D.x (fz(t) - Pz) = 0, grouped as
     * POV-Ray groups it; conic: k1 fx(t) + k2 fz(t) + k3 = 0 */
    const int conic = s->u.prism.conic;
    const double k1 = conic ? P.z * D.y - P.y * D.z : D.z;
    const double k2 = conic ? P.y * D.x - P.x * D.y : -D.x;
    const double constant = conic ? e->d[0] * k1 + e->d[1] * k2 + (P.x * D.z - P.z * D.x)
                                  : D.z * (e->d[0] - P.x) - D.x * (e->d[1] - P.z);
    double x[4];
    switch (s->u.prism.spline) {
    case SPLINE_LINEAR:
        x[0] = e->c[0] * k1 + e->c[1] * k2;
        if (!(fabs(x[0]) > POV_EPSILON))
            return 0;
        y[0] = -constant / x[0];
        return 1;
    case SPLINE_QUADRATIC:
        x[0] = e->b[0] * k1 + e->b[1] * k2;
        x[1] = e->c[0] * k1 + e->c[1] * k2;
        x[2] = constant;
        return poly_solve(2, x, y, 0, 0.0);
    default: /* cubic, Bezier */
        if (!s->u.prism.conic && !test_rectangle(P, D, e->x1, e->y1, e->x2, e->y2))
            return 0;
        x[0] = e->a[0] * k1 + e->a[1] * k2;
        x[1] = e->b[0] * k1 + e->b[1] * k2;
        x[2] = e->c[0] * k1 + e->c[1] * k2;
        x[3] = constant;
        return poly_solve(3, x, y, s->u.prism.sturm, 0.0);
    }
}

/* The distance along the ray (own space, unit D) to root w of segment e;
 * 0: none (POV-Ray's "should never happen" of a conic sweep). */
static int root_distance(const Shape *s, const PrismSegment *e, Vec3 P, Vec3 D, double w, double *k)
{
    if (!s->u.prism.conic) {
        if (fabs(D.x) > POV_EPSILON)
            *k = (segment_at(e, 0, w) - P.x) / D.x;
        else
            *k = (segment_at(e, 1, w) - P.z) / D.z;
        return 1;
    }
    double f = segment_at(e, 0, w), h = D.x - f * D.y;
    if (fabs(h) > POV_EPSILON) {
        *k = (f * P.y - P.x) / h;
        return 1;
    }
    f = segment_at(e, 1, w);
    h = D.z - f * D.y;
    if (!(fabs(h) > POV_EPSILON))
        return 0;
    *k = (f * P.y - P.z) / h;
    return 1;
}

int prism_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits)
{
    if (s->u.prism.degenerate)
        return 0;
    Vec3 P = inverse_transform_point(&s->to_world, org);
    Vec3 D = inverse_transform_direction(&s->to_world, dir);
    double len = v3_length(D);
    if (!(len > 0.0))
        return 0;
    D = v3_scale(D, 1.0 / len);
    /* the overall bounding rectangle */
    if ((D.x >= 0.0 && P.x > s->u.prism.x2) || (D.x <= 0.0 && P.x < s->u.prism.x1) ||
        (D.z >= 0.0 && P.z > s->u.prism.y2) || (D.z <= 0.0 && P.z < s->u.prism.y1))
        return 0;
    const double H1 = s->u.prism.height1, H2 = s->u.prism.height2;
    int n = 0;
    if (fabs(D.y) < POV_EPSILON) {
        if (P.y < H1 || P.y > H2)
            return 0;
    } else if (!s->u.prism.open) {
        caps(s, P, D, len, tmax, hits, &n);
    }
    if (fabs(D.x) > POV_EPSILON || fabs(D.z) > POV_EPSILON) {
        for (int j = 0; j < s->u.prism.nsegments; j++) {
            const PrismSegment *e = &s->u.prism.segments[j];
            /* the segment's bounding rectangle (modified Cohen-Sutherland) */
            if ((D.x >= 0.0 && P.x > e->x2) || (D.x <= 0.0 && P.x < e->x1) || (D.z >= 0.0 && P.z > e->y2) ||
                (D.z <= 0.0 && P.z < e->y1))
                continue;
            double y[3], k;
            int m = segment_roots(s, e, P, D, y);
            while (m--) { /* POV-Ray's order: the last root first */
                const double w = y[m];
                if (!(w >= 0.0 && w <= 1.0) || !root_distance(s, e, P, D, w, &k))
                    continue;
                const double h = P.y + k * D.y;
                if (!(h >= H1 && h <= H2))
                    continue;
                Vec3 q = v3_add(P, v3_scale(D, k));
                keep(s, hits, &n, k / len, tmax, PRISM_SEGMENT_PART + j, local_normal(s, e, q, w), D);
            }
        }
    }
    shape_hits_sort(hits, n);
    return n;
}

int prism_inside(const Shape *s, Vec3 p)
{
    Vec3 q = inverse_transform_point(&s->to_world, p);
    int inside = 0;
    if (q.y >= s->u.prism.height1 && q.y < s->u.prism.height2) {
        if (s->u.prism.conic) {
            if (fabs(q.y) > POV_EPSILON) {
                q.x /= q.y;
                q.z /= q.y;
            } else {
                q.x = q.z = HUGE_VAL;
            }
        }
        inside = in_curve(s, q.x, q.z);
    }
    return inside != (s->inverse != 0);
}

/* The parameter of the point q (own space, scaled back for a conic sweep)
 * on segment e: the root in [0, 1] of z(w) = q.z whose x lies nearest
 * q's (ShapeHit keeps no parameter; POV-Ray's Intersection does). */
static double parameter_at(const PrismSegment *e, double qx, double qz)
{
    for (int a = 1; a >= 0; a--) { /* z decides; x where z is level */
        const double target = a == 1 ? qz : qx;
        const double c[4] = { e->a[a], e->b[a], e->c[a], e->d[a] - target };
        double w[3], best = 0.0, err = HUGE_VAL;
        int n = poly_solve(3, c, w, 0, 0.0);
        for (int i = 0; i < n; i++) {
            double x = w[i] < 0.0 ? 0.0 : w[i] > 1.0 ? 1.0 : w[i];
            double d = fabs(segment_at(e, 0, x) - qx) + fabs(segment_at(e, 1, x) - qz);
            if (d < err) {
                err = d;
                best = x;
            }
        }
        if (err < HUGE_VAL)
            return best;
    }
    return 0.0;
}

Vec3 prism_normal(const Shape *s, Vec3 p, int part)
{
    Vec3 n = v3(0.0, 1.0, 0.0);
    if (part >= PRISM_SEGMENT_PART) {
        const PrismSegment *e = &s->u.prism.segments[part - PRISM_SEGMENT_PART];
        Vec3 q = inverse_transform_point(&s->to_world, p);
        double qx = q.x, qz = q.z;
        if (s->u.prism.conic && fabs(q.y) > POV_EPSILON) {
            qx /= q.y;
            qz /= q.y;
        }
        n = local_normal(s, e, q, parameter_at(e, qx, qz));
    }
    return v3_normalize(transform_normal(&s->to_world, n));
}
