/* CSG intersection, merge and union of solids, after POV-Ray 3.7's
 * csg.cpp (All_Intersections, Inside, Compute_BBox); written anew from
 * reading it. */
#include "csg.h"

#include <math.h>

/* Does a crossing of `crossed`, one of s's parts, at p count as one of s's
 * surfaces? */
static int crossing_counts(const Shape *s, const Shape *crossed, Vec3 p)
{
    if (s->u.csg.op == CSG_UNION || s->u.csg.op == CSG_BOUND)
        return 1;
    const int want_inside = s->u.csg.op != CSG_MERGE;
    const Shape *c = s->u.csg.parts;
    for (int k = 0; k < s->u.csg.nparts; k++, c += c->subtree)
        if (c != crossed && shape_inside(c, p) != want_inside)
            return 0;
    return 1;
}

/* POV-Ray's MIN_ISECT_DEPTH: Find_Intersection takes no nearer crossing
 * (a bounding solid's among them). */
#define MIN_ISECT_DEPTH 1.0e-4

/* Ray_In_Bound: does the whole line from org along dir meet every
 * bounding solid of s (its parts after the first) at MIN_ISECT_DEPTH or
 * beyond, or start inside it? Whatever the ray's own length: POV-Ray
 * tests the bound along the ray as it was cast. */
static int ray_in_bounds(const Shape *s, Vec3 org, Vec3 dir)
{
    ShapeHit hits[SHAPE_MAX_HITS];
    const Shape *c = s->u.csg.parts + s->u.csg.parts->subtree;
    for (int k = 1; k < s->u.csg.nparts; k++, c += c->subtree) {
        int met = 0;
        if (shape_box_hit(c, org, dir, HUGE_VAL)) {
            int m = shape_intersect_all(c, org, dir, HUGE_VAL, hits);
            for (int j = 0; j < m && !met; j++)
                met = hits[j].t >= MIN_ISECT_DEPTH;
        }
        if (!met && !shape_inside(c, org))
            return 0;
    }
    return 1;
}

int csg_intersect_all(const Shape *s, Vec3 org, Vec3 dir, double tmax, ShapeHit *hits)
{
    int n = 0;
    const Shape *c = s->u.csg.parts;
    if (s->u.csg.op == CSG_BOUND && !ray_in_bounds(s, org, dir))
        return 0;
    /* a clipped or bounded object: its own crossings alone */
    const int crossed = s->u.csg.op == CSG_CLIP || s->u.csg.op == CSG_BOUND ? 1 : s->u.csg.nparts;
    for (int k = 0; k < crossed; k++, c += c->subtree) {
        if (!shape_box_hit(c, org, dir, tmax))
            continue;
        /* the part's crossings go where the kept ones end, and are kept
         * in place: no buffer per level of nesting */
        int m = shape_intersect_all(c, org, dir, tmax, hits + n);
        int kept = 0;
        for (int j = 0; j < m; j++) {
            ShapeHit h = hits[n + j];
            if (!h.leaf)
                h.leaf = c;
            /* POV-Ray's IPoint: the ray's origin plus the depth along its
             * unit direction */
            if (crossing_counts(s, c, v3_add(org, v3_scale(dir, h.t))))
                hits[n + kept++] = h;
        }
        n += kept;
    }
    /* nearest first; at one distance the earlier part first (stable) */
    shape_hits_sort(hits, n);
    return n;
}

int csg_inside(const Shape *s, Vec3 p)
{
    if (s->u.csg.op == CSG_BOUND) /* Inside_Object does not ask the bound */
        return shape_inside(s->u.csg.parts, p);
    const int all = s->u.csg.op == CSG_INTERSECTION || s->u.csg.op == CSG_CLIP;
    const Shape *c = s->u.csg.parts;
    for (int k = 0; k < s->u.csg.nparts; k++, c += c->subtree) {
        int in = shape_inside(c, p);
        if (all && !in)
            return 0;
        if (!all && in)
            return 1;
    }
    return all;
}

void csg_compute_bounds(Shape *s)
{
    Vec3 lo = v3(HUGE_VAL, HUGE_VAL, HUGE_VAL), hi = v3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL);
    const Shape *c = s->u.csg.parts;
    /* every crossing is on a part: within the box around them (around
     * the first alone for a clipped object, whose crossings are its) */
    const int crossed = s->u.csg.op == CSG_CLIP || s->u.csg.op == CSG_BOUND ? 1 : s->u.csg.nparts;
    for (int k = 0; k < crossed && k < s->u.csg.nparts; k++, c += c->subtree) {
        lo = v3_min(lo, c->bbox_min);
        hi = v3_max(hi, c->bbox_max);
    }
    if (s->u.csg.op == CSG_INTERSECTION || s->u.csg.op == CSG_CLIP) {
        /* every crossing kept is inside each part that is not inverted,
         * so within its box */
        Vec3 olo = v3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL), ohi = v3(HUGE_VAL, HUGE_VAL, HUGE_VAL);
        c = s->u.csg.parts;
        for (int k = 0; k < s->u.csg.nparts; k++, c += c->subtree)
            if (!c->inverse) {
                olo = v3_max(olo, c->bbox_min);
                ohi = v3_min(ohi, c->bbox_max);
            }
        /* an empty overlap is not used (POV-Ray keeps the box it had) */
        if (olo.x <= ohi.x && olo.y <= ohi.y && olo.z <= ohi.z) {
            lo = v3_max(lo, olo);
            hi = v3_min(hi, ohi);
        }
    }
    if (s->u.csg.nparts == 0) /* no crossing ever: a point for the hierarchy */
        lo = hi = v3(0.0, 0.0, 0.0);
    s->bbox_min = lo;
    s->bbox_max = hi;
}
