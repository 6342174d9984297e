/* A bounding volume hierarchy over the world's polygons, for the ray queries
 * of objects (nearest hit) and the shadow ray (every hit up to the light):
 * binned SAH, 32-byte nodes in depth-first order, boxes in float rounded
 * outward, tested conservatively in double, so that no polygon the exact
 * test would hit is ever culled. The polygons themselves are still decided
 * by the watertight double test (intersect.h); the hierarchy only chooses
 * which to ask, so every decision is the exact test's.
 *
 * The uniform grid (grid.h) stays: it is the home of the shadow polygons
 * and of the paper's buckets, and the reference the queries are tested
 * against (tests/test_bvh.c). */
#ifndef HST_BVH_H
#define HST_BVH_H

#include <stdint.h>

#include "world.h"

typedef struct {
    float lo[3], hi[3];
    /* Interior: the second child's index (the first is the next node);
     * leaf: the first of `count` entries of Bvh.items. */
    uint32_t index;
    uint16_t count;       /* 0 for an interior node */
    uint16_t axis;        /* interior: the axis its children were split on */
} BvhNode;

typedef struct {
    BvhNode *nodes;
    int nnodes;
    uint32_t *items;      /* polygon indices, leaf by leaf */
    int nitems;
    int depth;            /* of the deepest leaf */
} Bvh;

/* Builds over every polygon of w (an empty hierarchy for none). Returns 0,
 * or -1 when out of memory. */
int bvh_build(Bvh *b, const World *w);
void bvh_free(Bvh *b);

/* The deepest a traversal stack needs to be. */
#define BVH_MAX_DEPTH 64

/* A ray as the box tests want it: the origin, and per axis the inverse
 * direction and which slab face is met first. */
typedef struct {
    double org[3], inv[3];
    int neg[3];
} BvhRay;

BvhRay bvh_ray(Vec3 org, Vec3 dir);

/* Does the ray meet the node's box for some t in [t0, t1]? Conservative:
 * true whenever an exact computation would say so (and sometimes near it).
 * *t_enter: where it enters (for ordering). */
static inline int bvh_node_hit(const BvhNode *n, const BvhRay *r, double t0, double t1, double *t_enter)
{
    /* Slab test; the far distances grow by 2 gamma(3) of rounding as in
     * pbrt-v4 (Pharr, Jakob, Humphreys, sec. 6.8), so the result is
     * conservative for any rounding of the subtractions and products. The
     * caller's far limit grows alike: an entry computed a few ulps beyond
     * it may be exactly at it (a tie the caller must still see). */
    const double grow = 1.0 + 2.0 * (3.0 * 0x1p-53) / (1.0 - 3.0 * 0x1p-53);
    t1 *= grow;
    for (int a = 0; a < 3; a++) {
        double lo = r->neg[a] ? n->hi[a] : n->lo[a];
        double hi = r->neg[a] ? n->lo[a] : n->hi[a];
        double tn = (lo - r->org[a]) * r->inv[a];
        double tf = (hi - r->org[a]) * r->inv[a] * grow;
        if (tn > t0)
            t0 = tn;
        if (tf < t1)
            t1 = tf;
    }
    *t_enter = t0;
    return t0 <= t1;
}

#endif
