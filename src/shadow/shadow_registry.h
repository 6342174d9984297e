/* The registry of shadow methods: every method a row, the first the
 * default, and the only place that names them all. The rest of the program
 * finds a method by name (--shadows), prepares it for the render and frees
 * what it prepared through here. It stands above every method (their rows
 * hold their functions): no method calls it. */
#ifndef HST_SHADOW_REGISTRY_H
#define HST_SHADOW_REGISTRY_H

#include "shadow.h"

/* NULL when no method has that name. */
const ShadowMethod *shadow_method_find(const char *name);
/* Whether method m decides on a world with instances (instance.h): with
 * hst's --volumes always (volumes_always) or any area light (area_lights)
 * in the scene, or not. A method that does not gets a flattened world. */
int shadow_method_takes_instances(const ShadowMethod *m, int volumes_always, int area_lights);
/* Why this build cannot use method m (embree without Embree), or NULL. */
const char *shadow_method_unavailable(const ShadowMethod *m);
/* Names of all methods, comma separated, for messages and --help. */
const char *shadow_method_names(void);

/* Prepares method m for the render (shadows_on: its prepare; else nothing
 * but the defaults). Returns 0, or -1 with a message in err (out of
 * memory, a library that failed); out is to be freed either way. */
int shadow_method_prepare(const ShadowMethod *m, const ShadowSetup *s, ShadowPrepared *out, char *err, int errlen);
void shadow_prepared_free(ShadowPrepared *p);

#endif
