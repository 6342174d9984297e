/* --shadows embree: Embree 3's shadow ray, a comparison method beside the
 * exact ones (configure --with-embree, the default when libembree-dev is
 * installed). One Embree scene per render, built in preprocessing from the
 * world's polygons and shared read-only by the render threads (Embree's
 * queries are thread-safe); a query's own state lives on the stack and in
 * the thread's ShadowContext.
 *
 * The rules are the shadow ray's (shadow_conventional.c): infinite planes
 * by shadow_planes_test, the shading point's own polygon excluded, no_shadow
 * objects left out, polygons edge-on to the light ignored, hits only at
 * distances in (trace_min_distance, the light) measured in double on the
 * polygon's plane, transparent polygons folded by shadow_fold_filtered. But
 * whether the ray passes inside a triangle is Embree's float decision, not
 * the watertight double test: the method is not exact, and
 * --verify-shadows counts where it disagrees with the shadow ray. */
#ifndef HST_SHADOW_EMBREE_H
#define HST_SHADOW_EMBREE_H

#include "shadow.h"

typedef struct EmbreeScene EmbreeScene;

/* What the Embree scene holds, for the statistics. */
typedef struct {
    int triangles;          /* the world's triangles, as Embree triangles */
    int fanned_polygons;    /* convex polygons of one outline, as fans of Embree triangles */
    int fan_triangles;      /* ... the triangles they became */
    int user_polygons;      /* the other polygons (holes, concave outlines): Embree user
                             * geometry whose test is hstrace's exact double one */
    int left_out;           /* no_shadow polygons: not in the scene at all */
    double seconds;         /* building it (wall) */
    const char *quality;    /* Embree's build quality */
} EmbreeSceneInfo;

/* 1 when this hstrace was built with Embree. */
int shadow_embree_built(void);
/* "3.13.5", or NULL when not built with Embree. */
const char *shadow_embree_version(void);

/* Builds the scene from w (threads: Embree's build threads, 0 for all
 * cores). NULL with a message in err when Embree fails, runs out of memory
 * or is not built in. */
EmbreeScene *shadow_embree_build(const World *w, int threads, char *err, int errlen);
void shadow_embree_free(EmbreeScene *es);
const EmbreeSceneInfo *shadow_embree_info(const EmbreeScene *es);
/* The Embree scene itself (an RTCScene), for queries of other kinds
 * (bench/camera_rays times Embree's nearest-hit queries on it); NULL when
 * not built with Embree. Its triangles carry only the shadow rules'
 * filters (occlusion queries), and its user polygons (holes, concave
 * outlines) answer occlusion queries only. */
void *shadow_embree_rtc_scene(const EmbreeScene *es);

/* The method's preparation: the Embree scene (out->embree). */
int shadow_embree_prepare(const ShadowMethod *self, const ShadowSetup *s, ShadowPrepared *out, char *err,
                          int errlen);
/* The method's test (ctx->embree must be set). */
void shadow_embree_test(ShadowContext *ctx, const ShadowQuery *q, RGB *light_through);

#endif
