/* POV-Ray 3.7's lathe (lathe.cpp), written anew from reading it: each
 * segment's polynomial in the spline parameter built as Lathe::Intersect
 * builds it and solved by POV-Ray's own solver. */
#include "lathe.h"

#include <math.h>

#include "polynomial_solver.h"
#include "scene.h"

#define POV_EPSILON 1.0e-10            /* POV-Ray's EPSILON */
#define POV_MAX_DISTANCE 1.0e7         /* POV-Ray's MAX_DISTANCE */
#define LATHE_DEPTH_TOLERANCE 1.0e-4   /* lathe.cpp's DEPTH_TOLERANCE, on world distances */

static double cubic_at(const SplineSegment *e, int a, double w)
{
    return w * (w * (w * e->a[a] + e->b[a]) + e->c[a]) + e->d[a];
}

/* The extremes of coordinate a over segment e, as Compute_Lathe finds
 * them: its end points (a Bezier segment's control points), and for
 * quadratic and cubic splines the values where the derivative vanishes
 * within [0, 1]. */
static void segment_extent(const Shape *s, const SplineSegment *e, int a, double *lo, double *hi)
{
    double v[4];
    if (s->u.lathe.spline == SPLINE_BEZIER) {
        v[0] = e->d[a];
        v[1] = e->d[a] + e->c[a] / 3.0;
        v[2] = e->d[a] + 2.0 * e->c[a] / 3.0 + e->b[a] / 3.0;
        v[3] = e->a[a] + e->b[a] + e->c[a] + e->d[a];
    } else {
        v[0] = v[2] = e->d[a];
        v[1] = v[3] = cubic_at(e, a, 1.0);
    }
    if (s->u.lathe.spline == SPLINE_QUADRATIC || s->u.lathe.spline == SPLINE_CUBIC) {
        const double c[3] = { 3.0 * e->a[a], 2.0 * e->b[a], e->c[a] };
        double r[2];
        int n = poly_solve(2, c, r, 0, 0.0);
        while (n--)
            if (r[n] >= 0.0 && r[n] <= 1.0)
                v[n] = cubic_at(e, a, r[n]);
    }
    *lo = fmin(fmin(v[0], v[1]), fmin(v[2], v[3]));
    *hi = fmax(fmax(v[0], v[1]), fmax(v[2], v[3]));
}

void lathe_place(Shape *s)
{
    double xmin = HUGE_VAL, xmax = -HUGE_VAL, ymin = HUGE_VAL, ymax = -HUGE_VAL;
    for (int i = 0; i < s->u.lathe.nsegments; i++) {
        double lo, hi;
        segment_extent(s, &s->u.lathe.segments[i], 0, &lo, &hi);
        xmin = fmin(xmin, lo);
        xmax = fmax(xmax, hi);
        segment_extent(s, &s->u.lathe.segments[i], 1, &lo, &hi);
        ymin = fmin(ymin, lo);
        ymax = fmax(ymax, hi);
    }
    s->u.lathe.radius1 = xmin;
    s->u.lathe.radius2 = xmax;
    s->u.lathe.height1 = ymin;
    s->u.lathe.height2 = ymax;
}

/* The slack that keeps the culling in lathe_all conservative: a crossing
 * the solver finds lies some ulps off the exact heights and radii, so a
 * segment is passed over only when the ray misses its bounds by more than
 * this (relative to the numbers compared). */
#define CULL_SLACK 1.0e-6

/* Whether the ray P + k D (D of unit length), within k0 <= k <= k1, may
 * cross segment e: reaches its heights with a squared distance from the
 * axis, a k^2 + 2 m k + c, within the range of its squared radius. */
static int may_cross(const Shape *s, const SplineSegment *e, Vec3 P, Vec3 D, double a, double m, double c, double k0,
                     double k1)
{
    double ylo, yhi, xlo, xhi;
    segment_extent(s, e, 1, &ylo, &yhi);
    const double hslack = CULL_SLACK * (fabs(P.y) + fabs(ylo) + fabs(yhi) + 1.0);
    double ka = k0, kb = k1;
    if (D.y != 0.0) {
        const double ya = (ylo - hslack - P.y) / D.y, yb = (yhi + hslack - P.y) / D.y;
        ka = fmax(ka, fmin(ya, yb));
        kb = fmin(kb, fmax(ya, yb));
    } else if (P.y < ylo - hslack || P.y > yhi + hslack) {
        return 0;
    }
    if (ka > kb)
        return 0;
    if (!(a > 0.0))
        return 1; /* along the axis: the heights alone decide */
    segment_extent(s, e, 0, &xlo, &xhi);
    /* the squared radius's range: the polynomial squares the radius */
    const double x2lo = xlo <= 0.0 && xhi >= 0.0 ? 0.0 : fmin(xlo * xlo, xhi * xhi);
    const double x2hi = fmax(xlo * xlo, xhi * xhi);
    const double qa = (a * ka + 2.0 * m) * ka + c, qb = (a * kb + 2.0 * m) * kb + c;
    const double kmid = fmin(fmax(-m / a, ka), kb);
    const double qmin = (a * kmid + 2.0 * m) * kmid + c, qmax = fmax(qa, qb);
    const double qslack = CULL_SLACK * (fabs(qmax) + x2hi + 1.0);
    return !(qmin > x2hi + qslack || qmax < x2lo - qslack);
}

/* The spline parameter of the crossing at q (the lathe's own space) on
 * segment e: the root in [0, 1] of y(w) = q.y whose radius is nearest
 * q's (ShapeHit keeps no parameter; POV-Ray's Intersection does). */
static double parameter_at(const SplineSegment *e, Vec3 q)
{
    double r = sqrt(q.x * q.x + q.z * q.z);
    const double c[4] = { e->a[1], e->b[1], e->c[1], e->d[1] - q.y };
    double w[3], best = 0.0, err = HUGE_VAL;
    int n = poly_solve(3, c, w, 0, 0.0);
    for (int i = 0; i < n; i++) {
        double x = w[i] < 0.0 ? 0.0 : w[i] > 1.0 ? 1.0 : w[i];
        double d = fabs(cubic_at(e, 0, x) - r) + fabs(cubic_at(e, 1, x) - q.y);
        if (d < err) {
            err = d;
            best = x;
        }
    }
    if (err == HUGE_VAL) { /* a level segment: the radius decides */
        const double cx[4] = { e->a[0], e->b[0], e->c[0], e->d[0] - r };
        n = poly_solve(3, cx, w, 0, 0.0);
        for (int i = 0; i < n; i++)
            if (w[i] >= 0.0 && w[i] <= 1.0)
                return w[i];
    }
    return best;
}

/* The normal in the lathe's own space at q, parameter w on segment e. */
static Vec3 local_normal(const SplineSegment *e, Vec3 q, double w)
{
    double r = q.x * q.x + q.z * q.z;
    if (!(r > POV_EPSILON))
        return v3(0.0, 1.0, 0.0);
    r = sqrt(r);
    double dx = w * (3.0 * e->a[0] * w + 2.0 * e->b[0]) + e->c[0];
    double dy = w * (3.0 * e->a[1] * w + 2.0 * e->b[1]) + e->c[1];
    return v3(dy * q.x, -dx * r, dy * q.z);
}

/* test_hit: a crossing at world depth d kept where POV-Ray keeps it. */
static void keep(const Shape *s, ShapeHit *hits, int *n, double d, double tmax, int segment, Vec3 p, Vec3 dl,
                 double len, double w)
{
    if (!(d > LATHE_DEPTH_TOLERANCE && d < POV_MAX_DISTANCE && d < tmax))
        return;
    int at = shape_hit_slot(s, hits, n, d);
    if (at < 0)
        return;
    Vec3 q = v3_add(p, v3_scale(dl, d * len));
    Vec3 nrm = local_normal(&s->u.lathe.segments[segment], q, w);
    hits[at].t = d;
    hits[at].part = segment;
    hits[at].entering = (v3_dot(nrm, dl) < 0.0) != (s->inverse != 0);
}

int lathe_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits)
{
    Vec3 P = inverse_transform_point(&s->to_world, org);
    Vec3 D = inverse_transform_direction(&s->to_world, dir);
    double len = v3_length(D);
    if (!(len > 0.0))
        return 0;
    D = v3_scale(D, 1.0 / len);
    const double Dylen = D.y * len;
    const double R2 = s->u.lathe.radius2, H1 = s->u.lathe.height1, H2 = s->u.lathe.height2;
    /* the overall bounding cylinder */
    if ((D.y >= 0.0 && P.y > H2) || (D.y <= 0.0 && P.y < H1) || (D.x >= 0.0 && P.x > R2) || (D.x <= 0.0 && P.x < -R2))
        return 0;
    double r0 = fabs(P.x * D.z - P.z * D.x);
    double r = D.x * D.x + D.z * D.z;
    if (r > 0.0)
        r0 /= sqrt(r);
    if (r0 > R2)
        return 0;
    const double m = D.x * P.x + D.z * P.z, Dy2 = D.y * D.y;
    const int sturm = s->u.lathe.sturm;
    int n = 0;
    /* Only the segments the ray can cross are solved for, as POV-Ray's
     * bounding cylinders per segment spare it the others (a lathe of
     * thousands of points made every ray solve thousands of sextics, a
     * render of minutes that POV-Ray makes in a second): first the span
     * of the ray within the cylinder of the largest radius, then each
     * segment's heights and radii there (may_cross). */
    const double c = P.x * P.x + P.z * P.z;
    const double Rabs = fmax(fabs(s->u.lathe.radius1), fabs(R2)), Rs = Rabs * Rabs * (1.0 + CULL_SLACK);
    double k0 = -HUGE_VAL, k1 = HUGE_VAL;
    if (r > 0.0) {
        const double disc = m * m - r * (c - Rs);
        if (disc < 0.0)
            return 0;
        k0 = (-m - sqrt(disc)) / r;
        k1 = (-m + sqrt(disc)) / r;
    } else if (c > Rs) {
        return 0;
    }
    for (int j = 0; j < s->u.lathe.nsegments; j++) {
        const SplineSegment *e = &s->u.lathe.segments[j];
        if (!may_cross(s, e, P, D, r, m, c, k0, k1))
            continue;
        const double Ax = e->a[0], Bx = e->b[0], Cx = e->c[0], Dx = e->d[0];
        const double Ay = e->a[1], By = e->b[1], Cy = e->c[1], Dy = e->d[1];
        double x1[7], y1[6];
        int n1 = 0;
        switch (s->u.lathe.spline) {
        case SPLINE_LINEAR:
            x1[0] = Cy * Cy * r - Cx * Cx * Dy2;
            x1[1] = 2.0 * (Cy * ((Dy - P.y) * r + D.y * m) - Cx * Dx * Dy2);
            x1[2] = (Dy - P.y) * ((Dy - P.y) * r + 2.0 * D.y * m) + Dy2 * (P.x * P.x + P.z * P.z - Dx * Dx);
            n1 = poly_solve(2, x1, y1, 0, 0.0);
            break;
        case SPLINE_QUADRATIC:
            x1[0] = By * By * r - Bx * Bx * Dy2;
            x1[1] = 2.0 * (By * Cy * r - Bx * Cx * Dy2);
            x1[2] = r * (2.0 * By * (Dy - P.y) + Cy * Cy) + 2.0 * By * D.y * m - (2.0 * Bx * Dx + Cx * Cx) * Dy2;
            x1[3] = 2.0 * (Cy * ((Dy - P.y) * r + D.y * m) - Cx * Dx * Dy2);
            x1[4] = (Dy - P.y) * ((Dy - P.y) * r + 2.0 * D.y * m) + Dy2 * (P.x * P.x + P.z * P.z - Dx * Dx);
            n1 = poly_solve(4, x1, y1, sturm, 0.0);
            break;
        case SPLINE_CUBIC:
        case SPLINE_BEZIER:
            x1[0] = Ay * Ay * r - Ax * Ax * Dy2;
            x1[1] = 2.0 * (Ay * By * r - Ax * Bx * Dy2);
            x1[2] = (2.0 * Ay * Cy + By * By) * r - (2.0 * Ax * Cx + Bx * Bx) * Dy2;
            x1[3] = 2.0 * ((Ay * Dy + By * Cy - Ay * P.y) * r + Ay * D.y * m - (Ax * Dx + Bx * Cx) * Dy2);
            x1[4] = (2.0 * By * (Dy - P.y) + Cy * Cy) * r + 2.0 * By * D.y * m - (2.0 * Bx * Dx + Cx * Cx) * Dy2;
            x1[5] = 2.0 * (Cy * ((Dy - P.y) * r + D.y * m) - Cx * Dx * Dy2);
            x1[6] = (Dy - P.y) * ((Dy - P.y) * r + 2.0 * D.y * m) + Dy2 * (P.x * P.x + P.z * P.z - Dx * Dx);
            n1 = poly_solve(6, x1, y1, sturm, 0.0);
            break;
        }
        while (n1--) { /* POV-Ray's order: the last root first */
            double w = y1[n1];
            if (!(w >= 0.0 && w <= 1.0))
                continue;
            if (fabs(D.y) > POV_EPSILON) {
                double k = w * (w * (w * Ay + By) + Cy) + Dy - P.y;
                keep(s, hits, &n, k / Dylen, tmax, j, P, D, len, w);
            } else {
                /* a level ray: where it is at the segment's radius */
                double k = w * (w * (w * Ax + Bx) + Cx) + Dx;
                const double x2[3] = { r, 2.0 * m, P.x * P.x + P.z * P.z - k * k };
                double y2[2];
                int n2 = poly_solve(2, x2, y2, 0, 0.0);
                while (n2--)
                    keep(s, hits, &n, y2[n2] / len, tmax, j, P, D, len, w);
            }
        }
    }
    shape_hits_sort(hits, n);
    return n;
}

int lathe_inside(const Shape *s, Vec3 p)
{
    Vec3 q = inverse_transform_point(&s->to_world, p);
    int crossings = 0;
    if (q.y >= s->u.lathe.height1 && q.y <= s->u.lathe.height2) {
        double r = sqrt(q.x * q.x + q.z * q.z);
        if (r >= s->u.lathe.radius1 && r <= s->u.lathe.radius2) {
            for (int i = 0; i < s->u.lathe.nsegments; i++) {
                const SplineSegment *e = &s->u.lathe.segments[i];
                double lo, hi;
                segment_extent(s, e, 1, &lo, &hi); /* the segment's bounding cylinder's heights */
                if (!(q.y >= lo - POV_EPSILON && q.y <= hi + POV_EPSILON))
                    continue;
                const double c[4] = { e->a[1], e->b[1], e->c[1], e->d[1] - q.y };
                double w[3];
                int n = poly_solve(3, c, w, s->u.lathe.sturm, 0.0);
                while (n--)
                    if (w[n] >= 0.0 && w[n] <= 1.0 && cubic_at(e, 0, w[n]) - r >= 0.0)
                        crossings++;
            }
        }
    }
    return (crossings & 1) != (s->inverse != 0);
}

Vec3 lathe_normal(const Shape *s, Vec3 p, int part)
{
    const SplineSegment *e = &s->u.lathe.segments[part];
    Vec3 q = inverse_transform_point(&s->to_world, p);
    return v3_normalize(transform_normal(&s->to_world, local_normal(e, q, parameter_at(e, q))));
}

Vec3 lathe_uv(const Shape *s, Vec3 p)
{
    Vec3 q = inverse_transform_point(&s->to_world, p);
    /* the segment the point is on: the one its parameter puts nearest */
    int part = 0;
    double w = 0.0, err = HUGE_VAL, rq = sqrt(q.x * q.x + q.z * q.z);
    for (int i = 0; i < s->u.lathe.nsegments; i++) {
        const SplineSegment *e = &s->u.lathe.segments[i];
        double wi = parameter_at(e, q);
        double d = fabs(cubic_at(e, 0, wi) - rq) + fabs(cubic_at(e, 1, wi) - q.y);
        if (d < err) {
            err = d;
            part = i;
            w = wi;
        }
    }
    double len = q.x * q.x + q.z * q.z, theta = 0.0;
    if (len > POV_EPSILON) {
        len = sqrt(len);
        if (q.z == 0.0)
            theta = q.x > 0 ? 0.0 : M_PI;
        else {
            theta = acos(q.x / len);
            if (q.z < 0.0)
                theta = 2.0 * M_PI - theta;
        }
        theta /= 2.0 * M_PI;
    }
    double v = (w + (double)part) / s->u.lathe.nsegments;
    return v3(theta, v > 1.0 ? 1.0 : v, 0.0);
}
