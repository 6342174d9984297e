/* One pixel's analysis record (--aov), filled while the pixel is traced:
 * what the camera ray's first hit was, and what became of each light there
 * (which sub-scheme decided, the visibility, the depth count). The render
 * loop stores it into the analysis planes (aov.h). */
#ifndef HST_AOV_PIXEL_H
#define HST_AOV_PIXEL_H

#include <stdint.h>

#include "vecmath.h"

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
    AOV_CODE_AREA_LIT = 8,     /* hst: every sample of an area light proved lit by its beam */
    AOV_CODE_AREA_UMBRA = 9,   /* hst: ... proved blocked (the point in the light's umbra) */
    AOV_CODE_AREA_BEAM = 10,   /* hst: ... decided sample by sample against the beam's candidates */
    AOV_CODE_BUFFER_LIT = 11,  /* light buffer (hst, light-buffer): no candidate nearer the light */
    AOV_CODE_BUFFER_COVER = 12, /* ... a polygon covering the cell, nearer the light */
    AOV_CODE_BUFFER_LIST = 13, /* ... the cell's nearer candidates tested */
    AOV_NCODES
} AovCode;

/* The codes as one line, "0 none, 1 sustain, ...", for the EXR header. */
extern const char aov_code_legend[];

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
/* Before the pixel is traced; shadow_tests and rays: the thread's counters of
 * shadow-polygon and polygon tests in shadow testing, and of rays traced. */
void aov_pixel_begin(AovPixel *px, uint64_t shadow_tests, uint64_t rays);

/* The primary hit: its distance along the camera ray, point and normal. */
void aov_record_hit(AovPixel *px, double t, Vec3 point, Vec3 normal);
/* A light at the primary hit. */
void aov_record_light(AovPixel *px, int light, AovCode code, double visibility, int depth);
/* A light's share of the shading without and with its shadow. */
void aov_record_loss(AovPixel *px, const double unshadowed[3], const double shadowed[3]);

/* The code for a shadow method's sub-scheme (ShadowScheme). */
AovCode aov_code_of_scheme(int scheme);

#endif
