/* An interior's fade (POV-Ray 3.7's fade_distance, fade_power and
 * fade_colour): what is left of light that travelled a distance inside
 * it. One law, used by the rays seen through the interior (shade.c) and by
 * the shadow rays that cross it (shadow_conventional.c). */
#ifndef HST_FADE_H
#define HST_FADE_H

#include "world.h"

/* The colour light keeps after `depth` inside m's interior: with D the
 * fade distance, P the power and C the colour, C + (1 - C) / (1 + (depth/D)^P),
 * and for P >= 1000 (POV-Ray's "exponential" fade) exp(-(1 - C) depth / D).
 * The callers decide whether the interior fades at all; POV-Ray's two
 * callers ask differently (interior_fades_shadows). */
RGB interior_fade(const Material *m, double depth);

/* Whether a shadow ray crossing m's interior fades: POV-Ray's
 * ComputeShadowTexture asks for a positive power as well as a distance,
 * where rays seen through it (ComputeLightedTexture) ask only for the
 * distance. */
int interior_fades_shadows(const Material *m);

#endif
