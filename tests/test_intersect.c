/* Ray/polygon intersection and the inside test, holes included; and the
 * outline boxes' shortcut (World.outline_box: an outline the ray is
 * certainly outside of is passed over) against the full crossing count,
 * on lattices (a square with 3 x 3 holes) and stars (one concave outline)
 * turned and moved far from the origin, for rays aimed at random points, at their vertices and at
 * points on their edges: the same hits at the same distances, bit for bit. */
#include <math.h>
#include <string.h>

#include "fixtures.h"
#include "intersect.h"
#include "tap.h"
#include "world.h"

/* A 2.4-wide square with a 3 x 3 grid of 0.6-wide square holes, in z = 0. */
static SceneObject *lattice(Scene *s)
{
    Vec3 pts[50];
    int starts[11], n = 0;
    const double outer[4][2] = { { -1.2, -1.2 }, { 1.2, -1.2 }, { 1.2, 1.2 }, { -1.2, 1.2 } };
    starts[0] = 0;
    for (int c = 0; c <= 4; c++)
        pts[n++] = v3(outer[c % 4][0], outer[c % 4][1], 0);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double x = -1.05 + i * 0.75, y = -1.05 + j * 0.75;
            const double hole[4][2] = { { x, y }, { x + 0.6, y }, { x + 0.6, y + 0.6 }, { x, y + 0.6 } };
            starts[1 + 3 * i + j] = n;
            for (int c = 0; c <= 4; c++)
                pts[n++] = v3(hole[c % 4][0], hole[c % 4][1], 0);
        }
    starts[10] = n;
    return fixture_polygon(s, pts, n, starts, 10);
}

/* A five-pointed star, concave, of one outline of 10 points, in z = 0. */
static SceneObject *star(Scene *s)
{
    Vec3 pts[11];
    for (int i = 0; i <= 10; i++) {
        double r = i % 2 ? 0.5 : 1.3, a = 2.0 * M_PI * (i % 10) / 10.0;
        pts[i] = v3(r * cos(a), r * sin(a), 0);
    }
    int starts[] = { 0, 11 };
    return fixture_polygon(s, pts, 11, starts, 1);
}

/* Rays at lattices and stars turned and moved: with and without the outline boxes,
 * the same answer, bit for bit. Returns the disagreements; counts hits and
 * misses. */
static int outline_boxes_agree(int *hits, int *misses)
{
    TestRng rng = { 0x2545f4914f6cdd1dull };
    int wrong = 0;
    for (int shape = 0; shape < 12; shape++) {
        Scene *s = fixture_scene(2);
        SceneObject *o = shape % 3 == 2 ? star(s) : lattice(s);
        Vec3 turn = v3(rng_range(&rng, -180, 180), rng_range(&rng, -180, 180), rng_range(&rng, -180, 180));
        transform_rotate(&o->transform, turn);
        double far = shape < 4 ? 0.0 : shape < 8 ? 100.0 : 1e6;
        Vec3 move = v3(rng_range(&rng, -far, far), rng_range(&rng, -far, far), rng_range(&rng, -far, far));
        transform_translate(&o->transform, move);
        World w;
        WorldError err;
        if (world_build(&w, s, &err) != 0 || w.npolygons != 1 || !w.outline_box) {
            scene_free(s);
            return -1;
        }
        const Polygon *p = &w.polygons[0];
        OutlineBox *boxes = w.outline_box;
        for (int r = 0; r < 4000; r++) {
            /* the target: a random point of the lattice's box, a vertex, or a point on an edge */
            Vec3 target;
            int k = (int)(rng_uniform(&rng) * p->npoints) % p->npoints;
            Vec3 a = w.points[p->first_point + k], b = w.points[p->first_point + (k + 1) % p->npoints];
            double kind = rng_uniform(&rng);
            if (kind < 0.4)
                target = v3(rng_range(&rng, p->bbox_min.x, p->bbox_max.x),
                            rng_range(&rng, p->bbox_min.y, p->bbox_max.y),
                            rng_range(&rng, p->bbox_min.z, p->bbox_max.z));
            else if (kind < 0.7)
                target = a;
            else
                target = v3_add(a, v3_scale(v3_sub(b, a), rng_uniform(&rng)));
            Vec3 from = v3_add(target, v3(rng_range(&rng, -5, 5), rng_range(&rng, -5, 5), rng_range(&rng, -5, 5)));
            Vec3 dir = v3_sub(target, from);
            w.outline_box = boxes;
            double fast = intersect_polygon(&w, p, from, dir);
            w.outline_box = NULL;
            double full = intersect_polygon(&w, p, from, dir);
            w.outline_box = boxes;
            if (memcmp(&fast, &full, sizeof fast) != 0)
                wrong++;
            *hits += full >= 0.0;
            *misses += full < 0.0;
        }
        world_free(&w);
        scene_free(s);
    }
    return wrong;
}

int main(void)
{
    int hits = 0, misses = 0;
    int wrong = outline_boxes_agree(&hits, &misses);
    tap_ok(wrong == 0, "outline boxes (lattices and stars): the same hits as the full crossing count (%d differ)", wrong);
    tap_ok(hits > 10000 && misses > 10000, "outline boxes: rays both hit (%d) and miss (%d) the lattices", hits,
           misses);

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
