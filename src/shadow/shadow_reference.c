/* The long-double brute-force shadow reference (see shadow_reference.h). */
#include <math.h>

#include "shadow_reference.h"

#include "shadow.h"

typedef long double ld;

typedef struct {
    ld x, y, z;
} LVec;

static LVec lv(Vec3 a) { LVec r = { a.x, a.y, a.z }; return r; }
static LVec lsub(LVec a, LVec b) { LVec r = { a.x - b.x, a.y - b.y, a.z - b.z }; return r; }
static ld ldot(LVec a, LVec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static ld lcomp(LVec a, int axis) { return axis == 0 ? a.x : axis == 1 ? a.y : a.z; }

long double shadow_reference_eps(const Grid *g)
{
    double m = fmax(fmax(fabs(g->min.x), fabs(g->max.x)),
                    fmax(fmax(fabs(g->min.y), fabs(g->max.y)), fmax(fabs(g->min.z), fabs(g->max.z))));
    return 1e-12L * (1 + m);
}

/* The outlines of polygon p as point runs: triangles have one of 3 points. */
static int outlines(const World *w, const Polygon *p, int *start, int *count, int cap)
{
    if (p->first_outline < 0) {
        start[0] = p->first_point;
        count[0] = 3;
        return 1;
    }
    const int *s = &w->outline_start[p->first_outline];
    int n = p->noutlines < cap ? p->noutlines : cap;
    for (int k = 0; k < n; k++) {
        start[k] = s[k];
        count[k] = s[k + 1] - s[k];
    }
    return n;
}

static ld segment_distance(ld au, ld av, ld bu, ld bv, ld qu, ld qv)
{
    ld eu = bu - au, ev = bv - av, len2 = eu * eu + ev * ev;
    ld t = len2 > 0 ? ((qu - au) * eu + (qv - av) * ev) / len2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    ld du = qu - (au + t * eu), dv = qv - (av + t * ev);
    return sqrtl(du * du + dv * dv);
}

/* The segment from p toward light l: unit direction and length (a parallel
 * light: to the plane it shines from). */
static void light_segment(const Light *l, LVec p, LVec *d, ld *tmax)
{
    if (l->kind == LIGHT_PARALLEL) {
        *d = lv(l->direction);
        *tmax = ldot(lsub(lv(l->location), p), *d);
    } else {
        *d = lsub(lv(l->location), p);
        *tmax = sqrtl(ldot(*d, *d));
        d->x /= *tmax, d->y /= *tmax, d->z /= *tmax;
    }
}

/* Where the segment meets the plane n.x == h0 + n.p (h: the plane's signed
 * distance from p along n): REF_LIT when it does not, REF_TIE when it runs
 * along the plane or meets it at an end, else REF_BLOCKED and *t. */
static RefAnswer plane_crossing(LVec n, ld h, LVec d, ld tmin, ld tmax, ld eps, ld *t)
{
    ld denom = ldot(n, d);
    if (fabsl(denom) <= eps)
        return fabsl(h) <= eps ? REF_TIE : REF_LIT;
    *t = h / denom;
    if (fabsl(*t - tmin) <= eps || fabsl(*t - tmax) <= eps)
        return REF_TIE;
    return *t <= tmin || *t >= tmax ? REF_LIT : REF_BLOCKED;
}

static RefAnswer polygon_answer(const World *w, int i, LVec p, LVec d, ld tmax, ld tmin, ld eps)
{
    const Polygon *poly = &w->polygons[i];
    int start[16] = { 0 }, count[16] = { 0 };
    int no = outlines(w, poly, start, count, 16);
    if (no < 1 || count[0] < 3)
        return REF_LIT;
    /* Newell's normal of the first outline, in long double. */
    LVec n = { 0, 0, 0 };
    const Vec3 *pts = w->points;
    for (int k = 0; k < count[0]; k++) {
        LVec a = lv(pts[start[0] + k]), b = lv(pts[start[0] + (k + 1) % count[0]]);
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    ld nl = sqrtl(ldot(n, n));
    if (nl == 0)
        return REF_LIT; /* degenerate: no area, blocks nothing */
    n.x /= nl, n.y /= nl, n.z /= nl;
    ld t = 0;
    RefAnswer r = plane_crossing(n, ldot(n, lsub(lv(pts[start[0]]), p)), d, tmin, tmax, eps, &t);
    if (r != REF_BLOCKED)
        return r;
    LVec x = { p.x + t * d.x, p.y + t * d.y, p.z + t * d.z };
    int iu = poly->axis_u, iv = poly->axis_v;
    ld qu = lcomp(x, iu), qv = lcomp(x, iv);
    int inside = 0;
    for (int o = 0; o < no; o++) {
        int c = count[o], in = 0;
        for (int k = 0; k < c; k++) {
            LVec a = lv(pts[start[o] + k]), b = lv(pts[start[o] + (k + 1) % c]);
            ld au = lcomp(a, iu), av = lcomp(a, iv), bu = lcomp(b, iu), bv = lcomp(b, iv);
            if (segment_distance(au, av, bu, bv, qu, qv) <= eps)
                return REF_TIE;
            if ((av >= qv) != (bv >= qv)) {
                ld u = au + (qv - av) * (bu - au) / (bv - av);
                if (qu < u)
                    in = !in;
            }
        }
        inside ^= in;
    }
    return inside ? REF_BLOCKED : REF_LIT;
}

RefAnswer shadow_reference_polygon(const World *w, int i, Vec3 p, const Light *l, long double tmin, long double eps)
{
    LVec lp = lv(p), d;
    ld tmax;
    light_segment(l, lp, &d, &tmax);
    return polygon_answer(w, i, lp, d, tmax, tmin, eps);
}

/* Can the segment come within eps of the box [lo, hi] at all? A cheap,
 * conservative rejection. */
static int segment_near_box(LVec p, LVec d, ld tmax, Vec3 lo, Vec3 hi, ld eps)
{
    ld a[3] = { p.x, p.y, p.z }, b[3] = { p.x + tmax * d.x, p.y + tmax * d.y, p.z + tmax * d.z };
    double l3[3] = { lo.x, lo.y, lo.z }, h3[3] = { hi.x, hi.y, hi.z };
    for (int k = 0; k < 3; k++) {
        ld smin = a[k] < b[k] ? a[k] : b[k], smax = a[k] < b[k] ? b[k] : a[k];
        if (smax < l3[k] - eps || smin > h3[k] + eps)
            return 0;
    }
    return 1;
}

RefAnswer shadow_reference(const World *w, const Hit *at, const Light *l, long double eps)
{
    LVec p = lv(at->point), d;
    ld tmax;
    light_segment(l, p, &d, &tmax);
    ld tmin = trace_min_distance(at->point);
    RefAnswer r = REF_LIT;
    for (int i = 0; i < w->npolygons; i++) {
        const Polygon *poly = &w->polygons[i];
        if ((at->kind == HIT_POLYGON && at->index == i) || w->materials[poly->material].no_shadow ||
            !segment_near_box(p, d, tmax, poly->bbox_min, poly->bbox_max, eps))
            continue;
        RefAnswer a = polygon_answer(w, i, p, d, tmax, tmin, eps);
        if (a == REF_BLOCKED)
            return REF_BLOCKED; /* a clear blocker decides, whatever else is a tie */
        if (a == REF_TIE)
            r = REF_TIE;
    }
    for (int i = 0; i < w->nplanes; i++) {
        const InfinitePlane *pl = &w->planes[i];
        if ((at->kind == HIT_PLANE && at->index == i) || w->materials[pl->material].no_shadow)
            continue;
        LVec n = lv(pl->normal);
        ld t;
        RefAnswer a = plane_crossing(n, (ld)pl->d - ldot(n, p), d, tmin, tmax, eps, &t);
        if (a == REF_BLOCKED)
            return REF_BLOCKED;
        if (a == REF_TIE)
            r = REF_TIE;
    }
    /* The shapes by their own test (shape.h), which is POV-Ray's
     * arithmetic and so the definition rather than an approximation of
     * it: a crossing of one blocks, as a polygon's does here. */
    Vec3 dd = { (double)d.x, (double)d.y, (double)d.z };
    double smin, slimit;
    shadow_shape_window((double)tmax, &smin, &slimit);
    for (int i = 0; i < w->nshapes; i++) {
        const Shape *s = &w->shapes[i];
        ShapeHit hits[SHAPE_MAX_HITS];
        int n = w->materials[s->material].no_shadow ? 0 : shape_intersect_all(s, at->point, dd, slimit, hits);
        for (int k = 0; k < n; k++)
            if (hits[k].t > smin)
                return REF_BLOCKED;
    }
    return r;
}

int shadow_reference_count(const World *w, const Hit *at, const Light *l, long double eps)
{
    int n = 0;
    for (int i = 0; i < w->npolygons; i++)
        if (!(at->kind == HIT_POLYGON && at->index == i))
            n += shadow_reference_polygon(w, i, at->point, l, trace_min_distance(at->point), eps) != REF_LIT;
    return n;
}
