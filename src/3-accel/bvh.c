/* Building the hierarchy (bvh.h): a binary tree, top-down by the binned
 * surface area heuristic over the polygons' bounding-box centres (Wald, "On
 * fast construction of SAH-based bounding volume hierarchies", 2007), then
 * collapsed into 4-wide nodes by pulling up the grandchildren of the
 * largest children (as Embree's BVH4 and Wald, Benthin and Boulos, "Getting
 * rid of packets", 2008, do). */
#include "bvh.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#define BINS 16
#define LEAF_MAX 4        /* polygons a leaf may hold */
#define COST_TRAVERSE 1.0 /* SAH: one box test ... */
#define COST_INTERSECT 1.5 /* ... against one polygon test */

/* A box in float, as the nodes keep them (bounds rounded outward). */
typedef struct {
    float lo[3], hi[3];
} Box;

static inline void box_empty(Box *b)
{
    for (int a = 0; a < 3; a++) {
        b->lo[a] = HUGE_VALF;
        b->hi[a] = -HUGE_VALF;
    }
}

static inline void box_grow(Box *b, const float lo[3], const float hi[3])
{
    for (int a = 0; a < 3; a++) {
        b->lo[a] = lo[a] < b->lo[a] ? lo[a] : b->lo[a];
        b->hi[a] = hi[a] > b->hi[a] ? hi[a] : b->hi[a];
    }
}

static inline void box_join(Box *b, const Box *c) { box_grow(b, c->lo, c->hi); }

static inline double box_area(const Box *b)
{
    double e[3];
    for (int a = 0; a < 3; a++)
        e[a] = b->hi[a] > b->lo[a] ? (double)b->hi[a] - (double)b->lo[a] : 0.0;
    return 2.0 * (e[0] * e[1] + e[1] * e[2] + e[2] * e[0]);
}

/* The float nearest x on the side away from the box's inside. */
static float round_down(double x)
{
    float f = (float)x;
    return (double)f > x ? nextafterf(f, -HUGE_VALF) : f;
}

static float round_up(double x)
{
    float f = (float)x;
    return (double)f < x ? nextafterf(f, HUGE_VALF) : f;
}

/* A polygon as the build moves it: its box and centre, records partitioned
 * in place so that every pass reads memory in order. */
typedef struct {
    float lo[3], hi[3], centre[3];
    uint32_t polygon;
} BuildItem;

/* A node of the binary tree the build makes first. */
typedef struct {
    Box box;
    uint32_t index;       /* interior: the second child (the first follows); leaf: first item */
    uint16_t count;       /* 0 for an interior node */
} BinNode;

typedef struct {
    BuildItem *items;
    BinNode *nodes;
    int nnodes, cap;
    int depth;
    int threads;          /* this builder may hand subtrees to threads of its own, up to this many in all */
} Builder;

/* Subtrees of fewer items are built on the thread that reaches them. */
#define PARALLEL_MIN 20000

static int new_node(Builder *bd)
{
    if (bd->nnodes == bd->cap) {
        int cap = bd->cap ? bd->cap * 2 : 64;
        BinNode *n = realloc(bd->nodes, sizeof *n * (size_t)cap);
        if (!n)
            return -1;
        bd->nodes = n;
        bd->cap = cap;
    }
    return bd->nnodes++;
}

/* The bin of centre coordinate c. A coordinate beyond float's range is
 * infinite in the build records, and an infinite centre gives NaN here: it
 * goes to the first bin (converting NaN to an int would be undefined). */
static inline int bin_of(float c, float lo, float scale)
{
    float x = (c - lo) * scale;
    return x >= 0.0f ? (x < (float)BINS ? (int)x : BINS - 1) : 0;
}

/* items[first, first + count), whose boxes' union is `bounds` and whose
 * centres' is `cbounds`: one subtree. Returns 0, or -1 when out of memory. */
static int build(Builder *bd, int first, int count, int depth, const Box *bounds, const Box *cbounds);

/* The second half of a split built on a thread of its own, into a builder
 * of its own (the items are shared: the halves are disjoint). */
typedef struct {
    Builder sub;
    int first, count, depth;
    Box bounds, cbounds;
    int failed;
} Half;

static void *build_half(void *arg)
{
    Half *h = arg;
    h->failed = build(&h->sub, h->first, h->count, h->depth, &h->bounds, &h->cbounds);
    return NULL;
}

/* Both halves of a split: the second on another thread when it is big and
 * threads are left, its nodes then appended after the first's, so that the
 * layout is the one a single thread makes. Returns the second's root
 * index, or -1 when out of memory. */
static int build_halves(Builder *bd, int first, int mid, int count, int depth, const Box *lb, const Box *lcb,
                        const Box *rb, const Box *rcb)
{
    pthread_t tid;
    Half h;
    int spawned = 0;
    if (bd->threads > 1 && count - mid >= PARALLEL_MIN && mid >= PARALLEL_MIN) {
        memset(&h, 0, sizeof h);
        h.sub.items = bd->items;
        h.sub.threads = bd->threads / 2;
        h.first = first + mid;
        h.count = count - mid;
        h.depth = depth;
        h.bounds = *rb;
        h.cbounds = *rcb;
        spawned = pthread_create(&tid, NULL, build_half, &h) == 0;
    }
    if (!spawned) {
        if (build(bd, first, mid, depth, lb, lcb))
            return -1;
        int second = bd->nnodes;
        if (build(bd, first + mid, count - mid, depth, rb, rcb))
            return -1;
        return second;
    }
    int keep = bd->threads;
    bd->threads -= h.sub.threads;
    int failed = build(bd, first, mid, depth, lb, lcb);
    bd->threads = keep;
    pthread_join(tid, NULL);
    int second = bd->nnodes;
    if (!failed && !h.failed) {
        while (bd->cap < bd->nnodes + h.sub.nnodes) {
            int cap = bd->cap ? bd->cap * 2 : 64;
            BinNode *n = realloc(bd->nodes, sizeof *n * (size_t)cap);
            if (!n) {
                failed = 1;
                break;
            }
            bd->nodes = n;
            bd->cap = cap;
        }
    }
    if (failed || h.failed) {
        free(h.sub.nodes);
        return -1;
    }
    for (int i = 0; i < h.sub.nnodes; i++) {
        BinNode node = h.sub.nodes[i];
        if (node.count == 0)
            node.index += (uint32_t)second; /* the second child, moved along */
        bd->nodes[second + i] = node;
    }
    bd->nnodes += h.sub.nnodes;
    if (h.sub.depth > bd->depth)
        bd->depth = h.sub.depth;
    free(h.sub.nodes);
    return second;
}

static int build(Builder *bd, int first, int count, int depth, const Box *bounds, const Box *cbounds)
{
    int ni = new_node(bd);
    if (ni < 0)
        return -1;
    if (depth > bd->depth)
        bd->depth = depth;
    bd->nodes[ni].box = *bounds;
    BuildItem *it = bd->items + first;

    /* The best binned split over the three axes, binned in one pass; below
     * a depth that a pathological scene could reach, plain halving by index
     * keeps the hierarchy within BVH_MAX_DEPTH. */
    int best_axis = -1, best_bin = 0;
    double best_cost = COST_INTERSECT * count;
    int halve_only = depth >= BVH_MAX_DEPTH - 24;
    float scale[3];
    int splittable[3];
    for (int a = 0; a < 3; a++) {
        float ext = cbounds->hi[a] - cbounds->lo[a];
        splittable[a] = ext > 0.0f && ext < HUGE_VALF && (float)BINS / ext < HUGE_VALF;
        scale[a] = splittable[a] ? (float)BINS / ext : 0.0f;
    }
    /* Per axis and bin: the items and their boxes' union. */
    int n[3][BINS];
    Box b[3][BINS];
    if (count > 1 && !halve_only) {
        for (int a = 0; a < 3; a++)
            for (int k = 0; k < BINS; k++) {
                n[a][k] = 0;
                box_empty(&b[a][k]);
            }
        for (int i = 0; i < count; i++)
            for (int a = 0; a < 3; a++) {
                int k = bin_of(it[i].centre[a], cbounds->lo[a], scale[a]);
                n[a][k]++;
                box_grow(&b[a][k], it[i].lo, it[i].hi);
            }
        double leaf_area = box_area(bounds);
        for (int a = 0; a < 3; a++) {
            if (!splittable[a])
                continue;
            /* Sweep: areas and counts left of each boundary, then right. */
            double left_area[BINS];
            int left_n[BINS];
            Box acc;
            box_empty(&acc);
            int s = 0;
            for (int k = 0; k < BINS - 1; k++) {
                box_join(&acc, &b[a][k]);
                s += n[a][k];
                left_area[k] = box_area(&acc);
                left_n[k] = s;
            }
            box_empty(&acc);
            s = 0;
            for (int k = BINS - 1; k > 0; k--) {
                box_join(&acc, &b[a][k]);
                s += n[a][k];
                int nl = left_n[k - 1];
                if (nl == 0 || s == 0)
                    continue;
                double cost = COST_TRAVERSE +
                              COST_INTERSECT * (left_area[k - 1] * nl + box_area(&acc) * s) / leaf_area;
                if (cost < best_cost) {
                    best_cost = cost;
                    best_axis = a;
                    best_bin = k;
                }
            }
        }
    }
    int by_sah = best_axis >= 0 && best_cost < COST_INTERSECT * count;
    if (!by_sah) {
        if (count <= LEAF_MAX) {
            bd->nodes[ni].index = (uint32_t)first;
            bd->nodes[ni].count = (uint16_t)count;
            return 0;
        }
        /* Too many for a leaf: halve along the centres' widest axis (both
         * halves get some, the extreme centres fall in the end bins), or
         * by index where the centres coincide. */
        int a = 0;
        for (int k = 1; k < 3; k++)
            if (cbounds->hi[k] - cbounds->lo[k] > cbounds->hi[a] - cbounds->lo[a])
                a = k;
        best_axis = a;
        best_bin = !halve_only && splittable[a] ? BINS / 2 : -1;
    }

    /* Partition: items whose centre falls in a bin below best_bin go left;
     * the halves' bounds come with them. */
    int mid;
    Box lb, lcb, rb, rcb;
    box_empty(&lb);
    box_empty(&lcb);
    box_empty(&rb);
    box_empty(&rcb);
    if (best_bin < 0) {
        mid = count / 2;
        for (int i = 0; i < count; i++) {
            box_grow(i < mid ? &lb : &rb, it[i].lo, it[i].hi);
            box_grow(i < mid ? &lcb : &rcb, it[i].centre, it[i].centre);
        }
    } else {
        int a = best_axis;
        int i = 0, j = count - 1;
        while (i <= j) {
            if (bin_of(it[i].centre[a], cbounds->lo[a], scale[a]) < best_bin) {
                box_grow(&lb, it[i].lo, it[i].hi);
                box_grow(&lcb, it[i].centre, it[i].centre);
                i++;
            } else {
                BuildItem t = it[i];
                it[i] = it[j];
                it[j--] = t;
            }
        }
        mid = i;
        for (int k = mid; k < count; k++) {
            box_grow(&rb, it[k].lo, it[k].hi);
            box_grow(&rcb, it[k].centre, it[k].centre);
        }
        if (mid == 0 || mid == count) {
            /* cannot happen with both halves non-empty by construction; stay safe */
            mid = count / 2;
            box_empty(&lb);
            box_empty(&lcb);
            box_empty(&rb);
            box_empty(&rcb);
            for (int k = 0; k < count; k++) {
                box_grow(k < mid ? &lb : &rb, it[k].lo, it[k].hi);
                box_grow(k < mid ? &lcb : &rcb, it[k].centre, it[k].centre);
            }
        }
    }
    int second = build_halves(bd, first, mid, count, depth + 1, &lb, &lcb, &rb, &rcb);
    if (second < 0)
        return -1;
    bd->nodes[ni].index = (uint32_t)second;
    bd->nodes[ni].count = 0;
    return 0;
}

/* ---- collapsing into 4-wide nodes --------------------------------------- */

typedef struct {
    const BinNode *bin;
    BvhNode *nodes;
    int nnodes, cap;
    int depth;
} Collapser;

static void set_child_box(BvhNode *n, int k, const Box *b)
{
    for (int a = 0; a < 3; a++) {
        n->lo[a][k] = b->lo[a];
        n->hi[a][k] = b->hi[a];
    }
}

/* The 4-wide node for binary interior node bi; returns its index, or -1
 * when out of memory. */
static int collapse(Collapser *c, uint32_t bi, int depth)
{
    if (c->nnodes == c->cap) {
        int cap = c->cap ? c->cap * 2 : 64;
        BvhNode *n = realloc(c->nodes, sizeof *n * (size_t)cap);
        if (!n)
            return -1;
        c->nodes = n;
        c->cap = cap;
    }
    int ni = c->nnodes++;
    if (depth > c->depth)
        c->depth = depth;
    /* The two children, then, while there is room, the largest interior
     * one replaced by its own two. */
    uint32_t kids[BVH_WIDTH];
    int n = 2;
    kids[0] = bi + 1;
    kids[1] = c->bin[bi].index;
    while (n < BVH_WIDTH) {
        int best = -1;
        double best_area = -1.0;
        for (int k = 0; k < n; k++) {
            const BinNode *b = &c->bin[kids[k]];
            double area = box_area(&b->box);
            if (b->count == 0 && area > best_area) {
                best = k;
                best_area = area;
            }
        }
        if (best < 0)
            break;
        uint32_t x = kids[best];
        kids[best] = x + 1;
        kids[n++] = c->bin[x].index;
    }
    BvhNode node;
    for (int k = 0; k < BVH_WIDTH; k++) {
        node.child[k] = BVH_EMPTY;
        for (int a = 0; a < 3; a++) {
            node.lo[a][k] = HUGE_VALF; /* an empty box: no ray meets it */
            node.hi[a][k] = -HUGE_VALF;
        }
    }
    for (int k = 0; k < n; k++) {
        const BinNode *b = &c->bin[kids[k]];
        set_child_box(&node, k, &b->box);
        if (b->count) {
            node.child[k] = BVH_LEAF | (uint32_t)(b->count - 1) << BVH_COUNT_SHIFT | b->index;
        } else {
            int sub = collapse(c, kids[k], depth + 1);
            if (sub < 0)
                return -1;
            node.child[k] = (uint32_t)sub;
        }
    }
    c->nodes[ni] = node;
    return ni;
}

int bvh_build(Bvh *b, const World *w, int threads)
{
    memset(b, 0, sizeof *b);
    int n = w->npolygons;
    Builder bd;
    memset(&bd, 0, sizeof bd);
    bd.threads = threads > 1 ? threads : 1;
    bd.items = malloc(sizeof *bd.items * (size_t)(n > 0 ? n : 1));
    uint32_t *order = malloc(sizeof *order * (size_t)(n > 0 ? n : 1));
    if (!bd.items || !order) {
        free(bd.items);
        free(order);
        return -1;
    }
    Box bounds, cbounds;
    box_empty(&bounds);
    box_empty(&cbounds);
    for (int i = 0; i < n; i++) {
        const Polygon *p = &w->polygons[i];
        BuildItem *it = &bd.items[i];
        double lo[3] = { p->bbox_min.x, p->bbox_min.y, p->bbox_min.z };
        double hi[3] = { p->bbox_max.x, p->bbox_max.y, p->bbox_max.z };
        for (int a = 0; a < 3; a++) {
            it->lo[a] = round_down(lo[a]);
            it->hi[a] = round_up(hi[a]);
            it->centre[a] = (float)(0.5 * (lo[a] + hi[a]));
        }
        it->polygon = (uint32_t)i;
        box_grow(&bounds, it->lo, it->hi);
        box_grow(&cbounds, it->centre, it->centre);
    }
    int failed = n > 0 && build(&bd, 0, n, 1, &bounds, &cbounds);
    for (int i = 0; i < n && !failed; i++)
        order[i] = bd.items[i].polygon;
    free(bd.items);
    Collapser c;
    memset(&c, 0, sizeof c);
    c.bin = bd.nodes;
    if (!failed && n > 0) {
        if (bd.nodes[0].count) {
            /* A single leaf: a root with one child. */
            BvhNode node;
            for (int k = 0; k < BVH_WIDTH; k++) {
                node.child[k] = BVH_EMPTY;
                for (int a = 0; a < 3; a++) {
                    node.lo[a][k] = HUGE_VALF;
                    node.hi[a][k] = -HUGE_VALF;
                }
            }
            set_child_box(&node, 0, &bd.nodes[0].box);
            node.child[0] = BVH_LEAF | (uint32_t)(bd.nodes[0].count - 1) << BVH_COUNT_SHIFT;
            c.nodes = malloc(sizeof *c.nodes);
            failed = !c.nodes;
            if (c.nodes) {
                c.nodes[0] = node;
                c.nnodes = 1;
                c.depth = 1;
            }
        } else {
            failed = collapse(&c, 0, 1) < 0;
        }
    }
    free(bd.nodes);
    if (failed) {
        free(order);
        free(c.nodes);
        return -1;
    }
    BvhPrim *prims = malloc(sizeof *prims * (size_t)(n > 0 ? n : 1));
    PackedPolygon *packed = n <= BVH_PACK_MAX ? malloc(sizeof *packed * (size_t)(n > 0 ? n : 1)) : NULL;
    if (!prims || (n <= BVH_PACK_MAX && !packed)) {
        free(prims);
        free(packed);
        free(order);
        free(c.nodes);
        return -1;
    }
    for (int k = 0; k < n; k++) {
        const Polygon *p = &w->polygons[order[k]];
        const Material *m = &w->materials[p->material];
        BvhPrim *pr = &prims[k];
        pr->hide = (m->no_image ? HIDE_NO_IMAGE : 0u) | (m->no_reflection ? HIDE_NO_REFLECTION : 0u) |
                   (m->no_shadow ? HIDE_NO_SHADOW : 0u);
        pr->packed = packed ? (uint32_t)polygon_pack(w, p, &packed[k]) : 0u;
    }
    b->prims = prims;
    b->packed = packed;
    b->nodes = c.nodes;
    b->nnodes = c.nnodes;
    b->items = order;
    b->nitems = n;
    b->depth = c.depth;
    return 0;
}

void bvh_free(Bvh *b)
{
    free(b->nodes);
    free(b->items);
    free(b->prims);
    free(b->packed);
    memset(b, 0, sizeof *b);
}

int bvh_have_avx2(void)
{
#if BVH_HAVE_AVX2_PATH
    return __builtin_cpu_supports("avx2") != 0;
#else
    return 0;
#endif
}

BvhRay bvh_ray(Vec3 org, Vec3 dir)
{
    BvhRay r;
    double o[3] = { org.x, org.y, org.z }, d[3] = { dir.x, dir.y, dir.z };
    for (int a = 0; a < 3; a++) {
        r.org[a] = o[a];
        r.inv[a] = 1.0 / d[a];
        r.neg[a] = signbit(r.inv[a]) != 0;
#if defined(__SSE2__)
        r.org2[a] = _mm_set1_pd(r.org[a]);
        r.inv2[a] = _mm_set1_pd(r.inv[a]);
#endif
    }
    return r;
}

void bvh_ray_scalar(BvhRay *r, Vec3 org, Vec3 dir)
{
    const double o[3] = { org.x, org.y, org.z }, d[3] = { dir.x, dir.y, dir.z };
    for (int a = 0; a < 3; a++) {
        r->org[a] = o[a];
        r->inv[a] = 1.0 / d[a];
        r->neg[a] = signbit(r->inv[a]) != 0;
    }
}

unsigned bvh_node_hits_plain(const BvhNode *n, const BvhRay *r, double t0, double t1, double enter[BVH_WIDTH])
{
    unsigned mask = 0;
    double limit = t1 * BVH_GROW;
    for (int k = 0; k < BVH_WIDTH; k++) {
        double near = t0, far = limit;
        for (int a = 0; a < 3; a++) {
            double lo = r->neg[a] ? n->hi[a][k] : n->lo[a][k];
            double hi = r->neg[a] ? n->lo[a][k] : n->hi[a][k];
            double tn = (lo - r->org[a]) * r->inv[a];
            double tf = (hi - r->org[a]) * r->inv[a] * BVH_GROW;
            near = tn > near ? tn : near; /* NaN: not taken */
            far = tf < far ? tf : far;
        }
        enter[k] = near;
        if (near <= far)
            mask |= 1u << k;
    }
    return mask;
}
