/* A bounding volume hierarchy over the world's polygons, for the ray queries
 * of objects (nearest hit) and the shadow ray (every hit up to the light):
 * binned SAH, then 4-wide nodes whose children's boxes are kept side by side
 * (structure of arrays) so that one step tests all four. Boxes are stored in
 * float rounded outward and tested conservatively in double, so that no
 * polygon the exact test would hit is ever culled; the polygons themselves
 * are decided by the watertight double test (intersect.h), so every
 * decision is the exact test's.
 *
 * The uniform grid (grid.h) stays: it is the home of the shadow polygons
 * and of the paper's buckets, and the reference the queries are tested
 * against (tests/test_bvh.c). */
#ifndef HST_BVH_H
#define HST_BVH_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "intersect.h"
#include "world.h"

#define BVH_WIDTH 4

/* A child: BVH_EMPTY, a node index, or a leaf of 1 to 8 polygons: BVH_LEAF,
 * the count less one in bits 28-30, the first of them (in Bvh.items) below. */
#define BVH_EMPTY 0xFFFFFFFFu
#define BVH_LEAF 0x80000000u
#define BVH_COUNT_SHIFT 28
#define BVH_FIRST_MASK 0x0FFFFFFFu

static inline int bvh_is_leaf(uint32_t child) { return child != BVH_EMPTY && (child & BVH_LEAF); }
static inline uint32_t bvh_leaf_first(uint32_t child) { return child & BVH_FIRST_MASK; }
static inline uint32_t bvh_leaf_count(uint32_t child) { return ((child >> BVH_COUNT_SHIFT) & 7u) + 1u; }

typedef struct {
    float lo[3][BVH_WIDTH], hi[3][BVH_WIDTH]; /* per axis, per child; empty slots +inf..-inf */
    uint32_t child[BVH_WIDTH];
} BvhNode;

/* Objects a ray passes through (Tracer.hide, trace_segment_hits): no_image
 * ones for image rays, no_reflection ones for reflection rays, no_shadow
 * ones for shadow rays. */
enum { HIDE_NO_IMAGE = 1u, HIDE_NO_REFLECTION = 2u, HIDE_NO_SHADOW = 4u };

/* What a leaf's test needs of one polygon, beside it in leaf order: the
 * HIDE_* bits its material answers to, and whether Bvh.packed holds its
 * plane and points (a triangle or a polygon of one short outline): the
 * leaf test then reads that record rather than the polygon, its material
 * and its points (fewer loads per test; the same arithmetic, so the same
 * answers, intersect.h). */
typedef struct {
    uint32_t hide;        /* HIDE_* bits of its material */
    uint32_t packed;      /* 1: Bvh.packed[k] holds it; 0: test the polygon itself */
} BvhPrim;

/* The most polygons whose packed copies a hierarchy keeps: each costs
 * about 130 bytes, a few per cent of speed on small scenes and, measured
 * on 10^6 triangles, 90 MB and half a second of building for nothing
 * there (the polygons of a big mesh are in cache no more than their
 * copies). */
#define BVH_PACK_MAX (1 << 17)

/* A leaf item that is an instance (World.instances, in the low bits) rather
 * than a polygon: the top level's only (instance.h). */
#define BVH_INSTANCE 0x80000000u

typedef struct Bvh Bvh;
struct Bvh {
    BvhNode *nodes;       /* nodes[0] is the root (none when there are no polygons) */
    int nnodes;
    uint32_t *items;      /* polygon indices (or BVH_INSTANCE | instance), leaf by leaf */
    BvhPrim *prims;       /* prims[k] for polygon items[k] */
    PackedPolygon *packed; /* packed[k] where prims[k].packed; NULL above BVH_PACK_MAX polygons */
    int nitems;
    int depth;            /* of the deepest node */
    /* The top level's: one hierarchy per prototype (World.prototypes),
     * over its polygons in its own space; its items are their indices in
     * World.polygons, its prims hide nothing (the instance's walk does). */
    Bvh *protos;
    int nprotos;
    /* The top level's: instance i's box as the build saw it (rounded
     * outward, with the margin), lo[3] then hi[3], at 6 i: an instance
     * has a leaf of its own (so the node test tests its box), but where a
     * leaf holds more (a degenerate split) its box is tested before its
     * walk. */
    float *instance_box;
    /* The top level's: a hierarchy of its own over the world's shapes
     * (World.shapes; its items are their indices, its prims their
     * materials' HIDE_* bits), or NULL: none. The shapes are apart from
     * the polygons because every shadow method hands them to the shadow
     * ray's own test (shadow.h), while its own structures hold polygons. */
    Bvh *shapes;
};

/* Calls visit(user, shape) for every shape of hierarchy b (Bvh.shapes)
 * whose box the ray org + t dir meets for some t in [0, tmax]
 * (conservatively), its material not hiding it by `hide` (HIDE_*), until
 * visit returns 1 (then 1); *nodes counts the boxes tested. visit may
 * lower *tmax (a nearest-hit query: farther boxes are then passed over).
 * boxed: 1 where the shape is alone in its leaf, so that the box the walk
 * has just met is the shape's own (rounded outward to float, grown by the
 * margin), 0 where the leaf's box holds others.
 * avx2: the boxes tested with bvh_node_hits_avx2 (the same answers), where
 * the processor has it (Tracer.avx2). */
typedef int (*BvhShapeVisitor)(void *user, int shape, int boxed, double *tmax);
int bvh_shapes_walk(const Bvh *b, Vec3 org, Vec3 dir, double *tmax, unsigned hide, BvhShapeVisitor visit, void *user,
                    uint64_t *nodes, int avx2);
/* The same for a nearest-hit query (visit lowers *tmax): each node's
 * children are visited nearest entered first, so that farther ones are
 * passed over sooner. The visits' order is not bvh_shapes_walk's: the
 * visitor must not depend on it (tracer.c's nearer_shape breaks ties by
 * the shapes' order). */
int bvh_shapes_nearest_walk(const Bvh *b, Vec3 org, Vec3 dir, double *tmax, unsigned hide, BvhShapeVisitor visit,
                            void *user, uint64_t *nodes, int avx2);

/* The exact test of the polygon leaf item k holds (intersect.h): on its
 * packed copy where there is one, else the polygon's own test; the same
 * answer either way, bit for bit. */
static inline double bvh_item_test(const World *w, const Bvh *b, uint32_t k, const RayFrame *frame, double tmax)
{
    return b->prims[k].packed ? intersect_packed(&b->packed[k], frame, tmax)
                              : intersect_polygon_in(w, &w->polygons[b->items[k]], frame, tmax);
}

/* Builds over every polygon of w (an empty hierarchy for none), the big
 * subtrees on up to `threads` threads; the hierarchy is the same for any
 * number. Returns 0, or -1 when out of memory. */
int bvh_build(Bvh *b, const World *w, int threads);
/* bvh_build by the plain passes alone (no SIMD, every bin swept, the right
 * half's bounds in a pass of their own): the reference bvh_build must
 * equal bit for bit (tests/test_bvh.c). */
int bvh_build_plain(Bvh *b, const World *w, int threads);
void bvh_free(Bvh *b);

/* The deepest the binary tree is built (the 4-wide one is about half), and
 * the room a traversal stack needs. */
#define BVH_MAX_DEPTH 64
#define BVH_STACK (3 * BVH_MAX_DEPTH + 1)

/* A ray as the box tests want it: the origin, and per axis the inverse
 * direction and which slab face is met first. */
typedef struct {
    double org[3], inv[3];
    int neg[3];
    /* per axis, where in a BvhNode the children's bounds met first (lo,
     * or hi where neg) and last begin, in bytes: the AVX2 test's loads
     * without a choice per node */
    uint32_t first_at[3], last_at[3];
#if defined(__SSE2__)
    __m128d org2[3], inv2[3]; /* the same, in both lanes */
#endif
} BvhRay;

/* r's neg, first_at and last_at on axis a, from its inv. */
static inline void bvh_ray_faces(BvhRay *r, int a)
{
    const uint32_t lo = (uint32_t)(offsetof(BvhNode, lo) + (size_t)a * sizeof(float[BVH_WIDTH]));
    const uint32_t hi = (uint32_t)(offsetof(BvhNode, hi) + (size_t)a * sizeof(float[BVH_WIDTH]));
    r->neg[a] = signbit(r->inv[a]) != 0;
    r->first_at[a] = r->neg[a] ? hi : lo;
    r->last_at[a] = r->neg[a] ? lo : hi;
}

BvhRay bvh_ray(Vec3 org, Vec3 dir);
/* bvh_ray without the SSE2 lanes (org2, inv2, left unset), for the AVX2
 * box test, which broadcasts org and inv itself: made once per ray,
 * shadow rays included, so the copies it would not read are not made. */
/* bvh_ray_scalar (and bvh_ray) for a ray whose direction's inverses
 * (1 / dir, per axis) are already made (instance_inverse_dir). */
static inline void bvh_ray_scalar_inverse(BvhRay *r, Vec3 org, const double inv[3])
{
    const double o[3] = { org.x, org.y, org.z };
    for (int a = 0; a < 3; a++) {
        r->org[a] = o[a];
        r->inv[a] = inv[a];
        bvh_ray_faces(r, a);
    }
}

static inline void bvh_ray_inverse(BvhRay *r, Vec3 org, const double inv[3])
{
    bvh_ray_scalar_inverse(r, org, inv);
#if defined(__SSE2__)
    for (int a = 0; a < 3; a++) {
        r->org2[a] = _mm_set1_pd(r->org[a]);
        r->inv2[a] = _mm_set1_pd(r->inv[a]);
    }
#endif
}

static inline void bvh_ray_scalar(BvhRay *r, Vec3 org, Vec3 dir)
{
    const double o[3] = { org.x, org.y, org.z }, d[3] = { dir.x, dir.y, dir.z };
    for (int a = 0; a < 3; a++) {
        r->org[a] = o[a];
        r->inv[a] = 1.0 / d[a];
        bvh_ray_faces(r, a);
    }
}

/* Which of node n's children the ray meets for some t in [t0, t1]: bit k for
 * child k; enter[k] is where it enters child k's box (meaningful where the
 * bit is set). Conservative: a child the ray meets is always reported, as
 * an exact computation would (and sometimes one it passes close by).
 *
 * Slab tests in double; the far distances and t1 grow by 2 gamma(3) of
 * rounding, as in pbrt-v4 (Pharr, Jakob and Humphreys, sec. 6.8), which
 * covers any rounding of the subtractions and products; a zero direction
 * component gives NaN distances for a slab the origin lies on, which are
 * ignored (that slab does not limit the ray). bvh_node_hits is SSE2 where
 * the compiler has it, bvh_node_hits_plain the same arithmetic one child at
 * a time; tests/test_bvh.c checks that they agree, bit for bit. */
#define BVH_GROW (1.0 + 2.0 * (3.0 * 0x1p-53) / (1.0 - 3.0 * 0x1p-53)) /* 1 + 2 gamma(3), u = 2^-53 */

unsigned bvh_node_hits_plain(const BvhNode *n, const BvhRay *r, double t0, double t1, double enter[BVH_WIDTH]);

#if defined(__SSE2__)
/* Two children's float bounds on one axis as doubles. */
static inline __m128d bvh_load2(const float *p)
{
    return _mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64((const __m128i *)p)));
}

static inline unsigned bvh_node_hits(const BvhNode *n, const BvhRay *r, double t0, double t1, double enter[BVH_WIDTH])
{
    const __m128d grow = _mm_set1_pd(BVH_GROW);
    const __m128d start = _mm_set1_pd(t0), limit = _mm_set1_pd(t1 * BVH_GROW);
    unsigned mask = 0;
    for (int h = 0; h < BVH_WIDTH; h += 2) {
        __m128d near = start, far = limit;
        for (int a = 0; a < 3; a++) {
            const float *lo = r->neg[a] ? n->hi[a] : n->lo[a];
            const float *hi = r->neg[a] ? n->lo[a] : n->hi[a];
            __m128d tn = _mm_mul_pd(_mm_sub_pd(bvh_load2(lo + h), r->org2[a]), r->inv2[a]);
            __m128d tf = _mm_mul_pd(_mm_mul_pd(_mm_sub_pd(bvh_load2(hi + h), r->org2[a]), r->inv2[a]), grow);
            /* maxpd/minpd return their second operand when either is NaN:
             * a NaN distance leaves the bound as it was, as in the plain
             * version. */
            near = _mm_max_pd(tn, near);
            far = _mm_min_pd(tf, far);
        }
        _mm_storeu_pd(&enter[h], near);
        mask |= (unsigned)_mm_movemask_pd(_mm_cmple_pd(near, far)) << h;
    }
    return mask;
}
#else
static inline unsigned bvh_node_hits(const BvhNode *n, const BvhRay *r, double t0, double t1, double enter[BVH_WIDTH])
{
    return bvh_node_hits_plain(n, r, t0, t1, enter);
}
#endif

/* The same arithmetic on all four children at once with AVX2, for the
 * processors that have it (bvh_have_avx2; tracer.c chooses at run time).
 * Lane by lane it is the SSE2 version's: the same conversions, products in
 * the same order, and vmaxpd/vminpd/vcmppd (ordered) treat NaN as maxpd,
 * minpd and cmplepd do, so the answers are bit for bit the same. */
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define BVH_HAVE_AVX2_PATH 1
#include <immintrin.h>

/* One axis of bvh_node_hits_avx2: the four children's slabs narrowing
 * [near, far]. */
__attribute__((target("avx2"))) static inline void bvh_axis_avx2(const BvhNode *n, const BvhRay *r, int a,
                                                                __m256d *near, __m256d *far)
{
    const float *lo = (const float *)(const void *)((const char *)n + r->first_at[a]);
    const float *hi = (const float *)(const void *)((const char *)n + r->last_at[a]);
    const __m256d org = _mm256_set1_pd(r->org[a]), inv = _mm256_set1_pd(r->inv[a]);
    __m256d tn = _mm256_mul_pd(_mm256_sub_pd(_mm256_cvtps_pd(_mm_loadu_ps(lo)), org), inv);
    const __m256d grow = _mm256_set1_pd(BVH_GROW);
    __m256d tf = _mm256_mul_pd(_mm256_mul_pd(_mm256_sub_pd(_mm256_cvtps_pd(_mm_loadu_ps(hi)), org), inv), grow);
    *near = _mm256_max_pd(tn, *near);
    *far = _mm256_min_pd(tf, *far);
}

__attribute__((target("avx2"))) static inline unsigned bvh_node_hits_avx2(const BvhNode *n, const BvhRay *r,
                                                                          double t0, double t1,
                                                                          double enter[BVH_WIDTH])
{
    __m256d near = _mm256_set1_pd(t0), far = _mm256_set1_pd(t1 * BVH_GROW);
    /* the axes one by one, written out (no loop to count, no branch) */
    bvh_axis_avx2(n, r, 0, &near, &far);
    bvh_axis_avx2(n, r, 1, &near, &far);
    bvh_axis_avx2(n, r, 2, &near, &far);
    _mm256_storeu_pd(enter, near);
    return (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(near, far, _CMP_LE_OQ));
}
#else
#define BVH_HAVE_AVX2_PATH 0
#endif

/* Does the ray meet the box lo[3], hi[3] (Bvh.instance_box) for some t in
 * [0, t1]? bvh_node_hits_plain's arithmetic for one child: as conservative. */
static inline int bvh_box_hit(const float box[6], const BvhRay *r, double t1)
{
    double near = 0.0, far = t1 * BVH_GROW;
    for (int a = 0; a < 3; a++) {
        double lo = r->neg[a] ? box[3 + a] : box[a];
        double hi = r->neg[a] ? box[a] : box[3 + a];
        double tn = (lo - r->org[a]) * r->inv[a];
        double tf = (hi - r->org[a]) * r->inv[a] * BVH_GROW;
        near = tn > near ? tn : near; /* NaN: not taken */
        far = tf < far ? tf : far;
    }
    return near <= far;
}

/* 1 when this processor runs bvh_node_hits_avx2 (and the build has it). */
int bvh_have_avx2(void);

#endif
