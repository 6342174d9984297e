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

#include "image.h"
#include "stats.h"
#include "vecmath.h"

typedef enum { AOV_Z, AOV_N, AOV_P, AOV_SHADOW, AOV_HST, AOV_DEPTH, AOV_COST, AOV_NGROUPS } AovGroup;

#define AOV_ALL ((1u << AOV_NGROUPS) - 1u)

/* hst.L<i> codes: the shadow methods' sub-schemes, plus what happens when
 * no method is asked. */
typedef enum {
    AOV_CODE_NONE = 0,         /* no hit: the background */
    AOV_CODE_SUSTAIN = 1,      /* hst */
    AOV_CODE_SELF_SHADOW = 2,  /* hst */
    AOV_CODE_VOLUME = 3,       /* hst, volume */
    AOV_CODE_CONVENTIONAL = 4, /* the shadow ray: conventional, cache on a miss, hst, volume */
    AOV_CODE_CACHE_HIT = 5,    /* cache */
    AOV_CODE_FACES_AWAY = 6,   /* the surface faces away from the light: no method decided */
    AOV_CODE_UNTESTED = 7,     /* no test: shadows off (+Q3 or below, --shadows none), a
                                * shadowless light, a light adding nothing there */
    AOV_NCODES
} AovCode;

/* The codes as one line, "0 none, 1 sustain, ...", for the EXR header. */
extern const char aov_code_legend[];

/* Parses "Z,N,shadow" or "all" into a set of groups. Returns 0, or -1 with
 * a message naming the valid groups. */
int aov_parse(const char *list, unsigned *groups, char *err, int errlen);

/* The channels of a render, as planes (image.h's ImageChannel). */
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

/* What one light did at the primary hit. */
typedef struct {
    float visibility;
    uint32_t code;
    float depth;
} AovLight;

/* One pixel's record, filled while it is traced (one per render thread). */
typedef struct AovPixel {
    int hit;
    double z;
    Vec3 n, p;
    double loss[3];
    AovLight *light;
    int nlights;
    int shadows_off;            /* --shadows none: every light is untested */
    uint64_t shadow_tests, rays; /* counters when the pixel began */
} AovPixel;

int aov_pixel_init(AovPixel *px, int nlights, int shadows_off);
void aov_pixel_free(AovPixel *px);
void aov_pixel_begin(AovPixel *px, const RenderStats *s);
/* Stores the pixel (x, y) into the image; s: the counters now. */
void aov_pixel_end(AovPixel *px, const RenderStats *s, AovImage *img, int x, int y);

/* The primary hit: its distance along the camera ray, point and normal. */
void aov_record_hit(AovPixel *px, double t, Vec3 point, Vec3 normal);
/* A light at the primary hit. */
void aov_record_light(AovPixel *px, int light, AovCode code, double visibility, int depth);
/* A light's share of the shading without and with its shadow. */
void aov_record_loss(AovPixel *px, const double unshadowed[3], const double shadowed[3]);

/* The code for a shadow method's sub-scheme (ShadowScheme). */
AovCode aov_code_of_scheme(int scheme);

#endif
