/* The registry of shadow methods. */
#include "shadow.h"

#include <string.h>

/* --shadows=none: every light reaches every point (POV-Ray's +Q3 look). */
static void shadow_none_test(TraceContext *ctx, const ShadowQuery *q, RGB *light)
{
    (void)ctx;
    (void)q;
    light->r = light->g = light->b = 1.0;
}

static const ShadowMethod methods[] = {
    { "conventional", "a shadow ray per light through the grid (exact reference)", shadow_conventional_test },
    { "none", "no shadows: every light reaches every point", shadow_none_test },
};

const ShadowMethod *shadow_method_find(const char *name)
{
    for (size_t i = 0; i < sizeof methods / sizeof methods[0]; i++)
        if (strcmp(methods[i].name, name) == 0)
            return &methods[i];
    return NULL;
}

const char *shadow_method_names(void)
{
    return "conventional, none";
}
