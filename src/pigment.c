/* Pigment patterns, written from POV-Ray 3.7's definitions (checker_pattern,
 * hexagon_pattern, gradient_pattern, Evaluate_TPat's frequency/phase/wave,
 * Search_Blend_Map): the same small offsets, so that pattern borders fall
 * where POV-Ray puts them. */
#include "pigment.h"

#include <math.h>

#define POV_EPSILON 1.0e-10 /* POV-Ray's EPSILON */

/* POV-Ray's FLOOR macro: floor() written so that -0 and exact negative
 * integers land as POV-Ray's do. */
static double pov_floor(double x)
{
    return x >= 0.0 ? floor(x) : (0.0 - floor(0.0 - x) - 1.0);
}

static double checker_value(Vec3 p)
{
    /* The EPSILON nudges points on a cell face (a plane through whole
     * units, the usual case for a checkered floor) into the upper cell. */
    long v = (long)(floor(p.x + POV_EPSILON) + floor(p.y + POV_EPSILON) + floor(p.z + POV_EPSILON));
    return (v & 1) ? 1.0 : 0.0;
}

/* Hexagons in the x-z plane, three colours, as POV-Ray tiles them: a 6 x 6
 * grid of blocks half a unit wide and sqrt(3)/2 deep, some split along a
 * diagonal. */
static double hexagon_value(Vec3 p)
{
    const double xfactor = 0.5, zfactor = 0.866025404; /* POV-Ray's constants */
    double x = fabs(p.x);
    double z = p.z < 0.0 ? 5.196152424 - fabs(p.z) : p.z; /* no mirroring across x */
    double xs = x / xfactor, zs = z / zfactor;
    xs -= floor(xs / 6.0) * 6.0;
    zs -= floor(zs / 6.0) * 6.0;
    int xm = (int)pov_floor(xs) % 6, zm = (int)pov_floor(zs) % 6;
    static const int straight_05[6] = { 0, 1, 1, 2, 2, 0 }; /* columns 0 and 5 by zm */
    static const int straight_23[6] = { 2, 2, 0, 0, 1, 1 }; /* columns 2 and 3 */
    static const int below[6] = { 0, 2, 1, 0, 2, 1 };       /* split columns, under the diagonal */
    static const int above[6] = { 2, 1, 0, 2, 1, 0 };
    switch (xm) {
    case 0: case 5: return straight_05[zm];
    case 2: case 3: return straight_23[zm];
    default: {
        double xl = xs - xm, zl = zs - zm;
        if ((xm + zm) % 2 == 1)
            xl = 1.0 - xl; /* these blocks slope the other way */
        if (xl == 0.0)
            xl = 0.0001; /* POV-Ray's guard against dividing by zero */
        return zl / xl < 1.0 ? below[zm] : above[zm];
    }
    }
}

static double gradient_value(const Pigment *pig, Vec3 p)
{
    double v = v3_dot(p, pig->gradient);
    return v > 1.0 ? fmod(v, 1.0) : v;
}

static double wave(const Pigment *pig, double v)
{
    switch (pig->wave) {
    case WAVE_RAMP: return v;
    case WAVE_SINE: return (1.0 + sin(v * 2.0 * M_PI)) * 0.5;
    case WAVE_TRIANGLE: {
        double o = v - floor(v);
        return o >= 0.5 ? 2.0 * (1.0 - o) : 2.0 * o;
    }
    case WAVE_SCALLOP: return fabs(sin(v * 0.5 * 2.0 * M_PI));
    case WAVE_CUBIC: return v * v * (-2.0 * v + 3.0);
    case WAVE_POLY: return pow(v, pig->wave_exponent);
    }
    return v;
}

double pattern_value(const Pigment *pig, Vec3 p)
{
    double v;
    switch (pig->kind) {
    case PIGMENT_CHECKER: v = checker_value(p); break;
    case PIGMENT_HEXAGON: v = hexagon_value(p); break;
    case PIGMENT_GRADIENT: v = gradient_value(pig, p); break;
    default: return 0.0;
    }
    if (pig->frequency != 0.0)
        v = fmod(v * pig->frequency + pig->phase, 1.00001); /* POV-Ray's constant */
    if (v < 0.0)
        v -= floor(v);
    return wave(pig, v);
}

Colour colour_map_at(const ColourMapEntry *map, int n, double value)
{
    if (n <= 0) {
        Colour black = { 0, 0, 0, 0, 0 };
        return black;
    }
    if (value >= map[n - 1].value)
        return map[n - 1].colour;
    int c = 0;
    while (value > map[c].value)
        c++;
    if (c == 0 || value == map[c].value)
        return map[c].colour;
    const ColourMapEntry *a = &map[c - 1], *b = &map[c];
    double f = (value - a->value) / (b->value - a->value);
    Colour r = {
        a->colour.r + f * (b->colour.r - a->colour.r),
        a->colour.g + f * (b->colour.g - a->colour.g),
        a->colour.b + f * (b->colour.b - a->colour.b),
        a->colour.filter + f * (b->colour.filter - a->colour.filter),
        a->colour.transmit + f * (b->colour.transmit - a->colour.transmit),
    };
    return r;
}

Colour pigment_at(const Pigment *pig, Vec3 p)
{
    if (pig->kind == PIGMENT_SOLID)
        return pig->colour;
    return colour_map_at(pig->map, pig->nmap, pattern_value(pig, p));
}

int pigment_is_opaque(const Pigment *pig)
{
    if (pig->kind == PIGMENT_SOLID)
        return pig->colour.filter == 0.0 && pig->colour.transmit == 0.0;
    for (int i = 0; i < pig->nmap; i++)
        if (pig->map[i].colour.filter != 0.0 || pig->map[i].colour.transmit != 0.0)
            return 0;
    return 1;
}

Colour material_colour_at(const Material *m, Vec3 world_point)
{
    if (m->pattern.kind == PIGMENT_SOLID)
        return m->pigment;
    return pigment_at(&m->pattern, inverse_transform_point(&m->pattern_to_world, world_point));
}

RGB sky_colour(const World *w, Vec3 dir)
{
    RGB col = { 0, 0, 0 }, fil = { 1, 1, 1 };
    const SkySphere *sky = w->sky;
    if (sky) {
        /* POV-Ray transforms the direction as a point (MInvTransPoint) */
        Vec3 p = inverse_transform_point(&sky->transform, dir);
        for (int i = sky->npigments - 1; i >= 0; i--) { /* the last written is on top */
            const Pigment *pig = &sky->pigments[i];
            Colour c = pigment_at(pig, inverse_transform_point(&pig->transform, p));
            double opacity = 1.0 - c.filter - c.transmit;
            col.r += c.r * opacity * fil.r;
            col.g += c.g * opacity * fil.g;
            col.b += c.b * opacity * fil.b;
            fil.r *= c.r * c.filter + c.transmit;
            fil.g *= c.g * c.filter + c.transmit;
            fil.b *= c.b * c.filter + c.transmit;
        }
    }
    /* the background below, as one more (opaque: no alpha channel) layer */
    col.r += w->background.r * fil.r;
    col.g += w->background.g * fil.g;
    col.b += w->background.b * fil.b;
    return col;
}
