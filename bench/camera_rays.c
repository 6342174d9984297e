/* The cost of a camera ray alone, for bench/speed.sh: the scene parsed and
 * its grid and hierarchy built as hstrace builds them, then one camera ray
 * through every pixel centre, each a nearest-hit query (trace_nearest, the
 * query camera, reflected and refracted rays use), with no shading and no
 * shadows. A render with --shadows none would count the shading too.
 *
 * Beside it, where hstrace is built with Embree, the same rays as Embree's
 * nearest-hit queries on the scene --shadows embree builds (its highest
 * build quality), in float: one ray at a time (rtcIntersect1), and in
 * coherent packets of 8 rays, 4x2 pixels each (rtcIntersect8). Embree's
 * scene leaves out no_shadow polygons and answers no nearest-hit query on
 * its user polygons (holes, concave outlines: shadow_embree.h); its hits
 * are counted apart so a difference shows.
 *
 * usage: bench/camera_rays SCENE.pov [WIDTH HEIGHT [PASSES]]
 *   (default 640 480 3). Each pass traces every pixel once, on one thread,
 *   timed on the thread's CPU clock; prints one JSON object: the rays of a
 *   pass, the median pass's nanoseconds per ray, and ray/polygon tests and
 *   hierarchy nodes per ray; Embree's medians and hits (null without
 *   Embree). Exit status 0, 1 bad usage, 2 the scene failed. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "camera.h"
#include "clock.h"
#include "config.h"
#include "datadir.h"
#include "grid.h"
#include "parser.h"
#include "shadow_embree.h"
#include "tracer.h"

#ifdef HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

#ifdef HAVE_EMBREE
/* Embree's nearest hits of every pixel's camera ray, one ray at a time. */
static uint64_t embree_single_pass(RTCScene scene, const Camera *cam, int width, int height)
{
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    uint64_t hits = 0;
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            Vec3 org, dir;
            camera_ray(cam, width, height, x, y, &org, &dir);
            struct RTCRayHit rh;
            rh.ray.org_x = (float)org.x, rh.ray.org_y = (float)org.y, rh.ray.org_z = (float)org.z;
            rh.ray.dir_x = (float)dir.x, rh.ray.dir_y = (float)dir.y, rh.ray.dir_z = (float)dir.z;
            rh.ray.tnear = 0.0f;
            rh.ray.tfar = INFINITY;
            rh.ray.time = 0.0f;
            rh.ray.mask = 0xFFFFFFFFu;
            rh.ray.id = 0;
            rh.ray.flags = 0;
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(scene, &ctx, &rh);
            hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        }
    return hits;
}

/* ... in coherent packets of 4x2 pixels (rtcIntersect8). */
static uint64_t embree_packet_pass(RTCScene scene, const Camera *cam, int width, int height)
{
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    uint64_t hits = 0;
    for (int y0 = 0; y0 < height; y0 += 2)
        for (int x0 = 0; x0 < width; x0 += 4) {
            _Alignas(32) struct RTCRayHit8 rh;
            _Alignas(32) int valid[8];
            for (int k = 0; k < 8; k++) {
                int x = x0 + k % 4, y = y0 + k / 4;
                valid[k] = x < width && y < height ? -1 : 0;
                Vec3 org = { 0, 0, 0 }, dir = { 0, 0, 1 };
                if (valid[k])
                    camera_ray(cam, width, height, x, y, &org, &dir);
                rh.ray.org_x[k] = (float)org.x, rh.ray.org_y[k] = (float)org.y, rh.ray.org_z[k] = (float)org.z;
                rh.ray.dir_x[k] = (float)dir.x, rh.ray.dir_y[k] = (float)dir.y, rh.ray.dir_z[k] = (float)dir.z;
                rh.ray.tnear[k] = 0.0f;
                rh.ray.tfar[k] = INFINITY;
                rh.ray.time[k] = 0.0f;
                rh.ray.mask[k] = 0xFFFFFFFFu;
                rh.ray.id[k] = (unsigned)k;
                rh.ray.flags[k] = 0;
                rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
                rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
            }
            rtcIntersect8(valid, scene, &ctx, &rh);
            for (int k = 0; k < 8; k++)
                hits += valid[k] && rh.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID;
        }
    return hits;
}
#endif

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
    /* Embree's: "null" without it */
    char embree_single[32] = "null", embree_packet[32] = "null", embree_hits[32] = "null";
#ifdef HAVE_EMBREE
    char err[256];
    EmbreeScene *es = shadow_embree_build(&w, 1, err, (int)sizeof err);
    if (!es) {
        fprintf(stderr, "%s: %s\n", argv[1], err);
        return 2;
    }
    RTCScene rtc = shadow_embree_rtc_scene(es);
    double *single = malloc(sizeof(double) * (size_t)passes), *packet = malloc(sizeof(double) * (size_t)passes);
    uint64_t ehits = 0, phits = 0;
    for (int p = 0; p < passes; p++) {
        double t0 = clock_thread_cpu();
        ehits = embree_single_pass(rtc, &w.camera, width, height);
        single[p] = clock_thread_cpu() - t0;
        t0 = clock_thread_cpu();
        phits = embree_packet_pass(rtc, &w.camera, width, height);
        packet[p] = clock_thread_cpu() - t0;
    }
    qsort(single, (size_t)passes, sizeof *single, cmp_double);
    qsort(packet, (size_t)passes, sizeof *packet, cmp_double);
    snprintf(embree_single, sizeof embree_single, "%.2f", single[passes / 2] / rays * 1e9);
    snprintf(embree_packet, sizeof embree_packet, "%.2f", packet[passes / 2] / rays * 1e9);
    snprintf(embree_hits, sizeof embree_hits, "%llu", (unsigned long long)ehits);
    if (phits != ehits)
        fprintf(stderr, "%s: Embree's packets hit %llu times, its single rays %llu\n", argv[1],
                (unsigned long long)phits, (unsigned long long)ehits);
    free(single);
    free(packet);
    shadow_embree_free(es);
#endif
    printf("{\"scene\": \"%s\", \"width\": %d, \"height\": %d, \"passes\": %d, \"polygons\": %d, \"rays\": %.0f, "
           "\"hits\": %llu, \"ns_per_ray\": %.2f, \"polygon_tests_per_ray\": %.3f, \"nodes_per_ray\": %.3f, "
           "\"embree_ns_per_ray\": %s, \"embree_packet_ns_per_ray\": %s, \"embree_hits\": %s}\n",
           argv[1], width, height, passes, w.npolygons, rays, (unsigned long long)hits,
           seconds[passes / 2] / rays * 1e9, (double)(t.stats.polygon_tests - before.polygon_tests) / all,
           (double)(t.stats.nodes_visited - before.nodes_visited) / all, embree_single, embree_packet, embree_hits);
    free(seconds);
    tracer_free(&t);
    bvh_free(&b);
    grid_free(&g);
    world_free(&w);
    scene_free(scene);
    return 0;
}
