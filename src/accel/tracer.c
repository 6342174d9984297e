/* Nearest-hit queries through the grid, and the planes beside it. */
#include "tracer.h"
#include "big_memory.h"

#include <stdlib.h>
#include <string.h>

#include "instance.h"
#include "intersect.h"

void ray_counters_add(RayCounters *t, const RayCounters *p)
{
#define RAY_COUNTER(field, line, label, key, meaning) t->field += p->field;
#include "ray_counters.def"
#undef RAY_COUNTER
}

int tracer_init(Tracer *t, const World *w, const Grid *g)
{
    memset(t, 0, sizeof *t);
    t->world = w;
    t->grid = g;
    t->avx2 = bvh_have_avx2();
    t->stamp = big_calloc((size_t)(w->npolygons > 0 ? w->npolygons : 1), sizeof(uint32_t));
    return t->stamp ? 0 : -1;
}

int tracer_record_cells(Tracer *t, Vec3 box_min, Vec3 box_max)
{
    /* A 3DDDA walk visits at most one cell per boundary crossed. */
    t->segment_cells_cap = t->grid->n[0] + t->grid->n[1] + t->grid->n[2] + 3;
    t->segment_cells = malloc(sizeof(uint32_t) * (size_t)t->segment_cells_cap);
    t->record_min = box_min;
    t->record_max = box_max;
    return t->segment_cells ? 0 : -1;
}

void tracer_free(Tracer *t)
{
    free(t->stamp);
    free(t->segment_cells);
    t->stamp = NULL;
    t->segment_cells = NULL;
}

/* Does polygon pi (not the hit's own) hold the hit point, within tol? */
static inline int touches(const World *w, uint32_t pi, Vec3 x, double tol)
{
    const Polygon *p = &w->polygons[pi];
    return fabs(v3_dot(p->normal, x) - p->d) <= tol && polygon_classify_point(w, p, x, tol) != 0;
}

/* touches_other by the hierarchy: the polygons whose boxes reach within
 * 5 tol of x on every axis, which hold every polygon the grid's nearby
 * cells would offer that can touch x (the argument below), since a node's
 * box, rounded outward, holds its polygons' boxes. The same answer as the
 * grid's, without the grid's registrations. */
static int touches_other_in_bvh(Tracer *t, const Hit *hit, double tol)
{
    const World *w = t->world;
    const Bvh *b = t->bvh;
    if (b->nnodes == 0)
        return 0;
    double lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        lo[a] = v3_comp(hit->point, a) - 5.0 * tol;
        hi[a] = v3_comp(hit->point, a) + 5.0 * tol;
    }
    int own = hit->kind == HIT_POLYGON ? hit->index : -1;
    if (own >= w->npolygons)
        return 1; /* on an instance's polygon: said to touch (see below) */
    uint32_t stack[BVH_STACK];
    int sp = 0;
    stack[sp++] = 0;
    while (sp > 0) {
        const BvhNode *n = &b->nodes[stack[--sp]];
        t->stats.nodes_visited++;
        for (int k = 0; k < BVH_WIDTH; k++) {
            uint32_t c = n->child[k];
            if (c == BVH_EMPTY || !(n->lo[0][k] <= hi[0] && n->hi[0][k] >= lo[0] && n->lo[1][k] <= hi[1] &&
                                    n->hi[1][k] >= lo[1] && n->lo[2][k] <= hi[2] && n->hi[2][k] >= lo[2]))
                continue;
            if (!bvh_is_leaf(c)) {
                stack[sp++] = c;
                continue;
            }
            for (uint32_t i = 0, first = bvh_leaf_first(c); i < bvh_leaf_count(c); i++) {
                uint32_t pi = b->items[first + i];
                /* An instance near the point is said to touch it: the
                 * answer errs to the safe side (a caller then asks the
                 * shadow ray), and the methods that carry depth counts
                 * build no instances (shadow volumes want world-space
                 * polygons: instancing is off for them). */
                if (pi & BVH_INSTANCE)
                    return 1;
                if ((int)pi != own && touches(w, pi, hit->point, tol))
                    return 1;
            }
        }
    }
    return 0;
}

/* The uncached part of trace_point_touches_other: by the hierarchy where
 * the tracer has one, else by the grid's registrations (the reference
 * tests/test_bvh.c compares it with). */
static int touches_other(Tracer *t, const Hit *hit, double tol)
{
    const World *w = t->world;
    const Grid *g = t->grid;
    if (hit->kind == HIT_POLYGON && hit->index >= w->npolygons)
        return 1; /* an instance's polygon: see touches_other_in_bvh */
    if (hit->kind == HIT_POLYGON && polygon_classify_point(w, &w->polygons[hit->index], hit->point, tol) < 0)
        return 1; /* on its own polygon's border: on the neighbours' too */
    if (t->bvh)
        return touches_other_in_bvh(t, hit, tol);
    /* A point beyond the grid's box touches nothing: the box holds every
     * polygon. (Hits on an infinite plane near the horizon lie there, 1e16
     * units away.) A polygon that holds the point within tol has a point y
     * with |y - x| <= tol on its projection's two axes and, since x is
     * within tol of the plane and the dropped axis is the normal's largest
     * (|n_w| >= 1/sqrt 3), |y_w - x_w| <= sqrt 3 (1 + sqrt 2) tol < 4.2 tol
     * on the third: it is listed in a cell within 5 tol of x on every axis
     * (usually the one cell holding x). */
    for (int a = 0; a < 3; a++)
        if (!(v3_comp(hit->point, a) + 5.0 * tol >= v3_comp(g->min, a) &&
              v3_comp(hit->point, a) - 5.0 * tol <= v3_comp(g->max, a)))
            return 0;
    int lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        lo[a] = grid_cell_coord(g, v3_comp(hit->point, a) - 5.0 * tol, a);
        hi[a] = grid_cell_coord(g, v3_comp(hit->point, a) + 5.0 * tol, a);
    }
    uint32_t id = trace_new_segment(t);
    if (hit->kind == HIT_POLYGON)
        t->stamp[hit->index] = id;
    for (int z = lo[2]; z <= hi[2]; z++)
        for (int y = lo[1]; y <= hi[1]; y++)
            for (int x = lo[0]; x <= hi[0]; x++) {
                int c[3] = { x, y, z };
                int ci = grid_cell_index(g, c);
                for (uint32_t k = g->cell_start[ci]; k < g->cell_start[ci + 1]; k++) {
                    uint32_t pi = g->items[k];
                    if (bucket_admit(t, id, pi) && touches(w, pi, hit->point, tol))
                        return 1;
                }
            }
    return 0;
}

int trace_point_touches_other(Tracer *t, const Hit *hit, double tol)
{
    if (t->touch_valid && t->touch_kind == (int)hit->kind && t->touch_index == hit->index &&
        t->touch_point.x == hit->point.x && t->touch_point.y == hit->point.y && t->touch_point.z == hit->point.z)
        return t->touch_result;
    t->touch_valid = 1;
    t->touch_kind = (int)hit->kind;
    t->touch_index = hit->index;
    t->touch_point = hit->point;
    t->touch_result = touches_other(t, hit, tol);
    return t->touch_result;
}

static int inside_box(Vec3 lo, Vec3 hi, Vec3 p)
{
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
}

static int material_hidden(const Material *m, unsigned hide)
{
    return ((hide & HIDE_NO_IMAGE) && m->no_image) || ((hide & HIDE_NO_REFLECTION) && m->no_reflection) ||
           ((hide & HIDE_NO_SHADOW) && m->no_shadow);
}

void tracer_use_bvh(Tracer *t, const Bvh *bvh)
{
    t->bvh = bvh;
}

void tracer_use_avx2(Tracer *t, int on)
{
    t->avx2 = on && bvh_have_avx2();
}

/* Takes polygon pi's hit at t when it is nearer than the best so far, or as
 * near and of a lower index: the rule for exact ties, so that the answer
 * does not depend on the order the polygons were tested in. */
static inline void take_nearer(Hit *hit, double *best, uint32_t pi, int instance, double t)
{
    if (hit->kind == HIT_NONE || t < *best || (int)pi < hit->index) {
        *best = t;
        hit->kind = HIT_POLYGON;
        hit->index = (int)pi;
        hit->instance = instance;
    }
}

/* Polygon pi's hit at t, about to be offered to take_nearer, against the
 * nearest so far: at exactly its distance it is a coincident surface
 * (trace_coincident_material), and the one of the two take_nearer will not
 * keep (the higher index) is remembered with the distance. */
static inline void note_tie(Tracer *tr, const Hit *hit, double best, uint32_t pi, int instance, double t)
{
    if (hit->kind != HIT_POLYGON || t != best || (int)pi == hit->index)
        return;
    int keeps_new = (int)pi < hit->index;
    tr->tie_t = t;
    tr->tie_material = keeps_new ? world_polygon_material_hinted(tr->world, hit->index, hit->instance)
                                 : world_polygon_material_hinted(tr->world, (int)pi, instance);
}

/* The farthest distance a polygon test may still report: below the best so
 * far, or at it (for a tie), and before the plane (which wins ties). */
static inline double test_limit(const Hit *hit, double best, double plane_t)
{
    return hit->kind == HIT_NONE ? plane_t : nextafter(best, HUGE_VAL);
}

/* Polygon pi as a candidate for the nearest hit (not hidden; the caller
 * has left out the segment's own polygon). */
static inline void try_nearer(Tracer *tr, const RayFrame *frame, uint32_t pi, double tmin, double plane_t, Hit *hit,
                              double *best)
{
    const World *w = tr->world;
    if (tr->hide && material_hidden(&w->materials[w->polygons[pi].material], tr->hide))
        return;
    tr->stats.polygon_tests++;
    double t = intersect_polygon_in(w, &w->polygons[pi], frame, test_limit(hit, *best, plane_t));
    if (t > tmin) {
        note_tie(tr, hit, *best, pi, -1, t);
        take_nearer(hit, best, pi, -1, t);
    }
}

/* The exact test of the polygon a leaf item holds (bvh.h): on its packed
 * copy where there is one, else the polygon's own test. */
static inline double prim_test(const World *w, const Bvh *b, uint32_t k, uint32_t pi, const RayFrame *frame,
                               double tmax)
{
    (void)pi;
    return bvh_item_test(w, b, k, frame, tmax);
}

/* try_nearer for item k of hierarchy b, polygon id `id`, from its record. */
static inline void try_nearer_prim(Tracer *tr, const Bvh *b, const RayFrame *frame, uint32_t k, uint32_t id,
                                   int instance, double tmin, double plane_t, Hit *hit, double *best)
{
    if (b->prims[k].hide & tr->hide)
        return;
    tr->stats.polygon_tests++;
    double t = prim_test(tr->world, b, k, id, frame, test_limit(hit, *best, plane_t));
    if (t > tmin) {
        note_tie(tr, hit, *best, id, instance, t);
        take_nearer(hit, best, id, instance, t);
    }
}

/* Whether an instance's polygon pi (in World.polygons) is hidden from the
 * query: its material is the instance's. */
static inline int instance_hidden(const World *w, const Instance *in, uint32_t pi, unsigned hide)
{
    return material_hidden(&w->materials[instance_material(w, in, &w->polygons[pi])], hide);
}

/* The nearest polygon by the grid: cell by cell, a hit inside a cell
 * ending the walk. */
static void nearest_in_grid(Tracer *tr, Vec3 org, Vec3 dir, double tmin, double plane_t, int exclude, Hit *hit,
                            double *best)
{
    const World *w = tr->world;
    const Grid *g = tr->grid;
    GridWalk walk;
    if (w->npolygons == 0 || !grid_walk_begin(g, org, dir, 0.0, plane_t, &walk))
        return;
    uint32_t id = trace_new_segment(tr);
    RayFrame frame = ray_frame(org, dir);
    if (exclude >= 0)
        tr->stamp[exclude] = id;
    do {
        tr->stats.cells_visited++;
        int c = grid_cell_index(g, walk.cell);
        for (uint32_t k = g->cell_start[c]; k < g->cell_start[c + 1]; k++) {
            uint32_t pi = g->items[k];
            if (bucket_admit(tr, id, pi))
                try_nearer(tr, &frame, pi, tmin, plane_t, hit, best);
        }
        /* A hit inside this cell cannot be beaten by later cells. */
        if (hit->kind != HIT_NONE && *best <= grid_walk_exit(&walk))
            break;
        if (hit->kind != HIT_NONE && *best < walk.t_end)
            walk.t_end = *best;
    } while (grid_walk_next(g, &walk));
}

/* A node or leaf waiting on the traversal stack, and where the ray enters it. */
typedef struct {
    uint32_t child;
    double enter;
} Pending;

/* Pushes the children of node n the ray meets, nearest last so that it is
 * taken first. */
static inline int push_children(Pending *stack, int sp, const BvhNode *n, unsigned mask, const double *enter)
{
    /* Sorted where they will lie on the stack: sorting into a local array
     * and copying it over became a memcpy call per node (4% of desk.pov's
     * whole render). */
    Pending *hit = stack + sp;
    int m = 0;
    for (int k = 0; k < BVH_WIDTH; k++) {
        if (!(mask & (1u << k)) || n->child[k] == BVH_EMPTY)
            continue;
        /* Insertion by distance, farthest first. */
        int i = m++;
        while (i > 0 && hit[i - 1].enter < enter[k]) {
            hit[i] = hit[i - 1];
            i--;
        }
        hit[i].child = n->child[k];
        hit[i].enter = enter[k];
    }
    return sp + m;
}

/* The hierarchy's two traversals (bvh_traverse.h), once with the SSE2 box
 * test and once with AVX2's, which tracer_init chooses where the processor
 * has it: the same answers, bit for bit (bvh.h). */
#define BVH_TRAVERSE_NAME(f) f##_sse2
#define BVH_TRAVERSE_NODE_HITS bvh_node_hits
#define BVH_TRAVERSE_RAY(r, org, dir) (*(r) = bvh_ray(org, dir))
#define BVH_TRAVERSE_RAY_INV bvh_ray_inverse
#define BVH_TRAVERSE_TARGET
#include "bvh_traverse.h"
#undef BVH_TRAVERSE_NAME
#undef BVH_TRAVERSE_NODE_HITS
#undef BVH_TRAVERSE_RAY
#undef BVH_TRAVERSE_RAY_INV
#undef BVH_TRAVERSE_TARGET
#if BVH_HAVE_AVX2_PATH
#define BVH_TRAVERSE_NAME(f) f##_avx2
#define BVH_TRAVERSE_NODE_HITS bvh_node_hits_avx2
#define BVH_TRAVERSE_RAY bvh_ray_scalar
#define BVH_TRAVERSE_RAY_INV bvh_ray_scalar_inverse
#define BVH_TRAVERSE_TARGET __attribute__((target("avx2")))
#include "bvh_traverse.h"
#undef BVH_TRAVERSE_NAME
#undef BVH_TRAVERSE_NODE_HITS
#undef BVH_TRAVERSE_RAY
#undef BVH_TRAVERSE_RAY_INV
#undef BVH_TRAVERSE_TARGET
#else
#define nearest_in_bvh_avx2 nearest_in_bvh_sse2
#endif
/* The cells a segment pierces, recorded for the shadow buckets: those the
 * grid's own nearest-hit walk would visit (up to the cell holding the hit). */
static void record_cells(Tracer *tr, Vec3 org, Vec3 dir, double plane_t, const Hit *hit, double best)
{
    const Grid *g = tr->grid;
    GridWalk walk;
    tr->segment_ncells = 0;
    int overflow = 0;
    if (grid_walk_begin(g, org, dir, 0.0, plane_t, &walk)) {
        int polygon = hit->kind == HIT_POLYGON;
        if (polygon && best < walk.t_end)
            walk.t_end = best;
        do {
            if (tr->segment_ncells < tr->segment_cells_cap)
                tr->segment_cells[tr->segment_ncells++] = (uint32_t)grid_cell_index(g, walk.cell);
            else
                overflow = 1; /* cannot happen with 3DDDA; distrust the bucket if it did */
            if (polygon && best <= grid_walk_exit(&walk))
                break;
        } while (grid_walk_next(g, &walk));
    }
    /* The walk covered the whole segment only when its ends are in the box. */
    tr->segment_in_box = !overflow && hit->kind != HIT_NONE && inside_box(tr->record_min, tr->record_max, hit->point) &&
                         inside_box(tr->record_min, tr->record_max, org);
}

/* The nearest shape so far along a ray (trace_nearest): `best` starts at
 * the nearest plane's distance, which a shape must beat (the plane wins
 * ties, as with polygons); between shapes at one distance, the first in
 * the world's order, whatever order a walk meets them in. */
typedef struct {
    Tracer *tr;
    Vec3 org, dir;
    double best;
    int shape, part;
    int surface;          /* the primitive met: `shape`, or a part of it (a CSG object's) */
    int plane;            /* the nearest plane, which `best` starts at (-1: none) */
    int ray_made;         /* ray: made at the first untransformed sphere met */
    ShapeRay ray;
} NearestShape;

/* Two surfaces this near along a ray (relatively) are one surface to the
 * eye, and which of them a renderer shows there is its rounding's choice:
 * coincident surfaces (trace_coincident_material). */
#define COINCIDENT_WINDOW 1e-9

/* The material of the surface nearest so far in a shapes walk. */
static int nearest_shape_material(const NearestShape *ns)
{
    const World *w = ns->tr->world;
    return ns->shape >= 0 ? w->shapes[ns->surface].material : ns->plane >= 0 ? w->planes[ns->plane].material : -1;
}

/* Shape surface `surface` met at t in a shapes walk, beside the nearest so
 * far (before it is taken, if it is): within COINCIDENT_WINDOW of it, the
 * two are coincident, the one not kept remembered with its distance. */
static void note_shape_tie(NearestShape *ns, int surface, double t, int taken)
{
    if (ns->shape < 0 && ns->plane < 0)
        return;
    if (!(fabs(t - ns->best) <= COINCIDENT_WINDOW * ns->best))
        return;
    const World *w = ns->tr->world;
    if (ns->shape >= 0 && ns->surface == surface)
        return;
    ns->tr->tie_t = taken ? ns->best : t;
    ns->tr->tie_material = taken ? nearest_shape_material(ns) : w->shapes[surface].material;
}

/* The limit a shape's crossing must beat to be the nearest (an exact tie
 * kept for the lower index), and the window a little beyond it that the
 * shape is tested to, for the coincident surfaces there. */
static double shape_limit(const NearestShape *ns, int i)
{
    return ns->shape >= 0 && i < ns->shape ? nextafter(ns->best, HUGE_VAL) : ns->best;
}

static double shape_window(double limit) { return limit < HUGE_VAL ? limit * (1.0 + COINCIDENT_WINDOW) : limit; }

/* Shape i's crossing at t > 0 (within the window), on surface `surface`
 * and part `part`: noted if coincident with the nearest so far, and kept
 * if it is nearer (within the limit, as before the window). */
static void offer_shape(NearestShape *ns, int i, int surface, int part, double t, double limit, double *tmax)
{
    int taken = t < limit && (t < ns->best || i < ns->shape);
    note_shape_tie(ns, surface, t, taken);
    if (taken) {
        ns->best = t;
        ns->shape = i;
        ns->part = part;
        ns->surface = surface;
        *tmax = t;
    }
}

/* boxed: the walk has just met the shape's own box (bvh.h), a cull the
 * hierarchy already trusts to keep every crossing: shape_box_hit, the same
 * box grown otherwise, would cull again before the exact test (in marbles,
 * none of 640,000 rays). Left out, the exact test sees every ray it saw and
 * more, never fewer, and decides them as before (POV-Ray too tests an
 * object after its bounding box alone). */
static int nearer_shape(void *user, int i, int boxed, double *tmax)
{
    NearestShape *ns = user;
    const Shape *s = &ns->tr->world->shapes[i];
    double limit = shape_limit(ns, i), window = shape_window(limit);
    if (!boxed && !shape_box_hit(s, ns->org, ns->dir, window))
        return 0;
    ns->tr->stats.shape_tests++;
    ShapeHit h;
    double t = shape_nearest(s, ns->org, ns->dir, window, &h);
    if (t > 0.0)
        offer_shape(ns, i, h.leaf ? (int)(h.leaf - ns->tr->world->shapes) : i, h.part, t, limit, tmax);
    return 0;
}

/* nearer_shape, with an untransformed sphere's test by
 * shape_sphere_crossings (shape_nearest's answer, bit for bit: the nearest
 * of shape_intersect_all's crossings, on the ray made unit once for all the
 * spheres it meets) and its box tested only where it is crossed (the box
 * and the sphere decide together, in either order). tests/test_bvh.c
 * compares trace_nearest with shape_nearest on every shape. */
static int nearer_shape_fast(void *user, int i, int boxed, double *tmax)
{
    NearestShape *ns = user;
    const Shape *s = &ns->tr->world->shapes[i];
    if (s->kind != SHAPE_SPHERE || s->transformed)
        return nearer_shape(user, i, boxed, tmax);
    double limit = shape_limit(ns, i), window = shape_window(limit);
    if (!ns->ray_made) {
        shape_ray_init(&ns->ray, ns->org, ns->dir);
        ns->ray_made = 1;
    }
    ns->tr->stats.shape_tests++;
    double t[2];
    if (shape_sphere_crossings(s, &ns->ray, window, t) == 0 || (!boxed && !shape_box_hit(s, ns->org, ns->dir, window)))
        return 0;
    if (t[0] > 0.0)
        offer_shape(ns, i, i, SHAPE_SIDE, t[0], limit, tmax);
    return 0;
}

int trace_nearest(Tracer *tr, Vec3 org, Vec3 dir, double tmax, const Hit *from, Hit *hit)
{
    const World *w = tr->world;
    double tmin = trace_min_distance(org);
    hit->kind = HIT_NONE;
    hit->instance = -1;
    tr->tie_t = -1.0;

    /* Planes first: they bound the polygon query, and on an exact tie (a
     * box resting on a plane) the plane wins, as it does in POV-Ray, whose
     * bounding tree meets the infinite plane before the finite object. */
    double plane_t = tmax;
    int plane = -1;
    for (int i = 0; i < w->nplanes; i++) {
        if (from && from->kind == HIT_PLANE && from->index == i)
            continue;
        if (tr->hide && material_hidden(&w->materials[w->planes[i].material], tr->hide))
            continue;
        tr->stats.plane_tests++;
        double t = intersect_plane(&w->planes[i], org, dir);
        if (t > tmin && t < plane_t) {
            plane_t = t;
            plane = i;
        }
    }

    /* The shapes next, under the same bound: a shape nearer than every
     * plane bounds the polygon query in turn. */
    NearestShape ns; /* its ray left unset: made where a sphere needs it (ray_made) */
    ns.tr = tr;
    ns.org = org;
    ns.dir = dir;
    ns.best = plane_t;
    ns.shape = -1;
    ns.part = 0;
    ns.surface = -1;
    ns.plane = plane;
    ns.ray_made = 0;
    if (w->nshapes > 0) {
        if (tr->bvh && tr->bvh->shapes) {
            double limit = plane_t;
            bvh_shapes_nearest_walk(tr->bvh->shapes, org, dir, &limit, tr->hide, nearer_shape_fast, &ns,
                                    &tr->stats.nodes_visited, tr->avx2);
        } else {
            for (int i = 0; i < w->nshapes; i++) {
                double limit = ns.best;
                if (!(tr->hide && material_hidden(&w->materials[w->shapes[i].material], tr->hide)))
                    nearer_shape(&ns, i, 0, &limit);
            }
        }
        if (ns.shape >= 0) {
            plane_t = ns.best;
            plane = -1;
        }
    }
    const int shape = ns.shape, shape_part = ns.part, shape_surface = ns.surface;

    double best = HUGE_VAL;
    int exclude = (from && from->kind == HIT_POLYGON) ? from->index : -1;
    if (!tr->bvh)
        nearest_in_grid(tr, org, dir, tmin, plane_t, exclude, hit, &best);
    else if (tr->bvh->nnodes == 0) {
        /* no polygon: not even the walk's call (a world of shapes and planes) */
    } else if (tr->avx2)
        nearest_in_bvh_avx2(tr, tr->bvh, NULL, org, dir, NULL, tmin, plane_t, exclude, hit, &best);
    else
        nearest_in_bvh_sse2(tr, tr->bvh, NULL, org, dir, NULL, tmin, plane_t, exclude, hit, &best);
    if (hit->kind == HIT_NONE) {
        if (plane < 0 && shape < 0) {
            if (tr->segment_cells)
                tr->segment_in_box = 0;
            return 0;
        }
        hit->kind = shape >= 0 ? HIT_SHAPE : HIT_PLANE;
        hit->index = shape >= 0 ? shape_surface : plane;
        hit->part = shape_part;
        best = plane_t;
    } else {
        tr->stats.polygon_hits++;
        /* a polygon just nearer than the curved object or plane that
         * bounded its walk: coincident with it (one just beyond that
         * object is not looked for) */
        if ((shape >= 0 || plane >= 0) && fabs(plane_t - best) <= COINCIDENT_WINDOW * best) {
            tr->tie_t = plane_t;
            tr->tie_material = shape >= 0 ? w->shapes[shape_surface].material : w->planes[plane].material;
        }
    }
    hit->t = best;
    hit->point = v3_madd(org, dir, best);
    if (tr->segment_cells)
        record_cells(tr, org, dir, plane_t, hit, best);
    return 1;
}

int trace_segment_hits(Tracer *tr, Vec3 org, Vec3 dir, double tmin, double tmax, int exclude, unsigned hide,
                       TraceHitVisitor visit, void *user, uint64_t *tests)
{
    const World *w = tr->world;
    if (w->npolygons == 0 && w->ninstances == 0)
        return 0;
    if (tr->bvh) {
#if BVH_HAVE_AVX2_PATH
        if (tr->avx2)
            return segment_hits_in_bvh_avx2(tr, tr->bvh, NULL, org, dir, NULL, tmin, tmax, exclude, hide, visit, user,
                                            tests);
#endif
        return segment_hits_in_bvh_sse2(tr, tr->bvh, NULL, org, dir, NULL, tmin, tmax, exclude, hide, visit, user, tests);
    }
    RayFrame frame = ray_frame(org, dir);
    const Grid *g = tr->grid;
    GridWalk walk;
    if (!grid_walk_begin(g, org, dir, 0.0, tmax, &walk))
        return 0;
    uint32_t id = trace_new_segment(tr);
    if (exclude >= 0)
        tr->stamp[exclude] = id;
    do {
        int c = grid_cell_index(g, walk.cell);
        for (uint32_t k = g->cell_start[c]; k < g->cell_start[c + 1]; k++) {
            uint32_t pi = g->items[k];
            if (!bucket_admit(tr, id, pi))
                continue;
            if (hide && material_hidden(&w->materials[w->polygons[pi].material], hide))
                continue;
            ++*tests;
            double t = intersect_polygon_in(w, &w->polygons[pi], &frame, tmax);
            if (t > tmin && visit(user, pi, t))
                return 1;
        }
    } while (grid_walk_next(g, &walk));
    return 0;
}

int trace_instance_hits(Tracer *tr, int instance, Vec3 org, Vec3 dir, double tmin, double tmax, int exclude,
                        unsigned hide, TraceHitVisitor visit, void *user, uint64_t *tests)
{
    const Instance *in = &tr->world->instances[instance];
    const Bvh *b = &tr->bvh->protos[in->prototype];
    Vec3 lorg, ldir;
    tr->stats.instance_walks++;
    instance_ray(in, org, dir, &lorg, &ldir);
#if BVH_HAVE_AVX2_PATH
    if (tr->avx2)
        return segment_hits_in_bvh_avx2(tr, b, in, lorg, ldir, NULL, tmin, tmax, exclude, hide, visit, user, tests);
#endif
    return segment_hits_in_bvh_sse2(tr, b, in, lorg, ldir, NULL, tmin, tmax, exclude, hide, visit, user, tests);
}

int trace_coincident_material(const Tracer *t, const Hit *hit)
{
    if (t->tie_t < 0.0 || !(fabs(t->tie_t - hit->t) <= COINCIDENT_WINDOW * hit->t))
        return -1;
    int other = t->tie_material;
    int mine = hit_material(t->world, hit);
    const Material *m = t->world->materials;
    return other != mine && !materials_look_alike(&m[other], &m[mine]) ? other : -1;
}
