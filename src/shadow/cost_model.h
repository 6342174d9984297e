/* The paper's cost model (eq. 1-7): when is counting shadow polygons along
 * a segment cheaper than firing a shadow ray? The machine costs C_s, C_i,
 * C_c, C_o are measured at start-up on the scene's own data (a few ms), the
 * scene statistics p and alpha by sampling shadow rays through the built
 * grid, N_c as the mean number of cells such a ray visits.
 *
 * Eq. (6) prices the shadow ray as the paper fired it, walking the grid.
 * hstrace fires it through the hierarchy (bvh.h), which costs far less, so
 * the threshold hst uses is priced at what the shadow ray costs now: C_ray,
 * the mean time of the exact shadow ray through the hierarchy on the sample
 * rays, against C_s + C_g, a crossing test and the gathering of one shadow
 * polygon into a bucket (N_th = C_ray / (C_s + C_g)). Eq. (7)'s value is
 * kept and reported beside it, for the paper's comparison. */
#ifndef HST_COST_MODEL_H
#define HST_COST_MODEL_H

#include "bvh.h"
#include "grid.h"
#include "shadow_volumes.h"
#include "world.h"

typedef struct CostModel {
    double c_s;     /* one segment/shadow polygon test, seconds */
    double c_i;     /* setting up a 3DDDA walk */
    double c_c;     /* one cell step */
    double c_o;     /* one ray/polygon test */
    double p;       /* chance that a polygon tested in a visited cell is hit */
    double alpha;   /* new polygons met per cell */
    double n_c;     /* cells a shadow ray visits, mean over samples */
    double n_o;     /* alpha * n_c */
    double nth;     /* eq. (7) with these values */
    double c_ray;   /* the exact shadow ray through the hierarchy (0: no hierarchy measured) */
    double c_g;     /* gathering one shadow polygon into a segment's bucket */
    double nth_ray; /* C_ray / (C_s + C_g): the threshold for the shadow ray as fired now */
    double seconds; /* what the calibration cost */
    int full;       /* 0: only C_ray, C_s and C_g (cost_model_calibrate_threshold) */
    int samples;    /* shadow rays sampled for p and alpha */
} CostModel;

/* Measures everything. The sample shadow rays start where camera rays
 * through a coarse grid of pixels of a width x height image land, toward a
 * random light (fixed seed: only the timings vary between runs). Returns 0,
 * or -1 when out of memory. */
int cost_model_calibrate(CostModel *m, const World *w, const Grid *g, const Bvh *bvh, const ShadowVolumes *sv,
                         int width, int height);

/* Only what N_th = C_ray / (C_s + C_g) needs (C_s, C_ray, C_g), for a
 * quick trial (volume_plan.h); eq. (7)'s values are left 0. */
int cost_model_calibrate_threshold(CostModel *m, const World *w, const Grid *g, const Bvh *bvh,
                                   const ShadowVolumes *sv, int width, int height);

/* Eq. (7): N_th for a shadow ray that would visit n_c cells. */
double cost_model_threshold(const CostModel *m, double n_c);

/* Cells a walk from p to the light visits (3DDDA: one per boundary crossed). */
int cost_model_cells_to_light(const Grid *g, Vec3 p, const Light *l);

#endif
