/* Area lights sampled as POV-Ray 3.7 samples them (area_light.h). */
#include "area_light.h"

#include <math.h>
#include <string.h>

#include "shadow_decide.h"

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

Vec3 area_light_offset(const Light *l, Vec3 axis1, Vec3 axis2, double u, double v)
{
    const AreaLight *a = &l->area;
    if (a->circular) {
        /* The square's shells mapped onto circles: (u, v) in [-0.5, 0.5]
         * (nudged off the centre), scaled by max(|u|, |v|) / |(u, v)|. */
        u = u / (a->size1 - 1) - 0.5 + 0.001;
        v = v / (a->size2 - 1) - 0.5 + 0.001;
        double scale = (fabs(u) > fabs(v) ? fabs(u) : fabs(v)) / sqrt(u * u + v * v);
        return v3_add(v3_scale(axis1, u * scale), v3_scale(axis2, v * scale));
    }
    Vec3 o1 = a->size1 > 1 ? v3_scale(axis1, u / (double)(a->size1 - 1) - 0.5) : v3(0.0, 0.0, 0.0);
    Vec3 o2 = a->size2 > 1 ? v3_scale(axis2, v / (double)(a->size2 - 1) - 0.5) : v3(0.0, 0.0, 0.0);
    return v3_add(o1, o2);
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

void area_light_jitter(Vec3 p, int light, int u, int v, int stream, double *ju, double *jv)
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

double area_light_sample_ray(const Light *l, Vec3 offset, Vec3 p, Light *sample, Vec3 *to_light)
{
    *sample = *l;
    Vec3 centre = v3_add(l->location, offset);
    sample->location = centre;
    if (l->kind == LIGHT_PARALLEL) {
        /* From point_at toward the moved centre; the distance to the plane
         * through it, perpendicular to that. */
        Vec3 d = v3_normalize(v3_sub(centre, l->point_at));
        sample->direction = d;
        *to_light = d;
        return v3_dot(v3_sub(centre, p), d);
    }
    Vec3 d = v3_sub(centre, p);
    double distance = v3_length(d);
    *to_light = v3_scale(d, 1.0 / distance);
    return distance;
}

/* What one sampling of an area light at one point shares. */
typedef struct {
    ShadowContext *ctx;
    const ShadowQuery *q;
    const Light *light;
    Vec3 axis1, axis2;
    RGB lc;
} Sampling;

static RGB sample_at(Sampling *s, int u, int v)
{
    const Light *l = s->light;
    int at = u * l->area.size2 + v;
    if (s->ctx->area_known[at])
        return s->ctx->area_colour[at];
    double ju = (double)u, jv = (double)v;
    if (l->area.jitter) {
        double du, dv;
        area_light_jitter(s->q->point, s->q->light, u, v, 0, &du, &dv);
        ju += du;
        jv += dv;
    }
    Light sample;
    ShadowQuery q = *s->q;
    q.distance = area_light_sample_ray(l, area_light_offset(l, s->axis1, s->axis2, ju, jv), q.point, &sample,
                                       &q.to_light);
    q.source = &sample;
    RGB through;
    shadow_decide(s->ctx, &q, &through);
    s->ctx->stats.area_samples++;
    RGB c = { s->lc.r * through.r, s->lc.g * through.g, s->lc.b * through.b };
    s->ctx->area_colour[at] = c;
    s->ctx->area_known[at] = 1;
    return c;
}

static double colour_distance(RGB a, RGB b) { return fabs(a.r - b.r) + fabs(a.g - b.g) + fabs(a.b - b.b); }

/* The region [u1, u2] x [v1, v2] of the grid at subdivision level `level`. */
static RGB sample_region(Sampling *s, int u1, int v1, int u2, int v2, int level)
{
    RGB c[4] = { sample_at(s, u1, v1), sample_at(s, u2, v1), sample_at(s, u1, v2), sample_at(s, u2, v2) };
    if ((u2 - u1 > 1 || v2 - v1 > 1) &&
        (level < s->light->area.adaptive || colour_distance(c[0], c[1]) > 0.1 || colour_distance(c[1], c[3]) > 0.1 ||
         colour_distance(c[3], c[2]) > 0.1 || colour_distance(c[2], c[0]) > 0.1)) {
        /* POV-Ray's halves: floor and ceil of the midpoint (so a region
         * one sample wide splits into its two columns) */
        int ul = (int)floor((u1 + u2) / 2.0), uh = (int)ceil((u1 + u2) / 2.0);
        int vl = (int)floor((v1 + v2) / 2.0), vh = (int)ceil((v1 + v2) / 2.0);
        c[0] = sample_region(s, u1, v1, ul, vl, level + 1);
        c[1] = sample_region(s, uh, v1, u2, vl, level + 1);
        c[2] = sample_region(s, u1, vh, ul, v2, level + 1);
        c[3] = sample_region(s, uh, vh, u2, v2, level + 1);
    }
    RGB mean = { (c[0].r + c[1].r + c[2].r + c[3].r) * 0.25, (c[0].g + c[1].g + c[2].g + c[3].g) * 0.25,
                 (c[0].b + c[1].b + c[2].b + c[3].b) * 0.25 };
    return mean;
}

RGB area_light_shadow(ShadowContext *ctx, const ShadowQuery *q, RGB lc)
{
    const Light *l = &ctx->tracer.world->lights[q->light];
    Sampling s = { ctx, q, l, l->area.axis1, l->area.axis2, lc };
    area_light_axes(l, q->to_light, &s.axis1, &s.axis2);
    memset(ctx->area_known, 0, (size_t)l->area.size1 * (size_t)l->area.size2);
    ctx->stats.area_points++;
    return sample_region(&s, 0, 0, l->area.size1 - 1, l->area.size2 - 1, 0);
}
