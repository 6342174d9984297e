/* The blob (blob.h): POV-Ray 3.7's Blob written anew from reading blob.cpp,
 * with its steps, tolerances and order of arithmetic where they decide what
 * a ray meets. Its bounding-sphere hierarchy is not built: it changes which
 * components are tested, never which influence a ray, only the order in
 * which equal boundaries are listed. */
#include "blob.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "polynomial_solver.h"

#define POV_EPSILON 1.0e-10
#define POV_BOUND_HUGE 2.0e10
#define POV_MAX_DISTANCE 1.0e7
#define POV_SMALL_TOLERANCE 0.001    /* frame.h's SMALL_TOLERANCE */
#define BLOB_DEPTH_TOLERANCE 1.0e-2  /* blob.cpp's DEPTH_TOLERANCE */
#define BLOB_INSIDE_TOLERANCE 1.0e-6 /* blob.cpp's INSIDE_TOLERANCE */
#define BLOB_ROOT_EPSILON 1.0e-11    /* the root elimination bound All_Intersections passes */

/* ---- making the blob ---------------------------------------------------- */

static void set_field(BlobElement *e, double strength)
{
    e->c[0] = strength / (e->radius2 * e->radius2);
    e->c[1] = -(2.0 * strength) / e->radius2;
    e->c[2] = strength;
}

Blob *blob_make(const SceneBlobComponent *components, int n, double threshold)
{
    int count = 0;
    for (int i = 0; i < n; i++)
        count += components[i].kind == BLOB_COMPONENT_CYLINDER ? 3 : 1;
    Blob *b = calloc(1, sizeof *b);
    BlobElement *e = b ? calloc((size_t)count, sizeof *e) : NULL;
    if (!e) {
        free(b);
        return NULL;
    }
    b->threshold = threshold;
    b->nelements = count;
    b->elements = e;
    /* Parse_Blob lists the components last written first */
    int k = 0;
    for (int i = n - 1; i >= 0; i--) {
        const SceneBlobComponent *c = &components[i];
        BlobElement *el = &e[k++];
        el->radius2 = c->radius2;
        set_field(el, c->strength);
        if (c->kind == BLOB_COMPONENT_SPHERE) {
            el->kind = c->own_space ? BLOB_ELLIPSOID : BLOB_SPHERE;
            el->center = c->center;
            el->placed = c->own_space;
            el->to_element = c->placed;
            continue;
        }
        /* Compute_Coordinate_Transform from base along the unit axis,
         * then the component's own transforms */
        Vec3 axis = v3_sub(c->apex, c->base);
        el->len = v3_length(axis);
        double inv = 1.0 / el->len;
        axis = v3(axis.x * inv, axis.y * inv, axis.z * inv);
        transform_coordinate_frame(&el->to_element, c->base, axis, 1.0, 1.0);
        transform_compose(&el->to_element, &c->placed);
        el->kind = BLOB_CYLINDER;
        el->placed = 1;
        e[k] = *el;
        e[k++].kind = BLOB_BASE_HEMISPHERE;
        e[k] = *el;
        e[k++].kind = BLOB_APEX_HEMISPHERE;
    }
    return b;
}

void blob_free(Blob *b)
{
    if (!b)
        return;
    free(b->elements);
    free(b);
}

/* ---- where each component influences a ray ------------------------------ */

typedef struct {
    double bound;
    int entering;
    int element;
} Boundary;

/* insert_hit: the element's entry and exit into the list sorted by
 * distance, a new boundary after those at the same distance. */
static void insert_hit(int element, double t0, double t1, Boundary *list, int *cnt)
{
    list[*cnt] = (Boundary){ t0, 1, element };
    int k = 0;
    while (t0 > list[k].bound)
        k++;
    if (k < *cnt) {
        memmove(&list[k + 1], &list[k], sizeof *list * (size_t)(*cnt - k));
        list[k] = (Boundary){ t0, 1, element };
        (*cnt)++;
        list[*cnt] = (Boundary){ t1, 0, element };
        for (k = k + 1; t1 > list[k].bound; k++)
            ;
        if (k < *cnt) {
            memmove(&list[k + 1], &list[k], sizeof *list * (size_t)(*cnt - k));
            list[k] = (Boundary){ t1, 0, element };
        }
        (*cnt)++;
    } else {
        (*cnt)++;
        list[*cnt] = (Boundary){ t1, 0, element };
        (*cnt)++;
    }
}

/* The ray in an element's own space, its direction made unit (len: the
 * factor taken out). */
static void element_ray(const BlobElement *e, Vec3 p, Vec3 d, Vec3 *pp, Vec3 *dd, double *len)
{
    *pp = inverse_transform_point(&e->to_element, p);
    *dd = inverse_transform_direction(&e->to_element, d);
    *len = v3_length(*dd);
    double inv = 1.0 / *len;
    *dd = v3(dd->x * inv, dd->y * inv, dd->z * inv);
}

static void widen(double t, double *tmin, double *tmax)
{
    if (t < *tmin)
        *tmin = t;
    if (t > *tmax)
        *tmax = t;
}

/* intersect_cylinder: the span of the capped cylinder of radius sqrt(rad2). */
static int cylinder_span(const BlobElement *e, Vec3 P, Vec3 D, double mindist, double *tmin, double *tmax)
{
    Vec3 pp, dd;
    double len;
    element_ray(e, P, D, &pp, &dd, &len);
    double a = dd.x * dd.x + dd.y * dd.y;
    if (a > POV_EPSILON) {
        double b = pp.x * dd.x + pp.y * dd.y;
        double c = pp.x * pp.x + pp.y * pp.y - e->radius2;
        double d = b * b - a * c;
        if (d > POV_EPSILON) {
            d = sqrt(d);
            double t = (-b + d) / a, w = pp.z + t * dd.z;
            if (w >= 0.0 && w <= e->len)
                widen(t, tmin, tmax);
            t = (-b - d) / a;
            w = pp.z + t * dd.z;
            if (w >= 0.0 && w <= e->len)
                widen(t, tmin, tmax);
        }
    }
    if (fabs(dd.z) > POV_EPSILON) {
        double t = -pp.z / dd.z, u = pp.x + t * dd.x, v = pp.y + t * dd.y;
        if (u * u + v * v <= e->radius2)
            widen(t, tmin, tmax);
        t = (e->len - pp.z) / dd.z;
        u = pp.x + t * dd.x;
        v = pp.y + t * dd.y;
        if (u * u + v * v <= e->radius2)
            widen(t, tmin, tmax);
    }
    *tmin /= len;
    *tmax /= len;
    if (*tmin < mindist)
        *tmin = 0.0;
    if (*tmax < mindist)
        *tmax = 0.0;
    return *tmin < *tmax;
}

/* intersect_sphere and intersect_ellipsoid: the span within the radius. */
static int sphere_span(const BlobElement *e, Vec3 P, Vec3 D, double mindist, double *tmin, double *tmax)
{
    double len = 1.0;
    Vec3 pp = P, dd = D;
    if (e->kind == BLOB_ELLIPSOID)
        element_ray(e, P, D, &pp, &dd, &len);
    Vec3 v = v3_sub(pp, e->center);
    double b = v3_dot(v, dd), t = v3_dot(v, v);
    double d = b * b - t + e->radius2;
    if (d < POV_EPSILON)
        return 0;
    d = sqrt(d);
    *tmax = (-b + d) / len;
    if (*tmax < mindist)
        *tmax = 0.0;
    *tmin = (-b - d) / len;
    if (*tmin < mindist)
        *tmin = 0.0;
    if (*tmax == *tmin)
        return 0;
    if (*tmax < *tmin) {
        d = *tmin;
        *tmin = *tmax;
        *tmax = d;
    }
    return 1;
}

/* intersect_hemisphere: the sphere's span cut at the plane z = 0 (base,
 * the half below it) or z = len (apex, the half above). */
static int hemisphere_span(const BlobElement *e, Vec3 P, Vec3 D, double mindist, double *tmin, double *tmax)
{
    Vec3 pp, dd;
    double len;
    element_ray(e, P, D, &pp, &dd, &len);
    const int apex = e->kind == BLOB_APEX_HEMISPHERE;
    if (apex)
        pp.z -= e->len;
    double b = v3_dot(pp, dd), t = v3_dot(pp, pp);
    double d = b * b - t + e->radius2;
    if (d < POV_EPSILON)
        return 0;
    d = sqrt(d);
    *tmax = -b + d;
    *tmin = -b - d;
    if (*tmax < *tmin) {
        d = *tmin;
        *tmin = *tmax;
        *tmax = d;
    }
    double z1 = pp.z + *tmin * dd.z, z2 = pp.z + *tmax * dd.z;
    /* in1, in2: each end on the side the other half takes (no crossing) */
    int in1 = apex ? z1 <= 0.0 : z1 >= 0.0, in2 = apex ? z2 <= 0.0 : z2 >= 0.0;
    if (in1 && in2)
        return 0;
    if (!in1 && !in2) {
        *tmin /= len;
        *tmax /= len;
        return 1;
    }
    t = -pp.z / dd.z;
    if (in1)
        *tmin = t < mindist ? 0.0 : t; /* from the other half into this one */
    else
        *tmax = t < mindist ? 0.0 : t;
    *tmin /= len;
    *tmax /= len;
    return 1;
}

/* intersect_element */
static int element_span(const BlobElement *e, Vec3 P, Vec3 D, double mindist, double *tmin, double *tmax)
{
    *tmin = POV_BOUND_HUGE;
    *tmax = -POV_BOUND_HUGE;
    switch (e->kind) {
    case BLOB_SPHERE: case BLOB_ELLIPSOID: return sphere_span(e, P, D, mindist, tmin, tmax);
    case BLOB_BASE_HEMISPHERE: case BLOB_APEX_HEMISPHERE: return hemisphere_span(e, P, D, mindist, tmin, tmax);
    case BLOB_CYLINDER: return cylinder_span(e, P, D, mindist, tmin, tmax);
    }
    return 0;
}

/* ---- the field, the surface and its normal ----------------------------- */

/* The quartic in t of an element's field along P + t D, where t0 = |V|^2,
 * t1 = V.D and t2 = |D|^2 of its own space. */
static void field_along(const BlobElement *e, double t0, double t1, double t2, double *f)
{
    double c0 = e->c[0], c1 = e->c[1], c2 = e->c[2];
    f[0] = c0 * t2 * t2;
    f[1] = 4.0 * c0 * t1 * t2;
    f[2] = 2.0 * c0 * (2.0 * t1 * t1 + t0 * t2) + c1 * t2;
    f[3] = 2.0 * t1 * (2.0 * c0 * t0 + c1);
    f[4] = t0 * (c0 * t0 + c1) + c2;
}

static void element_coefficients(const BlobElement *e, Vec3 P, Vec3 D, double max_bound, double *f)
{
    Vec3 pp, dd, v;
    switch (e->kind) {
    case BLOB_SPHERE:
        v = v3_sub(P, e->center);
        field_along(e, v3_dot(v, v), v3_dot(v, D), max_bound * max_bound, f);
        return;
    case BLOB_ELLIPSOID:
        pp = inverse_transform_point(&e->to_element, P);
        dd = inverse_transform_direction(&e->to_element, D);
        v = v3_sub(pp, e->center);
        field_along(e, v3_dot(v, v), v3_dot(v, dd), v3_dot(dd, dd), f);
        return;
    case BLOB_BASE_HEMISPHERE:
    case BLOB_APEX_HEMISPHERE:
        pp = inverse_transform_point(&e->to_element, P);
        dd = inverse_transform_direction(&e->to_element, D);
        if (e->kind == BLOB_APEX_HEMISPHERE)
            pp.z -= e->len;
        field_along(e, v3_dot(pp, pp), v3_dot(pp, dd), v3_dot(dd, dd), f);
        return;
    case BLOB_CYLINDER:
        pp = inverse_transform_point(&e->to_element, P);
        dd = inverse_transform_direction(&e->to_element, D);
        field_along(e, pp.x * pp.x + pp.y * pp.y, pp.x * dd.x + pp.y * dd.y, dd.x * dd.x + dd.y * dd.y, f);
        return;
    }
}

/* calculate_element_field: the element's field at blob-space point p. */
static double element_field(const BlobElement *e, Vec3 p)
{
    double r2;
    Vec3 q;
    switch (e->kind) {
    case BLOB_SPHERE:
    case BLOB_ELLIPSOID:
        q = e->kind == BLOB_SPHERE ? p : inverse_transform_point(&e->to_element, p);
        q = v3_sub(q, e->center);
        r2 = v3_dot(q, q);
        return r2 < e->radius2 ? r2 * (r2 * e->c[0] + e->c[1]) + e->c[2] : 0.0;
    case BLOB_BASE_HEMISPHERE:
    case BLOB_APEX_HEMISPHERE:
        q = inverse_transform_point(&e->to_element, p);
        if (e->kind == BLOB_APEX_HEMISPHERE) {
            q.z -= e->len;
            if (!(q.z >= 0.0))
                return 0.0;
        } else if (!(q.z <= 0.0)) {
            return 0.0;
        }
        r2 = v3_dot(q, q);
        return r2 <= e->radius2 ? r2 * (r2 * e->c[0] + e->c[1]) + e->c[2] : 0.0;
    case BLOB_CYLINDER:
        q = inverse_transform_point(&e->to_element, p);
        if (!(q.z >= 0.0 && q.z <= e->len))
            return 0.0;
        r2 = q.x * q.x + q.y * q.y;
        return r2 <= e->radius2 ? r2 * (r2 * e->c[0] + e->c[1]) + e->c[2] : 0.0;
    }
    return 0.0;
}

int blob_inside(const Shape *s, Vec3 p)
{
    const Blob *b = s->u.blob.blob;
    Vec3 q = inverse_transform_point(&s->to_world, p);
    double density = 0.0;
    for (int i = 0; i < b->nelements; i++)
        density += element_field(&b->elements[i], q);
    int in = density > b->threshold - BLOB_INSIDE_TOLERANCE;
    return in != (s->inverse != 0);
}

/* element_normal: the element's share of the normal at blob-space p. */
static Vec3 element_normal(const BlobElement *e, Vec3 p, Vec3 sum)
{
    Vec3 q;
    double dist;
    switch (e->kind) {
    case BLOB_SPHERE:
    case BLOB_ELLIPSOID:
        q = e->kind == BLOB_SPHERE ? p : inverse_transform_point(&e->to_element, p);
        q = v3_sub(q, e->center);
        dist = v3_dot(q, q);
        if (!(dist <= e->radius2))
            return sum;
        if (e->kind == BLOB_ELLIPSOID)
            q = transform_normal(&e->to_element, q);
        break;
    case BLOB_BASE_HEMISPHERE:
    case BLOB_APEX_HEMISPHERE:
        q = inverse_transform_point(&e->to_element, p);
        if (e->kind == BLOB_APEX_HEMISPHERE) {
            q.z -= e->len;
            if (!(q.z >= 0.0))
                return sum;
        } else if (!(q.z <= 0.0)) {
            return sum;
        }
        dist = v3_dot(q, q);
        if (!(dist <= e->radius2))
            return sum;
        q = transform_normal(&e->to_element, q);
        break;
    case BLOB_CYLINDER:
        q = inverse_transform_point(&e->to_element, p);
        if (!(q.z >= 0.0 && q.z <= e->len))
            return sum;
        dist = q.x * q.x + q.y * q.y;
        if (!(dist <= e->radius2))
            return sum;
        q.z = 0.0;
        q = transform_normal(&e->to_element, q);
        break;
    default:
        return sum;
    }
    double val = -2.0 * e->c[0] * dist - e->c[1];
    return v3(sum.x + val * q.x, sum.y + val * q.y, sum.z + val * q.z);
}

/* Blob::Normal in blob space, unit (x when the field is flat there). */
static Vec3 local_normal(const Blob *b, Vec3 q)
{
    Vec3 n = v3(0.0, 0.0, 0.0);
    for (int i = 0; i < b->nelements; i++)
        n = element_normal(&b->elements[i], q, n);
    double val = v3_dot(n, n);
    if (val == 0.0)
        return v3(1.0, 0.0, 0.0);
    val = 1.0 / sqrt(val);
    return v3(n.x * val, n.y * val, n.z * val);
}

Vec3 blob_normal(const Shape *s, Vec3 p)
{
    Vec3 q = inverse_transform_point(&s->to_world, p);
    return v3_normalize(transform_normal(&s->to_world, local_normal(s->u.blob.blob, q)));
}

/* ---- the ray and the surface -------------------------------------------- */

enum { LOCAL_ELEMENTS = 64 };

/* Blob::All_Intersections: the boundaries of the components along the
 * ray, their fields' quartic coefficients added on entering and taken
 * away on leaving, and between each pair of boundaries the roots of the
 * sum less the threshold (the interval mapped to [0, 1], skipped when its
 * Bezier control values share one sign). POV-Ray stops after the first
 * interval that gives a crossing when the blob is not a CSG part, and asks
 * again from each crossing for the next (shadow rays through transparent
 * surfaces, refraction): every interval's crossings are those answers. */
int blob_intersect_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits)
{
    const Blob *b = s->u.blob.blob;
    Vec3 P = inverse_transform_point(&s->to_world, org);
    Vec3 D = inverse_transform_direction(&s->to_world, dir);
    double len = v3_length(D);
    if (!(len > 0.0))
        return 0;
    double inv = 1.0 / len;
    D = v3(D.x * inv, D.y * inv, D.z * inv);

    Boundary local_list[2 * LOCAL_ELEMENTS + 1];
    double local_coeffs[5 * LOCAL_ELEMENTS];
    Boundary *list = local_list;
    double *coeffs_of = local_coeffs;
    if (b->nelements > LOCAL_ELEMENTS) {
        list = malloc(sizeof *list * (size_t)(2 * b->nelements + 1));
        coeffs_of = malloc(sizeof *coeffs_of * 5 * (size_t)b->nelements);
        if (!list || !coeffs_of) {
            free(list);
            free(coeffs_of);
            return 0;
        }
    }
    int cnt = 0;
    for (int i = 0; i < b->nelements; i++) {
        double t0, t1;
        if (element_span(&b->elements[i], P, D, BLOB_DEPTH_TOLERANCE, &t0, &t1))
            insert_hit(i, t0, t1, list, &cnt);
    }
    int n = 0;
    if (cnt == 0)
        goto done;

    /* start at the first boundary, and scale the ray to the last one */
    double start_dist = list[0].bound;
    if (start_dist < POV_SMALL_TOLERANCE)
        start_dist = 0.0;
    for (int i = 0; i < cnt; i++)
        list[i].bound -= start_dist;
    P = v3(P.x + start_dist * D.x, P.y + start_dist * D.y, P.z + start_dist * D.z);
    double max_bound = list[0].bound;
    for (int i = 0; i < cnt; i++)
        if (list[i].bound > max_bound)
            max_bound = list[i].bound;
    if (max_bound != 0) {
        D = v3(D.x * max_bound, D.y * max_bound, D.z * max_bound);
        for (int i = 0; i < cnt; i++)
            list[i].bound /= max_bound;
    } else {
        max_bound = 1;
    }

    double coeffs[5] = { 0.0, 0.0, 0.0, 0.0, -b->threshold };
    int active = 0;
    for (int i = 0; i < cnt; i++) {
        double *f = &coeffs_of[5 * list[i].element];
        if (list[i].entering) {
            active++;
            element_coefficients(&b->elements[list[i].element], P, D, max_bound, f);
            for (int j = 0; j < 5; j++)
                coeffs[j] += f[j];
        } else {
            for (int j = 0; j < 5; j++)
                coeffs[j] -= f[j];
            if (--active == 0)
                continue;
        }
        /* a boundary right after this one: add or take it first */
        if (i + 1 >= cnt || fabs(list[i].bound - list[i + 1].bound) < POV_EPSILON)
            continue;
        double l = list[i].bound, w = list[i + 1].bound - l;
        double nc[5];
        nc[0] = coeffs[0] * w * w * w * w;
        nc[1] = (coeffs[1] + 4.0 * coeffs[0] * l) * w * w * w;
        nc[2] = (3.0 * l * (2.0 * coeffs[0] * l + coeffs[1]) + coeffs[2]) * w * w;
        nc[3] = (2.0 * l * (2.0 * l * (coeffs[0] * l + 0.75 * coeffs[1]) + coeffs[2]) + coeffs[3]) * w;
        nc[4] = l * (l * (l * (coeffs[0] * l + coeffs[1]) + coeffs[2]) + coeffs[3]) + coeffs[4];
        double dk[5];
        dk[0] = nc[4];
        dk[1] = nc[4] + 0.25 * nc[3];
        dk[2] = nc[4] + 0.50 * (nc[3] + nc[2] / 3.0);
        dk[3] = nc[4] + 0.50 * (1.5 * nc[3] + nc[2] + 0.5 * nc[1]);
        dk[4] = nc[4] + nc[3] + nc[2] + nc[1] + nc[0];
        if ((dk[0] >= 0.0 && dk[1] >= 0.0 && dk[2] >= 0.0 && dk[3] >= 0.0 && dk[4] >= 0.0) ||
            (dk[0] <= 0.0 && dk[1] <= 0.0 && dk[2] <= 0.0 && dk[3] <= 0.0 && dk[4] <= 0.0))
            continue;
        double roots[4];
        int nr = poly_solve(4, coeffs, roots, s->u.blob.sturm, BLOB_ROOT_EPSILON);
        int first = n;
        for (int j = 0; j < nr && n < s->max_hits; j++) {
            double dist = roots[j];
            if (!(dist >= list[i].bound && dist <= list[i + 1].bound))
                continue;
            dist = (dist * max_bound + start_dist) / len;
            if (!(dist > BLOB_DEPTH_TOLERANCE && dist < POV_MAX_DISTANCE))
                continue;
            if (!(dist < tmax))
                continue;
            /* in order, nearest first */
            int k = n++;
            while (k > first && hits[k - 1].t > dist) {
                hits[k] = hits[k - 1];
                k--;
            }
            hits[k].t = dist;
            hits[k].part = SHAPE_SIDE;
            hits[k].leaf = NULL;
        }
    }
    for (int k = 0; k < n; k++) { /* entering where the ray goes against the outward normal */
        Vec3 at = v3_add(org, v3_scale(dir, hits[k].t));
        hits[k].entering = (v3_dot(dir, blob_normal(s, at)) < 0.0) != (s->inverse != 0);
    }
done:
    if (list != local_list) {
        free(list);
        free(coeffs_of);
    }
    return n;
}

/* ---- bounds -------------------------------------------------------------- */

/* get_element_bounding_sphere, in blob space. */
static void element_sphere(const BlobElement *e, Vec3 *center, double *r2)
{
    Vec3 c = e->center;
    double rr = e->radius2;
    if (e->kind == BLOB_BASE_HEMISPHERE) {
        c = v3(0.0, 0.0, 0.0);
    } else if (e->kind == BLOB_APEX_HEMISPHERE) {
        c = v3(0.0, 0.0, e->len);
    } else if (e->kind == BLOB_CYLINDER) {
        c = v3(0.0, 0.0, 0.5 * e->len);
        rr = e->radius2 + 0.25 * e->len * e->len;
    }
    if (e->placed) {
        /* the widest extent of the cube [0, r]^3 carried by the transform */
        double r = sqrt(rr), widest = 0.0;
        c = transform_point(&e->to_element, c);
        for (int i = 0; i < 3; i++) {
            double extent = r * (fabs(e->to_element.m[0][i]) + fabs(e->to_element.m[1][i]) +
                                 fabs(e->to_element.m[2][i]));
            if (extent > widest)
                widest = extent;
        }
        rr = widest * widest + POV_EPSILON;
    }
    *center = c;
    *r2 = rr;
}

void blob_bounds(const Shape *s, Vec3 *lo, Vec3 *hi)
{
    const Blob *b = s->u.blob.blob;
    Vec3 mn = v3(POV_BOUND_HUGE, POV_BOUND_HUGE, POV_BOUND_HUGE), mx = v3_neg(mn);
    for (int i = 0; i < b->nelements; i++) {
        if (!(b->elements[i].c[2] > 0.0)) /* only what adds to the field */
            continue;
        Vec3 c;
        double r2;
        element_sphere(&b->elements[i], &c, &r2);
        double r = sqrt(r2);
        mn = v3_min(mn, v3(c.x - r, c.y - r, c.z - r));
        mx = v3_max(mx, v3(c.x + r, c.y + r, c.z + r));
    }
    if (!(mn.x <= mx.x)) { /* nothing adds to the field: nothing to meet */
        *lo = v3(HUGE_VAL, HUGE_VAL, HUGE_VAL);
        *hi = v3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL);
        return;
    }
    *lo = v3(HUGE_VAL, HUGE_VAL, HUGE_VAL);
    *hi = v3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL);
    for (int k = 0; k < 8; k++) {
        Vec3 corner = v3(k & 1 ? mx.x : mn.x, k & 2 ? mx.y : mn.y, k & 4 ? mx.z : mn.z);
        Vec3 w = transform_point(&s->to_world, corner);
        *lo = v3_min(*lo, w);
        *hi = v3_max(*hi, w);
    }
}
