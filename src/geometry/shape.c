/* POV-Ray 3.7's analytic shapes (source/backend/shape/ spheres.cpp,
 * discs.cpp, cones.cpp, torus.cpp): the same arithmetic in the same order
 * where it decides what a ray meets, so that hits, grazes and misses fall
 * where POV-Ray's do. Written anew from reading them, not copied. */
#include "shape.h"

#include <math.h>
#include <stddef.h>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "blob.h"
#include "csg.h"
#include "polynomial_solver.h"
#include "poly.h"
#include "lathe.h"
#include "prism.h"
#include "quadric.h"
#include "sor.h"
#include "superellipsoid.h"
#include "text.h"

#define POV_EPSILON 1.0e-10      /* POV-Ray's EPSILON */
#define POV_MAX_DISTANCE 1.0e7   /* POV-Ray's MAX_DISTANCE: farther crossings are not reported */

/* ---- sphere ------------------------------------------------------------- */

/* The ray in s's own space where its parameters are kept there
 * (Shape.transformed), else as it is; the direction is not made unit. */
static void own_ray(const Shape *s, Vec3 org, Vec3 dir, Vec3 *o, Vec3 *d)
{
    *o = s->transformed ? inverse_transform_point(&s->to_world, org) : org;
    *d = s->transformed ? inverse_transform_direction(&s->to_world, dir) : dir;
}

static int sphere_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits)
{
    Vec3 o, d;
    own_ray(s, org, dir, &o, &d);
    /* POV-Ray's rays have unit directions (an ellipsoid's is made unit in
     * its own space): the tolerances apply to distances along such a ray,
     * which are then divided back to t along dir. */
    double len = v3_length(d);
    if (!(len > 0.0))
        return 0;
    Vec3 u = len == 1.0 ? d : v3_scale(d, 1.0 / len);
    double t[2];
    unsigned kept = shape_sphere_unit_crossings(s, o, u, len, tmax, t);
    int n = 0;
    /* the first crossing enters the solid, the second leaves it (an
     * inverse sphere's solid is the outside) */
    for (int k = 0; k < 2; k++) {
        if (!(kept & (1u << k)))
            continue;
        hits[n].t = t[k];
        hits[n].entering = (k == 0) != (s->inverse != 0);
        hits[n].part = SHAPE_SIDE;
        n++;
    }
    return n;
}

static int sphere_inside(const Shape *s, Vec3 p)
{
    Vec3 q = s->transformed ? inverse_transform_point(&s->to_world, p) : p;
    Vec3 oc = v3_sub(s->u.sphere.center, q);
    double oc2 = v3_dot(oc, oc), r2 = s->u.sphere.radius * s->u.sphere.radius;
    return s->inverse ? oc2 > r2 : oc2 < r2;
}

static Vec3 sphere_normal(const Shape *s, Vec3 p)
{
    if (s->transformed) {
        Vec3 q = inverse_transform_point(&s->to_world, p);
        return v3_normalize(transform_normal(&s->to_world, v3_sub(q, s->u.sphere.center)));
    }
    /* POV-Ray divides by the radius rather than normalising */
    return v3_scale(v3_sub(p, s->u.sphere.center), 1.0 / s->u.sphere.radius);
}

/* Sphere::UVCoord: longitude from +x toward +z, latitude from the x-z
 * plane, of the point in the sphere's own space (POV-Ray carries the point
 * and the centre back through UV_Trans, every transform of the object), so
 * that the mapping turns with the sphere. */
static Vec3 sphere_uv(const Shape *s, Vec3 p)
{
    Vec3 q = inverse_transform_point(&s->to_world, p);
    double x = q.x - s->u.sphere.own_center.x, y = q.y - s->u.sphere.own_center.y, z = q.z - s->u.sphere.own_center.z;
    double len = sqrt(x * x + y * y + z * z);
    if (len == 0.0)
        return v3(0.0, 0.0, 0.0); /* POV-Ray leaves its result unset: ours is 0 */
    x /= len;
    y /= len;
    z /= len;
    double phi = 0.5 + asin(y) / M_PI;
    double theta;
    double xz = x * x + z * z;
    if (xz > POV_EPSILON) {
        xz = sqrt(xz);
        if (z == 0.0) {
            theta = x > 0 ? 0.0 : M_PI;
        } else {
            theta = acos(x / xz);
            if (z < 0.0)
                theta = 2.0 * M_PI - theta;
        }
        theta /= 2.0 * M_PI;
    } else {
        theta = 0.0; /* a pole: any longitude */
    }
    return v3(theta, phi, 0.0);
}

static void sphere_local_bounds(const Shape *s, Vec3 *lo, Vec3 *hi)
{
    double r = fabs(s->u.sphere.radius);
    Vec3 c = s->u.sphere.center;
    *lo = v3(c.x - r, c.y - r, c.z - r);
    *hi = v3(c.x + r, c.y + r, c.z + r);
}

/* ---- disc ------------------------------------------------------------------ */

#define DISC_DEPTH_TOLERANCE 1.0e-6 /* discs.cpp's DEPTH_TOLERANCE, on world distances */

/* Disc::Intersect: the crossing of its plane (z = 0 of its own space)
 * between the two radii. */
static int disc_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits)
{
    Vec3 p = inverse_transform_point(&s->to_world, org);
    Vec3 d = inverse_transform_direction(&s->to_world, dir);
    double len = v3_length(d);
    if (!(len > 0.0))
        return 0;
    d = v3_scale(d, 1.0 / len);
    if (!(fabs(d.z) > POV_EPSILON))
        return 0;
    double t = -p.z / d.z;
    if (!(t >= 0.0))
        return 0;
    double u = p.x + t * d.x, v = p.y + t * d.y;
    double r2 = u * u + v * v;
    if (!(r2 >= s->u.disc.inner2 && r2 <= s->u.disc.outer2))
        return 0;
    double depth = t / len;
    if (!(depth > DISC_DEPTH_TOLERANCE && depth < POV_MAX_DISTANCE && depth < tmax))
        return 0;
    /* its solid is the half-space below it (z < 0: Disc::Inside) */
    hits[0].t = depth;
    hits[0].entering = (d.z < 0.0) != (s->inverse != 0);
    hits[0].part = SHAPE_SIDE;
    return 1;
}

static int disc_inside(const Shape *s, Vec3 p)
{
    Vec3 q = inverse_transform_point(&s->to_world, p);
    return (q.z < 0.0) != (s->inverse != 0);
}

/* ---- cone and cylinder ------------------------------------------------------- */

#define CONE_TOLERANCE 1.0e-9 /* cones.cpp's Cone_Tolerance, on distances in its own space */

/* One crossing of a cone's part at local distance t (the ray's own space,
 * unit direction), kept where POV-Ray keeps it; `outward` the part's
 * local normal there, which says whether the ray enters. */
static int cone_keep(const Shape *s, ShapeHit *h, double t, double len, double tmax, int part, Vec3 d, Vec3 outward)
{
    if (!(t > CONE_TOLERANCE && t < POV_MAX_DISTANCE))
        return 0;
    double depth = t / len;
    if (!(depth < tmax))
        return 0;
    h->t = depth;
    h->part = part;
    h->entering = (v3_dot(d, outward) < 0.0) != (s->inverse != 0);
    return 1;
}

/* Cone::Intersect: the side's two roots, then the caps, in its own space. */
static int cone_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits)
{
    Vec3 p = inverse_transform_point(&s->to_world, org);
    Vec3 d = inverse_transform_direction(&s->to_world, dir);
    double len = v3_length(d);
    if (!(len > 0.0))
        return 0;
    d = v3_scale(d, 1.0 / len);
    const double dist = s->u.cone.dist;
    int n = 0;
    if (s->u.cone.cylinder) {
        double a = d.x * d.x + d.y * d.y;
        if (a > POV_EPSILON) {
            double b = p.x * d.x + p.y * d.y;
            double c = p.x * p.x + p.y * p.y - 1.0;
            double disc = b * b - a * c;
            if (disc >= 0.0) {
                disc = sqrt(disc);
                const double roots[2] = { (-b + disc) / a, (-b - disc) / a };
                for (int k = 0; k < 2; k++) {
                    double z = p.z + roots[k] * d.z;
                    Vec3 at = v3_add(p, v3_scale(d, roots[k]));
                    if (z >= 0.0 && z <= 1.0)
                        n += cone_keep(s, &hits[n], roots[k], len, tmax, SHAPE_SIDE, d, v3(at.x, at.y, 0.0));
                }
            }
        }
    } else {
        double a = d.x * d.x + d.y * d.y - d.z * d.z;
        double b = d.x * p.x + d.y * p.y - d.z * p.z;
        double c = p.x * p.x + p.y * p.y - p.z * p.z;
        if (fabs(a) < POV_EPSILON) {
            if (fabs(b) > POV_EPSILON) { /* the ray parallel to the side: one crossing */
                double t = -0.5 * c / b;
                double z = p.z + t * d.z;
                Vec3 at = v3_add(p, v3_scale(d, t));
                if (z >= dist && z <= 1.0)
                    n += cone_keep(s, &hits[n], t, len, tmax, SHAPE_SIDE, d, v3(at.x, at.y, -at.z));
            }
        } else {
            double disc = b * b - a * c;
            if (disc >= 0.0) {
                disc = sqrt(disc);
                const double roots[2] = { (-b - disc) / a, (-b + disc) / a };
                for (int k = 0; k < 2; k++) {
                    double z = p.z + roots[k] * d.z;
                    Vec3 at = v3_add(p, v3_scale(d, roots[k]));
                    if (z >= dist && z <= 1.0)
                        n += cone_keep(s, &hits[n], roots[k], len, tmax, SHAPE_SIDE, d, v3(at.x, at.y, -at.z));
                }
            }
        }
    }
    if (s->u.cone.closed && fabs(d.z) > POV_EPSILON) {
        double t = (1.0 - p.z) / d.z;
        double a = p.x + t * d.x, b = p.y + t * d.y;
        if (a * a + b * b <= 1.0)
            n += cone_keep(s, &hits[n], t, len, tmax, SHAPE_CAP, d, v3(0.0, 0.0, 1.0));
        t = (dist - p.z) / d.z;
        a = p.x + t * d.x;
        b = p.y + t * d.y;
        if (a * a + b * b <= (s->u.cone.cylinder ? 1.0 : dist * dist))
            n += cone_keep(s, &hits[n], t, len, tmax, SHAPE_BASE, d, v3(0.0, 0.0, -1.0));
    }
    /* nearest first (POV-Ray takes the nearest of its stack) */
    shape_hits_sort(hits, n);
    return n;
}

/* Cone::Inside, with its EPSILON margin (inward for a closed one). */
static int cone_inside(const Shape *s, Vec3 p)
{
    Vec3 q = inverse_transform_point(&s->to_world, p);
    double offset = s->u.cone.closed ? -POV_EPSILON : POV_EPSILON;
    double w2 = q.x * q.x + q.y * q.y;
    int out;
    if (s->u.cone.cylinder)
        out = w2 > 1.0 + offset || q.z < 0.0 - offset || q.z > 1.0 + offset;
    else
        out = w2 > q.z * q.z + offset || q.z < s->u.cone.dist - offset || q.z > 1.0 + offset;
    return out == (s->inverse != 0);
}

static Vec3 cone_normal(const Shape *s, Vec3 p, int part)
{
    Vec3 n;
    if (part == SHAPE_CAP) {
        n = v3(0.0, 0.0, 1.0);
    } else if (part == SHAPE_BASE) {
        n = v3(0.0, 0.0, -1.0);
    } else {
        n = inverse_transform_point(&s->to_world, p);
        n.z = s->u.cone.cylinder ? 0.0 : -n.z;
    }
    return v3_normalize(transform_normal(&s->to_world, n));
}


/* ---- torus ------------------------------------------------------------------ */

#define TORUS_DEPTH_TOLERANCE 1.0e-4 /* torus.cpp's DEPTH_TOLERANCE, on world distances */
#define TORUS_ROOT_TOLERANCE 1.0e-4  /* its ROOT_TOLERANCE: a root this near 0 is dropped */

/* One of Test_Thick_Cylinder's tests: does the ray cross the cylinder
 * x^2 + z^2 = r2 between the heights at a distance beyond EPSILON? */
static int crosses_cylinder(Vec3 p, Vec3 d, double a, double b, double r2, double h1, double h2)
{
    double c = p.x * p.x + p.z * p.z - r2;
    double disc = b * b - a * c;
    if (!(disc >= 0.0))
        return 0;
    disc = sqrt(disc);
    const double k[2] = { (-b + disc) / a, (-b - disc) / a };
    for (int i = 0; i < 2; i++) {
        if (k[i] > POV_EPSILON && k[i] < POV_MAX_DISTANCE) {
            double h = p.y + k[i] * d.y;
            if (h >= h1 && h <= h2)
                return 1;
        }
    }
    return 0;
}

/* Torus::Test_Thick_Cylinder: POV-Ray tests a ray against the torus only
 * where it crosses the thick cylinder around it (between heights h1, h2
 * and the squared radii r1, r2). */
static int crosses_thick_cylinder(Vec3 p, Vec3 d, double h1, double h2, double r1, double r2)
{
    if (fabs(d.y) < POV_EPSILON) {
        if (p.y < h1 || p.y > h2)
            return 0;
    } else {
        const double heights[2] = { h2, h1 };
        for (int i = 0; i < 2; i++) {
            double k = (heights[i] - p.y) / d.y;
            double u = p.x + k * d.x, v = p.z + k * d.z;
            if (k > POV_EPSILON && k < POV_MAX_DISTANCE) {
                double r = u * u + v * v;
                if (r >= r1 && r <= r2)
                    return 1;
            }
        }
    }
    double a = d.x * d.x + d.z * d.z;
    if (!(a > POV_EPSILON))
        return 0;
    double b = p.x * d.x + p.z * d.z;
    return crosses_cylinder(p, d, a, b, r2, h1, h2) || crosses_cylinder(p, d, a, b, r1, h1, h2);
}

static Vec3 torus_local_normal(const Shape *s, Vec3 q)
{
    double dist = sqrt(q.x * q.x + q.z * q.z);
    Vec3 m = dist > POV_EPSILON ? v3(s->u.torus.major * q.x / dist, 0.0, s->u.torus.major * q.z / dist) : v3(0, 0, 0);
    return v3_sub(q, m);
}

/* Torus::Intersect: the quartic in the distance along the ray in the
 * torus's own space, its origin first moved to just outside the bounding
 * sphere for precision, as POV-Ray moves it. */
static int torus_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits)
{
    Vec3 p = inverse_transform_point(&s->to_world, org);
    Vec3 d = inverse_transform_direction(&s->to_world, dir);
    double len = v3_length(d);
    if (!(len > 0.0))
        return 0;
    d = v3_scale(d, 1.0 / len);
    const double R = s->u.torus.major, r = s->u.torus.minor;
    double inner = R < r ? 0.0 : (R - r) * (R - r);
    if (!crosses_thick_cylinder(p, d, -r, r, inner, (R + r) * (R + r)))
        return 0;
    double bound = R + r + r, closer = 0.0;
    double dist2 = v3_dot(p, p);
    if (dist2 > bound * bound) {
        closer = sqrt(dist2) - bound;
        p = v3_add(p, v3_scale(d, closer));
    }
    double R2 = R * R, r2 = r * r;
    double py2 = p.y * p.y, dy2 = d.y * d.y, pdy2 = p.y * d.y;
    double k1 = p.x * p.x + p.z * p.z + py2 - R2 - r2;
    double k2 = p.x * d.x + p.z * d.z + pdy2;
    double c[5] = { 1.0, 4.0 * k2, 2.0 * (k1 + 2.0 * (k2 * k2 + R2 * dy2)), 4.0 * (k2 * k1 + 2.0 * R2 * pdy2),
                    k1 * k1 + 4.0 * R2 * (py2 - r2) };
    /* POV-Ray's Solve_Polynomial, its root elimination included */
    double roots[4];
    int nr = poly_solve(4, c, roots, s->u.torus.sturm, TORUS_ROOT_TOLERANCE);
    int n = 0;
    for (int k = 0; k < nr; k++) {
        double depth = (roots[k] + closer) / len;
        if (!(depth > TORUS_DEPTH_TOLERANCE && depth < POV_MAX_DISTANCE && depth < tmax))
            continue;
        Vec3 at = v3_add(p, v3_scale(d, roots[k]));
        hits[n].t = depth;
        hits[n].part = SHAPE_SIDE;
        hits[n].entering = (v3_dot(d, torus_local_normal(s, at)) < 0.0) != (s->inverse != 0);
        n++;
    }
    shape_hits_sort(hits, n);
    return n;
}

static int torus_inside(const Shape *s, Vec3 p)
{
    Vec3 q = inverse_transform_point(&s->to_world, p);
    double rr = sqrt(q.x * q.x + q.z * q.z) - s->u.torus.major;
    int in = q.y * q.y + rr * rr <= s->u.torus.minor * s->u.torus.minor;
    return in != (s->inverse != 0);
}

static Vec3 torus_normal(const Shape *s, Vec3 p)
{
    Vec3 q = inverse_transform_point(&s->to_world, p);
    return v3_normalize(transform_normal(&s->to_world, torus_local_normal(s, q)));
}

/* Torus::CalcUV: u around the y axis, v around the tube. */
static Vec3 torus_uv(const Shape *s, Vec3 p)
{
    Vec3 q = inverse_transform_point(&s->to_world, p);
    double u = 1.0 - (atan2(q.z, q.x) + M_PI) / (2.0 * M_PI);
    double x = sqrt(q.x * q.x + q.z * q.z) - s->u.torus.major;
    double v = (atan2(q.y, x) + M_PI) / (2.0 * M_PI);
    return v3(u, v, 0.0);
}

/* ---- box (a CSG part) --------------------------------------------------- */

#define BOX_DEPTH_TOLERANCE 1.0e-6 /* boxes.cpp's DEPTH_TOLERANCE */
#define BOX_CLOSE_TOLERANCE 1.0e-6 /* its CLOSE_TOLERANCE: slab distances this close are one */

/* The slab of axis a: entering and leaving distances along d (unit in
 * world space), in Box::Intersect's order and with its tie rule: where a
 * later axis's distance is within CLOSE_TOLERANCE of the current one, the
 * side is that axis's only when the ray runs more along it. `prefer`
 * says whether this axis beats the side already chosen. Returns 0 when
 * the ray misses. */
typedef struct {
    double tmin, tmax;
    int smin, smax;
} BoxSpan;

static double box_axis_weight(Vec3 d, int side)
{
    /* |D| along the axis of a side already chosen (Box::Intersect's
     * switch over smin/smax: X or Y; a Z side or none is never replaced) */
    switch (side) {
    case BOX_SIDE_X0: case BOX_SIDE_X1: return fabs(d.x);
    case BOX_SIDE_Y0: case BOX_SIDE_Y1: return fabs(d.y);
    default: return HUGE_VAL;
    }
}

static int box_slab(BoxSpan *sp, int axis, double p, double d, double lo, double hi, Vec3 dir)
{
    const int side_lo = BOX_SIDE_X0 + 2 * axis, side_hi = side_lo + 1;
    if (!(d < -POV_EPSILON || d > POV_EPSILON))
        return !(p < lo || p > hi);
    /* the far side first, then the near one */
    const double far_c = d < 0.0 ? lo : hi, near_c = d < 0.0 ? hi : lo;
    const int far_s = d < 0.0 ? side_lo : side_hi, near_s = d < 0.0 ? side_hi : side_lo;
    const double ad = fabs(d);
    double t = (far_c - p) / d;
    if (t < sp->tmin)
        return 0;
    if (axis == 0) {
        if (t <= sp->tmax) {
            sp->smax = far_s;
            sp->tmax = t;
        }
    } else if (t <= sp->tmax - BOX_CLOSE_TOLERANCE) {
        sp->smax = far_s;
        sp->tmax = t;
    } else if (t <= sp->tmax + BOX_CLOSE_TOLERANCE) {
        double other = axis == 1 ? fabs(dir.x) : box_axis_weight(dir, sp->smax);
        if (ad > other)
            sp->smax = far_s;
    }
    t = (near_c - p) / d;
    if (axis == 0) {
        if (t >= sp->tmin) {
            if (t > sp->tmax)
                return 0;
            sp->smin = near_s;
            sp->tmin = t;
        }
    } else if (t >= sp->tmin + BOX_CLOSE_TOLERANCE) {
        if (t > sp->tmax)
            return 0;
        sp->smin = near_s;
        sp->tmin = t;
    } else if (t >= sp->tmin - BOX_CLOSE_TOLERANCE) {
        double other = axis == 1 ? fabs(dir.x) : box_axis_weight(dir, sp->smin);
        if (ad > other)
            sp->smin = near_s;
    }
    return 1;
}

/* Box::All_Intersections: the slabs in the box's space (the ray's
 * direction carried there, not made unit: distances stay the world's). */
static int box_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits)
{
    Vec3 p, d;
    own_ray(s, org, dir, &p, &d);
    BoxSpan sp = { 0.0, 2.0e10, 0, 0 }; /* POV-Ray's BOUND_HUGE */
    const Vec3 lo = s->u.box.lo, hi = s->u.box.hi;
    if (!box_slab(&sp, 0, p.x, d.x, lo.x, hi.x, d) || !box_slab(&sp, 1, p.y, d.y, lo.y, hi.y, d) ||
        !box_slab(&sp, 2, p.z, d.z, lo.z, hi.z, d))
        return 0;
    if (sp.tmax < BOX_DEPTH_TOLERANCE)
        return 0;
    int n = 0;
    if (sp.tmin > BOX_DEPTH_TOLERANCE && sp.tmin < tmax) {
        hits[n].t = sp.tmin;
        hits[n].part = sp.smin;
        hits[n].entering = !s->inverse;
        n++;
    }
    if (sp.tmax < tmax) {
        hits[n].t = sp.tmax;
        hits[n].part = sp.smax;
        hits[n].entering = s->inverse != 0;
        n++;
    }
    return n;
}

static int box_inside(const Shape *s, Vec3 p)
{
    Vec3 q = s->transformed ? inverse_transform_point(&s->to_world, p) : p;
    const Vec3 lo = s->u.box.lo, hi = s->u.box.hi;
    int out = q.x < lo.x || q.x > hi.x || q.y < lo.y || q.y > hi.y || q.z < lo.z || q.z > hi.z;
    return out == (s->inverse != 0);
}

static Vec3 box_normal(const Shape *s, int part)
{
    static const Vec3 sides[7] = { { 0, 1, 0 }, { -1, 0, 0 }, { 1, 0, 0 }, { 0, -1, 0 },
                                   { 0, 1, 0 },  { 0, 0, -1 }, { 0, 0, 1 } };
    Vec3 n = sides[part >= 1 && part <= 6 ? part : 0];
    return s->transformed ? v3_normalize(transform_normal(&s->to_world, n)) : n;
}

/* ---- plane (a CSG part) ------------------------------------------------- */

#define PLANE_DEPTH_TOLERANCE 1.0e-6 /* planes.cpp's DEPTH_TOLERANCE */

/* Plane::Intersect, in its own space where it has a transform. */
static int plane_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits)
{
    Vec3 p, d;
    own_ray(s, org, dir, &p, &d);
    const Vec3 n = s->u.plane.normal;
    double nd = v3_dot(n, d);
    if (fabs(nd) < POV_EPSILON)
        return 0;
    double depth = -(v3_dot(n, p) + s->u.plane.distance) / nd;
    if (!(depth >= PLANE_DEPTH_TOLERANCE && depth <= POV_MAX_DISTANCE && depth < tmax))
        return 0;
    hits[0].t = depth;
    hits[0].part = SHAPE_SIDE;
    hits[0].entering = nd < 0.0; /* the solid is where dot(p, normal) is less (inverse: normal negated) */
    return 1;
}

static int plane_inside(const Shape *s, Vec3 p)
{
    Vec3 q = s->transformed ? inverse_transform_point(&s->to_world, p) : p;
    return v3_dot(q, s->u.plane.normal) + s->u.plane.distance < POV_EPSILON;
}

static Vec3 plane_normal(const Shape *s)
{
    Vec3 n = s->u.plane.normal;
    return s->transformed ? v3_normalize(transform_normal(&s->to_world, n)) : n;
}

/* ---- every shape ----------------------------------------------------------- */

void shape_compute_bounds(Shape *s)
{
    Vec3 lo, hi;
    switch (s->kind) {
    case SHAPE_CSG:
        csg_compute_bounds(s);
        return;
    case SHAPE_QUADRIC: /* its bounds are set with its coefficients (quadric_place) */
        return;
    case SHAPE_POLY: /* unbounded, as Poly::Compute_BBox makes it */
        s->bbox_min = v3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL);
        s->bbox_max = v3(HUGE_VAL, HUGE_VAL, HUGE_VAL);
        return;
    case SHAPE_BOX:
        lo = s->u.box.lo;
        hi = s->u.box.hi;
        break;
    case SHAPE_PLANE: /* unbounded (POV-Ray bounds only an axis-aligned one, which no CSG overlap here uses) */
        s->bbox_min = v3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL);
        s->bbox_max = v3(HUGE_VAL, HUGE_VAL, HUGE_VAL);
        return;
    case SHAPE_SPHERE:
        sphere_local_bounds(s, &lo, &hi);
        break;
    case SHAPE_DISC: {
        double r = sqrt(s->u.disc.outer2);
        lo = v3(-r, -r, -1e-3); /* POV-Ray's SMALL_TOLERANCE of thickness */
        hi = v3(r, r, 1e-3);
        break;
    }
    case SHAPE_CONE:
        lo = v3(-1.0, -1.0, s->u.cone.dist);
        hi = v3(1.0, 1.0, 1.0);
        break;
    case SHAPE_LATHE: /* Lathe::Compute_BBox */
        lo = v3(-s->u.lathe.radius2, s->u.lathe.height1, -s->u.lathe.radius2);
        hi = v3(s->u.lathe.radius2, s->u.lathe.height2, s->u.lathe.radius2);
        break;
    case SHAPE_SOR: /* Sor::Compute_BBox */
        lo = v3(-s->u.sor.radius2, s->u.sor.height1, -s->u.sor.radius2);
        hi = v3(s->u.sor.radius2, s->u.sor.height2, s->u.sor.radius2);
        break;
    case SHAPE_PRISM: /* Prism::Compute_BBox */
        lo = v3(s->u.prism.x1, s->u.prism.height1, s->u.prism.y1);
        hi = v3(s->u.prism.x2, s->u.prism.height2, s->u.prism.y2);
        break;
    case SHAPE_SUPERELLIPSOID: /* Superellipsoid::Compute_BBox */
        lo = v3(-1.0001, -1.0001, -1.0001);
        hi = v3(1.0001, 1.0001, 1.0001);
        break;
    case SHAPE_GLYPH:
        glyph_local_bounds(s, &lo, &hi);
        break;
    case SHAPE_BLOB:
        blob_bounds(s, &s->bbox_min, &s->bbox_max);
        return;
    case SHAPE_TORUS: {
        double r1 = s->u.torus.minor, r2 = s->u.torus.major + s->u.torus.minor;
        lo = v3(-r2, -r1, -r2);
        hi = v3(r2, r1, r2);
        break;
    }
    }
    if (!s->transformed) {
        s->bbox_min = lo;
        s->bbox_max = hi;
        return;
    }
    /* the box's eight corners carried to world space */
    Vec3 wlo = v3(HUGE_VAL, HUGE_VAL, HUGE_VAL), whi = v3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL);
    for (int k = 0; k < 8; k++) {
        Vec3 c = v3(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
        Vec3 w = transform_point(&s->to_world, c);
        wlo = v3_min(wlo, w);
        whi = v3_max(whi, w);
    }
    s->bbox_min = wlo;
    s->bbox_max = whi;
}

/* The crossings of a primitive by one test of the ray along unit u. */
static int one_test(const Shape *s, Vec3 org, Vec3 u, double ulimit, ShapeHit *hits)
{
    switch (s->kind) {
    case SHAPE_SPHERE: return sphere_all(s, org, u, ulimit, hits);
    case SHAPE_DISC: return disc_all(s, org, u, ulimit, hits);
    case SHAPE_CONE: return cone_all(s, org, u, ulimit, hits);
    case SHAPE_TORUS: return torus_all(s, org, u, ulimit, hits);
    case SHAPE_CSG: return csg_intersect_all(s, org, u, ulimit, hits);
    case SHAPE_BOX: return box_all(s, org, u, ulimit, hits);
    case SHAPE_PLANE: return plane_all(s, org, u, ulimit, hits);
    case SHAPE_GLYPH: return glyph_intersect_all(s, org, u, ulimit, hits);
    case SHAPE_BLOB: return blob_intersect_all(s, org, u, ulimit, hits);
    case SHAPE_QUADRIC: return quadric_all(s, org, u, ulimit, hits);
    case SHAPE_POLY: return poly_all(s, org, u, ulimit, hits);
    case SHAPE_SUPERELLIPSOID: return superellipsoid_all(s, org, u, ulimit, hits);
    case SHAPE_LATHE: return lathe_all(s, org, u, ulimit, hits);
    case SHAPE_SOR: return sor_all(s, org, u, ulimit, hits);
    case SHAPE_PRISM: return prism_all(s, org, u, ulimit, hits);
    }
    return 0;
}

/* The shapes whose crossings POV-Ray finds numerically from the ray's
 * origin (its polynomial solver, the superellipsoid's sampling), so that
 * where they are found depends on where the ray starts. */
static int found_from_origin(ShapeKind k)
{
    return k == SHAPE_POLY || k == SHAPE_SUPERELLIPSOID || k == SHAPE_LATHE || k == SHAPE_SOR || k == SHAPE_PRISM;
}

/* Such a shape's crossings as POV-Ray meets them along a ray that goes on
 * through it (a shadow ray through a see-through object, TracePointLight-
 * ShadowRay): its nearest crossing, then the nearest of the ray cast again
 * from there (POV-Ray's IPoint, the origin moved by that distance), and
 * so on. A CSG part's are all of one test, as POV-Ray's CSG asks them. */
static int crossings_cast_again(const Shape *s, Vec3 org, Vec3 u, double ulimit, ShapeHit *hits)
{
    ShapeHit one[SHAPE_NUMERIC_MAX_HITS];
    int n = 0;
    double done = 0.0;
    Vec3 o = org;
    while (n < s->max_hits) {
        if (one_test(s, o, u, HUGE_VAL, one) == 0)
            break;
        double t = one[0].t;
        if (!(done + t < ulimit))
            break;
        hits[n] = one[0];
        hits[n].t = done + t;
        n++;
        done += t;
        o = v3_add(o, v3_scale(u, t));
    }
    return n;
}

/* shape_intersect_all; nearest_only: the nearest crossing is all the
 * caller needs (no casting again past it). */
static int crossings(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits, int nearest_only)
{
    /* POV-Ray's rays have unit directions and its tolerances are distances
     * along them: the test runs on the unit direction, and its distances
     * are divided back to t along dir */
    double len = v3_length(dir);
    if (!(len > 0.0))
        return 0;
    Vec3 u = len == 1.0 ? dir : v3_scale(dir, 1.0 / len);
    double ulimit = len == 1.0 ? tmax : tmax * len;
    /* a sphere, the commonest shape, tested here without one_test's frame
     * (the room every shape's test needs) */
    int n = s->kind == SHAPE_SPHERE ? sphere_all(s, org, u, ulimit, hits)
            : found_from_origin(s->kind) && !s->is_part && !nearest_only ? crossings_cast_again(s, org, u, ulimit, hits)
                                                                         : one_test(s, org, u, ulimit, hits);
    if (s->kind != SHAPE_CSG) /* a primitive's crossings are its own */
        for (int k = 0; k < n; k++)
            hits[k].leaf = NULL;
    if (len != 1.0)
        for (int k = 0; k < n; k++)
            hits[k].t /= len;
    return n;
}

int shape_intersect_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits)
{
    return crossings(s, org, dir, tmax, hits, 0);
}

double shape_nearest(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hit)
{
    ShapeHit hits[SHAPE_MAX_HITS];
    if (crossings(s, org, dir, tmax, hits, 1) == 0)
        return -1.0;
    *hit = hits[0];
    return hits[0].t;
}

int shape_inside(const Shape *s, Vec3 p)
{
    switch (s->kind) {
    case SHAPE_SPHERE: return sphere_inside(s, p);
    case SHAPE_DISC: return disc_inside(s, p);
    case SHAPE_CONE: return cone_inside(s, p);
    case SHAPE_TORUS: return torus_inside(s, p);
    case SHAPE_CSG: return csg_inside(s, p);
    case SHAPE_BOX: return box_inside(s, p);
    case SHAPE_PLANE: return plane_inside(s, p);
    case SHAPE_QUADRIC: return quadric_inside(s, p);
    case SHAPE_POLY: return poly_inside(s, p);
    case SHAPE_SUPERELLIPSOID: return superellipsoid_inside(s, p);
    case SHAPE_LATHE: return lathe_inside(s, p);
    case SHAPE_SOR: return sor_inside(s, p);
    case SHAPE_PRISM: return prism_inside(s, p);
    case SHAPE_GLYPH: return glyph_inside(s, p);
    case SHAPE_BLOB: return blob_inside(s, p);
    }
    return 0;
}

Vec3 shape_normal(const Shape *s, Vec3 p, int part)
{
    switch (s->kind) {
    case SHAPE_SPHERE: return sphere_normal(s, p);
    case SHAPE_DISC: return s->u.disc.normal;
    case SHAPE_CONE: return cone_normal(s, p, part);
    case SHAPE_TORUS: return torus_normal(s, p);
    case SHAPE_CSG: break; /* its crossings are on its primitives (ShapeHit.leaf) */
    case SHAPE_BOX: return box_normal(s, part);
    case SHAPE_PLANE: return plane_normal(s);
    case SHAPE_QUADRIC: return quadric_normal(s, p);
    case SHAPE_POLY: return poly_normal(s, p);
    case SHAPE_SUPERELLIPSOID: return superellipsoid_normal(s, p);
    case SHAPE_LATHE: return lathe_normal(s, p, part);
    case SHAPE_SOR: return sor_normal(s, p, part);
    case SHAPE_PRISM: return prism_normal(s, p, part);
    case SHAPE_GLYPH: return glyph_normal(s, p, part);
    case SHAPE_BLOB: return blob_normal(s, p);
    }
    return v3(0.0, 1.0, 0.0);
}

Vec3 shape_uv(const Shape *s, Vec3 p)
{
    if (s->kind == SHAPE_LATHE)
        return lathe_uv(s, p);
    if (s->kind == SHAPE_SOR)
        return sor_uv(s, p);
    switch (s->kind) {
    case SHAPE_SPHERE: return sphere_uv(s, p);
    case SHAPE_TORUS: return torus_uv(s, p);
    case SHAPE_DISC:
    case SHAPE_CONE: break; /* no mapping of their own in POV-Ray 3.7 */
    case SHAPE_CSG: break;  /* its crossings are on its primitives */
    case SHAPE_BOX:         /* hstrace keeps no uv of a box that is a CSG part (man page) */
    case SHAPE_PLANE: break;
    case SHAPE_QUADRIC: /* no mapping of their own in POV-Ray 3.7 */
    case SHAPE_POLY:
    case SHAPE_SUPERELLIPSOID: break;
    case SHAPE_LATHE: /* above */
    case SHAPE_SOR: break;
    case SHAPE_PRISM: break; /* no mapping of its own in POV-Ray 3.7 */
    case SHAPE_GLYPH: break; /* POV-Ray 3.7's TrueType has no mapping of its own */
    case SHAPE_BLOB: break; /* POV-Ray's blob has no uv mapping */
    }
    return v3(p.x, p.y, 0.0); /* POV-Ray's default UVCoord */
}
int shape_hit_slot(const Shape *s, ShapeHit *hits, int *n, double d)
{
    if (*n < s->max_hits)
        return (*n)++;
    int at = 0;
    for (int i = 1; i < *n; i++)
        if (hits[i].t > hits[at].t)
            at = i;
    return d < hits[at].t ? at : -1;
}

void shape_hits_sort(ShapeHit *hits, int n)
{
    for (int i = 1; i < n; i++) /* insertion: a shape has a few crossings */
        for (int j = i; j > 0 && hits[j].t < hits[j - 1].t; j--) {
            ShapeHit x = hits[j];
            hits[j] = hits[j - 1];
            hits[j - 1] = x;
        }
}

/* One axis of shape_box_hit: the slab between lo and hi grown by a
 * relative margin far above the rounding of the box's corners and of the
 * slab distances, narrowing [*near, *far]; 0 when the ray misses it. Its
 * scalars are passed one axis at a time (no arrays of the ray and the box
 * to fill per call: this test runs before every exact test of a shape). */
static inline int bounds_slab(double lo, double hi, double o, double d, double *near, double *far)
{
    double margin = 1e-9 * (1.0 + fabs(lo) + fabs(hi) + fabs(o));
    double l = lo - margin, h = hi + margin;
    if (d == 0.0)
        return !(o < l || o > h);
    double t0 = (l - o) / d, t1 = (h - o) / d;
    if (t0 > t1) {
        double x = t0;
        t0 = t1;
        t1 = x;
    }
    t1 *= 1.0 + 1e-9;
    if (t0 > *near)
        *near = t0;
    if (t1 < *far)
        *far = t1;
    return !(*near > *far);
}

#if defined(__SSE2__)
/* bounds_slab on x and y at once, for a ray whose x and y directions are
 * not 0 (narrowing [*near, *far] from [0, tmax]): each lane is bounds_slab's
 * arithmetic in its order (IEEE operations, lane by lane); minpd(t1, t0)
 * and maxpd(t0, t1) are its swap (t0 > t1: false for NaN, as there), maxpd
 * and minpd against near and far its updates (a NaN distance leaves them
 * as they were), and the lanes joined as the second axis's updates after
 * the first's. That bounds_slab's early rejection after x is left out
 * changes nothing: near only grows and far only shrinks. */
static inline void bounds_slabs_xy(const Shape *s, Vec3 org, Vec3 dir, double *near, double *far)
{
    const __m128d sign = _mm_set1_pd(-0.0);
    const __m128d lo = _mm_set_pd(s->bbox_min.y, s->bbox_min.x), hi = _mm_set_pd(s->bbox_max.y, s->bbox_max.x);
    const __m128d o = _mm_set_pd(org.y, org.x), d = _mm_set_pd(dir.y, dir.x);
    __m128d sum = _mm_add_pd(_mm_add_pd(_mm_add_pd(_mm_set1_pd(1.0), _mm_andnot_pd(sign, lo)), _mm_andnot_pd(sign, hi)),
                             _mm_andnot_pd(sign, o));
    __m128d margin = _mm_mul_pd(_mm_set1_pd(1e-9), sum);
    __m128d t0 = _mm_div_pd(_mm_sub_pd(_mm_sub_pd(lo, margin), o), d);
    __m128d t1 = _mm_div_pd(_mm_sub_pd(_mm_add_pd(hi, margin), o), d);
    __m128d tn = _mm_min_pd(t1, t0), tf = _mm_mul_pd(_mm_max_pd(t0, t1), _mm_set1_pd(1.0 + 1e-9));
    __m128d n = _mm_max_pd(tn, _mm_set1_pd(*near)), f = _mm_min_pd(tf, _mm_set1_pd(*far));
    double nx = _mm_cvtsd_f64(n), ny = _mm_cvtsd_f64(_mm_unpackhi_pd(n, n));
    double fx = _mm_cvtsd_f64(f), fy = _mm_cvtsd_f64(_mm_unpackhi_pd(f, f));
    *near = ny > nx ? ny : nx;
    *far = fy < fx ? fy : fx;
}
#endif

int shape_box_hit(const Shape *s, Vec3 org, Vec3 dir, double tmax)
{
    double near = 0.0, far = tmax;
#if defined(__SSE2__)
    if (dir.x != 0.0 && dir.y != 0.0) {
        bounds_slabs_xy(s, org, dir, &near, &far);
        return !(near > far) && bounds_slab(s->bbox_min.z, s->bbox_max.z, org.z, dir.z, &near, &far);
    }
#endif
    return bounds_slab(s->bbox_min.x, s->bbox_max.x, org.x, dir.x, &near, &far) &&
           bounds_slab(s->bbox_min.y, s->bbox_max.y, org.y, dir.y, &near, &far) &&
           bounds_slab(s->bbox_min.z, s->bbox_max.z, org.z, dir.z, &near, &far);
}
