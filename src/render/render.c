/* Rendering in tiles on a pool of threads. */
#include "render.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "aov.h"
#include "camera.h"
#include "clock.h"
#include "deadline.h"
#include "shade.h"

#define TILE 16

int render_default_threads(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n < 1 ? 1 : n > 1024 ? 1024 : (int)n;
}

typedef struct {
    const World *world;
    const Grid *grid;
    const RenderOptions *opt;
    Image *img;
    TileGrid tiles;
    atomic_int next_tile;   /* shared by the workers: the only mutable shared state */
    atomic_int done_tiles;
    atomic_long done_pixels; /* for the progress line */
    long total_pixels;
    int reported;            /* the progress line was printed (worker 0 only) */
    atomic_int failed;
    atomic_int expired;      /* a thread went past the deadline: all stop */
    atomic_int tree_overflow; /* a camera ray's tree went past --max-tree-rays: all stop */
    double start;
    double deadline;         /* clock_wall() time, or 0 */
} Job;

typedef struct {
    Job *job;
    int index;
    RenderStats stats;
} Worker;

/* A pixel the camera traces no ray through (camera_ray): POV-Ray's
 * TracePixel leaves it black and fully transparent. */
static const Radiance UNTRACED_PIXEL = { 0.0, 0.0, 0.0, 1.0 };

/* The counters the analysis channels' costs are differences of. */
static uint64_t shadow_tests(const ShadeContext *ctx)
{
    return ctx->shadow.stats.shadow_volume_tests + ctx->shadow.stats.shadow_polygon_tests;
}

static uint64_t rays_traced(const ShadeContext *ctx, const RenderStats *loop)
{
    return loop->camera_rays + ctx->stats.reflected_rays + ctx->stats.refracted_rays + ctx->stats.transmitted_rays +
           ctx->shadow.stats.shadow_rays;
}

/* One anti-aliasing sample: a camera ray through pixel coordinates (x, y). */
typedef struct {
    ShadeContext *ctx;
    RenderStats *loop;
    const Job *job;
} SampleUser;

static void trace_sample(void *user, double x, double y, AaColour *out)
{
    SampleUser *u = user;
    const RenderOptions *opt = u->job->opt;
    Ray ray;
    ray_init_camera(&ray);
    Radiance c = UNTRACED_PIXEL;
    if (camera_ray_at(&u->job->world->camera, opt->width, opt->height, x, y, &ray.org, &ray.dir)) {
        shade_camera_interiors(u->ctx, u->job->world, ray.org, &ray.inside);
        shade_trace(u->ctx, &ray, 1.0, 0, &c);
        u->loop->camera_rays++;
    }
    out->c[0] = (float)c.r;
    out->c[1] = (float)c.g;
    out->c[2] = (float)c.b;
    out->c[3] = (float)c.transmit;
}

/* A block of POV-Ray's anti-aliasing (antialias.h) into the image. */
static long antialiased_tile(ShadeContext *ctx, RenderStats *loop, Job *job, int x0, int y0, int x1, int y1)
{
    const RenderOptions *opt = job->opt;
    AaColour *px = malloc(sizeof *px * (size_t)(x1 - x0) * (size_t)(y1 - y0));
    SampleUser u = { ctx, loop, job };
    if (!px || antialias_block(&opt->aa, x0, y0, x1 - 1, y1 - 1, trace_sample, &u, px)) {
        free(px);
        atomic_store(&job->failed, 1);
        return 0;
    }
    for (int y = y0; y < y1; y++) {
        for (int x = x0; x < x1; x++) {
            const AaColour *c = &px[(y - y0) * (x1 - x0) + (x - x0)];
            float *out = &job->img->rgba[((size_t)y * opt->width + x) * 4];
            out[0] = c->c[0];
            out[1] = c->c[1];
            out[2] = c->c[2];
            out[3] = 1.0f - c->c[3];
        }
    }
    loop->pixels += (uint64_t)(x1 - x0) * (uint64_t)(y1 - y0);
    free(px);
    return (long)(x1 - x0) * (y1 - y0);
}

/* loop: the render loop's own counters (pixels, camera rays). Returns the
 * tile's pixels. */
static long render_tile(ShadeContext *ctx, RenderStats *loop, Job *job, int tile)
{
    const RenderOptions *opt = job->opt;
    int x0, y0, x1, y1;
    render_tile_area(&job->tiles, tile, &x0, &y0, &x1, &y1);
    /* the tile's corner on the grid, before the area cut it */
    const int ts = job->tiles.tile_size;
    const int cx = job->tiles.grid_x0 + (job->tiles.tile_x0 + tile % job->tiles.tiles_x) * ts;
    const int cy = job->tiles.grid_y0 + (job->tiles.tile_y0 + tile / job->tiles.tiles_x) * ts;
    /* The cache method's last blockers start empty in every tile, so that
     * what it decides and counts for a pixel (the analysis channels, the
     * statistics) does not depend on which tiles this thread rendered
     * before: the same for any thread count. */
    shadow_tile_begin(&ctx->shadow);
    if (opt->aa.method)
        return antialiased_tile(ctx, loop, job, x0, y0, x1, y1);
    /* What the cache and pixel coherence carry from pixel to pixel (the
     * last blockers, the neighbour's depth counts) changes which
     * sub-scheme decides and what it costs, never the decision. So a tile
     * the area cuts is walked from its corner on the image's grid, the
     * pixels outside the area traced for that state only, when the
     * analysis channels record it: then a partial render's channels are
     * the full render's too, and partial renders stitch into it bit for
     * bit (hstrace stitch). The rows below the area are never needed. */
    int wx0 = cx, wy0 = cy, wx1 = cx + ts < opt->width ? cx + ts : opt->width;
    if (!opt->aov) {
        wx0 = x0;
        wy0 = y0;
        wx1 = x1;
    }
    for (int y = wy0; y < y1; y++) {
        for (int x = wx0; x < wx1; x++) {
            int inside = x >= x0 && x < x1 && y >= y0;
            Ray ray;
            ray_init_camera(&ray);
            int traced = camera_ray(&job->world->camera, opt->width, opt->height, x, y, &ray.org, &ray.dir);
            Radiance c = UNTRACED_PIXEL;
            if (ctx->aov)
                aov_pixel_begin(ctx->aov, shadow_tests(ctx), rays_traced(ctx, loop));
            shadow_pixel_begin(&ctx->shadow, x == wx0, y == wy0);
            if (traced) {
                shade_camera_interiors(ctx, job->world, ray.org, &ray.inside);
                shade_trace(ctx, &ray, 1.0, 0, &c);
                loop->camera_rays++;
            }
            shadow_pixel_end(&ctx->shadow, x == wx0);
            if (!inside)
                continue;
            loop->pixels++;
            if (ctx->aov)
                aov_image_store(opt->aov, ctx->aov, shadow_tests(ctx), rays_traced(ctx, loop), x, y);
            float *px = &job->img->rgba[((size_t)y * opt->width + x) * 4];
            px[0] = (float)c.r;
            px[1] = (float)c.g;
            px[2] = (float)c.b;
            px[3] = (float)(1.0 - c.transmit);
        }
    }
    return (long)(x1 - x0) * (y1 - y0);
}

/* "1m05s", "12.3s": a duration for the progress line. */
static void format_duration(char *buf, size_t n, double s)
{
    if (s < 60.0)
        snprintf(buf, n, "%.1fs", s);
    else if (s < 3600.0)
        snprintf(buf, n, "%dm%02ds", (int)(s / 60.0), (int)s % 60);
    else
        snprintf(buf, n, "%dh%02dm", (int)(s / 3600.0), (int)(s / 60.0) % 60);
}

/* The live progress line on a terminal: pixels done, the share, the time so
 * far and an estimate of what is left, rewritten in place. */
static void report_progress(Job *job, double elapsed)
{
    long done = atomic_load(&job->done_pixels);
    char spent[32], left[32];
    format_duration(spent, sizeof spent, elapsed);
    format_duration(left, sizeof left, done > 0 ? elapsed * (double)(job->total_pixels - done) / (double)done : 0.0);
    fprintf(stderr, "\rrendering: %ld of %ld pixels (%3d%%), %s elapsed, about %s left\033[K", done,
            job->total_pixels, (int)(100.0 * (double)done / (double)job->total_pixels), spent, left);
    fflush(stderr);
    job->reported = 1;
}

static void *worker_main(void *arg)
{
    Worker *wk = arg;
    Job *job = wk->job;
    ShadeContext ctx;
    memset(&ctx, 0, sizeof ctx);
    RenderStats loop;
    memset(&loop, 0, sizeof loop);
    const RenderOptions *opt = job->opt;
    ctx.quality = opt->quality;
    const ShadowPrepared *shadows = opt->shadows;
    AovPixel aov;
    memset(&aov, 0, sizeof aov);
    /* The tracer first (the method's state may ask it to record cells),
     * then the shadow testing that asks it; pixel coherence only where
     * each pixel is one camera ray. */
    int failed = tracer_init(&ctx.tracer, job->world, job->grid);
    if (!failed) {
        tracer_use_bvh(&ctx.tracer, opt->bvh);
        failed = shadow_context_init(&ctx.shadow, &ctx.tracer, job->world, job->grid, shadows, opt->verify,
                                     opt->pixel_coherence && !opt->aa.method) ||
                 (opt->aov && aov_pixel_init(&aov, job->world->nlights, shadows->decider->blind));
        ctx.shadow.perturb_normals = ctx.quality.normal;
    }
    if (failed) {
        aov_pixel_free(&aov);
        shadow_context_free(&ctx.shadow);
        tracer_free(&ctx.tracer);
        atomic_store(&job->failed, 1);
        return NULL;
    }
    if (opt->aov)
        ctx.aov = &aov;
    ctx.deadline = job->deadline;
    deadline_set(job->deadline); /* for the patterns whose one value may take hours */
    ctx.max_tree_rays = opt->max_tree_rays;
    double t0 = clock_thread_cpu();
    double last_report = 0.0;
    for (;;) {
        if (job->deadline > 0.0 && (atomic_load(&job->expired) || clock_wall() > job->deadline)) {
            atomic_store(&job->expired, 1);
            break;
        }
        if (atomic_load(&job->tree_overflow))
            break;
        int tile = opt->tiles ? opt->tiles->next(opt->tiles, wk->index) : atomic_fetch_add(&job->next_tile, 1);
        if (tile < 0 || tile >= job->tiles.ntiles)
            break;
        /* Shadow time is sampled on the wall clock (shadow_decide.c), which
         * also counts the time the thread spent preempted on a busy
         * machine. Scaling each tile's share by the tile's CPU time over
         * its wall time takes that out (no change on an idle machine). */
        double *shadow_seconds = &ctx.shadow.stats.shadow_seconds;
        double *secondary_seconds = &ctx.shadow.stats.shadow_seconds_secondary;
        double tile_wall = clock_wall(), tile_cpu = clock_thread_cpu(), shadow_before = *shadow_seconds;
        double secondary_before = *secondary_seconds;
        long pixels = render_tile(&ctx, &loop, job, tile);
        if (ctx.expired) {
            atomic_store(&job->expired, 1);
            break;
        }
        if (ctx.tree_overflow) {
            atomic_store(&job->tree_overflow, 1);
            break;
        }
        atomic_fetch_add(&job->done_pixels, pixels);
        tile_wall = clock_wall() - tile_wall;
        tile_cpu = clock_thread_cpu() - tile_cpu;
        if (opt->tile_seconds)
            opt->tile_seconds[tile] = tile_cpu; /* each tile is one thread's */
        if (tile_wall > 0.0 && tile_cpu < tile_wall) {
            *shadow_seconds = shadow_before + (*shadow_seconds - shadow_before) * (tile_cpu / tile_wall);
            *secondary_seconds = secondary_before + (*secondary_seconds - secondary_before) * (tile_cpu / tile_wall);
        }
        atomic_fetch_add(&job->done_tiles, 1);
        /* At most four times a second, from half a second on. */
        if (job->opt->progress && wk->index == 0) {
            double now = clock_wall() - job->start;
            if (now > 0.5 && now - last_report >= 0.25) {
                report_progress(job, now);
                last_report = now;
            }
        }
    }
    loop.render_seconds = clock_thread_cpu() - t0;
    loop.rays = ctx.tracer.stats;
    loop.shading = ctx.stats;
    loop.coincident_pair = ctx.coincident_pair;
    loop.shadow = ctx.shadow.stats;
    wk->stats = loop;
    deadline_set(0.0); /* this thread may be the caller's, working on after the render */
    aov_pixel_free(&aov);
    shadow_context_free(&ctx.shadow);
    tracer_free(&ctx.tracer);
    return NULL;
}

void render_tile_grid(const RenderOptions *opt, TileGrid *t)
{
    t->x0 = opt->x0;
    t->y0 = opt->y0;
    t->x1 = opt->x1 > 0 ? opt->x1 : opt->width;
    t->y1 = opt->y1 > 0 ? opt->y1 : opt->height;
    /* POV-Ray's anti-aliasing decides by blocks of its own size, from the
     * area's corner; the plain render's tiles lie on the image's grid. */
    int block = opt->aa.block > 0 ? opt->aa.block : ANTIALIAS_BLOCK;
    int span = t->x1 - t->x0 > t->y1 - t->y0 ? t->x1 - t->x0 : t->y1 - t->y0;
    if (block > span)
        block = span; /* as POV-Ray: one block, the whole area */
    t->tile_size = opt->aa.method ? block : TILE;
    t->grid_x0 = opt->aa.method ? t->x0 : 0;
    t->grid_y0 = opt->aa.method ? t->y0 : 0;
    t->tile_x0 = (t->x0 - t->grid_x0) / t->tile_size;
    t->tile_y0 = (t->y0 - t->grid_y0) / t->tile_size;
    t->tiles_x = (t->x1 - 1 - t->grid_x0) / t->tile_size - t->tile_x0 + 1;
    t->ntiles = t->tiles_x * ((t->y1 - 1 - t->grid_y0) / t->tile_size - t->tile_y0 + 1);
}

void render_tile_area(const TileGrid *t, int tile, int *x0, int *y0, int *x1, int *y1)
{
    /* Tiles lie on the whole image's grid, cut to the area rendered: a
     * partial render's pixels are those of the full render. */
    int ts = t->tile_size;
    int ax = t->grid_x0 + (t->tile_x0 + tile % t->tiles_x) * ts;
    int ay = t->grid_y0 + (t->tile_y0 + tile / t->tiles_x) * ts;
    *x1 = ax + ts < t->x1 ? ax + ts : t->x1;
    *y1 = ay + ts < t->y1 ? ay + ts : t->y1;
    *x0 = ax > t->x0 ? ax : t->x0;
    *y0 = ay > t->y0 ? ay : t->y0;
}

int render_image(const World *w, const Grid *g, const RenderOptions *opt, Image *img, RenderStats *stats)
{
    memset(stats, 0, sizeof *stats);
    if (image_alloc(img, opt->width, opt->height))
        return -1;
    Job job;
    memset(&job, 0, sizeof job);
    job.world = w;
    job.grid = g;
    job.opt = opt;
    job.img = img;
    render_tile_grid(opt, &job.tiles);
    atomic_init(&job.next_tile, 0);
    atomic_init(&job.done_tiles, 0);
    atomic_init(&job.done_pixels, 0);
    job.total_pixels = (long)(job.tiles.x1 - job.tiles.x0) * (job.tiles.y1 - job.tiles.y0);
    atomic_init(&job.failed, 0);
    atomic_init(&job.expired, 0);
    atomic_init(&job.tree_overflow, 0);
    job.start = clock_wall();
    job.deadline = opt->max_seconds > 0.0 ? job.start + opt->max_seconds : 0.0;

    int n = opt->threads < 1 ? 1 : opt->threads;
    Worker *workers = calloc((size_t)n, sizeof *workers);
    pthread_t *tids = calloc((size_t)n, sizeof *tids);
    if (!workers || !tids) {
        free(workers);
        free(tids);
        image_free(img);
        return -1;
    }
    int started = 0;
    for (int i = 0; i < n; i++) {
        workers[i].job = &job;
        workers[i].index = i;
        if (i == 0)
            continue; /* the calling thread is worker 0 */
        if (pthread_create(&tids[i], NULL, worker_main, &workers[i]) != 0)
            break;
        started = i;
    }
    worker_main(&workers[0]);
    for (int i = 1; i <= started; i++)
        pthread_join(tids[i], NULL);
    for (int i = 0; i < n; i++)
        stats_add(stats, &workers[i].stats);
    if (job.reported)
        fputs("\r\033[K", stderr); /* the line erased: the terminal as it was */
    free(workers);
    free(tids);
    /* Without a tile source, every tile must have been taken; a source
     * keeps its own account of what was handed out. */
    if (atomic_load(&job.failed)) {
        image_free(img);
        return RENDER_OUT_OF_MEMORY;
    }
    if (atomic_load(&job.expired)) {
        image_free(img);
        return RENDER_PAST_DEADLINE;
    }
    if (atomic_load(&job.tree_overflow)) {
        image_free(img);
        return RENDER_RAY_TREE;
    }
    if (!opt->tiles && atomic_load(&job.next_tile) < job.tiles.ntiles) {
        image_free(img);
        return RENDER_OUT_OF_MEMORY;
    }
    return 0;
}
