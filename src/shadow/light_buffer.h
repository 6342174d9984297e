/* The light buffer (Haines and Greenberg, IEEE CG&A 6(9), 1986; the
 * paper's reference [2]): a cube of directions around a point light whose
 * cells list the polygons that can stand between the light and a point
 * seen through the cell. A point's shadow decision then looks at its
 * cell only: an opaque polygon that covers the whole cell nearer than the
 * point is shadow at once; else the list's polygons nearer the light than
 * the point are looked at, those the point's side of their plane or the
 * shadow ray's distance from them rules out passed over, and the rest
 * tested by the shadow ray's own polygon test; none left is lit at once.
 *
 * Exactness (the shadow ray's decision, ties included) rests on
 * conservative steps with margins far above the rounding of the double
 * arithmetic involved (light_buffer.c works each bound out):
 * - a cell's list holds every polygon the shadow ray of any point in the
 *   cell can meet: the cell's pyramid (apex at the light) is widened by
 *   LB_WIDEN in the face's coordinates and its side planes pushed out by
 *   the scene's margin (LightBuffers.margin, 1e-9 of its size), which
 *   covers the rounding of a shadow ray's direction and of the watertight
 *   test (some 1e-15 of the size); the hierarchy's boxes are rounded
 *   outward (bvh.h);
 * - a candidate is passed over when a lower bound of its distance from the
 *   light (in float, rounded down) is beyond the point; when the point lies
 *   on the light's side of its plane by more than the float plane's error
 *   (the light at least plane_margin from it); or when the point's
 *   direction from the light lies outside the candidate's footprint on
 *   the face (the box of its points' directions, padded for the margins);
 * - "covers the cell" is proved in double for convex opaque polygons with
 *   a margin of 1e-5 of the scene's size on every side and away from the
 *   light and the point, for rays at least 1e-2 from the polygon's plane.
 * Everything else is the shadow ray's own test.
 *
 * Curved objects (World.shapes) are listed too, apart: a top cell holds
 * every object whose box, grown past the shadow ray's own box test's
 * growth, meets its pyramid, with its near bound and footprint as a
 * polygon's; a point tests only those nearer than it whose footprints
 * hold its direction, each by the shadow ray's own crossings
 * (shadow_shape_crossing), and the see-through ones crossed are folded in
 * the order the shadow ray's walk folds them (shadow_shape_fold), so the
 * colour is the shadow ray's to the bit.
 *
 * Cells are built lazily, the first time a point asks: a top cell by
 * walking the hierarchy with its pyramid; a cell of more than LB_SPLIT_AT
 * candidates above the last of LB_LEVELS levels is split into LB_SUB x
 * LB_SUB children, each built from its parent's list (the candidates whose
 * footprints overlap it), all together in two passes over that list when a
 * point first asks for one of them. Cells are shared by the
 * render's threads: each is built by one and published atomically (a
 * thread that loses the race frees its copy), and read-only after that;
 * which cell answers a point depends on the lists alone, not on the order
 * points came in. Their memory is counted against a budget; past it,
 * no cell is built and the shadow ray decides. */
#ifndef HST_LIGHT_BUFFER_H
#define HST_LIGHT_BUFFER_H

#include <math.h>
#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>

#include "bvh.h"
#include "shared_arena.h"
#include "world.h"

#define LB_TOP 8       /* cells per side of a face at the top level */
#define LB_SUB 4        /* a split cell's children per side (two bits of index a level) */
#define LB_LEVELS 3     /* levels, the top one included */
#define LB_SPLIT_AT 64  /* a cell with more candidates than this splits (above the last level) */
#define LB_SPLIT_OBJECTS_AT 8 /* ... or with more curved objects than this */
/* the finest cells per side of a face */
#define LB_FINE (LB_TOP << (2 * (LB_LEVELS - 1)))

/* A candidate's plane in float, turned so that the light lies on its
 * positive side; all zero where it must not be used (the light within
 * plane_margin of the plane). */
typedef struct {
    float nx, ny, nz, d;
} LbPlane;

/* Where a candidate lies on its face, in the face's coordinates: the box
 * of its points' directions, padded for the pyramids' margins and rounded
 * outward to float (light_buffer.c); the whole face and beyond where that
 * cannot be told. */
typedef struct {
    float u0, u1, v0, v1;
} LbFootprint;

/* A candidate's shape on its face: the lines of its edges in the face's
 * coordinates (a u + b v + c, (a, b) of unit length, positive inside),
 * for triangles and convex polygons of up to four points that lie in
 * front of the face (n edges; 0: none kept, the shadow ray's test
 * decides; the lines past the n-th are 0 u + 0 v + 1, which every
 * direction is inside of). A direction more than `out` outside an edge is
 * not the polygon's (the footprint's margins); one at least `in` inside
 * every edge crosses the polygon at least the cover's margin from its
 * border (light_buffer.c). Both margins hold LB_SHAPE_FLOAT_PAD for
 * lb_shape_classify's float arithmetic. */
typedef struct {
    float a[4], b[4], c[4];
    float in, out;
    uint8_t n;
    uint8_t opaque;         /* its material blocks light fully */
    uint8_t pad_[6];
} LbShape;

enum { LB_OUTSIDE, LB_UNSURE, LB_INSIDE };

/* lb_shape_classify's error: a line's value a u + b v + c evaluated in
 * float, at the direction (u, v) rounded to float (|u|, |v| <= 1 on the
 * face), against the same in exact arithmetic. |a|, |b| <= 1 + 2^-24 and
 * |c| <= 4 (|a| + |b|) (the shape's points lie within 4 of the axis): the
 * terms sum to at most 7.2, so the three roundings cost below
 * 3 2^-24 7.2 = 1.3e-6, and u's and v's own 2^-24 below 1.2e-7 more. */
#define LB_SHAPE_FLOAT_PAD 2e-6

/* Where direction (u, v) of the face (rounded to float) lies against
 * shape s: outside by more than s->out - LB_SHAPE_FLOAT_PAD of some edge
 * in exact arithmetic, inside by at least s->in - LB_SHAPE_FLOAT_PAD of
 * every edge, or unsure. lb_shape_classify_plain one edge at a time;
 * lb_shape_classify the same operations with SSE where the compiler has
 * it (tests/test_agreement.c holds them to each other and to the bound). */
static inline int lb_shape_classify_plain(const LbShape *s, float u, float v)
{
    if (s->n == 0)
        return LB_UNSURE;
    int outside = 0, inside = 1;
    for (int k = 0; k < 4; k++) {
        float d = (s->a[k] * u + s->b[k] * v) + s->c[k];
        outside |= d < -s->out;
        inside &= d >= s->in;
    }
    return outside ? LB_OUTSIDE : inside ? LB_INSIDE : LB_UNSURE;
}

#if defined(__SSE2__)
#include <emmintrin.h>

static inline int lb_shape_classify(const LbShape *s, float u, float v)
{
    if (s->n == 0)
        return LB_UNSURE;
    __m128 d = _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_loadu_ps(s->a), _mm_set1_ps(u)),
                                     _mm_mul_ps(_mm_loadu_ps(s->b), _mm_set1_ps(v))),
                          _mm_loadu_ps(s->c));
    if (_mm_movemask_ps(_mm_cmplt_ps(d, _mm_set1_ps(-s->out))))
        return LB_OUTSIDE;
    return _mm_movemask_ps(_mm_cmpge_ps(d, _mm_set1_ps(s->in))) == 0xF ? LB_INSIDE : LB_UNSURE;
}
#else
static inline int lb_shape_classify(const LbShape *s, float u, float v) { return lb_shape_classify_plain(s, u, v); }
#endif

/* Candidates are looked at LB_BLOCK at a time (lb_block_mask), their
 * near bounds and footprints side by side; a list is padded to a whole
 * block with entries no point selects. */
#define LB_BLOCK 4

/* LB_BLOCK candidates of a cell, each field's four side by side (so that
 * they are tested at once) and the block's fields together (so that a
 * point's scan reads the blocks it needs in order): the near bounds, the
 * footprints, the planes (LbPlane's fields). */
typedef struct LbBlock {
    float near[LB_BLOCK], u0[LB_BLOCK], u1[LB_BLOCK], v0[LB_BLOCK], v1[LB_BLOCK];
    float nx[LB_BLOCK], ny[LB_BLOCK], nz[LB_BLOCK], d[LB_BLOCK];
} LbBlock;

/* A curved object as a cell lists it: a lower bound of its grown box's
 * distance from the light (in float, rounded down) and the box's
 * footprint on the face (as a polygon's), so that a point passes over
 * the objects that lie beyond it or off its direction. */
typedef struct LbObject {
    float near, u0, u1, v0, v1;
    uint32_t shape;         /* its index in World.shapes */
} LbObject;

/* What a cell says about the points seen through it. */
typedef struct LbCell {
    uint32_t n;             /* candidates */
    int32_t cover;          /* an opaque polygon covering the whole cell, or -1 */
    double cover_beyond;    /* ... which blocks every point farther than this from the light */
    /* split: LB_SUB x LB_SUB slots for its children, row by row, built
     * from this cell's list when a point first asks for one; else NULL.
     * Set when the cell is made (its list decides), before it is
     * published: only the slots change after. */
    _Atomic(struct LbCell *) *child;
    /* Per candidate, in blocks (n rounded up to LB_BLOCK): a lower bound of
     * its distance from the light (ascending), its footprint and plane */
    const struct LbBlock *block;
    const uint32_t *item;   /* the candidates as the hierarchy's leaf items (Bvh.items), in that order */
    const uint32_t *shape_at; /* ... and their shapes, in shapes */
    /* The shapes of the top cell's candidates, kept once by the top cell
     * (nshapes of them; 0 in its children, which refer to them). */
    const LbShape *shapes;
    uint32_t nshapes;
    int level;
    /* The curved objects (World.shapes, the shapes' hierarchy's items)
     * whose boxes, grown by LightBuffers.object_growth, meet the top cell's
     * pyramid, nearest first: every object the shadow ray of a point seen
     * through the cell can cross, for points within
     * LightBuffers.object_reach of the origin. A split cell's children
     * list those of its objects whose footprints overlap them. */
    const struct LbObject *object;
    uint32_t nobjects;
} LbCell;

typedef struct LightBuffer {
    int light;              /* index in World.lights */
    Vec3 at;                /* the light's position */
    _Atomic(LbCell *) top[6][LB_TOP * LB_TOP]; /* face 2 axis + (negative), row by row (u, then v) */
    /* Per infinite plane of the world: the light's signed distance from it
     * (n.L - d) where the side test may decide it (light_buffer_plane_side),
     * else 0 (a plane that is not opaque, casts no shadow, or passes
     * within plane_margin of the light). */
    double *plane_side;
} LightBuffer;

/* Every light's buffer, shared by the render's threads. */
typedef struct LightBuffers {
    const World *world;
    const Bvh *bvh;
    double tolerance;       /* the shadow ray's edge-on rule (grid_tolerance) */
    double margin;          /* absolute margin of the cells' pyramids: 1e-9 of the scene's size */
    double cover_margin;    /* the cover's margin: 1e-5 of the scene's size */
    double plane_margin;    /* the least distance of the light from a plane lb_candidate_passed uses: 1e-3 of it */
    /* The curved objects' boxes are grown, per axis, by object_growth
     * (1 + |lo| + |hi|) plus the margin, four times the growth of the
     * shadow ray's box test (shape_box_hit) for points whose coordinates
     * are at most object_reach (four times the scene's size, lights
     * included): a point farther out has its objects walked by the shadow
     * ray itself. */
    double object_growth, object_reach;
    /* Per curved object of the shapes' hierarchy (World.shapes, up to
     * World.nshapes): its place in the order shadow_shapes_test's walk
     * visits them (shadow_shape_fold), in which see-through ones are
     * folded. */
    uint32_t *object_rank;
    int nlights;
    LightBuffer **light;    /* per light: its buffer, or NULL (not a point light) */
    uint32_t *item_of;      /* per world polygon, its leaf item in the hierarchy (instances' polygons
                             * are their instance's item's, instance.h) */
    size_t budget;          /* bytes the cells may take */
    uint32_t split_at;      /* LB_SPLIT_AT (tests set less) */
    atomic_size_t bytes;    /* ... taken */
    atomic_uint_fast64_t cells, candidates; /* cells published, and their list entries */
    atomic_uint_fast64_t full; /* cells not built for the budget */
    atomic_int exhausted;   /* 1: the budget is spent, no more cells are built */
    SharedArena arena;      /* the cells' memory, all of it freed with the buffers */
    int arena_made;
} LightBuffers;

/* The cells' arena's chunks: the least size that asks for huge pages. */
#define LB_ARENA_CHUNK ((size_t)4 << 20)

/* Buffers for the point lights of w (not parallel ones; area lights'
 * samples are not asked of them): empty, filled as points ask. budget:
 * the bytes their cells may take. Returns 0, or -1 when out of memory. */
int light_buffers_init(LightBuffers *lbs, const World *w, const Bvh *bvh, double tolerance, size_t budget);
void light_buffers_free(LightBuffers *lbs);

/* Where a direction from a light falls on its cube: the face, and the
 * finest cell's indices. 0 for a zero or non-finite direction (a point at
 * the light). */
typedef struct {
    int face, iu, iv;
    double u, v;            /* the direction in the face's coordinates */
} LbSpot;
static inline int light_buffer_spot(Vec3 d, LbSpot *spot)
{
    double ax = fabs(d.x), ay = fabs(d.y), az = fabs(d.z);
    /* a point at the light itself has no direction (NaN or infinite
     * components, or none at all): no cell, the shadow ray decides */
    double sum = ax + ay + az;
    if (!(sum > 0.0 && sum < INFINITY))
        return 0;
    /* the major axis (ties to the lower), and the face's coordinates: the
     * next two axes in turn, over the major's magnitude */
    double major, a, b;
    int axis;
    if (ax >= ay && ax >= az) {
        axis = 0, major = d.x, a = d.y, b = d.z;
    } else if (ay >= az) {
        axis = 1, major = d.y, a = d.z, b = d.x;
    } else {
        axis = 2, major = d.z, a = d.x, b = d.y;
    }
    spot->face = 2 * axis + (major < 0.0);
    double inv = 1.0 / fabs(major);
    double u = a * inv, v = b * inv;
    spot->u = u;
    spot->v = v;
    /* a direction on a cell's border may go to either: both cells'
     * pyramids hold it, widened */
    int iu = (int)((u + 1.0) * (0.5 * LB_FINE)), iv = (int)((v + 1.0) * (0.5 * LB_FINE));
    spot->iu = iu < 0 ? 0 : iu >= LB_FINE ? LB_FINE - 1 : iu;
    spot->iv = iv < 0 ? 0 : iv >= LB_FINE ? LB_FINE - 1 : iv;
    return 1;
}

/* The cell of light buffer lb at spot, built if need be; NULL when the
 * budget stops it or memory runs out (then the shadow ray decides).
 * *built: seconds spent building, 0 when the cell was there. */
const LbCell *light_buffer_cell(LightBuffers *lbs, LightBuffer *lb, const LbSpot *spot, double *built);

/* A point as the plane tests take it: the point, the sum of its
 * coordinates' magnitudes, and 1e-12 of its distance to the light; and
 * in float for lb_block_mask: the point rounded, and the part of the
 * passed-over margin that does not depend on the plane (LB_PASS_FLOAT
 * times the size, plus `far`), rounded up. */
typedef struct {
    Vec3 p;
    double size, far;
    float fx, fy, fz, fbase;
} LbPoint;

/* The float plane test's margin per unit of |P|_1 + |d|: the double
 * test's 1.2e-7 (lb_candidate_passed) plus the float arithmetic's own
 * error. That is the point's rounding to float (2^-24 |P|_1 against unit
 * normals) and the four-term sum's (4 2^-24 (|n.P|_1 + |d|), with
 * |n_i| <= 1 + 2^-24): together below 3.1e-7 (|P|_1 + |d|); 5e-7 leaves
 * room for the margin's own rounding (a few 2^-24 of it). A plane that
 * clears it in float clears lb_candidate_passed's bound in exact
 * arithmetic. */
#define LB_PASS_FLOAT 5e-7f

static inline LbPoint lb_point(Vec3 p, double distance)
{
    double size = fabs(p.x) + fabs(p.y) + fabs(p.z), far = 1e-12 * distance;
    LbPoint pt = { p, size, far, (float)p.x, (float)p.y, (float)p.z,
                   (float)((LB_PASS_FLOAT * size + far) * (1.0 + 0x1p-20)) };
    return pt;
}

/* Candidate i's plane. */
static inline LbPlane lb_plane_at(const LbCell *c, uint32_t i)
{
    const LbBlock *b = &c->block[i / LB_BLOCK];
    uint32_t k = i % LB_BLOCK;
    LbPlane pl = { b->nx[k], b->ny[k], b->nz[k], b->d[k] };
    return pl;
}

/* 1 when point p lies beyond candidate plane pl (away from the light) by
 * more than its float rounding and `margin`, and the unit direction
 * to_light meets the plane at least LB_COVER_ANGLE from it (with the
 * float normal's error): with a shape's LB_INSIDE, the shadow ray crosses
 * the polygon (light_buffer.c). */
#define LB_COVER_ANGLE 1e-2
static inline int lb_candidate_crossed(const LbPlane *pl, const LbPoint *pt, Vec3 to_light, double margin)
{
    double s = (double)pl->nx * pt->p.x + (double)pl->ny * pt->p.y + (double)pl->nz * pt->p.z - (double)pl->d;
    double err = 1.2e-7 * (pt->size + fabs((double)pl->d)) + pt->far;
    double cosine = (double)pl->nx * to_light.x + (double)pl->ny * to_light.y + (double)pl->nz * to_light.z;
    return s < -(err + margin) && fabs(cosine) >= LB_COVER_ANGLE + 1e-6;
}

/* 1 when point p lies on the light's side of candidate plane pl by more
 * than its float rounding (light_buffer.c: the shadow ray from p cannot
 * then meet the polygon). */
static inline int lb_candidate_passed(const LbPlane *pl, const LbPoint *pt)
{
    double s = (double)pl->nx * pt->p.x + (double)pl->ny * pt->p.y + (double)pl->nz * pt->p.z - (double)pl->d;
    return s > 1.2e-7 * (pt->size + fabs((double)pl->d)) + pt->far;
}

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

/* What a point's scan of a cell's blocks compares with, made once per
 * point (lb_scan): the limit on the near bounds (a float at least the
 * point's distance plus the margin), the point's direction (u, v) on the
 * face in float, and the point in float with the plane-independent part
 * of its margin (LbPoint); with SSE, each also in all four lanes. */
typedef struct {
    float limit, u, v, fx, fy, fz, fbase;
#if defined(__SSE2__)
    __m128 limit4, u4, v4, fx4, fy4, fz4, fbase4;
#endif
} LbScan;

static inline LbScan lb_scan(float limit, float u, float v, const LbPoint *pt)
{
    LbScan s = { limit, u, v, pt->fx, pt->fy, pt->fz, pt->fbase
#if defined(__SSE2__)
                 , _mm_set1_ps(limit), _mm_set1_ps(u), _mm_set1_ps(v), _mm_set1_ps(pt->fx), _mm_set1_ps(pt->fy),
                 _mm_set1_ps(pt->fz), _mm_set1_ps(pt->fbase)
#endif
    };
    return s;
}

/* The float plane test of candidate i: 1 when it passes the point over. */
static inline int lb_float_passed(const LbCell *c, uint32_t i, const LbScan *s)
{
    const LbBlock *b = &c->block[i / LB_BLOCK];
    uint32_t k = i % LB_BLOCK;
    float x = b->nx[k] * s->fx, y = b->ny[k] * s->fy, z = b->nz[k] * s->fz;
    float side = ((x + y) + z) - b->d[k];
    float margin = s->fbase + LB_PASS_FLOAT * fabsf(b->d[k]);
    return side > margin;
}

/* The candidates of block b (from LB_BLOCK * b) that a point may need:
 * nearer the light than the scan's limit, whose footprint holds the
 * point's direction (u, v) in float, and that the point does not lie
 * clearly on the light's side of (the float plane test, LB_PASS_FLOAT):
 * bit k for the block's k-th. Every point of the point's shadow ray has
 * that direction (to within the margins the footprints are padded by,
 * which also cover the rounding of u and v to float), so the shadow ray
 * cannot meet the others; nor can it meet a polygon whose plane the point
 * is on the light's side of (light_buffer.c). lb_block_mask_plain one
 * candidate at a time; lb_block_mask the same operations, in the same
 * order, with SSE where the compiler has it (tests/test_agreement.c holds
 * them to each other). */
static inline unsigned lb_block_mask_plain(const LbCell *c, uint32_t b, const LbScan *s)
{
    const LbBlock *bl = &c->block[b];
    unsigned mask = 0;
    for (uint32_t k = 0; k < LB_BLOCK; k++) {
        int passed = lb_float_passed(c, b * LB_BLOCK + k, s);
        mask |= (unsigned)(bl->near[k] < s->limit && bl->u0[k] <= s->u && s->u <= bl->u1[k] && bl->v0[k] <= s->v &&
                           s->v <= bl->v1[k] && !passed)
                << k;
    }
    return mask;
}

#if defined(__SSE2__)
static inline unsigned lb_block_mask(const LbCell *c, uint32_t b, const LbScan *s)
{
    const LbBlock *bl = &c->block[b];
    __m128 m = _mm_cmplt_ps(_mm_load_ps(bl->near), s->limit4);
    m = _mm_and_ps(m, _mm_cmple_ps(_mm_load_ps(bl->u0), s->u4));
    m = _mm_and_ps(m, _mm_cmple_ps(s->u4, _mm_load_ps(bl->u1)));
    m = _mm_and_ps(m, _mm_cmple_ps(_mm_load_ps(bl->v0), s->v4));
    m = _mm_and_ps(m, _mm_cmple_ps(s->v4, _mm_load_ps(bl->v1)));
    __m128 x = _mm_mul_ps(_mm_load_ps(bl->nx), s->fx4);
    __m128 y = _mm_mul_ps(_mm_load_ps(bl->ny), s->fy4);
    __m128 z = _mm_mul_ps(_mm_load_ps(bl->nz), s->fz4);
    __m128 d = _mm_load_ps(bl->d);
    __m128 side = _mm_sub_ps(_mm_add_ps(_mm_add_ps(x, y), z), d);
    __m128 absd = _mm_andnot_ps(_mm_set1_ps(-0.0f), d);
    __m128 margin = _mm_add_ps(s->fbase4, _mm_mul_ps(_mm_set1_ps(LB_PASS_FLOAT), absd));
    m = _mm_andnot_ps(_mm_cmpgt_ps(side, margin), m);
    return (unsigned)_mm_movemask_ps(m);
}
#else
static inline unsigned lb_block_mask(const LbCell *c, uint32_t b, const LbScan *s)
{
    return lb_block_mask_plain(c, b, s);
}
#endif

#endif
