/* Patterns that are closed forms of the point (POV-Ray 3.7's
 * leopard_pattern, onion_pattern, radial_pattern, planar_pattern,
 * spherical_pattern, cylindrical_pattern, boxed_pattern, quilted_pattern),
 * in the same order of operations. */
#include <math.h>

#include "patterns.h"

double pattern_floor(double x)
{
    return x >= 0.0 ? floor(x) : (0.0 - floor(0.0 - x) - 1.0);
}

/* POV-Ray's CLIP_DENSITY: 1 at the centre falling to 0 at distance 1, and
 * 0 beyond (the density patterns' shape). */
static double clip_density(double r)
{
    if (r < 0.0)
        return 1.0;
    if (r > 1.0)
        return 0.0;
    return 1.0 - r;
}

double leopard_value(Vec3 p)
{
    double s = (sin(p.x) + sin(p.y) + sin(p.z)) / 3.0;
    return s * s;
}

/* Concentric shells of width 1, each rising from 0 to 1. */
double onion_value(Vec3 p)
{
    return fmod(sqrt(p.x * p.x + p.y * p.y + p.z * p.z), 1.0);
}

/* The angle about the y axis from -z, a quarter turn on; near the axis,
 * where the angle is unsteady, 0.25 as POV-Ray answers. */
double radial_value(Vec3 p)
{
    if (fabs(p.x) < 0.001 && fabs(p.z) < 0.001)
        return 0.25;
    return 0.25 + (atan2(p.x, p.z) + M_PI) / (2.0 * M_PI);
}

double planar_value(Vec3 p)
{
    return clip_density(fabs(p.y));
}

double spherical_value(Vec3 p)
{
    return clip_density(sqrt(p.x * p.x + p.y * p.y + p.z * p.z));
}

double cylindrical_value(Vec3 p)
{
    return clip_density(sqrt(p.x * p.x + p.z * p.z));
}

double boxed_value(Vec3 p)
{
    return clip_density(fmax(fabs(p.x), fmax(fabs(p.y), fabs(p.z))));
}

double quilt_cubic(double t, double control0, double control1)
{
    double it = 1.0 - t, itsqrd = it * it, tsqrd = t * t, tcubed = t * tsqrd;
    /* 1.154700538 = 2 / sqrt(3): the corner of a unit cube's half at 1 */
    return (tcubed + 3.0 * t * itsqrd * control0 + 3.0 * tsqrd * it * control1) * 1.154700538;
}

/* The offset from the centre of the point's unit cube, scaled by
 * quilt_cubic of its length: the mean of its components' sizes. */
double quilted_value(const Pigment *pig, Vec3 p)
{
    Vec3 v = v3(p.x - pattern_floor(p.x) - 0.5, p.y - pattern_floor(p.y) - 0.5, p.z - pattern_floor(p.z) - 0.5);
    double t = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    t = quilt_cubic(t, pig->control0, pig->control1);
    return (fabs(v.x * t) + fabs(v.y * t) + fabs(v.z * t)) / 3.0;
}
