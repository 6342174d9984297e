/* Grid registration against overlap tests written here, sharing no code
 * with src/grid.c, and the 3DDDA walk against brute force.
 *
 * What "overlap" has to mean for the walk to stay exact. trace_nearest
 * stops in a cell once its best hit is no later than the cell's exit, and
 * the shadow ray tests only the polygons listed in the cells it walks.
 * Rounding decides which of two neighbouring cells a point on their shared
 * face falls in (grid_walk_begin's floor, grid_walk_next's comparison of
 * t), so a polygon must be listed in every cell whose CLOSED box meets the
 * CLOSED polygon: touching a face, an edge or a corner counts, and a
 * polygon lying in a cell face is listed on both sides. A hole is open (its
 * outline belongs to the polygon). Listing a polygon in more cells costs
 * time only; those extra registrations are counted and reported. Listing it
 * in fewer is a correctness bug: a ray could pass the polygon unseen.
 * Cell k of an axis spans [min + k*size, min + (k+1)*size], computed as
 * the walk computes it.
 *
 * The references:
 * - triangles: separating axes (the box's 3, the triangle's normal, the 9
 *   products of an edge and a box axis), in long double;
 * - polygons with outlines (concave, several, holes by even-odd): an
 *   outline edge meets the box (slabs), or else a point of the box's
 *   section by the polygon's plane lies inside (crossing number);
 *   both against the cell grown by DELTA_ULPS long-double ulps of the
 *   scene's size, so that exact touching is never lost to rounding, and
 *   shrunk by as much to tell "enters the cell" from "touches its border";
 * - sampling: the vertices, points on the edges and random points inside
 *   each polygon; every cell whose closed box holds the point (2, 4 or 8 on
 *   a face, edge or corner) must list the polygon;
 * - by hand: polygons placed to touch cells exactly at a face, an edge or a
 *   corner, and a hole whose outline runs along cell faces, with the cells
 *   they touch and enter written out;
 * on random polygons (fixed seed), at three resolutions, and on every
 * scene of scenes/ and scenes/hard/ built as hstrace builds it.
 * An extra registration is one no reference asks for, even with the cell
 * grown by twice grid_build's own margin (1e-9 of a cell); triangles must
 * have none (grid.h: "registered in exactly the cells it overlaps"), holes
 * and long outlines may. (These checks found that a polygon whose box
 * started exactly on a cell boundary could be left out of the cell below
 * it, which it touches: grid_build took the candidate cells from the bare
 * box.) */
#include <dirent.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cell_lists.h"
#include "fixtures.h"
#include "grid.h"
#include "image.h"
#include "intersect.h"
#include "parser.h"
#include "tap.h"
#include "tracer.h"

typedef long double ld;
typedef struct { ld x, y, z; } LVec;

static LVec lvec(Vec3 v) { LVec r = { v.x, v.y, v.z }; return r; }
static LVec lsub(LVec a, LVec b) { LVec r = { a.x - b.x, a.y - b.y, a.z - b.z }; return r; }
static LVec lcross(LVec a, LVec b)
{
    LVec r = { a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x };
    return r;
}
static ld ldot(LVec a, LVec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static ld lcomp(LVec a, int k) { return k == 0 ? a.x : k == 1 ? a.y : a.z; }

#define DELTA_ULPS 64

/* ---- the polygon as the world stores it (read here, not through src/) ---- */

typedef struct {
    int noutlines;
    const Vec3 *points; /* triangle: its 3 points; else the world's points */
    const int *start;   /* outline k: points[start[k]] .. points[start[k + 1] - 1]; NULL: a triangle */
    int triangle;
} Outlines;

static void shape_of(const World *w, const Polygon *p, Outlines *s)
{
    s->triangle = p->first_outline < 0;
    s->noutlines = s->triangle ? 1 : p->noutlines;
    s->points = s->triangle ? &w->points[p->first_point] : w->points;
    s->start = s->triangle ? NULL : &w->outline_start[p->first_outline];
}

static int outline_n(const Outlines *s, int k) { return s->start ? s->start[k + 1] - s->start[k] : 3; }
static Vec3 outline_pt(const Outlines *s, int k, int i)
{
    return s->start ? s->points[s->start[k] + i % outline_n(s, k)] : s->points[i % 3];
}

/* ---- reference 1: separating axes, triangle against a closed box ---------- */

static int sat_separates(const LVec v[3], LVec axis, LVec half)
{
    ld r = half.x * fabsl(axis.x) + half.y * fabsl(axis.y) + half.z * fabsl(axis.z);
    ld lo = ldot(v[0], axis), hi = lo;
    for (int i = 1; i < 3; i++) {
        ld p = ldot(v[i], axis);
        lo = p < lo ? p : lo;
        hi = p > hi ? p : hi;
    }
    return lo > r || hi < -r; /* strictly apart: touching is overlap */
}

static int triangle_meets_box(const Vec3 *t, LVec lo, LVec hi)
{
    LVec c = { (lo.x + hi.x) / 2, (lo.y + hi.y) / 2, (lo.z + hi.z) / 2 };
    LVec half = lsub(hi, c);
    LVec v[3];
    for (int i = 0; i < 3; i++)
        v[i] = lsub(lvec(t[i]), c);
    static const LVec axes[3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
    for (int k = 0; k < 3; k++)
        if (sat_separates(v, axes[k], half))
            return 0;
    LVec e[3] = { lsub(v[1], v[0]), lsub(v[2], v[1]), lsub(v[0], v[2]) };
    if (sat_separates(v, lcross(e[0], e[1]), half))
        return 0;
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
            if (sat_separates(v, lcross(e[i], axes[k]), half))
                return 0;
    return 1;
}

/* ---- reference 2: outlines (even-odd) against a closed box ----------------- */

static int segment_meets_box(LVec a, LVec b, LVec lo, LVec hi)
{
    ld t0 = 0, t1 = 1;
    for (int k = 0; k < 3; k++) {
        ld o = lcomp(a, k), d = lcomp(b, k) - o, l = lcomp(lo, k), h = lcomp(hi, k);
        if (d == 0) {
            if (o < l || o > h)
                return 0;
            continue;
        }
        ld ta = (l - o) / d, tb = (h - o) / d;
        if (ta > tb) { ld s = ta; ta = tb; tb = s; }
        t0 = ta > t0 ? ta : t0;
        t1 = tb < t1 ? tb : t1;
        if (t0 > t1)
            return 0;
    }
    return 1;
}

static LVec newell_normal(const Outlines *s)
{
    LVec n = { 0, 0, 0 };
    for (int k = 0; k < s->noutlines; k++)
        for (int i = 0; i < outline_n(s, k); i++) {
            LVec p = lvec(outline_pt(s, k, i)), q = lvec(outline_pt(s, k, i + 1));
            n.x += (p.y - q.y) * (p.z + q.z);
            n.y += (p.z - q.z) * (p.x + q.x);
            n.z += (p.x - q.x) * (p.y + q.y);
        }
    return n;
}

static int dominant_axis(LVec n)
{
    ld ax = fabsl(n.x), ay = fabsl(n.y), az = fabsl(n.z);
    return ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
}

/* Even-odd over every outline, in the plane of the two axes other than `drop`. */
static int inside_even_odd(const Outlines *s, int drop, ld qu, ld qv)
{
    int iu = (drop + 1) % 3, iv = (drop + 2) % 3, inside = 0;
    for (int k = 0; k < s->noutlines; k++)
        for (int i = 0; i < outline_n(s, k); i++) {
            LVec p = lvec(outline_pt(s, k, i)), q = lvec(outline_pt(s, k, i + 1));
            ld pu = lcomp(p, iu), pv = lcomp(p, iv), uq = lcomp(q, iu), vq = lcomp(q, iv);
            if ((pv > qv) != (vq > qv) && qu < pu + (qv - pv) * (uq - pu) / (vq - pv))
                inside = !inside;
        }
    return inside;
}

static int outlines_meet_box(const Outlines *s, LVec lo, LVec hi)
{
    for (int k = 0; k < s->noutlines; k++)
        for (int i = 0; i < outline_n(s, k); i++)
            if (segment_meets_box(lvec(outline_pt(s, k, i)), lvec(outline_pt(s, k, i + 1)), lo, hi))
                return 1;
    /* No edge meets the box, so its section by the plane lies wholly inside
     * the polygon or wholly outside: one point of the section decides. */
    LVec n = newell_normal(s), c = { 0, 0, 0 };
    int np = 0;
    for (int k = 0; k < s->noutlines; k++)
        for (int i = 0; i < outline_n(s, k); i++, np++) {
            c.x += outline_pt(s, k, i).x;
            c.y += outline_pt(s, k, i).y;
            c.z += outline_pt(s, k, i).z;
        }
    ld d = (n.x * c.x + n.y * c.y + n.z * c.z) / np;
    LVec corner[8];
    ld dist[8];
    for (int i = 0; i < 8; i++) {
        corner[i].x = i & 1 ? hi.x : lo.x;
        corner[i].y = i & 2 ? hi.y : lo.y;
        corner[i].z = i & 4 ? hi.z : lo.z;
        dist[i] = ldot(n, corner[i]) - d;
    }
    LVec x = { 0, 0, 0 };
    int nx = 0;
    for (int i = 0; i < 8; i++)
        for (int bit = 1; bit < 8; bit <<= 1) {
            int j = i | bit;
            if (j == i)
                continue; /* each of the 12 edges once, from its lower corner */
            if ((dist[i] <= 0) != (dist[j] <= 0) || dist[i] == 0) {
                ld t = dist[i] == dist[j] ? 0 : dist[i] / (dist[i] - dist[j]);
                x.x += corner[i].x + (corner[j].x - corner[i].x) * t;
                x.y += corner[i].y + (corner[j].y - corner[i].y) * t;
                x.z += corner[i].z + (corner[j].z - corner[i].z) * t;
                nx++;
            }
        }
    if (dist[7] == 0) {
        x.x += corner[7].x; x.y += corner[7].y; x.z += corner[7].z;
        nx++;
    }
    if (nx == 0)
        return 0; /* the plane misses the box */
    int drop = dominant_axis(n);
    return inside_even_odd(s, drop, lcomp(x, (drop + 1) % 3) / nx, lcomp(x, (drop + 2) % 3) / nx);
}

/* The reference: does polygon p meet the cell box grown by `grow` per axis? */
static int reference_overlap(const World *w, const Polygon *p, Vec3 lo, Vec3 hi, const ld grow[3])
{
    Outlines s;
    shape_of(w, p, &s);
    LVec l = { lo.x - grow[0], lo.y - grow[1], lo.z - grow[2] }, h = { hi.x + grow[0], hi.y + grow[1], hi.z + grow[2] };
    return s.triangle ? triangle_meets_box(s.points, l, h) : outlines_meet_box(&s, l, h);
}

/* ---- registrations, read back from the grid ------------------------------ */

typedef struct {
    uint32_t polygon, cell;
} Pair;

static int pair_cmp(const void *a, const void *b)
{
    const Pair *x = a, *y = b;
    return x->polygon != y->polygon ? (x->polygon < y->polygon ? -1 : 1) : x->cell < y->cell ? -1 : x->cell > y->cell;
}

typedef struct {
    Pair *pairs;
    size_t n;
    size_t *first; /* per polygon, into pairs; npolygons + 1 */
    int bad_index; /* registrations naming no polygon or no cell */
} Registrations;

static void registrations_read(Registrations *r, const Grid *g, int npolygons)
{
    r->n = g->cell_start[g->ncells];
    r->pairs = malloc((r->n ? r->n : 1) * sizeof *r->pairs);
    r->first = calloc((size_t)npolygons + 2, sizeof *r->first);
    r->bad_index = 0;
    size_t m = 0;
    for (int c = 0; c < g->ncells; c++)
        for (uint32_t k = g->cell_start[c]; k < g->cell_start[c + 1]; k++) {
            if (g->items[k] >= (uint32_t)npolygons) {
                r->bad_index++;
                continue;
            }
            r->pairs[m].polygon = g->items[k];
            r->pairs[m++].cell = (uint32_t)c;
        }
    r->n = m;
    qsort(r->pairs, r->n, sizeof *r->pairs, pair_cmp);
    for (size_t i = 0; i < r->n; i++)
        r->first[r->pairs[i].polygon + 1]++;
    for (int p = 0; p < npolygons; p++)
        r->first[p + 1] += r->first[p];
}

static void registrations_free(Registrations *r)
{
    free(r->pairs);
    free(r->first);
}

static int cell_of(const Grid *g, int x, int y, int z) { return (z * g->n[1] + y) * g->n[0] + x; }

/* The walk's boundary k on axis a. */
static double boundary(const Grid *g, int a, int k) { return v3_comp(g->min, a) + k * v3_comp(g->cell_size, a); }

/* Cells k of axis a whose closed span holds x: *k0 .. *k1 (empty when k1 < k0). */
static void cells_holding(const Grid *g, int a, double x0, double x1, int *k0, int *k1)
{
    *k0 = g->n[a];
    *k1 = -1;
    /* A guess, then the boundaries themselves decide. */
    double guess = floor((x0 - v3_comp(g->min, a)) / v3_comp(g->cell_size, a)) - 2;
    int start = guess < 0 ? 0 : guess > g->n[a] ? g->n[a] : (int)guess;
    for (int k = start; k < g->n[a] && boundary(g, a, k) <= x1; k++)
        if (x0 <= boundary(g, a, k + 1)) {
            if (k < *k0) *k0 = k;
            *k1 = k;
        }
}

/* ---- the whole check of one grid ------------------------------------------ */

typedef struct {
    long checked;      /* polygon/cell pairs the references looked at */
    long missing;      /* the polygon enters the cell's interior; the cell does not list it */
    long touching;     /* the polygon touches the closed cell only on its border; not listed */
    long sampled, orphans; /* sampled points; points no cell holding them lists the polygon for */
    long sampled_missing, sampled_touching; /* (point, cell holding it) not listed: as above */
    long extra_triangle, extra_outline; /* listed, no reference asks for it */
    long margin;       /* listed for touching within grid_build's margin only */
    long registrations;
    int bad_index;
    char first_missing[200], first_touching[200];
} Tally;

static void note(char *first, size_t size, const char *what, int p, int x, int y, int z)
{
    if (!first[0])
        snprintf(first, size, "%s: polygon %d not in cell (%d, %d, %d)", what, p, x, y, z);
}

typedef struct {
    const World *w;
    const Grid *g;
    int polygon;
    const unsigned char *listed;
    ld delta[3], shrink[3], wide[3];
    const char *what;
} Check;

static Vec3 cell_lo(const Grid *g, int x, int y, int z)
{
    return v3(boundary(g, 0, x), boundary(g, 1, y), boundary(g, 2, z));
}
static Vec3 cell_hi(const Grid *g, int x, int y, int z)
{
    return v3(boundary(g, 0, x + 1), boundary(g, 1, y + 1), boundary(g, 2, z + 1));
}

static void sample_point(const Check *c, Vec3 q, Tally *t)
{
    int k0[3], k1[3], holders = 0, listing = 0;
    for (int a = 0; a < 3; a++)
        cells_holding(c->g, a, v3_comp(q, a), v3_comp(q, a), &k0[a], &k1[a]);
    for (int z = k0[2]; z <= k1[2]; z++)
        for (int y = k0[1]; y <= k1[1]; y++)
            for (int x = k0[0]; x <= k1[0]; x++) {
                t->sampled++;
                holders++;
                if (c->listed[cell_of(c->g, x, y, z)]) {
                    listing++;
                    continue;
                }
                /* On a border of this cell: is the cell entered elsewhere? */
                const Polygon *p = &c->w->polygons[c->polygon];
                if (reference_overlap(c->w, p, cell_lo(c->g, x, y, z), cell_hi(c->g, x, y, z), c->shrink)) {
                    t->sampled_missing++;
                    note(t->first_missing, sizeof t->first_missing, c->what, c->polygon, x, y, z);
                } else {
                    t->sampled_touching++;
                }
            }
    if (holders > 0 && listing == 0)
        t->orphans++;
}

static void sample_polygon(const Check *c, TestRng *rng, Tally *t)
{
    Outlines s;
    shape_of(c->w, &c->w->polygons[c->polygon], &s);
    Vec3 lo = outline_pt(&s, 0, 0), hi = lo;
    for (int k = 0; k < s.noutlines; k++)
        for (int i = 0; i < outline_n(&s, k); i++) {
            Vec3 a = outline_pt(&s, k, i), b = outline_pt(&s, k, i + 1);
            lo = v3_min(lo, a);
            hi = v3_max(hi, a);
            sample_point(c, a, t);
            for (int j = 1; j < 4; j++)
                sample_point(c, v3_add(a, v3_scale(v3_sub(b, a), j / 4.0)), t);
        }
    if (s.triangle) {
        const Vec3 *v = s.points;
        for (int k = 0; k < 16; k++) {
            double a = rng_uniform(rng), b = rng_uniform(rng);
            if (a + b > 1) { a = 1 - a; b = 1 - b; }
            sample_point(c, v3_add(v[0], v3_add(v3_scale(v3_sub(v[1], v[0]), a), v3_scale(v3_sub(v[2], v[0]), b))), t);
        }
        return;
    }
    /* Inside points of outlines: random in the box, kept when inside, lifted to the plane. */
    LVec n = newell_normal(&s);
    int drop = dominant_axis(n), iu = (drop + 1) % 3, iv = (drop + 2) % 3;
    Vec3 p0 = outline_pt(&s, 0, 0);
    for (int tries = 0, got = 0; tries < 200 && got < 16; tries++) {
        double x[3];
        x[iu] = rng_range(rng, v3_comp(lo, iu), v3_comp(hi, iu));
        x[iv] = rng_range(rng, v3_comp(lo, iv), v3_comp(hi, iv));
        if (!inside_even_odd(&s, drop, x[iu], x[iv]))
            continue;
        /* n . (x - p0) = 0 */
        x[drop] = (double)(lcomp(lvec(p0), drop) -
                           (lcomp(n, iu) * (x[iu] - v3_comp(p0, iu)) + lcomp(n, iv) * (x[iv] - v3_comp(p0, iv))) /
                               lcomp(n, drop));
        sample_point(c, v3(x[0], x[1], x[2]), t);
        got++;
    }
}

static ld scene_ulps(const Grid *g)
{
    double m = fmax(fmax(fabs(g->min.x), fabs(g->max.x)),
                    fmax(fmax(fabs(g->min.y), fabs(g->max.y)), fmax(fabs(g->min.z), fabs(g->max.z))));
    return DELTA_ULPS * LDBL_EPSILON * (1 + (ld)m);
}

static void check_grid(const World *w, const Grid *g, TestRng *rng, const char *what, Tally *t)
{
    Registrations r;
    registrations_read(&r, g, w->npolygons);
    t->registrations += (long)r.n;
    t->bad_index += r.bad_index;
    unsigned char *listed = calloc((size_t)g->ncells, 1);
    Check c = { w, g, 0, listed, { 0 }, { 0 }, { 0 }, what };
    for (int a = 0; a < 3; a++) {
        c.delta[a] = scene_ulps(g);
        c.shrink[a] = -c.delta[a];
        c.wide[a] = 2e-9L * v3_comp(g->cell_size, a) + c.delta[a];
    }
    for (int pi = 0; pi < w->npolygons; pi++) {
        const Polygon *p = &w->polygons[pi];
        c.polygon = pi;
        for (size_t i = r.first[pi]; i < r.first[pi + 1]; i++)
            listed[r.pairs[i].cell] = 1;
        /* Every cell near the polygon's own box (from its points). */
        Outlines s;
        shape_of(w, p, &s);
        Vec3 lo = outline_pt(&s, 0, 0), hi = lo;
        for (int k = 0; k < s.noutlines; k++)
            for (int i = 0; i < outline_n(&s, k); i++) {
                lo = v3_min(lo, outline_pt(&s, k, i));
                hi = v3_max(hi, outline_pt(&s, k, i));
            }
        int k0[3], k1[3];
        for (int a = 0; a < 3; a++)
            cells_holding(g, a, v3_comp(lo, a) - (double)c.wide[a], v3_comp(hi, a) + (double)c.wide[a], &k0[a], &k1[a]);
        for (int z = k0[2]; z <= k1[2]; z++)
            for (int y = k0[1]; y <= k1[1]; y++)
                for (int x = k0[0]; x <= k1[0]; x++) {
                    Vec3 clo = cell_lo(g, x, y, z), chi = cell_hi(g, x, y, z);
                    int is = listed[cell_of(g, x, y, z)];
                    t->checked++;
                    if (reference_overlap(w, p, clo, chi, c.delta)) {
                        if (is)
                            continue;
                        if (reference_overlap(w, p, clo, chi, c.shrink)) {
                            t->missing++;
                            note(t->first_missing, sizeof t->first_missing, what, pi, x, y, z);
                        } else {
                            t->touching++;
                            note(t->first_touching, sizeof t->first_touching, what, pi, x, y, z);
                        }
                    } else if (is) {
                        if (reference_overlap(w, p, clo, chi, c.wide))
                            t->margin++;
                        else if (s.triangle)
                            t->extra_triangle++;
                        else
                            t->extra_outline++;
                    }
                }
        sample_polygon(&c, rng, t);
        for (size_t i = r.first[pi]; i < r.first[pi + 1]; i++)
            listed[r.pairs[i].cell] = 0;
    }
    free(listed);
    registrations_free(&r);
}

static void report(const char *what, const Tally *t)
{
    tap_ok(t->checked > 0 && t->missing == 0 && t->bad_index == 0,
           "%s: every polygon is listed in every cell whose interior it enters, by the separating-axis and outline "
           "tests (%ld missing of %ld polygon/cell pairs)%s%s",
           what, t->missing, t->checked, t->missing ? "; first: " : "", t->first_missing);
    tap_ok(t->sampled > 0 && t->orphans == 0 && t->sampled_missing == 0,
           "%s: every sampled point of a polygon (vertex, edge, inside) lies in a cell listing it (%ld orphans), and "
           "every cell it lies in that the polygon enters lists it (%ld missing of %ld)",
           what, t->orphans, t->sampled_missing, t->sampled);
    char line[600];
    snprintf(line, sizeof line,
             "%s: every polygon is listed in every cell it touches only on the cell's border (face, edge, corner) "
             "(%ld missing by the references, %ld by sampled points)%s%s",
             what, t->touching, t->sampled_touching, t->touching ? "; first: " : "", t->first_touching);
    tap_ok(t->touching == 0 && t->sampled_touching == 0, "%s", line);
    tap_ok(t->extra_triangle == 0,
           "%s: no triangle is listed in a cell it does not meet (%ld extra; %ld listings within grid_build's margin)",
           what, t->extra_triangle, t->margin);
    tap_diag("%s: %ld registrations, %ld of polygons with outlines in cells they do not meet (holes, long outlines)",
             what, t->registrations, t->extra_outline);
}

/* ---- scenes ---------------------------------------------------------------- */

/* A star-shaped outline of n points around c in the plane spanned by u, v. */
static int star(TestRng *rng, Vec3 c, Vec3 u, Vec3 v, double r0, double r1, int n, double phase, Vec3 *out)
{
    for (int i = 0; i < n; i++) {
        double a = phase + 2 * M_PI * i / n, r = rng_range(rng, r0, r1);
        out[i] = v3_add(c, v3_add(v3_scale(u, r * cos(a)), v3_scale(v, r * sin(a))));
    }
    out[n] = out[0];
    return n + 1;
}

static void add_random_outlines(Scene *s, TestRng *rng, int count)
{
    for (int i = 0; i < count; i++) {
        Vec3 c = v3(rng_range(rng, -8, 8), rng_range(rng, -8, 8), rng_range(rng, -8, 8));
        Vec3 u = v3_normalize(v3(rng_range(rng, -1, 1), rng_range(rng, -1, 1), rng_range(rng, -1, 1)));
        Vec3 v = v3_normalize(v3_cross(u, v3(rng_range(rng, -1, 1), rng_range(rng, -1, 1), rng_range(rng, -1, 1))));
        if (i % 4 == 0) { /* some in axis planes */
            u = v3(1, 0, 0);
            v = v3(0, i % 8 ? 1 : 0, i % 8 ? 0 : 1);
        }
        Vec3 pts[64];
        int starts[4] = { 0 }, no = 0, m = 0;
        double R = rng_range(rng, 0.5, 5);
        /* an outer star (concave), then up to two holes inside it */
        m += star(rng, c, u, v, 0.6 * R, R, 5 + i % 9, 0, pts);
        starts[++no] = m;
        for (int h = 0; h < i % 3; h++) {
            Vec3 hc = v3_add(c, v3_scale(u, (h ? -0.3 : 0.25) * R));
            m += star(rng, hc, u, v, 0.1 * R, 0.2 * R, 4 + h, 0.3, pts + m);
            starts[++no] = m;
        }
        fixture_polygon(s, pts, m, starts, no);
    }
}

static void random_triangles(Scene *s, TestRng *rng, int count)
{
    for (int i = 0; i < count; i++) {
        Vec3 c = v3(rng_range(rng, -10, 10), rng_range(rng, -10, 10), rng_range(rng, -10, 10));
        double r = rng_range(rng, 0.2, 3.0);
        fixture_triangle(s, v3_add(c, v3(rng_range(rng, -r, r), rng_range(rng, -r, r), rng_range(rng, -r, r))),
                         v3_add(c, v3(rng_range(rng, -r, r), rng_range(rng, -r, r), rng_range(rng, -r, r))),
                         v3_add(c, v3(rng_range(rng, -r, r), rng_range(rng, -r, r), rng_range(rng, -r, r))));
    }
}

static int build(const Scene *s, World *w, Grid *g, const int *res, int extra_points)
{
    WorldError err;
    if (world_build(w, s, &err))
        return -1;
    Vec3 extra[1 + 8 * 16];
    int nextra = extra_points ? grid_extra_points(w, extra, (int)(sizeof extra / sizeof extra[0])) : 0;
    if (grid_build(g, w, res, extra, nextra)) {
        world_free(w);
        return -1;
    }
    return 0;
}

/* The sparse per-cell lists the shadow volumes keep (cell_lists.h), against
 * dense offsets for every cell made here: random registrations over grids
 * whose cell counts are and are not multiples of 64, the first and the last
 * cell included, and none at all. */
static void sparse_cell_lists(TestRng *rng)
{
    static const int sizes[] = { 1, 64, 1000, 4096 * 3 + 17 };
    int bad = 0, lists = 0;
    for (int k = 0; k < 4; k++) {
        int ncells = sizes[k];
        for (int round = 0; round < 3; round++) {
            size_t n = round == 0 ? 0 : round == 1 ? 5 : (size_t)ncells * 2;
            uint32_t *pairs = malloc(sizeof(uint32_t) * 2 * (n ? n : 1));
            uint32_t *dense = calloc((size_t)ncells + 1, sizeof(uint32_t));
            if (!pairs || !dense) {
                free(pairs);
                free(dense);
                bad++;
                continue;
            }
            for (size_t i = 0; i < n; i++) {
                uint32_t c = (uint32_t)(rng_range(rng, 0, ncells) * 0.999999);
                if (i == 0)
                    c = 0;
                if (i == 1)
                    c = (uint32_t)ncells - 1;
                pairs[2 * i] = c;
                pairs[2 * i + 1] = (uint32_t)i;
                dense[c + 1]++;
            }
            for (int c = 0; c < ncells; c++)
                dense[c + 1] += dense[c];
            CellLists cl;
            if (cell_lists_build(&cl, ncells, &pairs[0], &pairs[1], 2 * sizeof(uint32_t), n)) {
                bad++;
            } else {
                /* cell by cell: the same length, and the items in registration order */
                for (int c = 0; c < ncells; c++) {
                    uint32_t b, e;
                    cell_lists_get(&cl, (uint32_t)c, &b, &e);
                    lists++;
                    if (e - b != dense[c + 1] - dense[c]) {
                        bad++;
                        continue;
                    }
                    uint32_t prev = 0;
                    for (uint32_t j = b; j < e; j++) {
                        uint32_t it = cl.items[j];
                        if (it >= n || pairs[2 * it] != (uint32_t)c || (j > b && it <= prev))
                            bad++;
                        prev = it;
                    }
                }
                if (cl.nitems != n)
                    bad++;
                cell_lists_free(&cl);
            }
            free(pairs);
            free(dense);
        }
    }
    tap_ok(bad == 0, "sparse cell lists: every cell's list as dense offsets give it (%d lists, %d wrong)", lists, bad);
}

/* grid_register on several threads: each takes a run of the polygons, and
 * the cells' lists must come out as one thread's, item for item, whatever
 * the count (60,000 triangles: enough that 2, 3 and 8 threads all start). */
static void registration_threads(TestRng *rng)
{
    Scene *s = fixture_scene(60000);
    random_triangles(s, rng, 60000);
    World w;
    WorldError err;
    if (world_build(&w, s, &err)) {
        tap_ok(0, "60,000 triangles build");
        fixture_scene_free(s);
        return;
    }
    Grid one;
    grid_build_box(&one, &w, NULL, NULL, 0);
    tap_ok(!grid_registered(&one), "grid_build_box registers nothing");
    tap_ok(grid_register(&one, &w, 1) == 0 && grid_registered(&one), "registered on 1 thread");
    static const int counts[] = { 2, 3, 8 };
    for (int k = 0; k < 3; k++) {
        Grid many;
        grid_build_box(&many, &w, NULL, NULL, 0);
        int ok = grid_register(&many, &w, counts[k]) == 0 && many.nitems == one.nitems &&
                 memcmp(many.cell_start, one.cell_start, sizeof(uint32_t) * ((size_t)one.ncells + 1)) == 0 &&
                 memcmp(many.items, one.items, sizeof(uint32_t) * one.nitems) == 0;
        tap_ok(ok, "registered on %d threads: the same %zu registrations, cell by cell, in the same order",
               counts[k], one.nitems);
        uint32_t *before = many.items;
        tap_ok(grid_register(&many, &w, counts[k]) == 0 && many.items == before, "registering again does nothing");
        grid_free(&many);
    }
    grid_free(&one);
    world_free(&w);
    fixture_scene_free(s);
}

/* Polygons placed on the cell boundaries of a known 8x8x8 grid, each with
 * the cells it touches and the cells it enters written out. */
typedef struct {
    const char *what;
    int lo[3], hi[3];   /* the cells it touches (closed boxes): lo..hi per axis */
    int elo[3], ehi[3]; /* the cells whose interior it enters; elo[0] < 0: none (it lies in a face) */
    int hole[3];        /* a cell of elo..ehi it does not enter after all; hole[0] < 0: none */
} Touching;

static void touching_cases(TestRng *rng)
{
    /* Two specks fix the grid box; the grid is built once to learn its boundaries. */
    Scene *s = fixture_scene(64);
    fixture_triangle(s, v3(-8, -8, -8), v3(-7.9, -8, -8), v3(-8, -7.9, -8));
    fixture_triangle(s, v3(8, 8, 8), v3(7.9, 8, 8), v3(8, 7.9, 8));
    int res[3] = { 8, 8, 8 };
    World w;
    Grid g;
    if (build(s, &w, &g, res, 0)) {
        tap_ok(0, "touching cases: grid builds");
        scene_free(s);
        return;
    }
    double b[3][9];
    for (int a = 0; a < 3; a++)
        for (int k = 0; k <= 8; k++)
            b[a][k] = boundary(&g, a, k);
    Vec3 gmin = g.min, gsize = g.cell_size;
    double q = 0.3 * gsize.x; /* a third of a cell, about */
    grid_free(&g);
    world_free(&w);
#define X(k) b[0][k]
#define Y(k) b[1][k]
#define Z(k) b[2][k]
    static Touching cases[16];
    int nc = 0;
    int starts[3];
    /* 1. A square lying in the face x = X(4): cells 3 and 4 in x. */
    {
        Vec3 sq[5] = { v3(X(4), Y(2) + q, Z(2) + q), v3(X(4), Y(3) - q, Z(2) + q), v3(X(4), Y(3) - q, Z(3) - q),
                       v3(X(4), Y(2) + q, Z(3) - q), v3(X(4), Y(2) + q, Z(2) + q) };
        starts[0] = 0; starts[1] = 5;
        fixture_polygon(s, sq, 5, starts, 1);
        cases[nc++] = (Touching){ "a square in a cell face", { 3, 2, 2 }, { 4, 2, 2 }, { -1 }, { -1 }, { -1 } };
    }
    /* 2. A triangle in the face y = Y(5), over two cells in x. */
    fixture_triangle(s, v3(X(1) + q, Y(5), Z(6) + q), v3(X(3) - q, Y(5), Z(6) + q), v3(X(2), Y(5), Z(7) - q));
    cases[nc++] = (Touching){ "a triangle in a cell face", { 1, 4, 6 }, { 2, 5, 6 }, { -1 }, { -1 }, { -1 } };
    /* 3. A triangle with an edge on the cell edge x = X(4), y = Y(4), leaning into x, y > 4:
     *    the four cells around that edge. */
    fixture_triangle(s, v3(X(4), Y(4), Z(1) + q), v3(X(4), Y(4), Z(2) - q), v3(X(4) + q, Y(4) + q, Z(1) + 2 * q));
    cases[nc++] = (Touching){ "a triangle touching a cell edge with its own edge", { 3, 3, 1 }, { 4, 4, 1 },
                              { 4, 4, 1 }, { 4, 4, 1 }, { -1 } };
    /* 4. A triangle with a vertex at the cell corner (X(5), Y(5), Z(5)), going into the
     *    positive octant: all 8 cells around that corner. */
    fixture_triangle(s, v3(X(5), Y(5), Z(5)), v3(X(5) + 2 * q, Y(5) + q, Z(5) + q),
                     v3(X(5) + q, Y(5) + 2 * q, Z(5) + 2 * q));
    cases[nc++] = (Touching){ "a triangle touching a cell corner with a vertex", { 4, 4, 4 }, { 5, 5, 5 }, { 5, 5, 5 },
                              { 5, 5, 5 }, { -1 } };
    /* 5. A triangle touching the face x = X(2) with one vertex, from below: cells 1 and 2. */
    fixture_triangle(s, v3(X(2), Y(6) + q, Z(2) + q), v3(X(2) - 2 * q, Y(6) + 2 * q, Z(2) + q),
                     v3(X(2) - q, Y(6) + q, Z(2) + 2 * q));
    cases[nc++] = (Touching){ "a triangle touching a cell face with a vertex", { 1, 6, 2 }, { 2, 6, 2 }, { 1, 6, 2 },
                              { 1, 6, 2 }, { -1 } };
    /* 6. A triangle touching the face z = Z(3) with an edge, from below: z cells 2 and 3. */
    fixture_triangle(s, v3(X(6) + q, Y(1) + q, Z(3)), v3(X(7) - q, Y(1) + q, Z(3)),
                     v3(X(6) + 2 * q, Y(2) - q, Z(3) - q));
    cases[nc++] = (Touching){ "a triangle touching a cell face with an edge", { 6, 1, 2 }, { 6, 1, 3 }, { 6, 1, 2 },
                              { 6, 1, 2 }, { -1 } };
    /* 7. A triangle touching the cell edge x = X(6), z = Z(6) with a vertex, from x, z < 6. */
    fixture_triangle(s, v3(X(6), Y(3) + q, Z(6)), v3(X(6) - q, Y(3) + 2 * q, Z(6) - 2 * q),
                     v3(X(6) - 2 * q, Y(3) + q, Z(6) - q));
    cases[nc++] = (Touching){ "a triangle touching a cell edge with a vertex", { 5, 3, 5 }, { 6, 3, 6 }, { 5, 3, 5 },
                              { 5, 3, 5 }, { -1 } };
    /* 8. A frame in the middle of z cell 6 whose square hole is exactly the x, y span of
     *    cell (2, 2): the hole's outline runs along that cell's side faces, so the cell
     *    touches the polygon (its hole is open) and must list it, as must its neighbours. */
    {
        double zm = Z(6) + 1.5 * q;
        Vec3 fr[10] = { v3(X(1) + q, Y(1) + q, zm), v3(X(4) - q, Y(1) + q, zm), v3(X(4) - q, Y(4) - q, zm),
                        v3(X(1) + q, Y(4) - q, zm), v3(X(1) + q, Y(1) + q, zm),
                        v3(X(2), Y(2), zm), v3(X(3), Y(2), zm), v3(X(3), Y(3), zm), v3(X(2), Y(3), zm),
                        v3(X(2), Y(2), zm) };
        starts[0] = 0; starts[1] = 5; starts[2] = 10;
        fixture_polygon(s, fr, 10, starts, 2);
        cases[nc++] = (Touching){ "a frame whose hole is bounded by cell faces", { 1, 1, 6 }, { 3, 3, 6 }, { 1, 1, 6 },
                                  { 3, 3, 6 }, { 2, 2, 6 } };
    }
    /* 9. A triangle in the face plane x = X(3) and also touching the cell edge y = Y(7)
     *    with its own edge: cells x 2, 3 and y 6, 7. */
    fixture_triangle(s, v3(X(3), Y(7), Z(4) + q), v3(X(3), Y(7), Z(5) - q), v3(X(3), Y(7) - q, Z(4) + 2 * q));
    cases[nc++] = (Touching){ "a triangle in a cell face touching a cell edge with its edge", { 2, 6, 4 }, { 3, 7, 4 },
                              { -1 }, { -1 }, { -1 } };

    if (build(s, &w, &g, res, 0) || g.min.x != gmin.x || g.min.y != gmin.y || g.min.z != gmin.z ||
        g.cell_size.x != gsize.x || g.cell_size.y != gsize.y || g.cell_size.z != gsize.z) {
        tap_ok(0, "touching cases: the grid keeps its boundaries when the touching polygons are added");
        scene_free(s);
        return;
    }
    Registrations r;
    registrations_read(&r, &g, w.npolygons);
    int touched = 0, touched_listed = 0;
    for (int c = 0; c < nc; c++) {
        const Touching *tc = &cases[c];
        int pi = 2 + c, entered = 0, entered_listed = 0, here = 0;
        for (int z = tc->lo[2]; z <= tc->hi[2]; z++)
            for (int y = tc->lo[1]; y <= tc->hi[1]; y++)
                for (int x = tc->lo[0]; x <= tc->hi[0]; x++) {
                    int has = 0;
                    for (size_t i = r.first[pi]; i < r.first[pi + 1]; i++)
                        has |= r.pairs[i].cell == (uint32_t)cell_of(&g, x, y, z);
                    int enters = tc->elo[0] >= 0 && x >= tc->elo[0] && x <= tc->ehi[0] && y >= tc->elo[1] &&
                                 y <= tc->ehi[1] && z >= tc->elo[2] && z <= tc->ehi[2] &&
                                 !(x == tc->hole[0] && y == tc->hole[1] && z == tc->hole[2]);
                    entered += enters;
                    entered_listed += enters && has;
                    touched++;
                    touched_listed += has;
                    here += has;
                }
        tap_ok(pi < w.npolygons && entered_listed == entered && here > 0,
               "placed by hand: %s is listed in each of the %d cells it enters (%d) and in some cell it touches",
               tc->what, entered, entered_listed);
    }
    tap_ok(touched_listed == touched, "placed by hand: each polygon is listed in every cell it touches (%d of %d listings)",
           touched_listed, touched);
    registrations_free(&r);
    Tally t;
    memset(&t, 0, sizeof t);
    check_grid(&w, &g, rng, "touching cases", &t);
    report("touching cases", &t);
    grid_free(&g);
    world_free(&w);
    scene_free(s);
#undef X
#undef Y
#undef Z
}

/* What a missing touching registration costs: a ray running in a cell
 * boundary plane x = X (as camera rays of a centred column do) meets a
 * triangle that starts at X only on the triangle's edge in that plane; the
 * walk keeps to the column its start point rounds into, which need not be
 * the one the triangle is listed in. Over grids of 2 to 40 cells along x
 * and every inner boundary: the walk's hit against every polygon tested. */
static void boundary_plane_rays(void)
{
    int rays = 0, missed = 0, first_n = 0, first_k = 0;
    for (int n = 2; n <= 40; n++)
        for (int k = 1; k < n; k++) {
            Scene *s = fixture_scene(8);
            fixture_triangle(s, v3(-8, -8, -8), v3(-7.9, -8, -8), v3(-8, -7.9, -8));
            fixture_triangle(s, v3(8, 8, 8), v3(7.9, 8, 8), v3(8, 7.9, 8));
            int res[3] = { n, 8, 8 };
            World w;
            Grid g;
            if (build(s, &w, &g, res, 0)) {
                scene_free(s);
                continue;
            }
            double X = boundary(&g, 0, k);
            grid_free(&g);
            world_free(&w);
            fixture_triangle(s, v3(X, 0.3, 0.5), v3(X + 0.1, 0.3, 0.5), v3(X, 0.3, 1.5));
            if (build(s, &w, &g, res, 0)) {
                scene_free(s);
                continue;
            }
            Tracer ctx;
            if (boundary(&g, 0, k) == X && tracer_init(&ctx, &w, &g) == 0) {
                Vec3 o = v3(X, -2, 1.0), d = v3(0, 1, 0);
                Hit h;
                int found = trace_nearest(&ctx, o, d, HUGE_VAL, NULL, &h);
                if (intersect_polygon(&w, &w.polygons[2], o, d) > 0) {
                    rays++;
                    if (!found && !missed++) {
                        first_n = n;
                        first_k = k;
                    }
                }
                tracer_free(&ctx);
            }
            grid_free(&g);
            world_free(&w);
            scene_free(s);
        }
    tap_ok(rays > 500, "rays in cell boundary planes meet the triangles starting there, tested one by one (%d)", rays);
    tap_ok(missed == 0,
           "the walk finds every triangle a ray in a cell boundary plane meets on its edge (%d of %d missed; first "
           "with %d cells along x, boundary %d)",
           missed, rays, first_n, first_k);
}

/* The project's scenes, parsed and built as hstrace builds them. */
static void real_scenes(TestRng *rng)
{
    const char *top = getenv("top_srcdir");
    char dirs[2][1024];
    snprintf(dirs[0], sizeof dirs[0], "%s/scenes", top ? top : ".");
    snprintf(dirs[1], sizeof dirs[1], "%s/scenes/hard", top ? top : ".");
    char include[1024];
    snprintf(include, sizeof include, "%s/data/include", top ? top : ".");
    const char *inc[2] = { include, "/usr/share/povray-3.7/include" };
    ParseOptions opts = { .include_dirs = inc, .ninclude_dirs = 2, .image_width = 320, .image_height = 240,
                          .load_image = image_read_for_scene };
    Tally t;
    memset(&t, 0, sizeof t);
    int scenes = 0, failed = 0;
    long polygons = 0;
    for (int d = 0; d < 2; d++) {
        DIR *dir = opendir(dirs[d]);
        if (!dir)
            continue;
        struct dirent *e;
        char names[64][256];
        int nn = 0;
        while ((e = readdir(dir)) && nn < 64) {
            size_t len = strlen(e->d_name);
            if (len > 4 && strcmp(e->d_name + len - 4, ".pov") == 0 && len < 256)
                memcpy(names[nn++], e->d_name, len + 1);
        }
        closedir(dir);
        for (int i = 0; i < nn; i++) {
            char path[2400];
            if (snprintf(path, sizeof path, "%s/%s", dirs[d], names[i]) >= (int)sizeof path)
                continue;
            ParseError perr;
            Scene *s = parse_scene_file(path, &opts, &perr);
            World w;
            Grid g;
            if (!s || build(s, &w, &g, NULL, 1)) {
                tap_diag("%s: %s", path, s ? "cannot build" : perr.message);
                failed++;
                scene_free(s);
                continue;
            }
            scenes++;
            polygons += w.npolygons;
            check_grid(&w, &g, rng, names[i], &t);
            grid_free(&g);
            world_free(&w);
            scene_free(s);
        }
    }
    char what[64];
    snprintf(what, sizeof what, "%d scenes of scenes/ (%ld polygons)", scenes, polygons);
    tap_ok(scenes >= 10 && failed == 0, "the project's scenes build (%d, %d failed)", scenes, failed);
    report(what, &t);
}

int main(void)
{
    TestRng rng = { 0x9E3779B97F4A7C15ULL };
    Scene *s = fixture_scene(400);
    random_triangles(s, &rng, 300);
    /* Axis-aligned quads lying exactly on cell boundaries are the hard case
     * for registration. */
    Vec3 quad[] = { { -10, -10, 0 }, { 10, -10, 0 }, { 10, 10, 0 }, { -10, 10, 0 }, { -10, -10, 0 } };
    int starts[] = { 0, 5 };
    fixture_polygon(s, quad, 5, starts, 1);
    add_random_outlines(s, &rng, 40);

    World w;
    WorldError err;
    tap_ok(world_build(&w, s, &err) == 0, "world builds");
    Grid g;
    int res[3] = { 8, 8, 8 };
    tap_ok(grid_build(&g, &w, res, NULL, 0) == 0, "grid builds");

    Tally tally;
    memset(&tally, 0, sizeof tally);
    check_grid(&w, &g, &rng, "random polygons, 8x8x8", &tally);
    report("random triangles and outlines with holes, 8x8x8", &tally);
    {
        static const int other[2][3] = { { 13, 7, 5 }, { 1, 1, 1 } };
        for (int k = 0; k < 2; k++) {
            Grid g2;
            if (grid_build(&g2, &w, other[k], NULL, 0)) {
                tap_ok(0, "grid %dx%dx%d builds", other[k][0], other[k][1], other[k][2]);
                continue;
            }
            Tally t2;
            memset(&t2, 0, sizeof t2);
            char what[80];
            snprintf(what, sizeof what, "random polygons, %dx%dx%d", other[k][0], other[k][1], other[k][2]);
            check_grid(&w, &g2, &rng, what, &t2);
            report(what, &t2);
            grid_free(&g2);
        }
    }
    touching_cases(&rng);
    boundary_plane_rays();
    registration_threads(&rng);
    sparse_cell_lists(&rng);
    real_scenes(&rng);

    /* The walk finds the same nearest hit as testing every polygon. */
    Tracer tracer;
    tap_ok(tracer_init(&tracer, &w, &g) == 0, "tracer");
    int mismatches = 0, hits = 0;
    const int nrays = 20000;
    for (int i = 0; i < nrays; i++) {
        Vec3 o = v3(rng_range(&rng, -15, 15), rng_range(&rng, -15, 15), rng_range(&rng, -15, 15));
        Vec3 d = v3_normalize(v3(rng_range(&rng, -1, 1), rng_range(&rng, -1, 1), rng_range(&rng, -1, 1)));
        /* Some rays run exactly along cell boundaries and axes. */
        if (i % 10 == 0) { o.z = 0.0; d = v3_normalize(v3(d.x, d.y, 0)); }
        if (i % 10 == 1) { d = v3(0, 0, d.z > 0 ? 1 : -1); }
        Hit h;
        int found = trace_nearest(&tracer, o, d, HUGE_VAL, NULL, &h);
        double best = HUGE_VAL;
        int best_i = -1;
        double tmin = trace_min_distance(o);
        for (int p = 0; p < w.npolygons; p++) {
            double t = intersect_polygon(&w, &w.polygons[p], o, d);
            if (t > tmin && t < best) { best = t; best_i = p; }
        }
        hits += best_i >= 0;
        if ((best_i >= 0) != found || (found && fabs(h.t - best) > 1e-9 * (1 + best)))
            mismatches++;
    }
    tap_ok(mismatches == 0, "3DDDA nearest hit equals brute force on %d random rays (%d hits, %d mismatches)", nrays,
           hits, mismatches);
    tracer_free(&tracer);

    /* Resolution heuristic: about eight cells per polygon, at least one per axis. */
    int r[3];
    grid_choose_resolution(&w, g.min, g.max, r);
    double cells = (double)r[0] * r[1] * r[2];
    tap_ok(cells >= 4.0 * w.npolygons && cells <= 32.0 * w.npolygons, "heuristic gives %dx%dx%d cells for %d polygons", r[0],
           r[1], r[2], w.npolygons);

    /* Points anywhere have a cell: the nearest edge cell beyond the box
     * (a plane's hit near the horizon lies 1e16 away), the first for NaN. */
    int far_ok = 1;
    for (int a = 0; a < 3; a++) {
        far_ok &= grid_cell_coord(&g, -3.57e16, a) == 0 && grid_cell_coord(&g, 3.57e16, a) == g.n[a] - 1;
        far_ok &= grid_cell_coord(&g, -HUGE_VAL, a) == 0 && grid_cell_coord(&g, HUGE_VAL, a) == g.n[a] - 1;
        far_ok &= grid_cell_coord(&g, NAN, a) == 0 && grid_cell_coord(&g, 1e308, a) == g.n[a] - 1;
    }
    tap_ok(far_ok, "cell coordinates of points at +-3.57e16, +-1e308, +-inf and NaN are the edge cells");
    /* A ray that goes nowhere has no walk: NaN, or a direction that
     * underflowed to zero (toward a light 1e308 away), with no end. */
    GridWalk gw;
    tap_ok(!grid_walk_begin(&g, v3(0, 0, 0), v3(0, 0, 0), 0.0, HUGE_VAL, &gw), "no walk for a zero direction");
    tap_ok(!grid_walk_begin(&g, v3(0, 0, 0), v3(NAN, 0, 1), 0.0, HUGE_VAL, &gw) &&
               !grid_walk_begin(&g, v3(NAN, 0, 0), v3(0, 0, 1), 0.0, HUGE_VAL, &gw) &&
               !grid_walk_begin(&g, v3(0, 0, 0), v3(0, 0, 1), 0.0, NAN, &gw),
           "no walk for a NaN origin, direction or end");
    int steps = 0;
    if (grid_walk_begin(&g, v3(-1e300, 0.5, 0.5), v3(1, 0, 0), 0.0, HUGE_VAL, &gw))
        do
            steps++;
        while (grid_walk_next(&g, &gw) && steps < 1000);
    /* (at t = 1e300 the cells' crossings round together: fewer cells, never more) */
    tap_ok(steps >= 1 && steps <= g.n[0], "a ray from 1e300 away ends its walk (%d cells, %d across)", steps, g.n[0]);

    grid_free(&g);
    world_free(&w);
    scene_free(s);
    return tap_done();
}
