/* Deciding, per light, whether shadow volumes pay (volume_plan.h). */
#include "volume_plan.h"

#include "light.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "camera.h"
#include "clock.h"
#include "shadow.h"

/* The pilot's camera rays per axis: about one ray in PILOT_SHARE of the
 * image's, so that planning costs well under 1% of a render (each pilot
 * ray is timed several times toward every light), within these bounds. */
#define PILOT_SHARE 1024
#define PILOT_GRID_MIN 8
#define PILOT_GRID_MAX 24
#define ROUNDS 2          /* each timing's fastest round counts: on a shared machine a timing is only ever slowed */
#define SAMPLE_MIN 1024   /* polygons in the build estimate's sample */
#define SAMPLE_MAX 8192
#define SAMPLE_SHARE 256  /* ... about one in this many */
#define POV_EPSILON 1.0e-10
/* hst is kept only where the pilot measures it clearly cheaper than the
 * shadow ray, by this ratio at least: the two timings are a few hundred
 * decisions each, and on a busy machine they wander by a few percent. */
#define KEEP_RATIO 0.9
/* Volumes are not even piloted from this many polygons a pixel: their
 * build grows with the polygons, what they can save with the pixels.
 * Measured on make-mesh 10^5 triangles x 4 lights, 640x480, 1 thread (0.33
 * polygons a pixel): building the volumes took 0.157 s (--volumes always),
 * every shadow ray of the render together 0.156 s (--shadows
 * conventional); at three times the polygons the build alone would cost
 * three times what the volumes could at best save. The pilot itself (some
 * 300 camera rays traced five times over, and the shadow rays) is what
 * such a scene is spared: 0.26% of make-mesh 10^6 x 8's instructions. */
#define PLAN_POLYGONS_PER_PIXEL 1.0

const char *volume_plan_decision_name(int decision)
{
    switch (decision) {
    case PLAN_IMPOSSIBLE: return "no volumes possible";
    case PLAN_AREA_LIGHT: return "an area light: no volumes; hst's beam, or the shadow ray, decides its samples";
    case PLAN_ALWAYS: return "built (--volumes always)";
    case PLAN_KEPT: return "built and kept";
    case PLAN_WONT_PAY: return "not built: what its volumes could save does not repay their build";
    case PLAN_SHARED_WONT_PAY:
        return "not built: the lights together cannot repay what their volumes share (welding, cells of camera rays)";
    case PLAN_DROPPED: return "built, dropped: hst not measured 10% cheaper than the shadow ray";
    case PLAN_TRIAL_FAILED: return "not built: the most promising light was tried first and did not pay";
    case PLAN_PREDICTED_WONT_PAY: return "not built: at the tried light's measured hst cost it would not pay";
    case PLAN_DROPPED_ALL: return "built, dropped: the lights kept would not repay the cells' recording";
    case PLAN_TOO_MANY_POLYGONS:
        return "not planned: a polygon a pixel or more, whose volumes would cost more to build than every shadow ray";
    }
    return "?";
}

void volume_plan_free(VolumePlan *plan)
{
    free(plan->light);
    free(plan->build);
    free(plan->org);
    free(plan->dir);
    free(plan->hit);
    free(plan->normal);
    memset(plan, 0, sizeof *plan);
}

/* The shading's question for light li at pilot point i (shade.c's
 * direct_light): is the light in front of the surface? */
static int asks(const World *w, const VolumePlan *plan, int i, int li, ShadowQuery *q)
{
    const Light *l = &w->lights[li];
    const Hit *h = &plan->hit[i];
    if (l->shadowless)
        return 0;
    Vec3 d = v3_sub(l->location, h->point);
    double distance = v3_length(d);
    if (!(distance > 0.0))
        return 0;
    Vec3 to_light = v3_scale(d, 1.0 / distance);
    if (l->kind == LIGHT_PARALLEL) {
        distance *= v3_dot(l->direction, to_light);
        to_light = l->direction;
    }
    int material = hit_material(w, h);
    if (!w->materials[material].double_illuminate && v3_dot(plan->normal[i], to_light) < POV_EPSILON)
        return 0;
    q->point = h->point;
    q->surface = h;
    q->light = li;
    q->source = l;
    q->to_light = to_light;
    q->distance = distance;
    q->normal = plan->normal[i];
    return 1;
}

/* The pilot's camera rays and where they land. */
static int pilot_points(VolumePlan *plan, const World *w, const Grid *g, const Bvh *bvh, int width, int height)
{
    int grid = (int)sqrt(plan->pixels / PILOT_SHARE);
    grid = grid < PILOT_GRID_MIN ? PILOT_GRID_MIN : grid > PILOT_GRID_MAX ? PILOT_GRID_MAX : grid;
    int n = grid * grid;
    plan->org = malloc(sizeof *plan->org * (size_t)n);
    plan->dir = malloc(sizeof *plan->dir * (size_t)n);
    plan->hit = malloc(sizeof *plan->hit * (size_t)n);
    plan->normal = malloc(sizeof *plan->normal * (size_t)n);
    Tracer t;
    int status = !plan->org || !plan->dir || !plan->hit || !plan->normal || tracer_init(&t, w, g) ? -1 : 0;
    if (status)
        return -1;
    tracer_use_bvh(&t, bvh);
    plan->pilot_rays = n;
    /* The centres of a grid of pixels: the same points on every run. */
    for (int i = 0; i < n; i++) {
        int px = (int)(((i % grid) + 0.5) * width / grid);
        int py = (int)(((i / grid) + 0.5) * height / grid);
        Vec3 org, dir;
        if (!camera_ray(&w->camera, width, height, px, py, &org, &dir))
            continue;
        Hit from = { HIT_NONE, -1, 0.0, org, -1, 0 }, hit;
        if (!trace_nearest(&t, org, dir, HUGE_VAL, &from, &hit))
            continue;
        Vec3 nrm = hit.kind == HIT_PLANE   ? w->planes[hit.index].normal
                 : hit.kind == HIT_SHAPE   ? shape_normal(&w->shapes[hit.index], hit.point, hit.part)
                                           : w->polygons[hit.index].normal;
        if (v3_dot(nrm, dir) > 0.0)
            nrm = v3_neg(nrm);
        int k = plan->npoints++;
        plan->org[k] = org;
        plan->dir[k] = dir;
        plan->hit[k] = hit;
        plan->normal[k] = nrm;
    }
    tracer_free(&t);
    return 0;
}

/* C_ray per light, C_touch and C_record at the pilot's points. */
static int time_pilot(VolumePlan *plan, const World *w, const Grid *g, const Bvh *bvh)
{
    /* the shadow ray keeps no state of its own: the context's common part */
    ShadowContext ctx;
    ShadowPrepared p = { 0 };
    if (shadow_context_init(&ctx, NULL, w, g, &p, 0, 0)) {
        shadow_context_free(&ctx);
        return -1;
    }
    tracer_use_bvh(ctx.tracer, bvh);
    Hit eye = { HIT_NONE, -1, 0.0, { 0, 0, 0 }, -1, 0 };
    Segment seg = { { 0, 0, 0 }, { 0, 0, 0 }, &eye, NULL, NULL, NULL, 0 };
    volatile double sink = 0.0;
    for (int li = 0; li < w->nlights; li++) {
        LightPlan *lp = &plan->light[li];
        double best = HUGE_VAL;
        for (int round = 0; round < ROUNDS; round++) {
            int n = 0;
            double t0 = clock_thread_cpu();
            for (int i = 0; i < plan->npoints; i++) {
                ShadowQuery q;
                q.segment = &seg;
                if (!asks(w, plan, i, li, &q))
                    continue;
                RGB through;
                shadow_conventional_test(&ctx, &q, &through);
                sink += through.r;
                n++;
            }
            double dt = clock_thread_cpu() - t0;
            lp->pilot_queries = n;
            if (n > 0)
                best = fmin(best, dt / n);
        }
        lp->c_ray = best < HUGE_VAL ? best : 0.0;
        lp->queries = plan->pilot_rays > 0 ? plan->pixels * lp->pilot_queries / plan->pilot_rays : 0.0;
    }
    /* The touching check, on a tracer of its own (it remembers its last point). */
    double best = HUGE_VAL;
    double tol = grid_tolerance(g);
    for (int round = 0; plan->npoints > 1 && round < ROUNDS; round++) {
        double t0 = clock_thread_cpu();
        for (int i = 0; i < plan->npoints; i++)
            sink += trace_point_touches_other(ctx.tracer, &plan->hit[i], tol);
        best = fmin(best, (clock_thread_cpu() - t0) / plan->npoints);
    }
    plan->c_touch = best < HUGE_VAL ? best : 0.0;
    shadow_context_free(&ctx);
    /* Recording: the camera rays traced with and without it, alternately. */
    Tracer plain, recording;
    int status = tracer_init(&plain, w, g) || tracer_init(&recording, w, g) ||
                 tracer_record_cells(&recording, g->min, g->max);
    if (status == 0 && plan->npoints > 0) {
        tracer_use_bvh(&plain, bvh);
        tracer_use_bvh(&recording, bvh);
        double with = HUGE_VAL, without = HUGE_VAL;
        for (int round = 0; round < ROUNDS; round++) {
            for (int pass = 0; pass < 2; pass++) {
                Tracer *t = pass ? &recording : &plain;
                double t0 = clock_thread_cpu();
                for (int i = 0; i < plan->npoints; i++) {
                    Hit from = { HIT_NONE, -1, 0.0, plan->org[i], -1, 0 }, hit;
                    sink += trace_nearest(t, plan->org[i], plan->dir[i], HUGE_VAL, &from, &hit);
                }
                double dt = (clock_thread_cpu() - t0) / plan->npoints;
                if (pass)
                    with = fmin(with, dt);
                else
                    without = fmin(without, dt);
            }
        }
        plan->c_record = fmax(with - without, 0.0);
    }
    tracer_free(&plain);
    tracer_free(&recording);
    (void)sink;
    return status ? -1 : 0;
}

int volume_plan_bound(VolumePlan *plan, const World *w)
{
    double together = 0.0;
    int candidates = 0;
    for (int li = 0; li < w->nlights; li++) {
        LightPlan *lp = &plan->light[li];
        lp->gain_bound = lp->queries * (lp->c_ray - plan->c_touch);
        plan->build[li] = 0;
        if (w->lights[li].shadowless || light_is_area(&w->lights[li])) {
            lp->decision = w->lights[li].shadowless ? PLAN_IMPOSSIBLE : PLAN_AREA_LIGHT;
        } else if (!(lp->gain_bound > 0.0)) {
            lp->decision = PLAN_WONT_PAY;
        } else {
            plan->build[li] = 1;
            together += lp->gain_bound;
            candidates++;
        }
    }
    /* Volumes for any light mean recording the cells of every camera ray. */
    if (candidates > 0 && together <= plan->pixels * plan->c_record) {
        for (int li = 0; li < w->nlights; li++) {
            if (plan->build[li]) {
                plan->light[li].decision = PLAN_SHARED_WONT_PAY;
                plan->build[li] = 0;
            }
        }
        candidates = 0;
    }
    return candidates;
}

/* hst beside the shadow ray at the pilot's points, for the usable lights of
 * sv that have no measurement yet (c_hst == 0). */
static int measure_hst(VolumePlan *plan, const World *w, const Grid *g, const Bvh *bvh, const ShadowVolumes *sv,
                       double nth, const CostModel *cost)
{
    /* hst's thread state (the volume methods' without pixel coherence) */
    ShadowContext ctx;
    ShadowPrepared p = { .volumes = (ShadowVolumes *)sv, .cost = (CostModel *)cost, .nth = nth };
    if (shadow_context_init(&ctx, NULL, w, g, &p, 0, 0) || shadow_volume_thread_init(&ctx, &p, 0)) {
        shadow_volume_thread_free(&ctx);
        shadow_context_free(&ctx);
        return -1;
    }
    tracer_use_bvh(ctx.tracer, bvh);
    /* The cells each pilot camera ray pierces, as the render records them. */
    size_t cap = (size_t)ctx.tracer->segment_cells_cap, np = (size_t)(plan->npoints > 0 ? plan->npoints : 1);
    uint32_t *cells = malloc(sizeof *cells * cap * np);
    int *ncells = malloc(sizeof *ncells * np);
    int8_t *in_box = malloc(np);
    Hit *hits = malloc(sizeof *hits * np);
    int status = cells && ncells && in_box && hits ? 0 : -1;
    for (int i = 0; status == 0 && i < plan->npoints; i++) {
        Hit from = { HIT_NONE, -1, 0.0, plan->org[i], -1, 0 };
        hits[i] = plan->hit[i];
        ncells[i] = 0;
        in_box[i] = 0;
        if (trace_nearest(ctx.tracer, plan->org[i], plan->dir[i], HUGE_VAL, &from, &hits[i])) {
            memcpy(&cells[(size_t)i * cap], ctx.tracer->segment_cells,
                   sizeof *cells * (size_t)ctx.tracer->segment_ncells);
            ncells[i] = ctx.tracer->segment_ncells;
            in_box[i] = (int8_t)ctx.tracer->segment_in_box;
        }
    }
    Hit eye = { HIT_NONE, -1, 0.0, { 0, 0, 0 }, -1, 0 };
    volatile double sink = 0.0;
    for (int li = 0; status == 0 && li < w->nlights; li++) {
        LightPlan *lp = &plan->light[li];
        if (!sv->light[li].usable || lp->c_hst > 0.0)
            continue;
        /* hst and the shadow ray in alternation, with the same set-up (the
         * camera ray's cells put back before each decision). */
        double best[2] = { HUGE_VAL, HUGE_VAL };
        for (int round = 0; round < ROUNDS; round++) {
            for (int method = 0; method < 2; method++) {
                int n = 0;
                double t0 = clock_thread_cpu();
                for (int i = 0; i < plan->npoints; i++) {
                    ShadowQuery q;
                    Segment seg = { plan->org[i], plan->dir[i], &eye, NULL, ctx.states, NULL, 0 };
                    q.segment = &seg;
                    if (!asks(w, plan, i, li, &q))
                        continue;
                    q.surface = &hits[i];
                    memcpy(ctx.tracer->segment_cells, &cells[(size_t)i * cap], sizeof *cells * (size_t)ncells[i]);
                    ctx.tracer->segment_ncells = ncells[i];
                    ctx.tracer->segment_in_box = in_box[i];
                    RGB through;
                    if (method == 0)
                        shadow_hst_test(&ctx, &q, &through);
                    else
                        shadow_conventional_test(&ctx, &q, &through);
                    sink += through.r;
                    n++;
                }
                if (n > 0)
                    best[method] = fmin(best[method], (clock_thread_cpu() - t0) / n);
            }
        }
        lp->c_hst = best[0] < HUGE_VAL ? best[0] : 0.0;
        lp->c_ray_beside = best[1] < HUGE_VAL ? best[1] : 0.0;
        lp->gain = lp->queries * (lp->c_ray_beside - lp->c_hst);
    }
    (void)sink;
    free(cells);
    free(ncells);
    free(in_box);
    free(hits);
    shadow_volume_thread_free(&ctx);
    shadow_context_free(&ctx);
    return status;
}

static double nth_for(const VolumePlanOptions *o, const CostModel *cost)
{
    return o->nth.mode == NTH_FIXED ? o->nth.value : o->nth.mode == NTH_AUTO ? cost->nth_ray : -1.0;
}

/* A fresh build of the lights plan->build asks for, calibrated. full: eq.
 * (7)'s values too (else only N_th's, for a trial; per-point N_th needs
 * them all). */
static int build_and_calibrate(VolumePlan *plan, ShadowVolumes *sv, CostModel *cost, const World *w, Grid *g,
                               const Bvh *bvh, const Vec3 *eye, const VolumePlanOptions *o, int full)
{
    shadow_volumes_free(sv);
    /* The polygons' registrations in the grid, which the calibration and
     * the render's pixel coherence read, made with the first volumes. */
    double t0 = clock_wall();
    if (!grid_registered(g)) {
        if (grid_register(g, w, o->threads))
            return -1;
        plan->register_seconds = clock_wall() - t0;
        plan->build_seconds += plan->register_seconds;
        t0 = clock_wall();
    }
    if (shadow_volumes_build(sv, w, g, eye, o->threads, plan->build) ||
        shadow_volumes_set_precision(sv, (PlanePrecision)o->precision))
        return -1;
    plan->builds++;
    plan->build_seconds += clock_wall() - t0;
    full = full || o->nth.mode == NTH_PER_POINT;
    return full ? cost_model_calibrate(cost, w, g, bvh, sv, o->width, o->height)
                : cost_model_calibrate_threshold(cost, w, g, bvh, sv, o->width, o->height);
}

/* The light of the largest bound among those plan->build asks for. */
static int most_promising(const VolumePlan *plan)
{
    int best = -1;
    for (int li = 0; li < plan->nlights; li++)
        if (plan->build[li] && (best < 0 || plan->light[li].gain_bound > plan->light[best].gain_bound))
            best = li;
    return best;
}

int volume_plan_build(VolumePlan *plan, ShadowVolumes *sv, CostModel *cost, const World *w, Grid *g,
                      const Bvh *bvh, const Vec3 *eye, const VolumePlanOptions *o)
{
    double start = clock_wall();
    memset(plan, 0, sizeof *plan);
    memset(sv, 0, sizeof *sv);
    memset(cost, 0, sizeof *cost);
    plan->mode = o->mode;
    plan->nlights = w->nlights;
    plan->tried = -1;
    int nl = w->nlights > 0 ? w->nlights : 1;
    plan->light = calloc((size_t)nl, sizeof *plan->light);
    plan->build = calloc((size_t)nl, sizeof *plan->build);
    if (!plan->light || !plan->build)
        return -1;
    plan->pixels = (double)o->width * (double)o->height;
    if (o->mode == VOLUMES_ALWAYS) {
        for (int li = 0; li < w->nlights; li++) {
            plan->build[li] = 1;
            plan->light[li].decision = w->lights[li].shadowless        ? PLAN_IMPOSSIBLE
                                       : light_is_area(&w->lights[li]) ? PLAN_AREA_LIGHT
                                                                       : PLAN_ALWAYS;
        }
        return build_and_calibrate(plan, sv, cost, w, g, bvh, eye, o, 1);
    }

    if (w->npolygons >= PLAN_POLYGONS_PER_PIXEL * plan->pixels) {
        for (int li = 0; li < w->nlights; li++)
            plan->light[li].decision = w->lights[li].shadowless        ? PLAN_IMPOSSIBLE
                                       : light_is_area(&w->lights[li]) ? PLAN_AREA_LIGHT
                                                                       : PLAN_TOO_MANY_POLYGONS;
        plan->seconds = clock_wall() - start;
        return 0;
    }

    /* Stage one: the pilot's timings and the bounds. */
    if (pilot_points(plan, w, g, bvh, o->width, o->height) || time_pilot(plan, w, g, bvh))
        return -1;
    int candidates = volume_plan_bound(plan, w);
    int best = most_promising(plan);
    /* The build of the most promising light, estimated where that is much
     * cheaper than building it (a big scene): if even it cannot pay, none
     * can, the lights' builds being alike. */
    int sample = w->npolygons / SAMPLE_SHARE;
    sample = sample < SAMPLE_MIN ? SAMPLE_MIN : sample > SAMPLE_MAX ? SAMPLE_MAX : sample;
    if (best >= 0 && w->npolygons > 2 * sample) {
        VolumesEstimate est;
        int8_t *only = calloc((size_t)nl, 1);
        if (!only)
            return -1;
        only[best] = 1;
        int failed = shadow_volumes_estimate(w, g, eye, only, sample, &est);
        free(only);
        if (failed)
            return -1;
        plan->sample_polygons = est.sample_polygons;
        plan->shared_estimate = est.shared_seconds;
        plan->register_estimate = est.register_seconds;
        double b = est.light_seconds[best];
        shadow_volumes_estimate_free(&est);
        double together = 0.0;
        for (int li = 0; li < w->nlights; li++) {
            LightPlan *lp = &plan->light[li];
            if (!plan->build[li])
                continue;
            lp->build_estimate = b;
            lp->gain_bound -= b;
            if (lp->gain_bound > 0.0) {
                together += lp->gain_bound;
            } else {
                lp->decision = PLAN_WONT_PAY;
                plan->build[li] = 0;
                candidates--;
            }
        }
        if (candidates > 0 && together <= plan->shared_estimate + plan->pixels * plan->c_record) {
            for (int li = 0; li < w->nlights; li++) {
                if (plan->build[li]) {
                    plan->light[li].decision = PLAN_SHARED_WONT_PAY;
                    plan->build[li] = 0;
                }
            }
            candidates = 0;
        }
        best = most_promising(plan);
    }
    if (candidates == 0 || best < 0) {
        plan->seconds = clock_wall() - start;
        return 0;
    }

    /* Stage two: the most promising light built alone and measured. */
    int8_t *wanted = malloc((size_t)nl);
    if (!wanted)
        return -1;
    memcpy(wanted, plan->build, (size_t)nl);
    memset(plan->build, 0, (size_t)nl);
    plan->build[best] = 1;
    plan->tried = best;
    double before = plan->build_seconds;
    int status = build_and_calibrate(plan, sv, cost, w, g, bvh, eye, o, 0);
    double trial_build = plan->build_seconds - before - plan->register_seconds; /* the others' builds share it */
    if (status == 0 && sv->light[best].usable)
        status = measure_hst(plan, w, g, bvh, sv, nth_for(o, cost), cost);
    LightPlan *tp = &plan->light[best];
    if (status == 0 && !(tp->gain > 0.0 && tp->c_hst < KEEP_RATIO * tp->c_ray_beside)) {
        tp->decision = PLAN_DROPPED;
        for (int li = 0; li < w->nlights; li++) {
            if (li != best && wanted[li]) {
                plan->light[li].decision = PLAN_TRIAL_FAILED;
                plan->build[li] = 0;
            }
        }
        plan->build[best] = 0;
        shadow_volumes_free(sv);
    } else if (status == 0) {
        /* The others priced at the tried light's measured ratio of hst to
         * the shadow ray, and its measured build. */
        double ratio = tp->c_ray_beside > 0.0 ? tp->c_hst / tp->c_ray_beside : 1.0;
        double together = tp->gain;
        int more = 0;
        for (int li = 0; li < w->nlights; li++) {
            LightPlan *lp = &plan->light[li];
            if (li == best || !wanted[li])
                continue;
            lp->gain = lp->queries * lp->c_ray * (1.0 - ratio) - trial_build;
            if (lp->gain > 0.0) {
                plan->build[li] = 1;
                together += lp->gain;
                more++;
            } else {
                lp->decision = PLAN_PREDICTED_WONT_PAY;
            }
        }
        if (together <= plan->pixels * plan->c_record) {
            for (int li = 0; li < w->nlights; li++) {
                if (plan->build[li]) {
                    plan->light[li].decision = li == best ? PLAN_DROPPED_ALL : PLAN_PREDICTED_WONT_PAY;
                    plan->build[li] = 0;
                }
            }
            shadow_volumes_free(sv);
        } else {
            /* All that should pay built together, and each measured. */
            for (int li = 0; li < w->nlights; li++)
                if (plan->build[li])
                    plan->light[li].decision = PLAN_KEPT;
            status = build_and_calibrate(plan, sv, cost, w, g, bvh, eye, o, 1);
            if (status == 0 && more > 0)
                status = measure_hst(plan, w, g, bvh, sv, nth_for(o, cost), cost);
            double kept = 0.0;
            for (int li = 0; status == 0 && li < w->nlights; li++) {
                LightPlan *lp = &plan->light[li];
                if (!sv->light[li].usable)
                    continue;
                if (lp->gain > 0.0 && lp->c_hst < KEEP_RATIO * lp->c_ray_beside) {
                    kept += lp->gain;
                } else {
                    lp->decision = PLAN_DROPPED;
                    shadow_volumes_drop_light(sv, li);
                }
            }
            if (status == 0 && kept <= plan->pixels * plan->c_record) {
                for (int li = 0; li < w->nlights; li++)
                    if (sv->light[li].usable)
                        plan->light[li].decision = PLAN_DROPPED_ALL;
                shadow_volumes_free(sv);
            }
        }
    }
    free(wanted);
    if (status == 0 && shadow_volumes_usable_lights(sv) == 0) {
        shadow_volumes_free(sv);
        memset(cost, 0, sizeof *cost);
    }
    plan->seconds = clock_wall() - start - plan->build_seconds;
    return status;
}
