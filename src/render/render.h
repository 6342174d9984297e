/* The render loop: camera rays through pixel centres exactly as POV-Ray
 * makes them, tiles handed to threads, one image out. Each pixel depends on
 * nothing but the scene, so the image is the same for any thread count. */
#ifndef HST_RENDER_H
#define HST_RENDER_H

#include "antialias.h"
#include "grid.h"
#include "image_buffer.h"
#include "shade.h"
#include "stats.h"
#include "world.h"

/* Where a render's tiles come from: by default the process's own counter;
 * a distributed render (mpi_job.h) hands them out across processes. next
 * is called from the render's threads at once (worker: the thread's index)
 * and returns a tile number below the grid's count, or -1 when none is left
 * for this process; it must be safe to call from several threads. */
typedef struct TileSource {
    int (*next)(struct TileSource *src, int worker);
} TileSource;

typedef struct {
    int width, height;
    /* The pixels rendered, [x0, x1) x [y0, y1) (a partial render); the rest
     * of the image stays 0. All zero: the whole image. */
    int x0, y0, x1, y1;
    int threads;              /* >= 1 */
    Antialias aa;             /* method 0: none (one camera ray through each pixel's centre) */
    Quality quality;
    const ShadowPrepared *shadows; /* the shadow method, prepared (shadow_method_prepare) */
    const Bvh *bvh;           /* the polygon queries' hierarchy; NULL: the grid's walk */
    int verify;               /* 1 --verify-shadows, 2 --verify-reference too */
    int pixel_coherence;      /* hst: count from the neighbouring pixel's hit */
    int progress;             /* print a progress line on stderr */
    struct AovImage *aov;     /* --aov: the analysis channels to fill, or NULL */
    TileSource *tiles;        /* NULL: every tile, in this process */
    /* When not NULL, the thread CPU seconds of each tile rendered here (the
     * tile grid's count of them), for the statistics' load balance. */
    double *tile_seconds;
    /* --max-render-seconds: seconds the render may take from its start (0:
     * no limit), checked by every thread before each tile and every
     * SHADE_CLOCK_RAYS rays; past them every thread stops and render_image
     * returns RENDER_PAST_DEADLINE (the pixels are then of no use). */
    double max_seconds;
    /* --max-tree-rays: the rays one camera ray's tree of reflected,
     * refracted and transmitted rays may hold (0: no limit); once one tree
     * goes past it every thread stops and render_image returns
     * RENDER_RAY_TREE. Deterministic, unlike the clock: the same scene
     * fails for any thread count. */
    uint64_t max_tree_rays;
} RenderOptions;

/* --max-tree-rays' default: a ray tree that splits at every level
 * (reflecting, see-through surfaces with adc_bailout 0) is
 * 2^max_trace_level rays in one pixel and would never end (POV-Ray
 * crashes); 2^20 rays, about a second, is far beyond what a pixel of a
 * scene that can be rendered holds. */
#define RENDER_DEFAULT_MAX_TREE_RAYS (1L << 20)

/* render_image's failures. */
enum { RENDER_OUT_OF_MEMORY = -1, RENDER_PAST_DEADLINE = -2, RENDER_RAY_TREE = -3 };

/* The tiles a render is cut into: on the whole image's grid (POV-Ray's
 * anti-aliasing blocks from the area's corner), cut to the area rendered. */
typedef struct {
    int tile_size, tiles_x, ntiles;
    int grid_x0, grid_y0;   /* where the grid of tiles starts */
    int tile_x0, tile_y0;   /* the first tile's place in that grid */
    int x0, y0, x1, y1;     /* the pixels rendered */
} TileGrid;

void render_tile_grid(const RenderOptions *opt, TileGrid *t);
/* Tile `tile`'s pixels, [x0, x1) x [y0, y1). */
void render_tile_area(const TileGrid *t, int tile, int *x0, int *y0, int *x1, int *y1);

/* The thread count when none is given: the online cores (1 to 1024). */
int render_default_threads(void);

/* Renders into img (allocated here; with a tile source, only the tiles it
 * gave this process, the rest 0). Returns 0, or RENDER_OUT_OF_MEMORY,
 * RENDER_PAST_DEADLINE or RENDER_RAY_TREE (img is then freed either way). */
int render_image(const World *w, const Grid *g, const RenderOptions *opt, Image *img, RenderStats *stats);

#endif
