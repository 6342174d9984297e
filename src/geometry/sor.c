/* POV-Ray 3.7's surface of revolution (sor.cpp), written anew from
 * reading it. */
#include "sor.h"

#include <math.h>

#include "polynomial_solver.h"
#include "scene.h"

#define POV_EPSILON 1.0e-10          /* POV-Ray's EPSILON */
#define POV_MAX_DISTANCE 1.0e7       /* POV-Ray's MAX_DISTANCE */
#define SOR_DEPTH_TOLERANCE 1.0e-4   /* sor.cpp's DEPTH_TOLERANCE, on world distances */

static double radius2_at(const SorSegment *e, double y) { return y * (y * (y * e->a + e->b) + e->c) + e->d; }

void sor_place(Shape *s)
{
    const SorSegment *seg = s->u.sor.segments;
    const int n = s->u.sor.nsegments;
    double xmax = -HUGE_VAL, xmin = HUGE_VAL;
    for (int i = 0; i < n; i++) {
        const SorSegment *e = &seg[i];
        double x[4] = { e->x1, e->x2, e->x1, e->x2 };
        const double c[3] = { 3.0 * e->a, 2.0 * e->b, e->c };
        double r[2];
        int k = poly_solve(2, c, r, 0, 0.0);
        while (k--)
            if (r[k] >= e->y1 && r[k] <= e->y2)
                x[k] = sqrt(radius2_at(e, r[k]));
        xmin = fmin(xmin, fmin(fmin(x[0], x[1]), fmin(x[2], x[3])));
        xmax = fmax(xmax, fmax(fmax(x[0], x[1]), fmax(x[2], x[3])));
    }
    s->u.sor.radius1 = xmin;
    s->u.sor.radius2 = xmax;
    s->u.sor.height1 = seg[0].y1;
    s->u.sor.height2 = seg[n - 1].y2;
    double cap = radius2_at(&seg[n - 1], seg[n - 1].y2), base = radius2_at(&seg[0], seg[0].y1);
    s->u.sor.cap2 = cap < 0.0 ? 0.0 : cap;
    s->u.sor.base2 = base < 0.0 ? 0.0 : base;
}

/* The slack that keeps the culling below conservative: a crossing the
 * solver finds lies some ulps off the exact heights and radii, so a
 * segment is passed over only when the ray misses it by more than this
 * (relative to the numbers compared). */
#define CULL_SLACK 1.0e-6

/* The squared radius's range over segment e: its ends and the cubic's
 * turning points between them. */
static void radius2_range(const SorSegment *e, double *lo, double *hi)
{
    double v[4] = { radius2_at(e, e->y1), radius2_at(e, e->y2), e->x1 * e->x1, e->x2 * e->x2 };
    int nv = 4;
    const double A = 3.0 * e->a, B = 2.0 * e->b, C = e->c; /* the derivative */
    double r[2];
    int k = 0;
    if (A != 0.0) {
        const double disc = B * B - 4.0 * A * C;
        if (disc >= 0.0) {
            r[k++] = (-B - sqrt(disc)) / (2.0 * A);
            r[k++] = (-B + sqrt(disc)) / (2.0 * A);
        }
    } else if (B != 0.0) {
        r[k++] = -C / B;
    }
    double extra[2];
    int ne = 0;
    while (k--)
        if (r[k] > e->y1 && r[k] < e->y2)
            extra[ne++] = radius2_at(e, r[k]);
    *lo = *hi = v[0];
    for (int i = 1; i < nv + ne; i++) {
        const double x = i < nv ? v[i] : extra[i - nv];
        *lo = fmin(*lo, x);
        *hi = fmax(*hi, x);
    }
}

/* The first segment whose top is at or above height h (the segments'
 * heights rise, the parser sees to it). */
static int first_segment_from(const Shape *s, double h)
{
    int lo = 0, hi = s->u.sor.nsegments;
    while (lo < hi) {
        const int mid = lo + (hi - lo) / 2;
        if (s->u.sor.segments[mid].y2 < h)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* test_hit, and whether the ray enters there (the local normal against
 * the direction). */
static void keep(const Shape *s, ShapeHit *hits, int *n, double d, double tmax, int part, Vec3 local_normal, Vec3 D)
{
    if (!(d > SOR_DEPTH_TOLERANCE && d < POV_MAX_DISTANCE && d < tmax))
        return;
    int at = shape_hit_slot(s, hits, n, d);
    if (at < 0)
        return;
    hits[at].t = d;
    hits[at].part = part;
    hits[at].entering = (v3_dot(local_normal, D) < 0.0) != (s->inverse != 0);
}

static Vec3 curve_normal(const SorSegment *e, Vec3 q)
{
    double k = 0.5 * (q.y * (3.0 * e->a * q.y + 2.0 * e->b) + e->c);
    return v3(q.x, -k, q.z);
}

int sor_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits)
{
    Vec3 P = inverse_transform_point(&s->to_world, org);
    Vec3 D = inverse_transform_direction(&s->to_world, dir);
    double len = v3_length(D);
    if (!(len > 0.0))
        return 0;
    D = v3_scale(D, 1.0 / len);
    const double R2 = s->u.sor.radius2, H1 = s->u.sor.height1, H2 = s->u.sor.height2;
    if ((D.y >= 0.0 && P.y > H2) || (D.y <= 0.0 && P.y < H1) || (D.x >= 0.0 && P.x > R2) || (D.x <= 0.0 && P.x < -R2))
        return 0;
    /* the ray's signed distance from the axis (POV-Ray does not take its
     * absolute value here, as its lathe does) */
    double r0 = P.x * D.z - P.z * D.x, a = D.x * D.x + D.z * D.z;
    if (a > 0.0)
        r0 /= sqrt(a);
    if (r0 > R2)
        return 0;
    int n = 0;
    if (!s->u.sor.open && fabs(D.y) > POV_EPSILON) {
        const double heights[2] = { H1, H2 }, radii2[2] = { s->u.sor.base2, s->u.sor.cap2 };
        for (int c = 0; c < 2; c++) {
            if (!(radii2[c] > SOR_DEPTH_TOLERANCE))
                continue;
            double k = (heights[c] - P.y) / D.y;
            double u = P.x + k * D.x, v = P.z + k * D.z;
            if (u * u + v * v <= radii2[c])
                keep(s, hits, &n, k / len, tmax, c == 0 ? SOR_BASE : SOR_CAP, v3(0.0, c == 0 ? -1.0 : 1.0, 0.0), D);
        }
    }
    /* Only the segments the ray can cross are solved for, as POV-Ray's
     * bounding cylinders per segment spare it the others (a sor of
     * thousands of points made every ray solve thousands of cubics, a
     * render of minutes that POV-Ray makes in a second). Along the ray the
     * squared distance from the axis is q(k) = a k^2 + 2 b k + c: first
     * the span of k within the overall cylinder, its heights found among
     * the segments by bisection; then each segment whose heights and
     * squared radii that span can reach. */
    const double b = P.x * D.x + P.z * D.z, c = P.x * P.x + P.z * P.z, R2s = R2 * R2 * (1.0 + CULL_SLACK);
    double k0 = -HUGE_VAL, k1 = HUGE_VAL;
    if (a > 0.0) {
        const double disc = b * b - a * (c - R2s);
        if (disc < 0.0) {
            shape_hits_sort(hits, n);
            return n;
        }
        k0 = (-b - sqrt(disc)) / a;
        k1 = (-b + sqrt(disc)) / a;
    } else if (c > R2s) {
        shape_hits_sort(hits, n);
        return n;
    }
    double hlo = -HUGE_VAL, hhi = HUGE_VAL;
    if (D.y == 0.0) {
        hlo = hhi = P.y;
    } else if (a > 0.0) {
        hlo = fmin(P.y + k0 * D.y, P.y + k1 * D.y);
        hhi = fmax(P.y + k0 * D.y, P.y + k1 * D.y);
    }
    const double hslack = CULL_SLACK * (fabs(P.y) + fabs(H1) + fabs(H2) + 1.0);
    for (int j = first_segment_from(s, hlo - hslack); j < s->u.sor.nsegments; j++) {
        const SorSegment *e = &s->u.sor.segments[j];
        if (e->y1 > hhi + hslack)
            break;
        if (a > 0.0) {
            /* the span of k where the ray is within the segment's heights */
            double ka = k0, kb = k1;
            if (D.y != 0.0) {
                const double ya = (e->y1 - hslack - P.y) / D.y, yb = (e->y2 + hslack - P.y) / D.y;
                ka = fmax(ka, fmin(ya, yb));
                kb = fmin(kb, fmax(ya, yb));
            }
            if (ka > kb)
                continue;
            const double qa = (a * ka + 2.0 * b) * ka + c, qb = (a * kb + 2.0 * b) * kb + c;
            const double kmid = fmin(fmax(-b / a, ka), kb);
            const double qmin = (a * kmid + 2.0 * b) * kmid + c, qmax = fmax(qa, qb);
            double rlo, rhi;
            radius2_range(e, &rlo, &rhi);
            const double qslack = CULL_SLACK * (fabs(qmax) + fabs(rhi) + fabs(rlo) + 1.0);
            if (qmin > rhi + qslack || qmax < rlo - qslack)
                continue;
        }
        double x[4], y[3];
        x[0] = e->a * D.y * D.y * D.y;
        x[1] = D.y * D.y * (3.0 * e->a * P.y + e->b) - a;
        x[2] = D.y * (P.y * (3.0 * e->a * P.y + 2.0 * e->b) + e->c) - 2.0 * (P.x * D.x + P.z * D.z);
        x[3] = P.y * (P.y * (e->a * P.y + e->b) + e->c) + e->d - P.x * P.x - P.z * P.z;
        int m = poly_solve(3, x, y, s->u.sor.sturm, 0.0);
        while (m--) {
            double k = y[m], h = P.y + k * D.y;
            if (h >= e->y1 && h <= e->y2)
                keep(s, hits, &n, k / len, tmax, SOR_CURVE + j, curve_normal(e, v3_add(P, v3_scale(D, k))), D);
        }
    }
    shape_hits_sort(hits, n);
    return n;
}

int sor_inside(const Shape *s, Vec3 p)
{
    Vec3 q = inverse_transform_point(&s->to_world, p);
    int in = 0;
    if (q.y >= s->u.sor.height1 && q.y <= s->u.sor.height2) {
        double r0 = q.x * q.x + q.z * q.z;
        if (r0 <= s->u.sor.radius2 * s->u.sor.radius2) {
            for (int i = 0; i < s->u.sor.nsegments; i++) {
                const SorSegment *e = &s->u.sor.segments[i];
                if (q.y >= e->y1 && q.y <= e->y2) {
                    in = r0 <= radius2_at(e, q.y);
                    break;
                }
            }
        }
    }
    return in != (s->inverse != 0);
}

Vec3 sor_normal(const Shape *s, Vec3 p, int part)
{
    Vec3 n;
    if (part == SOR_BASE)
        n = v3(0.0, -1.0, 0.0);
    else if (part == SOR_CAP)
        n = v3(0.0, 1.0, 0.0);
    else
        n = curve_normal(&s->u.sor.segments[part - SOR_CURVE], inverse_transform_point(&s->to_world, p));
    return v3_normalize(transform_normal(&s->to_world, n));
}

Vec3 sor_uv(const Shape *s, Vec3 p)
{
    Vec3 q = inverse_transform_point(&s->to_world, p);
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
    const double r = sqrt(q.x * q.x + q.z * q.z);
    const double scale = 1e-9 * (1.0 + fabs(s->u.sor.height2) + fabs(s->u.sor.height1));
    double v = 0.0;
    if (!s->u.sor.open && fabs(q.y - s->u.sor.height1) <= scale && s->u.sor.base2 > 0.0 &&
        r * r < s->u.sor.base2 * (1.0 - 1e-9)) {
        v = r / sqrt(s->u.sor.base2) - 1; /* the base disc */
    } else if (!s->u.sor.open && fabs(q.y - s->u.sor.height2) <= scale && s->u.sor.cap2 > 0.0 &&
               r * r < s->u.sor.cap2 * (1.0 - 1e-9)) {
        v = -r / sqrt(s->u.sor.cap2) + 2; /* the cap disc */
    } else {
        const int n = s->u.sor.nsegments;
        for (int i = 0; i < n; i++) {
            const SorSegment *e = &s->u.sor.segments[i];
            if (q.y >= e->y1 && q.y <= e->y2) {
                v = (q.y - e->y1) / (e->y2 - e->y1) * (1.0 / n) + i * (1.0 / n);
                break;
            }
        }
    }
    return v3(theta, v, 0.0);
}
