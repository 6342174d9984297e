/* The cost of a camera ray alone, for bench/speed.sh: the scene parsed and
 * its grid and hierarchy built as hstrace builds them, then one camera ray
 * through every pixel centre, each a nearest-hit query (trace_nearest, the
 * query camera, reflected and refracted rays use), with no shading and no
 * shadows. A render with --shadows none would count the shading too.
 *
 * usage: bench/camera_rays SCENE.pov [WIDTH HEIGHT [PASSES]]
 *   (default 640 480 3). Each pass traces every pixel once, on one thread,
 *   timed on the thread's CPU clock; prints one JSON object: the rays of a
 *   pass, the median pass's nanoseconds per ray, and ray/polygon tests and
 *   hierarchy nodes per ray. Exit status 0, 1 bad usage, 2 the scene failed. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "camera.h"
#include "clock.h"
#include "datadir.h"
#include "grid.h"
#include "parser.h"
#include "tracer.h"

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

int main(int argc, char **argv)
{
    if (argc != 2 && argc != 4 && argc != 5) {
        fprintf(stderr, "usage: %s SCENE.pov [WIDTH HEIGHT [PASSES]]\n", argv[0]);
        return 1;
    }
    int width = argc > 2 ? atoi(argv[2]) : 640, height = argc > 2 ? atoi(argv[3]) : 480;
    int passes = argc > 4 ? atoi(argv[4]) : 3;
    if (width < 1 || height < 1 || passes < 1 || passes > 100) {
        fprintf(stderr, "%s: bad size or pass count\n", argv[0]);
        return 1;
    }
    const char *dirs[2];
    int ndirs = 0;
    char own[4096];
    const char *povray = povray_include_folder();
    if (povray)
        dirs[ndirs++] = povray;
    if (data_folder("include", own, (int)sizeof own))
        dirs[ndirs++] = own;
    ParseOptions popt;
    memset(&popt, 0, sizeof popt);
    popt.include_dirs = dirs;
    popt.ninclude_dirs = ndirs;
    popt.image_width = width;
    popt.image_height = height;
    ParseError perr;
    Scene *scene = parse_scene_file(argv[1], &popt, &perr);
    if (!scene) {
        fprintf(stderr, "%s:%d:%d: %s\n", perr.file, perr.line, perr.column, perr.message);
        return 2;
    }
    World w;
    WorldError werr;
    Grid g;
    Bvh b;
    Tracer t;
    Vec3 extra[1 + 8 * 16];
    if (world_build(&w, scene, &werr)) {
        fprintf(stderr, "%s: %s\n", argv[1], werr.message);
        return 2;
    }
    int nextra = grid_extra_points(&w, extra, (int)(sizeof extra / sizeof extra[0]));
    if (grid_build(&g, &w, NULL, extra, nextra) || bvh_build(&b, &w, 1) || tracer_init(&t, &w, &g)) {
        fprintf(stderr, "%s: out of memory\n", argv[1]);
        return 2;
    }
    tracer_use_bvh(&t, &b);
    double *seconds = malloc(sizeof(double) * (size_t)passes);
    uint64_t hits = 0;
    RayCounters before = t.stats;
    for (int p = 0; p < passes; p++) {
        hits = 0;
        double t0 = clock_thread_cpu();
        for (int y = 0; y < height; y++)
            for (int x = 0; x < width; x++) {
                Vec3 org, dir;
                camera_ray(&w.camera, width, height, x, y, &org, &dir);
                Hit from = { HIT_NONE, -1, 0.0, org, -1, 0 }, hit;
                t.hide = HIDE_NO_IMAGE;
                hits += (uint64_t)trace_nearest(&t, org, dir, HUGE_VAL, &from, &hit);
            }
        seconds[p] = clock_thread_cpu() - t0;
    }
    qsort(seconds, (size_t)passes, sizeof *seconds, cmp_double);
    double rays = (double)width * height, all = rays * passes;
    printf("{\"scene\": \"%s\", \"width\": %d, \"height\": %d, \"passes\": %d, \"polygons\": %d, \"rays\": %.0f, "
           "\"hits\": %llu, \"ns_per_ray\": %.2f, \"polygon_tests_per_ray\": %.3f, \"nodes_per_ray\": %.3f}\n",
           argv[1], width, height, passes, w.npolygons, rays, (unsigned long long)hits,
           seconds[passes / 2] / rays * 1e9, (double)(t.stats.polygon_tests - before.polygon_tests) / all,
           (double)(t.stats.nodes_visited - before.nodes_visited) / all);
    free(seconds);
    tracer_free(&t);
    bvh_free(&b);
    grid_free(&g);
    world_free(&w);
    scene_free(scene);
    return 0;
}
