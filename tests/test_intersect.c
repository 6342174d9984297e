/* Ray/polygon intersection and the inside test, holes included. */
#include <math.h>

#include "fixtures.h"
#include "intersect.h"
#include "tap.h"
#include "world.h"

int main(void)
{
    Scene *s = fixture_scene(8);
    /* A 4x4 square frame with a 2x2 hole, in the z = 0 plane (POV-Ray
     * polygon semantics: two closed outlines, even-odd inside). */
    Vec3 frame[] = { { -2, -2, 0 }, { 2, -2, 0 }, { 2, 2, 0 }, { -2, 2, 0 }, { -2, -2, 0 },
                     { -1, -1, 0 }, { 1, -1, 0 }, { 1, 1, 0 }, { -1, 1, 0 }, { -1, -1, 0 } };
    int starts[] = { 0, 5, 10 };
    fixture_polygon(s, frame, 10, starts, 2);
    fixture_triangle(s, v3(0, 0, 5), v3(1, 0, 5), v3(0, 1, 5));
    /* A zero-area triangle: dropped at build time. */
    fixture_triangle(s, v3(0, 0, 7), v3(1, 1, 7), v3(2, 2, 7));
    /* Collinear in the file, rotated: rounding leaves an area of about
     * 1e-17, and a normal that is noise. Dropped too. */
    SceneObject *sliver = fixture_triangle(s, v3(0, 0, 0), v3(0.5, 0.4, 0), v3(1, 0.8, 0));
    transform_rotate(&sliver->transform, v3(-60, 0, 0));
    transform_translate(&sliver->transform, v3(0.6, 0.7, -0.3));
    /* Thin, but a triangle: 1e-6 as high as it is long. Kept. */
    fixture_triangle(s, v3(0, 0, 9), v3(1, 0, 9), v3(0.5, 1e-6, 9));

    World w;
    WorldError err;
    tap_ok(world_build(&w, s, &err) == 0, "world builds");
    tap_ok(w.npolygons == 3 && w.ndegenerate == 2,
           "zero-area and rotated collinear triangles dropped, thin one kept (%d polygons, %d dropped)", w.npolygons,
           w.ndegenerate);
    const Polygon *frame_p = &w.polygons[0], *tri = &w.polygons[1];

    tap_ok(polygon_contains(&w, frame_p, v3(1.5, 0, 0)), "point in the frame is inside");
    tap_ok(!polygon_contains(&w, frame_p, v3(0, 0, 0)), "point in the hole is outside");
    tap_ok(!polygon_contains(&w, frame_p, v3(3, 0, 0)), "point beyond the frame is outside");
    tap_ok(polygon_contains(&w, frame_p, v3(-1.5, 1.5, 0)), "corner of the frame is inside");

    double t = intersect_polygon(&w, frame_p, v3(1.5, 0.5, -3), v3(0, 0, 1));
    tap_ok(fabs(t - 3.0) < 1e-12, "ray hits the frame at t = 3 (%g)", t);
    t = intersect_polygon(&w, frame_p, v3(0.2, 0.1, -3), v3(0, 0, 1));
    tap_ok(t < 0, "ray through the hole misses");
    t = intersect_polygon(&w, frame_p, v3(1.5, 0.5, -3), v3(1, 0, 0));
    tap_ok(t < 0, "ray parallel to the plane misses");
    t = intersect_polygon(&w, frame_p, v3(1.5, 0.5, 3), v3(0, 0, 1));
    tap_ok(t < 0, "polygon behind the ray is not hit");

    /* Slanted ray hitting the triangle; hit point lies in the triangle's plane. */
    Vec3 o = v3(-1, -1, 0), d = v3_normalize(v3(1.25, 1.25, 5));
    t = intersect_polygon(&w, tri, o, d);
    Vec3 q = v3_madd(o, d, t);
    tap_ok(t > 0 && fabs(q.z - 5.0) < 1e-12, "slanted ray hits the triangle in its plane");
    /* Shared-edge rule: a point exactly on an edge is inside (no light leaks). */
    tap_ok(polygon_contains(&w, tri, v3(0.5, 0.5, 5)), "point on the hypotenuse counts as inside");
    tap_ok(polygon_contains(&w, tri, v3(0, 0, 5)), "vertex counts as inside");
    tap_ok(!polygon_contains(&w, tri, v3(0.6, 0.6, 5)), "point past the hypotenuse is outside");

    world_free(&w);
    scene_free(s);
    return tap_done();
}
