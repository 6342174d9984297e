/* area_illumination's diffuse sum over a light's samples (area_diffuse.h). */
#include "area_diffuse.h"

#include <math.h>

#include "area_light_samples.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

int area_diffuse_applies(const Light *l, const double (*factors)[2])
{
    return factors && l->kind == LIGHT_POINT && l->beam == BEAM_NONE &&
           !(l->fade_power > 0.0 && fabs(l->fade_distance) > POV_EPSILON);
}

/* One sample's light into every texture that takes it, as shade.c's
 * add_diffuse adds it (its fade is 1: the light's share as it is). */
static void add_sample(const AreaDiffuseSamples *s, const AreaDiffuseTexture *t, int n, Vec3 to_light)
{
    for (int i = 0; i < n; i++) {
        double dot = v3_dot(t[i].normal, to_light);
        if (!(s->both_sides || dot >= POV_EPSILON))
            continue;
        double intensity = fabs(dot) * t[i].diffuse * t[i].att;
        t[i].acc->r += intensity * t[i].pigment.r * s->share.r;
        t[i].acc->g += intensity * t[i].pigment.g * s->share.g;
        t[i].acc->b += intensity * t[i].pigment.b * s->share.b;
    }
}

void area_diffuse_plain(const AreaDiffuseSamples *s, const AreaDiffuseTexture *t, int n)
{
    const Light *l = s->light;
    for (int v = 0; v < l->area.size2; v++)
        for (int u = 0; u < l->area.size1; u++) {
            Vec3 to_light;
            Vec3 offset = area_light_offset_of(l, s->axis1, s->axis2, s->factors[u * l->area.size2 + v]);
            area_light_sample_ray(l, offset, s->point, &to_light);
            add_sample(s, t, n, to_light);
        }
}

#if defined(__SSE2__)
/* Two samples' unit directions from the point, lanes (low, high) = (first,
 * second): area_light_offset_of's offset (an axis a light is one sample
 * wide along adds nothing: +0, not the axis times 0) added to the light's
 * location, less the point, divided by its length as
 * area_light_sample_ray divides: times 1 / length. */
typedef struct {
    __m128d x, y, z;
} Directions;

static Directions two_directions(const AreaDiffuseSamples *s, const double *f, const double *g)
{
    const Light *l = s->light;
    const int along1 = l->area.circular || l->area.size1 > 1, along2 = l->area.circular || l->area.size2 > 1;
    const __m128d f1 = _mm_set_pd(g[0], f[0]), f2 = _mm_set_pd(g[1], f[1]);
    const __m128d zero = _mm_setzero_pd();
    __m128d o1x = along1 ? _mm_mul_pd(_mm_set1_pd(s->axis1.x), f1) : zero;
    __m128d o1y = along1 ? _mm_mul_pd(_mm_set1_pd(s->axis1.y), f1) : zero;
    __m128d o1z = along1 ? _mm_mul_pd(_mm_set1_pd(s->axis1.z), f1) : zero;
    __m128d o2x = along2 ? _mm_mul_pd(_mm_set1_pd(s->axis2.x), f2) : zero;
    __m128d o2y = along2 ? _mm_mul_pd(_mm_set1_pd(s->axis2.y), f2) : zero;
    __m128d o2z = along2 ? _mm_mul_pd(_mm_set1_pd(s->axis2.z), f2) : zero;
    __m128d dx = _mm_sub_pd(_mm_add_pd(_mm_set1_pd(l->location.x), _mm_add_pd(o1x, o2x)), _mm_set1_pd(s->point.x));
    __m128d dy = _mm_sub_pd(_mm_add_pd(_mm_set1_pd(l->location.y), _mm_add_pd(o1y, o2y)), _mm_set1_pd(s->point.y));
    __m128d dz = _mm_sub_pd(_mm_add_pd(_mm_set1_pd(l->location.z), _mm_add_pd(o1z, o2z)), _mm_set1_pd(s->point.z));
    __m128d length =
        _mm_sqrt_pd(_mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy)), _mm_mul_pd(dz, dz)));
    __m128d inv = _mm_div_pd(_mm_set1_pd(1.0), length);
    Directions d = { _mm_mul_pd(dx, inv), _mm_mul_pd(dy, inv), _mm_mul_pd(dz, inv) };
    return d;
}

/* What texture t gets from the two samples, per lane: its light (r, g, b)
 * and whether it takes it at all; then added first lane first. */
static void add_two(const AreaDiffuseSamples *s, const AreaDiffuseTexture *t, Directions d, int lanes)
{
    const __m128d nx = _mm_set1_pd(t->normal.x), ny = _mm_set1_pd(t->normal.y), nz = _mm_set1_pd(t->normal.z);
    __m128d dot = _mm_add_pd(_mm_add_pd(_mm_mul_pd(nx, d.x), _mm_mul_pd(ny, d.y)), _mm_mul_pd(nz, d.z));
    int takes = s->both_sides ? 3 : _mm_movemask_pd(_mm_cmpge_pd(dot, _mm_set1_pd(POV_EPSILON)));
    takes &= lanes;
    if (!takes)
        return;
    __m128d c = _mm_andnot_pd(_mm_set1_pd(-0.0), dot); /* fabs */
    __m128d intensity = _mm_mul_pd(_mm_mul_pd(c, _mm_set1_pd(t->diffuse)), _mm_set1_pd(t->att));
    double r[2], g[2], b[2];
    _mm_storeu_pd(r, _mm_mul_pd(_mm_mul_pd(intensity, _mm_set1_pd(t->pigment.r)), _mm_set1_pd(s->share.r)));
    _mm_storeu_pd(g, _mm_mul_pd(_mm_mul_pd(intensity, _mm_set1_pd(t->pigment.g)), _mm_set1_pd(s->share.g)));
    _mm_storeu_pd(b, _mm_mul_pd(_mm_mul_pd(intensity, _mm_set1_pd(t->pigment.b)), _mm_set1_pd(s->share.b)));
    for (int lane = 0; lane < 2; lane++)
        if (takes & (1 << lane)) {
            t->acc->r += r[lane];
            t->acc->g += g[lane];
            t->acc->b += b[lane];
        }
}

void area_diffuse(const AreaDiffuseSamples *s, const AreaDiffuseTexture *t, int n)
{
    const Light *l = s->light;
    const int size1 = l->area.size1, size2 = l->area.size2;
    const long total = (long)size1 * size2;
    /* sample j of the plain order (v by v, u by u within) is factors[u * size2 + v] */
    int u = 0, v = 0;
    for (long j = 0; j < total; j += 2) {
        const double *first = s->factors[u * size2 + v];
        if (++u == size1) {
            u = 0;
            v++;
        }
        const int pair = j + 1 < total;
        const double *second = pair ? s->factors[u * size2 + v] : first;
        if (pair && ++u == size1) {
            u = 0;
            v++;
        }
        Directions d = two_directions(s, first, second);
        for (int i = 0; i < n; i++)
            add_two(s, &t[i], d, pair ? 3 : 1);
    }
}
#else
void area_diffuse(const AreaDiffuseSamples *s, const AreaDiffuseTexture *t, int n) { area_diffuse_plain(s, t, n); }
#endif
