/* Shadow methods: one interface, selectable by name (--shadows, through
 * the registry: shadow_registry.h). A method answers, for a shading point
 * and a light, how much of the light arrives: (1,1,1) unblocked, (0,0,0)
 * blocked by an opaque object, a colour when the light passes through
 * transparent (filter/transmit) objects, as POV-Ray filters it. The conventional shadow ray is the exact reference; every
 * other method must give the same answer (--verify-shadows counts where it
 * does not).
 *
 * Methods that carry a shadow condition along the ray tree (volume, hst)
 * keep a LightState per light at every shading point; each ray segment
 * knows the state at its start and fills the one at its end. */
#ifndef HST_SHADOW_H
#define HST_SHADOW_H

#include <stddef.h>

#include "tracer.h"

/* What is known about one light at one point. The depth counts are the
 * number of opaque and of transparent polygons between the point and the
 * light (the polygon the point lies on excluded); infinite planes are not
 * counted, every method tests them directly. */
typedef enum { COND_UNKNOWN = 0, COND_LIT, COND_BLOCKED, COND_FILTERED } ShadowCondition;

typedef struct {
    int8_t condition;     /* of the polygons alone (ShadowCondition) */
    int8_t depth_known;
    int8_t self;          /* blocked by the polygon the point lies on (self-shadow) */
    int32_t depth_opaque, depth_transparent;
} LightState;

/* The ray segment P1 -> P2 that found the shading point P2. */
typedef struct {
    Vec3 org, dir;                /* P1 and the unit direction */
    const Hit *from;              /* P1's surface (HIT_NONE: the eye) */
    const LightState *from_state; /* per light at P1; NULL: the eye's */
    LightState *state;            /* per light at P2, filled by the method; NULL: not kept */
    /* The interiors the segment runs inside (the ray's, innermost last;
     * may be 0 with NULL): POV-Ray's shadow ray starts inside them, which
     * decides where it fades (shadow_fold_filtered). */
    const void *const *inside;
    int ninside;
} Segment;

typedef struct {
    Vec3 point;          /* the shading point P2 */
    const Hit *surface;  /* the surface it lies on (excluded from the test) */
    const Segment *segment;
    int light;           /* index into World.lights */
    Vec3 to_light;       /* unit direction toward the light */
    double distance;     /* to the light (parallel: to the light's plane) */
    Vec3 normal;         /* shading normal, facing the arriving ray */
    const Light *source; /* the point light the ray is aimed at: &World.lights[light], or
                          * one sample of that area light (area_light.h) */
} ShadowQuery;

/* 1 when q's point is the hit of a reflected, refracted or transmitted
 * ray, 0 at a camera ray's hit. */
static inline int shadow_query_secondary(const ShadowQuery *q)
{
    return q->segment && q->segment->from && q->segment->from->kind != HIT_NONE;
}

/* How a decision was made (statistics, --verify-shadows, --aov). A test
 * always sets ctx->last_scheme; a skip sets it only when it decides the
 * state at P2 (sustain, self-shadow, volume), so callers that want to know
 * set SCHEME_NONE before a skip. */
typedef enum {
    SCHEME_NONE = -1,
    SCHEME_SUSTAIN, SCHEME_SELF_SHADOW, SCHEME_VOLUME, SCHEME_CONVENTIONAL, SCHEME_CACHE_HIT,
    /* hst's area lights (area_light_beam.h): samples proved lit or in umbra
     * with the rest of the light by its beam, or decided by a shadow ray
     * against the beam's candidates */
    SCHEME_AREA_LIT, SCHEME_AREA_UMBRA, SCHEME_AREA_BEAM,
    /* the light buffer (light_buffer.h): no candidate nearer the light than
     * the point, a proved cover, or the candidates tested */
    SCHEME_BUFFER_LIT, SCHEME_BUFFER_COVER, SCHEME_BUFFER_LIST,
    SCHEME_COUNT
} ShadowScheme;

extern const char *const shadow_scheme_names[SCHEME_COUNT];

/* What the shadow methods did, for the statistics (summed over threads):
 * the counters of shadow_counters.def, then the decisions and the
 * disagreements by sub-scheme and the time. */
typedef struct {
#define SHADOW_COUNTER(field, line, label, key, meaning) uint64_t field;
#include "shadow_counters.def"
#undef SHADOW_COUNTER
    uint64_t shadow_schemes[SCHEME_COUNT]; /* decisions, in the order of ShadowScheme */
    uint64_t shadow_disagreements_by_scheme[SCHEME_COUNT];
    double shadow_seconds;        /* time spent deciding shadows, summed over threads */
    double shadow_seconds_secondary; /* ... of which for shading points at secondary hits */
} ShadowCounters;

void shadow_counters_add(ShadowCounters *total, const ShadowCounters *part);

/* The cache method's memory of one light: the opaque polygon that last
 * blocked it, and how often trying it first has paid in this tile (a
 * shading point's neighbours on a mesh of small triangles are seldom
 * blocked by the same one, and a miss costs a polygon test). */
typedef struct {
    int blocker;               /* the polygon (its id, instance.h), or -1 */
    /* Its plane in world space (world_polygon_plane: an instance's is
     * carried out with a square root) and its instance (-1: a world
     * polygon), made at its first try rather than at every try, nor when
     * it is remembered (on a big mesh the blocker changes at nearly every
     * blocked decision and the cache sits out most of them) */
    Polygon plane;
    int instance;
    int plane_made;            /* 1: plane and instance are the blocker's */
    unsigned tries, hits;      /* cache tries in this tile and the hits among them */
    unsigned skipped;          /* queries the cache sat out since its last try */
    int lit_last;              /* 1: the light's last decision here found no polygon blocking it fully */
} LightCache;

/* A see-through polygon a shadow ray met, at distance t. */
typedef struct {
    double t;
    uint32_t polygon;
} FilteredHit;

/* A thread's last light buffer cell of a light (shadow_light_buffer.c),
 * and where it lies: face and indices at its level. One for the camera's
 * hits and one for the secondary ones, which interleave with them but
 * are coherent among themselves (shadow_query_secondary). */
typedef struct LbMemo {
    const struct LbCell *cell;
    int face, i, j;
} LbMemo;
/* The cells remembered per light and kind of point (ShadowContext.
 * light_buffer_memo), the last used first: two, since the points a thread
 * asks about often go back and forth across a cell's border (the
 * anti-aliasing's samples, a tile's rows). */
#define LB_MEMO_CELLS 2

/* The most polygons an hst beam gathers before it gives up (its samples
 * then decided by the shadow ray through the hierarchy). */
#define AREA_BEAM_CAP 256

/* A render thread's shadow testing: the tracer it asks (the shading's, or
 * its own when it is used alone), the method, and the methods' per-thread
 * state. */
typedef struct ShadowContext {
    Tracer *tracer;
    Tracer own_tracer;         /* the tracer of a context made without one */
    int owns_tracer;
    const struct ShadowMethod *method;
    ShadowCounters stats;
    int last_scheme;           /* how the last decision was made (ShadowScheme) */
    int last_blocker;          /* polygon that blocked the last shadow ray, or -1 */
    int last_filtered;         /* transparent polygons the last shadow ray passed */
    unsigned shadow_timer;     /* decisions until the next timed one (shadow_decide.c) */
    double clock_floor;        /* the least interval between two reads of the clock (shadow_decide.h) */
    LightCache *light_cache;   /* cache method: per light, the last opaque blocker and how often it pays */
    FilteredHit *filtered;     /* the shadow ray's see-through polygons, one slot for each of the world's */
    int nfiltered;
    int perturb_normals;       /* the render perturbs normals (+Q8): so do fake caustics (shadow_conventional.c) */
    int verify;                /* 1: check every decision against the shadow ray (--verify-shadows);
                                  2: and against the long-double reference (--verify-reference) */
    long double reference_eps; /* the reference's margin of ties */
    double nth;                /* hst: N_th; negative: per point from its own N_c */
    const struct CostModel *cost;  /* for the per-point N_th */
    /* Shadow buckets (volume, hst): the tracer records the cells each
     * segment pierced; a method that needs a light's bucket (the shadow
     * polygons registered in those cells, each once: stamps) fills it from
     * them (shadow_bucket.h). */
    const struct ShadowVolumes *volumes;
    uint32_t *sp_stamp;
    uint32_t sp_id;
    uint32_t *bucket;          /* room for any light's shadow polygons */
    struct PixelCoherence *coherence; /* hst's pixel coherence (its thread_init makes it), or NULL when off */
    void *method_state;        /* a method's own per-thread data (its thread_init makes it), or NULL */
    const struct EmbreeScene *embree; /* the embree method's scene (shared, read-only), or NULL */
    struct LightBuffers *light_buffers; /* the lights' buffers (shared, built as points ask), or NULL */
    struct LbMemo *light_buffer_memo;   /* ... and per light, at LB_MEMO_CELLS (2 light + secondary): the cells this thread used last */
    /* Time of the current decision already counted whole (a light buffer's
     * cell built), which the sampled timing leaves out (shadow_decide.h). */
    double untimed_seconds;
    /* Area lights: the samples decided at the current point, a colour per
     * sample of the largest (area_light.c); NULL without area lights. */
    RGB *area_colour;
    unsigned char *area_known;
    uint32_t *area_candidates;  /* hst: a beam's candidates (AREA_BEAM_CAP) */
    /* Per light: its samples' places on the grid (index u * size2 + v)
     * when they are the same from every point (no jitter) and there are at
     * most AREA_FIXED_CAP of them; else NULL. The grid's divisions done
     * once per thread, not per sample (area_light_samples.h). */
    double (**area_fixed_factors)[2];
    int *area_uniform_visits;   /* per light: the samples its sampling visits when all agree */
    int *area_uniform_levels;   /* ... and the levels of means over them */
    /* Light states along the ray tree: one row of nlights per recursion
     * depth, which the volume methods' segment hooks hand out. */
    LightState *states;
    int state_depth, state_capacity;
} ShadowContext;

struct ShadowPrepared;

/* A thread's context for the prepared method p (its decider, volumes,
 * Embree scene, cost model and N_th): the common part, then the method's
 * own (its thread_init); a p without a decider gives the common part alone
 * (the measurements of the cost model and the volume plan, which call the
 * decisions and the volume methods' thread state themselves). tracer: the
 * shading's, which the context asks; NULL: a tracer of its own (a context
 * used alone: the plan's pilot, the cost model, tests). verify:
 * --verify-shadows (1) or --verify-reference (2). pixel_coherence: hst may
 * count from the neighbouring pixel. Returns 0, or -1 when out of memory
 * (free it all the same). */
int shadow_context_init(ShadowContext *ctx, Tracer *tracer, const World *w, const Grid *g,
                        const struct ShadowPrepared *p, int verify, int pixel_coherence);
void shadow_context_free(ShadowContext *ctx);

/* The render loop's hooks, which call the method's where it has them:
 * at each tile's start (the caches start empty, so that a pixel's
 * decisions and counts do not depend on the tiles rendered before); around
 * each camera ray of a plain render (first_in_row: the tile's row starts,
 * first_row: the tile's first row); and around each ray segment the
 * shading follows, whose hit's light states (one per light, or NULL where
 * the method keeps none) segment_begin hands out. */
void shadow_tile_begin(ShadowContext *ctx);
void shadow_pixel_begin(ShadowContext *ctx, int first_in_row, int first_row);
void shadow_pixel_end(ShadowContext *ctx, int first_in_row);
LightState *shadow_segment_begin(ShadowContext *ctx, const Hit *hit, int from_eye);
void shadow_segment_end(ShadowContext *ctx);

/* hst's switching threshold N_th (--nth): a fixed value, measured once per
 * scene (auto: the shadow ray's cost over that of counting one shadow
 * polygon), or eq. (7) at every shading point from its own N_c. */
typedef enum { NTH_FIXED, NTH_AUTO, NTH_PER_POINT } NthMode;
typedef struct {
    NthMode mode;
    double value; /* NTH_FIXED's */
} NthSetting;

/* What a method's preparation may use: the world, its grid (empty cells:
 * the polygons are registered only if volumes are built) and hierarchy,
 * and the options that bear on shadows. */
typedef struct ShadowSetup {
    const World *world;
    Grid *grid;
    const Bvh *bvh;
    const Vec3 *eye;        /* the camera's location; NULL for an orthographic camera */
    int width, height;      /* the image, for the plan's estimates */
    int threads;
    int shadows_on;         /* the quality asks for shadows (+Q4 and up): else nothing is prepared */
    int volumes_always;     /* --volumes always */
    NthSetting nth;
    int precision;          /* PlanePrecision of the shadow polygons' planes */
    /* A render spread over processes: the leader plans (plans rest on
     * timings, which differ between processes) and broadcast hands its
     * choices to the others, so that every process decides alike. NULL:
     * one process. */
    void (*broadcast)(void *data, size_t size);
    int leader;
} ShadowSetup;

/* What a method prepared, shared read-only by the render's threads, and
 * the method that decides (hst hands its decisions to the shadow ray with
 * the last-blocker cache when no volume pays and no area light needs its
 * beams). Released by shadow_prepared_free. */
typedef struct ShadowPrepared {
    const struct ShadowMethod *decider;
    struct ShadowVolumes *volumes; /* at least one usable light's, or NULL */
    struct VolumePlan *plan;       /* which lights got volumes and why, or NULL */
    struct CostModel *cost;        /* calibrated with the volumes (zero without) */
    struct EmbreeScene *embree;    /* the embree method's scene, or NULL */
    struct LightBuffers *light_buffers; /* the point lights' light buffers, or NULL */
    double nth;                    /* hst: N_th as decided; negative: per point */
    const char *nth_mode;          /* for the report */
    double plan_seconds;           /* planning, builds included (wall) */
    double volumes_seconds;        /* ... the builds */
} ShadowPrepared;

typedef struct ShadowMethod {
    const char *name;
    const char *summary;
    int uses_volumes;    /* needs shadow volumes and the shadow buckets of segments */
    /* Prepares what the method shares between threads into out (whose
     * decider is the method itself, its nth the setting's value, the rest
     * empty); NULL: nothing to prepare. Returns 0, or -1 with a message
     * in err. */
    int (*prepare)(const struct ShadowMethod *self, const ShadowSetup *s, ShadowPrepared *out, char *err,
                   int errlen);
    /* A thread's own state, made after the context's common part and
     * freed before it (NULL: none). Returns 0, or -1 when out of memory. */
    int (*thread_init)(ShadowContext *ctx, const ShadowPrepared *p, int pixel_coherence);
    void (*thread_free)(ShadowContext *ctx);
    /* The render loop's hooks (shadow_pixel_begin ...; NULL: nothing). */
    void (*pixel_begin)(ShadowContext *ctx, int first_in_row, int first_row);
    void (*pixel_end)(ShadowContext *ctx, int first_in_row);
    LightState *(*segment_begin)(ShadowContext *ctx, const Hit *hit, int from_eye);
    void (*segment_end)(ShadowContext *ctx);
    /* Decides q's light; sets ctx->last_scheme. */
    void (*test)(ShadowContext *ctx, const ShadowQuery *q, RGB *light_through);
    /* The shading needs no answer for q's light (it faces away from the
     * point, or adds nothing there); keeps the state at P2 consistent.
     * faces_away: the shading normal faces away from the light. May be NULL. */
    void (*skip)(ShadowContext *ctx, const ShadowQuery *q, int faces_away);
    /* 1: not exact, by design (embree: float tests); its disagreements with
     * the shadow ray are a figure to report, not a bug. 0: every decision
     * must be the shadow ray's. */
    int inexact;
    /* 1: area lights by their beam's proofs (hst, area_light_beam.h); 0:
     * each sample by test. */
    int area_beam;
    /* 1: decides nothing, every light reaches every point (none). */
    int blind;
    /* 1: for the tests only: found by name, but listed nowhere. */
    int hidden;
    /* 1: decides on a world with instances (instance.h) as on a flat one;
     * 0: wants world-space polygons (shadow_method_takes_instances). */
    int instances;
} ShadowMethod;

/* The test-only method (shadow_every_lit.c): every light reaches every
 * point, through every door a method has. */
extern const ShadowMethod shadow_every_lit_method;
/* The cache method (shadow_cache.c): the shadow ray with the light's last
 * opaque blocker tried first (exact); also what a method hands its
 * decisions to where what it prepared would not pay (hst without volumes). */
extern const ShadowMethod shadow_cache_method;
/* The shadow ray alone (shadow_conventional.c): the exact reference, and
 * hst's decider where not even the cache pays. */
extern const ShadowMethod shadow_conventional_method;
/* The light buffer (shadow_light_buffer.c), and its decision for hst:
 * the infinite planes and the curved objects first (shadow_planes_test's
 * answer, the objects by the light's cell), then, unless they block
 * (*surfaces_blocked), the polygons: the light's cell decides, or the cache
 * method's polygon part where the light has no buffer or the cell is not
 * built, counting the decision and its scheme. Multiplies into *light and
 * returns 1 when it is fully blocked. */
extern const ShadowMethod shadow_light_buffer_method;
int shadow_light_buffer_decide(ShadowContext *ctx, const ShadowQuery *q, RGB *light, int *surfaces_blocked);
/* The point lights' buffers, empty, for the render (a method's
 * preparation: the light-buffer method's, hst's). Returns 0, or -1 with
 * a message in err. */
int shadow_light_buffer_prepare(const ShadowMethod *self, const ShadowSetup *s, ShadowPrepared *out, char *err,
                                int errlen);

/* The record of one decision, the same for every method, for the analysis
 * channels (--aov): read right after test or skip. */
typedef struct {
    int scheme;  /* ctx->last_scheme: ShadowScheme, or SCHEME_NONE */
    int depth;   /* opaque polygons between the point and the light (the
                  * depth count), -1 where the method does not know it */
} ShadowRecord;

/* Methods that keep states report their depth count where it is known;
 * the others know it is 0 where some light got through (the shadow ray met
 * no opaque polygon on its way), and nothing where it was blocked (the ray
 * stops at the first blocker). answer: the test's answer, NULL after a skip. */
ShadowRecord shadow_record(const ShadowContext *ctx, const ShadowQuery *q, const RGB *answer);

/* The exact test: a shadow ray walked through the grid to the light,
 * infinite planes first, then polygons. */
void shadow_conventional_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light_through);
/* Its two halves, so that methods sharing the plane part stay exact:
 * both multiply into *light and return 1 when it is fully blocked. The
 * first is every surface that is not a polygon: the infinite planes, then
 * the analytic shapes (shadow_shapes_test). Every method decides it by the
 * shadow ray's own tests, and only the polygons by its own means; so each
 * is exact on shapes as it is on polygons, and a method's polygon state
 * (hst's depths, the cache's blocker, the light buffer's cells) is the
 * polygons' alone, whatever shapes lie about. */
int shadow_planes_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light);
/* The shapes' part: every crossing of a shape (World.shapes) between the
 * point and the light, met by the shapes' own intersection (shape.h: the
 * nearest-hit query's, POV-Ray's tolerances), filtering the light through
 * see-through ones; 1 when they block it fully. */
int shadow_shapes_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light);
/* What q's shadow ray meets of one shape (World.shapes[i], its parts for
 * a CSG object), by shadow_shapes_test's own crossings: nothing; an
 * opaque surface (the light is blocked, whatever else the ray meets); or
 * see-through surfaces only (their colour is shadow_shapes_test's to fold,
 * in its order). For methods that ask the shapes they list rather than
 * walk the shapes' hierarchy. */
typedef enum { SHAPE_NOT_CROSSED, SHAPE_CROSSED_OPAQUE, SHAPE_CROSSED_SEE_THROUGH } ShapeCrossing;
/* q's shadow ray as the spheres' fast test takes it (shape_sphere_crossings),
 * made at the first untransformed sphere asked about ({ .made = 0 } before):
 * a caller that asks about many shapes for one q keeps one. */
typedef struct {
    ShapeRay ray;
    int made;
    /* the last sphere's crossings in the shadow window, nearest first,
     * where shadow_shape_crossing found it crossed (else n is 0) */
    int n;
    double t[2];
} ShadowSphereRay;
/* The shapes shadow_shape_crossing tests by the spheres' fast test. */
static inline int shadow_sphere_fast(const Shape *s) { return s->kind == SHAPE_SPHERE && !s->transformed; }
/* sr: q's (see above). An untransformed sphere's answer is the spheres'
 * fast test's (its box asked only where the sphere is crossed: the answer
 * is the box's and the sphere's together, in either order); every other
 * shape's is shadow_shapes_test's own crossings'. */
ShapeCrossing shadow_shape_crossing(ShadowContext *ctx, const ShadowQuery *q, int i, ShadowSphereRay *sr);
/* Shape i's part of shadow_shapes_test: its crossings' colours folded
 * into *light; 1 when it is now fully blocked. shadow_shapes_test folds
 * the shapes in the order its walk of their hierarchy visits them, which
 * is the order of Bvh.shapes' leaves depth first, the first child first,
 * whatever the ray (it only passes some over): a method that folds the
 * shapes it found crossed in that order gets the walk's colour, bit for
 * bit. */
int shadow_shape_fold(ShadowContext *ctx, const ShadowQuery *q, int i, RGB *light);
/* shadow_shape_fold for a sphere shadow_shape_crossing found crossed, see
 * through, by the fast test (shadow_sphere_fast): its crossings (t[0..n-1],
 * ShadowSphereRay's) folded as shadow_shape_fold folds its own, without
 * finding them again. */
int shadow_sphere_fold(ShadowContext *ctx, const ShadowQuery *q, int i, const double *t, int n, RGB *light);
/* The distances along a shadow ray at which a shape's crossing counts:
 * (tmin, tlimit), POV-Ray's window for its shadow rays (trace.cpp,
 * TracePointLightShadowRay: beyond SMALL_TOLERANCE of the point, short of
 * the light by SHADOW_TOLERANCE, both 1e-3), for a light `distance` away. */
static inline void shadow_shape_window(double distance, double *tmin, double *tlimit)
{
    *tmin = 1.0e-3;
    *tlimit = distance - 1.0e-3;
}
/* shadow_shape_crossing for an untransformed sphere: shape_shadow_crossings'
 * answer (some crossing in the window, inside the box) with the sphere's
 * test first, by shape_sphere_crossings (the same arithmetic as
 * shape_intersect_all's), and the box's only where the sphere is crossed:
 * most spheres a cell lists pass the box test and miss, and the box costs
 * as much as the sphere. Both tests are exact functions of the ray: their
 * order changes no answer. shadow_shape_tests counts the exact tests.
 * Inline here for the light buffer's loop over a cell's objects. */
static inline ShapeCrossing shadow_sphere_crossing(ShadowContext *ctx, const ShadowQuery *q, const Shape *s,
                                                   ShadowSphereRay *sr)
{
    const Material *m = &ctx->tracer->world->materials[s->material];
    if (m->no_shadow)
        return SHAPE_NOT_CROSSED;
    if (!sr->made) {
        shape_ray_init(&sr->ray, q->point, q->to_light);
        sr->made = 1;
    }
    double tmin, tlimit, t[2];
    shadow_shape_window(q->distance, &tmin, &tlimit);
    ctx->stats.shadow_shape_tests++;
    int nall = shape_sphere_crossings(s, &sr->ray, tlimit, t);
    sr->n = 0;
    for (int k = 0; k < nall; k++) /* shape_shadow_crossings' window */
        if (t[k] > tmin)
            sr->t[sr->n++] = t[k];
    if (sr->n == 0 || !shape_box_hit(s, q->point, q->to_light, tlimit)) {
        sr->n = 0;
        return SHAPE_NOT_CROSSED;
    }
    return m->opaque ? SHAPE_CROSSED_OPAQUE : SHAPE_CROSSED_SEE_THROUGH;
}

/* One plane's part: World.planes[i] (passed over where it is q's own
 * surface or casts no shadow); tmin: trace_min_distance(q->point). */
int shadow_plane_test(ShadowContext *ctx, const ShadowQuery *q, int i, double tmin, RGB *light);
int shadow_polygons_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light);
/* The polygon part against a list of candidates instead of the hierarchy:
 * the same answer as shadow_polygons_test when the list holds every
 * polygon the ray can meet (no_shadow ones left out; q's own is passed
 * over here). */
int shadow_polygons_test_among(ShadowContext *ctx, const ShadowQuery *q, const uint32_t *candidates, int n,
                               RGB *light);
/* The same, a candidate at a time, for methods that pass some over by
 * their own proofs: begin; meet each candidate (1: an opaque polygon
 * blocks the light fully, and the walk is over: the answer is no light);
 * else end, which folds the see-through polygons met into *light (1 when
 * that blocks it fully). */
typedef struct {
    ShadowContext *ctx;
    const ShadowQuery *q;
    RayFrame frame;
    double tmin;
    uint32_t own;
    /* 1: the walk's candidates (world polygons, not an instance's) are
     * known not to be edge-on to q's source, which the shadow ray's rule
     * would ask of each met (the light buffer lists no such polygon):
     * shadow_list_meet_item and _crossed skip asking again. 0 from begin. */
    int sides_known;
} ShadowListWalk;
void shadow_list_begin(ShadowListWalk *lw, ShadowContext *ctx, const ShadowQuery *q);
int shadow_list_meet(ShadowListWalk *lw, uint32_t polygon);
/* shadow_list_meet for the polygon of the hierarchy's leaf item `item` (on its packed copy) */
int shadow_list_meet_item(ShadowListWalk *lw, const Bvh *b, uint32_t item);
/* shadow_list_meet for a polygon (not q's own) the ray is proved to cross
 * away from its border, in the test's range: only the distance to its
 * plane is computed, as the test computes it (the same answer). */
int shadow_list_meet_crossed(ShadowListWalk *lw, uint32_t polygon);
int shadow_list_end(ShadowListWalk *lw, RGB *light);
/* The end of the polygon part: folds the see-through polygons the ray met,
 * ctx->filtered[0..nfiltered) in any order (each polygon once), into *light
 * in the order the light passes them (by distance, then index), once per
 * group within POV-Ray's SMALL_TOLERANCE; 1 when that blocks it fully.
 * Shared, so that a method finding them its own way folds them alike. */
int shadow_fold_filtered(ShadowContext *ctx, const ShadowQuery *q, RGB *light);

void shadow_cache_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light_through);
/* Its polygon part (the planes tested before): the last blocker, then the
 * shadow ray; counts the decision and its scheme, and returns 1 when the
 * light is fully blocked. */
int shadow_cache_polygons_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light);
/* The last-blocker cache (shadow_cache.c), for the methods that fire shadow
 * rays: 1 when the opaque polygon that last blocked q's light blocks q's
 * shadow ray too (then the ray's answer is "no light"); after a shadow
 * ray, remember its blocker when it was opaque and blocked fully. */
int shadow_cached_blocker_hits(ShadowContext *ctx, const ShadowQuery *q);
void shadow_cache_remember(ShadowContext *ctx, const ShadowQuery *q, const RGB *light);
/* Empties the caches of lights [0, nlights) and their tallies (shadow.c:
 * the context holds them): at every tile's start, so that what the cache
 * does for a pixel does not depend on the tiles its thread rendered
 * before. */
void shadow_cache_forget(ShadowContext *ctx, int nlights);
void shadow_volume_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light_through);
void shadow_volume_skip(ShadowContext *ctx, const ShadowQuery *q, int faces_away);
void shadow_hst_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light_through);
/* The volume methods' preparation (shadow_hst.c): the volume plan, with
 * every light's volumes (volume) or only those that pay (hst, unless
 * --volumes always), the cost model and N_th. */
int shadow_hst_prepare(const ShadowMethod *self, const ShadowSetup *s, ShadowPrepared *out, char *err, int errlen);
int shadow_volume_prepare(const ShadowMethod *self, const ShadowSetup *s, ShadowPrepared *out, char *err,
                          int errlen);
/* ... and their threads' state and hooks (shadow_volume_thread.c): the
 * light states along the ray tree, the shadow buckets, the cells camera
 * segments pierce, and hst's pixel coherence. */
int shadow_volume_thread_init(ShadowContext *ctx, const ShadowPrepared *p, int pixel_coherence);
int shadow_hst_thread_init(ShadowContext *ctx, const ShadowPrepared *p, int pixel_coherence);
void shadow_volume_thread_free(ShadowContext *ctx);
void shadow_volume_pixel_begin(ShadowContext *ctx, int first_in_row, int first_row);
void shadow_volume_pixel_end(ShadowContext *ctx, int first_in_row);
LightState *shadow_volume_segment_begin(ShadowContext *ctx, const Hit *hit, int from_eye);
void shadow_volume_segment_end(ShadowContext *ctx);
void shadow_hst_skip(ShadowContext *ctx, const ShadowQuery *q, int faces_away);

#endif
