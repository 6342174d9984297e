/* Building the hierarchy (bvh.h): a binary tree, top-down by the binned
 * surface area heuristic over the polygons' bounding-box centres (Wald, "On
 * fast construction of SAH-based bounding volume hierarchies", 2007), then
 * collapsed into 4-wide nodes by pulling up the grandchildren of the
 * largest children (as Embree's BVH4 and Wald, Benthin and Boulos, "Getting
 * rid of packets", 2008, do). */
#include "bvh.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define BINS 16
#define LEAF_MAX 4        /* polygons a leaf may hold */
#define COST_TRAVERSE 1.0 /* SAH: one box test ... */
#define COST_INTERSECT 1.5 /* ... against one polygon test */

typedef struct {
    double lo[3], hi[3];
} Box;

/* A node of the binary tree the build makes first. */
typedef struct {
    Box box;
    uint32_t index;       /* interior: the second child (the first follows); leaf: first item */
    uint16_t count;       /* 0 for an interior node */
} BinNode;

static void box_empty(Box *b)
{
    for (int a = 0; a < 3; a++) {
        b->lo[a] = HUGE_VAL;
        b->hi[a] = -HUGE_VAL;
    }
}

static void box_grow(Box *b, const Box *c)
{
    for (int a = 0; a < 3; a++) {
        if (c->lo[a] < b->lo[a])
            b->lo[a] = c->lo[a];
        if (c->hi[a] > b->hi[a])
            b->hi[a] = c->hi[a];
    }
}

static double box_area(const Box *b)
{
    double e[3];
    for (int a = 0; a < 3; a++)
        e[a] = b->hi[a] > b->lo[a] ? b->hi[a] - b->lo[a] : 0.0;
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

typedef struct {
    const World *w;
    Box *boxes;           /* per polygon */
    double (*centre)[3];  /* per polygon */
    uint32_t *items;
    BinNode *nodes;
    int nnodes, cap;
    int depth;
} Builder;

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


/* items[first, first + count): one subtree. Returns 0, or -1 when out of memory. */
static int build(Builder *bd, int first, int count, int depth)
{
    int ni = new_node(bd);
    if (ni < 0)
        return -1;
    if (depth > bd->depth)
        bd->depth = depth;
    Box bounds, cbounds;
    box_empty(&bounds);
    box_empty(&cbounds);
    for (int i = first; i < first + count; i++) {
        uint32_t p = bd->items[i];
        box_grow(&bounds, &bd->boxes[p]);
        Box c = { { bd->centre[p][0], bd->centre[p][1], bd->centre[p][2] },
                  { bd->centre[p][0], bd->centre[p][1], bd->centre[p][2] } };
        box_grow(&cbounds, &c);
    }
    bd->nodes[ni].box = bounds;

    /* The best binned split over the three axes; below a depth that a
     * pathological scene could reach, plain halving by index keeps the
     * hierarchy within BVH_MAX_DEPTH. */
    int best_axis = -1, best_bin = 0;
    double best_cost = COST_INTERSECT * count;
    int halve_only = depth >= BVH_MAX_DEPTH - 24;
    if (count > 1 && !halve_only) {
        double leaf_area = box_area(&bounds);
        for (int a = 0; a < 3; a++) {
            double lo = cbounds.lo[a], ext = cbounds.hi[a] - lo;
            if (!(ext > 0.0))
                continue;
            int n[BINS] = { 0 };
            Box b[BINS];
            for (int k = 0; k < BINS; k++)
                box_empty(&b[k]);
            double scale = BINS / ext;
            for (int i = first; i < first + count; i++) {
                uint32_t p = bd->items[i];
                int k = (int)((bd->centre[p][a] - lo) * scale);
                k = k < 0 ? 0 : k >= BINS ? BINS - 1 : k;
                n[k]++;
                box_grow(&b[k], &bd->boxes[p]);
            }
            /* Sweep: areas and counts left of each boundary, then right. */
            double left_area[BINS];
            int left_n[BINS];
            Box acc;
            box_empty(&acc);
            int s = 0;
            for (int k = 0; k < BINS - 1; k++) {
                box_grow(&acc, &b[k]);
                s += n[k];
                left_area[k] = box_area(&acc);
                left_n[k] = s;
            }
            box_empty(&acc);
            s = 0;
            for (int k = BINS - 1; k > 0; k--) {
                box_grow(&acc, &b[k]);
                s += n[k];
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
    if (best_axis < 0 || best_cost >= COST_INTERSECT * count) {
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
            if (cbounds.hi[k] - cbounds.lo[k] > cbounds.hi[a] - cbounds.lo[a])
                a = k;
        best_axis = a;
        best_bin = !halve_only && cbounds.hi[a] > cbounds.lo[a] ? BINS / 2 : -1;
    }

    /* Partition: items whose centre falls in a bin below best_bin go left. */
    int mid;
    if (best_bin < 0) {
        mid = first + count / 2;
    } else {
        double lo = cbounds.lo[best_axis], scale = BINS / (cbounds.hi[best_axis] - lo);
        int i = first, j = first + count - 1;
        while (i <= j) {
            uint32_t p = bd->items[i];
            int k = (int)((bd->centre[p][best_axis] - lo) * scale);
            k = k < 0 ? 0 : k >= BINS ? BINS - 1 : k;
            if (k < best_bin) {
                i++;
            } else {
                bd->items[i] = bd->items[j];
                bd->items[j--] = p;
            }
        }
        mid = i;
        if (mid == first || mid == first + count)
            mid = first + count / 2; /* cannot happen with a positive-cost split; stay safe */
    }
    if (build(bd, first, mid - first, depth + 1))
        return -1;
    int second = bd->nnodes;
    if (build(bd, mid, first + count - mid, depth + 1))
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
        n->lo[a][k] = round_down(b->lo[a]);
        n->hi[a][k] = round_up(b->hi[a]);
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

int bvh_build(Bvh *b, const World *w)
{
    memset(b, 0, sizeof *b);
    int n = w->npolygons;
    Builder bd;
    memset(&bd, 0, sizeof bd);
    bd.w = w;
    bd.boxes = malloc(sizeof *bd.boxes * (size_t)(n > 0 ? n : 1));
    bd.centre = malloc(sizeof *bd.centre * (size_t)(n > 0 ? n : 1));
    bd.items = malloc(sizeof *bd.items * (size_t)(n > 0 ? n : 1));
    if (!bd.boxes || !bd.centre || !bd.items) {
        free(bd.boxes);
        free(bd.centre);
        free(bd.items);
        return -1;
    }
    for (int i = 0; i < n; i++) {
        const Polygon *p = &w->polygons[i];
        Box *bx = &bd.boxes[i];
        bx->lo[0] = p->bbox_min.x;
        bx->lo[1] = p->bbox_min.y;
        bx->lo[2] = p->bbox_min.z;
        bx->hi[0] = p->bbox_max.x;
        bx->hi[1] = p->bbox_max.y;
        bx->hi[2] = p->bbox_max.z;
        for (int a = 0; a < 3; a++)
            bd.centre[i][a] = 0.5 * (bx->lo[a] + bx->hi[a]);
        bd.items[i] = (uint32_t)i;
    }
    int failed = n > 0 && build(&bd, 0, n, 1);
    free(bd.boxes);
    free(bd.centre);
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
        free(bd.items);
        free(c.nodes);
        return -1;
    }
    b->nodes = c.nodes;
    b->nnodes = c.nnodes;
    b->items = bd.items;
    b->nitems = n;
    b->depth = c.depth;
    return 0;
}

void bvh_free(Bvh *b)
{
    free(b->nodes);
    free(b->items);
    memset(b, 0, sizeof *b);
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
