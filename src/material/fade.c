/* An interior's fade (see fade.h). */
#include "fade.h"

#include <math.h>

RGB interior_fade(const Material *m, double depth)
{
    const RGB c = m->fade_colour;
    if (m->fade_power >= 1000) {
        double k = depth / m->fade_distance;
        return (RGB){ exp(-(1.0 - c.r) * k), exp(-(1.0 - c.g) * k), exp(-(1.0 - c.b) * k) };
    }
    double a = 1.0 + pow(depth / m->fade_distance, m->fade_power);
    return (RGB){ c.r + (1.0 - c.r) / a, c.g + (1.0 - c.g) / a, c.b + (1.0 - c.b) / a };
}

int interior_fades_shadows(const Material *m)
{
    return m->fade_power > 0.0 && fabs(m->fade_distance) > POV_EPSILON;
}
