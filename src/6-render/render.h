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

typedef struct {
    int width, height;
    /* The pixels rendered, [x0, x1) x [y0, y1) (a partial render); the rest
     * of the image stays 0. All zero: the whole image. */
    int x0, y0, x1, y1;
    int threads;              /* >= 1 */
    Antialias aa;             /* method 0: none (one camera ray through each pixel's centre) */
    Quality quality;
    const ShadowMethod *shadow;
    const Bvh *bvh;           /* the polygon queries' hierarchy; NULL: the grid's walk */
    const struct ShadowVolumes *volumes; /* when the method uses them */
    const struct EmbreeScene *embree;    /* when the method is embree */
    const struct CostModel *cost;        /* hst's per-point N_th */
    double nth;               /* hst: N_th; negative: per point */
    int verify;               /* 1 --verify-shadows, 2 --verify-reference too */
    int pixel_coherence;      /* hst: count from the neighbouring pixel's hit */
    int progress;             /* print a progress line on stderr */
    struct AovImage *aov;     /* --aov: the analysis channels to fill, or NULL */
} RenderOptions;

/* The thread count when none is given: the online cores (1 to 1024). */
int render_default_threads(void);

/* Renders into img (allocated here). Returns 0, or -1 when out of memory. */
int render_image(const World *w, const Grid *g, const RenderOptions *opt, Image *img, RenderStats *stats);

#endif
