/* Building the shadow volumes: welding, silhouette edges with weights,
 * shadow polygons clipped to the grid box and registered per light, and the
 * eye's depth count. */
#include "shadow_volumes.h"
#include "big_memory.h"

#include "light.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "clock.h"
#include "intersect.h"
#include "parallel.h"

/* ---- welding vertices by exact position ---------------------------------- */

static uint64_t bits(double x)
{
    if (x == 0.0)
        x = 0.0; /* -0 and +0 are one position */
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static uint64_t hash_point(Vec3 p)
{
    uint64_t h = bits(p.x) * 0x9E3779B97F4A7C15ull;
    h ^= bits(p.y) + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2);
    h ^= bits(p.z) + 0x85EBCA77C2B2AE63ull + (h << 6) + (h >> 2);
    return h ^ (h >> 29);
}

static int same_point(Vec3 a, Vec3 b)
{
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

/* weld[i] for every entry of w->points: the index of its position class. */
static int *weld_points(const World *w, int *nclasses)
{
    int n = w->npoints;
    int *weld = big_malloc(sizeof(int) * (size_t)(n > 0 ? n : 1));
    size_t cap = 16;
    while (cap < (size_t)n * 2)
        cap *= 2;
    int *table = big_malloc(sizeof(int) * cap); /* holds a representative point index */
    if (!weld || !table) {
        free(weld);
        free(table);
        return NULL;
    }
    for (size_t i = 0; i < cap; i++)
        table[i] = -1;
    int classes = 0;
    for (int i = 0; i < n; i++) {
        size_t h = (size_t)hash_point(w->points[i]) & (cap - 1);
        while (table[h] >= 0 && !same_point(w->points[table[h]], w->points[i]))
            h = (h + 1) & (cap - 1);
        if (table[h] < 0) {
            table[h] = i;
            weld[i] = classes++;
        } else {
            weld[i] = weld[table[h]];
        }
    }
    free(table);
    *nclasses = classes;
    return weld;
}

/* ---- polygon edges with the side their polygon lies on ------------------- */

typedef struct {
    int a, b;          /* point indices, in outline order */
    int interior_left; /* the polygon lies on the side of cross(normal, b - a) */
} PolygonEdge;

static double outline_orientation(const Vec3 *pts, int n, Vec3 normal)
{
    Vec3 area = v3(0, 0, 0);
    for (int i = 0; i < n; i++)
        area = v3_add(area, v3_cross(pts[i], pts[(i + 1) % n]));
    return v3_dot(area, normal);
}

/* Fills edges (capacity p->npoints + 3) and returns their number. */
static int polygon_edges(const World *w, const Polygon *p, PolygonEdge *edges)
{
    int m = 0;
    if (p->first_outline < 0) {
        const Vec3 *v = &w->points[p->first_point];
        int left = v3_dot(v3_cross(v3_sub(v[1], v[0]), v3_sub(v[2], v[0])), p->normal) > 0.0;
        for (int i = 0; i < 3; i++)
            edges[m++] = (PolygonEdge){ p->first_point + i, p->first_point + (i + 1) % 3, left };
        return m;
    }
    const int *start = &w->outline_start[p->first_outline];
    for (int k = 0; k < p->noutlines; k++) {
        int s = start[k], e = start[k + 1], n = e - s;
        if (n < 3)
            continue;
        /* An outline inside an odd number of others bounds a hole: the
         * polygon lies outside it. */
        int nesting = 0;
        Vec3 q = w->points[s];
        for (int j = 0; j < p->noutlines; j++)
            if (j != k)
                nesting += outline_contains(&w->points[start[j]], start[j + 1] - start[j], p->axis_u, p->axis_v,
                                            v3_comp(q, p->axis_u), v3_comp(q, p->axis_v));
        int ccw = outline_orientation(&w->points[s], n, p->normal) > 0.0;
        int left = ccw ^ (nesting & 1);
        for (int i = 0; i < n; i++)
            edges[m++] = (PolygonEdge){ s + i, s + (i + 1) % n, left };
    }
    return m;
}

/* ---- edge contributions and merging -------------------------------------- */

/* One polygon's use of a welded edge. What a use is does not depend on the
 * light: the uses of every polygon are gathered and put in order once, for
 * all lights (edge_uses_build); each light's build then takes those of the
 * polygons that cast its shadows. */
typedef struct {
    int lo, hi;            /* welded vertex ids, lo < hi */
    int a, b;              /* point indices of lo and hi */
    int polygon;
    int8_t swapped;        /* the polygon's outline runs from b to a */
    int8_t interior_left;  /* as PolygonEdge's, for the outline's direction */
    int8_t edge_flat;      /* on an edge's first use: its polygons all lie in one plane (faces_flat) */
} EdgeUse;

/* Every polygon's uses of welded edges, by (lo, hi); the uses of one edge
 * in the order of the polygons and of their outlines. */
typedef struct {
    EdgeUse *uses;
    size_t n;
} EdgeUses;

/* A use as one light sees it. */
typedef struct {
    const EdgeUse *use;
    int8_t sign;     /* +1: the polygon lies on the positive side of the plane through the edge and the light */
    int8_t channel;  /* 1 opaque, 2 transparent */
} LightEdgeUse;

/* Polygons sharing an edge lie in one plane when their normals are
 * parallel (to the first one's). */
static int normals_parallel(Vec3 n0, Vec3 n) { return v3_length(v3_cross(n0, n)) <= 1e-12; }

/* The faces of a cancelled edge that are not all in one plane are bent
 * (see OccluderSide). When the light takes all `all` uses of the edge, the
 * answer is the one edge_uses_build found for every light (the same
 * normals, in the same order); else it is worked out for these n. */
static void mark_bent(LightVolumes *lv, const World *w, const LightEdgeUse *u, size_t n, const EdgeUse *first,
                      size_t all)
{
    int flat = 1;
    if (n == all) {
        flat = first->edge_flat;
    } else {
        Vec3 n0 = w->polygons[u[0].use->polygon].normal;
        for (size_t k = 1; k < n && flat; k++)
            flat = normals_parallel(n0, w->polygons[u[k].use->polygon].normal);
    }
    if (!flat)
        for (size_t k = 0; k < n; k++)
            lv->occluder[u[k].use->polygon].bent = 1;
}

/* The plane through the edge (a, b) and the light, from the canonical
 * vertex order so that every use of a welded edge gets the same plane. */
static int edge_plane(const Light *l, Vec3 a, Vec3 b, Vec3 *normal)
{
    Vec3 n = l->kind == LIGHT_PARALLEL ? v3_cross(v3_sub(b, a), l->direction)
                                       : v3_cross(v3_sub(a, l->location), v3_sub(b, l->location));
    double len = v3_length(n);
    /* the larger of the two distances as one root of the larger square: the same bits */
    Vec3 la = v3_sub(a, l->location), lb = v3_sub(b, l->location);
    double scale = v3_length(v3_sub(b, a)) *
                   (l->kind == LIGHT_PARALLEL ? 1.0 : sqrt(max_of(v3_dot(la, la), v3_dot(lb, lb))));
    if (!(len > 1e-12 * scale)) /* the light on the edge's line: no plane */
        return 0;
    *normal = v3_scale(n, 1.0 / len);
    return 1;
}

/* Whether edge_plane finds a plane for (a, b), most often without its
 * square roots: when the squared lengths say the cross product's length is
 * more than twice the bound, the rounded roots cannot bring it below once
 * the bound (each rounding moves a root by a relative 2^-53, and the squares
 * are normal numbers, so no step loses more); else edge_plane decides. */
static int edge_has_plane(const Light *l, Vec3 a, Vec3 b)
{
    Vec3 la = v3_sub(a, l->location), lb = v3_sub(b, l->location), ab = v3_sub(b, a);
    Vec3 n = l->kind == LIGHT_PARALLEL ? v3_cross(ab, l->direction) : v3_cross(la, lb);
    double n2 = v3_dot(n, n);
    double scale2 = v3_dot(ab, ab) * (l->kind == LIGHT_PARALLEL ? 1.0 : max_of(v3_dot(la, la), v3_dot(lb, lb)));
    double bound2 = 4e-24 * scale2; /* (2e-12)^2 */
    if (isfinite(n2) && isfinite(scale2) && bound2 >= DBL_MIN && n2 > bound2)
        return 1;
    Vec3 unused;
    return edge_plane(l, a, b, &unused);
}

/* The side of the plane through a use's edge and the light (edge_plane's,
 * from the canonical ends A, B) that its polygon lies on: +1 or -1, the sign
 * of n . inward, inward the polygon's direction across the edge in its plane
 * (N x (b - a) for the outline's order a, b, turned by interior_left).
 *
 * The plain way computes both vectors (use_side_by_plane). For a triangle
 * the answer follows from the light's side of its plane: A and B lie in it
 * (N . x = d), so by (p x q) . (r x s) = (p . r)(q . s) - (p . s)(q . r),
 * with n ~ (A - L) x (B - L) for a point light at L,
 *     n . (N x (B - A)) = -(N . L - d) |B - A|^2,
 * and with n ~ (B - A) x dir for a parallel light, -(N . dir) |B - A|^2.
 * The sign is minus the light's side (light_side, nonzero: within the
 * tolerance of the plane the polygon casts nothing), turned when the
 * outline runs from B to A and when the interior lies right of it. The
 * rounded product agrees wherever the light is well off the plane; where
 * it is not, this is the exact answer it approximates. shadow_volumes_build_plain
 * takes the plain way everywhere; tests/test_shadow_volumes.c compares the
 * two builds. */
static int8_t triangle_use_side(int light_side, int swapped, int interior_left)
{
    int side = -light_side;
    if (swapped)
        side = -side;
    if (!interior_left)
        side = -side;
    return (int8_t)side;
}

static int8_t use_side_by_plane(const World *w, const Polygon *p, int a, int b, int interior_left, Vec3 n)
{
    Vec3 inward = v3_cross(p->normal, v3_sub(w->points[b], w->points[a]));
    if (!interior_left)
        inward = v3_neg(inward);
    return (int8_t)(v3_dot(n, inward) > 0.0 ? 1 : -1);
}

static Vec3 unit(Vec3 v)
{
    double len = v3_length(v);
    return len > 0.0 ? v3_scale(v, 1.0 / len) : v;
}

/* The wedge of edge (a, b): in the plane, beyond the edge, between the two
 * rays from the light through a and b (parallel: along the light direction). */
static void make_shadow_polygon(ShadowPolygon *sp, const Light *l, Vec3 a, Vec3 b, Vec3 n)
{
    sp->normal = n;
    sp->d = v3_dot(n, a);
    sp->end[0] = a;
    sp->end[1] = b;
    for (int i = 0; i < 2; i++)
        sp->toward[i] = l->kind == LIGHT_PARALLEL ? l->direction : unit(v3_sub(l->location, sp->end[i]));
    /* Inside lies on b's side of the ray through a, and on a's through b. */
    sp->inside_sign[0] = (int8_t)(v3_dot(n, v3_cross(sp->toward[0], v3_sub(b, a))) >= 0.0 ? 1 : -1);
    sp->inside_sign[1] = (int8_t)(v3_dot(n, v3_cross(sp->toward[1], v3_sub(a, b))) >= 0.0 ? 1 : -1);
    Vec3 e = unit(v3_cross(n, v3_sub(b, a))); /* the edge, inward away from the light */
    if (v3_dot(e, v3_add(sp->toward[0], sp->toward[1])) > 0.0)
        e = v3_neg(e);
    sp->edge_normal = e;
    sp->edge_d = v3_dot(e, a);
}

/* ---- registration in the grid --------------------------------------------- */

typedef struct {
    uint32_t cell, item;
} Registration;

typedef struct {
    Registration *r;
    size_t n, cap;
} RegList;

static int reg_push(RegList *l, uint32_t cell, uint32_t item)
{
    if (l->n == l->cap) {
        size_t cap = l->cap ? l->cap * 2 : 1024;
        Registration *r = big_realloc(l->r, cap * sizeof *r);
        if (!r)
            return -1;
        l->r = r;
        l->cap = cap;
    }
    l->r[l->n++] = (Registration){ cell, item };
    return 0;
}

/* The part of the wedge inside the box lies within the quadrilateral
 * (a, b, b_far, a_far) when the far points are a box diagonal beyond the
 * edge as seen from the light. */
static void wedge_outline(const Light *l, Vec3 a, Vec3 b, double diagonal, Vec3 out[4])
{
    out[0] = a;
    out[1] = b;
    if (l->kind == LIGHT_PARALLEL) {
        Vec3 away = v3_scale(l->direction, -2.0 * diagonal);
        out[2] = v3_add(b, away);
        out[3] = v3_add(a, away);
        return;
    }
    /* Distance from the light to the segment ab bounds how fast the wedge
     * moves away from the edge. */
    Vec3 ab = v3_sub(b, a), la = v3_sub(a, l->location);
    double len2 = v3_dot(ab, ab);
    double t = len2 > 0.0 ? -v3_dot(la, ab) / len2 : 0.0;
    t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
    double dist = v3_length(v3_add(la, v3_scale(ab, t)));
    double lambda = 2.0 * diagonal / (dist > 1e-300 ? dist : 1e-300);
    if (lambda > 1e12)
        lambda = 1e12;
    out[2] = v3_add(b, v3_scale(v3_sub(b, l->location), lambda));
    out[3] = v3_add(a, v3_scale(la, lambda));
}

/* Room for a convex outline clipped by up to ten planes: the wedge's 4
 * corners, one more per plane. */
#define CLIPPED_MAX 16

/* Clips a convex outline to the slab lo <= coordinate `axis` <= hi. */
static int clip_slab(const Vec3 *in, int n, Vec3 *out, int axis, double lo, double hi)
{
    Vec3 tmp[CLIPPED_MAX];
    int m = clip_against(in, n, tmp, axis, lo, +1);
    return m > 0 ? clip_against(tmp, m, out, axis, hi, -1) : 0;
}

static void extent(const Vec3 *pts, int n, int axis, double *lo, double *hi)
{
    *lo = HUGE_VAL;
    *hi = -HUGE_VAL;
    for (int i = 0; i < n; i++) {
        double v = v3_comp(pts[i], axis);
        *lo = min_of(*lo, v);
        *hi = max_of(*hi, v);
    }
}

/* Registers the quadrilateral q (convex) in every cell it overlaps, cells
 * grown by tol: a point that close to the shadow polygon must find it in
 * its own cell, to know that it is undecidable. Row by row: clipped to a
 * z-slab, then to a y-row, the outline is still convex and connected, so
 * it overlaps exactly the cells its x-extent spans. */
static int register_shadow_polygon(RegList *regs, const Grid *g, const Vec3 wedge[4], uint32_t item, double tol)
{
    /* The wedge reaches twice the grid's diagonal past its edge; clipped to
     * the grid box first, the slab loops below visit only the rows it
     * actually crosses (on a 10^6-triangle scene most wedges leave the box
     * within a few cells, and the loops over empty slabs were most of the
     * build time). */
    Vec3 a[CLIPPED_MAX], b[CLIPPED_MAX];
    int nq = 4;
    memcpy(a, wedge, 4 * sizeof *a);
    for (int axis = 0; axis < 3 && nq > 0; axis++) {
        nq = clip_slab(a, nq, b, axis, v3_comp(g->min, axis) - tol, v3_comp(g->max, axis) + tol);
        memcpy(a, b, (size_t)nq * sizeof *a);
    }
    if (nq == 0)
        return 0;
    const Vec3 *q = a;
    double zlo, zhi;
    extent(q, nq, 2, &zlo, &zhi);
    int z0 = grid_cell_coord(g, zlo - tol, 2), z1 = grid_cell_coord(g, zhi + tol, 2);
    for (int z = z0; z <= z1; z++) {
        Vec3 pz[CLIPPED_MAX], pzy[CLIPPED_MAX];
        double cz = g->min.z + z * g->cell_size.z;
        int nz = clip_slab(q, nq, pz, 2, cz - tol, cz + g->cell_size.z + tol);
        if (nz == 0)
            continue;
        double ylo, yhi;
        extent(pz, nz, 1, &ylo, &yhi);
        int y0 = grid_cell_coord(g, ylo - tol, 1), y1 = grid_cell_coord(g, yhi + tol, 1);
        for (int y = y0; y <= y1; y++) {
            double cy = g->min.y + y * g->cell_size.y;
            int nzy = clip_slab(pz, nz, pzy, 1, cy - tol, cy + g->cell_size.y + tol);
            if (nzy == 0)
                continue;
            double xlo, xhi;
            extent(pzy, nzy, 0, &xlo, &xhi);
            if (xhi < g->min.x - tol || xlo > g->max.x + tol)
                continue;
            int x0 = grid_cell_coord(g, xlo - tol, 0), x1 = grid_cell_coord(g, xhi + tol, 0);
            for (int x = x0; x <= x1; x++) {
                int cell[3] = { x, y, z };
                if (reg_push(regs, (uint32_t)grid_cell_index(g, cell), item))
                    return -1;
            }
        }
    }
    return 0;
}

/* The light's lists per cell (cell_lists.h); items keep their order per cell. */
static int fill_cells(LightVolumes *lv, const Grid *g, RegList *regs)
{
    const Registration *r = regs->r;
    Registration none = { 0, 0 };
    if (cell_lists_build(&lv->cells, g->ncells, r ? &r->cell : &none.cell, r ? &r->item : &none.item, sizeof *r,
                         regs->n))
        return -1;
    lv->nitems = regs->n;
    return 0;
}

/* ---- the eye's depth count ------------------------------------------------ */

static double point_segment_distance(Vec3 p, Vec3 a, Vec3 b)
{
    Vec3 ab = v3_sub(b, a);
    double len2 = v3_dot(ab, ab);
    double t = len2 > 0.0 ? v3_dot(v3_sub(p, a), ab) / len2 : 0.0;
    t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
    return v3_length(v3_sub(p, v3_add(a, v3_scale(ab, t))));
}

/* Does the segment from `eye` to the light cross polygon p? Returns 1 or 0,
 * or -1 when the crossing lies within tol of p's plane or border. */
static int eye_crosses(const World *w, const Polygon *p, const Light *l, Vec3 eye, double tol, PolygonEdge *edges)
{
    double se = v3_dot(p->normal, eye) - p->d;
    Vec3 dir;
    double t;
    if (l->kind == LIGHT_PARALLEL) {
        dir = l->direction;
        double den = v3_dot(p->normal, dir);
        if (fabs(se) <= tol)
            return -1;
        if (den == 0.0)
            return 0;
        t = -se / den;
        if (t <= 0.0)
            return 0;
    } else {
        double sl = v3_dot(p->normal, l->location) - p->d;
        if (fabs(se) <= tol)
            return -1;
        if ((se > 0.0) == (sl > 0.0))
            return 0;
        dir = v3_sub(l->location, eye);
        t = se / (se - sl);
    }
    Vec3 x = v3_add(eye, v3_scale(dir, t));
    /* Well outside the polygon's box (twice tol: rounding of the distances
     * below cannot bring it within tol): neither inside nor near its border,
     * which both lie in the box. Most crossings of the plane end here. */
    for (int a = 0; a < 3; a++)
        if (v3_comp(x, a) < v3_comp(p->bbox_min, a) - 2.0 * tol || v3_comp(x, a) > v3_comp(p->bbox_max, a) + 2.0 * tol)
            return 0;
    int m = polygon_edges(w, p, edges);
    for (int i = 0; i < m; i++)
        if (point_segment_distance(x, w->points[edges[i].a], w->points[edges[i].b]) <= tol)
            return -1;
    return polygon_contains(w, p, x);
}

/* ---- the whole build ------------------------------------------------------ */

/* Every polygon's uses of welded edges (zero-length ones left out), by
 * (lo, hi) and, within an edge, in the order of the polygons and their
 * outlines: counted per lo, placed, then each lo's few sorted by hi, in
 * place and stably. Linear in the uses; once for all lights. Returns 0, or
 * -1 when out of memory. */
static int edge_uses_build(EdgeUses *eu, const World *w, const int *weld, int nclasses, PolygonEdge *edges)
{
    eu->uses = NULL;
    eu->n = 0;
    size_t *start = big_calloc((size_t)nclasses + 1, sizeof *start);
    if (!start)
        return -1;
    for (int pi = 0; pi < w->npolygons; pi++) {
        int ne = polygon_edges(w, &w->polygons[pi], edges);
        for (int i = 0; i < ne; i++) {
            int la = weld[edges[i].a], lb = weld[edges[i].b];
            if (la != lb)
                start[(la < lb ? la : lb) + 1]++;
        }
    }
    for (int c = 0; c < nclasses; c++)
        start[c + 1] += start[c];
    eu->n = start[nclasses];
    eu->uses = big_malloc(sizeof *eu->uses * (eu->n > 0 ? eu->n : 1));
    if (!eu->uses) {
        free(start);
        return -1;
    }
    for (int pi = 0; pi < w->npolygons; pi++) {
        int ne = polygon_edges(w, &w->polygons[pi], edges);
        for (int i = 0; i < ne; i++) {
            int a = edges[i].a, b = edges[i].b;
            if (weld[a] == weld[b])
                continue;
            int swap = weld[a] > weld[b];
            EdgeUse *u = &eu->uses[start[swap ? weld[b] : weld[a]]++];
            u->lo = swap ? weld[b] : weld[a];
            u->hi = swap ? weld[a] : weld[b];
            u->a = swap ? b : a;
            u->b = swap ? a : b;
            u->polygon = pi;
            u->swapped = (int8_t)swap;
            u->interior_left = (int8_t)edges[i].interior_left;
        }
    }
    free(start); /* each now the end of its lo's uses */
    /* Within a lo, by hi: insertion sort, stable, over a vertex's few edges. */
    for (size_t i = 1; i < eu->n; i++) {
        EdgeUse u = eu->uses[i];
        size_t k = i;
        while (k > 0 && eu->uses[k - 1].lo == u.lo && eu->uses[k - 1].hi > u.hi) {
            eu->uses[k] = eu->uses[k - 1];
            k--;
        }
        eu->uses[k] = u;
    }
    /* Each edge's flatness, for mark_bent. */
    for (size_t e = 0, e_end; e < eu->n; e = e_end) {
        Vec3 n0 = w->polygons[eu->uses[e].polygon].normal;
        int flat = 1;
        for (e_end = e + 1; e_end < eu->n && eu->uses[e_end].lo == eu->uses[e].lo && eu->uses[e_end].hi == eu->uses[e].hi;
             e_end++)
            flat = flat && normals_parallel(n0, w->polygons[eu->uses[e_end].polygon].normal);
        eu->uses[e].edge_flat = (int8_t)flat;
    }
    return 0;
}

/* A silhouette edge as a light's first pass finds it: the use its shadow
 * polygon is made from (the first of the edge's uses the light takes), and
 * the count change across it. */
typedef struct {
    uint32_t use; /* index in EdgeUses.uses */
    int16_t weight_opaque, weight_transparent;
} Silhouette;

typedef struct {
    Silhouette *s;
    size_t n, cap;
} SilhouetteList;

static int silhouette_push(SilhouetteList *l, Silhouette s)
{
    if (l->n == l->cap) {
        size_t cap = l->cap ? l->cap * 2 : 1024;
        Silhouette *bigger = big_realloc(l->s, cap * sizeof *bigger);
        if (!bigger)
            return -1;
        l->s = bigger;
        l->cap = cap;
    }
    l->s[l->n++] = s;
    return 0;
}

/* A light's first pass: which side of it each polygon faces (and whether
 * the eye's segment to it crosses the polygon), then edge by edge whether
 * the uses cancel (bent faces marked) or make a silhouette. */
static int classify_light(ShadowVolumes *sv, LightVolumes *lv, const World *w, const Light *l, const EdgeUses *eu,
                          const Vec3 *eye, PolygonEdge *edges, SilhouetteList *sil, int plain)
{
    double tol = sv->tolerance;
    sil->n = 0;
    if (eu->n > UINT32_MAX)
        return -1;
    lv->occluder = big_calloc((size_t)(w->npolygons > 0 ? w->npolygons : 1), sizeof *lv->occluder);
    if (!lv->occluder)
        return -1;
    lv->eye_known = eye != NULL;
    for (int pi = 0; pi < w->npolygons; pi++) {
        const Polygon *p = &w->polygons[pi];
        const Material *m = &w->materials[p->material];
        OccluderSide *o = &lv->occluder[pi];
        o->light_side = (int8_t)light_side_of(p, l, tol);
        o->channel = (int8_t)(m->no_shadow || o->light_side == 0 ? 0 : m->opaque ? 1 : 2);
        if (!o->channel)
            continue;
        if (lv->eye_known) {
            int c = eye_crosses(w, p, l, *eye, tol, edges);
            if (c < 0)
                lv->eye_known = 0;
            else if (c && o->channel == 1)
                lv->eye_opaque++;
            else if (c)
                lv->eye_transparent++;
        }
    }

    int status = 0;
    /* Edge by edge: the uses by polygons that cast this light's shadows and
     * whose edge has a plane through the light. */
    size_t cap_group = 16;
    LightEdgeUse *uses = malloc(cap_group * sizeof *uses);
    if (!uses)
        status = -1;
    for (size_t e = 0; e < eu->n && status == 0;) {
        size_t e_first = e, e_end = e;
        size_t nuses = 0;
        /* The uses of an edge mostly have its ends at the same coordinates
         * (a mesh's faces copy their vertices): whether they have a plane,
         * and the plane where it is needed, is found once. */
        Vec3 last_a = v3(0, 0, 0), last_b = last_a, last_n = last_a;
        int have_last = 0, last_ok = 0, have_n = 0;
        for (; e_end < eu->n && eu->uses[e_end].lo == eu->uses[e].lo && eu->uses[e_end].hi == eu->uses[e].hi; e_end++) {
            const EdgeUse *u = &eu->uses[e_end];
            const OccluderSide *o = &lv->occluder[u->polygon];
            if (!o->channel)
                continue;
            const Vec3 *pa = &w->points[u->a], *pb = &w->points[u->b];
            if (!have_last || memcmp(pa, &last_a, sizeof last_a) != 0 || memcmp(pb, &last_b, sizeof last_b) != 0) {
                last_a = *pa;
                last_b = *pb;
                have_n = plain;
                last_ok = plain ? edge_plane(l, last_a, last_b, &last_n) : edge_has_plane(l, last_a, last_b);
                have_last = 1;
            }
            if (!last_ok)
                continue;
            /* The polygon's side of the plane. */
            const Polygon *p = &w->polygons[u->polygon];
            int8_t side;
            if (!plain && p->first_outline < 0) {
                side = triangle_use_side(o->light_side, u->swapped, u->interior_left);
            } else {
                if (!have_n)
                    have_n = edge_plane(l, last_a, last_b, &last_n);
                side = use_side_by_plane(w, p, u->swapped ? u->b : u->a, u->swapped ? u->a : u->b, u->interior_left,
                                         last_n);
            }
            if (nuses == cap_group) {
                cap_group *= 2;
                LightEdgeUse *bigger = realloc(uses, cap_group * sizeof *uses);
                if (!bigger) {
                    status = -1;
                    break;
                }
                uses = bigger;
            }
            uses[nuses++] = (LightEdgeUse){ u, side, o->channel };
        }
        e = e_end;
        if (nuses == 0 || status)
            continue;
        size_t i = 0, j = nuses;
        int wo = 0, wt = 0;
        for (size_t k = i; k < j; k++) {
            if (uses[k].channel == 1)
                wo += uses[k].sign;
            else
                wt += uses[k].sign;
        }
        if (wo == 0 && wt == 0) {
            lv->cancelled_edges++;
            mark_bent(lv, w, uses + i, j - i, &eu->uses[e_first], e - e_first);
            continue;
        }
        lv->silhouette_edges++;
        status = silhouette_push(sil, (Silhouette){ (uint32_t)(uses[i].use - eu->uses), (int16_t)wo, (int16_t)wt });
    }
    free(uses);
    return status;
}

/* A light's second pass: its shadow polygons, made into out[0 .. sil->n)
 * (shadow polygons first .. first + n of all lights') and registered in
 * the cells they cross, as they are numbered among all lights'. regs is
 * the caller's scratch list, kept from light to light (its pages are
 * touched once, not per light). */
static int make_light_polygons(ShadowVolumes *sv, LightVolumes *lv, const World *w, const Grid *g, const Light *l,
                               const EdgeUses *eu, const SilhouetteList *sil, ShadowPolygon *out, size_t first,
                               RegList *regs, int fill)
{
    double tol = sv->tolerance;
    double diagonal = v3_length(v3_sub(g->max, g->min));
    regs->n = 0;
    lv->first = (int)first;
    lv->count = (int)sil->n;
    int status = 0;
    for (size_t k = 0; k < sil->n && status == 0; k++) {
        const EdgeUse *u = &eu->uses[sil->s[k].use];
        Vec3 a = w->points[u->a], b = w->points[u->b], n;
        edge_plane(l, a, b, &n); /* the plane the first pass found for this use: it has one */
        ShadowPolygon *sp = &out[k];
        make_shadow_polygon(sp, l, a, b, n);
        sp->weight_opaque = sil->s[k].weight_opaque;
        sp->weight_transparent = sil->s[k].weight_transparent;
        Vec3 q[4];
        wedge_outline(l, a, b, diagonal, q);
        status = register_shadow_polygon(regs, g, q, (uint32_t)(first + k), tol);
    }
    lv->nitems = regs->n;
    if (status == 0 && fill)
        status = fill_cells(lv, g, regs);
    return status;
}

/* One light's volumes, both passes, into an array of its own (*all, *nall
 * shadow polygons numbered from 0): the build's estimate (volume_plan.h)
 * times it on a sample. */
static int build_light(ShadowVolumes *sv, LightVolumes *lv, const World *w, const Grid *g, const Light *l,
                       const EdgeUses *eu, const Vec3 *eye, PolygonEdge *edges, RegList *regs, ShadowPolygon **all,
                       int *nall, int fill)
{
    SilhouetteList sil = { NULL, 0, 0 };
    int status = classify_light(sv, lv, w, l, eu, eye, edges, &sil, 0);
    *all = status == 0 ? big_malloc(sizeof **all * (sil.n > 0 ? sil.n : 1)) : NULL;
    if (status == 0 && !*all)
        status = -1;
    if (status == 0)
        status = make_light_polygons(sv, lv, w, g, l, eu, &sil, *all, 0, regs, fill);
    *nall = status == 0 ? (int)sil.n : 0;
    free(sil.s);
    return status;
}

/* A parallel light shines from the plane through its location, across its
 * direction: does any of the grid box lie on or beyond that plane? */
static int parallel_plane_cuts_box(const Light *l, const Grid *g, double tol)
{
    if (l->kind != LIGHT_PARALLEL)
        return 0;
    for (int k = 0; k < 8; k++) {
        Vec3 c = v3(k & 1 ? g->max.x : g->min.x, k & 2 ? g->max.y : g->min.y, k & 4 ? g->max.z : g->min.z);
        if (v3_dot(v3_sub(l->location, c), l->direction) <= tol)
            return 1;
    }
    return 0;
}

/* The lights' volumes on threads, each light on one, in two passes with all
 * lights' first passes done before any second: their silhouettes counted,
 * every light's shadow polygons are made straight into their places in
 * the one array (no light's copied there afterwards). */
typedef struct {
    ShadowVolumes *sv;
    const World *w;
    const Grid *g;
    const EdgeUses *uses;
    const Vec3 *eye;
    int maxpts;
    int first_light, stride;  /* the lights i = first_light + k * stride */
    SilhouetteList *sil;      /* per light */
    const size_t *first;      /* per light: its first shadow polygon's index (second pass) */
    int plain;                /* shadow_volumes_build_plain: every use's side by its plane */
    int status;
} LightJob;

static void *classify_lights(void *arg)
{
    LightJob *j = arg;
    const World *w = j->w;
    PolygonEdge *edges = malloc(sizeof *edges * (size_t)j->maxpts);
    if (!edges) {
        j->status = -1;
        return NULL;
    }
    for (int li = j->first_light; li < w->nlights && j->status == 0; li += j->stride)
        if (j->sv->light[li].usable)
            j->status = classify_light(j->sv, &j->sv->light[li], w, &w->lights[li], j->uses, j->eye, edges, &j->sil[li],
                                       j->plain);
    free(edges);
    return NULL;
}

static void *make_lights_polygons(void *arg)
{
    LightJob *j = arg;
    const World *w = j->w;
    RegList regs = { NULL, 0, 0 };
    for (int li = j->first_light; li < w->nlights && j->status == 0; li += j->stride)
        if (j->sv->light[li].usable)
            j->status = make_light_polygons(j->sv, &j->sv->light[li], w, j->g, &w->lights[li], j->uses, &j->sil[li],
                                            j->sv->polygons + j->first[li], j->first[li], &regs, 1);
    free(regs.r);
    return NULL;
}

/* Light li can have volumes: it casts shadows, and a parallel light's
 * plane does not cut the grid box. *cuts: why not, when it does. */
static int light_can_have_volumes(const World *w, const Grid *g, int li, double tol, int *cuts)
{
    *cuts = 0;
    /* an area light's samples are point lights of their own, decided by the shadow ray (area_light.h) */
    if (w->lights[li].shadowless || light_is_area(&w->lights[li]))
        return 0;
    if (parallel_plane_cuts_box(&w->lights[li], g, tol)) {
        *cuts = 1;
        return 0;
    }
    return 1;
}

static int build_volumes(ShadowVolumes *sv, const World *w, const Grid *g, const Vec3 *eye, int threads,
                         const int8_t *want, int plain)
{
    memset(sv, 0, sizeof *sv);
    sv->tolerance = grid_tolerance(g);
    sv->box_min = g->min;
    sv->box_max = g->max;
    sv->nlights = w->nlights;
    int nl = w->nlights > 0 ? w->nlights : 1;
    sv->light = calloc((size_t)nl, sizeof *sv->light);
    SilhouetteList *sil = calloc((size_t)nl, sizeof *sil);
    size_t *first = calloc((size_t)nl, sizeof *first);
    int nclasses = 0;
    int *weld = weld_points(w, &nclasses);
    int maxpts = 3;
    for (int i = 0; i < w->npolygons; i++)
        if (w->polygons[i].npoints + 3 > maxpts)
            maxpts = w->polygons[i].npoints + 3;
    int status = !sv->light || !sil || !first || !weld ? -1 : 0;
    sv->nwelded_vertices = nclasses;
    /* The edges' uses, for every light alike. */
    EdgeUses uses = { NULL, 0 };
    if (status == 0) {
        PolygonEdge *edges = malloc(sizeof *edges * (size_t)maxpts);
        status = edges && edge_uses_build(&uses, w, weld, nclasses, edges) == 0 ? 0 : -1;
        free(edges);
    }
    free(weld);
    int usable = 0;
    for (int li = 0; status == 0 && li < w->nlights; li++) {
        if (!light_can_have_volumes(w, g, li, sv->tolerance, &sv->light[li].plane_cuts_scene))
            continue;
        if (want && !want[li]) {
            sv->light[li].not_wanted = 1;
            continue;
        }
        sv->light[li].usable = 1;
        usable++;
    }
    /* The lights on up to `threads` threads, each light on one: what each
     * builds does not depend on the others, nor on which thread built it. */
    int nthreads = threads < 1 ? 1 : threads;
    if (nthreads > usable)
        nthreads = usable > 0 ? usable : 1;
    if (nthreads > PARALLEL_MAX_JOBS)
        nthreads = PARALLEL_MAX_JOBS;
    LightJob jobs[PARALLEL_MAX_JOBS];
    for (int t = 0; t < nthreads; t++)
        jobs[t] = (LightJob){ sv, w, g, &uses, eye, maxpts, t, nthreads, sil, first, plain, 0 };
    if (status == 0)
        parallel_run(nthreads, classify_lights, jobs, sizeof jobs[0]);
    for (int t = 0; t < nthreads; t++)
        if (jobs[t].status)
            status = -1;
    /* Every light's place in the one array, in light order. */
    size_t total = 0;
    for (int li = 0; status == 0 && li < w->nlights; li++) {
        first[li] = total;
        total += sil[li].n;
    }
    if (status == 0 && total > INT32_MAX)
        status = -1; /* shadow polygons are numbered in 32 bits, and counted in int */
    if (status == 0) {
        sv->polygons = big_malloc(sizeof *sv->polygons * (total > 0 ? total : 1));
        status = sv->polygons ? 0 : -1;
    }
    if (status == 0)
        parallel_run(nthreads, make_lights_polygons, jobs, sizeof jobs[0]);
    for (int t = 0; t < nthreads; t++)
        if (jobs[t].status)
            status = -1;
    sv->npolygons = (int)total;
    for (int li = 0; sil && li < w->nlights; li++)
        free(sil[li].s);
    free(sil);
    free(first);
    free(uses.uses);
    if (status == 0) {
        sv->planes = big_malloc(sizeof *sv->planes * (size_t)(sv->npolygons > 0 ? sv->npolygons : 1));
        if (!sv->planes)
            status = -1;
        for (int i = 0; status == 0 && i < sv->npolygons; i++)
            sv->planes[i] = (ShadowPlane){ sv->polygons[i].normal, sv->polygons[i].d };
    }
    if (status) {
        shadow_volumes_free(sv);
        return -1;
    }
    return 0;
}

int shadow_volumes_build(ShadowVolumes *sv, const World *w, const Grid *g, const Vec3 *eye, int threads,
                         const int8_t *want)
{
    return build_volumes(sv, w, g, eye, threads, want, 0);
}

int shadow_volumes_build_plain(ShadowVolumes *sv, const World *w, const Grid *g, const Vec3 *eye, int threads,
                               const int8_t *want)
{
    return build_volumes(sv, w, g, eye, threads, want, 1);
}

void shadow_volumes_free(ShadowVolumes *sv)
{
    if (sv->light) {
        for (int i = 0; i < sv->nlights; i++) {
            cell_lists_free(&sv->light[i].cells);
            free(sv->light[i].occluder);
        }
    }
    free(sv->light);
    free(sv->polygons);
    free(sv->planes);
    free(sv->planes_f);
    memset(sv, 0, sizeof *sv);
}

void shadow_volumes_drop_light(ShadowVolumes *sv, int li)
{
    LightVolumes *lv = &sv->light[li];
    cell_lists_free(&lv->cells);
    free(lv->occluder);
    lv->occluder = NULL;
    lv->nitems = 0;
    lv->usable = 0;
    lv->dropped = 1;
}

int shadow_volumes_usable_lights(const ShadowVolumes *sv)
{
    int n = 0;
    for (int i = 0; i < sv->nlights; i++)
        n += sv->light[i].usable;
    return n;
}

/* ---- what a build would cost ---------------------------------------------- */

/* The polygons [first, first + n) of w as a world of their own: their
 * points (and outlines) copied and renumbered, everything else shared. */
static int sample_world(World *s, const World *w, int first, int n)
{
    *s = *w;
    s->npolygons = n;
    s->polygons = malloc(sizeof *s->polygons * (size_t)(n > 0 ? n : 1));
    int npts = 0, nstarts = 0;
    for (int i = first; i < first + n; i++) {
        npts += w->polygons[i].npoints;
        if (w->polygons[i].first_outline >= 0)
            nstarts += w->polygons[i].noutlines + 1;
    }
    s->points = malloc(sizeof *s->points * (size_t)(npts > 0 ? npts : 1));
    s->outline_start = malloc(sizeof *s->outline_start * (size_t)(nstarts > 0 ? nstarts : 1));
    s->outline_box = w->outline_box ? malloc(sizeof *s->outline_box * (size_t)(nstarts > 0 ? nstarts : 1)) : NULL;
    if (!s->polygons || !s->points || !s->outline_start || (w->outline_box && !s->outline_box))
        return -1;
    s->npoints = npts;
    s->noutline_starts = nstarts;
    int pt = 0, st = 0;
    for (int i = 0; i < n; i++) {
        Polygon p = w->polygons[first + i];
        memcpy(&s->points[pt], &w->points[p.first_point], sizeof *s->points * (size_t)p.npoints);
        if (p.first_outline >= 0) {
            for (int k = 0; k <= p.noutlines; k++) {
                s->outline_start[st + k] = w->outline_start[p.first_outline + k] - p.first_point + pt;
                if (s->outline_box && k < p.noutlines && polygon_has_outline_boxes(p.noutlines, p.npoints))
                    s->outline_box[st + k] = w->outline_box[p.first_outline + k];
            }
            p.first_outline = st;
            st += p.noutlines + 1;
        }
        p.first_point = pt;
        pt += p.npoints;
        s->polygons[i] = p;
    }
    return 0;
}

static void sample_world_free(World *s)
{
    free(s->polygons);
    free(s->points);
    free(s->outline_start);
    free(s->outline_box);
}

/* The fastest of a few timings: on a shared machine a timing can only be
 * slowed down, never sped up. */
#define ESTIMATE_ROUNDS 2

int shadow_volumes_estimate(const World *w, const Grid *g, const Vec3 *eye, const int8_t *want, int sample,
                            VolumesEstimate *est)
{
    memset(est, 0, sizeof *est);
    est->light_seconds = calloc((size_t)(w->nlights > 0 ? w->nlights : 1), sizeof *est->light_seconds);
    est->light_registrations = calloc((size_t)(w->nlights > 0 ? w->nlights : 1), sizeof *est->light_registrations);
    if (!est->light_seconds || !est->light_registrations)
        return -1;
    if (w->npolygons == 0)
        return 0;
    /* A run of consecutive polygons from the middle: a mesh's neighbours
     * are mostly neighbours in its list too, so the sample keeps most of
     * its edges shared, as the whole does. (Its cut edges become
     * silhouettes: if anything, the estimate is high.) */
    int n = sample < w->npolygons ? sample : w->npolygons;
    int first = (w->npolygons - n) / 2;
    World s;
    int status = sample_world(&s, w, first, n);
    long total_points = 0;
    for (int i = 0; i < w->npolygons; i++)
        total_points += w->polygons[i].npoints;
    est->sample_polygons = n;
    est->scale = s.npoints > 0 ? (double)total_points / (double)s.npoints : 1.0;
    int maxpts = 3;
    for (int i = 0; i < s.npolygons; i++)
        if (s.polygons[i].npoints + 3 > maxpts)
            maxpts = s.polygons[i].npoints + 3;
    PolygonEdge *edges = status == 0 ? malloc(sizeof *edges * (size_t)maxpts) : NULL;
    if (!edges)
        status = -1;
    ShadowVolumes sv;
    memset(&sv, 0, sizeof sv);
    sv.tolerance = grid_tolerance(g);
    LightVolumes lv;
    /* The shared part: welding and the edges' uses. */
    EdgeUses uses = { NULL, 0 };
    est->shared_seconds = HUGE_VAL;
    for (int round = 0; status == 0 && round < ESTIMATE_ROUNDS; round++) {
        free(uses.uses);
        uses.uses = NULL;
        double t0 = clock_thread_cpu();
        int nclasses = 0;
        int *weld = weld_points(&s, &nclasses);
        status = weld && edge_uses_build(&uses, &s, weld, nclasses, edges) == 0 ? 0 : -1;
        free(weld);
        est->shared_seconds = fmin(est->shared_seconds, (clock_thread_cpu() - t0) * est->scale);
    }
    /* Each wanted light's silhouettes and registrations on the sample. */
    RegList regs = { NULL, 0, 0 };
    for (int li = 0; status == 0 && li < w->nlights; li++) {
        int cuts;
        if (!light_can_have_volumes(w, g, li, sv.tolerance, &cuts) || (want && !want[li]))
            continue;
        double best = HUGE_VAL;
        for (int round = 0; status == 0 && round < ESTIMATE_ROUNDS; round++) {
            memset(&lv, 0, sizeof lv);
            ShadowPolygon *polygons = NULL;
            int npolygons = 0;
            double t0 = clock_thread_cpu();
            status = build_light(&sv, &lv, &s, g, &w->lights[li], &uses, eye, edges, &regs, &polygons, &npolygons, 0);
            best = fmin(best, clock_thread_cpu() - t0);
            est->light_registrations[li] = (double)lv.nitems * est->scale;
            free(lv.occluder);
            free(polygons);
        }
        est->light_seconds[li] = best * est->scale;
    }
    free(regs.r);
    /* Filling a light's cells: its offsets span the whole grid, whatever
     * the sample (its occupancy masks), so that part is timed at full size
     * (with no items). */
    est->fill_seconds = HUGE_VAL;
    for (int round = 0; status == 0 && round < ESTIMATE_ROUNDS; round++) {
        memset(&lv, 0, sizeof lv);
        RegList none = { NULL, 0, 0 };
        double t0 = clock_thread_cpu();
        status = fill_cells(&lv, g, &none);
        est->fill_seconds = fmin(est->fill_seconds, clock_thread_cpu() - t0);
        cell_lists_free(&lv.cells);
    }
    for (int li = 0; status == 0 && li < w->nlights; li++)
        if (est->light_seconds[li] > 0.0)
            est->light_seconds[li] += est->fill_seconds;
    /* The polygons' registration, if the volumes would be the first to
     * need it: the sample's, scaled, and one fill of the grid's offsets
     * (the same work as a light's). */
    if (status == 0 && !grid_registered(g) && est->fill_seconds < HUGE_VAL) {
        double best = HUGE_VAL;
        for (int round = 0; status == 0 && round < ESTIMATE_ROUNDS; round++) {
            double t0 = clock_thread_cpu();
            status = grid_count_registrations(g, &s) < 0 ? -1 : 0;
            best = fmin(best, clock_thread_cpu() - t0);
        }
        if (status == 0) {
            est->register_seconds = best * (double)w->npolygons / (double)n + est->fill_seconds;
            est->shared_seconds += est->register_seconds;
        }
    }
    free(uses.uses);
    free(edges);
    sample_world_free(&s);
    if (status) {
        shadow_volumes_estimate_free(est);
        return -1;
    }
    if (!(est->shared_seconds < HUGE_VAL))
        est->shared_seconds = 0.0;
    if (!(est->fill_seconds < HUGE_VAL))
        est->fill_seconds = 0.0;
    return 0;
}

void shadow_volumes_estimate_free(VolumesEstimate *est)
{
    free(est->light_seconds);
    free(est->light_registrations);
    est->light_seconds = NULL;
    est->light_registrations = NULL;
}

int shadow_volumes_set_precision(ShadowVolumes *sv, PlanePrecision p)
{
    sv->precision = p;
    if (p == PLANES_DOUBLE)
        return 0;
    if (!sv->planes_f) {
        sv->planes_f = big_malloc(sizeof *sv->planes_f * (size_t)(sv->npolygons > 0 ? sv->npolygons : 1));
        if (!sv->planes_f)
            return -1;
        for (int i = 0; i < sv->npolygons; i++) {
            const ShadowPlane *pl = &sv->planes[i];
            sv->planes_f[i] = (ShadowPlaneF){ (float)pl->normal.x, (float)pl->normal.y, (float)pl->normal.z, (float)pl->d };
        }
    }
    /* Rounding n, p and d to float and the four products and sums in float
     * moves a distance by at most about 8 units of float's last place of
     * |n|(|px| + |py| + |pz|) + |d| <= 3M + sqrt(3)M for points and planes
     * in the box (largest coordinate M): 16 units of 5M, to be safe. */
    double m = 0.0;
    const double c[6] = { sv->box_min.x, sv->box_min.y, sv->box_min.z, sv->box_max.x, sv->box_max.y, sv->box_max.z };
    for (int k = 0; k < 6; k++)
        m = fmax(m, fabs(c[k]));
    double margin = p == PLANES_FLOAT ? sv->tolerance + 16.0 * FLT_EPSILON * 5.0 * m : sv->tolerance;
    sv->float_margin = (float)margin;
    return 0;
}

/* The float rejection: both ends clearly on one side of plane i. */
static inline int float_same_side(const ShadowPlaneF *pl, const float a[3], const float b[3], float m)
{
    float s1 = pl->nx * a[0] + pl->ny * a[1] + pl->nz * a[2] - pl->d;
    float s2 = pl->nx * b[0] + pl->ny * b[1] + pl->nz * b[2] - pl->d;
    return (s1 > m && s2 > m) || (s1 < -m && s2 < -m);
}

int shadow_bucket_crossings(const ShadowVolumes *sv, const uint32_t *bucket, int n, Vec3 p1, Vec3 p2, int *opaque,
                            int *transparent)
{
    double tol = sv->tolerance;
    int use_float = sv->precision != PLANES_DOUBLE;
    const float a[3] = { (float)p1.x, (float)p1.y, (float)p1.z }, b[3] = { (float)p2.x, (float)p2.y, (float)p2.z };
    for (int i = 0; i < n; i++) {
        /* Both ends clearly on one side of the plane: no crossing. The
         * float test only rejects; what it lets through is decided in
         * double, as without it. */
        if (use_float && float_same_side(&sv->planes_f[bucket[i]], a, b, sv->float_margin))
            continue;
        const ShadowPlane *pl = &sv->planes[bucket[i]];
        double s1 = v3_dot(pl->normal, p1) - pl->d, s2 = v3_dot(pl->normal, p2) - pl->d;
        if ((s1 > tol && s2 > tol) || (s1 < -tol && s2 < -tol))
            continue;
        const ShadowPolygon *sp = &sv->polygons[bucket[i]];
        int sign = 0;
        CrossResult r = shadow_polygon_cross_sides(sp, p1, p2, s1, s2, tol, &sign);
        if (r == CROSS_UNSURE)
            return 0;
        if (r == CROSS_YES) {
            *opaque += sign * sp->weight_opaque;
            *transparent += sign * sp->weight_transparent;
        }
    }
    return 1;
}
