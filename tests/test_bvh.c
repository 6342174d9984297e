/* The hierarchy (bvh.h) against the grid's walk, the reference path it
 * replaced for the polygon queries: on every scene of scenes/ and
 * scenes/hard/, and on random triangle soups, the nearest hit of camera
 * rays, of rays from points on polygons in random directions, and of rays
 * along the grid's axes is the same polygon at the same distance, bit for
 * bit; and a segment meets the same polygons at the same distances. Also
 * the hierarchy's shape: every polygon in exactly one leaf, every box
 * holding what is below it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bvh.h"
#include "camera.h"
#include "fixtures.h"
#include "grid.h"
#include "intersect.h"
#include "parser.h"
#include "tap.h"
#include "tracer.h"
#include "world.h"

/* ---- the shape ------------------------------------------------------------ */

static int box_holds(const BvhNode *n, int k, Vec3 lo, Vec3 hi)
{
    return n->lo[0][k] <= lo.x && n->lo[1][k] <= lo.y && n->lo[2][k] <= lo.z && n->hi[0][k] >= hi.x &&
           n->hi[1][k] >= hi.y && n->hi[2][k] >= hi.z;
}

/* Child k's box holds every box of node m. */
static int node_holds(const BvhNode *n, int k, const BvhNode *m)
{
    for (int j = 0; j < BVH_WIDTH; j++) {
        if (m->child[j] == BVH_EMPTY)
            continue;
        for (int a = 0; a < 3; a++)
            if (n->lo[a][k] > m->lo[a][j] || n->hi[a][k] < m->hi[a][j])
                return 0;
    }
    return 1;
}

/* Returns the problems found below node ni; counts leaf entries per polygon. */
static int check_shape(const Bvh *b, const World *w, uint32_t ni, int depth, int *seen)
{
    const BvhNode *n = &b->nodes[ni];
    if (depth > BVH_MAX_DEPTH)
        return 1;
    int bad = 0, used = 0;
    for (int k = 0; k < BVH_WIDTH; k++) {
        uint32_t c = n->child[k];
        if (c == BVH_EMPTY)
            continue;
        used++;
        if (bvh_is_leaf(c)) {
            for (uint32_t i = bvh_leaf_first(c); i < bvh_leaf_first(c) + bvh_leaf_count(c); i++) {
                uint32_t p = b->items[i];
                seen[p]++;
                bad += !box_holds(n, k, w->polygons[p].bbox_min, w->polygons[p].bbox_max);
            }
        } else {
            bad += (int)c <= (int)ni || (int)c >= b->nnodes; /* children come after their parent */
            if (!bad) {
                bad += !node_holds(n, k, &b->nodes[c]);
                bad += check_shape(b, w, c, depth + 1, seen);
            }
        }
    }
    return bad + (used == 0);
}

/* ---- the queries ------------------------------------------------------------ */

typedef struct {
    int n, cap;
    struct { uint32_t polygon; double t; } *hit;
} HitList;

static int collect(void *user, uint32_t polygon, double t)
{
    HitList *l = user;
    if (l->n == l->cap) {
        l->cap = l->cap ? 2 * l->cap : 64;
        l->hit = realloc(l->hit, sizeof *l->hit * (size_t)l->cap);
    }
    l->hit[l->n].polygon = polygon;
    l->hit[l->n].t = t;
    l->n++;
    return 0;
}

static int by_polygon(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return x < y ? -1 : x > y;
}

static int same_hits(HitList *a, HitList *b)
{
    if (a->n != b->n)
        return 0;
    if (a->n == 0)
        return 1;
    qsort(a->hit, (size_t)a->n, sizeof *a->hit, by_polygon);
    qsort(b->hit, (size_t)b->n, sizeof *b->hit, by_polygon);
    for (int i = 0; i < a->n; i++)
        if (a->hit[i].polygon != b->hit[i].polygon || a->hit[i].t != b->hit[i].t)
            return 0;
    return 1;
}

typedef struct {
    int rays, hits, brute_wrong, grid_wrong, grid_ties, segments, segment_wrong, touch_asked, touching, touch_wrong,
        touch_grid_wrong, touch_grid_missed;
} Tally;

/* The nearest hit by testing everything, written out apart from the tracer:
 * planes first (the nearest, t beyond the start's margin), then the polygon
 * nearest and strictly before the plane, the lowest index among exact ties. */
static int brute_nearest(const World *w, Vec3 org, Vec3 dir, const Hit *from, Hit *hit)
{
    double tmin = trace_min_distance(org), plane_t = HUGE_VAL;
    int plane = -1;
    for (int i = 0; i < w->nplanes; i++) {
        if (from && from->kind == HIT_PLANE && from->index == i)
            continue;
        double t = intersect_plane(&w->planes[i], org, dir);
        if (t > tmin && t < plane_t) {
            plane_t = t;
            plane = i;
        }
    }
    /* the shapes, in order: nearer than the plane, the first of tied ones */
    int shape = -1, part = 0;
    for (int i = 0; i < w->nshapes; i++) {
        ShapeHit h;
        double t = shape_nearest(&w->shapes[i], org, dir, plane_t, &h);
        if (t > 0.0) {
            plane_t = t;
            shape = h.leaf ? (int)(h.leaf - w->shapes) : i;
            part = h.part;
            plane = -1;
        }
    }
    RayFrame f = ray_frame(org, dir);
    double best = plane_t;
    int poly = -1;
    for (int i = 0; i < w->npolygons; i++) {
        if (from && from->kind == HIT_POLYGON && from->index == i)
            continue;
        double t = intersect_polygon_in(w, &w->polygons[i], &f, HUGE_VAL);
        if (t > tmin && (t < best || (poly >= 0 && t == best && i < poly))) {
            best = t;
            poly = i;
        }
    }
    if (poly < 0 && plane < 0 && shape < 0)
        return 0;
    hit->kind = poly >= 0 ? HIT_POLYGON : shape >= 0 ? HIT_SHAPE : HIT_PLANE;
    hit->index = poly >= 0 ? poly : shape >= 0 ? shape : plane;
    hit->part = part;
    hit->t = best;
    return 1;
}

static int same_hit(int fa, const Hit *a, int fb, const Hit *b)
{
    return fa == fb && (!fa || (a->kind == b->kind && a->index == b->index && a->t == b->t));
}

static void compare_ray(Tracer *grid, Tracer *tree, Vec3 org, Vec3 dir, const Hit *from, int brute, Tally *t,
                        HitList *a, HitList *b)
{
    Hit hg, hb, hx;
    int fg = trace_nearest(grid, org, dir, HUGE_VAL, from, &hg);
    int fb = trace_nearest(tree, org, dir, HUGE_VAL, from, &hb);
    t->rays++;
    t->hits += fb;
    if (brute) {
        int fx = brute_nearest(tree->world, org, dir, from, &hx);
        t->brute_wrong += !same_hit(fx, &hx, fb, &hb);
    }
    /* The grid may pick another of polygons tied at the same distance, when
     * the tie straddles a cell boundary (its walk stops at the first cell
     * that holds a hit); everything else must agree. */
    if (!same_hit(fg, &hg, fb, &hb)) {
        int tie = fg && fb && hg.kind == HIT_POLYGON && hb.kind == HIT_POLYGON && hg.t == hb.t && hb.index < hg.index;
        if (tie)
            t->grid_ties++;
        else
            t->grid_wrong++;
    }
    /* Whether the hit point lies on another polygon too (the shadow
     * volumes' rule), against asking every polygon: the hierarchy's tracer
     * asks the polygons whose boxes come near, the grid's those of the
     * nearby cells. */
    if (fb) {
        const World *w = tree->world;
        double tol = grid_tolerance(grid->grid) * 1e3; /* wide enough that the answer is often yes */
        int tg = trace_point_touches_other(grid, &hb, tol), tb = trace_point_touches_other(tree, &hb, tol);
        int want = hb.kind == HIT_POLYGON && polygon_classify_point(w, &w->polygons[hb.index], hb.point, tol) < 0;
        for (int i = 0; i < w->npolygons && !want; i++) {
            const Polygon *p = &w->polygons[i];
            want = !(hb.kind == HIT_POLYGON && hb.index == i) && fabs(v3_dot(p->normal, hb.point) - p->d) <= tol &&
                   polygon_classify_point(w, p, hb.point, tol) != 0;
        }
        t->touch_asked++;
        t->touching += want;
        t->touch_wrong += tb != want;
        t->touch_grid_wrong += tg && !want;
        t->touch_grid_missed += !tg && want;
    }
    /* The segment to the hit (or a long way), as a shadow ray sees it. */
    double tmax = fb ? hb.t : 1e6;
    int exclude = from && from->kind == HIT_POLYGON ? from->index : -1;
    uint64_t tests = 0;
    a->n = b->n = 0;
    trace_segment_hits(grid, org, dir, trace_min_distance(org), tmax, exclude, 0, collect, a, &tests);
    trace_segment_hits(tree, org, dir, trace_min_distance(org), tmax, exclude, 0, collect, b, &tests);
    t->segments++;
    t->segment_wrong += !same_hits(a, b);
}

static double unit(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return (double)(*s >> 11) * 0x1p-53;
}

static Vec3 random_dir(uint64_t *s)
{
    for (;;) {
        Vec3 d = v3(2 * unit(s) - 1, 2 * unit(s) - 1, 2 * unit(s) - 1);
        double l = v3_length(d);
        if (l > 1e-3 && l <= 1.0)
            return v3_scale(d, 1.0 / l);
    }
}

/* A point inside polygon p (a vertex-weighted average of its first three). */
static Vec3 point_on(const World *w, const Polygon *p, uint64_t *s)
{
    const Vec3 *v = &w->points[p->first_point];
    double a = unit(s), b = unit(s);
    if (a + b > 1.0) {
        a = 1.0 - a;
        b = 1.0 - b;
    }
    return v3_add(v[0], v3_add(v3_scale(v3_sub(v[1], v[0]), a), v3_scale(v3_sub(v[2], v[0]), b)));
}

/* "NAME (AVX2)", for the descriptions of the second pass. */
static const char *avx2_name(const char *name)
{
    static char buf[1100];
    snprintf(buf, sizeof buf, "%s (AVX2)", name);
    return buf;
}

/* The same hierarchy, bit for bit: nodes, leaf order, records, depth; and
 * the same of the shapes' own (Bvh.shapes). An empty one (a world of
 * shapes alone has no polygons) has no arrays to compare. */
static int same_bvh(const Bvh *a, const Bvh *b)
{
    if (a->nnodes != b->nnodes || a->nitems != b->nitems || a->depth != b->depth || !a->shapes != !b->shapes)
        return 0;
    if (a->shapes && !same_bvh(a->shapes, b->shapes))
        return 0;
    return a->nnodes == 0 || (memcmp(a->nodes, b->nodes, sizeof *a->nodes * (size_t)a->nnodes) == 0 &&
                              memcmp(a->items, b->items, sizeof *a->items * (size_t)a->nitems) == 0 &&
                              memcmp(a->prims, b->prims, sizeof *a->prims * (size_t)a->nitems) == 0);
}

/* bvh_build (its SIMD passes, the sweep over the bins that hold items,
 * threads) makes the hierarchy bvh_build_plain does, on 1, 2 and 3 threads. */
static void check_same_as_plain(const char *name, const World *w)
{
    Bvh ref, b;
    if (bvh_build_plain(&ref, w, 1)) {
        tap_ok(0, "%s: the plain hierarchy builds", name);
        return;
    }
    int same = 1;
    for (int threads = 1; threads <= 3; threads++) {
        if (bvh_build(&b, w, threads)) {
            same = 0;
            break;
        }
        same &= same_bvh(&ref, &b);
        bvh_free(&b);
    }
    tap_ok(same, "%s: the hierarchy is the plain build's, node for node, on 1, 2 and 3 threads (%d nodes)", name,
           ref.nnodes);
    bvh_free(&ref);
}

/* avx2: the hierarchy's traversals with the AVX2 box test (else SSE2's). */
static void check_world(const char *name, const World *w, int avx2)
{
    Vec3 extra[1 + 8 * 16];
    int nextra = grid_extra_points(w, extra, (int)(sizeof extra / sizeof extra[0]));
    Grid g;
    Bvh b;
    if (grid_build(&g, w, NULL, extra, nextra) || bvh_build(&b, w, 1)) {
        tap_ok(0, "%s: grid and hierarchy build", name);
        return;
    }
    int *seen = calloc((size_t)(w->npolygons > 0 ? w->npolygons : 1), sizeof *seen);
    int shape = b.nnodes ? check_shape(&b, w, 0, 1, seen) : 0, once = 1;
    /* The SSE2 box test and the plain one agree, bit for bit, on every node
     * and a spread of rays (axis-parallel ones, with their NaN slabs,
     * included). */
    int node_tests = 0, node_differ = 0;
    uint64_t rs = 0x853C49E6748FEA9BULL;
    for (int i = 0; i < b.nnodes; i++)
        for (int j = 0; j < 8; j++) {
            Vec3 o = v3(g.min.x + unit(&rs) * (g.max.x - g.min.x), g.min.y + unit(&rs) * (g.max.y - g.min.y),
                        g.min.z + unit(&rs) * (g.max.z - g.min.z));
            Vec3 d = j % 4 == 0 ? v3(0, 0, j % 8 ? 1 : -1) : random_dir(&rs);
            if (j == 5)
                o = v3(b.nodes[i].lo[0][0], b.nodes[i].lo[1][0], o.z); /* on a slab face */
            BvhRay r = bvh_ray(o, d);
            double e1[BVH_WIDTH], e2[BVH_WIDTH];
            double t1 = j % 3 ? HUGE_VAL : 10.0 * unit(&rs);
            unsigned m2 = bvh_node_hits_plain(&b.nodes[i], &r, 0.0, t1, e2), m1;
#if BVH_HAVE_AVX2_PATH
            if (avx2)
                m1 = bvh_node_hits_avx2(&b.nodes[i], &r, 0.0, t1, e1);
            else
#endif
                m1 = bvh_node_hits(&b.nodes[i], &r, 0.0, t1, e1);
            node_tests++;
            int differ = m1 != m2;
            for (int k = 0; k < BVH_WIDTH; k++)
                differ |= (m1 & (1u << k)) && memcmp(&e1[k], &e2[k], sizeof e1[k]) != 0;
            node_differ += differ;
        }
    tap_ok(node_differ == 0, "%s: the %s and plain box tests agree on %d node tests (%d differ)", name,
           avx2 ? "AVX2" : "SSE2", node_tests, node_differ);
    if (avx2)
        name = avx2_name(name);
    for (int i = 0; i < w->npolygons; i++)
        once &= seen[i] == 1;
    tap_ok(shape == 0 && once && b.depth <= BVH_MAX_DEPTH,
           "%s: hierarchy of %d nodes, depth %d, holds each of %d polygons once, every box around what is below it "
           "(%d problems)",
           name, b.nnodes, b.depth, w->npolygons, shape);
    free(seen);

    Tracer grid, tree;
    tracer_init(&grid, w, &g);
    tracer_init(&tree, w, &g);
    tracer_use_bvh(&tree, &b);
    tracer_use_avx2(&tree, avx2);
    Tally t = { 0 };
    HitList la = { 0 }, lb = { 0 };
    uint64_t s = 0x9E3779B97F4A7C15ULL;
    /* Camera rays through a grid of pixel centres. */
    for (int y = 0; y < 48; y++)
        for (int x = 0; x < 64; x++) {
            Vec3 org, dir;
            camera_ray(&w->camera, 64, 48, x, y, &org, &dir);
            Hit none = { HIT_NONE, -1, 0.0, org, -1, 0 };
            compare_ray(&grid, &tree, org, dir, &none, (x + y) % 3 == 0, &t, &la, &lb);
        }
    /* From points on polygons, in random directions and toward vertices
     * (through shared edges and corners, the ties). */
    for (int i = 0; i < 3000 && w->npolygons > 0; i++) {
        int pi = (int)(unit(&s) * w->npolygons);
        const Polygon *p = &w->polygons[pi];
        Vec3 org = point_on(w, p, &s);
        Vec3 dir = random_dir(&s);
        if (i % 3 == 0) {
            Vec3 d = v3_sub(w->points[(int)(unit(&s) * w->npoints)], org);
            if (v3_length(d) > 0.0)
                dir = v3_normalize(d);
        }
        Hit from = { HIT_POLYGON, pi, 0.0, org, -1, 0 };
        compare_ray(&grid, &tree, org, dir, &from, i % 3 == 0, &t, &la, &lb);
    }
    /* Along the axes from inside the box: rays in cell and slab planes. */
    for (int i = 0; i < 600; i++) {
        Vec3 org = v3(g.min.x + unit(&s) * (g.max.x - g.min.x), g.min.y + unit(&s) * (g.max.y - g.min.y),
                      g.min.z + unit(&s) * (g.max.z - g.min.z));
        if (i % 2 && w->npolygons > 0)
            org = w->points[(int)(unit(&s) * w->npoints)];
        double sgn = i % 4 < 2 ? 1.0 : -1.0;
        Vec3 dir = i % 3 == 0 ? v3(sgn, 0, 0) : i % 3 == 1 ? v3(0, sgn, 0) : v3(0, 0, sgn);
        Hit none = { HIT_NONE, -1, 0.0, org, -1, 0 };
        compare_ray(&grid, &tree, org, dir, &none, 1, &t, &la, &lb);
    }
    tap_ok(t.brute_wrong == 0,
           "%s: nearest hit by the hierarchy equals testing every polygon, exact ties to the lowest index (%d rays, "
           "a third of them checked so, %d differ)",
           name, t.rays, t.brute_wrong);
    tap_ok(t.grid_wrong == 0,
           "%s: ... and the grid's walk (%d rays, %d hits; %d ties across a cell boundary the grid gave to a higher "
           "index; %d other differences)",
           name, t.rays, t.hits, t.grid_ties, t.grid_wrong);
    tap_ok(t.segment_wrong == 0, "%s: the polygons a segment meets, and where, equal the grid's on %d segments (%d differ)",
           name, t.segments, t.segment_wrong);
    tap_ok(t.touch_wrong == 0 && t.touch_grid_wrong == 0 && t.touch_grid_missed == 0,
           "%s: whether a hit point lies on a second polygon is every polygon's answer (%d points, %d on one; %d "
           "differ, %d wrongly, %d missed by the grid-walk tracer)",
           name, t.touch_asked, t.touching, t.touch_wrong, t.touch_grid_wrong, t.touch_grid_missed);
    free(la.hit);
    free(lb.hit);
    tracer_free(&grid);
    tracer_free(&tree);
    bvh_free(&b);
    grid_free(&g);
}

/* shape_sphere_crossings (the spheres' fast test) against shape_intersect_all
 * (the reference), bit for bit, on an untransformed sphere: rays from around
 * it, from its surface (along it, grazing, out, in), along the axes, of
 * unit and other lengths (and none), under limits short of, at and past its
 * crossings. Returns how many rays differ; *rays counts them. */
static int sphere_crossings_differ(const Shape *s, uint64_t *rs, int *rays)
{
    Vec3 c = s->u.sphere.center;
    double r = s->u.sphere.radius;
    int differ = 0;
    for (int i = 0; i < 400; i++) {
        Vec3 n = random_dir(rs), d = random_dir(rs);
        Vec3 o = v3_add(c, v3_scale(random_dir(rs), r * 4.0 * unit(rs)));
        switch (i % 8) {
        case 0: /* on the surface, along it (grazing) */
            o = v3_add(c, v3_scale(n, r));
            d = v3_normalize(v3_cross(n, d));
            break;
        case 1: /* on the surface, in or out */
            o = v3_add(c, v3_scale(n, r));
            d = i % 16 == 1 ? n : v3_neg(n);
            break;
        case 2: /* toward the centre from far off */
            o = v3_add(c, v3_scale(n, r * 1e4));
            d = v3_sub(c, o);
            break;
        case 3: /* along an axis */
            d = i % 24 == 3 ? v3(1, 0, 0) : i % 24 == 11 ? v3(0, -1, 0) : v3(0, 0, 1);
            break;
        case 4: /* not of unit length */
            d = v3_scale(d, 0.37 + 5.0 * unit(rs));
            break;
        case 5: /* none */
            if (i % 40 == 5)
                d = v3(0, 0, 0);
            break;
        default: /* toward a point on the surface, tangent at it or nearly */
            d = v3_sub(v3_add(c, v3_scale(n, r * (1.0 + (unit(rs) - 0.5) * 1e-9))), o);
            break;
        }
        double tmax = i % 3 == 0 ? HUGE_VAL : i % 3 == 1 ? 3.0 * r * unit(rs) : 1e-6;
        ShapeHit hits[SHAPE_MAX_HITS];
        int n_ref = shape_intersect_all(s, o, d, tmax, hits);
        ShapeRay ray;
        shape_ray_init(&ray, o, d);
        double t[2];
        int n_fast = shape_sphere_crossings(s, &ray, tmax, t);
        int same = n_fast == n_ref;
        for (int k = 0; same && k < n_ref; k++)
            same = memcmp(&t[k], &hits[k].t, sizeof t[k]) == 0;
        differ += !same;
        ++*rays;
    }
    return differ;
}

static void check_sphere_crossings(const char *name, const World *w)
{
    uint64_t rs = 0xD1B54A32D192ED03ULL;
    int rays = 0, differ = 0, spheres = 0;
    for (int i = 0; i < w->nshapes; i++)
        if (w->shapes[i].kind == SHAPE_SPHERE && !w->shapes[i].transformed) {
            differ += sphere_crossings_differ(&w->shapes[i], &rs, &rays);
            spheres++;
        }
    if (spheres > 0)
        tap_ok(differ == 0,
               "%s: the spheres' fast test (shape_sphere_crossings) finds shape_intersect_all's crossings, bit for "
               "bit (%d spheres, %d rays, %d differ)",
               name, spheres, rays, differ);
}

/* The same on spheres of every size and place, inverse ones among them. */
static void check_sphere_crossings_spread(void)
{
    uint64_t rs = 0x94D049BB133111EBULL;
    int rays = 0, differ = 0;
    for (int i = 0; i < 200; i++) {
        Shape s;
        memset(&s, 0, sizeof s);
        s.kind = SHAPE_SPHERE;
        s.u.sphere.center = v3((unit(&rs) - 0.5) * (i < 100 ? 10.0 : 1e5), unit(&rs) - 0.5, (unit(&rs) - 0.5) * 1e3);
        s.u.sphere.radius = i % 5 == 0 ? 1e-4 : i % 5 == 1 ? 300.0 : 0.05 + 2.0 * unit(&rs);
        s.inverse = i % 7 == 0;
        shape_compute_bounds(&s);
        differ += sphere_crossings_differ(&s, &rs, &rays);
    }
    tap_ok(differ == 0,
           "the spheres' fast test (shape_sphere_crossings) finds shape_intersect_all's crossings, bit for bit, on "
           "200 spheres of every size and place (%d rays, %d differ)",
           rays, differ);
}

static void check_scene_file(const char *srcdir, const char *rel)
{
    World w;
    char why[4096];
    Scene *sc = fixture_scene_file(srcdir, rel, &w, why, sizeof why);
    if (!sc) {
        tap_ok(0, "%s", why);
        return;
    }
    check_same_as_plain(rel, &w);
    check_sphere_crossings(rel, &w);
    check_world(rel, &w, 0);
    /* The traversals again with AVX2's box test, where this processor has it. */
    if (bvh_have_avx2())
        check_world(rel, &w, 1);
    world_free(&w);
    scene_free(sc);
}

int main(void)
{
    const char *srcdir = getenv("top_srcdir");
    if (!srcdir)
        srcdir = ".";
    static const char *const scenes[] = {
        "scenes/desk.pov", "scenes/glasses.pov", "scenes/stars.pov", "scenes/cards.pov", "scenes/holes.pov",
        "scenes/mesh2.pov", "scenes/hard/boundary-columns.pov", "scenes/hard/contact.pov",
        "scenes/hard/degenerate.pov", "scenes/hard/far-coordinates.pov", "scenes/hard/grazing.pov",
        "scenes/hard/inside-volume.pov", "scenes/hard/light-in-plane.pov", "scenes/hard/long-shadows.pov",
        "scenes/hard/mirrors.pov", "scenes/hard/shared-edges-perspective.pov", "scenes/hard/shared-edges.pov",
        "scenes/hard/transparent.pov", "scenes/shapes/shapes-many.pov", "scenes/shapes/sphere-basic.pov",
        "bench/marbles.pov",
    };
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++)
        check_scene_file(srcdir, scenes[i]);
    check_sphere_crossings_spread();

    /* Random soups: clusters of small triangles, many of them sharing
     * vertices exactly (ties), and coincident copies of the same triangle;
     * from soup 3 on, two coordinates in five at +0 or -0, so that box
     * faces lie where rounding to float leaves them no slack (box_margin
     * in bvh.c: without it these soups lose some 30 nearest hits in 21
     * seeds). */
    for (int soup = 0; soup < 8; soup++) {
        uint64_t s = 0x2545F4914F6CDD1DULL + (uint64_t)soup;
        int n = soup == 0 ? 200 : soup == 1 ? 2000 : 500;
        Scene *sc = fixture_scene(n + 1);
        Vec3 last[3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
        for (int i = 0; i < n; i++) {
            Vec3 c = v3(20 * unit(&s) - 10, 20 * unit(&s) - 10, 20 * unit(&s) - 10);
            double r = soup == 1 ? 0.3 : 2.0;
            Vec3 v[3];
            for (int k = 0; k < 3; k++)
                v[k] = v3_add(c, v3(r * (2 * unit(&s) - 1), r * (2 * unit(&s) - 1), r * (2 * unit(&s) - 1)));
            if (i % 4 == 1) { /* share an edge with the last one */
                v[0] = last[0];
                v[1] = last[1];
            }
            if (soup >= 3)
                for (int k = 0; k < 3; k++) {
                    if (unit(&s) < 0.4)
                        v[k].x = unit(&s) < 0.5 ? 0.0 : -0.0;
                    if (unit(&s) < 0.4)
                        v[k].y = unit(&s) < 0.5 ? 0.0 : -0.0;
                    if (unit(&s) < 0.4)
                        v[k].z = unit(&s) < 0.5 ? 0.0 : -0.0;
                }
            if (soup == 2 && i % 10 == 5) /* an exact copy: a tie everywhere */
                memcpy(v, last, sizeof v);
            fixture_triangle(sc, v[0], v[1], v[2]);
            memcpy(last, v, sizeof v);
        }
        World w;
        WorldError we;
        char name[64];
        snprintf(name, sizeof name, "soup %d (%d triangles)", soup, n);
        if (world_build(&w, sc, &we) == 0) {
            check_same_as_plain(name, &w);
            check_world(name, &w, 0);
            if (bvh_have_avx2())
                check_world(name, &w, 1);
            world_free(&w);
        } else {
            tap_ok(0, "%s: world builds", name);
        }
        fixture_scene_free(sc);
    }
    /* Bounds of equal value and different bits, +0 and -0: which of them a
     * node's box keeps depends on the order the build grows it in. A soup
     * of triangles at coordinates of at least 0, many of them 0, built by
     * bvh_build and bvh_build_plain, with the zero bounds of every other
     * polygon made -0 (the world's transforms leave no -0 behind; the
     * build reads only the bounds). */
    {
        uint64_t s = 0x9E3779B97F4A7C15ULL;
        int n = 3000;
        Scene *sc = fixture_scene(n + 1);
        for (int i = 0; i < n; i++) {
            Vec3 v[3];
            for (int k = 0; k < 3; k++) {
                double xyz[3];
                for (int a = 0; a < 3; a++)
                    xyz[a] = unit(&s) < 0.4 ? 0.0 : 4.0 * unit(&s);
                v[k] = v3(xyz[0], xyz[1], xyz[2]);
            }
            fixture_triangle(sc, v[0], v[1], v[2]);
        }
        World w;
        WorldError we;
        if (world_build(&w, sc, &we) == 0) {
            int negative = 0;
            for (int i = 1; i < w.npolygons; i += 2) {
                double *b[6] = { &w.polygons[i].bbox_min.x, &w.polygons[i].bbox_min.y, &w.polygons[i].bbox_min.z,
                                 &w.polygons[i].bbox_max.x, &w.polygons[i].bbox_max.y, &w.polygons[i].bbox_max.z };
                for (int k = 0; k < 6; k++)
                    if (*b[k] == 0.0) {
                        *b[k] = -0.0;
                        negative++;
                    }
            }
            tap_ok(negative > 1000, "a soup of triangles at +0 and -0: %d bounds made -0", negative);
            check_same_as_plain("a soup of triangles at +0 and -0", &w);
            world_free(&w);
        } else {
            tap_ok(0, "a soup of triangles at +0 and -0: world builds");
        }
        fixture_scene_free(sc);
    }
    /* A hit nearer than the start's margin (trace_min_distance) is the start
     * itself: two parallel triangles 1e-10 apart (beyond plane_distance's
     * 1e-12 of a start in the plane, within the margin's 1e-9), a ray
     * leaving the lower toward the upper one meets nothing, by the grid's
     * walk and by the hierarchy alike; 1e-8 apart, it meets the upper. */
    for (int far = 0; far < 2; far++) {
        double gap = far ? 1e-8 : 1e-10;
        Scene *sc = fixture_scene(3);
        fixture_triangle(sc, v3(-1, 0, -1), v3(1, 0, -1), v3(0, 0, 1));
        fixture_triangle(sc, v3(-1, gap, -1), v3(1, gap, -1), v3(0, gap, 1));
        World w;
        WorldError we;
        Grid g;
        Bvh b;
        if (world_build(&w, sc, &we) || grid_build(&g, &w, NULL, NULL, 0) || bvh_build(&b, &w, 1)) {
            tap_ok(0, "two triangles %g apart build", gap);
            fixture_scene_free(sc);
            continue;
        }
        Tracer grid, tree;
        tracer_init(&grid, &w, &g);
        tracer_init(&tree, &w, &g);
        tracer_use_bvh(&tree, &b);
        Vec3 org = v3(0.1, 0, -0.2), dir = v3_normalize(v3(0.3, 1, 0.2));
        Hit from = { HIT_POLYGON, 0, 0.0, org, -1, 0 }, hg, hb;
        int fg = trace_nearest(&grid, org, dir, HUGE_VAL, &from, &hg);
        int fb = trace_nearest(&tree, org, dir, HUGE_VAL, &from, &hb);
        if (far)
            tap_ok(fg && fb && hg.index == 1 && hb.index == 1,
                   "a ray leaving a triangle meets a parallel one 1e-8 above it (beyond the start's margin)");
        else
            tap_ok(!fg && !fb, "a ray leaving a triangle does not meet a parallel one 1e-10 above it: within the "
                               "start's margin, the hit is the start itself");
        tracer_free(&grid);
        tracer_free(&tree);
        bvh_free(&b);
        grid_free(&g);
        world_free(&w);
        fixture_scene_free(sc);
    }

    /* The hierarchy does not depend on the threads that built it: a soup
     * big enough that its subtrees go to threads, built by 1, 2 and 3. */
    {
        uint64_t s = 0xDA942042E4DD58B5ULL;
        int n = 120000;
        Scene *sc = fixture_scene(n + 1);
        for (int i = 0; i < n; i++) {
            Vec3 c = v3(100 * unit(&s) - 50, 100 * unit(&s) - 50, 100 * unit(&s) - 50);
            fixture_triangle(sc, c, v3_add(c, v3(unit(&s), 0, 0)), v3_add(c, v3(0, unit(&s), unit(&s))));
        }
        World w;
        WorldError we;
        /* 2, 3 and 8 threads: subtrees handed to whichever thread is free,
         * the top collapsed here and its subtrees on threads (bvh.c). */
        const int counts[] = { 2, 3, 8 };
        Bvh b1, bt;
        if (world_build(&w, sc, &we) == 0 && bvh_build(&b1, &w, 1) == 0) {
            int same = 1;
            for (size_t i = 0; i < sizeof counts / sizeof counts[0]; i++) {
                if (bvh_build(&bt, &w, counts[i])) {
                    same = 0;
                    break;
                }
                same &= same_bvh(&b1, &bt);
                bvh_free(&bt);
            }
            tap_ok(same, "the hierarchy of %d triangles is the same, node for node, built on 1, 2, 3 and 8 threads (%d nodes)",
                   n, b1.nnodes);
            char name[64];
            snprintf(name, sizeof name, "a soup of %d triangles", n);
            check_same_as_plain(name, &w);
            bvh_free(&b1);
            world_free(&w);
        } else {
            tap_ok(0, "a soup of %d triangles builds", n);
        }
        fixture_scene_free(sc);
    }
    return tap_done();
}
