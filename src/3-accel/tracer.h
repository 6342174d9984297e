/* Ray queries against the world: nearest hit (camera, reflected and refracted
 * rays) through the grid with a per-segment bucket. One TraceContext per
 * render thread; it owns the bucket stamps and the thread's counters. */
#ifndef HST_TRACER_H
#define HST_TRACER_H

#include <stdint.h>

#include "grid.h"
#include "stats.h"
#include "world.h"

struct ShadowMethod;
struct ShadowVolumes;
struct PixelCoherence;
struct AovPixel;

/* What a surface hit is: a grid polygon or an infinite plane. */
typedef enum { HIT_NONE, HIT_POLYGON, HIT_PLANE } HitKind;

typedef struct {
    HitKind kind;
    int index;          /* polygon or plane index */
    double t;
    Vec3 point;
} Hit;

/* Which rays and tests a render performs: POV-Ray's +Q levels. */
typedef struct {
    int shadows;        /* Q >= 4 */
    int refraction;     /* Q >= 6 */
    int reflection;     /* Q >= 8 */
    int full_ambient;   /* Q <= 1: pigment colour only */
    int volume;         /* Q >= 9: fog */
} Quality;

/* Objects a ray passes through (TraceContext.hide): no_image ones for
 * image rays, no_reflection ones for reflection rays. */
enum { HIDE_NO_IMAGE = 1u, HIDE_NO_REFLECTION = 2u };

typedef struct {
    const World *world;
    const Grid *grid;
    unsigned hide;             /* HIDE_* for the next trace_nearest, 0 otherwise */
    const struct ShadowMethod *shadow;
    Quality quality;
    /* The bucket: stamp[i] == ray_id marks polygon i as already tested by
     * the current segment, so it is tested once however many cells hold it. */
    uint32_t *stamp;
    uint32_t ray_id;
    RenderStats stats;

    /* Shadow methods' per-thread state. */
    int last_scheme;           /* how the last decision was made (ShadowScheme) */
    int last_blocker;          /* polygon that blocked the last shadow ray, or -1 */
    int last_filtered;         /* transparent polygons the last shadow ray passed */
    unsigned shadow_timer;     /* decisions so far, for timing every 8th */
    int *light_cache;          /* cache method: last opaque blocker per light, or -1 */
    int verify;                /* 1: check every decision against the shadow ray (--verify-shadows);
                                  2: and against the long-double reference (--verify-reference) */
    long double reference_eps; /* the reference's margin of ties */
    double nth;                /* hst: N_th; negative: per point from its own N_c */
    const struct CostModel *cost;  /* for the per-point N_th */
    /* Shadow buckets (volume, hst). The walk of a segment records the cells
     * it pierced; a method that needs a light's bucket (the shadow polygons
     * registered in those cells, each once: stamps) fills it from them. */
    const struct ShadowVolumes *volumes;
    uint32_t *segment_cells;
    int segment_ncells, segment_cells_cap;
    int segment_in_box;        /* the current segment lies inside the grid box */
    uint32_t *sp_stamp;
    uint32_t sp_id;
    uint32_t *bucket;          /* room for any light's shadow polygons */
    /* trace_point_touches_other's answer for the last point asked about. */
    int touch_valid, touch_kind, touch_index, touch_result;
    Vec3 touch_point;
    struct PixelCoherence *coherence; /* hst's pixel coherence, or NULL when off */
    /* Light states along the ray tree: one row of nlights per recursion depth. */
    void *states;
    int state_depth, state_capacity;
    /* --aov: the current pixel's analysis record, or NULL when off. */
    struct AovPixel *aov;
} TraceContext;

/* volumes: the shadow volumes when the method uses them, else NULL. */
int trace_context_init(TraceContext *ctx, const World *w, const Grid *g, const struct ShadowMethod *shadow, Quality q,
                       const struct ShadowVolumes *volumes);
void trace_context_free(TraceContext *ctx);

/* The next mailbox id for a stamp array of n entries (cleared when the id
 * wraps, so old stamps cannot collide). */
static inline uint32_t stamp_next(uint32_t *stamp, int n, uint32_t *id)
{
    if (++*id == 0) {
        for (int i = 0; i < n; i++)
            stamp[i] = 0;
        *id = 1;
    }
    return *id;
}

/* A fresh bucket for a new segment. */
static inline uint32_t trace_new_segment(TraceContext *ctx)
{
    return stamp_next(ctx->stamp, ctx->world->npolygons, &ctx->ray_id);
}

/* The bucket test: 1 when polygon pi is new to the segment `id` (and now
 * marked), 0 when the segment has already tested it in an earlier cell. */
static inline int bucket_admit(TraceContext *ctx, uint32_t id, uint32_t pi)
{
    if (ctx->stamp[pi] == id)
        return 0;
    ctx->stamp[pi] = id;
    return 1;
}

/* Smallest distance below which a hit is taken to be the segment's own start
 * point: a few thousand ulps of the coordinates involved. */
static inline double trace_min_distance(Vec3 org)
{
    double m = fmax(fabs(org.x), fmax(fabs(org.y), fabs(org.z)));
    return 1e-9 * (1.0 + m);
}

/* Nearest hit along org + t*dir, t in (min distance, tmax); `from` is the
 * surface the segment starts on (excluded, as the paper's bucket rule says),
 * kind HIT_NONE for the camera. */
int trace_nearest(TraceContext *ctx, Vec3 org, Vec3 dir, double tmax, const Hit *from, Hit *hit);

/* The current segment's shadow bucket for a light: fills ctx->bucket with
 * the distinct shadow polygons registered in the cells the segment pierced
 * and returns how many (the paper's N_s). Stops early, returning more than
 * `limit`, once there are more than `limit` of them. */
int trace_fill_shadow_bucket(TraceContext *ctx, int light, int limit);
/* Registrations of the light's shadow polygons in those cells: 0 exactly
 * when the bucket is empty, never less than its size. Cheap. */
uint32_t trace_shadow_registrations(const TraceContext *ctx, int light);
/* The same for any list of cells (another segment's walk). */
int trace_fill_shadow_bucket_in(TraceContext *ctx, int light, const uint32_t *cells, int ncells, int limit);
uint32_t trace_shadow_registrations_in(const TraceContext *ctx, int light, const uint32_t *cells, int ncells);

/* Does the hit point lie (within tol) on a polygon besides its own: on the
 * border of its own (so on the neighbours sharing that edge or vertex), or
 * in the plane and area of another? A depth count carried to or from such a
 * point would include or miss that polygon, where the shadow ray excludes
 * it (it starts on it). Remembers the last answer. */
int trace_point_touches_other(TraceContext *ctx, const Hit *hit, double tol);

static inline int hit_material(const World *w, const Hit *h)
{
    return h->kind == HIT_POLYGON ? w->polygons[h->index].material : w->planes[h->index].material;
}

#endif
