/* Analysis channels (--aov): per-pixel values written into the EXR beside
 * R G B A, so that one file shows where each light's shadows are, which
 * sub-scheme decided them and what they cost. Everything is recorded at the
 * camera ray's first hit (the primary hit), except the costs, which cover
 * the whole pixel (every ray of its tree, every light).
 *
 * Channels, by group (--aov Z,N,P,shadow,hst,depth,cost or all); lights are
 * numbered from 1 in the order of the scene's light_source statements:
 *   Z              distance from the ray's origin to the hit along the
 *                  camera ray; +inf where the ray hits nothing     FLOAT
 *   N.X N.Y N.Z    shading normal, world space, facing the camera   FLOAT
 *   P.X P.Y P.Z    hit point, world space                           FLOAT
 *   shadow.L<i>    fraction of light i arriving, as the shading used it:
 *                  1 lit, 0 blocked, between for light filtered by
 *                  transparent objects (POV-Ray's grey of the filter
 *                  colour); 0 where the surface faces away from the light
 *                  and where there is no hit; 1 where nothing was tested
 *                                                     half (--exr-float: FLOAT)
 *   shadow.loss.R/G/B  light the shadows took at the primary hit (all lights;
 *                  what a +Q3 render minus a +Q4 render shows)      as shadow.L<i>
 *   hst.L<i>       the code of the sub-scheme that decided (AovCode) UINT
 *   depth.L<i>     the depth count: opaque polygons between the point and
 *                  light i, -1 where the method does not know it    FLOAT
 *   cost.shadow    shadow-polygon and polygon tests of shadow testing UINT
 *   cost.rays      rays traced: camera, reflected, refracted, transmitted
 *                  and shadow rays                                  UINT
 * Geometry and depth are FLOAT whatever --exr-float says (positions need
 * more than half's 11 bits); codes and counts are exact integers. */
#ifndef HST_AOV_H
#define HST_AOV_H

#include <stdint.h>

#include "aov_pixel.h"
#include "image_buffer.h"

typedef enum { AOV_Z, AOV_N, AOV_P, AOV_SHADOW, AOV_HST, AOV_DEPTH, AOV_COST, AOV_NGROUPS } AovGroup;

#define AOV_ALL ((1u << AOV_NGROUPS) - 1u)

/* Parses "Z,N,shadow" or "all" into a set of groups. Returns 0, or -1 with
 * a message naming the valid groups. */
int aov_parse(const char *list, unsigned *groups, char *err, int errlen);

/* The channels of a render, as planes (image_buffer.h's ImageChannel). */
typedef struct AovImage {
    unsigned groups;
    int width, height, nlights;
    int nchannels;
    ImageChannel *channels;
    char (*names)[32];
    void *planes;               /* nchannels planes of width*height 4-byte samples */
    /* The first channel of each kind, -1 when not written. */
    int z, n, p, shadow, loss, hst, depth, cost;
} AovImage;

/* Returns 0, or -1 when out of memory. exr_float: shadow.* as FLOAT. */
int aov_image_alloc(AovImage *a, unsigned groups, int width, int height, int nlights, int exr_float);
void aov_image_free(AovImage *a);

/* Stores pixel (x, y)'s record into the planes; shadow_tests and rays: the
 * thread's counters now (aov_pixel_begin had them when the pixel began). */
void aov_image_store(AovImage *a, const AovPixel *px, uint64_t shadow_tests, uint64_t rays, int x, int y);

#endif
