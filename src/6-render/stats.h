/* Counters and timers. Each render thread owns a RenderStats and the totals
 * are summed once at the end, so nothing here is shared while rendering. */
#ifndef HST_STATS_H
#define HST_STATS_H

#include <stdint.h>
#include <stdio.h>

#include "scene.h"

#define STATS_SCHEMES 5

typedef struct {
    uint64_t pixels;
    uint64_t camera_rays, reflected_rays, refracted_rays, transmitted_rays;
    uint64_t polygon_tests, polygon_hits, plane_tests;
    uint64_t cells_visited;
    uint64_t shadow_queries;      /* shading point x light pairs that needed a decision */
    uint64_t shadow_rays;         /* conventional shadow rays walked */
    uint64_t shadow_blocked;      /* ... of which found an opaque blocker */
    uint64_t shadow_polygon_tests;
    /* Decisions by sub-scheme: sustain, self-shadow, volume, conventional,
     * cache hit (the order of ShadowScheme in shadow.h). */
    uint64_t shadow_schemes[STATS_SCHEMES];
    uint64_t shadow_volume_tests;  /* segment/shadow polygon tests */
    uint64_t shadow_bucket_polygons; /* shadow polygons gathered into segments' buckets */
    uint64_t shadow_unsure;       /* counts abandoned for a crossing too close to call */
    uint64_t shadow_coherent;     /* volume counts carried from the neighbouring pixel's hit */
    uint64_t shadow_coherence_unsure; /* ... abandoned (too close to call) for the count from the eye */
    uint64_t shadow_touching;     /* points on a second polygon: left to the shadow ray */
    uint64_t shadow_in_plane;     /* segments in the plane of their start polygon: left to the shadow ray */
    uint64_t shadow_no_count;     /* volume: no count possible (depth unknown, outside the box) */
    uint64_t shadow_deferred;     /* states left unknown where nobody needed the answer */
    uint64_t shadow_verified;     /* decisions checked against the shadow ray */
    uint64_t shadow_disagreements;
    uint64_t shadow_disagreements_by_scheme[STATS_SCHEMES];
    /* --verify-reference: the same decisions against the long-double
     * reference; ties are where it cannot tell (then only the shadow ray's
     * answer counts, as above). */
    uint64_t reference_ties;
    uint64_t reference_wrong;     /* the method, on clear cases */
    uint64_t reference_ray_wrong; /* the shadow ray itself, on clear cases */
    double shadow_seconds;        /* time spent deciding shadows, summed over threads */
    double render_seconds;        /* thread CPU time in the render loop */
} RenderStats;

void stats_add(RenderStats *total, const RenderStats *part);

/* The report: phases (the rows of the paper's Table 2) and counters. */
typedef struct {
    const char *scene;
    const char *shadow_method;
    int width, height, threads;
    int grid[3];
    uint64_t grid_registrations;
    int npolygons, nplanes, nlights;
    int ndegenerate;             /* polygons dropped at build: no area up to rounding */
    int napproximations;         /* what the scene uses that hstrace approximates */
    const SceneApproximation *approximations;
    double parse_seconds, preprocess_seconds, output_seconds, wall_seconds;
    double volumes_seconds;           /* silhouettes and shadow polygon registration (in preprocessing) */
    const struct ShadowVolumes *volumes; /* NULL unless the method uses them */
    const struct CostModel *cost;     /* the calibration, when made */
    double nth;                       /* N_th used (negative: per point) */
    const char *nth_mode;
    int verify;
    RenderStats render;
} StatsReport;

void stats_print(FILE *f, const StatsReport *r);
int stats_write_json(const char *path, const StatsReport *r, char *err, int errlen);

/* Monotonic wall clock and this thread's CPU clock, in seconds. */
double clock_wall(void);
double clock_thread_cpu(void);

#endif
