/* Ray queries against the world: nearest hit (camera, reflected and refracted
 * rays) through the grid with a per-segment bucket. One Tracer per render
 * thread; it owns the bucket stamps and the thread's counters of tests. */
#ifndef HST_TRACER_H
#define HST_TRACER_H

#include <stdint.h>

#include "bvh.h"
#include "grid.h"
#include "instance.h"
#include "world.h"

/* What a surface hit is: a grid polygon, an infinite plane or an analytic
 * shape (World.shapes). */
typedef enum { HIT_NONE, HIT_POLYGON, HIT_PLANE, HIT_SHAPE } HitKind;

typedef struct {
    HitKind kind;
    int index;          /* polygon id (instance.h: a world polygon's index, or an instance's polygon), plane or shape index */
    double t;
    Vec3 point;
    int instance;       /* the instance of an instance's polygon as the query found it (a hint:
                         * world_polygon_hinted checks it; last, so that {kind, index, t, point} sets none) */
    int part;           /* a shape's: which part of it (shape.h's SHAPE_SIDE ...) */
} Hit;

/* (HIDE_NO_IMAGE, HIDE_NO_REFLECTION and HIDE_NO_SHADOW: bvh.h) */

/* What the ray queries did, for the statistics (summed over threads). */
typedef struct {
#define RAY_COUNTER(field, line, label, key, meaning) uint64_t field;
#include "ray_counters.def"
#undef RAY_COUNTER
} RayCounters;

void ray_counters_add(RayCounters *total, const RayCounters *part);

typedef struct {
    const World *world;
    const Grid *grid;
    /* The hierarchy the polygon queries use, or NULL: then they walk the
     * grid (the reference path, which tests compare the hierarchy with). */
    const Bvh *bvh;
    int avx2;                  /* 1: its box tests with AVX2 (the processor has it; tracer_use_avx2) */
    unsigned hide;             /* HIDE_* for the next trace_nearest, 0 otherwise */
    /* The bucket: stamp[i] == ray_id marks polygon i as already tested by
     * the current segment, so it is tested once however many cells hold it. */
    uint32_t *stamp;
    uint32_t ray_id;
    RayCounters stats;
    /* With tracer_record_cells: the cells the last trace_nearest pierced, in
     * walk order, and whether that walk covered the whole segment (both ends
     * inside the recording box). The shadow buckets are gathered from them. */
    uint32_t *segment_cells;
    int segment_ncells, segment_cells_cap;
    int segment_in_box;
    Vec3 record_min, record_max;
    /* trace_segment_hits: the instance whose polygon the visitor is being
     * handed (an index in World.instances), -1 for a world polygon: a hint
     * for world_polygon_hinted. */
    int visiting;
    /* The last trace_nearest's tie: a surface met at tie_t, as near as the
     * one kept, and its material (trace_coincident_material); tie_t < 0:
     * none. */
    double tie_t;
    int tie_material;
    /* trace_point_touches_other's answer for the last point asked about. */
    int touch_valid, touch_kind, touch_index, touch_result;
    Vec3 touch_point;
} Tracer;

/* Returns 0, or -1 when out of memory (free it all the same). */
int tracer_init(Tracer *t, const World *w, const Grid *g);
/* From now on, every trace_nearest records the cells it pierces;
 * segment_in_box tells whether both ends lay in [box_min, box_max]. */
int tracer_record_cells(Tracer *t, Vec3 box_min, Vec3 box_max);
/* Polygon queries through the hierarchy from now on (NULL: the grid). */
void tracer_use_bvh(Tracer *t, const Bvh *bvh);
/* The hierarchy's box tests with AVX2 (on: where the processor has it, the
 * default) or SSE2: the same answers, bit for bit; for tests and timing. */
void tracer_use_avx2(Tracer *t, int on);
void tracer_free(Tracer *t);

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
static inline uint32_t trace_new_segment(Tracer *t)
{
    return stamp_next(t->stamp, t->world->npolygons, &t->ray_id);
}

/* The bucket test: 1 when polygon pi is new to the segment `id` (and now
 * marked), 0 when the segment has already tested it in an earlier cell. */
static inline int bucket_admit(Tracer *t, uint32_t id, uint32_t pi)
{
    if (t->stamp[pi] == id)
        return 0;
    t->stamp[pi] = id;
    return 1;
}

/* Smallest distance below which a hit is taken to be the segment's own start
 * point: a few thousand ulps of the coordinates involved. */
static inline double trace_min_distance(Vec3 org)
{
    return 1e-9 * (1.0 + v3_max_abs(org));
}

/* Nearest hit along org + t*dir, t in (min distance, tmax); `from` is the
 * surface the segment starts on (excluded, as the paper's bucket rule says,
 * when it is a polygon or plane; a shape is not: as in POV-Ray its own
 * depth tolerance keeps the ray off its start, and a ray can meet the
 * far side of the sphere it leaves), kind HIT_NONE for the camera. */
int trace_nearest(Tracer *t, Vec3 org, Vec3 dir, double tmax, const Hit *from, Hit *hit);

/* Every polygon a segment meets, for the shadow ray: visit(user, polygon, t)
 * is called for each polygon met at t in (tmin, tmax), in no particular
 * order, `exclude` (-1: none) and the polygons `hide` names left out; it
 * returns 1 to stop. Returns 1 when a visit stopped it. *tests counts the
 * polygons tested. */
typedef int (*TraceHitVisitor)(void *user, uint32_t polygon, double t);
int trace_segment_hits(Tracer *t, Vec3 org, Vec3 dir, double tmin, double tmax, int exclude, unsigned hide,
                       TraceHitVisitor visit, void *user, uint64_t *tests);

/* trace_segment_hits for the polygons of one instance (World.instances)
 * alone: the walk trace_segment_hits makes of it, so the same polygons at
 * the same t. For lists of candidates that name instances (the light
 * buffer's cells). */
int trace_instance_hits(Tracer *t, int instance, Vec3 org, Vec3 dir, double tmin, double tmax, int exclude,
                        unsigned hide, TraceHitVisitor visit, void *user, uint64_t *tests);

/* Does the hit point lie (within tol) on a polygon besides its own: on the
 * border of its own (so on the neighbours sharing that edge or vertex), or
 * in the plane and area of another? A depth count carried to or from such a
 * point would include or miss that polygon, where the shadow ray excludes
 * it (it starts on it). Remembers the last answer. */
int trace_point_touches_other(Tracer *t, const Hit *hit, double tol);

static inline int hit_material(const World *w, const Hit *h)
{
    return h->kind == HIT_POLYGON ? world_polygon_material_hinted(w, h->index, h->instance)
         : h->kind == HIT_SHAPE   ? w->shapes[h->index].material
                                  : w->planes[h->index].material;
}

/* Coincident surfaces: where the hit found by the last trace_nearest lies
 * at the distance of another surface of a different material (and not one
 * placed alike: materials_look_alike), that material (an index in
 * World.materials), else -1. Polygons tie at exactly one distance, and
 * hstrace keeps the lower index, the object declared first; a curved
 * object ties with a plane or another curved object within
 * COINCIDENT_WINDOW (1e-9) of it, where their arithmetic's rounding
 * decides. POV-Ray keeps whichever its bounding hierarchy meets first or
 * its rounding puts nearer, which varies from pixel to pixel (the speckles
 * of coincident surfaces), so such hits are counted and reported, not
 * matched. A polygon just nearer than a plane or curved object is looked
 * for, not one just beyond it. */
int trace_coincident_material(const Tracer *t, const Hit *hit);

/* The surface a hit lies on as the material code names it (pigment.h's
 * surface ids): a polygon's id, -1 for a plane, a shape's id. */
static inline int hit_surface(const Hit *h)
{
    return h->kind == HIT_POLYGON ? h->index : h->kind == HIT_SHAPE ? surface_of_shape(h->index) : -1;
}

#endif
