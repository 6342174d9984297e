/* Building the hierarchy (bvh.h): a binary tree, top-down by the binned
 * surface area heuristic over the polygons' bounding-box centres (Wald, "On
 * fast construction of SAH-based bounding volume hierarchies", 2007), then
 * collapsed into 4-wide nodes by pulling up the grandchildren of the
 * largest children (as Embree's BVH4 and Wald, Benthin and Boulos, "Getting
 * rid of packets", 2008, do). */
#include "bvh.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "big_memory.h"
#include "parallel.h"

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

static inline double area_of(const float lo[3], const float hi[3])
{
    double e[3];
    for (int a = 0; a < 3; a++)
        e[a] = hi[a] > lo[a] ? (double)hi[a] - (double)lo[a] : 0.0;
    return 2.0 * (e[0] * e[1] + e[1] * e[2] + e[2] * e[0]);
}

static inline double box_area(const Box *b) { return area_of(b->lo, b->hi); }

/* nextafterf(f, -inf) and nextafterf(f, +inf) for a float that is not NaN
 * (round_down and round_up call them only then), by its bits: a tenth of
 * the library call's cost, which the set-up of 10^6 polygons made 60 ms. */
static float float_below(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    if (u == 0u)
        return -0x1p-149f; /* +0: the negative float nearest 0 */
    u = (u & 0x80000000u) ? (u == 0xFF800000u ? u : u + 1u) : u - 1u;
    memcpy(&f, &u, sizeof f);
    return f;
}

static float float_above(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    if (u == 0x80000000u)
        return 0x1p-149f; /* -0 */
    u = (u & 0x80000000u) ? u - 1u : (u == 0x7F800000u ? u : u + 1u);
    memcpy(&f, &u, sizeof f);
    return f;
}

/* The float nearest x on the side away from the box's inside. */
static float round_down(double x)
{
    float f = (float)x;
    return (double)f > x ? float_below(f) : f;
}

static float round_up(double x)
{
    float f = (float)x;
    return (double)f < x ? float_above(f) : f;
}

/* The SSE2 passes of the build (binning, partition) do per item in one
 * vector operation what the plain ones do per axis, with the same float
 * operations, so the same results bit for bit; bvh_build_plain uses the
 * plain ones everywhere (tests/test_bvh.c compares the two). */
#if defined(__SSE2__)
#define BUILD_SSE 1
#else
#define BUILD_SSE 0
#endif

/* A polygon as the build moves it: its box and centre, records partitioned
 * in place so that every pass reads memory in order. 48 bytes, lo, hi and
 * centre each 16-byte aligned, so that they load as vectors: lo's fourth
 * lane is the polygon's index (masked off before it meets a bound), the
 * others' are 0. */
typedef struct {
    _Alignas(16) float lo[3];
    uint32_t polygon;
    float hi[3], hi_pad;
    float centre[3], centre_pad;
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
    /* Threads that may start now (shared by every builder of one build):
     * a split hands its second half to a new thread while one is free, so
     * that a thread done early takes a share of what is left. */
    atomic_int *free_threads;
    int plain;            /* bvh_build_plain: the reference passes, one axis at a time, every bin swept */
} Builder;

/* Subtrees of fewer items are built on the thread that reaches them. */
#define PARALLEL_MIN 20000

/* Room for the nodes of a tree over `count` items made at once: a binary
 * tree whose leaves hold at least one item has at most 2 count - 1 nodes.
 * Pages never written cost nothing, and the array never moves (growing it by
 * doublings copied and faulted in every node again). 0, or -1 when out of
 * memory (then new_node grows the array as needed). */
static int reserve_nodes(Builder *bd, int count)
{
    size_t cap = count > 0 ? 2 * (size_t)count - 1 : 1;
    if (cap > INT32_MAX)
        return -1;
    bd->nodes = big_malloc(sizeof *bd->nodes * cap);
    bd->cap = bd->nodes ? (int)cap : 0;
    return bd->nodes ? 0 : -1;
}

static int new_node(Builder *bd)
{
    if (bd->nnodes == bd->cap) {
        int cap = bd->cap ? bd->cap * 2 : 64;
        BinNode *n = big_realloc(bd->nodes, sizeof *n * (size_t)cap);
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

/* Per axis and bin: the items and their boxes' union (the fourth lanes
 * unused). The bins serve only the SAH costs, through areas, which do not
 * depend on the sign of a zero bound: so the union may be taken in any
 * order (a box's bound that is -0 in one order may be +0 in another). */
typedef struct {
    _Alignas(16) float lo[4];
    float hi[4];
} BinBox;

typedef struct {
    int n[3][BINS];
    BinBox b[3][BINS];
} Bins;

static inline void binbox_empty(BinBox *b)
{
    for (int l = 0; l < 4; l++) {
        b->lo[l] = HUGE_VALF;
        b->hi[l] = -HUGE_VALF;
    }
}

static void bins_empty(Bins *bn)
{
    for (int a = 0; a < 3; a++)
        for (int k = 0; k < BINS; k++) {
            bn->n[a][k] = 0;
            binbox_empty(&bn->b[a][k]);
        }
}

static inline void binbox_join(BinBox *b, const BinBox *c)
{
    for (int a = 0; a < 3; a++) {
        b->lo[a] = c->lo[a] < b->lo[a] ? c->lo[a] : b->lo[a];
        b->hi[a] = c->hi[a] > b->hi[a] ? c->hi[a] : b->hi[a];
    }
}

/* Bins items it[0, count) by their centres, cb being the centres' union;
 * scale[a] is BINS over cb's extent on axis a (0 where it cannot split). */
static void bin_items_plain(Bins *bn, const BuildItem *it, int count, const Box *cb, const float scale[3])
{
    for (int i = 0; i < count; i++)
        for (int a = 0; a < 3; a++) {
            int k = bin_of(it[i].centre[a], cb->lo[a], scale[a]);
            BinBox *b = &bn->b[a][k];
            bn->n[a][k]++;
            for (int l = 0; l < 3; l++) {
                b->lo[l] = it[i].lo[l] < b->lo[l] ? it[i].lo[l] : b->lo[l];
                b->hi[l] = it[i].hi[l] > b->hi[l] ? it[i].hi[l] : b->hi[l];
            }
        }
}

#if BUILD_SSE
/* All lanes but the fourth. */
static inline __m128 lanes3(void) { return _mm_castsi128_ps(_mm_setr_epi32(-1, -1, -1, 0)); }

static inline __m128 load3(const float v[3]) { return _mm_setr_ps(v[0], v[1], v[2], 0.0f); }

static inline void store3(float v[3], __m128 x)
{
    float t[4];
    _mm_storeu_ps(t, x);
    v[0] = t[0];
    v[1] = t[1];
    v[2] = t[2];
}

/* The three bins of an item's centre c: bin_of lane by lane, (c - lo) *
 * scale, then maxps(x, 0) sends NaN (maxps returns its second operand when
 * either is NaN) and negatives (and -0) to 0, minps(., 15) sends 15 and
 * above (+inf too) to the last bin, and truncation does the rest, as
 * (int) does on [0, 15]. */
static inline __m128i bins_of(__m128 c, __m128 lo, __m128 scale)
{
    __m128 x = _mm_mul_ps(_mm_sub_ps(c, lo), scale);
    x = _mm_min_ps(_mm_max_ps(x, _mm_setzero_ps()), _mm_set1_ps((float)(BINS - 1)));
    return _mm_cvttps_epi32(x);
}

/* minps(a, b) is a < b ? a : b and maxps(a, b) a > b ? a : b, operand for
 * operand the plain passes' choices (the box's old bound on a tie or a
 * NaN). */
static inline void binbox_grow_sse(BinBox *b, __m128 lo, __m128 hi)
{
    _mm_store_ps(b->lo, _mm_min_ps(lo, _mm_load_ps(b->lo)));
    _mm_store_ps(b->hi, _mm_max_ps(hi, _mm_load_ps(b->hi)));
}

/* One item into bins bn. */
static inline void bin_item_sse(Bins *bn, const BuildItem *it, __m128 lo, __m128 sc, __m128 mask)
{
    __m128i k = bins_of(_mm_load_ps(it->centre), lo, sc);
    __m128 l = _mm_and_ps(_mm_load_ps(it->lo), mask), h = _mm_load_ps(it->hi);
    int k0 = _mm_cvtsi128_si32(k), k1 = _mm_cvtsi128_si32(_mm_shuffle_epi32(k, 1)),
        k2 = _mm_cvtsi128_si32(_mm_shuffle_epi32(k, 2));
    bn->n[0][k0]++;
    bn->n[1][k1]++;
    bn->n[2][k2]++;
    binbox_grow_sse(&bn->b[0][k0], l, h);
    binbox_grow_sse(&bn->b[1][k1], l, h);
    binbox_grow_sse(&bn->b[2][k2], l, h);
}

static void bin_items_sse(Bins *bn, const BuildItem *it, int count, const Box *cb, const float scale[3])
{
    const __m128 lo = load3(cb->lo), sc = load3(scale), mask = lanes3();
    for (int i = 0; i < count; i++)
        bin_item_sse(bn, &it[i], lo, sc, mask);
}

#define SMALL_BIN 16

/* bin_items_sse for a node of at most SMALL_BIN items, which leave most
 * bins empty: only the bins the items fall in are made empty before they
 * are grown (and only those are read: best_split sweeps over the bins that
 * hold items), instead of all 48. */
static void bin_items_small_sse(Bins *bn, const BuildItem *it, int count, const Box *cb, const float scale[3])
{
    const __m128 lo = load3(cb->lo), sc = load3(scale), mask = lanes3();
    const __m128 inf = _mm_set1_ps(HUGE_VALF), ninf = _mm_set1_ps(-HUGE_VALF);
    _Alignas(16) int k[SMALL_BIN][4];
    memset(bn->n, 0, sizeof bn->n);
    for (int i = 0; i < count; i++) {
        _mm_store_si128((__m128i *)k[i], bins_of(_mm_load_ps(it[i].centre), lo, sc));
        for (int a = 0; a < 3; a++) {
            bn->n[a][k[i][a]]++;
            _mm_store_ps(bn->b[a][k[i][a]].lo, inf);
            _mm_store_ps(bn->b[a][k[i][a]].hi, ninf);
        }
    }
    for (int i = 0; i < count; i++) {
        __m128 l = _mm_and_ps(_mm_load_ps(it[i].lo), mask), h = _mm_load_ps(it[i].hi);
        for (int a = 0; a < 3; a++)
            binbox_grow_sse(&bn->b[a][k[i][a]], l, h);
    }
}
#endif

static void bin_items(const Builder *bd, Bins *bn, const BuildItem *it, int count, const Box *cb, const float scale[3])
{
#if BUILD_SSE
    if (!bd->plain) {
        if (count <= SMALL_BIN) {
            bin_items_small_sse(bn, it, count, cb, scale);
        } else {
            bins_empty(bn);
            bin_items_sse(bn, it, count, cb, scale);
        }
        return;
    }
#else
    (void)bd; /* one way to bin */
#endif
    bins_empty(bn);
    bin_items_plain(bn, it, count, cb, scale);
}

/* Bit k set for each bin k of n that holds items. */
static inline unsigned used_bins(const int n[BINS])
{
#if BUILD_SSE && BINS == 16
    const __m128i zero = _mm_setzero_si128();
    __m128i e0 = _mm_packs_epi32(_mm_cmpeq_epi32(_mm_loadu_si128((const __m128i *)n), zero),
                                 _mm_cmpeq_epi32(_mm_loadu_si128((const __m128i *)(n + 4)), zero));
    __m128i e1 = _mm_packs_epi32(_mm_cmpeq_epi32(_mm_loadu_si128((const __m128i *)(n + 8)), zero),
                                 _mm_cmpeq_epi32(_mm_loadu_si128((const __m128i *)(n + 12)), zero));
    return ~(unsigned)_mm_movemask_epi8(_mm_packs_epi16(e0, e1)) & 0xFFFFu;
#else
    unsigned m = 0;
    for (int k = 0; k < BINS; k++)
        m |= (unsigned)(n[k] != 0) << k;
    return m;
#endif
}

/* The index of m's lowest set bit (m not 0). */
static inline int lowest_bit(unsigned m)
{
#if defined(__GNUC__)
    return __builtin_ctz(m);
#else
    int k = 0;
    while (!(m & 1u)) {
        m >>= 1;
        k++;
    }
    return k;
#endif
}

/* The binned split of least SAH cost, if below *best_cost: sets *best_axis,
 * *best_bin (the first bin of the right part) and *best_cost. Axes in
 * order, on each the boundaries from the top bin down, the first of equal
 * costs kept. `every`: sweep over every bin (the plain build); otherwise
 * over the bins that hold items, which tries the same boundaries that can
 * win: an empty bin changes neither the union nor the counts, so the
 * boundary below it costs exactly what the one above it does, tried just
 * before (or neither splits). Small nodes leave most bins empty. */
static void best_split(const Bins *bn, const Box *bounds, const int splittable[3], int every, int *best_axis,
                       int *best_bin, double *best_cost)
{
    double leaf_area = box_area(bounds);
    /* The cost is 1 + (1.5 x) / leaf_area, x = left_area nl + right_area s,
     * each step rounded upward or downward alike: never less for a larger
     * x. So a boundary whose x is at least the best's cannot win, and its
     * division is spared (a NaN x fails the test and is computed, to no
     * avail, as before). */
    double best_x = 0.0;
    int have_x = 0;
    for (int a = 0; a < 3; a++) {
        if (!splittable[a])
            continue;
        int used[BINS], nu = 0;
        if (every) {
            for (int k = 0; k < BINS; k++)
                used[nu++] = k;
        } else {
            for (unsigned m = used_bins(bn->n[a]); m; m &= m - 1)
                used[nu++] = lowest_bit(m);
        }
        /* Sweep: areas and counts left of each boundary, then right. */
        double left_area[BINS];
        int left_n[BINS];
        BinBox acc;
        binbox_empty(&acc);
        int s = 0;
        for (int u = 0; u < nu - 1; u++) {
            binbox_join(&acc, &bn->b[a][used[u]]);
            s += bn->n[a][used[u]];
            left_area[u] = area_of(acc.lo, acc.hi);
            left_n[u] = s;
        }
        binbox_empty(&acc);
        s = 0;
        for (int u = nu - 1; u > 0; u--) {
            int k = used[u];
            binbox_join(&acc, &bn->b[a][k]);
            s += bn->n[a][k];
            int nl = left_n[u - 1];
            if (nl == 0 || s == 0)
                continue;
            double x = left_area[u - 1] * nl + area_of(acc.lo, acc.hi) * s;
            if (!every && have_x && x >= best_x)
                continue;
            double cost = COST_TRAVERSE + COST_INTERSECT * x / leaf_area;
            if (cost < *best_cost) {
                *best_cost = cost;
                *best_axis = a;
                *best_bin = k;
                best_x = x;
                have_x = 1;
            }
        }
    }
}

/* Partition of it[0, count): items whose centre falls in a bin below
 * `split` on axis a go left; returns how many, with the halves' bounds
 * (lb, rb: those of their boxes, lcb, rcb: of their centres). The plain
 * pass grows rb over the right half afterwards, first to last; the SSE2
 * one as the items reach their places there, last to first, the new value
 * winning ties (<= for <), which keeps of equal bounds (+0 and -0) the one
 * the first-to-last pass keeps: the same bounds bit for bit. Without SSE2
 * the plain pass is the only one. */
static int partition_plain(BuildItem *it, int count, int a, float clo, float scale, int split, Box *lb, Box *lcb,
                           Box *rb, Box *rcb)
{
    int i = 0, j = count - 1;
    while (i <= j) {
        if (bin_of(it[i].centre[a], clo, scale) < split) {
            box_grow(lb, it[i].lo, it[i].hi);
            box_grow(lcb, it[i].centre, it[i].centre);
            i++;
        } else {
            BuildItem t = it[i];
            it[i] = it[j];
            it[j--] = t;
        }
    }
    for (int k = i; k < count; k++) {
        box_grow(rb, it[k].lo, it[k].hi);
        box_grow(rcb, it[k].centre, it[k].centre);
    }
    return i;
}

#if BUILD_SSE
/* minps/maxps where the new value wins ties (a NaN new value still
 * loses, as cmpleps/cmpgeps are false for it). */
static inline __m128 min_back(__m128 x, __m128 b)
{
    __m128 take = _mm_cmple_ps(x, b);
    return _mm_or_ps(_mm_and_ps(take, x), _mm_andnot_ps(take, b));
}

static inline __m128 max_back(__m128 x, __m128 b)
{
    __m128 take = _mm_cmpge_ps(x, b);
    return _mm_or_ps(_mm_and_ps(take, x), _mm_andnot_ps(take, b));
}

static int partition_sse(BuildItem *it, int count, int a, float clo, float scale, int split, Box *lb, Box *lcb,
                         Box *rb, Box *rcb)
{
    const __m128 mask = lanes3();
    __m128 lb_lo = load3(lb->lo), lb_hi = load3(lb->hi), lc_lo = load3(lcb->lo), lc_hi = load3(lcb->hi);
    __m128 rb_lo = load3(rb->lo), rb_hi = load3(rb->hi), rc_lo = load3(rcb->lo), rc_hi = load3(rcb->hi);
    int i = 0, j = count - 1;
    while (i <= j) {
        __m128 l = _mm_load_ps(it[i].lo), h = _mm_load_ps(it[i].hi), c = _mm_load_ps(it[i].centre);
        __m128 lm = _mm_and_ps(l, mask);
        if (bin_of(it[i].centre[a], clo, scale) < split) {
            lb_lo = _mm_min_ps(lm, lb_lo);
            lb_hi = _mm_max_ps(h, lb_hi);
            lc_lo = _mm_min_ps(c, lc_lo);
            lc_hi = _mm_max_ps(c, lc_hi);
            i++;
        } else {
            /* it[i] goes to it[j], its place: j only comes down. */
            it[i] = it[j];
            _mm_store_ps(it[j].lo, l);
            _mm_store_ps(it[j].hi, h);
            _mm_store_ps(it[j].centre, c);
            j--;
            rb_lo = min_back(lm, rb_lo);
            rb_hi = max_back(h, rb_hi);
            rc_lo = _mm_min_ps(c, rc_lo); /* centre bounds: order does not matter (Bins) */
            rc_hi = _mm_max_ps(c, rc_hi);
        }
    }
    store3(lb->lo, lb_lo);
    store3(lb->hi, lb_hi);
    store3(lcb->lo, lc_lo);
    store3(lcb->hi, lc_hi);
    store3(rb->lo, rb_lo);
    store3(rb->hi, rb_hi);
    store3(rcb->lo, rc_lo);
    store3(rcb->hi, rc_hi);
    return i;
}
#endif

static int partition(const Builder *bd, BuildItem *it, int count, int a, float clo, float scale, int split, Box *lb,
                     Box *lcb, Box *rb, Box *rcb)
{
    if (bd->plain)
        return partition_plain(it, count, a, clo, scale, split, lb, lcb, rb, rcb);
#if BUILD_SSE
    return partition_sse(it, count, a, clo, scale, split, lb, lcb, rb, rcb);
#else
    return partition_plain(it, count, a, clo, scale, split, lb, lcb, rb, rcb);
#endif
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
    atomic_fetch_add(h->sub.free_threads, 1); /* this thread is done */
    return NULL;
}

/* Takes one of the free threads, if any. */
static int take_thread(atomic_int *free_threads)
{
    int n = atomic_load(free_threads);
    while (n > 0)
        if (atomic_compare_exchange_weak(free_threads, &n, n - 1))
            return 1;
    return 0;
}

/* Both halves of a split: the second on another thread when it is big and
 * a thread is free, its nodes then appended after the first's, so that the
 * layout is the one a single thread makes, whichever thread built what.
 * Returns the second's root index, or -1 when out of memory. */
static int build_halves(Builder *bd, int first, int mid, int count, int depth, const Box *lb, const Box *lcb,
                        const Box *rb, const Box *rcb)
{
    pthread_t tid;
    Half h;
    int spawned = 0;
    if (count - mid >= PARALLEL_MIN && mid >= PARALLEL_MIN && take_thread(bd->free_threads)) {
        memset(&h, 0, sizeof h);
        h.sub.items = bd->items;
        h.sub.free_threads = bd->free_threads;
        h.sub.plain = bd->plain;
        h.first = first + mid;
        h.count = count - mid;
        h.depth = depth;
        (void)reserve_nodes(&h.sub, h.count);
        h.bounds = *rb;
        h.cbounds = *rcb;
        spawned = pthread_create(&tid, NULL, build_half, &h) == 0;
        if (!spawned)
            atomic_fetch_add(bd->free_threads, 1);
    }
    if (!spawned) {
        if (build(bd, first, mid, depth, lb, lcb))
            return -1;
        int second = bd->nnodes;
        if (build(bd, first + mid, count - mid, depth, rb, rcb))
            return -1;
        return second;
    }
    int failed = build(bd, first, mid, depth, lb, lcb);
    /* Waiting, this thread works no more: another split may use it. */
    atomic_fetch_add(bd->free_threads, 1);
    pthread_join(tid, NULL);
    atomic_fetch_sub(bd->free_threads, 1);
    int second = bd->nnodes;
    if (!failed && !h.failed) {
        while (bd->cap < bd->nnodes + h.sub.nnodes) {
            int cap = bd->cap ? bd->cap * 2 : 64;
            BinNode *n = big_realloc(bd->nodes, sizeof *n * (size_t)cap);
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
    if (count > 1 && !halve_only) {
        Bins bn;
        bin_items(bd, &bn, it, count, cbounds, scale);
        best_split(&bn, bounds, splittable, bd->plain, &best_axis, &best_bin, &best_cost);
    }
    int by_sah = best_axis >= 0 && best_cost < COST_INTERSECT * count;
    /* An instance (instance.h) takes a leaf of its own: its box is then
     * the leaf's, tested with its siblings' four at a time, where in a
     * shared leaf it would be tested alone before its walk. */
    int instance = 0;
    for (int i = 0; i < count && count > 1 && count <= LEAF_MAX; i++)
        instance |= (it[i].polygon & BVH_INSTANCE) != 0;
    if (!by_sah && instance)
        by_sah = best_axis >= 0; /* the best split there is, if any; else halving, below */
    if (!by_sah) {
        if (count <= LEAF_MAX && !instance) {
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
        mid = partition(bd, it, count, a, cbounds->lo[a], scale[a], best_bin, &lb, &lcb, &rb, &rcb);
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
    int fixed;       /* nodes is part of a bigger array: never grown */
    uint32_t offset; /* added to the interior indices it stores: the place of nodes[0] in that array */
} Collapser;

static void set_child_box(BvhNode *n, int k, const Box *b)
{
    for (int a = 0; a < 3; a++) {
        n->lo[a][k] = b->lo[a];
        n->hi[a][k] = b->hi[a];
    }
}

/* The children binary interior node bi's 4-wide node takes: its two, then,
 * while there is room, the largest interior one replaced by its own two.
 * Returns how many. */
static int wide_children(const BinNode *bin, uint32_t bi, uint32_t kids[BVH_WIDTH])
{
    int n = 2;
    kids[0] = bi + 1;
    kids[1] = bin[bi].index;
    while (n < BVH_WIDTH) {
        int best = -1;
        double best_area = -1.0;
        for (int k = 0; k < n; k++) {
            const BinNode *b = &bin[kids[k]];
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
        kids[n++] = bin[x].index;
    }
    return n;
}

/* The 4-wide node over those children: their boxes and leaves; an interior
 * child's index is the caller's to fill in. */
static BvhNode wide_node(const BinNode *bin, const uint32_t *kids, int n)
{
    BvhNode node;
    for (int k = 0; k < BVH_WIDTH; k++) {
        node.child[k] = BVH_EMPTY;
        for (int a = 0; a < 3; a++) {
            node.lo[a][k] = HUGE_VALF; /* an empty box: no ray meets it */
            node.hi[a][k] = -HUGE_VALF;
        }
    }
    for (int k = 0; k < n; k++) {
        const BinNode *b = &bin[kids[k]];
        set_child_box(&node, k, &b->box);
        if (b->count)
            node.child[k] = BVH_LEAF | (uint32_t)(b->count - 1) << BVH_COUNT_SHIFT | b->index;
    }
    return node;
}

/* The 4-wide node for binary interior node bi, its subtrees' after it,
 * depth first; returns its index, or -1 when out of memory. */
static int collapse(Collapser *c, uint32_t bi, int depth)
{
    if (c->nnodes == c->cap) {
        if (c->fixed)
            return -1; /* its size was counted: cannot happen */
        int cap = c->cap ? c->cap * 2 : 64;
        BvhNode *n = big_realloc(c->nodes, sizeof *n * (size_t)cap);
        if (!n)
            return -1;
        c->nodes = n;
        c->cap = cap;
    }
    int ni = c->nnodes++;
    if (depth > c->depth)
        c->depth = depth;
    uint32_t kids[BVH_WIDTH];
    int n = wide_children(c->bin, bi, kids);
    BvhNode node = wide_node(c->bin, kids, n);
    for (int k = 0; k < n; k++) {
        if (c->bin[kids[k]].count)
            continue;
        int sub = collapse(c, kids[k], depth + 1);
        if (sub < 0)
            return -1;
        node.child[k] = (uint32_t)sub + c->offset;
    }
    c->nodes[ni] = node;
    return ni;
}

/* The 4-wide nodes collapse makes of bi's subtree. */
static int count_wide_nodes(const BinNode *bin, uint32_t bi)
{
    uint32_t kids[BVH_WIDTH];
    int n = wide_children(bin, bi, kids), count = 1;
    for (int k = 0; k < n; k++)
        if (bin[kids[k]].count == 0)
            count += count_wide_nodes(bin, kids[k]);
    return count;
}

/* ---- the same collapse on threads ------------------------------------- */

/* A big hierarchy is collapsed on threads: the 4-wide nodes of its top
 * COLLAPSE_TOP_LEVELS levels are made here, and the subtrees below them on
 * threads that each take the next subtree left (the biggest first). The
 * subtrees' nodes are counted first, on the threads too, so that each is
 * made straight into its place in the whole array, the place the
 * one-thread collapse gives it (after its parent, after the subtrees of
 * its parent's earlier children): the same nodes at the same places,
 * whichever thread made them. */
#define COLLAPSE_TOP_LEVELS 3
#define COLLAPSE_SUBTREES_MAX 64 /* BVH_WIDTH^COLLAPSE_TOP_LEVELS */
#define COLLAPSE_PARALLEL_MIN (4 * PARALLEL_MIN) /* binary nodes: below, one thread */

typedef struct {
    uint32_t bin;   /* the subtree's binary root */
    int depth;      /* its 4-wide root's depth */
    uint32_t size;  /* binary nodes in it: the biggest are taken first */
    int count;      /* its 4-wide nodes */
    int base;       /* the first one's place */
    int deepest;    /* its deepest 4-wide node's depth */
    int failed;
} Subtree;

typedef struct {
    Subtree *subs;
    const int *order; /* the subtrees, biggest first */
    int nsubs;
    atomic_int next;
    const BinNode *bin;
    BvhNode *nodes;   /* the whole array, once counted */
} SubtreeQueue;

typedef struct {
    SubtreeQueue *q;
} SubtreeWorker;

/* The binary nodes of bi's subtree: in depth-first order they run from bi
 * to its last descendant, the end of its chain of second children. */
static uint32_t subtree_size(const BinNode *bin, uint32_t bi)
{
    uint32_t x = bi;
    while (bin[x].count == 0)
        x = bin[x].index;
    return x + 1 - bi;
}

/* The subtrees below the top `levels` levels of bi's 4-wide node, in the
 * order the one-thread collapse reaches them; *ntop counts the top's nodes. */
static int list_subtrees(const BinNode *bin, uint32_t bi, int depth, int levels, Subtree *subs, int n, int *ntop)
{
    (*ntop)++;
    uint32_t kids[BVH_WIDTH];
    int m = wide_children(bin, bi, kids);
    for (int k = 0; k < m; k++) {
        if (bin[kids[k]].count)
            continue;
        if (levels == 1)
            subs[n++] = (Subtree){ .bin = kids[k], .depth = depth + 1, .size = subtree_size(bin, kids[k]) };
        else
            n = list_subtrees(bin, kids[k], depth + 1, levels - 1, subs, n, ntop);
    }
    return n;
}

static void *count_subtrees(void *arg)
{
    SubtreeQueue *q = ((SubtreeWorker *)arg)->q;
    for (int i; (i = atomic_fetch_add(&q->next, 1)) < q->nsubs;) {
        Subtree *s = &q->subs[q->order[i]];
        s->count = count_wide_nodes(q->bin, s->bin);
    }
    return NULL;
}

static void *collapse_subtrees(void *arg)
{
    SubtreeQueue *q = ((SubtreeWorker *)arg)->q;
    for (int i; (i = atomic_fetch_add(&q->next, 1)) < q->nsubs;) {
        Subtree *s = &q->subs[q->order[i]];
        Collapser c = { .bin = q->bin, .nodes = q->nodes + s->base, .cap = s->count, .fixed = 1,
                        .offset = (uint32_t)s->base };
        s->failed = collapse(&c, s->bin, s->depth) < 0 || c.nnodes != s->count;
        s->deepest = c.depth;
    }
    return NULL;
}

/* The top's 4-wide nodes, as collapse makes them, with the subtrees'
 * places kept for them. */
static int place_top(Collapser *c, uint32_t bi, int depth, int levels, Subtree *subs, int *next)
{
    int ni = c->nnodes++;
    if (depth > c->depth)
        c->depth = depth;
    uint32_t kids[BVH_WIDTH];
    int n = wide_children(c->bin, bi, kids);
    BvhNode node = wide_node(c->bin, kids, n);
    for (int k = 0; k < n; k++) {
        if (c->bin[kids[k]].count)
            continue;
        if (levels == 1) {
            Subtree *s = &subs[(*next)++];
            s->base = c->nnodes;
            c->nnodes += s->count;
            node.child[k] = (uint32_t)s->base;
        } else {
            node.child[k] = (uint32_t)place_top(c, kids[k], depth + 1, levels - 1, subs, next);
        }
    }
    c->nodes[ni] = node;
    return ni;
}

/* collapse(c, 0, 1) on up to `threads` threads, into c->nodes (which it
 * allocates). Returns 0, or -1 when out of memory. */
static int collapse_on_threads(Collapser *c, int threads)
{
    Subtree subs[COLLAPSE_SUBTREES_MAX];
    int order[COLLAPSE_SUBTREES_MAX];
    int ntop = 0;
    int nsubs = list_subtrees(c->bin, 0, 1, COLLAPSE_TOP_LEVELS, subs, 0, &ntop);
    /* Biggest first, so that no thread is left with a big one at the end. */
    for (int i = 0; i < nsubs; i++) {
        int k = i;
        while (k > 0 && subs[order[k - 1]].size < subs[i].size) {
            order[k] = order[k - 1];
            k--;
        }
        order[k] = i;
    }
    SubtreeQueue q = { subs, order, nsubs, 0, c->bin, NULL };
    SubtreeWorker workers[PARALLEL_MAX_JOBS];
    int nw = threads < nsubs ? threads : nsubs;
    nw = nw > PARALLEL_MAX_JOBS ? PARALLEL_MAX_JOBS : nw < 1 ? 1 : nw;
    for (int t = 0; t < nw; t++)
        workers[t].q = &q;
    parallel_run(nw, count_subtrees, workers, sizeof workers[0]);
    long total = ntop;
    for (int i = 0; i < nsubs; i++)
        total += subs[i].count;
    c->nodes = total <= INT32_MAX ? big_malloc(sizeof *c->nodes * (size_t)total) : NULL;
    if (!c->nodes)
        return -1;
    c->cap = (int)total;
    int next = 0;
    place_top(c, 0, 1, COLLAPSE_TOP_LEVELS, subs, &next);
    q.nodes = c->nodes;
    atomic_store(&q.next, 0);
    parallel_run(nw, collapse_subtrees, workers, sizeof workers[0]);
    int failed = 0;
    for (int i = 0; i < nsubs; i++) {
        failed |= subs[i].failed;
        if (subs[i].deepest > c->depth)
            c->depth = subs[i].deepest;
    }
    return failed ? -1 : 0;
}

/* The margin every polygon's box grows by, beyond rounding to float.
 * The polygon test's distance t is the ray's distance to the polygon's
 * stored plane, (d - n.org) / (n.dir), whose rounding (and the stored
 * plane's own, at the vertices) can put the computed hit a few units of
 * 2^-53 of the coordinates' size outside the polygon's exact box: a box
 * face on a coordinate that float holds exactly (0, integers: the box
 * faces of a city, a vertex at -0) then gets no slack from the rounding
 * to float, and a polygon whose computed t is the nearest could sit in a
 * box the ray enters just beyond that t, and be culled (tests/test_bvh.c's
 * soup of zero coordinates: one ray in 6672 took the next polygon, 2e-16
 * farther). 2^-32 of the largest coordinate a polygon or the camera (where
 * rays start) has covers that error up to rays within 1e-6 of the plane's
 * direction; it is 2e-10 of the scene's size, too little to cost a box
 * test. A scene beyond float's range gets none (its boxes are infinite). */
static double box_margin(double origins_max_abs, double polygons_max_abs)
{
    double s = fmax(origins_max_abs, polygons_max_abs);
    return isfinite(s) ? s * 0x1p-32 : 0.0;
}

/* The build records of polygons [first, end), made on one of the set-up's
 * threads: first the largest coordinate (for the margin), then, the margin
 * known, the records and the union of their boxes and of their centres
 * (taken in index order; the runs' unions are joined in run order, which
 * keeps what one pass keeps, equal bounds of either sign included). */
typedef struct {
    const World *w;
    BuildItem *items;
    int first, end;       /* items: polygons src_first + [0, npolygons), then the world's instances */
    int src_first, npolygons;
    int shapes;           /* 1: the items are the world's shapes (Bvh.shapes) instead */
    double max_abs, margin;
    Box bounds, cbounds;
} SetupJob;

/* Item i's box: a polygon's, or an instance's in world space. */
static void item_box(const SetupJob *j, int i, Vec3 *lo, Vec3 *hi, uint32_t *item)
{
    if (j->shapes) {
        /* a shape's box, held within +-1e30 (a huge or broken shape's may
         * be infinite): the shapes report no crossing farther than
         * POV-Ray's MAX_DISTANCE (1e7) from where a ray starts */
        const Shape *s = &j->w->shapes[i];
        *lo = v3(fmin(fmax(s->bbox_min.x, -1e30), 1e30), fmin(fmax(s->bbox_min.y, -1e30), 1e30),
                 fmin(fmax(s->bbox_min.z, -1e30), 1e30));
        *hi = v3(fmax(fmin(s->bbox_max.x, 1e30), -1e30), fmax(fmin(s->bbox_max.y, 1e30), -1e30),
                 fmax(fmin(s->bbox_max.z, 1e30), -1e30));
        *item = (uint32_t)i;
        return;
    }
    if (i < j->npolygons) {
        const Polygon *p = &j->w->polygons[j->src_first + i];
        *lo = p->bbox_min;
        *hi = p->bbox_max;
        *item = (uint32_t)(j->src_first + i);
    } else {
        const Instance *in = &j->w->instances[i - j->npolygons];
        *lo = in->bbox_min;
        *hi = in->bbox_max;
        *item = BVH_INSTANCE | (uint32_t)(i - j->npolygons);
    }
}

static void *largest_coordinate(void *arg)
{
    SetupJob *j = arg;
    double s = 0.0;
    for (int i = j->first; i < j->end; i++) {
        Vec3 lo, hi;
        uint32_t item;
        item_box(j, i, &lo, &hi, &item);
        s = fmax(s, fmax(v3_max_abs(lo), v3_max_abs(hi)));
    }
    j->max_abs = s;
    return NULL;
}

static void *make_items(void *arg)
{
    SetupJob *j = arg;
    box_empty(&j->bounds);
    box_empty(&j->cbounds);
    for (int i = j->first; i < j->end; i++) {
        Vec3 blo, bhi;
        uint32_t item;
        item_box(j, i, &blo, &bhi, &item);
        BuildItem *it = &j->items[i];
        double lo[3] = { blo.x, blo.y, blo.z };
        double hi[3] = { bhi.x, bhi.y, bhi.z };
        for (int a = 0; a < 3; a++) {
            it->lo[a] = round_down(lo[a] - j->margin);
            it->hi[a] = round_up(hi[a] + j->margin);
            it->centre[a] = (float)(0.5 * (lo[a] + hi[a]));
        }
        it->polygon = item;
        it->hi_pad = 0.0f;
        it->centre_pad = 0.0f;
        box_grow(&j->bounds, it->lo, it->hi);
        box_grow(&j->cbounds, it->centre, it->centre);
    }
    return NULL;
}

/* The leaf items' records [first, end), in leaf order: what a query hides,
 * and the packed form of the polygon test (bvh.h). */
typedef struct {
    const World *w;
    const uint32_t *order;
    BvhPrim *prims;
    PackedPolygon *packed;
    int first, end;
    int prototype;        /* a prototype's polygons: materials are its instances', hidden by them */
    int shapes;           /* the items are shapes (World.shapes) */
} PrimJob;

static uint32_t hide_bits(const Material *m)
{
    return (m->no_image ? HIDE_NO_IMAGE : 0u) | (m->no_reflection ? HIDE_NO_REFLECTION : 0u) |
           (m->no_shadow ? HIDE_NO_SHADOW : 0u);
}

static void *make_prims(void *arg)
{
    PrimJob *j = arg;
    const World *w = j->w;
    for (int k = j->first; k < j->end; k++) {
        BvhPrim *pr = &j->prims[k];
        if (j->shapes) {
            pr->hide = hide_bits(&w->materials[w->shapes[j->order[k]].material]);
            pr->packed = 0u;
            continue;
        }
        if (j->order[k] & BVH_INSTANCE) { /* an instance: its own walk hides what it hides */
            pr->hide = 0u;
            pr->packed = 0u;
            continue;
        }
        const Polygon *p = &w->polygons[j->order[k]];
        if (j->prototype) {
            pr->hide = 0u;
        } else {
            pr->hide = hide_bits(&w->materials[p->material]);
        }
        pr->packed = j->packed ? (uint32_t)polygon_pack(w, p, &j->packed[k]) : 0u;
    }
    return NULL;
}

/* Polygons per set-up thread, at least. */
#define SETUP_PER_THREAD_MIN 50000

/* The hierarchy over polygons [src_first, src_first + npolygons) of w and,
 * with `instances`, the world's instances (the top level), or with
 * `shapes` over the world's shapes alone (Bvh.shapes); rays start within
 * origins_max_abs of the origin, in the space of the polygons. */
static int build_bvh_over(Bvh *b, const World *w, int src_first, int npolygons, int instances, int shapes,
                          double origins_max_abs, int threads, int plain)
{
    memset(b, 0, sizeof *b);
    int n = shapes ? w->nshapes : npolygons + (instances ? w->ninstances : 0);
    Builder bd;
    memset(&bd, 0, sizeof bd);
    threads = threads > 1 ? threads : 1;
    atomic_int free_threads = threads - 1;
    bd.free_threads = &free_threads;
    bd.plain = plain;
    (void)reserve_nodes(&bd, n);
    /* 16-byte aligned for the vector loads (sizeof (BuildItem) is 48). */
    bd.items = aligned_alloc(16, sizeof *bd.items * (size_t)(n > 0 ? n : 1));
    big_memory_advise(bd.items, sizeof *bd.items * (size_t)(n > 0 ? n : 1));
    uint32_t *order = big_malloc(sizeof *order * (size_t)(n > 0 ? n : 1));
    if (!bd.items || !order) {
        free(bd.items);
        free(order);
        free(bd.nodes);
        return -1;
    }
    SetupJob jobs[PARALLEL_MAX_JOBS];
    int nj = parallel_jobs(n, SETUP_PER_THREAD_MIN, threads);
    double max_abs = 0.0;
    for (int k = 0; k < nj; k++) {
        jobs[k] = (SetupJob){ .w = w, .items = bd.items, .src_first = src_first, .npolygons = npolygons,
                              .shapes = shapes };
        jobs[k].first = (int)((long long)n * k / nj);
        jobs[k].end = (int)((long long)n * (k + 1) / nj);
    }
    parallel_run(nj, largest_coordinate, jobs, sizeof jobs[0]);
    for (int k = 0; k < nj; k++)
        max_abs = fmax(max_abs, jobs[k].max_abs);
    const double margin = box_margin(origins_max_abs, max_abs);
    for (int k = 0; k < nj; k++)
        jobs[k].margin = margin;
    parallel_run(nj, make_items, jobs, sizeof jobs[0]);
    Box bounds, cbounds;
    box_empty(&bounds);
    box_empty(&cbounds);
    for (int k = 0; k < nj; k++) {
        box_join(&bounds, &jobs[k].bounds);
        box_join(&cbounds, &jobs[k].cbounds);
    }
    if (instances && w->ninstances > 0) {
        /* the instances' boxes as built, before the build moves the items */
        b->instance_box = malloc(sizeof *b->instance_box * 6 * (size_t)w->ninstances);
        if (!b->instance_box) {
            free(bd.items);
            free(order);
            free(bd.nodes);
            return -1;
        }
        for (int i = 0; i < w->ninstances; i++)
            for (int a = 0; a < 3; a++) {
                b->instance_box[6 * i + a] = bd.items[npolygons + i].lo[a];
                b->instance_box[6 * i + 3 + a] = bd.items[npolygons + i].hi[a];
            }
    }
    int failed = n > 0 && build(&bd, 0, n, 1, &bounds, &cbounds);
    for (int i = 0; i < n && !failed; i++)
        order[i] = bd.items[i].polygon;
    free(bd.items);
    Collapser c;
    memset(&c, 0, sizeof c);
    c.bin = bd.nodes;
    /* Room for them all at once: a 4-wide node per binary interior node at
     * most, about a third of them used (pages never touched cost nothing);
     * growing by doublings copied 20 MB on 10^6 polygons. */
    int on_threads = threads > 1 && bd.nnodes >= COLLAPSE_PARALLEL_MIN;
    if (!failed && n > 0 && !bd.nodes[0].count && !on_threads) {
        c.cap = bd.nnodes / 2 + 1;
        c.nodes = big_malloc(sizeof *c.nodes * (size_t)c.cap);
        if (!c.nodes)
            c.cap = 0; /* collapse grows it, or fails, as before */
    }
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
        } else if (on_threads) {
            failed = collapse_on_threads(&c, threads) < 0;
        } else {
            failed = collapse(&c, 0, 1) < 0;
        }
    }
    free(bd.nodes);
    if (failed) {
        free(order);
        free(c.nodes);
        free(b->instance_box);
        b->instance_box = NULL;
        return -1;
    }
    BvhPrim *prims = big_malloc(sizeof *prims * (size_t)(n > 0 ? n : 1));
    const int pack = n <= BVH_PACK_MAX && !shapes;
    PackedPolygon *packed = pack ? big_malloc(sizeof *packed * (size_t)(n > 0 ? n : 1)) : NULL;
    if (!prims || (pack && !packed)) {
        free(prims);
        free(packed);
        free(order);
        free(c.nodes);
        free(b->instance_box);
        b->instance_box = NULL;
        return -1;
    }
    PrimJob pj[PARALLEL_MAX_JOBS];
    nj = parallel_jobs(n, SETUP_PER_THREAD_MIN, threads);
    for (int k = 0; k < nj; k++)
        pj[k] = (PrimJob){ w, order, prims, packed, (int)((long long)n * k / nj), (int)((long long)n * (k + 1) / nj),
                           !instances, shapes };
    parallel_run(nj, make_prims, pj, sizeof pj[0]);
    b->prims = prims;
    b->packed = packed;
    b->nodes = c.nodes;
    b->nnodes = c.nnodes;
    b->items = order;
    b->nitems = n;
    b->depth = c.depth;
    return 0;
}

/* The farthest from the origin a ray starts in world space: the camera
 * (with its frame) or any surface point. */
static double world_origins_max_abs(const World *w)
{
    const Camera *c = &w->camera;
    double s = v3_max_abs(c->location) + v3_length(c->right) + v3_length(c->up) + v3_length(c->direction);
    if (w->bounds_min.x <= w->bounds_max.x)
        s = fmax(s, fmax(v3_max_abs(w->bounds_min), v3_max_abs(w->bounds_max)));
    return s;
}

/* The same in prototype k's space, over its instances: where the camera
 * and the corners of the world's box land there. */
static double prototype_origins_max_abs(const World *w, int k)
{
    const Camera *c = &w->camera;
    double frame = v3_length(c->right) + v3_length(c->up) + v3_length(c->direction);
    double s = 0.0;
    for (int i = 0; i < w->ninstances; i++) {
        const Instance *in = &w->instances[i];
        if (in->prototype != k)
            continue;
        s = fmax(s, v3_max_abs(inverse_transform_point(&in->to_world, c->location)) +
                        v3_length(inverse_transform_direction(&in->to_world, v3(frame, frame, frame))));
        for (int q = 0; q < 8 && w->bounds_min.x <= w->bounds_max.x; q++) {
            Vec3 x = v3(q & 1 ? w->bounds_max.x : w->bounds_min.x, q & 2 ? w->bounds_max.y : w->bounds_min.y,
                        q & 4 ? w->bounds_max.z : w->bounds_min.z);
            s = fmax(s, v3_max_abs(inverse_transform_point(&in->to_world, x)));
        }
    }
    return s;
}

static int build_bvh(Bvh *b, const World *w, int threads, int plain)
{
    if (build_bvh_over(b, w, 0, w->npolygons, 1, 0, world_origins_max_abs(w), threads, plain))
        return -1;
    if (w->nshapes > 0) {
        b->shapes = calloc(1, sizeof *b->shapes);
        if (!b->shapes || build_bvh_over(b->shapes, w, 0, 0, 0, 1, world_origins_max_abs(w), threads, plain)) {
            bvh_free(b);
            return -1;
        }
    }
    if (w->nprototypes == 0)
        return 0;
    b->protos = calloc((size_t)w->nprototypes, sizeof *b->protos);
    if (!b->protos) {
        bvh_free(b);
        return -1;
    }
    b->nprotos = w->nprototypes;
    for (int k = 0; k < w->nprototypes; k++) {
        const Prototype *pr = &w->prototypes[k];
        if (build_bvh_over(&b->protos[k], w, pr->first_polygon, pr->npolygons, 0, 0, prototype_origins_max_abs(w, k),
                           threads, plain)) {
            bvh_free(b);
            return -1;
        }
    }
    return 0;
}

int bvh_build(Bvh *b, const World *w, int threads) { return build_bvh(b, w, threads, 0); }

int bvh_build_plain(Bvh *b, const World *w, int threads) { return build_bvh(b, w, threads, 1); }

void bvh_free(Bvh *b)
{
    if (b->shapes)
        bvh_free(b->shapes);
    free(b->shapes);
    for (int k = 0; k < b->nprotos; k++)
        bvh_free(&b->protos[k]);
    free(b->protos);
    free(b->instance_box);
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
        bvh_ray_faces(&r, a);
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

/* bvh_shapes_walk and bvh_shapes_nearest_walk: `nearest_first` pushes a
 * node's children met so that the nearest entered is visited first.
 * Always inlined: into shapes_walk_avx2, so that the AVX2 node test is
 * compiled in place rather than called per node. */
__attribute__((always_inline)) static inline int shapes_walk(const Bvh *b, Vec3 org, Vec3 dir, double *tmax,
                                                             unsigned hide, BvhShapeVisitor visit, void *user,
                                                             uint64_t *nodes, int nearest_first, int avx2)
{
    if (!b || b->nnodes == 0)
        return 0;
    /* the AVX2 node test broadcasts the ray itself: no SSE2 lanes made for it */
    BvhRay br;
    if (avx2)
        bvh_ray_scalar(&br, org, dir);
    else
        br = bvh_ray(org, dir);
    uint32_t stack[BVH_STACK];
    double enter_at[BVH_STACK];
    int sp = 0;
    stack[sp] = 0;
    enter_at[sp++] = 0.0;
    while (sp > 0) {
        sp--;
        uint32_t c = stack[sp];
        /* entered beyond what the visits left of the ray: passed over */
        if (enter_at[sp] > *tmax * BVH_GROW)
            continue;
        if (!bvh_is_leaf(c)) {
            const BvhNode *n = &b->nodes[c];
            double enter[BVH_WIDTH];
            ++*nodes;
#if BVH_HAVE_AVX2_PATH
            unsigned mask = avx2 ? bvh_node_hits_avx2(n, &br, 0.0, *tmax, enter)
                                 : bvh_node_hits(n, &br, 0.0, *tmax, enter);
#else
            unsigned mask = bvh_node_hits(n, &br, 0.0, *tmax, enter);
#endif
            int first = sp;
            /* the children met, the last first (the first is visited first) */
            while (mask) {
                int k = 31 - __builtin_clz(mask);
                mask &= ~(1u << k);
                if (n->child[k] != BVH_EMPTY) {
                    stack[sp] = n->child[k];
                    enter_at[sp++] = enter[k];
                }
            }
            if (nearest_first) /* farthest lowest on the stack: insertion sort of at most BVH_WIDTH */
                for (int i = first + 1; i < sp; i++)
                    for (int j = i; j > first && enter_at[j - 1] < enter_at[j]; j--) {
                        double e = enter_at[j];
                        uint32_t x = stack[j];
                        enter_at[j] = enter_at[j - 1];
                        stack[j] = stack[j - 1];
                        enter_at[j - 1] = e;
                        stack[j - 1] = x;
                    }
            continue;
        }
        uint32_t first = bvh_leaf_first(c), end = first + bvh_leaf_count(c);
        /* a leaf of one: the node test was its shape's own box */
        const int boxed = end == first + 1;
        for (uint32_t k = first; k < end; k++)
            if (!(b->prims[k].hide & hide) && visit(user, (int)b->items[k], boxed, tmax))
                return 1;
    }
    return 0;
}

/* The walks with the AVX2 node test, inlined where the processor has it
 * (the same answers: bvh.h). */
#if BVH_HAVE_AVX2_PATH
__attribute__((target("avx2"))) static int shapes_walk_avx2(const Bvh *b, Vec3 org, Vec3 dir, double *tmax,
                                                            unsigned hide, BvhShapeVisitor visit, void *user,
                                                            uint64_t *nodes, int nearest_first)
{
    return nearest_first ? shapes_walk(b, org, dir, tmax, hide, visit, user, nodes, 1, 1)
                         : shapes_walk(b, org, dir, tmax, hide, visit, user, nodes, 0, 1);
}
#endif

int bvh_shapes_walk(const Bvh *b, Vec3 org, Vec3 dir, double *tmax, unsigned hide, BvhShapeVisitor visit, void *user,
                    uint64_t *nodes, int avx2)
{
#if BVH_HAVE_AVX2_PATH
    if (avx2)
        return shapes_walk_avx2(b, org, dir, tmax, hide, visit, user, nodes, 0);
#endif
    (void)avx2;
    return shapes_walk(b, org, dir, tmax, hide, visit, user, nodes, 0, 0);
}

int bvh_shapes_nearest_walk(const Bvh *b, Vec3 org, Vec3 dir, double *tmax, unsigned hide, BvhShapeVisitor visit,
                            void *user, uint64_t *nodes, int avx2)
{
#if BVH_HAVE_AVX2_PATH
    if (avx2)
        return shapes_walk_avx2(b, org, dir, tmax, hide, visit, user, nodes, 1);
#endif
    (void)avx2;
    return shapes_walk(b, org, dir, tmax, hide, visit, user, nodes, 1, 0);
}
