/* Shadow methods: one interface, selectable by name (--shadows). A method
 * answers, for a shading point and a light, how much of the light arrives:
 * (1,1,1) unblocked, (0,0,0) blocked by an opaque object, a colour when the
 * light passes through transparent (filter/transmit) objects, as POV-Ray
 * filters it. The conventional shadow ray is the exact reference; every
 * other method must give the same answer (--verify-shadows counts where it
 * does not).
 *
 * Methods that carry a shadow condition along the ray tree (volume, hst)
 * keep a LightState per light at every shading point; each ray segment
 * knows the state at its start and fills the one at its end. */
#ifndef HST_SHADOW_H
#define HST_SHADOW_H

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
} Segment;

typedef struct {
    Vec3 point;          /* the shading point P2 */
    const Hit *surface;  /* the surface it lies on (excluded from the test) */
    const Segment *segment;
    int light;           /* index into World.lights */
    Vec3 to_light;       /* unit direction toward the light */
    double distance;     /* to the light (parallel: to the light's plane) */
    Vec3 normal;         /* shading normal, facing the arriving ray */
} ShadowQuery;

/* How a decision was made (statistics, --verify-shadows, --aov). A test
 * always sets ctx->last_scheme; a skip sets it only when it decides the
 * state at P2 (sustain, self-shadow, volume), so callers that want to know
 * set SCHEME_NONE before a skip. */
typedef enum {
    SCHEME_NONE = -1,
    SCHEME_SUSTAIN, SCHEME_SELF_SHADOW, SCHEME_VOLUME, SCHEME_CONVENTIONAL, SCHEME_CACHE_HIT,
    SCHEME_COUNT
} ShadowScheme;

extern const char *const shadow_scheme_names[SCHEME_COUNT];

typedef struct ShadowMethod {
    const char *name;
    const char *summary;
    int uses_volumes;    /* needs shadow volumes and the shadow buckets of segments */
    /* Decides q's light; sets ctx->last_scheme. */
    void (*test)(TraceContext *ctx, const ShadowQuery *q, RGB *light_through);
    /* The shading needs no answer for q's light (it faces away from the
     * point, or adds nothing there); keeps the state at P2 consistent.
     * faces_away: the shading normal faces away from the light. May be NULL. */
    void (*skip)(TraceContext *ctx, const ShadowQuery *q, int faces_away);
} ShadowMethod;

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
ShadowRecord shadow_record(const TraceContext *ctx, const ShadowQuery *q, const RGB *answer);

/* NULL when no method has that name. */
const ShadowMethod *shadow_method_find(const char *name);
/* Names of all methods, comma separated, for messages and --help. */
const char *shadow_method_names(void);

/* The exact test: a shadow ray walked through the grid to the light,
 * infinite planes first, then polygons. */
void shadow_conventional_test(TraceContext *ctx, const ShadowQuery *q, RGB *light_through);
/* Its two halves, so that methods sharing the plane part stay exact:
 * both multiply into *light and return 1 when it is fully blocked. */
int shadow_planes_test(TraceContext *ctx, const ShadowQuery *q, RGB *light);
int shadow_polygons_test(TraceContext *ctx, const ShadowQuery *q, RGB *light);

void shadow_cache_test(TraceContext *ctx, const ShadowQuery *q, RGB *light_through);
void shadow_volume_test(TraceContext *ctx, const ShadowQuery *q, RGB *light_through);
void shadow_volume_skip(TraceContext *ctx, const ShadowQuery *q, int faces_away);
void shadow_hst_test(TraceContext *ctx, const ShadowQuery *q, RGB *light_through);
void shadow_hst_skip(TraceContext *ctx, const ShadowQuery *q, int faces_away);
/* The most shadow polygons a bucket may hold for a count under N_th. */
int bucket_limit(double nth);

#endif
