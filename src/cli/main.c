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
#include "camera.h"
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
#include "shadow_registry.h"
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

/* Everything one frame owns, released by frame_free (every release is
 * safe on what was never made), and what its steps hand on. */
typedef struct {
    ParseDeclare *declares;
    ColourDisplay *colour;
    Scene *scene;
    World world;
    Grid grid;
    Bvh bvh;
    ShadowPrepared shadows;
    AovImage aov;
    Provenance prov;
    SceneHash scene_hash;
    RenderStats *per_rank;
    MpiTileWaits *waits;
    long *requests;
    double *wait_seconds;
    double *tile_seconds;
    StatsReport report;
    RenderOptions ropt;
    Image img;
    int have_img;
    int writes;            /* this process writes the image and the report */
    int threads;
    double working_gamma;
    double parse_start, preprocess_start;
} Frame;

static void frame_free(Frame *f)
{
    if (f->scene_hash.state == 1) { /* its thread joined on every way out */
        uint64_t unused;
        (void)scene_hash_finish(&f->scene_hash, &unused);
    }
    if (f->have_img)
        image_free(&f->img);
    free(f->per_rank);
    free(f->waits);
    free(f->requests);
    free(f->wait_seconds);
    free(f->tile_seconds);
    provenance_free(&f->prov);
    aov_image_free(&f->aov);
    shadow_prepared_free(&f->shadows);
    bvh_free(&f->bvh);
    grid_free(&f->grid);
    world_free(&f->world);
    scene_free(f->scene);
    colour_display_free(f->colour);
    free(f->declares);
}

static int check_output(const Options *o, const char *output)
{
    if (image_format_from_path(output) == IMAGE_FORMAT_UNKNOWN) {
        fprintf(stderr, "hstrace: '%s': unknown image format (use .exr, .png, .ppm, .tga, .bmp, .jpg or .hdr)\n", output);
        return EXIT_USAGE;
    }
    if (o->aov && image_format_from_path(output) != IMAGE_FORMAT_EXR) {
        fprintf(stderr, "hstrace: --aov: '%s': analysis channels need an EXR output (-o FILE.exr)\n", output);
        return EXIT_USAGE;
    }
    return EXIT_OK;
}

/* Colour management: OpenColorIO when an option or $OCIO asks for it, else
 * POV-Ray's own encoding. Opened before any work, so that a bad config or
 * name costs nothing. */
static int open_colour(Frame *f, const Options *o)
{
    char err[1024];
    ColourRequest creq = { o->ocio_config, o->display, o->view, o->colorspace };
    if (!colour_requested(&creq))
        return EXIT_OK;
    ColourStatus cs = colour_display_open(&creq, &f->colour, err, sizeof err);
    int from_env_only = !o->ocio_config && !o->display && !o->view && !o->colorspace;
    if (cs == COLOUR_ERR_UNAVAILABLE && from_env_only) {
        /* $OCIO is set for every program of a user; one built without the
         * library goes on as if it were not. */
        if (o->warning_console)
            fprintf(stderr, "hstrace: warning: $OCIO ignored: %s\n", err);
    } else if (cs != COLOUR_OK) {
        fprintf(stderr, "hstrace: %s\n", err);
        return cs == COLOUR_ERR_CONFIG ? EXIT_IO : EXIT_USAGE;
    }
    return EXIT_OK;
}

/* The scene file into its description, with the EXR header's hash of the
 * file made beside the parse. */
static int parse_scene(Frame *f, const Options *o, const ParseAnimation *anim, const char *output)
{
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
    popt.quick_colours = o->quality <= 5;
    popt.load_image = image_read_for_scene;
    popt.language_version_given = o->language_version_given;
    popt.quiet_debug = !o->debug_console;
    popt.quiet_warnings = !o->warning_console;
    popt.max_memory = o->max_memory;
    popt.max_parse_seconds = o->max_parse_seconds;
    popt.max_loop_iterations = o->max_loop_iterations;
    popt.max_macro_calls = o->max_macro_calls;
    popt.max_repeated_tokens = o->max_repeated_tokens;
    /* Declare=NAME=VALUE: the options' list has the parser's shape. */
    f->declares = o->ndeclares ? calloc((size_t)o->ndeclares, sizeof *f->declares) : NULL;
    if (o->ndeclares && !f->declares) {
        fprintf(stderr, "hstrace: out of memory\n");
        return EXIT_IO;
    }
    for (int i = 0; i < o->ndeclares; i++)
        f->declares[i] = (ParseDeclare){ o->declares[i].name, o->declares[i].number, o->declares[i].string };
    popt.declares = f->declares;
    popt.ndeclares = o->ndeclares;
    popt.animation = anim;
    popt.threads = f->threads;

    int spare_core = f->threads > 1;
    scene_hash_start(&f->scene_hash, o->scene, spare_core && image_format_from_path(output) == IMAGE_FORMAT_EXR);
    double t = clock_wall();
    f->parse_start = t;
    ParseError perr;
    f->scene = parse_scene_file(o->scene, &popt, &perr);
    if (!f->scene) {
        if (perr.line > 0)
            fprintf(stderr, "%s:%d:%d: %s\n", perr.file, perr.line, perr.column, perr.message);
        else
            fprintf(stderr, "%s: %s\n", perr.file[0] ? perr.file : o->scene, perr.message);
        fputs(perr.notes, stderr);
        return perr.is_io ? EXIT_IO : EXIT_SCENE;
    }
    f->report.parse_seconds = clock_wall() - t;
    f->report.napproximations = f->scene->napproximations;
    f->report.approximations = f->scene->approximations;
    /* Like POV-Ray's warnings: the image is not what POV-Ray would make. */
    for (int i = 0; o->warning_console && i < f->scene->napproximations; i++) {
        const SceneApproximation *a = &f->scene->approximations[i];
        fprintf(stderr, "%s:%d:%d: warning: %s approximated: %s (%d place%s; --strict refuses it)\n", a->first.file,
                a->first.line, a->first.column, a->what, approx_kind_effect(a->kind), a->count,
                a->count == 1 ? "" : "s");
    }
    return EXIT_OK;
}

/* The world's polygons, the grid's box and the hierarchy. */
static int build_world(Frame *f, const Options *o)
{
    f->preprocess_start = clock_wall();
    f->working_gamma = scene_working_gamma(f->scene);
    WorldError werr;
    /* The world's build is held to the parse's budgets: the memory (its
     * own, counted before anything is made) and the time (the parse's and
     * the build's together). */
    WorldLimits wlim = { o->max_memory ? o->max_memory : parse_default_max_memory(),
                         o->max_parse_seconds > 0.0 ? f->parse_start + o->max_parse_seconds : 0.0,
                         o->max_parse_seconds, 0 };
    /* Meshes placed many times kept once (instance.h) where the method
     * decides on instances, and --verify-reference's brute force (which
     * reads world-space polygons) is not asked for. */
    int area_lights = 0;
    for (int i = 0; i < f->scene->nlights; i++)
        area_lights |= f->scene->lights[i].area.size1 > 0;
    const ShadowMethod *method = shadow_method_find(o->shadows);
    wlim.instance_meshes = o->instancing && method && o->verify_shadows < 2 &&
                           shadow_method_takes_instances(method, o->volumes_always, area_lights);
    if (world_build_limited(&f->world, f->scene, f->threads, &wlim, &werr)) {
        if (werr.pos.file && werr.pos.line > 0)
            fprintf(stderr, "%s:%d:%d: %s\n", werr.pos.file, werr.pos.line, werr.pos.column, werr.message);
        else
            fprintf(stderr, "hstrace: %s\n", werr.message);
        return werr.over_budget ? EXIT_SCENE : EXIT_IO;
    }
    f->world.alpha_background = o->output_alpha;
    /* The world has its own copy of the meshes now: their lists go before
     * the hierarchy's build, where the memory peaks. */
    scene_release_mesh_lists(f->scene);
    f->report.world_seconds = clock_wall() - f->preprocess_start;
    /* The grid box holds the camera (depth counts start there) and the part
     * of every infinite plane under the geometry, where shadows fall. */
    Vec3 extra[1 + 8 * 16];
    int nextra = grid_extra_points(&f->world, extra, (int)(sizeof extra / sizeof extra[0]));
    /* The polygons are registered in its cells only if shadow volumes are
     * built (volume_plan_build): every other query goes through the hierarchy. */
    grid_build_box(&f->grid, &f->world, o->grid[0] ? o->grid : NULL, extra, nextra);
    grid_set_tolerance(&f->grid, o->tolerance);
    double t_hierarchy = clock_wall();
    int bvh_failed = bvh_build(&f->bvh, &f->world, f->threads);
    f->report.hierarchy_seconds = clock_wall() - t_hierarchy;
    if (bvh_failed) {
        fprintf(stderr, "hstrace: out of memory while building the hierarchy\n");
        return EXIT_IO;
    }
    return EXIT_OK;
}

/* The shadow method's own preparation (shadow_method_prepare); across an
 * MPI job's ranks rank 0 decides for all. */
static int prepare_shadows(Frame *f, const Options *o, int distributed)
{
    ShadowSetup setup = { &f->world, &f->grid, &f->bvh,
                          camera_has_one_origin(&f->world.camera) ? &f->world.camera.location : NULL,
                          o->width, o->height, f->threads, o->quality >= 4, o->volumes_always, o->nth,
                          o->plane_precision, distributed ? mpi_job_broadcast : NULL, mpi_job_rank() == 0 };
    char err[1024];
    if (shadow_method_prepare(shadow_method_find(o->shadows), &setup, &f->shadows, err, sizeof err)) {
        if (distributed)
            fprintf(stderr, "hstrace: rank %d: %s\n", mpi_job_rank(), err);
        else
            fprintf(stderr, "hstrace: %s\n", err);
        if (distributed)
            mpi_job_abort(EXIT_IO);
        return EXIT_IO;
    }
    StatsReport *r = &f->report;
    r->plan = f->shadows.plan;
    r->plan_seconds = f->shadows.plan_seconds;
    r->volumes_seconds = f->shadows.volumes_seconds;
    r->volumes = f->shadows.volumes;
    r->cost = f->shadows.volumes ? f->shadows.cost : NULL;
    r->embree = f->shadows.embree;
    r->light_buffers = f->shadows.light_buffers;
    r->nth = f->shadows.nth;
    r->nth_mode = f->shadows.nth_mode;
    r->preprocess_seconds = clock_wall() - f->preprocess_start;
    memcpy(r->grid, f->grid.n, sizeof r->grid);
    r->grid_registrations = f->grid.nitems;
    r->grid_registered = grid_registered(&f->grid);
    r->npolygons = f->world.npolygons;
    r->ndegenerate = f->world.ndegenerate;
    r->ninstances = f->world.ninstances;
    r->nprototypes = f->world.nprototypes;
    r->nproto_polygons = f->world.nproto_polygons;
    r->ninstanced_polygons = f->world.nids - f->world.npolygons;
    r->nplanes = f->world.nplanes;
    r->nshapes = f->world.nshapes;
    r->nlights = f->world.nlights;
    return EXIT_OK;
}

/* The render loop's options, from the command line's and what the steps
 * before made. */
static int set_render_options(Frame *f, const Options *o, int distributed, const char *stats_json)
{
    RenderOptions *ropt = &f->ropt;
    memset(ropt, 0, sizeof *ropt);
    ropt->width = o->width;
    ropt->height = o->height;
    if (o->antialias_on) {
        ropt->aa.method = o->aa_method;
        ropt->aa.threshold = o->aa_threshold < 1.0 ? o->aa_threshold : 1.0; /* clipped to 1, as POV-Ray does */
        ropt->aa.depth = o->aa_depth;
        ropt->aa.gamma = o->aa_gamma;
        ropt->aa.work_gamma = f->working_gamma;
        ropt->aa.jitter = o->jitter_on ? (o->jitter_amount < 1.0 ? o->jitter_amount : 1.0) : 0.0; /* clipped, as POV-Ray */
        ropt->aa.block = o->render_block_size;
    }
    ropt->x0 = o->area_x0;
    ropt->y0 = o->area_y0;
    ropt->x1 = o->area_x1;
    ropt->y1 = o->area_y1;
    ropt->threads = f->threads;
    ropt->max_seconds = o->max_render_seconds;
    ropt->max_tree_rays = (uint64_t)o->max_tree_rays;
    ropt->quality = quality_from_level(o->quality);
    ropt->shadows = &f->shadows;
    ropt->bvh = &f->bvh;
    ropt->verify = o->verify_shadows;
    ropt->pixel_coherence = o->pixel_coherence;
    /* A distributed render's progress is no one rank's to tell. */
    ropt->progress = o->render_console && isatty(STDERR_FILENO) && !distributed;
    f->report.verify = o->verify_shadows;
    f->report.threads = ropt->threads;
    if (o->aov) {
        if (aov_image_alloc(&f->aov, o->aov, o->width, o->height, f->world.nlights, o->exr_float)) {
            fprintf(stderr, "hstrace: out of memory for the analysis channels\n");
            return EXIT_IO;
        }
        ropt->aov = &f->aov;
    }
    /* Each tile's time, for the JSON's load balance. */
    TileGrid tile_grid;
    render_tile_grid(ropt, &tile_grid);
    if (stats_json) {
        f->tile_seconds = calloc((size_t)(tile_grid.ntiles > 0 ? tile_grid.ntiles : 1), sizeof *f->tile_seconds);
        ropt->tile_seconds = f->tile_seconds;
        f->report.ntiles = tile_grid.ntiles;
        f->report.tile_seconds = f->tile_seconds;
    }
    return EXIT_OK;
}

/* A render that went past --max-render-seconds: a budget crossed, as the
 * parse's are, a scene error named by its file (no one place is to blame). */
static int past_deadline(const Options *o)
{
    fprintf(stderr, "%s: the render ran for more than %g s (--max-render-seconds); no image written\n", o->scene,
            o->max_render_seconds);
    return EXIT_SCENE;
}

/* A camera ray's tree went past --max-tree-rays: a budget crossed, a scene
 * error (deterministic: the same for any thread count). */
static int tree_too_big(const Frame *f, const Options *o)
{
    fprintf(stderr, "%s: a camera ray's tree of reflected and transmitted rays held more than %ld rays "
                    "(max_trace_level %d, adc_bailout %g): lower max_trace_level, raise adc_bailout, or raise "
                    "--max-tree-rays; no image written\n",
            o->scene, o->max_tree_rays, f->world.max_trace_level, f->world.adc_bailout);
    return EXIT_SCENE;
}

/* The render: in this process, or with the tiles from rank 0 and the
 * pixels and counters back to it (only rank 0 then writes). */
static int render(Frame *f, const Options *o, int distributed)
{
    RenderOptions *ropt = &f->ropt;
    f->writes = 1;
    if (!distributed) {
        int rc = render_image(&f->world, &f->grid, ropt, &f->img, &f->report.render);
        if (rc == RENDER_PAST_DEADLINE)
            return past_deadline(o);
        if (rc == RENDER_RAY_TREE)
            return tree_too_big(f, o);
        if (rc != 0) {
            fprintf(stderr, "hstrace: out of memory while rendering\n");
            return EXIT_IO;
        }
        f->have_img = 1;
        return EXIT_OK;
    }
    const int ranks = mpi_job_size();
    MpiTiles tiles;
    TileGrid tg;
    render_tile_grid(ropt, &tg);
    if (mpi_job_rank() == 0) {
        f->per_rank = calloc((size_t)ranks, sizeof *f->per_rank);
        f->waits = calloc((size_t)ranks, sizeof *f->waits);
        f->requests = calloc((size_t)ranks, sizeof *f->requests);
        f->wait_seconds = calloc((size_t)ranks, sizeof *f->wait_seconds);
    }
    if (mpi_tiles_begin(&tiles, &tg, f->threads)) {
        fprintf(stderr, "hstrace: out of memory for the tiles of a distributed render\n");
        return EXIT_IO;
    }
    ropt->tiles = &tiles.source;
    double render_start = clock_wall();
    int rc = render_image(&f->world, &f->grid, ropt, &f->img, &f->report.render);
    f->have_img = rc == 0;
    double gather = clock_wall();
    if (mpi_tiles_end(&tiles, &tg, rc, &f->img, o->aov ? &f->aov : NULL, &f->report.render, f->per_rank, f->waits,
                      f->tile_seconds)) {
        /* The ranks share one verdict: past the time if this rank went past it or, near enough, would have. */
        if (rc == RENDER_PAST_DEADLINE || (o->max_render_seconds > 0.0 && gather - render_start >= o->max_render_seconds))
            return past_deadline(o);
        if (rc == RENDER_RAY_TREE)
            return tree_too_big(f, o);
        fprintf(stderr, "hstrace: a rank ran out of memory while rendering\n");
        return EXIT_IO;
    }
    StatsReport *r = &f->report;
    r->gather_seconds = clock_wall() - gather;
    r->ranks = ranks;
    r->rank_render = f->per_rank;
    for (int k = 0; f->waits && f->requests && f->wait_seconds && k < ranks; k++) {
        f->requests[k] = f->waits[k].requests;
        f->wait_seconds[k] = f->waits[k].wait_seconds;
    }
    r->rank_requests = f->requests;
    r->rank_wait_seconds = f->wait_seconds;
    f->writes = mpi_job_rank() == 0;
    return EXIT_OK;
}

/* Coincident surfaces the camera saw (trace_coincident_material): where
 * two objects' surfaces of different materials lie at one distance, the
 * image is hstrace's rule (the object declared first), not POV-Ray's
 * (whichever its bounding hierarchy meets first, often a speckle of both).
 * Said like the approximations, at the first object of the least pair. */
static void warn_coincident(const Frame *f, const Options *o)
{
    const RenderStats *s = &f->report.render;
    uint64_t n = s->shading.coincident_hits, m = s->shading.coincident_secondary, pair = s->coincident_pair;
    if (n + m == 0 || pair == 0)
        return;
    const Material *a = &f->world.materials[(pair >> 32) - 1], *b = &f->world.materials[(pair & 0xffffffffu) - 1];
    const char *where = a->pos.file ? a->pos.file : o->scene;
    fprintf(stderr,
            "%s:%d:%d: warning: %llu camera ray%s and %llu other%s met coincident surfaces of two objects, this one "
            "and %s:%d:%d (among others); hstrace shows the one declared first or the nearer by its rounding, "
            "POV-Ray the one it meets first or the nearer by its rounding (a speckle of both where their textures "
            "differ)\n",
            where, a->pos.line, a->pos.column, (unsigned long long)n, n == 1 ? "" : "s", (unsigned long long)m,
            m == 1 ? "" : "s", b->pos.file ? b->pos.file : where, b->pos.line, b->pos.column);
}

/* The image into `output`, with the EXR header's provenance. */
static int write_image(Frame *f, int argc, char **argv, const Options *o, const ParseAnimation *anim,
                       const char *output, double wall0)
{
    int status = EXIT_OK;
    char err[1024];
    double t = clock_wall();
    /* with gamma correction off, POV-Ray's working and file gamma are both
     * Display_Gamma (sRGB unless set): its pixels go out as they are, an
     * EXR's decoded by it; else the file gamma is File_Gamma (sRGB unless
     * set), which EXR and HDR, linear, do not use */
    const int gamma_off = scene_gamma_correction_off(f->scene);
    image_decode_working_gamma(&f->img, gamma_off ? o->display_gamma : f->working_gamma);
    ImageWriteOptions wopt;
    memset(&wopt, 0, sizeof wopt);
    wopt.exr_float = o->exr_float;
    wopt.png_16bit = o->png16;
    wopt.write_alpha = o->output_alpha;
    wopt.tga_rle = o->output_type == 'C';
    wopt.jpeg_quality = o->jpeg_quality;
    wopt.software = "hstrace " PACKAGE_VERSION;
    wopt.display_gamma = gamma_off ? o->display_gamma : o->file_gamma;
    wopt.display = f->colour; /* or OpenColorIO's display/view transform */
    if (f->colour != NULL) {
        wopt.have_chromaticities = colour_display_chromaticities(f->colour, wopt.chromaticities) == 0;
    } else {
        wopt.have_chromaticities = 1;
        memcpy(wopt.chromaticities, colour_rec709_chromaticities, sizeof wopt.chromaticities);
    }
    wopt.threads = f->threads;
    wopt.channels = f->aov.channels;
    wopt.nchannels = f->aov.nchannels;
    f->report.wall_seconds = clock_wall() - wall0; /* so far: the header is written before the pixels */
    if (image_format_from_path(output) == IMAGE_FORMAT_EXR) {
        if (provenance_build(&f->prov, argc, argv, o, anim, &f->report, &f->scene_hash)) {
            fprintf(stderr, "hstrace: out of memory\n");
            status = EXIT_IO;
        }
        wopt.attributes = f->prov.attr;
        wopt.nattributes = f->prov.n;
    }
    if (status == EXIT_OK && !o->no_output && image_write(output, &f->img, &wopt, err, sizeof err)) {
        fprintf(stderr, "hstrace: %s\n", err);
        status = EXIT_IO;
    }
    f->report.output_seconds = clock_wall() - t;
    image_free(&f->img);
    f->have_img = 0;
    f->report.wall_seconds = clock_wall() - wall0;
    return status;
}

/* --stats on the standard error, --stats-json into its file. */
static int report(const Frame *f, const Options *o, const char *stats_json)
{
    if (o->stats && o->statistics_console) {
        stats_print(stderr, &f->report);
        if (f->colour != NULL)
            fprintf(stderr, "colour: %s, config '%s', display '%s', view '%s', working space '%s'\n",
                    colour_ocio_version(), colour_display_config(f->colour), colour_display_name(f->colour),
                    colour_display_view(f->colour), colour_display_working_space(f->colour));
        else
            fprintf(stderr, "colour: POV-Ray's sRGB encoding (no OpenColorIO config asked for)\n");
    }
    char err[1024];
    if (stats_json && stats_write_json(stats_json, &f->report, err, sizeof err)) {
        fprintf(stderr, "hstrace: %s\n", err);
        return EXIT_IO;
    }
    return EXIT_OK;
}

/* One frame (or the still): parse, build, prepare the shadow method,
 * render, write `output` and report. wall0: when the frame's work began.
 * distributed: the frame's tiles are spread over the MPI job's ranks
 * (mpi_job.h), rank 0 writing. Returns the exit status. */
static int render_frame(int argc, char **argv, const Options *o, const ParseAnimation *anim, const char *output,
                        const char *stats_json, double wall0, int distributed)
{
    Frame f;
    memset(&f, 0, sizeof f);
    /* Each rank takes its share of this machine's cores. */
    f.threads = o->threads > 0 ? o->threads : render_default_threads();
    if (o->threads <= 0 && mpi_job_size() > 1)
        f.threads = f.threads / mpi_job_local_size() > 1 ? f.threads / mpi_job_local_size() : 1;
    f.report.scene = o->scene;
    f.report.povray_ini = o->povray_ini;
    f.report.povray_ini_why = o->povray_ini ? o->povray_ini_why
                              : o->no_povray_ini ? "--no-povray-ini"
                                                 : "none where POV-Ray looks for one";
    f.report.shadow_method = o->shadows;
    f.report.width = o->width;
    f.report.height = o->height;

    int status = check_output(o, output);
    if (status == EXIT_OK)
        status = open_colour(&f, o);
    if (status == EXIT_OK)
        status = parse_scene(&f, o, anim, output);
    if (status == EXIT_OK)
        status = build_world(&f, o);
    if (status == EXIT_OK)
        status = prepare_shadows(&f, o, distributed);
    if (status == EXIT_OK)
        status = set_render_options(&f, o, distributed, stats_json);
    if (status == EXIT_OK)
        status = render(&f, o, distributed);
    if (status == EXIT_OK && f.writes && o->warning_console)
        warn_coincident(&f, o);
    if (status == EXIT_OK && f.writes)
        status = write_image(&f, argc, argv, o, anim, output, wall0);
    if (status == EXIT_OK && f.writes)
        status = report(&f, o, stats_json);
    frame_free(&f);
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
    int status = EXIT_OK;
    if (options_parse(argc, argv, &opt, err, sizeof err)) {
        /* An INI file's mistake begins with its FILE:LINE:COLUMN. */
        fprintf(stderr, opt.error_has_position ? "%s\n" : "hstrace: %s\n", err);
        int io = opt.error_is_io;
        options_free(&opt);
        return io ? EXIT_IO : EXIT_USAGE;
    }
    if (opt.help || opt.version || opt.povray_options) {
        if (opt.help)
            options_usage(stdout);
        else if (opt.povray_options)
            status = options_povray_list(stdout) ? EXIT_IO : EXIT_OK;
        else if (shadow_embree_built())
            printf("hstrace %s (%s; Embree %s; %s)\n", PACKAGE_VERSION, colour_ocio_version(), shadow_embree_version(),
                   mpi_job_built() ? "Open MPI" : "no MPI");
        else
            printf("hstrace %s (%s; no Embree; %s)\n", PACKAGE_VERSION, colour_ocio_version(),
                   mpi_job_built() ? "Open MPI" : "no MPI");
        options_free(&opt);
        return status;
    }

    if (opt.povray_ini_warning[0] && opt.warning_console)
        fprintf(stderr, "hstrace: warning: %s; the search for povray.ini goes on, as POV-Ray's does\n",
                opt.povray_ini_warning);
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
    const int by_frames = ranks > 1 && anim.animated && animation_frames(&anim) >= ranks;
    const int distributed = ranks > 1 && !by_frames;
    if (distributed && rank != 0 && !freopen("/dev/null", "w", stderr))
        return EXIT_IO;
    char *default_name = opt.output ? NULL : default_output(opt.scene, options_output_extension(&opt));
    const char *output = opt.output ? opt.output : default_name;
    status = output ? EXIT_OK : EXIT_IO;
    if (ranks > 1 && rank == 0 && opt.stats)
        fprintf(stderr, "hstrace: %d ranks, %s\n", ranks, by_frames ? "the frames spread over them" : "the tiles of each frame spread over them");
    if (!output)
        fprintf(stderr, "hstrace: out of memory\n");
    /* Each frame is parsed, built and rendered anew, as POV-Ray does, and
     * written to its own numbered file; the first that fails ends the run. */
    for (int frame = anim.first; status == EXIT_OK && frame <= anim.last; frame += anim.step) {
        const int nth = (frame - anim.first) / anim.step; /* counted from 0 */
        if (by_frames && nth % ranks != rank)
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
                fprintf(stderr, "hstrace: frame %d (%d of %d), clock %g: %s\n", frame, nth + 1, animation_frames(&anim),
                        pa.clock, name);
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
