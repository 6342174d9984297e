/* Which lights get shadow volumes (volume_plan.h), on what can be checked
 * without a clock:
 *   - the build estimate runs the real build on its sample: with the whole
 *     scene as the sample (a height field, a polygon with a hole, a card)
 *     its registrations are exactly the build's, light by light; on a run
 *     of a mesh's rows they are the whole's scaled, never far below (the
 *     run's cut edges only add silhouettes);
 *   - stage one's rule on figures set by hand, against the rule as the
 *     header states it;
 *   - --volumes always builds every light that casts shadows and calibrates
 *     the whole cost model; auto with a camera that sees nothing expects no
 *     decision, builds nothing and leaves no volumes and no calibration;
 *     auto with a polygon a pixel or more runs no pilot at all. */
#include <stdio.h>

#include "fixtures.h"
#include "grid.h"
#include "shadow_volumes.h"
#include "tap.h"
#include "volume_plan.h"
#include "world.h"

/* A welded height field of n x n quads (2 n^2 triangles), rows in order. */
static void height_field(Scene *s, int n, TestRng *r)
{
    double h[65][65];
    for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++)
            h[i][j] = rng_range(r, 0.0, 0.3);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            double x0 = -2.0 + 4.0 * i / n, x1 = -2.0 + 4.0 * (i + 1) / n;
            double z0 = -2.0 + 4.0 * j / n, z1 = -2.0 + 4.0 * (j + 1) / n;
            Vec3 a = v3(x0, h[i][j], z0), b = v3(x1, h[i + 1][j], z0), c = v3(x1, h[i + 1][j + 1], z1),
                 d = v3(x0, h[i][j + 1], z1);
            fixture_triangle(s, a, b, c);
            fixture_triangle(s, a, c, d);
        }
}

typedef struct {
    Scene *scene;
    SceneLight lights[3];
    World w;
    Grid g;
    int ok;
} Fixture;

/* The height field, a frame with a hole above it and a standing card; two
 * point lights and a shadowless one. */
static void fixture_make(Fixture *f, int n, int extras)
{
    TestRng r = { 0x2545F4914F6CDD1Dull };
    f->scene = fixture_scene(2 * n * n + 4);
    height_field(f->scene, n, &r);
    if (extras) {
        Vec3 frame[10] = { v3(-1, 1.2, -1), v3(1, 1.2, -1), v3(1, 1.2, 1), v3(-1, 1.2, 1), v3(-1, 1.2, -1),
                           v3(-0.5, 1.2, -0.5), v3(0.5, 1.2, -0.5), v3(0.5, 1.2, 0.5), v3(-0.5, 1.2, 0.5),
                           v3(-0.5, 1.2, -0.5) };
        int starts[3] = { 0, 5, 10 };
        fixture_polygon(f->scene, frame, 10, starts, 2);
        fixture_triangle(f->scene, v3(1.2, 0.2, 1.2), v3(1.8, 0.2, 1.5), v3(1.5, 1.4, 1.4));
    }
    memset(f->lights, 0, sizeof f->lights);
    for (int i = 0; i < 3; i++) {
        f->lights[i].kind = LIGHT_POINT;
        f->lights[i].colour.r = f->lights[i].colour.g = f->lights[i].colour.b = 1;
    }
    f->lights[0].location = v3(3, 6, -2);
    f->lights[1].location = v3(-4, 5, 3);
    f->lights[2].location = v3(0, 8, 0);
    f->lights[2].shadowless = 1;
    f->scene->lights = f->lights;
    f->scene->nlights = 3;
    f->scene->camera.location = v3(0, 4, -6);
    f->scene->camera.direction = v3_normalize(v3(0, -0.6, 1));
    f->scene->camera.up = v3_normalize(v3(0, 1, 0.6));
    WorldError err;
    f->ok = world_build(&f->w, f->scene, &err) == 0;
    Vec3 extra[1] = { f->w.camera.location };
    f->ok = f->ok && grid_build(&f->g, &f->w, NULL, extra, 1) == 0;
}

static void fixture_done(Fixture *f)
{
    if (f->ok) {
        grid_free(&f->g);
        world_free(&f->w);
    }
    fixture_scene_free(f->scene);
}

static void estimate_against_build(void)
{
    /* The whole scene as the sample: the same registrations. */
    Fixture f;
    fixture_make(&f, 12, 1);
    ShadowVolumes sv;
    VolumesEstimate est;
    const Vec3 *eye = &f.w.camera.location;
    int built = f.ok && shadow_volumes_build(&sv, &f.w, &f.g, eye, 1, NULL) == 0;
    int estimated = built && shadow_volumes_estimate(&f.w, &f.g, eye, NULL, f.w.npolygons, &est) == 0;
    tap_ok(estimated, "the build and its estimate run on a height field, a frame with a hole and a card");
    if (estimated) {
        tap_ok(est.sample_polygons == f.w.npolygons && est.scale == 1.0,
               "a sample of all %d polygons scales by 1 (%d polygons, scale %g)", f.w.npolygons,
               est.sample_polygons, est.scale);
        for (int li = 0; li < 2; li++)
            tap_ok(est.light_registrations[li] == (double)sv.light[li].nitems,
                   "light %d: the estimate on the whole scene registers what the build does (%g and %zu)", li,
                   est.light_registrations[li], sv.light[li].nitems);
        tap_ok(est.light_seconds[2] == 0.0 && est.light_registrations[2] == 0.0,
               "the shadowless light is not estimated");
        tap_ok(est.register_seconds == 0.0, "on a grid whose polygons are registered, registering costs nothing");
        shadow_volumes_estimate_free(&est);
        /* The same box with no polygons registered (as hstrace builds it
         * before any volumes): their registration is estimated, as shared
         * cost, and counted as grid_register makes it. */
        Grid bare;
        Vec3 extra[1] = { f.w.camera.location };
        grid_build_box(&bare, &f.w, NULL, extra, 1);
        tap_ok(grid_count_registrations(&bare, &f.w) == (long)f.g.nitems,
               "the polygons' registrations counted on the bare grid are the registered grid's (%ld and %zu)",
               grid_count_registrations(&bare, &f.w), f.g.nitems);
        if (shadow_volumes_estimate(&f.w, &bare, eye, NULL, f.w.npolygons, &est) == 0) {
            tap_ok(est.register_seconds > 0.0 && est.shared_seconds >= est.register_seconds,
                   "on a bare grid the polygons' registration is estimated, within the shared cost (%.3g s of %.3g s)",
                   est.register_seconds, est.shared_seconds);
            shadow_volumes_estimate_free(&est);
        } else {
            tap_ok(0, "the estimate runs on a bare grid");
        }
        grid_free(&bare);
    }
    if (built)
        shadow_volumes_free(&sv);
    fixture_done(&f);

    /* A run of rows of a bigger mesh: the whole's registrations, scaled,
     * high rather than low. */
    fixture_make(&f, 48, 0);
    built = f.ok && shadow_volumes_build(&sv, &f.w, &f.g, eye, 1, NULL) == 0;
    int sample = f.w.npolygons / 8;
    estimated = built && shadow_volumes_estimate(&f.w, &f.g, &f.w.camera.location, NULL, sample, &est) == 0;
    tap_ok(estimated, "the estimate runs on a sample of %d of %d triangles", sample, f.ok ? f.w.npolygons : 0);
    if (estimated) {
        tap_ok(est.scale > 7.9 && est.scale < 8.1, "one polygon in 8 sampled scales by the points, 8 (%g)", est.scale);
        for (int li = 0; li < 2; li++) {
            double ratio = est.light_registrations[li] / (double)sv.light[li].nitems;
            tap_ok(ratio >= 0.75 && ratio <= 3.0,
                   "light %d: registrations estimated from the sample are the whole's within 0.75 to 3 "
                   "(%.0f against %zu: %.2f)",
                   li, est.light_registrations[li], sv.light[li].nitems, ratio);
        }
        shadow_volumes_estimate_free(&est);
    }
    if (built)
        shadow_volumes_free(&sv);
    fixture_done(&f);
}

static void rule_by_hand(void)
{
    Fixture f;
    fixture_make(&f, 2, 0);
    if (!f.ok) {
        tap_ok(0, "the rule's fixture builds");
        fixture_done(&f);
        return;
    }
    LightPlan lights[3];
    int8_t build[3];
    VolumePlan p;
    memset(&p, 0, sizeof p);
    p.nlights = 3;
    p.light = lights;
    p.build = build;
    p.pixels = 1000.0;
    p.c_touch = 50e-9;
    p.c_record = 100e-9; /* the recording of 1000 camera rays: 100 us */
    memset(lights, 0, sizeof lights);
    /* Light 0: 1000 decisions at 200 ns, at most 150 us to gain; light 1:
     * its shadow ray no dearer than the touching check. */
    lights[0].queries = 1000.0;
    lights[0].c_ray = 200e-9;
    lights[1].queries = 1000.0;
    lights[1].c_ray = 50e-9;
    lights[2].queries = 1000.0;
    lights[2].c_ray = 500e-9;
    int n = volume_plan_bound(&p, &f.w);
    tap_ok(n == 1 && build[0] && !build[1] && !build[2], "one candidate: light 0 (%d candidates)", n);
    tap_ok(lights[0].gain_bound > 149e-6 && lights[0].gain_bound < 151e-6,
           "light 0 may gain 1000 x (200 - 50) ns = 150 us (%.1f us)", lights[0].gain_bound * 1e6);
    tap_ok(lights[1].decision == PLAN_WONT_PAY, "a shadow ray no dearer than the touching check: cannot pay (%s)",
           volume_plan_decision_name(lights[1].decision));
    tap_ok(lights[2].decision == PLAN_IMPOSSIBLE, "a shadowless light has no volumes (%s)",
           volume_plan_decision_name(lights[2].decision));
    /* Recording dearer than all the bounds: none. */
    p.c_record = 200e-9;
    n = volume_plan_bound(&p, &f.w);
    tap_ok(n == 0 && !build[0] && lights[0].decision == PLAN_SHARED_WONT_PAY,
           "150 us to gain against 200 us of recording cells: nothing built (%s)",
           volume_plan_decision_name(lights[0].decision));
    fixture_done(&f);
}

static void modes(void)
{
    Fixture f;
    fixture_make(&f, 8, 1);
    if (!f.ok) {
        tap_ok(0, "the modes' fixture builds");
        fixture_done(&f);
        return;
    }
    Bvh bvh;
    int have_bvh = bvh_build(&bvh, &f.w, 1) == 0;
    VolumePlan plan;
    ShadowVolumes sv;
    CostModel cost;
    VolumePlanOptions o = { VOLUMES_ALWAYS, 32, 24, 2, 0, { NTH_AUTO, 0.0 } };
    int r = have_bvh ? volume_plan_build(&plan, &sv, &cost, &f.w, &f.g, &bvh, &f.w.camera.location, &o) : -1;
    tap_ok(r == 0 && sv.light && sv.light[0].usable && sv.light[1].usable && !sv.light[2].usable,
           "--volumes always: both lights that cast shadows get volumes, the shadowless one none");
    tap_ok(r == 0 && plan.light[0].decision == PLAN_ALWAYS && plan.light[2].decision == PLAN_IMPOSSIBLE,
           "--volumes always: the plan says why (%s; %s)", r == 0 ? volume_plan_decision_name(plan.light[0].decision) : "",
           r == 0 ? volume_plan_decision_name(plan.light[2].decision) : "");
    tap_ok(r == 0 && cost.full && cost.c_s > 0.0, "--volumes always: the whole cost model is calibrated");
    if (r == 0) {
        volume_plan_free(&plan);
        shadow_volumes_free(&sv);
    }
    /* Auto, the camera turned away from everything: no pilot ray lands, so
     * no decision is expected and no volume can pay. */
    f.w.camera.direction = v3_neg(f.w.camera.direction);
    f.w.camera.up = v3_neg(f.w.camera.up);
    o.mode = VOLUMES_AUTO;
    r = have_bvh ? volume_plan_build(&plan, &sv, &cost, &f.w, &f.g, &bvh, &f.w.camera.location, &o) : -1;
    tap_ok(r == 0 && plan.npoints == 0 && plan.pilot_rays > 0,
           "auto, looking away: %d pilot rays, none lands", r == 0 ? plan.pilot_rays : 0);
    tap_ok(r == 0 && sv.light == NULL && cost.seconds == 0.0, "auto, looking away: no volumes built, no calibration");
    tap_ok(r == 0 && plan.light[0].decision == PLAN_WONT_PAY && plan.light[1].decision == PLAN_WONT_PAY &&
               plan.light[2].decision == PLAN_IMPOSSIBLE,
           "auto, looking away: the lights cannot pay, the shadowless one has none (%s)",
           r == 0 ? volume_plan_decision_name(plan.light[0].decision) : "");
    if (r == 0) {
        volume_plan_free(&plan);
        shadow_volumes_free(&sv);
    }
    /* Auto with a polygon a pixel or more: not even piloted; one pixel
     * more than the polygons, the pilot runs. */
    o.width = f.w.npolygons;
    o.height = 1;
    r = have_bvh ? volume_plan_build(&plan, &sv, &cost, &f.w, &f.g, &bvh, &f.w.camera.location, &o) : -1;
    tap_ok(r == 0 && plan.pilot_rays == 0 && sv.light == NULL && plan.light[0].decision == PLAN_TOO_MANY_POLYGONS &&
               plan.light[1].decision == PLAN_TOO_MANY_POLYGONS && plan.light[2].decision == PLAN_IMPOSSIBLE,
           "auto, %d polygons for as many pixels: no pilot, no volumes (%s)", f.w.npolygons,
           r == 0 ? volume_plan_decision_name(plan.light[0].decision) : "");
    if (r == 0) {
        volume_plan_free(&plan);
        shadow_volumes_free(&sv);
    }
    o.width = f.w.npolygons + 1;
    r = have_bvh ? volume_plan_build(&plan, &sv, &cost, &f.w, &f.g, &bvh, &f.w.camera.location, &o) : -1;
    tap_ok(r == 0 && plan.pilot_rays > 0 && plan.light[0].decision != PLAN_TOO_MANY_POLYGONS,
           "auto, %d polygons for one pixel more: piloted (%d pilot rays)", f.w.npolygons, r == 0 ? plan.pilot_rays : 0);
    if (r == 0) {
        volume_plan_free(&plan);
        shadow_volumes_free(&sv);
    }
    if (have_bvh)
        bvh_free(&bvh);
    fixture_done(&f);
}

int main(void)
{
    estimate_against_build();
    rule_by_hand();
    modes();
    return tap_done();
}
