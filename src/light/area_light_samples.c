/* Where an area light's samples lie (area_light_samples.h). */
#include "area_light_samples.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "light.h"

void area_light_axes(const Light *l, Vec3 centre_dir, Vec3 *axis1, Vec3 *axis2)
{
    *axis1 = l->area.axis1;
    *axis2 = l->area.axis2;
    if (!l->area.orient)
        return;
    /* Axis 1 across the ray, by the horizon when the ray is near the z
     * axis; axis 2 across both; both of axis 1's length. */
    double length = v3_length(l->area.axis1);
    Vec3 across = fabs(fabs(centre_dir.z) - 1.0) < 0.01 ? v3(0.0, 1.0, 0.0) : v3(0.0, 0.0, 1.0);
    Vec3 a1 = v3_normalize(v3_cross(centre_dir, across));
    Vec3 a2 = v3_normalize(v3_cross(centre_dir, a1));
    *axis1 = v3_scale(a1, length);
    *axis2 = v3_scale(a2, length);
}

/* The offset of grid position (u, v), jitter included. */
/* A sample's place on the grid, (u, v) in cells, as the factors of the
 * two axes that make its offset (grid_offset): what the point cannot
 * change unless it jitters, kept per thread (area_light_fixed_factors). */
static void grid_factors(const Light *l, double u, double v, double *f1, double *f2)
{
    const AreaLight *a = &l->area;
    if (a->circular) {
        /* The square's shells mapped onto circles: (u, v) in [-0.5, 0.5]
         * (nudged off the centre), scaled by max(|u|, |v|) / |(u, v)|. */
        u = u / (a->size1 - 1) - 0.5 + 0.001;
        v = v / (a->size2 - 1) - 0.5 + 0.001;
        double scale = (fabs(u) > fabs(v) ? fabs(u) : fabs(v)) / sqrt(u * u + v * v);
        *f1 = u * scale;
        *f2 = v * scale;
        return;
    }
    *f1 = a->size1 > 1 ? u / (double)(a->size1 - 1) - 0.5 : 0.0;
    *f2 = a->size2 > 1 ? v / (double)(a->size2 - 1) - 0.5 : 0.0;
}

Vec3 area_light_offset_of(const Light *l, Vec3 axis1, Vec3 axis2, const double f[2])
{
    const AreaLight *a = &l->area;
    if (a->circular)
        return v3_add(v3_scale(axis1, f[0]), v3_scale(axis2, f[1]));
    /* a light one sample wide has no offset along that axis (not 0 times
     * the axis, whose zeros may carry a sign) */
    Vec3 o1 = a->size1 > 1 ? v3_scale(axis1, f[0]) : v3(0.0, 0.0, 0.0);
    Vec3 o2 = a->size2 > 1 ? v3_scale(axis2, f[1]) : v3(0.0, 0.0, 0.0);
    return v3_add(o1, o2);
}

static Vec3 grid_offset(const Light *l, Vec3 axis1, Vec3 axis2, double u, double v)
{
    double f[2];
    grid_factors(l, u, v, &f[0], &f[1]);
    return area_light_offset_of(l, axis1, axis2, f);
}

static uint64_t mix64(uint64_t x)
{
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebull;
    x ^= x >> 31;
    return x;
}

static uint64_t bits_of(double d)
{
    uint64_t b;
    memcpy(&b, &d, sizeof b);
    return b;
}

static void jitter(Vec3 p, int light, int u, int v, int stream, double *ju, double *jv)
{
    uint64_t h = mix64(bits_of(p.x) + 0x9e3779b97f4a7c15ull);
    h = mix64(h ^ bits_of(p.y));
    h = mix64(h ^ bits_of(p.z));
    h = mix64(h ^ ((uint64_t)(uint32_t)light << 32 | (uint64_t)(uint32_t)stream));
    h = mix64(h ^ ((uint64_t)(uint32_t)u << 32 | (uint64_t)(uint32_t)v));
    /* two 26-bit fractions of one hash: [0, 1) each */
    *ju = (double)(h >> 38) / (double)(1u << 26) - 0.5;
    *jv = (double)((h >> 12) & ((1u << 26) - 1)) / (double)(1u << 26) - 0.5;
}

Vec3 area_light_sample_offset(const Light *l, int light, Vec3 p, Vec3 axis1, Vec3 axis2, int u, int v, int stream)
{
    double ju = (double)u, jv = (double)v;
    if (l->area.jitter) {
        double du, dv;
        jitter(p, light, u, v, stream, &du, &dv);
        ju += du;
        jv += dv;
    }
    return grid_offset(l, axis1, axis2, ju, jv);
}

int area_light_fixed_factors(const Light *l, double (**factors)[2])
{
    *factors = NULL;
    const size_t n = (size_t)l->area.size1 * (size_t)l->area.size2;
    if (!light_is_area(l) || l->area.jitter || n > AREA_FIXED_CAP)
        return 0;
    double(*f)[2] = malloc(n * sizeof *f);
    if (!f)
        return -1;
    for (int u = 0; u < l->area.size1; u++)
        for (int v = 0; v < l->area.size2; v++) {
            double *at = f[(size_t)u * (size_t)l->area.size2 + (size_t)v];
            grid_factors(l, (double)u, (double)v, &at[0], &at[1]);
        }
    *factors = f;
    return 0;
}

double area_light_sample_ray(const Light *l, Vec3 offset, Vec3 p, Vec3 *to_light)
{
    Vec3 centre = v3_add(l->location, offset);
    if (l->kind == LIGHT_PARALLEL) {
        /* From point_at toward the moved centre; the distance to the plane
         * through it, perpendicular to that. */
        Vec3 d = v3_normalize(v3_sub(centre, l->point_at));
        *to_light = d;
        return v3_dot(v3_sub(centre, p), d);
    }
    Vec3 d = v3_sub(centre, p);
    double distance = v3_length(d);
    *to_light = v3_scale(d, 1.0 / distance);
    return distance;
}

void area_light_sample_light(const Light *l, Vec3 offset, Vec3 to_light, Light *sample)
{
    sample->location = v3_add(l->location, offset);
    if (l->kind == LIGHT_PARALLEL)
        sample->direction = to_light;
}

/* The corners the sampling (area_light.c's sample_region) visits when every
 * sample agrees: it splits by level alone. */
static void mark_uniform(const Light *l, unsigned char *seen, int u1, int v1, int u2, int v2, int level)
{
    seen[u1 * l->area.size2 + v1] = seen[u2 * l->area.size2 + v1] = 1;
    seen[u1 * l->area.size2 + v2] = seen[u2 * l->area.size2 + v2] = 1;
    if ((u2 - u1 > 1 || v2 - v1 > 1) && level < l->area.adaptive) {
        int ul, uh, vl, vh;
        area_light_halves(u1, u2, &ul, &uh);
        area_light_halves(v1, v2, &vl, &vh);
        mark_uniform(l, seen, u1, v1, ul, vl, level + 1);
        mark_uniform(l, seen, uh, v1, u2, vl, level + 1);
        mark_uniform(l, seen, u1, vh, ul, v2, level + 1);
        mark_uniform(l, seen, uh, vh, u2, v2, level + 1);
    }
}

void area_light_uniform_shape(const Light *l, unsigned char *scratch, int *visits, int *levels)
{
    int n = l->area.size1 * l->area.size2;
    memset(scratch, 0, (size_t)n);
    mark_uniform(l, scratch, 0, 0, l->area.size1 - 1, l->area.size2 - 1, 0);
    *visits = 0;
    for (int i = 0; i < n; i++)
        *visits += scratch[i];
    /* A region's halves are equally wide (floor(w / 2) samples apart), so
     * every region of a level is alike: one chain of means. */
    int w = l->area.size1 - 1, h = l->area.size2 - 1;
    *levels = 1;
    for (int level = 0; (w > 1 || h > 1) && level < l->area.adaptive; level++) {
        w /= 2;
        h /= 2;
        ++*levels;
    }
}
