/* Fog along a ray, as POV-Ray 3.7 computes it (Trace::ComputeFog and its
 * constant and ground fog colours, with turbulence). */
#include <math.h>

#include "fog.h"
#include "noise.h"

#define POV_BOUND_HUGE 2.0e10 /* POV-Ray's depth of a ray that hits nothing */

static double greyscale(double r, double g, double b) { return 0.297 * r + 0.589 * g + 0.114 * b; }

/* Turbulence thins the fog along a ray: the fog's width shrinks by the
 * turbulence at `at` (scaled by the fog's turbulence vector), the less the
 * longer the ray. */
static double turbulent_width(const World *w, const SceneFog *f, Vec3 at, double width)
{
    if (!f->turbulent)
        return width;
    double k = exp(-width / f->distance);
    if (k == 0.0) /* a ray into the distance (or to the sky): turbulence has no say */
        return width;
    Vec3 p = v3(at.x * f->turbulence.x, at.y * f->turbulence.y, at.z * f->turbulence.z);
    double t = noise_turbulence(p, f->octaves, f->omega, f->lambda, w->noise_generator) * f->turb_depth;
    return width * (1.0 - k * fmin(1.0, t));
}

/* Transmittance of a constant fog over `width` from org. */
static double constant_fog(const World *w, const SceneFog *f, Vec3 org, Vec3 dir, double width)
{
    width = turbulent_width(w, f, v3_add(org, v3_scale(dir, width / 2.0)), width);
    return exp(-width / f->distance);
}

/* Transmittance of a ground fog over `width` from org: the density is 1
 * below the offset and 1 / (1 + h^2) at h alts above it, averaged along the
 * ray by its integral (atan). */
static double ground_fog(const World *w, const SceneFog *f, Vec3 org, Vec3 dir, double width)
{
    if (f->alt == 0.0) /* POV-Ray divides by it; hstrace takes a fog without height falloff */
        return constant_fog(w, f, org, dir, width);
    Vec3 end_point = v3_add(org, v3_scale(dir, width));
    double start = (v3_dot(org, f->up) - f->offset) / f->alt;
    double end = (v3_dot(end_point, f->up) - f->offset) / f->alt;
    double density;
    if (start <= 0.0) {
        density = end <= 0.0 ? 1.0 : (atan(end) - start) / (end - start);
    } else if (end <= 0.0) {
        density = (atan(start) - end) / (start - end);
    } else {
        double delta = start - end;
        density = fabs(delta) > POV_EPSILON ? (atan(start) - atan(end)) / delta : 1.0 / (start * start + 1.0);
    }
    Vec3 middle = v3_scale(v3_add(org, end_point), 0.5);
    width = turbulent_width(w, f, middle, width);
    return exp(-width * density / f->distance);
}

void fog_apply(const World *w, Vec3 org, Vec3 dir, double depth, Radiance *seen)
{
    double width = depth == HUGE_VAL ? POV_BOUND_HUGE : depth;
    double keep[3] = { 1.0, 1.0, 1.0 }; /* what the fogs let through */
    double add[3] = { 0.0, 0.0, 0.0 };  /* the fogs' own colour */
    for (int i = 0; i < w->nfogs; i++) {
        const SceneFog *f = &w->fogs[i];
        if (fabs(f->distance) <= POV_EPSILON)
            continue;
        double att = f->type == 2 ? ground_fog(w, f, org, dir, width) : constant_fog(w, f, org, dir, width);
        const Colour *c = &f->colour;
        if (att < c->transmit) /* a transmitting fog colour lets at least that much through */
            att = c->transmit;
        const double rgb[3] = { c->r, c->g, c->b };
        for (int k = 0; k < 3; k++) {
            keep[k] *= att * ((1.0 - c->filter) + c->filter * rgb[k]);
            add[k] += (1.0 - att) * rgb[k];
        }
    }
    seen->r = add[0] + keep[0] * seen->r;
    seen->g = add[1] + keep[1] * seen->g;
    seen->b = add[2] + keep[2] * seen->b;
    seen->transmit *= greyscale(keep[0], keep[1], keep[2]);
}
