/* libFuzzer entry point: a scene, parsed, and when it parses, rendered as
 * the command line renders it (world, grid, hierarchy, shadow volumes,
 * cost model, hybrid shadow testing) at 4x3 pixels on one thread, so that hostile
 * geometry reaches the engine too.
 *
 * The parse has small budgets (64 MiB, 50000 tokens read again, 5000
 * macro calls) and only scenes of up to 2000 polygons are rendered, so that
 * each input ends in milliseconds: the budgets' code is what is
 * exercised, not their size. #fopen may not write (the fuzzer
 * would write files named by its inputs), and #include finds hstrace's own
 * colors.inc beside the scene's folder. Built and run by tests/fuzz/run.sh
 * (`make fuzz`). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "bvh.h"
#include "cost_model.h"
#include "grid.h"
#include "light_buffer.h"
#include "parser.h"
#include "render.h"
#include "shadow.h"
#include "shadow_registry.h"
#include "shadow_volumes.h"
#include "volume_plan.h"
#include "world.h"

#ifndef FUZZ_INCLUDE_DIR
#define FUZZ_INCLUDE_DIR "data/include"
#endif

/* Each render's time, as --max-render-seconds bounds it: a scene whose one
 * colour takes hours (a fractal pattern of 2^31 iterations, averages of
 * averages nested 40 deep: tests/hostile) stops there, as hstrace stops it. */
#define FUZZ_RENDER_SECONDS 1.0

static void render_tiny(const Scene *scene)
{
    /* The world held to the parse's own memory budget, as hstrace holds it
     * to --max-memory: a union of copies doubled twenty times (150 bytes of
     * a seed, tests/hostile/union-doublings.pov) is refused from the
     * scene's tree before anything is made, not built for 15 s. */
    World world;
    WorldError werr;
    WorldLimits limits = { (size_t)64 << 20, 0.0, 0.0, 0 }; /* flattened: shadow volumes below */
    if (world_build_limited(&world, scene, 1, &limits, &werr))
        return;
    Vec3 extra[1 + 8 * 16];
    int nextra = grid_extra_points(&world, extra, (int)(sizeof extra / sizeof extra[0]));
    Grid grid;
    if (world.npolygons > 2000 || grid_build(&grid, &world, NULL, extra, nextra)) {
        world_free(&world);
        return;
    }
    Bvh bvh;
    if (bvh_build(&bvh, &world, 1)) {
        grid_free(&grid);
        world_free(&world);
        return;
    }
    ShadowVolumes volumes;
    memset(&volumes, 0, sizeof volumes);
    CostModel cost;
    memset(&cost, 0, sizeof cost);
    const Vec3 *eye = world.camera.kind == CAMERA_ORTHOGRAPHIC ? NULL : &world.camera.location;
    if (shadow_volumes_build(&volumes, &world, &grid, eye, 1, NULL) == 0) {
        (void)cost_model_calibrate(&cost, &world, &grid, &bvh, &volumes, 4, 3);
        RenderOptions ropt;
        memset(&ropt, 0, sizeof ropt);
        ropt.width = 4;
        ropt.height = 3;
        ropt.threads = 1;
        Quality q = { 1, 1, 1, 0, 1, 1, 1 }; /* +Q9, normals and area lights too */
        ropt.quality = q;
        /* hst with every light's volumes, as --volumes always prepares it
         * but without the plan's timings (which would make runs differ). */
        ShadowPrepared prepared;
        memset(&prepared, 0, sizeof prepared);
        prepared.decider = shadow_method_find("hst");
        prepared.volumes = &volumes;
        prepared.cost = &cost;
        prepared.nth = cost.nth;
        ropt.shadows = &prepared;
        ropt.max_tree_rays = RENDER_DEFAULT_MAX_TREE_RAYS; /* a tree of 2^256 rays ends, as in hstrace */
        ropt.max_seconds = FUZZ_RENDER_SECONDS;
        ropt.bvh = &bvh;
        ropt.pixel_coherence = 1;
        Image img;
        RenderStats stats;
        if (render_image(&world, &grid, &ropt, &img, &stats) == 0)
            image_free(&img);
        shadow_volumes_free(&volumes);
    }
    /* The light buffers (shadow_light_buffer.c), every cell split down to
     * the last level so that the children's lists are built too. */
    LightBuffers buffers;
    if (light_buffers_init(&buffers, &world, &bvh, grid_tolerance(&grid), (size_t)16 << 20) == 0) {
        buffers.split_at = 0;
        RenderOptions ropt;
        memset(&ropt, 0, sizeof ropt);
        ropt.width = 4;
        ropt.height = 3;
        ropt.threads = 1;
        Quality q = { 1, 1, 1, 0, 1, 1, 1 };
        ropt.quality = q;
        ShadowPrepared prepared;
        memset(&prepared, 0, sizeof prepared);
        prepared.decider = shadow_method_find("light-buffer");
        prepared.light_buffers = &buffers;
        prepared.cost = &cost;
        ropt.shadows = &prepared;
        ropt.max_tree_rays = RENDER_DEFAULT_MAX_TREE_RAYS;
        ropt.max_seconds = FUZZ_RENDER_SECONDS;
        ropt.bvh = &bvh;
        Image img;
        RenderStats stats;
        if (render_image(&world, &grid, &ropt, &img, &stats) == 0)
            image_free(&img);
    }
    light_buffers_free(&buffers);
    /* The cost model's plan of which volumes pay: its pilot, its estimate
     * on a sample of the polygons, and whatever it builds. */
    VolumePlan plan;
    VolumePlanOptions po = { VOLUMES_AUTO, 4, 3, 1, 0, { NTH_AUTO, 0.0 } };
    (void)volume_plan_build(&plan, &volumes, &cost, &world, &grid, &bvh, eye, &po);
    volume_plan_free(&plan);
    shadow_volumes_free(&volumes);
    bvh_free(&bvh);
    grid_free(&grid);
    world_free(&world);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    static const char *const dirs[] = { FUZZ_INCLUDE_DIR };
    ParseOptions opts;
    memset(&opts, 0, sizeof opts);
    opts.include_dirs = dirs;
    opts.ninclude_dirs = 1;
    opts.image_width = 4;
    opts.image_height = 3;
    opts.max_memory = (size_t)64 << 20;
    opts.max_repeated_tokens = 50000;
    opts.max_macro_calls = 5000;
    opts.max_loop_iterations = 20000;
    opts.forbid_writes = 1;
    ParseError err;
    Scene *scene = parse_scene_string("fuzz.pov", text, &opts, &err);
    if (scene) {
        render_tiny(scene);
        scene_free(scene);
    } else if (err.line < 0 || err.column < 0 || (!err.file[0] && !err.message[0])) {
        abort(); /* every error names where it is and what */
    }
    free(text);
    return 0;
}
