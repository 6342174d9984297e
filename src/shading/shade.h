/* Shading: POV-Ray 3.7's classic model for one-layer textures (ambient,
 * emission, diffuse with brilliance, phong, specular, reflection, refraction
 * with ior, filter and transmit, max_trace_level, adc_bailout, light fading),
 * and its blend of them for texture_maps.
 * Shadows are asked of the context's shadow method. */
#ifndef HST_SHADE_H
#define HST_SHADE_H

#include "shadow.h"

struct AovPixel;

/* Which rays and tests a render performs: POV-Ray's +Q levels. */
typedef struct {
    int shadows;        /* Q >= 4 */
    int refraction;     /* Q >= 6 */
    int reflection;     /* Q >= 8 */
    int full_ambient;   /* Q <= 1: pigment colour only */
    int volume;         /* Q >= 9: fog, and POV-Ray's "advanced light" (radiosity) */
    int normal;         /* Q >= 8: normal perturbation */
    int area_lights;    /* Q >= 5: area lights sampled (below, a point light at the centre) */
} Quality;

/* The secondary rays shading sent, for the statistics (summed over threads). */
typedef struct {
#define SHADE_COUNTER(field, line, label, key, meaning) uint64_t field;
#include "shade_counters.def"
#undef SHADE_COUNTER
} ShadeCounters;

void shade_counters_add(ShadeCounters *total, const ShadeCounters *part);

#define MAX_INTERIOR_NESTING 16

/* The interiors a ray is inside, innermost last (for ior ratios; fog only
 * where all of them are hollow). */
typedef struct {
    int n;
    const void *key[MAX_INTERIOR_NESTING];
    double ior[MAX_INTERIOR_NESTING];
    unsigned char hollow[MAX_INTERIOR_NESTING];
} InteriorList;

/* A render thread's shading: its tracer (the ray queries and their
 * mailbox, which its shadow testing asks too), its shadow testing, what
 * the +Q level asks for, and the current pixel's analysis record. */
typedef struct {
    Tracer tracer;
    ShadowContext shadow;
    int depth;                /* ray segments being shaded: 1 at a camera ray's hit */
    Quality quality;
    ShadeCounters stats;
    struct AovPixel *aov;     /* --aov: the current pixel's record, or NULL when off */
    /* --max-render-seconds: the clock_wall() time the render must end by (0:
     * none), read every SHADE_CLOCK_RAYS rays; once past it, `expired` is
     * set and every ray returns black at once (a ray tree of 2^256 rays is
     * one pixel's: a check per tile alone would never come). */
    double deadline;
    unsigned rays_unchecked;
    int expired;
    /* --max-tree-rays: the rays one camera ray's tree may hold (0: no
     * limit), what is left of them in the current tree, and whether a tree
     * went past it (then every ray returns black at once). */
    uint64_t max_tree_rays, tree_rays_left;
    int tree_overflow;
    /* The interiors the last camera ray started in, and where it started
     * (shade_camera_interiors): every camera ray of a perspective camera
     * starts at its location. */
    int camera_inside_known;
    Vec3 camera_inside_at;
    InteriorList camera_inside;
    /* Of the camera rays' coincident surfaces (stats.coincident_hits), the
     * pair of materials of the least key ((a + 1) << 32 | (b + 1), a < b), 0: none. */
    uint64_t coincident_pair;
} ShadeContext;

#define SHADE_CLOCK_RAYS 1024


typedef struct {
    Vec3 org, dir;      /* dir is unit length */
    Hit from;           /* surface the ray leaves (kind HIT_NONE for camera rays) */
    InteriorList inside;
    const LightState *state;   /* shadow methods' state per light at org; NULL: the eye */
    /* POV-Ray's ray kinds for no_image / no_reflection: an image ray is a
     * camera ray or refracted from one; a reflection ray is reflected, or
     * refracted from one. Zero for camera rays. */
    unsigned not_image : 1, reflection : 1;
} Ray;

/* dst = src, its interiors alone (the first n of each array): the rest is
 * never read, and the whole list is some 280 bytes, copied for every ray. */
static inline void interior_copy(InteriorList *dst, const InteriorList *src)
{
    dst->n = src->n;
    for (int i = 0; i < src->n; i++) {
        dst->key[i] = src->key[i];
        dst->ior[i] = src->ior[i];
        dst->hollow[i] = src->hollow[i];
    }
}

/* A camera ray before its origin and direction are set: from nothing
 * (HIT_NONE), inside nothing, at the eye (no shadow state), an image ray.
 * Set field by field: a memset would clear its interior list's arrays,
 * which nothing reads past n. */
static inline void ray_init_camera(Ray *r)
{
    r->org = r->dir = v3(0, 0, 0);
    r->from = (Hit){ .kind = HIT_NONE };
    r->inside.n = 0;
    r->state = NULL;
    r->not_image = 0;
    r->reflection = 0;
}

/* The interiors a camera ray starts inside: those of the shapes whose
 * inside holds its origin, in the world's order (POV-Ray's
 * InitRayContainerState, which asks every object's Inside; hstrace asks
 * its shapes': planes, boxes and meshes are not asked). */
void shade_camera_interiors(ShadeContext *ctx, const World *w, Vec3 org, InteriorList *inside);

/* Colour seen along a ray: rgb plus transmittance (for the alpha channel). */
typedef struct {
    double r, g, b, transmit;
} Radiance;

/* Traces `ray` and returns what it sees. `level` counts rays already on the
 * path (0 for camera rays), as POV-Ray's trace level. */
void shade_trace(ShadeContext *ctx, const Ray *ray, double weight, int level, Radiance *out);

#endif
