/* --shadows embree against the shadow ray where float cannot matter: a
 * scene of well-separated polygons (a floor, opaque and see-through
 * occluders high above it, a polygon with a hole and a concave one, two
 * panes closer than POV-Ray's 1e-3 along the ray, a no_shadow one) and
 * shadow rays that pass no polygon's border within a wide margin. There the
 * two must give the same light, bit for bit: the same decisions, and the
 * same colour through the same transparent polygons folded the same way.
 * Without Embree the method is refused and this test is skipped. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fixtures.h"
#include "grid.h"
#include "intersect.h"
#include "shadow.h"
#include "shadow_embree.h"
#include "shadow_registry.h"
#include "tap.h"

/* A square of side 2r at height y (a convex polygon of one outline). */
static SceneObject *square(Scene *s, double cx, double cz, double r, double y)
{
    Vec3 p[5] = { v3(cx - r, y, cz - r), v3(cx + r, y, cz - r), v3(cx + r, y, cz + r), v3(cx - r, y, cz + r),
                  v3(cx - r, y, cz - r) };
    int starts[2] = { 0, 5 };
    return fixture_polygon(s, p, 5, starts, 1);
}

static Scene *make_scene(void)
{
    Scene *s = fixture_scene(16);
    s->camera.location = v3(0, 6, -8);
    square(s, 0, 0, 4, 0); /* the floor: polygon 0 */
    /* Opaque: a triangle, and a square with a square hole (user geometry). */
    fixture_triangle(s, v3(-2.5, 1, -2.5), v3(-0.5, 1, -2.5), v3(-1.5, 1, -0.5));
    Vec3 holed[10] = { v3(0.5, 1.2, -2.5), v3(2.5, 1.2, -2.5), v3(2.5, 1.2, -0.5), v3(0.5, 1.2, -0.5),
                       v3(0.5, 1.2, -2.5), v3(1.1, 1.2, -1.9), v3(1.9, 1.2, -1.9), v3(1.9, 1.2, -1.1),
                       v3(1.1, 1.2, -1.1), v3(1.1, 1.2, -1.9) };
    int holed_starts[3] = { 0, 5, 10 };
    fixture_polygon(s, holed, 10, holed_starts, 2);
    /* See-through: a filtering triangle, a transmitting square, a concave
     * L (user geometry) that filters and transmits. */
    fixture_pigment(s, fixture_triangle(s, v3(-2.5, 1.6, 0.5), v3(-0.5, 1.6, 0.5), v3(-1.5, 1.6, 2.5)), 0.9, 0.3,
                    0.2, 0.7, 0.0);
    fixture_pigment(s, square(s, 1.5, 1.5, 1.0, 2.0), 0.2, 0.8, 0.3, 0.0, 0.5);
    Vec3 ell[7] = { v3(-1, 0.8, -0.8), v3(1, 0.8, -0.8), v3(1, 0.8, -0.2), v3(-0.4, 0.8, -0.2),
                    v3(-0.4, 0.8, 0.8), v3(-1, 0.8, 0.8), v3(-1, 0.8, -0.8) };
    int ell_starts[2] = { 0, 7 };
    fixture_pigment(s, fixture_polygon(s, ell, 7, ell_starts, 1), 0.5, 0.6, 0.9, 0.4, 0.3);
    /* Two panes 0.0005 apart (within SMALL_TOLERANCE: filtered once), over
     * an opaque-free part of the floor. */
    fixture_pigment(s, square(s, 0.0, 2.6, 0.9, 2.5), 0.3, 0.5, 0.9, 0.8, 0.1);
    fixture_pigment(s, square(s, 0.0, 2.6, 0.9, 2.5005), 0.9, 0.9, 0.4, 0.6, 0.2);
    /* no_shadow: the shadow rays pass it. */
    fixture_triangle(s, v3(2.6, 1.4, 0.3), v3(3.6, 1.4, 0.3), v3(3.1, 1.4, 1.3))->no_shadow = 1;
    return s;
}

/* Does the segment org + t dir, t in (0, tmax), pass within `margin` of the
 * border of a polygon other than `own` (or run near its plane)? */
static int near_a_border(const World *w, int own, Vec3 org, Vec3 dir, double tmax, double margin)
{
    for (int i = 0; i < w->npolygons; i++) {
        if (i == own)
            continue;
        const Polygon *p = &w->polygons[i];
        double denom = v3_dot(p->normal, dir);
        if (fabs(denom) < 0.05)
            return 1;
        double t = (p->d - v3_dot(p->normal, org)) / denom;
        if (t <= -margin || t >= tmax + margin)
            continue;
        if (t < margin || t > tmax - margin)
            return 1;
        if (polygon_classify_point(w, p, v3_madd(org, dir, t), margin) == -1)
            return 1;
    }
    return 0;
}

int main(void)
{
    if (!shadow_embree_built()) {
        const ShadowMethod *m = shadow_method_find("embree");
        tap_ok(m && shadow_method_unavailable(m) && strstr(shadow_method_unavailable(m), "Embree"),
               "without Embree, the embree method says it is not built in");
        printf("ok 2 # SKIP embree not built\n");
        printf("1..2\n");
        return 0;
    }
    Scene *s = make_scene();
    SceneLight lights[2];
    memset(lights, 0, sizeof lights);
    lights[0].kind = LIGHT_POINT;
    lights[0].location = v3(0.3, 6, -0.2);
    lights[0].colour.r = lights[0].colour.g = lights[0].colour.b = 1;
    lights[1].kind = LIGHT_PARALLEL;
    lights[1].location = v3(-2, 8, 1);
    lights[1].point_at = v3(0, 0, 0);
    lights[1].colour.r = lights[1].colour.g = lights[1].colour.b = 1;
    s->lights = lights;
    s->nlights = 2;
    World w;
    WorldError werr;
    if (world_build(&w, s, &werr)) {
        tap_ok(0, "the scene builds: %s", werr.message);
        return tap_done();
    }
    Vec3 extra[1 + 8 * 16];
    int nextra = grid_extra_points(&w, extra, (int)(sizeof extra / sizeof extra[0]));
    Grid g;
    Bvh b;
    char err[512];
    EmbreeScene *es = NULL;
    if (grid_build(&g, &w, NULL, extra, nextra) || bvh_build(&b, &w, 1) ||
        !(es = shadow_embree_build(&w, 1, err, sizeof err))) {
        tap_ok(0, "grid, hierarchy and Embree scene build (%s)", es ? "" : err);
        return tap_done();
    }
    const EmbreeSceneInfo *info = shadow_embree_info(es);
    tap_ok(w.npolygons == 9 && info->triangles == 2 && info->fanned_polygons == 4 && info->fan_triangles == 8 &&
               info->user_polygons == 2 && info->left_out == 1,
           "the Embree scene: %d triangles, %d convex polygons as %d triangles, %d polygons of holes or concave "
           "outlines as user geometry, %d no_shadow left out (of %d polygons)",
           info->triangles, info->fanned_polygons, info->fan_triangles, info->user_polygons, info->left_out,
           w.npolygons);

    ShadowContext ctx;
    ShadowPrepared prepared = { .decider = shadow_method_find("embree"), .embree = es };
    if (shadow_context_init(&ctx, NULL, &w, &g, &prepared, 0, 0)) {
        tap_ok(0, "shadow context");
        return tap_done();
    }
    tracer_use_bvh(ctx.tracer, &b);
    TestRng rng = { 0x243F6A8885A308D3ull };
    int tested = 0, skipped = 0, wrong = 0, lit = 0, blocked = 0, filtered = 0, on_occluder = 0;
    for (int k = 0; k < 6000; k++) {
        /* Points on the floor, and every 4th on the top of an occluder
         * (its own polygon then excluded). */
        int own = 0;
        Vec3 at = v3(rng_range(&rng, -3.9, 3.9), 0, rng_range(&rng, -3.9, 3.9));
        if (k % 4 == 3) {
            own = 1 + (int)(rng_uniform(&rng) * (w.npolygons - 1));
            const Polygon *p = &w.polygons[own];
            at = v3(rng_range(&rng, p->bbox_min.x, p->bbox_max.x), p->bbox_min.y,
                    rng_range(&rng, p->bbox_min.z, p->bbox_max.z));
            if (polygon_classify_point(&w, p, at, 0.05) != 1) {
                skipped++;
                continue;
            }
        }
        Hit surface = { HIT_POLYGON, own, 1.0, at, -1, 0 };
        Segment seg = { w.camera.location, v3(0, -1, 0), &surface, NULL, NULL, NULL, 0 };
        for (int li = 0; li < w.nlights; li++) {
            const Light *l = &w.lights[li];
            Vec3 d = v3_sub(l->location, at);
            double distance = v3_length(d);
            Vec3 to_light = v3_scale(d, 1.0 / distance);
            if (l->kind == LIGHT_PARALLEL) {
                distance *= v3_dot(l->direction, to_light);
                to_light = l->direction;
            }
            if (near_a_border(&w, own, at, to_light, distance, 0.02)) {
                skipped++;
                continue;
            }
            ShadowQuery q = { at, &surface, &seg, li, to_light, distance, v3(0, 1, 0), &w.lights[li] };
            RGB want, got;
            shadow_conventional_test(&ctx, &q, &want);
            shadow_embree_test(&ctx, &q, &got);
            tested++;
            on_occluder += own != 0;
            if (want.r != got.r || want.g != got.g || want.b != got.b) {
                if (wrong++ < 5)
                    tap_diag("at (%.17g, %.17g, %.17g) on polygon %d, light %d: shadow ray (%g, %g, %g), embree "
                             "(%g, %g, %g)",
                             at.x, at.y, at.z, own, li, want.r, want.g, want.b, got.r, got.g, got.b);
            } else if (want.r == 1.0 && want.g == 1.0 && want.b == 1.0) {
                lit++;
            } else if (want.r == 0.0 && want.g == 0.0 && want.b == 0.0) {
                blocked++;
            } else {
                filtered++;
            }
        }
    }
    tap_ok(wrong == 0 && tested > 5000 && lit > 500 && blocked > 500 && filtered > 500 && on_occluder > 500,
           "well-separated polygons: embree lets exactly the shadow ray's light through at every one of %d "
           "decisions (%d wrong; %d lit, %d blocked, %d filtered by transparent polygons; %d from points on "
           "occluders; %d near a border, left out)",
           tested, wrong, lit, blocked, filtered, on_occluder, skipped);
    shadow_context_free(&ctx);
    shadow_embree_free(es);
    bvh_free(&b);
    grid_free(&g);
    world_free(&w);
    fixture_scene_free(s);
    return tap_done();
}
