/* hstrace: scene file -> description -> polygons and grid -> rays -> image;
 * `hstrace compare` compares images (compare.h); `hstrace vs-povray` renders
 * a scene with POV-Ray and every shadow method and compares (vs_povray.h);
 * `hstrace stitch` joins partial renders into the whole image (stitch.h). */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "config.h"
#include "aov.h"
#include "clock.h"
#include "colour.h"
#include "compare.h"
#include "datadir.h"
#include "grid.h"
#include "image.h"
#include "options.h"
#include "parser.h"
#include "provenance.h"
#include "render.h"
#include "cost_model.h"
#include "area_light.h"
#include "shadow.h"
#include "shadow_embree.h"
#include "shadow_volumes.h"
#include "stats.h"
#include "stitch.h"
#include "volume_plan.h"
#include "animation.h"
#include "mpi_job.h"
#include "vs_povray.h"
#include "world.h"

static Quality quality_from_level(int q)
{
    /* POV-Ray's QUALITY_n flags (povray.h): shadows from 4, refraction
     * from 6, reflection and normals from 8, fog at 9; 0-1 show the bare
     * pigment colour. */
    Quality r = { q >= 4, q >= 6, q >= 8, q <= 1, q >= 9, q >= 8, q >= 5 };
    return r;
}

/* Default output: the scene's base name with .png, in the current folder,
 * as POV-Ray does. */
static char *default_output(const char *scene, const char *ext)
{
    const char *base = strrchr(scene, '/');
    base = base ? base + 1 : scene;
    size_t n = strlen(base);
    const char *dot = strrchr(base, '.');
    if (dot && dot != base)
        n = (size_t)(dot - base);
    size_t e = strlen(ext);
    char *out = malloc(n + e + 1);
    if (out) {
        memcpy(out, base, n);
        memcpy(out + n, ext, e + 1);
    }
    return out;
}

/* What rank 0's volume plan chose, for the other ranks of a distributed
 * render: the plan's choices rest on timings, which differ between ranks,
 * and every rank must decide (and count, for the analysis channels) alike. */
typedef struct {
    int have_volumes;
    double nth;
    CostModel cost;
} VolumeChoice;

/* Rank 0 sends, the others rebuild: the lights built, then the same ones
 * dropped, with the same planes, cost model and N_th. Returns 0, or -1 when
 * out of memory (on this rank). */
static int share_volume_choices(ShadowVolumes *sv, CostModel *cost, double *nth, int *have_volumes, const World *w,
                                Grid *g, const Vec3 *eye, int threads, int precision)
{
    VolumeChoice c;
    memset(&c, 0, sizeof c);
    int n = w->nlights;
    int8_t *flags = calloc((size_t)(2 * n + 1), 1); /* per light: built, then dropped */
    if (!flags)
        return -1;
    if (mpi_job_rank() == 0) {
        c.have_volumes = *have_volumes;
        c.nth = *nth;
        c.cost = *cost;
        for (int li = 0; *have_volumes && li < n; li++) {
            flags[li] = !sv->light[li].not_wanted;
            flags[n + li] = (int8_t)sv->light[li].dropped;
        }
    }
    mpi_job_broadcast(&c, sizeof c);
    mpi_job_broadcast(flags, (size_t)(2 * n));
    int status = 0;
    if (mpi_job_rank() != 0) {
        *have_volumes = c.have_volumes;
        *nth = c.nth;
        *cost = c.cost;
        if (c.have_volumes) {
            /* the registrations pixel coherence reads (rank 0's plan made its own) */
            status = grid_register(g, w, threads) || shadow_volumes_build(sv, w, g, eye, threads, flags) ||
                     shadow_volumes_set_precision(sv, (PlanePrecision)precision);
            for (int li = 0; status == 0 && li < n; li++)
                if (flags[n + li])
                    shadow_volumes_drop_light(sv, li);
        }
    }
    free(flags);
    return status ? -1 : 0;
}

/* One frame (or the still): parse, build, render and write `output`. wall0:
 * when the frame's work began. distributed: the frame's tiles are spread
 * over the MPI job's ranks (mpi_job.h), rank 0 writing. Returns the exit
 * status. */
static int render_frame(int argc, char **argv, const Options *o, const ParseAnimation *anim, const char *output,
                        const char *stats_json, double wall0, int distributed)
{
    /* Everything the render owns, released once at the end (every release
     * is safe on what was never made). */
    int status = EXIT_OK;
    char err[1024];
    ParseDeclare *declares = NULL;
    ColourDisplay *colour = NULL;
    Scene *scene = NULL;
    World world;
    Grid grid;
    Bvh bvh;
    ShadowVolumes volumes;
    VolumePlan plan;
    EmbreeScene *embree = NULL;
    CostModel cost;
    AovImage aov;
    Provenance prov;
    SceneHash scene_hash = { 0 };
    RenderStats *per_rank = NULL;
    MpiTileWaits *waits = NULL;
    long *requests = NULL;
    double *wait_seconds = NULL;
    double *tile_seconds = NULL;
    memset(&world, 0, sizeof world);
    memset(&grid, 0, sizeof grid);
    memset(&bvh, 0, sizeof bvh);
    memset(&volumes, 0, sizeof volumes);
    memset(&plan, 0, sizeof plan);
    memset(&cost, 0, sizeof cost);
    memset(&aov, 0, sizeof aov);
    memset(&prov, 0, sizeof prov);

    if (image_format_from_path(output) == IMAGE_FORMAT_UNKNOWN) {
        fprintf(stderr, "hstrace: '%s': unknown image format (use .exr, .png, .ppm, .tga, .bmp, .jpg or .hdr)\n", output);
        status = EXIT_USAGE;
        goto done;
    }
    if (o->aov && image_format_from_path(output) != IMAGE_FORMAT_EXR) {
        fprintf(stderr, "hstrace: --aov: '%s': analysis channels need an EXR output (-o FILE.exr)\n", output);
        status = EXIT_USAGE;
        goto done;
    }

    /* Colour management: OpenColorIO when an option or $OCIO asks for it,
     * else POV-Ray's own encoding. Opened before any work, so that a bad
     * config or name costs nothing. */
    ColourRequest creq = { o->ocio_config, o->display, o->view, o->colorspace };
    if (colour_requested(&creq)) {
        ColourStatus cs = colour_display_open(&creq, &colour, err, sizeof err);
        int from_env_only = !o->ocio_config && !o->display && !o->view && !o->colorspace;
        if (cs == COLOUR_ERR_UNAVAILABLE && from_env_only) {
            /* $OCIO is set for every program of a user; one built without
             * the library goes on as if it were not. */
            if (o->warning_console)
                fprintf(stderr, "hstrace: warning: $OCIO ignored: %s\n", err);
        } else if (cs != COLOUR_OK) {
            fprintf(stderr, "hstrace: %s\n", err);
            status = cs == COLOUR_ERR_CONFIG ? EXIT_IO : EXIT_USAGE;
            goto done;
        }
    }

    /* Include and image search: the current folder (POV-Ray looks there
     * first: exporters' scenes count on it), the including file's folder
     * (the parser's own rule), the user's folders, POV-Ray's when
     * installed, and last hstrace's own (its colors.inc for systems without
     * POV-Ray's). */
    const char *dirs[MAX_INCLUDE_PATHS + 2];
    int ndirs = 0;
    for (int i = 0; i < o->ninclude_paths; i++)
        dirs[ndirs++] = o->include_paths[i];
    const char *povray_dir = povray_include_folder();
    if (povray_dir)
        dirs[ndirs++] = povray_dir;
    char own_include[PATH_MAX];
    if (data_folder("include", own_include, (int)sizeof own_include))
        dirs[ndirs++] = own_include;
    ParseOptions popt;
    memset(&popt, 0, sizeof popt);
    popt.first_dir = ".";
    popt.include_dirs = dirs;
    popt.ninclude_dirs = ndirs;
    popt.image_width = o->width;
    popt.image_height = o->height;
    popt.strict = o->strict;
    popt.load_image = image_read_for_scene;
    popt.quiet_debug = !o->debug_console;
    popt.quiet_warnings = !o->warning_console;
    popt.max_memory = o->max_memory;
    popt.max_parse_seconds = o->max_parse_seconds;
    popt.max_loop_iterations = o->max_loop_iterations;
    popt.max_macro_calls = o->max_macro_calls;
    popt.max_repeated_tokens = o->max_repeated_tokens;
    /* Declare=NAME=VALUE: the options' list has the parser's shape. */
    declares = o->ndeclares ? calloc((size_t)o->ndeclares, sizeof *declares) : NULL;
    for (int i = 0; declares && i < o->ndeclares; i++)
        declares[i] = (ParseDeclare){ o->declares[i].name, o->declares[i].number, o->declares[i].string };
    if (o->ndeclares && !declares) {
        fprintf(stderr, "hstrace: out of memory\n");
        status = EXIT_IO;
        goto done;
    }
    popt.declares = declares;
    popt.ndeclares = o->ndeclares;
    popt.animation = anim;
    /* Each rank takes its share of this machine's cores. */
    int threads = o->threads > 0 ? o->threads : render_default_threads();
    if (o->threads <= 0 && mpi_job_size() > 1)
        threads = threads / mpi_job_local_size() > 1 ? threads / mpi_job_local_size() : 1;
    popt.threads = threads;

    StatsReport report;
    memset(&report, 0, sizeof report);
    report.scene = o->scene;
    report.shadow_method = o->shadows;
    report.width = o->width;
    report.height = o->height;

    /* The EXR header's hash of the scene file, beside the parse. */
    int spare_core = threads > 1;
    scene_hash_start(&scene_hash, o->scene, spare_core && image_format_from_path(output) == IMAGE_FORMAT_EXR);
    double t = clock_wall();
    ParseError perr;
    scene = parse_scene_file(o->scene, &popt, &perr);
    if (!scene) {
        if (perr.line > 0)
            fprintf(stderr, "%s:%d:%d: %s\n", perr.file, perr.line, perr.column, perr.message);
        else
            fprintf(stderr, "%s: %s\n", perr.file[0] ? perr.file : o->scene, perr.message);
        fputs(perr.notes, stderr);
        status = perr.is_io ? EXIT_IO : EXIT_SCENE;
        goto done;
    }
    report.parse_seconds = clock_wall() - t;
    report.napproximations = scene->napproximations;
    report.approximations = scene->approximations;
    /* Like POV-Ray's warnings: the image is not what POV-Ray would make. */
    for (int i = 0; o->warning_console && i < scene->napproximations; i++) {
        const SceneApproximation *a = &scene->approximations[i];
        fprintf(stderr, "%s:%d:%d: warning: %s approximated: %s (%d place%s; --strict refuses it)\n", a->first.file,
                a->first.line, a->first.column, a->what, approx_kind_effect(a->kind), a->count,
                a->count == 1 ? "" : "s");
    }

    double parse_start = t;
    t = clock_wall();
    double working_gamma = scene_working_gamma(scene);
    WorldError werr;
    /* The world's build is held to the parse's budgets: the memory (its
     * own, counted before anything is made) and the time (the parse's and
     * the build's together). */
    WorldLimits wlim = { o->max_memory ? o->max_memory : parse_default_max_memory(),
                         o->max_parse_seconds > 0.0 ? parse_start + o->max_parse_seconds : 0.0,
                         o->max_parse_seconds };
    if (world_build_limited(&world, scene, threads, &wlim, &werr)) {
        if (werr.pos.file && werr.pos.line > 0)
            fprintf(stderr, "%s:%d:%d: %s\n", werr.pos.file, werr.pos.line, werr.pos.column, werr.message);
        else
            fprintf(stderr, "hstrace: %s\n", werr.message);
        status = werr.over_budget ? EXIT_SCENE : EXIT_IO;
        goto done;
    }
    world.alpha_background = o->output_alpha;
    /* The world has its own copy of the meshes now: their lists go before
     * the hierarchy's build, where the memory peaks. */
    scene_release_mesh_lists(scene);
    report.world_seconds = clock_wall() - t;
    /* The grid box holds the camera (depth counts start there) and the part
     * of every infinite plane under the geometry, where shadows fall. */
    Vec3 extra[1 + 8 * 16];
    int nextra = grid_extra_points(&world, extra, (int)(sizeof extra / sizeof extra[0]));
    /* The polygons are registered in its cells only if shadow volumes are
     * built (volume_plan_build): every other query goes through the hierarchy. */
    grid_build_box(&grid, &world, o->grid[0] ? o->grid : NULL, extra, nextra);
    grid_set_tolerance(&grid, o->tolerance);
    double t_hierarchy = clock_wall();
    int bvh_failed = bvh_build(&bvh, &world, threads);
    report.hierarchy_seconds = clock_wall() - t_hierarchy;
    if (bvh_failed) {
        fprintf(stderr, "hstrace: out of memory while building the hierarchy\n");
        status = EXIT_IO;
        goto done;
    }
    const ShadowMethod *method = shadow_method_find(o->shadows);
    int have_volumes = 0;
    /* N_th as the render will use it (auto: measured with the volumes). */
    double nth = o->nth == NTH_PER_POINT ? -1.0 : o->nth == NTH_AUTO ? 0.0 : o->nth;
    const Vec3 *plan_eye = world.camera.kind == CAMERA_ORTHOGRAPHIC ? NULL : &world.camera.location;
    if (method->uses_volumes && o->quality >= 4 && (!distributed || mpi_job_rank() == 0)) {
        /* hst builds only the volumes that pay (volume_plan.h); the pure
         * volume method is the paper's baseline and builds them all. */
        VolumePlanOptions po;
        po.mode = method->test == shadow_hst_test && !o->volumes_always ? VOLUMES_AUTO : VOLUMES_ALWAYS;
        po.width = o->width;
        po.height = o->height;
        po.threads = threads;
        po.precision = o->plane_precision;
        po.nth = o->nth == NTH_PER_POINT ? VOLUME_PLAN_NTH_PER_POINT : o->nth == NTH_AUTO ? VOLUME_PLAN_NTH_AUTO : o->nth;
        double t_plan = clock_wall();
        int plan_failed = volume_plan_build(&plan, &volumes, &cost, &world, &grid, &bvh, plan_eye, &po);
        report.plan_seconds = clock_wall() - t_plan;
        if (plan_failed) {
            fprintf(stderr, "hstrace: out of memory while building shadow volumes\n");
            status = EXIT_IO;
            goto done;
        }
        report.plan = &plan;
        report.volumes_seconds = plan.build_seconds;
        have_volumes = volumes.light != NULL;
        if (have_volumes) {
            report.volumes = &volumes;
            report.cost = &cost;
            if (o->nth == NTH_AUTO)
                nth = cost.nth_ray;
        }
    }
    if (distributed && method->uses_volumes && o->quality >= 4) {
        if (share_volume_choices(&volumes, &cost, &nth, &have_volumes, &world, &grid, plan_eye, threads,
                                 o->plane_precision)) {
            fprintf(stderr, "hstrace: rank %d: out of memory while building shadow volumes\n", mpi_job_rank());
            mpi_job_abort(EXIT_IO);
            status = EXIT_IO;
            goto done;
        }
        if (have_volumes) {
            report.volumes = &volumes;
            report.cost = &cost;
        }
    }
    if (method->test == shadow_embree_test && o->quality >= 4) {
        embree = shadow_embree_build(&world, threads, err, sizeof err);
        if (!embree) {
            fprintf(stderr, "hstrace: %s\n", err);
            status = EXIT_IO;
            goto done;
        }
        report.embree = embree;
    }
    report.preprocess_seconds = clock_wall() - t;
    memcpy(report.grid, grid.n, sizeof report.grid);
    report.grid_registrations = grid.nitems;
    report.grid_registered = grid_registered(&grid);
    report.npolygons = world.npolygons;
    report.ndegenerate = world.ndegenerate;
    report.nplanes = world.nplanes;
    report.nlights = world.nlights;

    RenderOptions ropt;
    memset(&ropt, 0, sizeof ropt);
    ropt.width = o->width;
    ropt.height = o->height;
    if (o->antialias_on) {
        ropt.aa.method = o->aa_method;
        ropt.aa.threshold = o->aa_threshold < 1.0 ? o->aa_threshold : 1.0; /* clipped to 1, as POV-Ray does */
        ropt.aa.depth = o->aa_depth;
        ropt.aa.gamma = o->aa_gamma;
        ropt.aa.work_gamma = working_gamma;
        ropt.aa.jitter = o->jitter_on ? (o->jitter_amount < 1.0 ? o->jitter_amount : 1.0) : 0.0; /* clipped, as POV-Ray */
    }
    ropt.x0 = o->area_x0;
    ropt.y0 = o->area_y0;
    ropt.x1 = o->area_x1;
    ropt.y1 = o->area_y1;
    ropt.threads = threads;
    ropt.max_seconds = o->max_render_seconds;
    ropt.quality = quality_from_level(o->quality);
    /* hst with no light whose volumes pay (and no area light for its
     * beams) is the shadow ray alone: render it as the cache method does,
     * the shadow ray with the light's last opaque blocker tried first
     * (exact: shadow_cache.c), without hst's per-decision wrapper. The
     * decisions and images are the same; the analysis codes show the
     * cache's hits (on desk.pov 1.46 of the 1.54 million blocked rays,
     * each one polygon test instead of a walk through the hierarchy). */
    ropt.shadow = method->uses_volumes && !have_volumes && method->test == shadow_hst_test && !world_has_beams(&world)
                      ? shadow_method_find("cache")
                      : method;
    ropt.bvh = &bvh;
    ropt.volumes = have_volumes ? &volumes : NULL;
    ropt.embree = embree;
    ropt.cost = &cost;
    ropt.verify = o->verify_shadows;
    ropt.pixel_coherence = o->pixel_coherence;
    ropt.nth = nth;
    report.nth = ropt.nth;
    report.nth_mode = o->nth == NTH_PER_POINT ? "per-point" : o->nth == NTH_AUTO ? "auto (C_ray / (C_s + C_g))" : "fixed";
    report.verify = o->verify_shadows;
    /* A distributed render's progress is no one rank's to tell. */
    ropt.progress = o->render_console && isatty(STDERR_FILENO) && !distributed;
    report.threads = ropt.threads;

    if (o->aov) {
        if (aov_image_alloc(&aov, o->aov, o->width, o->height, world.nlights, o->exr_float)) {
            fprintf(stderr, "hstrace: out of memory for the analysis channels\n");
            status = EXIT_IO;
            goto done;
        }
        ropt.aov = &aov;
    }

    /* Each tile's time, for the JSON's load balance. */
    TileGrid tile_grid;
    render_tile_grid(&ropt, &tile_grid);
    if (stats_json) {
        tile_seconds = calloc((size_t)(tile_grid.ntiles > 0 ? tile_grid.ntiles : 1), sizeof *tile_seconds);
        ropt.tile_seconds = tile_seconds;
        report.ntiles = tile_grid.ntiles;
        report.tile_seconds = tile_seconds;
    }
    Image img;
    int rc_render;
    if (distributed) {
        /* Tiles from rank 0, the pixels and counters back to it. */
        MpiTiles tiles;
        TileGrid tg;
        render_tile_grid(&ropt, &tg);
        if (mpi_job_rank() == 0) {
            per_rank = calloc((size_t)mpi_job_size(), sizeof *per_rank);
            waits = calloc((size_t)mpi_job_size(), sizeof *waits);
            requests = calloc((size_t)mpi_job_size(), sizeof *requests);
            wait_seconds = calloc((size_t)mpi_job_size(), sizeof *wait_seconds);
        }
        if (mpi_tiles_begin(&tiles, &tg, threads)) {
            fprintf(stderr, "hstrace: out of memory for the tiles of a distributed render\n");
            status = EXIT_IO;
            goto done;
        }
        ropt.tiles = &tiles.source;
        double render_start = clock_wall();
        int rc = render_image(&world, &grid, &ropt, &img, &report.render);
        double gather = clock_wall();
        if (mpi_tiles_end(&tiles, &tg, rc, &img, o->aov ? &aov : NULL, &report.render, per_rank, waits, tile_seconds)) {
            /* The ranks share one verdict: past the time if this rank went past it or, near enough, would have. */
            if (rc == RENDER_PAST_DEADLINE ||
                (o->max_render_seconds > 0.0 && gather - render_start >= o->max_render_seconds)) {
                fprintf(stderr, "%s: the render ran for more than %g s (--max-render-seconds); no image written\n",
                        o->scene, o->max_render_seconds);
                status = EXIT_SCENE;
            } else {
                fprintf(stderr, "hstrace: a rank ran out of memory while rendering\n");
                status = EXIT_IO;
            }
            if (rc == 0)
                image_free(&img);
            goto done;
        }
        report.gather_seconds = clock_wall() - gather;
        report.ranks = mpi_job_size();
        report.rank_render = per_rank;
        for (int r = 0; waits && requests && wait_seconds && r < mpi_job_size(); r++) {
            requests[r] = waits[r].requests;
            wait_seconds[r] = waits[r].wait_seconds;
        }
        report.rank_requests = requests;
        report.rank_wait_seconds = wait_seconds;
        if (mpi_job_rank() != 0) { /* rank 0 writes the image and the report */
            image_free(&img);
            goto done;
        }
    } else if ((rc_render = render_image(&world, &grid, &ropt, &img, &report.render)) != 0) {
        if (rc_render == RENDER_PAST_DEADLINE) {
            /* A budget crossed, as the parse's are: a scene error, named by its file (no one place is to blame). */
            fprintf(stderr, "%s: the render ran for more than %g s (--max-render-seconds); no image written\n",
                    o->scene, o->max_render_seconds);
            status = EXIT_SCENE;
        } else {
            fprintf(stderr, "hstrace: out of memory while rendering\n");
            status = EXIT_IO;
        }
        goto done;
    }
    t = clock_wall();
    image_decode_working_gamma(&img, working_gamma);
    ImageWriteOptions wopt;
    memset(&wopt, 0, sizeof wopt);
    wopt.exr_float = o->exr_float;
    wopt.png_16bit = o->png16;
    wopt.write_alpha = o->output_alpha;
    wopt.tga_rle = o->output_type == 'C';
    wopt.jpeg_quality = o->jpeg_quality;
    wopt.software = "hstrace " PACKAGE_VERSION;
    wopt.display_gamma = 0.0; /* sRGB, as POV-Ray 3.7 writes assumed_gamma 1 scenes */
    wopt.display = colour;    /* or OpenColorIO's display/view transform */
    if (colour != NULL) {
        wopt.have_chromaticities = colour_display_chromaticities(colour, wopt.chromaticities) == 0;
    } else {
        wopt.have_chromaticities = 1;
        memcpy(wopt.chromaticities, colour_rec709_chromaticities, sizeof wopt.chromaticities);
    }
    wopt.channels = aov.channels;
    wopt.nchannels = aov.nchannels;
    report.wall_seconds = clock_wall() - wall0; /* so far: the header is written before the pixels */
    if (image_format_from_path(output) == IMAGE_FORMAT_EXR) {
        if (provenance_build(&prov, argc, argv, o, anim, &report, &scene_hash)) {
            fprintf(stderr, "hstrace: out of memory\n");
            status = EXIT_IO;
        }
        wopt.attributes = prov.attr;
        wopt.nattributes = prov.n;
    }
    if (status == EXIT_OK && !o->no_output && image_write(output, &img, &wopt, err, sizeof err)) {
        fprintf(stderr, "hstrace: %s\n", err);
        status = EXIT_IO;
    }
    report.output_seconds = clock_wall() - t;
    image_free(&img);
    report.wall_seconds = clock_wall() - wall0;
    if (status == EXIT_OK && o->stats && o->statistics_console) {
        stats_print(stderr, &report);
        if (colour != NULL)
            fprintf(stderr, "colour: %s, config '%s', display '%s', view '%s', working space '%s'\n",
                    colour_ocio_version(), colour_display_config(colour), colour_display_name(colour),
                    colour_display_view(colour), colour_display_working_space(colour));
        else
            fprintf(stderr, "colour: POV-Ray's sRGB encoding (no OpenColorIO config asked for)\n");
    }
    if (status == EXIT_OK && stats_json && stats_write_json(stats_json, &report, err, sizeof err)) {
        fprintf(stderr, "hstrace: %s\n", err);
        status = EXIT_IO;
    }

done:
    if (scene_hash.state == 1) { /* its thread joined on every way out */
        uint64_t unused;
        (void)scene_hash_finish(&scene_hash, &unused);
    }
    free(per_rank);
    free(waits);
    free(requests);
    free(wait_seconds);
    free(tile_seconds);
    provenance_free(&prov);
    aov_image_free(&aov);
    shadow_volumes_free(&volumes);
    volume_plan_free(&plan);
    shadow_embree_free(embree);
    bvh_free(&bvh);
    grid_free(&grid);
    world_free(&world);
    scene_free(scene);
    colour_display_free(colour);
    free(declares);
    return status;
}

static int main_rank(int argc, char **argv, double wall0);

int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "compare") == 0)
        return compare_main(argc - 1, argv + 1);
    if (argc > 1 && strcmp(argv[1], "vs-povray") == 0)
        return vs_povray_main(argc - 1, argv + 1, argv[0]);
    if (argc > 1 && strcmp(argv[1], "stitch") == 0)
        return stitch_main(argc - 1, argv + 1, argv[0]);
    double wall0 = clock_wall();
    char err[1024];
    /* Under mpirun: one rank of a job (mpi_job.h); before any thread. */
    if (mpi_job_init(&argc, &argv, err, sizeof err)) {
        fprintf(stderr, "hstrace: %s\n", err);
        mpi_job_finalize();
        return EXIT_USAGE;
    }
    int status = main_rank(argc, argv, wall0);
    mpi_job_finalize();
    return status;
}

/* main's work, between MPI's start and end. */
static int main_rank(int argc, char **argv, double wall0)
{
    Options opt;
    char err[1024];
    if (options_parse(argc, argv, &opt, err, sizeof err)) {
        /* An INI file's mistake begins with its FILE:LINE:COLUMN. */
        fprintf(stderr, opt.error_has_position ? "%s\n" : "hstrace: %s\n", err);
        int io = opt.error_is_io;
        options_free(&opt);
        return io ? EXIT_IO : EXIT_USAGE;
    }
    if (opt.help || opt.version) {
        if (opt.help)
            options_usage(stdout);
        else if (shadow_embree_built())
            printf("hstrace %s (%s; Embree %s; %s)\n", PACKAGE_VERSION, colour_ocio_version(), shadow_embree_version(),
                   mpi_job_built() ? "Open MPI" : "no MPI");
        else
            printf("hstrace %s (%s; no Embree; %s)\n", PACKAGE_VERSION, colour_ocio_version(),
                   mpi_job_built() ? "Open MPI" : "no MPI");
        options_free(&opt);
        return EXIT_OK;
    }

    if (opt.display_asked)
        fprintf(stderr, "hstrace: note: +D: hstrace has no display window; the image goes to its file only\n");
    if (opt.pause_asked)
        fprintf(stderr, "hstrace: note: +P: hstrace has no display window to pause on; it ends when the image is written\n");
    Animation anim;
    if (animation_plan(&opt, &anim, err, sizeof err)) {
        fprintf(stderr, "hstrace: %s\n", err);
        options_free(&opt);
        return EXIT_USAGE;
    }
    /* Across ranks: an animation of at least as many frames as ranks by
     * frames (each rank its own, every size-th from its rank), else each
     * frame by tiles, where only rank 0 speaks (the others would repeat
     * its messages; a rank that fails alone ends the job, named by
     * mpirun). */
    const int ranks = mpi_job_size(), rank = mpi_job_rank();
    const int by_frames = ranks > 1 && anim.animated && anim.last - anim.first + 1 >= ranks;
    const int distributed = ranks > 1 && !by_frames;
    if (distributed && rank != 0 && !freopen("/dev/null", "w", stderr))
        return EXIT_IO;
    char *default_name = opt.output ? NULL : default_output(opt.scene, options_output_extension(&opt));
    const char *output = opt.output ? opt.output : default_name;
    int status = output ? EXIT_OK : EXIT_IO;
    if (ranks > 1 && rank == 0 && opt.stats)
        fprintf(stderr, "hstrace: %d ranks, %s\n", ranks, by_frames ? "the frames spread over them" : "the tiles of each frame spread over them");
    if (!output)
        fprintf(stderr, "hstrace: out of memory\n");
    /* Each frame is parsed, built and rendered anew, as POV-Ray does, and
     * written to its own numbered file; the first that fails ends the run. */
    for (int frame = anim.first; status == EXIT_OK && frame <= anim.last; frame++) {
        if (by_frames && (frame - anim.first) % ranks != rank)
            continue;
        /* The values as POV-Ray 3.7 hands them to the scene (animation.h). */
        ParseAnimation pa = { animation_clock(&anim, frame), pov_declared_value(anim.clock_delta),
                              pov_declared_value(anim.initial_clock), pov_declared_value(anim.final_clock),
                              pov_declared_value(frame), pov_declared_value(anim.initial_frame),
                              pov_declared_value(anim.final_frame), 1 };
        ParseAnimation still = { anim.still_clock, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, anim.still_clock_on };
        char *name = anim.animated ? animation_file_name(output, frame, anim.digits) : NULL;
        char *json = anim.animated && opt.stats_json ? animation_file_name(opt.stats_json, frame, anim.digits) : NULL;
        if ((anim.animated && !name) || (anim.animated && opt.stats_json && !json)) {
            fprintf(stderr, "hstrace: out of memory\n");
            status = EXIT_IO;
        } else {
            if (anim.animated && isatty(STDERR_FILENO))
                fprintf(stderr, "hstrace: frame %d (%d of %d), clock %g: %s\n", frame, frame - anim.first + 1,
                        anim.last - anim.first + 1, pa.clock, name);
            status = render_frame(argc, argv, &opt, anim.animated ? &pa : &still, name ? name : output,
                                  json ? json : opt.stats_json, frame == anim.first ? wall0 : clock_wall(), distributed);
        }
        free(name);
        free(json);
    }
    free(default_name);
    options_free(&opt);
    return status;
}
