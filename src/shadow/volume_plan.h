/* Which lights get shadow volumes (hst's --volumes auto): the cost model
 * carried over to preprocessing. Volumes repay their build only where the
 * decisions they make cheaper are many and the shadow ray they replace is
 * dear; on a big mesh rendered small, building them costs more than every
 * shadow ray of the image. So, per light, before building:
 *
 *   gain bound = Q * (C_ray - C_touch) - B
 *
 * Q: the decisions the image will ask toward the light (a pilot of camera
 * rays through a coarse grid of pixels, scaled to the image), C_ray: the
 * exact shadow ray toward it, timed at the pilot's points, C_touch: the
 * one check every hst decision makes (a point on a second polygon), B: the
 * build, estimated by running the build on a sample of the polygons
 * (shadow_volumes_estimate). A light is built only when its bound is
 * positive and the lights' bounds together repay the shared part of the
 * build (welding, edges' uses) and the recording of the cells every camera
 * ray pierces, which hst needs as soon as one light has volumes.
 *
 * The bound is optimistic: it prices an hst decision at its cheapest. So
 * after building, the pilot is run again with hst itself beside the shadow
 * ray, on the same points; a light whose hst decisions do not measure
 * clearly cheaper than its shadow rays (by 10%) is dropped (its build is spent, its memory freed),
 * and if what the kept lights save does not repay the cells' recording,
 * all are. A light without volumes is decided by the shadow ray, exactly
 * as with volumes: the images are the same whatever is decided, only the
 * time and the sub-schemes differ. The timings differ between runs, so the
 * decisions may too; --volumes always builds every light, as the paper did. */
#ifndef HST_VOLUME_PLAN_H
#define HST_VOLUME_PLAN_H

#include "bvh.h"
#include "cost_model.h"
#include "grid.h"
#include "shadow.h"
#include "shadow_volumes.h"
#include "tracer.h"
#include "world.h"

typedef enum { VOLUMES_AUTO, VOLUMES_ALWAYS } VolumesMode;

typedef enum {
    PLAN_IMPOSSIBLE,      /* no volumes possible: a shadowless light, or a parallel light whose plane cuts the scene */
    PLAN_AREA_LIGHT,      /* an area light: its samples are decided by the shadow ray (area_light.h) */
    PLAN_ALWAYS,          /* built because --volumes always asked */
    PLAN_KEPT,            /* built, and the pilot measured hst cheaper than the shadow ray: kept */
    PLAN_WONT_PAY,        /* its bound says the volumes cannot repay their build: not built */
    PLAN_SHARED_WONT_PAY, /* the lights' bounds together cannot repay what volumes share: not built */
    PLAN_DROPPED,         /* built; the pilot measured hst no cheaper than the shadow ray: dropped */
    PLAN_TRIAL_FAILED,    /* not built: the most promising light's volumes were tried first and did not pay */
    PLAN_PREDICTED_WONT_PAY, /* not built: priced at the tried light's measured hst cost, they would not pay */
    PLAN_DROPPED_ALL,     /* built and cheaper, but the lights kept would not repay the cells' recording: dropped */
    PLAN_TOO_MANY_POLYGONS /* not planned: a polygon a pixel or more, whose volumes' build outweighs every shadow ray */
} LightPlanDecision;

typedef struct {
    int decision;          /* LightPlanDecision */
    int pilot_queries;     /* pilot points that ask this light */
    double queries;        /* decisions expected toward this light over the image */
    double c_ray;          /* exact shadow ray, seconds per decision, at the pilot's points */
    double gain_bound;     /* queries * (c_ray - c_touch) - build_estimate: the most its volumes could save */
    double build_estimate; /* seconds on one thread before building (0: not estimated) */
    /* Once built (PLAN_KEPT, PLAN_DROPPED, PLAN_DROPPED_ALL): */
    double c_hst;          /* hst with its volumes, seconds per decision, on the same points */
    double c_ray_beside;   /* the shadow ray timed beside it */
    double gain;           /* queries * (c_ray_beside - c_hst); predicted from the tried light's before */
} LightPlan;

typedef struct VolumePlan {
    VolumesMode mode;
    int nlights;
    LightPlan *light;
    int8_t *build;          /* per light: what shadow_volumes_build is asked for */
    int pilot_rays;         /* camera rays of the pilot */
    double pixels;          /* camera rays the image will shoot */
    double c_touch;         /* the touching check, per decision */
    double c_record;        /* recording the cells one camera ray pierces */
    double shared_estimate; /* welding, edges' uses and the polygons' registration, once for all lights
                               (0: not estimated) */
    double register_estimate; /* the polygons' registration in the grid, of that */
    int sample_polygons;    /* the build estimate's sample */
    int tried;              /* the light tried first, or -1 */
    int builds;             /* shadow_volumes_build calls made */
    double build_seconds;   /* ... their wall time, with register_seconds */
    double register_seconds; /* registering the polygons in the grid (grid_register), before the first build */
    double seconds;         /* planning's own cost: pilots and estimates */
    /* The pilot's points. */
    int npoints;
    Vec3 *org, *dir;
    Hit *hit;
    Vec3 *normal;           /* geometric, facing the camera ray */
} VolumePlan;

typedef struct {
    VolumesMode mode;
    int width, height;      /* the image */
    int threads;            /* for the build */
    int precision;          /* PlanePrecision of the planes */
    NthSetting nth;         /* hst's N_th */
} VolumePlanOptions;

/* Plans, builds into sv and calibrates cost (eq. 7 included) the volumes
 * that pay; with VOLUMES_ALWAYS, every light's. On return sv holds at
 * least one usable light, or nothing (zeroed: no volumes at all, and
 * cost->seconds is 0). Before the first build it registers the polygons
 * in g (grid_register), which only volumes need. Returns 0, or -1 when out
 * of memory. */
int volume_plan_build(VolumePlan *plan, ShadowVolumes *sv, CostModel *cost, const World *w, Grid *g,
                      const Bvh *bvh, const Vec3 *eye, const VolumePlanOptions *o);

void volume_plan_free(VolumePlan *plan);

/* Stage one's rule on the figures measured into plan (per light queries
 * and c_ray; c_touch, c_record, pixels): a light is a candidate when
 * queries * (c_ray - c_touch) > 0 (its gain_bound), and the candidates
 * stay so only when their bounds together exceed pixels * c_record. Sets
 * each light's decision and plan->build; returns the candidates left. */
int volume_plan_bound(VolumePlan *plan, const World *w);

/* A short phrase for --stats and the JSON. */
const char *volume_plan_decision_name(int decision);

#endif
