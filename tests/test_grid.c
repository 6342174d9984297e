/* Grid registration and the 3DDDA walk, checked against brute force:
 * every polygon is registered in exactly the cells it overlaps, and the
 * nearest hit found by walking the grid is the nearest hit of all. */
#include <math.h>
#include <stdlib.h>

#include "fixtures.h"
#include "grid.h"
#include "intersect.h"
#include "tap.h"
#include "tracer.h"

static int registered(const Grid *g, int cell, int poly)
{
    for (uint32_t k = g->cell_start[cell]; k < g->cell_start[cell + 1]; k++)
        if ((int)g->items[k] == poly)
            return 1;
    return 0;
}

int main(void)
{
    TestRng rng = { 0x9E3779B97F4A7C15ULL };
    Scene *s = fixture_scene(400);
    for (int i = 0; i < 300; i++) {
        Vec3 c = v3(rng_range(&rng, -10, 10), rng_range(&rng, -10, 10), rng_range(&rng, -10, 10));
        double r = rng_range(&rng, 0.2, 3.0);
        fixture_triangle(s, v3_add(c, v3(rng_range(&rng, -r, r), rng_range(&rng, -r, r), rng_range(&rng, -r, r))),
                         v3_add(c, v3(rng_range(&rng, -r, r), rng_range(&rng, -r, r), rng_range(&rng, -r, r))),
                         v3_add(c, v3(rng_range(&rng, -r, r), rng_range(&rng, -r, r), rng_range(&rng, -r, r))));
    }
    /* Axis-aligned quads lying exactly on cell boundaries are the hard case
     * for registration. */
    Vec3 quad[] = { { -10, -10, 0 }, { 10, -10, 0 }, { 10, 10, 0 }, { -10, 10, 0 }, { -10, -10, 0 } };
    int starts[] = { 0, 5 };
    fixture_polygon(s, quad, 5, starts, 1);

    World w;
    WorldError err;
    tap_ok(world_build(&w, s, &err) == 0, "world builds");
    Grid g;
    int res[3] = { 8, 8, 8 };
    tap_ok(grid_build(&g, &w, res, NULL, 0) == 0, "grid builds");

    /* Registration is exact: registered <=> the polygon overlaps the cell. */
    int wrong = 0, sampled_missing = 0;
    for (int z = 0; z < g.n[2]; z++)
        for (int y = 0; y < g.n[1]; y++)
            for (int x = 0; x < g.n[0]; x++) {
                int c[3] = { x, y, z };
                int cell = grid_cell_index(&g, c);
                Vec3 lo = v3(g.min.x + x * g.cell_size.x, g.min.y + y * g.cell_size.y, g.min.z + z * g.cell_size.z);
                Vec3 hi = v3_add(lo, g.cell_size);
                Vec3 eps = v3_scale(g.cell_size, 1e-9);
                for (int p = 0; p < w.npolygons; p++)
                    if (registered(&g, cell, p) != polygon_overlaps_box(&w, &w.polygons[p], v3_sub(lo, eps), v3_add(hi, eps)))
                        wrong++;
            }
    tap_ok(wrong == 0, "registration matches the exact overlap test (%d mismatches)", wrong);
    /* Independent check: random points on each triangle must be in a cell that lists it. */
    for (int p = 0; p < w.npolygons; p++) {
        const Polygon *poly = &w.polygons[p];
        if (poly->first_outline >= 0)
            continue;
        const Vec3 *v = &w.points[poly->first_point];
        for (int k = 0; k < 50; k++) {
            double a = rng_uniform(&rng), b = rng_uniform(&rng);
            if (a + b > 1) { a = 1 - a; b = 1 - b; }
            Vec3 q = v3_add(v[0], v3_add(v3_scale(v3_sub(v[1], v[0]), a), v3_scale(v3_sub(v[2], v[0]), b)));
            int c[3];
            for (int ax = 0; ax < 3; ax++) {
                int ci = (int)floor((v3_comp(q, ax) - v3_comp(g.min, ax)) / v3_comp(g.cell_size, ax));
                c[ax] = ci < 0 ? 0 : ci >= g.n[ax] ? g.n[ax] - 1 : ci;
            }
            if (!registered(&g, grid_cell_index(&g, c), p))
                sampled_missing++;
        }
    }
    tap_ok(sampled_missing == 0, "points sampled on triangles lie in cells that list them (%d missing)", sampled_missing);

    /* The walk finds the same nearest hit as testing every polygon. */
    Tracer tracer;
    tap_ok(tracer_init(&tracer, &w, &g) == 0, "tracer");
    int mismatches = 0, hits = 0;
    const int nrays = 20000;
    for (int i = 0; i < nrays; i++) {
        Vec3 o = v3(rng_range(&rng, -15, 15), rng_range(&rng, -15, 15), rng_range(&rng, -15, 15));
        Vec3 d = v3_normalize(v3(rng_range(&rng, -1, 1), rng_range(&rng, -1, 1), rng_range(&rng, -1, 1)));
        /* Some rays run exactly along cell boundaries and axes. */
        if (i % 10 == 0) { o.z = 0.0; d = v3_normalize(v3(d.x, d.y, 0)); }
        if (i % 10 == 1) { d = v3(0, 0, d.z > 0 ? 1 : -1); }
        Hit h;
        int found = trace_nearest(&tracer, o, d, HUGE_VAL, NULL, &h);
        double best = HUGE_VAL;
        int best_i = -1;
        double tmin = trace_min_distance(o);
        for (int p = 0; p < w.npolygons; p++) {
            double t = intersect_polygon(&w, &w.polygons[p], o, d);
            if (t > tmin && t < best) { best = t; best_i = p; }
        }
        hits += best_i >= 0;
        if ((best_i >= 0) != found || (found && fabs(h.t - best) > 1e-9 * (1 + best)))
            mismatches++;
    }
    tap_ok(mismatches == 0, "3DDDA nearest hit equals brute force on %d random rays (%d hits, %d mismatches)", nrays,
           hits, mismatches);
    tracer_free(&tracer);

    /* Resolution heuristic: about two cells per polygon, at least one per axis. */
    int r[3];
    grid_choose_resolution(&w, g.min, g.max, r);
    double cells = (double)r[0] * r[1] * r[2];
    tap_ok(cells >= 4.0 * w.npolygons && cells <= 32.0 * w.npolygons, "heuristic gives %dx%dx%d cells for %d polygons", r[0],
           r[1], r[2], w.npolygons);

    /* Points anywhere have a cell: the nearest edge cell beyond the box
     * (a plane's hit near the horizon lies 1e16 away), the first for NaN. */
    int far_ok = 1;
    for (int a = 0; a < 3; a++) {
        far_ok &= grid_cell_coord(&g, -3.57e16, a) == 0 && grid_cell_coord(&g, 3.57e16, a) == g.n[a] - 1;
        far_ok &= grid_cell_coord(&g, -HUGE_VAL, a) == 0 && grid_cell_coord(&g, HUGE_VAL, a) == g.n[a] - 1;
        far_ok &= grid_cell_coord(&g, NAN, a) == 0 && grid_cell_coord(&g, 1e308, a) == g.n[a] - 1;
    }
    tap_ok(far_ok, "cell coordinates of points at +-3.57e16, +-1e308, +-inf and NaN are the edge cells");
    /* A ray that goes nowhere has no walk: NaN, or a direction that
     * underflowed to zero (toward a light 1e308 away), with no end. */
    GridWalk gw;
    tap_ok(!grid_walk_begin(&g, v3(0, 0, 0), v3(0, 0, 0), 0.0, HUGE_VAL, &gw), "no walk for a zero direction");
    tap_ok(!grid_walk_begin(&g, v3(0, 0, 0), v3(NAN, 0, 1), 0.0, HUGE_VAL, &gw) &&
               !grid_walk_begin(&g, v3(NAN, 0, 0), v3(0, 0, 1), 0.0, HUGE_VAL, &gw) &&
               !grid_walk_begin(&g, v3(0, 0, 0), v3(0, 0, 1), 0.0, NAN, &gw),
           "no walk for a NaN origin, direction or end");
    int steps = 0;
    if (grid_walk_begin(&g, v3(-1e300, 0.5, 0.5), v3(1, 0, 0), 0.0, HUGE_VAL, &gw))
        do
            steps++;
        while (grid_walk_next(&g, &gw) && steps < 1000);
    /* (at t = 1e300 the cells' crossings round together: fewer cells, never more) */
    tap_ok(steps >= 1 && steps <= g.n[0], "a ray from 1e300 away ends its walk (%d cells, %d across)", steps, g.n[0]);

    grid_free(&g);
    world_free(&w);
    scene_free(s);
    return tap_done();
}
