/* Statistics: the counters of a render and the report printed from them.
 * Each render thread owns its counters and the totals are summed once at
 * the end, so nothing here is shared while rendering. */
#ifndef HST_STATS_H
#define HST_STATS_H

#include <stdint.h>
#include <stdio.h>

#include "scene.h"
#include "shade.h"

/* A render's counters: each room's own, and the render loop's. */
typedef struct {
    uint64_t pixels, camera_rays;
    RayCounters rays;             /* the tracer's tests (tracer.h) */
    ShadeCounters shading;        /* secondary rays (shade.h) */
    ShadowCounters shadow;        /* shadow testing (shadow.h) */
    double render_seconds;        /* thread CPU time in the render loop */
    /* Two coincident materials camera rays met (ShadeContext.coincident_pair):
     * (a + 1) << 32 | (b + 1), a < b, the least over threads and ranks; 0: none */
    uint64_t coincident_pair;
} RenderStats;

void stats_add(RenderStats *total, const RenderStats *part);

/* The report: phases (the rows of the paper's Table 2) and counters. */
typedef struct {
    const char *scene;
    /* The povray.ini the options were read after (NULL: none), and which
     * one it is, or why none was read; NULL: not said. */
    const char *povray_ini, *povray_ini_why;
    const char *shadow_method;
    int width, height, threads;
    int grid[3];
    uint64_t grid_registrations;
    int grid_registered;              /* the polygons registered in its cells (grid_register) */
    int npolygons, nplanes, nshapes, nlights;
    int ndegenerate;             /* polygons dropped at build: no area up to rounding */
    /* Instancing (instance.h): placements kept as instances, the meshes
     * they place (prototypes) and those meshes' polygons, kept once, and
     * the polygons the instances place */
    int ninstances, nprototypes, nproto_polygons, ninstanced_polygons;
    int napproximations;         /* what the scene uses that hstrace approximates */
    const SceneApproximation *approximations;
    double parse_seconds, preprocess_seconds, output_seconds, wall_seconds;
    double volumes_seconds;           /* silhouettes and shadow polygon registration (in preprocessing) */
    /* The parts of preprocessing, wall time: the world (polygons from the
     * scene description), the hierarchy, and the volume plan (pilot,
     * estimates, and the builds of volumes_seconds). */
    double world_seconds, hierarchy_seconds, plan_seconds;
    const struct VolumePlan *plan;    /* which lights got volumes and why; NULL unless the method uses them */
    const struct ShadowVolumes *volumes; /* NULL unless the method uses them */
    const struct EmbreeScene *embree;    /* NULL unless the method is embree */
    const struct LightBuffers *light_buffers; /* NULL unless the method keeps light buffers */
    const struct CostModel *cost;     /* the calibration, when made */
    double nth;                       /* N_th used (negative: per point) */
    const char *nth_mode;
    int verify;
    RenderStats render;           /* all ranks' together */
    /* A render spread over an MPI job's ranks (mpi_job.h): their number
     * and each one's counters (NULL: one process). */
    int ranks;
    const RenderStats *rank_render;
    double gather_seconds;        /* rank 0: waiting for and gathering the other ranks' pixels */
    const long *rank_requests;    /* per rank: runs of tiles asked of rank 0 (NULL: not kept) */
    const double *rank_wait_seconds; /* ... and the time waiting for them */
    /* Each tile's thread CPU seconds (NULL: not kept), for load balance. */
    int ntiles;
    const double *tile_seconds;
} StatsReport;

void stats_print(FILE *f, const StatsReport *r);
int stats_write_json(const char *path, const StatsReport *r, char *err, int errlen);

#endif
