/* Shadow methods: one interface, selectable by name (--shadows). A method
 * answers, for a shading point and a light, how much of the light arrives:
 * (1,1,1) unblocked, (0,0,0) blocked by an opaque polygon, a colour when the
 * light passes through transparent (filter/transmit) polygons, as POV-Ray
 * filters it. The conventional shadow ray is the exact reference. */
#ifndef HST_SHADOW_H
#define HST_SHADOW_H

#include "tracer.h"

typedef struct {
    Vec3 point;          /* the shading point */
    const Hit *surface;  /* the surface it lies on (excluded from the test) */
    int light;           /* index into World.lights */
    Vec3 to_light;       /* unit direction toward the light */
    double distance;     /* to the light (parallel: to the light's plane) */
} ShadowQuery;

typedef struct ShadowMethod {
    const char *name;
    const char *summary;
    void (*test)(TraceContext *ctx, const ShadowQuery *q, RGB *light_through);
} ShadowMethod;

/* NULL when no method has that name. */
const ShadowMethod *shadow_method_find(const char *name);
/* Names of all methods, comma separated, for messages and --help. */
const char *shadow_method_names(void);

/* The exact test: a shadow ray walked through the grid to the light. */
void shadow_conventional_test(TraceContext *ctx, const ShadowQuery *q, RGB *light_through);

#endif
