/* Normal perturbation as POV-Ray 3.7 computes it (normal.cpp there).
 *
 * A normal's pattern space is reached as a pigment's: its transform, then
 * its turbulence. The surface normal goes with it (Warp_Normal: the
 * transpose of the transform, normalised unless no_bump_scale), is
 * displaced there, and comes back (UnWarp_Normal: the inverse transpose).
 * The patterns made for normals (bumps, dents, wrinkles, waves, ripples,
 * quilted) displace it by formulas of their own; any other pattern by its
 * slope, which POV-Ray samples at the four corners of a tetrahedron of
 * size `accuracy` around the point, each value through the slope_map.
 * The floating-point operations follow POV-Ray's order, and the values it
 * keeps in single precision (bump_size, accuracy, map values) are kept so
 * here too, so that the normals are POV-Ray's to the last bits. */
#include <math.h>
#include <stdlib.h>

#include "deadline.h"
#include "noise.h"
#include "normal.h"
#include "patterns.h"
#include "pigment.h"
#include "transform.h"

/* POV-Ray's Pyramid_Vect: the corners of a regular tetrahedron. */
static const Vec3 pyramid[4] = {
    { 0.942809041, -0.333333333, 0.0 },
    { -0.471404521, -0.333333333, 0.816496581 },
    { -0.471404521, -0.333333333, -0.816496581 },
    { 0.0, 1.0, 0.0 },
};

NormalSetting normal_setting_of(const World *w)
{
    NormalSetting s = { w->number_of_waves, w->noise_generator };
    if (s.nwaves < 1)
        s.nwaves = 1;
    if (s.nwaves > MAX_NUMBER_OF_WAVES)
        s.nwaves = MAX_NUMBER_OF_WAVES;
    return s;
}

/* POV-Ray's cycloidal(): a sine of period 1, through the fraction. */
static double cycloidal(double v)
{
    if (v >= 0.0)
        return sin((v - floor(v)) * 50000.0 / 50000.0 * (2.0 * M_PI));
    return 0.0 - sin((0.0 - (v + floor(0.0 - v))) * 50000.0 / 50000.0 * (2.0 * M_PI));
}

/* normal += s * v, as VAddScaledEq. */
static Vec3 add_scaled(Vec3 normal, double s, Vec3 v)
{
    return v3(normal.x + s * v.x, normal.y + s * v.y, normal.z + s * v.z);
}

/* Waves and ripples: a sum over the scene's wave sources of sines of the
 * distance, each pushing the normal away from its source. */
static Vec3 waves(const NormalSetting *s, const SceneNormal *n, Vec3 p, Vec3 normal, int own_frequencies)
{
    const double amount = (double)(float)n->amount, freq = n->pattern.frequency, phase = n->pattern.phase;
    for (int i = 0; i < s->nwaves; i++) {
        Vec3 d = v3_sub(p, wave_source(i));
        double length = v3_length(d);
        if (length == 0.0)
            length = 1.0;
        double scalar;
        if (own_frequencies) {
            double index = length * freq * wave_frequency(i) + phase;
            scalar = cycloidal(index) * amount / wave_frequency(i);
        } else {
            double index = length * freq + phase;
            scalar = cycloidal(index) * amount;
        }
        normal = add_scaled(normal, scalar / (length * (double)s->nwaves), d);
    }
    return normal;
}

static Vec3 wrinkles(const SceneNormal *n, Vec3 p, Vec3 normal)
{
    Vec3 r = v3(0, 0, 0);
    double scale = 1.0;
    for (int i = 0; i < 10; scale *= 2.0, i++) {
        Vec3 v = noise_vector(v3(p.x * scale, p.y * scale, p.z * scale));
        r.x += fabs(v.x / scale);
        r.y += fabs(v.y / scale);
        r.z += fabs(v.z / scale);
    }
    return add_scaled(normal, n->amount, r);
}

static Vec3 quilted(const SceneNormal *n, Vec3 p, Vec3 normal)
{
    Vec3 v = v3(p.x - pattern_floor(p.x) - 0.5, p.y - pattern_floor(p.y) - 0.5, p.z - pattern_floor(p.z) - 0.5);
    double t = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    t = quilt_cubic(t, n->pattern.control0, n->pattern.control1);
    v = v3(v.x * t, v.y * t, v.z * t);
    return add_scaled(normal, n->amount, v);
}

/* POV-Ray's Colour::greyscale, in its single-precision colour. */
static float greyscale(Colour c)
{
    return (float)(0.297 * (double)(float)c.r + 0.589 * (double)(float)c.g + 0.114 * (double)(float)c.b);
}

/* bump_map: the picture's brightness as heights at three pixels (the
 * point's, one left and down, one right and down) make a triangle whose
 * normal is set in the frame of the surface normal. */
static Vec3 bump_map(const SceneNormal *n, Vec3 p, Vec3 normal)
{
    const Pigment *pig = &n->pattern;
    const double iw = (double)pig->image->width, ih = (double)pig->image->height;
    double x, y;
    if (!image_map_position(pig, p, &x, &y))
        return normal;
    int i1, i2, i3; /* palette entries (-1: none) */
    Colour c1 = image_colour_index_at(pig, x, y, &i1, 1);
    x -= 1.0;
    y += 1.0;
    if (x < 0.0)
        x += iw;
    else if (x >= iw)
        x -= iw;
    if (y < 0.0)
        y += ih;
    else if (y >= ih)
        y -= ih;
    Colour c2 = image_colour_index_at(pig, x, y, &i2, 1);
    x += 2.0;
    if (x < 0.0)
        x += iw;
    else if (x >= iw)
        x -= iw;
    Colour c3 = image_colour_index_at(pig, x, y, &i3, 1);
    const float amount = (float)n->amount;
    Vec3 p1 = v3(0.0, (double)(amount * greyscale(c1)), 0.0);
    Vec3 p2 = v3(-1.0, (double)(amount * greyscale(c2)), 1.0);
    Vec3 p3 = v3(1.0, (double)(amount * greyscale(c3)), 1.0);
    if (pig->image_use_index && i1 != -1 && i2 != -1 && i3 != -1) {
        /* use_index on a colour-mapped picture: the entries are the heights */
        p1.y = n->amount * i1;
        p2.y = n->amount * i2;
        p3.y = n->amount * i3;
    }
    Vec3 bump = v3_normalize(v3_cross(v3_sub(p3, p2), v3_sub(p1, p2)));

    Vec3 yp = normal;
    Vec3 xp = v3_cross(yp, v3(0.0, 1.0, 0.0));
    double length = v3_length(xp);
    if (length < POV_EPSILON) {
        yp = fabs(normal.y - 1.0) < POV_EPSILON ? v3(0.0, 1.0, 0.0) : v3(0.0, -1.0, 0.0);
        xp = v3(1.0, 0.0, 0.0);
        length = 1.0;
    }
    xp = v3_scale(xp, 1.0 / length);
    Vec3 zp = v3_normalize(v3_cross(xp, yp));
    xp = v3_scale(xp, bump.x);
    yp = v3_scale(yp, bump.y);
    zp = v3_scale(zp, bump.z);
    Vec3 t = v3_add(xp, yp);
    zp = v3_scale(zp, -1.0);
    return v3_add(t, zp);
}

/* POV-Ray's Hermite_Cubic between two [height, slope] pairs. */
static double hermite_cubic(double t, const SlopeMapEntry *a, const SlopeMapEntry *b)
{
    double tt = t * t, ttt = tt * t;
    double rv = ttt * (a->slope + b->slope + 2.0 * (a->height - b->height));
    rv += -tt * (2.0 * a->slope + b->slope + 3.0 * (a->height - b->height));
    rv += t * a->slope + a->height;
    return rv;
}

/* POV-Ray's Search_Blend_Map over values in single precision: the entries
 * around v (both the same one at or beyond the ends, or on an entry). */
static void search_map(const double *values, size_t stride, int n, double v, int *prev, int *cur)
{
#define VALUE(i) (*(const double *)((const char *)values + (size_t)(i) * stride))
    int p = 0, c = 0;
    if (v >= VALUE(n - 1)) {
        p = c = n - 1;
    } else {
        while (v > VALUE(c))
            p = c++;
    }
    if (v == VALUE(c))
        p = c;
    *prev = p;
    *cur = c;
#undef VALUE
}

static double slope_map(const SceneNormal *n, double v)
{
    if (n->nslope == 0)
        return v;
    int prev, cur;
    search_map(&n->slope[0].value, sizeof n->slope[0], n->nslope, v, &prev, &cur);
    if (prev == cur)
        return n->slope[cur].height;
    const SlopeMapEntry *a = &n->slope[prev], *b = &n->slope[cur];
    return hermite_cubic((v - a->value) / (b->value - a->value), a, b);
}

/* Warp_Normal and UnWarp_Normal: into the pattern's space and back. */
static Vec3 warp_normal(const SceneNormal *n, const Transform *tr, Vec3 v)
{
    if (!n->no_bump_scale)
        v = v3_normalize(v);
    v = inverse_transform_normal(tr, v);
    return n->no_bump_scale ? v : v3_normalize(v);
}

static Vec3 unwarp_normal(const SceneNormal *n, const Transform *tr, Vec3 v)
{
    if (!n->no_bump_scale)
        v = v3_normalize(v);
    v = transform_normal(tr, v);
    return n->no_bump_scale ? v : v3_normalize(v);
}

/* Warp_EPoint: the transform, then the turbulence. */
static Vec3 warp_point(const SceneNormal *n, const Transform *tr, Vec3 p)
{
    return pattern_warp(&n->pattern, inverse_transform_point(tr, p));
}

static Vec3 perturb(const NormalSetting *s, const SceneNormal *n, const Transform *trp, const Transform *trn, Vec3 p,
                    Vec3 uv, Vec3 normal);

/* The pattern's value selects two normals of the map; their perturbations
 * are blended linearly between the entries' values. */
static Vec3 normal_map(const NormalSetting *s, const SceneNormal *n, const Transform *trp, const Transform *trn,
                       Vec3 p, Vec3 uv, Vec3 normal)
{
    Vec3 tp = warp_point(n, trp, p);
    double value = pattern_value_warped(&n->pattern, tp, s->noise_generator, s->nwaves);
    int prev, cur;
    search_map(&n->map[0].value, sizeof n->map[0], n->nmap, value, &prev, &cur);
    normal = warp_normal(n, trn, normal);
    Vec3 other = normal;
    const SceneNormal *c = n->map[cur].normal;
    normal = perturb(s, c, c ? &c->pattern.transform : NULL, c ? &c->pattern.transform : NULL, tp, uv, normal);
    if (prev != cur) {
        const SceneNormal *q = n->map[prev].normal;
        other = perturb(s, q, q ? &q->pattern.transform : NULL, q ? &q->pattern.transform : NULL, tp, uv, other);
        double b = (value - n->map[prev].value) / (n->map[cur].value - n->map[prev].value), a = 1.0 - b;
        normal = v3(a * other.x + b * normal.x, a * other.y + b * normal.y, a * other.z + b * normal.z);
    }
    normal = unwarp_normal(n, trn, normal);
    return v3_normalize(normal);
}

/* average: the entries' perturbations of the same normal, weighed by their
 * values (single precision, as POV-Ray sums them). */
static Vec3 average(const NormalSetting *s, const SceneNormal *n, Vec3 tp, Vec3 uv, Vec3 normal)
{
    Vec3 sum = v3(0, 0, 0);
    float total = 0.0f;
    for (int i = 0; i < n->nmap; i++) {
        const SceneNormal *e = n->map[i].normal;
        float w = (float)n->map[i].value;
        const Transform *t = e ? &e->pattern.transform : NULL;
        Vec3 v = perturb(s, e, t, t, tp, uv, normal);
        sum = add_scaled(sum, (double)w, v);
        total += w;
    }
    return v3(sum.x / (double)total, sum.y / (double)total, sum.z / (double)total);
}

Vec3 normal_pattern_displace(const NormalSetting *s, const SceneNormal *n, Vec3 tp, Vec3 normal)
{
    switch (n->kind) {
    case NORMAL_BUMPS:
        return add_scaled(normal, n->amount, noise_vector(tp));
    case NORMAL_DENTS: {
        int generator = n->pattern.noise_generator ? n->pattern.noise_generator : s->noise_generator;
        double noise = noise_value(tp, generator);
        noise = noise * noise * noise * n->amount;
        return add_scaled(normal, noise, noise_vector(tp));
    }
    case NORMAL_WRINKLES: return wrinkles(n, tp, normal);
    case NORMAL_WAVES: return waves(s, n, tp, normal, 1);
    case NORMAL_RIPPLES: return waves(s, n, tp, normal, 0);
    case NORMAL_QUILTED: return quilted(n, tp, normal);
    case NORMAL_BUMP_MAP: return bump_map(n, tp, normal);
    default: return normal;
    }
}

/* POV-Ray's Perturb_Normal, for normal n whose pattern space `trp` takes
 * to the space of p, and `trn` to the space of the normal (the same but
 * for a texture_map's entries, whose normals come from world through the
 * map's transforms). */
static Vec3 perturb(const NormalSetting *s, const SceneNormal *n, const Transform *trp, const Transform *trn, Vec3 p,
                    Vec3 uv, Vec3 normal)
{
    if (!n || n->kind == NORMAL_NONE) /* a map's missing entry, or a pattern not evaluated */
        return normal;
    /* nested maps and averages may ask for 2^40 normals at one point:
     * past --max-render-seconds each ends at once (the render is
     * discarded) */
    if (deadline_step())
        return normal;
    if (n->kind == NORMAL_UV) {
        /* the entry at the surface's (u, v, 0), the normal's own warps unused */
        const SceneNormal *e = n->uv_entry;
        return v3_normalize(perturb(s, e, &e->pattern.transform, &e->pattern.transform, uv, uv, normal));
    }
    if (n->nmap > 0 && n->kind != NORMAL_AVERAGE)
        return normal_map(s, n, trp, trn, p, uv, normal);
    normal = warp_normal(n, trn, normal);
    Vec3 tp = warp_point(n, trp, p);
    if (n->kind == NORMAL_AVERAGE) {
        normal = average(s, n, tp, uv, normal);
    } else if (n->kind != NORMAL_PATTERN) {
        normal = normal_pattern_displace(s, n, tp, normal);
    } else {
        /* the slope, from four samples around the point */
        double amount = (double)(float)n->amount * -5.0;
        amount *= 0.02 / (double)(float)n->accuracy;
        const double delta = (double)(float)n->accuracy;
        for (int i = 0; i < 4; i++) {
            Vec3 q = v3_madd(tp, pyramid[i], delta);
            double v = slope_map(n, pattern_value_warped(&n->pattern, q, s->noise_generator, s->nwaves));
            normal = add_scaled(normal, v * amount, pyramid[i]);
        }
    }
    return unwarp_normal(n, trn, normal);
}

Vec3 normal_perturb(const NormalSetting *s, const SceneNormal *n, const Transform *to_texture, Vec3 point, Vec3 uv,
                    Vec3 normal)
{
    Vec3 r = perturb(s, n, to_texture, to_texture, point, uv, normal);
    return n->no_bump_scale ? v3_normalize(r) : r; /* else UnWarp_Normal has normalised it */
}

Vec3 normal_perturb_in(const NormalSetting *s, const SceneNormal *n, const Transform *parent_to_world, Vec3 point,
                       Vec3 uv, Vec3 normal)
{
    Transform to_world = n->pattern.transform;
    transform_compose(&to_world, parent_to_world);
    Vec3 r = perturb(s, n, &n->pattern.transform, &to_world, point, uv, normal);
    return n->no_bump_scale ? v3_normalize(r) : r;
}
