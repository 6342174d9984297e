/* POV-Ray 3.7's superellipsoid (super.cpp), written anew from reading it:
 * its sampling of the ray and its root finder, step for step, since where
 * they find (or miss) the surface is part of the image POV-Ray makes. */
#include "superellipsoid.h"

#include <math.h>
#include <stdlib.h>

#define POV_EPSILON 1.0e-10        /* POV-Ray's EPSILON */
#define POV_MAX_DISTANCE 1.0e7     /* POV-Ray's MAX_DISTANCE */
#define BOUND_HUGE 2.0e10          /* POV-Ray's BOUND_HUGE */
#define SUPER_DEPTH_TOLERANCE 1.0e-4 /* super.cpp's DEPTH_TOLERANCE, on world distances */
#define ZERO_TOLERANCE 1.0e-10     /* a value this near 0 is on the surface */
#define BOX_MIN (-1.01)            /* its MIN_VALUE and MAX_VALUE: the box the ray is cut to */
#define BOX_MAX 1.01
#define MAX_ITERATIONS 20
#define PLANE_COUNT 9

/* The planes through the centre that cut the ray into pieces. */
static const double PLANES[PLANE_COUNT][3] = { { 1, 1, 0 }, { 1, -1, 0 }, { 1, 0, 1 }, { 1, 0, -1 }, { 0, 1, 1 },
                                               { 0, 1, -1 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };

/* x^e, by multiplications for the whole powers up to 6 (power()).
 * POV-Ray converts e to an int first; here e is tested to lie in int's
 * range before, since an exponent near 0 gives 1/e beyond it (C's
 * undefined behaviour), and pow takes every power outside 0 to 6 anyway. */
static double power(double x, double e)
{
    const int i = e >= 0.0 && e <= 6.0 ? (int)e : -1;
    if (i >= 0 && e == (double)i) {
        double b = x;
        switch (i) {
        case 0: return 1.0;
        case 1: return b;
        case 2: return b * b;
        case 3: return b * b * b;
        case 4: b *= b; return b * b;
        case 5: b *= b; return b * b * x;
        case 6: b *= b; return b * b * b;
        default: return pow(x, e);
        }
    }
    return pow(x, e);
}

/* evaluate_g: (x^e + y^e)^(1/e) for x, y >= 0, the larger factored out. */
static double evaluate_g(double x, double y, double e)
{
    double g = 0;
    if (x > y) {
        g = 1 + power(y / x, e);
        if (g != 1)
            g = power(g, 1 / e);
        g *= x;
    } else if (y != 0) {
        g = 1 + power(x / y, e);
        if (g != 1)
            g = power(g, 1 / e);
        g *= y;
    }
    return g;
}

/* The superellipsoid's function (0 on the surface, negative inside). */
static double evaluate(const Shape *s, Vec3 p)
{
    return evaluate_g(evaluate_g(fabs(p.x), fabs(p.y), s->u.superellipsoid.ex), fabs(p.z), s->u.superellipsoid.ez) -
           1;
}

/* intersect_box: the ray's span in the box of +-1.01, with the slab order
 * and EPSILON tests of POV-Ray's. */
static int clip_to_box(Vec3 p, Vec3 d, double *dmin, double *dmax)
{
    if (fabs(d.x) > POV_EPSILON) {
        if (d.x > POV_EPSILON) {
            *dmin = (BOX_MIN - p.x) / d.x;
            *dmax = (BOX_MAX - p.x) / d.x;
            if (*dmax < POV_EPSILON)
                return 0;
        } else {
            *dmax = (BOX_MIN - p.x) / d.x;
            if (*dmax < POV_EPSILON)
                return 0;
            *dmin = (BOX_MAX - p.x) / d.x;
        }
        if (*dmin > *dmax)
            return 0;
    } else {
        if (p.x < BOX_MIN || p.x > BOX_MAX)
            return 0;
        *dmin = -BOUND_HUGE;
        *dmax = BOUND_HUGE;
    }
    const double pa[2] = { p.y, p.z }, da[2] = { d.y, d.z };
    for (int a = 0; a < 2; a++) {
        if (fabs(da[a]) > POV_EPSILON) {
            double tmin, tmax;
            if (da[a] > POV_EPSILON) {
                tmin = (BOX_MIN - pa[a]) / da[a];
                tmax = (BOX_MAX - pa[a]) / da[a];
            } else {
                tmax = (BOX_MIN - pa[a]) / da[a];
                tmin = (BOX_MAX - pa[a]) / da[a];
            }
            if (tmax < *dmax) {
                if (tmax < POV_EPSILON)
                    return 0;
                if (tmin > *dmin) {
                    if (tmin > tmax)
                        return 0;
                    *dmin = tmin;
                } else if (*dmin > tmax) {
                    return 0;
                }
                *dmax = tmax;
            } else if (tmin > *dmin) {
                if (tmin > *dmax)
                    return 0;
                *dmin = tmin;
            }
        } else if (pa[a] < BOX_MIN || pa[a] > BOX_MAX) {
            return 0;
        }
    }
    return 1;
}

static int compare_distances(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x == y ? 0 : 1;
}

/* find_ray_plane_points: the distances at which the ray crosses the nine
 * planes within [lo, hi] (widened by EPSILON of its length), added to
 * dists, all sorted. */
static int add_plane_points(Vec3 p, Vec3 d, int cnt, double *dists, double lo, double hi)
{
    double widen = POV_EPSILON * (hi - lo);
    lo -= widen;
    hi += widen;
    for (int i = 0; i < PLANE_COUNT; i++) {
        double dn = d.x * PLANES[i][0] + d.y * PLANES[i][1] + d.z * PLANES[i][2];
        if (fabs(dn) < POV_EPSILON)
            continue;
        double t = (0.0 - (p.x * PLANES[i][0] + p.y * PLANES[i][1] + p.z * PLANES[i][2])) / dn;
        if (t >= lo && t <= hi)
            dists[cnt++] = t;
    }
    qsort(dists, (size_t)cnt, sizeof *dists, compare_distances);
    return cnt;
}

static Vec3 along(Vec3 a, double x, Vec3 b) /* a + x (b - a), as VAddScaled(a, x, b - a) */
{
    Vec3 d = v3_sub(b, a);
    return v3_add(a, v3_scale(d, x));
}

/* solve_hit1: the surface between P0 and P1, where the function changes
 * sign, by secant and bisection steps, whichever comes nearer. */
static Vec3 solve_between(const Shape *s, double v0, Vec3 p0, double v1, Vec3 p1)
{
    int i;
    for (i = 0; i < MAX_ITERATIONS; i++) {
        if (fabs(v0) < ZERO_TOLERANCE)
            return p0;
        if (fabs(v1) < ZERO_TOLERANCE)
            return p1;
        double x = fabs(v0) / fabs(v1 - v0);
        Vec3 p2 = along(p0, x, p1);
        double v2 = evaluate(s, p2);
        Vec3 p3 = along(p0, 0.5, p1);
        double v3 = evaluate(s, p3);
        if (v2 * v3 < 0.0) {
            v0 = v2;
            p0 = p2;
            v1 = v3;
            p1 = p3;
        } else if (fabs(v2) < fabs(v3)) { /* the secant does better */
            if (v0 * v2 < 0) {
                v1 = v2;
                p1 = p2;
            } else {
                v0 = v2;
                p0 = p2;
            }
        } else { /* bisection does better */
            if (v0 * v3 < 0) {
                v1 = v3;
                p1 = p3;
            } else {
                v0 = v3;
                p0 = p3;
            }
        }
    }
    return fabs(v0) < fabs(v1) ? p0 : p1;
}

/* check_hit2: between distances t0 and t1 without a change of sign, a
 * walk by secant steps from t0 in case the ray touches the surface there;
 * *t the distance found. */
static int walk_for_hit(const Shape *s, Vec3 p, Vec3 d, double t0, Vec3 p0, double v0, double t1, double *t)
{
    double dt0 = t0, dt1 = t0 + 0.0001 * (t1 - t0), maxdelta = t1 - t0, deltat = 0.0;
    for (int i = 0; dt0 < t1 && i < MAX_ITERATIONS; i++) {
        Vec3 p1 = v3_add(p, v3_scale(d, dt1));
        double v1 = evaluate(s, p1);
        if (v0 * v1 < 0) {
            Vec3 q = solve_between(s, v0, p0, v1, p1);
            *t = v3_length(v3_sub(q, p));
            return 1;
        }
        if (fabs(v1) < ZERO_TOLERANCE) {
            *t = dt1;
            return 1;
        }
        if ((v0 > 0.0 && v1 > v0) || (v0 < 0.0 && v1 < v0))
            break; /* moving away: no touch */
        if (v1 == v0)
            break;
        deltat = v1 * (dt1 - dt0) / (v1 - v0);
        if (fabs(deltat) > maxdelta)
            break;
        v0 = v1;
        dt0 = dt1;
        dt1 -= deltat;
    }
    return 0;
}

/* One crossing at world distance depth (insert_hit: beyond
 * DEPTH_TOLERANCE, before MAX_DISTANCE); returns whether it was kept.
 * outside_before: the function was positive at the sample before it, so
 * the ray enters the solid there. */
static int keep(const Shape *s, ShapeHit *hits, int *n, double depth, double tmax, int outside_before)
{
    if (!(depth > SUPER_DEPTH_TOLERANCE && depth < POV_MAX_DISTANCE))
        return 0;
    if (depth < tmax) {
        hits[*n].t = depth;
        hits[*n].part = SHAPE_SIDE;
        hits[*n].entering = outside_before != (s->inverse != 0);
        (*n)++;
    }
    return 1;
}

int superellipsoid_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits)
{
    Vec3 p = inverse_transform_point(&s->to_world, org);
    Vec3 d = inverse_transform_direction(&s->to_world, dir);
    double len = v3_length(d);
    if (!(len > 0.0))
        return 0;
    d = v3_scale(d, 1.0 / len);
    double t1, t2;
    if (!clip_to_box(p, d, &t1, &t2) || t2 < SUPER_DEPTH_TOLERANCE)
        return 0;
    if (t1 < SUPER_DEPTH_TOLERANCE)
        t1 = SUPER_DEPTH_TOLERANCE;
    double dists[PLANE_COUNT + 2] = { t1, t2 };
    int cnt = add_plane_points(p, d, 2, dists, t1, t2);
    if (cnt <= 1)
        return 0;
    int n = 0;
    Vec3 p0 = v3_add(p, v3_scale(d, dists[0]));
    double v0 = evaluate(s, p0);
    if (fabs(v0) < ZERO_TOLERANCE) /* on the surface where the ray enters its box */
        (void)keep(s, hits, &n, dists[0] / len, tmax, evaluate(s, v3_add(p0, d)) < v0);
    for (int i = 1; i < cnt; i++) {
        Vec3 p1 = v3_add(p, v3_scale(d, dists[i]));
        double v1 = evaluate(s, p1);
        if (fabs(v1) < ZERO_TOLERANCE) {
            (void)keep(s, hits, &n, dists[i] / len, tmax, v0 > 0.0);
        } else if (v0 * v1 < 0.0) { /* a change of sign: a root between */
            Vec3 q = solve_between(s, v0, p0, v1, p1);
            (void)keep(s, hits, &n, v3_length(v3_sub(q, p)) / len, tmax, v0 > 0.0);
        } else {
            /* no change of sign, but the ray may touch the surface
             * between the samples; a touch not kept ends the search */
            double t;
            if (walk_for_hit(s, p, d, dists[i - 1], p0, v0, dists[i], &t) &&
                !keep(s, hits, &n, t / len, tmax, v0 > 0.0))
                break;
        }
        v0 = v1;
        p0 = p1;
    }
    /* in order of the samples, so nearest first up to the solver's
     * rounding; sorted to be sure */
    shape_hits_sort(hits, n);
    return n;
}

int superellipsoid_inside(const Shape *s, Vec3 p)
{
    Vec3 q = inverse_transform_point(&s->to_world, p);
    return (evaluate(s, q) < POV_EPSILON) != (s->inverse != 0);
}

Vec3 superellipsoid_normal(const Shape *s, Vec3 p)
{
    const double ex = s->u.superellipsoid.ex, ez = s->u.superellipsoid.ez;
    Vec3 q = inverse_transform_point(&s->to_world, p);
    /* r stays 0 where POV-Ray leaves it unset (x = y = 0) */
    double r = 0.0, z2n = 0.0;
    if (q.z != 0) {
        z2n = power(fabs(q.z), ez);
        q.z = z2n / q.z;
    }
    if (fabs(q.x) > fabs(q.y)) {
        r = power(fabs(q.y / q.x), ex);
        q.x = (1 - z2n) / q.x;
        q.y = q.y != 0.0 ? (1 - z2n) * r / q.y : 0;
    } else if (q.y != 0) {
        r = power(fabs(q.x / q.y), ex);
        q.x = q.x != 0.0 ? (1 - z2n) * r / q.x : 0;
        q.y = (1 - z2n) / q.y;
    }
    if (q.z != 0.0)
        q.z *= 1 + r;
    return v3_normalize(transform_normal(&s->to_world, q));
}
