/* One pixel's analysis record (aov_pixel.h). */
#include "aov_pixel.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "shadow.h"

const char aov_code_legend[] = "0 none (no hit), 1 sustain, 2 self-shadow, 3 volume, 4 conventional, 5 cache hit, "
                               "6 faces away (not tested), 7 untested (shadows off, shadowless or dark light), "
                               "8 area lit, 9 area umbra, 10 area beam (an area light's samples, by hst's beam), "
                               "11 buffer lit, 12 buffer cover, 13 buffer list (a light buffer's cell)";

AovCode aov_code_of_scheme(int scheme)
{
    switch (scheme) {
    case SCHEME_SUSTAIN: return AOV_CODE_SUSTAIN;
    case SCHEME_SELF_SHADOW: return AOV_CODE_SELF_SHADOW;
    case SCHEME_VOLUME: return AOV_CODE_VOLUME;
    case SCHEME_CONVENTIONAL: return AOV_CODE_CONVENTIONAL;
    case SCHEME_CACHE_HIT: return AOV_CODE_CACHE_HIT;
    case SCHEME_AREA_LIT: return AOV_CODE_AREA_LIT;
    case SCHEME_AREA_UMBRA: return AOV_CODE_AREA_UMBRA;
    case SCHEME_AREA_BEAM: return AOV_CODE_AREA_BEAM;
    case SCHEME_BUFFER_LIT: return AOV_CODE_BUFFER_LIT;
    case SCHEME_BUFFER_COVER: return AOV_CODE_BUFFER_COVER;
    case SCHEME_BUFFER_LIST: return AOV_CODE_BUFFER_LIST;
    default: return AOV_CODE_UNTESTED;
    }
}

int aov_pixel_init(AovPixel *px, int nlights, int shadows_off)
{
    memset(px, 0, sizeof *px);
    px->nlights = nlights;
    px->shadows_off = shadows_off;
    px->light = calloc((size_t)(nlights > 0 ? nlights : 1), sizeof *px->light);
    return px->light ? 0 : -1;
}

void aov_pixel_free(AovPixel *px)
{
    free(px->light);
    px->light = NULL;
}

void aov_pixel_begin(AovPixel *px, uint64_t shadow_tests, uint64_t rays)
{
    px->hit = 0;
    px->z = INFINITY;
    px->n = px->p = v3(0, 0, 0);
    px->loss[0] = px->loss[1] = px->loss[2] = 0.0;
    for (int i = 0; i < px->nlights; i++) {
        px->light[i].visibility = 0.0f;
        px->light[i].code = AOV_CODE_NONE;
        px->light[i].depth = -1.0f;
    }
    px->shadow_tests = shadow_tests;
    px->rays = rays;
}

void aov_record_hit(AovPixel *px, double t, Vec3 point, Vec3 normal)
{
    px->hit = 1;
    px->z = t;
    px->p = point;
    px->n = normal;
}

void aov_record_light(AovPixel *px, int light, AovCode code, double visibility, int depth)
{
    if (light < 0 || light >= px->nlights)
        return;
    if (px->shadows_off && code != AOV_CODE_FACES_AWAY) {
        code = AOV_CODE_UNTESTED;
        visibility = 1.0;
        depth = -1;
    }
    px->light[light].code = (uint32_t)code;
    px->light[light].visibility = (float)visibility;
    px->light[light].depth = (float)depth;
}

void aov_record_loss(AovPixel *px, const double unshadowed[3], const double shadowed[3])
{
    for (int k = 0; k < 3; k++)
        px->loss[k] += unshadowed[k] - shadowed[k];
}
