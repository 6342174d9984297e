/* The beam from a shading point to a whole area light (area_light_beam.h). */
#include "area_light_beam.h"

#include <math.h>

#include "intersect.h"

/* Where along one axis (in units of the axis, 0 the centre) the samples
 * with grid indices lo..hi can lie: their nominal places, half a cell more
 * each way with jitter, and circular's remapping, which nudges by 0.001
 * and then pulls each sample toward the centre by a factor between
 * 1/sqrt(2) and 1 (so [x * 0.7071, x] holds it); widened for rounding. */
static void extent(const Light *l, int size, int lo, int hi, double *from, double *to)
{
    if (size <= 1) {
        *from = *to = 0.0;
        return;
    }
    double jit = l->area.jitter ? 0.5 : 0.0;
    double a = ((double)lo - jit) / (double)(size - 1) - 0.5, b = ((double)hi + jit) / (double)(size - 1) - 0.5;
    if (l->area.circular) {
        a += 0.001;
        b += 0.001;
        double s = 0.7071;
        double lo2 = fmin(fmin(a, b), fmin(a * s, b * s)), hi2 = fmax(fmax(a, b), fmax(a * s, b * s));
        a = lo2;
        b = hi2;
    }
    double pad = 1e-9 * (1.0 + fmax(fabs(a), fabs(b)));
    *from = a - pad;
    *to = b + pad;
}

/* plain comparisons: libm's fmin and fmax are calls, in the hot tests */
static inline double min2(double a, double b) { return a < b ? a : b; }
static inline double max2(double a, double b) { return a > b ? a : b; }

static double scale_of(Vec3 v) { return fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z))); }

int area_beam_init(AreaBeam *b, const Light *l, Vec3 p, Vec3 axis1, Vec3 axis2, double tol)
{
    double f0, f1, g0, g1;
    extent(l, l->area.size1, 0, l->area.size1 - 1, &f0, &f1);
    extent(l, l->area.size2, 0, l->area.size2 - 1, &g0, &g1);
    Vec3 c = l->location;
    b->apex = p;
    b->parallel = l->kind == LIGHT_PARALLEL;
    b->corner[0] = v3_add(v3_add(c, v3_scale(axis1, f0)), v3_scale(axis2, g0));
    b->corner[1] = v3_add(v3_add(c, v3_scale(axis1, f1)), v3_scale(axis2, g0));
    b->corner[2] = v3_add(v3_add(c, v3_scale(axis1, f1)), v3_scale(axis2, g1));
    b->corner[3] = v3_add(v3_add(c, v3_scale(axis1, f0)), v3_scale(axis2, g1));
    /* the middle of the samples' parallelogram (circular's nudge moves it
     * off the light's centre), inside the pyramid */
    Vec3 mid = v3_add(v3_add(c, v3_scale(axis1, 0.5 * (f0 + f1))), v3_scale(axis2, 0.5 * (g0 + g1)));
    double scale = fmax(scale_of(p), scale_of(c)) + v3_length(axis1) + v3_length(axis2);
    if (b->parallel)
        scale = fmax(scale, scale_of(l->point_at));
    b->margin = 4.0 * fmax(tol, 1e-9 * (1.0 + scale));
    /* The corners' rays: toward each corner, or for a parallel light along
     * the line from point_at through it (POV-Ray's samples of a parallel
     * light point that way, each to the plane through it). */
    Vec3 from = b->parallel ? l->point_at : p;
    for (int k = 0; k < 4; k++)
        b->dir[k] = v3_sub(b->corner[k], from);
    Vec3 n = v3_cross(v3_sub(b->corner[1], b->corner[0]), v3_sub(b->corner[3], b->corner[0]));
    double nl = v3_length(n);
    if (!(nl > 0.0))
        return -1; /* one sample, or collinear axes: nothing to gain */
    n = v3_scale(n, 1.0 / nl);
    /* the sides: through the point, along each pair of neighbouring
     * corners' rays, the centre's ray inside */
    Vec3 axis = v3_sub(mid, from);
    if (fabs(v3_dot(n, axis)) <= 4.0 * b->margin)
        return -1; /* the point (point_at) in the light's plane */
    for (int k = 0; k < 4; k++) {
        Vec3 sd = v3_cross(b->dir[k], b->dir[(k + 1) % 4]);
        double sl = v3_length(sd);
        if (!(sl > 0.0))
            return -1;
        sd = v3_scale(sd, 1.0 / sl);
        if (v3_dot(sd, axis) > 0.0)
            sd = v3_neg(sd);
        b->normal[k] = sd;
        b->limit[k] = b->margin;
    }
    if (!b->parallel) {
        /* the base: the light's plane, the point on the inside */
        double height = v3_dot(n, v3_sub(mid, p));
        if (height < 0.0)
            n = v3_neg(n);
        b->normal[4] = n;
        b->limit[4] = fabs(height) + b->margin;
    } else {
        /* a parallel sample's ray ends at the foot of the perpendicular
         * from the sample to it, no farther from p than the sample, and the
         * farthest sample is a corner */
        double reach = 0.0;
        for (int k = 0; k < 4; k++)
            reach = fmax(reach, v3_length(v3_sub(b->corner[k], p)));
        b->normal[4] = v3_normalize(axis);
        b->limit[4] = reach * (1.0 + 1e-9) + b->margin;
    }
    return 0;
}

/* Is the box [lo, hi] wholly outside one of the planes? */
static int box_outside(const AreaBeam *b, const double lo[3], const double hi[3])
{
    for (int k = 0; k < 5; k++) {
        const Vec3 n = b->normal[k];
        /* the box's corner farthest inside */
        double x = n.x > 0.0 ? lo[0] : hi[0], y = n.y > 0.0 ? lo[1] : hi[1], z = n.z > 0.0 ? lo[2] : hi[2];
        if (n.x * (x - b->apex.x) + n.y * (y - b->apex.y) + n.z * (z - b->apex.z) > b->limit[k])
            return 1;
    }
    return 0;
}

static int polygon_outside(const AreaBeam *b, const World *w, const Polygon *p)
{
    const Vec3 *v = &w->points[p->first_point];
    for (int k = 0; k < 5; k++) {
        int out = 1;
        for (int i = 0; i < p->npoints && out; i++)
            out = v3_dot(b->normal[k], v3_sub(v[i], b->apex)) > b->limit[k];
        if (out)
            return 1;
    }
    return 0;
}

int area_beam_gather(const AreaBeam *b, const World *w, const Bvh *bvh, int exclude, uint32_t *out, int cap,
                     uint64_t *nodes)
{
    if (!bvh || bvh->nnodes == 0)
        return 0;
    int n = 0;
    uint32_t stack[BVH_STACK];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const BvhNode *node = &bvh->nodes[stack[--top]];
        for (int c = 0; c < BVH_WIDTH; c++) {
            uint32_t child = node->child[c];
            if (child == BVH_EMPTY)
                continue;
            ++*nodes;
            /* the float boxes are rounded outward: conservative in double */
            double lo[3] = { node->lo[0][c], node->lo[1][c], node->lo[2][c] };
            double hi[3] = { node->hi[0][c], node->hi[1][c], node->hi[2][c] };
            if (box_outside(b, lo, hi))
                continue;
            if (!bvh_is_leaf(child)) {
                if (top >= BVH_STACK)
                    return -1; /* cannot happen: the hierarchy is shallower */
                stack[top++] = child;
                continue;
            }
            uint32_t first = bvh_leaf_first(child), count = bvh_leaf_count(child);
            for (uint32_t i = 0; i < count; i++) {
                uint32_t pi = bvh->items[first + i];
                const Polygon *p = &w->polygons[pi];
                if ((int)pi == exclude || w->materials[p->material].no_shadow || polygon_outside(b, w, p))
                    continue;
                if (n >= cap)
                    return -1;
                out[n++] = pi;
            }
        }
    }
    return n;
}

int area_beam_planes_clear(const AreaBeam *b, const World *w, int exclude)
{
    /* the samples' planes test holds the shapes' too (shadow_planes_test),
     * which the beam does not look at: each sample's ray tests them */
    if (w->nshapes > 0)
        return 0;
    for (int i = 0; i < w->nplanes; i++) {
        const InfinitePlane *pl = &w->planes[i];
        if (i == exclude)
            continue; /* the point's own plane, which the shadow ray leaves out too */
        if (w->materials[pl->material].no_shadow)
            continue;
        double s = v3_dot(pl->normal, b->apex) - pl->d;
        if (!(fabs(s) > b->margin))
            return 0;
        for (int k = 0; k < 4; k++) {
            if (b->parallel) {
                /* every ray leaves the plane behind, or runs along it */
                if (v3_dot(pl->normal, b->dir[k]) * s < 0.0)
                    return 0;
                continue;
            }
            double sk = v3_dot(pl->normal, b->corner[k]) - pl->d;
            if (!(fabs(sk) > b->margin) || (sk > 0.0) != (s > 0.0))
                return 0;
        }
    }
    return 1;
}

/* 2-D: a convex quadrilateral, its edges' outward unit normals and its
 * box, for the tests of a polygon's edges against it. */
typedef struct {
    double q[4][2];
    double nx[4], ny[4], off[4]; /* outward: nx * x + ny * y - off > 0 beyond edge k */
    double lo[2], hi[2];
} Quad2;

static void quad_prepare(Quad2 *g)
{
    double turn = 0.0;
    for (int k = 0; k < 4; k++) {
        const double *p0 = g->q[k], *p1 = g->q[(k + 1) % 4];
        turn += p0[0] * p1[1] - p1[0] * p0[1];
    }
    for (int k = 0; k < 4; k++) {
        const double *p0 = g->q[k], *p1 = g->q[(k + 1) % 4];
        double ex = p1[0] - p0[0], ey = p1[1] - p0[1], len = sqrt(ex * ex + ey * ey);
        double nx = len > 0.0 ? ey / len : 0.0, ny = len > 0.0 ? -ex / len : 0.0;
        if (turn < 0.0) {
            nx = -nx;
            ny = -ny;
        }
        g->nx[k] = nx;
        g->ny[k] = ny;
        g->off[k] = nx * p0[0] + ny * p0[1];
    }
    for (int a = 0; a < 2; a++) {
        g->lo[a] = min2(min2(g->q[0][a], g->q[1][a]), min2(g->q[2][a], g->q[3][a]));
        g->hi[a] = max2(max2(g->q[0][a], g->q[1][a]), max2(g->q[2][a], g->q[3][a]));
    }
}

/* The quad and the segment a-b are apart by more than m: their boxes are,
 * or some edge line of the quad, or the segment's own line, has them on
 * its two sides. */
static int apart_2d(const Quad2 *g, const double a[2], const double b[2], double m)
{
    if (max2(a[0], b[0]) < g->lo[0] - m || min2(a[0], b[0]) > g->hi[0] + m || max2(a[1], b[1]) < g->lo[1] - m ||
        min2(a[1], b[1]) > g->hi[1] + m)
        return 1;
    for (int k = 0; k < 4; k++)
        if (g->nx[k] * a[0] + g->ny[k] * a[1] - g->off[k] > m && g->nx[k] * b[0] + g->ny[k] * b[1] - g->off[k] > m)
            return 1;
    double ex = b[0] - a[0], ey = b[1] - a[1], len = sqrt(ex * ex + ey * ey);
    if (!(len > 0.0))
        return 0;
    int below = 0, above = 0;
    for (int k = 0; k < 4; k++) {
        double sk = (ex * (g->q[k][1] - a[1]) - ey * (g->q[k][0] - a[0])) / len;
        below += sk < -m;
        above += sk > m;
    }
    return below == 4 || above == 4;
}

int area_beam_classify(const AreaBeam *b, const World *w, uint32_t pi)
{
    const Polygon *p = &w->polygons[pi];
    double sp = v3_dot(p->normal, b->apex) - p->d;
    if (!(fabs(sp) > b->margin))
        return BEAM_PARTIAL;
    /* the corners' rays where they cross the polygon's plane, in its 2-D projection */
    int iu = p->axis_u, iv = p->axis_v;
    Quad2 quad;
    Vec3 xs[4];
    for (int k = 0; k < 4; k++) {
        Vec3 x;
        if (b->parallel) {
            /* where the corner's ray meets the plane, if it heads for it
             * (how far it gets is not known: only MISSES can be told) */
            double toward = v3_dot(p->normal, b->dir[k]);
            if (!(toward * sp < 0.0) || !(fabs(toward) > 1e-12 * v3_length(b->dir[k])))
                return BEAM_PARTIAL;
            x = v3_add(b->apex, v3_scale(b->dir[k], -sp / toward));
        } else {
            double sk = v3_dot(p->normal, b->corner[k]) - p->d;
            if (!(fabs(sk) > b->margin) || (sk > 0.0) == (sp > 0.0))
                return BEAM_PARTIAL; /* the plane is not strictly between the point and this corner */
            x = v3_add(b->apex, v3_scale(v3_sub(b->corner[k], b->apex), sp / (sp - sk)));
        }
        xs[k] = x;
        quad.q[k][0] = v3_comp(x, iu);
        quad.q[k][1] = v3_comp(x, iv);
    }
    /* beside the polygon's box: beside the polygon */
    double m = b->margin;
    quad_prepare(&quad);
    if (quad.hi[0] < v3_comp(p->bbox_min, iu) - m || quad.lo[0] > v3_comp(p->bbox_max, iu) + m ||
        quad.hi[1] < v3_comp(p->bbox_min, iv) - m || quad.lo[1] > v3_comp(p->bbox_max, iv) + m)
        return BEAM_MISSES;
    /* No border comes within the margin of the quadrilateral: it lies
     * wholly on one side, in the polygon or beside it (in a hole, or
     * outside), as any of its points does. The rays to the light's
     * parallelogram cross the plane inside that quadrilateral. */
    for (int k = 0; k < polygon_outline_count(p); k++) {
        int n;
        const Vec3 *v = polygon_outline(w, p, k, &n);
        for (int i = 0; i < n; i++) {
            double a[2] = { v3_comp(v[i], iu), v3_comp(v[i], iv) };
            double c[2] = { v3_comp(v[(i + 1) % n], iu), v3_comp(v[(i + 1) % n], iv) };
            if (!apart_2d(&quad, a, c, m))
                return BEAM_PARTIAL;
        }
    }
    int inside = polygon_contains(w, p, xs[0]);
    if (inside)
        return b->parallel ? BEAM_PARTIAL : BEAM_COVERED;
    return BEAM_MISSES;
}
