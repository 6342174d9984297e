/* Shading, following POV-Ray 3.7's Trace::ComputeLightedTexture for plain
 * textures (one layer, or layers each lit with its own pigment, normal and
 * finish and seen through the layers above), and its
 * ComputeOneTextureColour for texture_maps (each texture around the map's
 * value shaded in full, the colours blended), so that images compare pixel
 * for pixel. Where POV-Ray
 * has a tolerance (EPSILON) we use the same value, and say so. */
#include "shade.h"

#include <string.h>

#include "aov_pixel.h"
#include "area_diffuse.h"
#include "area_light.h"
#include "clock.h"
#include "fade.h"
#include "fog.h"
#include "intersect.h"
#include "light.h"
#include "pigment.h"
#include "shadow.h"
#include "shadow_decide.h"


/* POV-Ray's greyscale weights (base/types.h). */
static double greyscale(double r, double g, double b) { return 0.297 * r + 0.589 * g + 0.114 * b; }

static void background(const World *w, const Ray *ray, Radiance *out)
{
    /* With an alpha channel (+UA), camera rays and rays refracted from them
     * (not reflected ones: POV-Ray's alphaBackground) see the background's
     * transparency. Otherwise it is opaque and the transmittance 0: without
     * an alpha channel composited on black, with one (for reflected rays)
     * its colour as given. */
    if (w->alpha_background && !ray->reflection) {
        RGB c = sky_colour_alpha(w, ray->dir, &out->transmit);
        out->r = c.r;
        out->g = c.g;
        out->b = c.b;
        return;
    }
    RGB below = w->alpha_background ? w->background_colour : w->background;
    RGB c = w->sky ? sky_colour_over(w, ray->dir, below) : below;
    out->r = c.r;
    out->g = c.g;
    out->b = c.b;
    out->transmit = 0.0;
}

/* POV-Ray's smooth step across a beam's edge: 0 below low, 1 from high on,
 * with zero slope at both ends. */
static double beam_edge(double low, double high, double x)
{
    if (x < low)
        return 0.0;
    if (x >= high)
        return 1.0;
    x = (x - low) / (high - low);
    return (3.0 - 2.0 * x) * x * x;
}

/* The share of a spotlight's or cylinder light's intensity that reaches p
 * (to_light: unit direction from p toward the light), as POV-Ray's
 * Attenuate_Light computes it. */
static double beam_attenuation(const Light *l, Vec3 p, Vec3 to_light)
{
    /* the beam's axis is -l->direction */
    if (l->beam == BEAM_SPOT) {
        double cos_angle = v3_dot(to_light, l->direction);
        if (cos_angle <= 0.0)
            return 0.0;
        double a = pow(cos_angle, l->beam_tightness);
        if (l->beam_radius > 0.0 && cos_angle < l->beam_radius)
            a *= beam_edge(l->beam_falloff, l->beam_radius, cos_angle);
        return a;
    }
    /* cylinder: by the distance of p from the axis, in front of the light only */
    Vec3 from_centre = v3_sub(p, l->location);
    double along = -v3_dot(from_centre, l->direction);
    if (along <= 0.0)
        return 0.0;
    double off_axis = v3_length(v3_add(from_centre, v3_scale(l->direction, along)));
    if (off_axis >= l->beam_falloff)
        return 0.0;
    double inside = 1.0 - off_axis / l->beam_falloff;
    double a = pow(inside, l->beam_tightness);
    if (l->beam_radius > 0.0 && off_axis > l->beam_radius)
        a *= beam_edge(0.0, 1.0 - l->beam_radius / l->beam_falloff, inside);
    return a;
}

/* The share of the light's colour that reaches p: the beam, then distance
 * fading (POV-Ray's Attenuate_Light). */
static inline double light_attenuation(const Light *l, Vec3 p, Vec3 to_light, double distance)
{
    double a = l->beam == BEAM_NONE ? 1.0 : beam_attenuation(l, p, to_light);
    if (a > 0.0 && l->fade_power > 0.0 && fabs(l->fade_distance) > POV_EPSILON)
        a *= 2.0 / (1.0 + pow(distance / l->fade_distance, l->fade_power));
    return a;
}

/* POV-Ray's empirical Fresnel term for metallic highlights. */
static RGB metallic_colour(double metallic, Vec3 normal, Vec3 to_light, RGB light, RGB pigment)
{
    double x = fabs(acos(v3_dot(normal, to_light))) / (M_PI / 2.0);
    double f = 0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903;
    f = min_of(1.0, max_of(0.0, f));
    double k = metallic * (1.0 - f);
    RGB r = { light.r * (1.0 + k * (pigment.r - 1.0)), light.g * (1.0 + k * (pigment.g - 1.0)),
              light.b * (1.0 + k * (pigment.b - 1.0)) };
    return r;
}

/* The unit direction from p toward the light, and the distance to it. A
 * parallel light has one direction, and the distance is to the plane
 * through the light perpendicular to it. */
static inline double light_direction(const Light *l, Vec3 p, Vec3 *to_light)
{
    Vec3 d = v3_sub(l->location, p);
    double distance = v3_length(d);
    *to_light = v3_scale(d, 1.0 / distance);
    if (l->kind == LIGHT_PARALLEL) {
        distance *= v3_dot(l->direction, *to_light);
        *to_light = l->direction;
    }
    return distance;
}

/* --aov: what became of q's light at the primary hit. asked: the method's
 * test or skip ran; through: the test's answer (NULL after a skip). */
static void record_light(ShadeContext *ctx, const ShadowQuery *q, int asked, int faces_away, const RGB *through)
{
    ShadowRecord r = { SCHEME_NONE, -1 };
    if (asked)
        r = shadow_record(&ctx->shadow, q, through);
    AovCode code = r.scheme != SCHEME_NONE ? aov_code_of_scheme(r.scheme)
                   : faces_away            ? AOV_CODE_FACES_AWAY
                                           : AOV_CODE_UNTESTED;
    double visibility = faces_away ? 0.0 : through ? greyscale(through->r, through->g, through->b) : 1.0;
    aov_record_light(ctx->aov, q->light, code, visibility, r.depth);
}

/* record_light where there is an --aov and q is at the primary hit: asked
 * for every light of every hit, which mostly has none. */
static inline void note_light(ShadeContext *ctx, const ShadowQuery *q, int asked, int faces_away, const RGB *through)
{
    if (ctx->aov && ctx->depth == 1)
        record_light(ctx, q, asked, faces_away, through);
}

/* The shadow methods' states when the shading asks nothing about any light. */
static void skip_all_lights(ShadeContext *ctx, const Hit *hit, const Segment *seg)
{
    const World *w = ctx->tracer.world;
    int ask = ctx->quality.shadows && ctx->shadow.method->skip;
    if (!ask && !(ctx->aov && ctx->depth == 1))
        return;
    for (int li = 0; li < w->nlights; li++) {
        const Light *l = &w->lights[li];
        Vec3 to_light;
        double distance = light_direction(l, hit->point, &to_light);
        ShadowQuery q = { hit->point, hit, seg, li, to_light, distance, v3(0, 0, 0), &w->lights[li] };
        if (ask && !l->shadowless) {
            shadow_decide_skip(&ctx->shadow, &q, 0);
            note_light(ctx, &q, 1, 0, NULL);
        } else {
            note_light(ctx, &q, 0, 0, NULL);
        }
    }
}

/* Light l's diffuse, phong and specular terms for light colour lc. */
/* add_light's diffuse term alone (inlined where area_illumination adds
 * it for every sample). */
static inline void add_diffuse(const Finish *f, Vec3 normal, Vec3 to_light, RGB pigment, double attenuation, RGB lc,
                               RGB *acc)
{
    if (f->diffuse > 0.0) {
        double c = fabs(v3_dot(normal, to_light));
        double intensity = (f->brilliance != 1.0 ? pow(c, f->brilliance) : c) * f->diffuse * attenuation;
        acc->r += intensity * pigment.r * lc.r;
        acc->g += intensity * pigment.g * lc.g;
        acc->b += intensity * pigment.b * lc.b;
    }
}

/* The finish adds only diffuse light from l: no phong or specular (or a
 * fill light, which gives no highlights). */
static int diffuse_only(const Finish *f, const Light *l)
{
    return l->shadowless || (!(f->phong > 0.0) && !(f->specular > 0.0));
}

/* Always inlined: its arguments (three vectors and two colours by value)
 * cost as much to pass as its diffuse term costs to work out, and
 * direct_light calls it for every texture and light. */
__attribute__((always_inline)) static inline void add_light(const Finish *f, const Light *l, Vec3 eye_dir,
                                                             Vec3 normal, Vec3 to_light, RGB pigment,
                                                             double attenuation, RGB lc, RGB *acc)
{
    add_diffuse(f, normal, to_light, pigment, attenuation, lc, acc);
    if (l->shadowless)
        return; /* POV-Ray's fill lights give no highlights */
    if (f->phong > 0.0) {
        Vec3 refl = v3_madd(eye_dir, normal, -2.0 * v3_dot(eye_dir, normal));
        double c = v3_dot(refl, to_light);
        if (c > 0.0) {
            double intensity = (f->phong_size < 60 || c > 0.0008) ? f->phong * pow(c, f->phong_size) : 0.0;
            RGB cs = f->metallic > 0.0 ? metallic_colour(f->metallic, normal, to_light, lc, pigment) : lc;
            acc->r += intensity * cs.r;
            acc->g += intensity * cs.g;
            acc->b += intensity * cs.b;
        }
    }
    if (f->specular > 0.0) {
        Vec3 half = v3_scale(v3_add(v3_neg(eye_dir), to_light), 0.5);
        double hl = v3_length(half);
        if (hl > 0.0) {
            double c = v3_dot(half, normal) / hl;
            if (c > 0.0) {
                double intensity = f->specular * pow(c, f->roughness);
                RGB cs = f->metallic > 0.0 ? metallic_colour(f->metallic, normal, to_light, lc, pigment) : lc;
                acc->r += intensity * cs.r;
                acc->g += intensity * cs.g;
                acc->b += intensity * cs.b;
            }
        }
    }
}

static int visible(RGB lc)
{
    return fabs(lc.r) > POV_EPSILON || fabs(lc.g) > POV_EPSILON || fabs(lc.b) > POV_EPSILON;
}

/* One plain texture shaded at a hit, as POV-Ray's ComputeLightedTexture
 * shades a one-layer texture: a texture_map's hit is shaded with each of
 * the textures around its pattern's value, and their colours blended by
 * weight. Each texture has its own pigment colour, finish and normal. */
typedef struct {
    double weight;        /* its share of the blend (1: a plain texture) */
    Colour colour;        /* its pigment's colour here, filter and transmit included */
    RGB pigment;
    const Finish *finish;
    Vec3 normal;          /* its shading normal, facing the arriving ray */
    double att;           /* its own light's share: 1 - filter - transmit (3.6 scenes: texture_own_light) */
    RGB reflec;           /* its reflectivity, and the weight of its reflected ray */
    double reflect_weight;
    RGB acc;              /* its light so far: ambient and emission, then the lights' */
} LitTexture;

/* direct_light keeps the textures that take a light as bits of one word */
_Static_assert(MAX_SURFACE_TEXTURES <= 32, "a texture per bit of an unsigned");
_Static_assert(MAX_TEXTURE_LAYERS <= 32, "a layer per bit of an unsigned");

static int has_highlights_or_diffuse(const Finish *f)
{
    return f->diffuse != 0.0 || f->specular != 0.0 || f->phong != 0.0;
}

/* add_full_area_light's loop through area_diffuse when it applies (a
 * light of one strength over its samples, every texture that takes it
 * diffuse only, with brilliance 1): 1 when done, 0 to do it here. */
static int add_area_diffuse(const ShadowContext *sc, const Light *l, int li, const Material *m, Vec3 p, Vec3 axis1,
                            Vec3 axis2, RGB share, LitTexture *lit, int n, unsigned takes, unsigned plain)
{
    const double(*factors)[2] = sc->area_fixed_factors ? sc->area_fixed_factors[li] : NULL;
    if (!area_diffuse_applies(l, factors))
        return 0;
    AreaDiffuseTexture t[MAX_SURFACE_TEXTURES];
    int nt = 0;
    for (int i = 0; i < n; i++) {
        if (!(takes & (1u << i)))
            continue;
        const Finish *f = lit[i].finish;
        if (!(plain & (1u << i)) || f->brilliance != 1.0)
            return 0;
        if (f->diffuse > 0.0) /* else it adds nothing (add_diffuse) */
            t[nt++] = (AreaDiffuseTexture){ lit[i].normal, lit[i].pigment, f->diffuse, lit[i].att, &lit[i].acc };
    }
    AreaDiffuseSamples s = { l, factors, axis1, axis2, p, share, m->double_illuminate };
    area_diffuse(&s, t, nt);
    return 1;
}

/* area_illumination (POV-Ray's ComputeFullAreaDiffuseLight): the light
 * that arrived, lc (shadowed, not yet attenuated), shared among the
 * samples, and each sample's share attenuated and shaded from where the
 * sample is, for the textures in `takes` that face it. */
static void add_full_area_light(const ShadowContext *sc, const Light *l, int li, const Material *m, Vec3 p,
                                Vec3 eye_dir, Vec3 centre_dir, RGB lc, LitTexture *lit, int n, unsigned takes)
{
    Vec3 axis1, axis2;
    area_light_axes(l, centre_dir, &axis1, &axis2);
    double samples = (double)l->area.size1 * (double)l->area.size2;
    RGB share = { lc.r / samples, lc.g / samples, lc.b / samples };
    unsigned plain = 0; /* the textures whose finish adds diffuse light only: the inlined term */
    for (int i = 0; i < n; i++)
        plain |= (unsigned)diffuse_only(lit[i].finish, l) << i;
    if (add_area_diffuse(sc, l, li, m, p, axis1, axis2, share, lit, n, takes, plain))
        return;
    for (int v = 0; v < l->area.size2; v++) {
        for (int u = 0; u < l->area.size1; u++) {
            Vec3 to_light;
            double distance =
                area_light_sample_ray(l, area_light_offset(sc, l, li, p, axis1, axis2, u, v, 1), p, &to_light);
            double fade = light_attenuation(l, p, to_light, distance);
            RGB slc = { share.r * fade, share.g * fade, share.b * fade };
            for (int i = 0; i < n; i++) {
                LitTexture *t = &lit[i];
                if (!(takes & (1u << i)) || !(m->double_illuminate || v3_dot(t->normal, to_light) >= POV_EPSILON))
                    continue;
                if (plain & (1u << i))
                    add_diffuse(t->finish, t->normal, to_light, t->pigment, t->att, slc, &t->acc);
                else
                    add_light(t->finish, l, eye_dir, t->normal, to_light, t->pigment, t->att, slc, &t->acc);
            }
        }
    }
}

/* Diffuse, phong and specular from every light (ComputeDiffuseLight), for
 * each of the n textures of the hit: one shadow decision per light, which
 * all of them share (POV-Ray's light colour cache of the intersection),
 * asked when some texture that takes light faces it. An area light (at
 * +Q5 and above) is decided sample by sample (area_light.h); it shades
 * from its centre, or with area_illumination from each sample. */
static void direct_light(ShadeContext *ctx, const Material *m, const Hit *hit, const Segment *seg, Vec3 eye_dir,
                         Vec3 normal, LitTexture *lit, int n)
{
    const World *w = ctx->tracer.world;
    for (int li = 0; li < w->nlights; li++) {
        const Light *l = &w->lights[li];
        int area = ctx->quality.area_lights && light_is_area(l);
        int full_area = area && l->area.full_area; /* attenuated and facing per sample */
        Vec3 to_light;
        double distance = light_direction(l, hit->point, &to_light);
        double fade = full_area ? 1.0 : light_attenuation(l, hit->point, to_light, distance);
        RGB lc = { l->colour.r * fade, l->colour.g * fade, l->colour.b * fade };
        int shadows = ctx->quality.shadows && !l->shadowless;
        ShadowQuery q = { hit->point, hit, seg, li, to_light, distance, normal, l };
        /* A light behind the surface (as seen from the eye) adds nothing and
         * needs no shadow test; methods that carry state still see it. */
        /* the textures that take this light: lit, and facing it */
        unsigned takes = 0;
        for (int i = 0; i < n; i++)
            if (has_highlights_or_diffuse(lit[i].finish) &&
                (full_area || m->double_illuminate || v3_dot(lit[i].normal, to_light) >= POV_EPSILON))
                takes |= 1u << i;
        int faces_away = takes == 0;
        if (faces_away || (fabs(lc.r) < POV_EPSILON && fabs(lc.g) < POV_EPSILON && fabs(lc.b) < POV_EPSILON)) {
            int asked = shadows && ctx->shadow.method->skip;
            if (asked)
                shadow_decide_skip(&ctx->shadow, &q, faces_away);
            note_light(ctx, &q, asked, faces_away, NULL);
            continue;
        }
        if (shadows) {
            RGB through;
            RGB unshadowed = lc;
            if (area) {
                lc = area_light_shadow(&ctx->shadow, &q, lc);
                /* the share that arrived, for the analysis channels */
                through.r = unshadowed.r != 0.0 ? lc.r / unshadowed.r : 1.0;
                through.g = unshadowed.g != 0.0 ? lc.g / unshadowed.g : 1.0;
                through.b = unshadowed.b != 0.0 ? lc.b / unshadowed.b : 1.0;
            } else {
                shadow_decide(&ctx->shadow, &q, &through);
                lc.r *= through.r;
                lc.g *= through.g;
                lc.b *= through.b;
            }
            note_light(ctx, &q, 1, 0, &through);
            if (ctx->aov && ctx->depth == 1 && (through.r != 1.0 || through.g != 1.0 || through.b != 1.0)) {
                /* --aov: what this shadow took, as a +Q3 render would show it. */
                RGB u = { 0, 0, 0 }, s = { 0, 0, 0 };
                for (int i = 0; i < n; i++) {
                    const LitTexture *t = &lit[i];
                    if (!(takes & (1u << i)))
                        continue;
                    LitTexture ut = *t, st = *t;
                    ut.acc = st.acc = (RGB){ 0, 0, 0 };
                    if (full_area) {
                        add_full_area_light(&ctx->shadow, l, li, m, hit->point, eye_dir, to_light, unshadowed, &ut, 1, 1u);
                        if (visible(lc))
                            add_full_area_light(&ctx->shadow, l, li, m, hit->point, eye_dir, to_light, lc, &st, 1, 1u);
                    } else {
                        if (visible(unshadowed))
                            add_light(t->finish, l, eye_dir, t->normal, to_light, t->pigment, t->att, unshadowed, &ut.acc);
                        if (visible(lc))
                            add_light(t->finish, l, eye_dir, t->normal, to_light, t->pigment, t->att, lc, &st.acc);
                    }
                    u.r += t->weight * ut.acc.r;
                    u.g += t->weight * ut.acc.g;
                    u.b += t->weight * ut.acc.b;
                    s.r += t->weight * st.acc.r;
                    s.g += t->weight * st.acc.g;
                    s.b += t->weight * st.acc.b;
                }
                aov_record_loss(ctx->aov, (const double[3]){ u.r, u.g, u.b }, (const double[3]){ s.r, s.g, s.b });
            }
        } else {
            note_light(ctx, &q, 0, 0, NULL);
        }
        if (!visible(lc))
            continue;
        if (full_area) {
            add_full_area_light(&ctx->shadow, l, li, m, hit->point, eye_dir, to_light, lc, lit, n, takes);
            continue;
        }
        for (int i = 0; i < n; i++) {
            LitTexture *t = &lit[i];
            if (takes & (1u << i))
                add_light(t->finish, l, eye_dir, t->normal, to_light, t->pigment, t->att, lc, &t->acc);
        }
    }
}

/* Reflectivity for the plain (non-fresnel) reflection model, and the
 * weight of the reflected ray (ComputeReflectivity, type 0). */
static RGB reflectivity(const Finish *f, double cos_incidence, double *weight)
{
    double wmax = max_of(f->reflection_max[0], max_of(f->reflection_max[1], f->reflection_max[2]));
    double wmin = max_of(f->reflection_min[0], max_of(f->reflection_min[1], f->reflection_min[2]));
    *weight *= max_of(wmax, wmin);
    double frac = fabs(f->reflection_falloff - 1.0) > POV_EPSILON ? pow(1.0 - cos_incidence, f->reflection_falloff)
                                                                  : 1.0 - cos_incidence;
    RGB r;
    if (fabs(frac) < POV_EPSILON) {
        r.r = f->reflection_min[0]; r.g = f->reflection_min[1]; r.b = f->reflection_min[2];
    } else if (fabs(frac - 1.0) < POV_EPSILON) {
        r.r = f->reflection_max[0]; r.g = f->reflection_max[1]; r.b = f->reflection_max[2];
    } else {
        r.r = frac * f->reflection_max[0] + (1.0 - frac) * f->reflection_min[0];
        r.g = frac * f->reflection_max[1] + (1.0 - frac) * f->reflection_min[1];
        r.b = frac * f->reflection_max[2] + (1.0 - frac) * f->reflection_min[2];
    }
    return r;
}

/* Fresnel reflectivity (reflection { ... fresnel }), POV-Ray's formula. */
static RGB reflectivity_fresnel(const Finish *f, double cos_incidence, double ior, double *weight)
{
    RGB r;
    double sqx = ior * ior + cos_incidence * cos_incidence - 1.0;
    if (sqx > 0.0) {
        double g = sqrt(sqx);
        double k = 0.5 * ((g - cos_incidence) * (g - cos_incidence)) / ((g + cos_incidence) * (g + cos_incidence));
        double a = cos_incidence * (g + cos_incidence) - 1.0, b = cos_incidence * (g - cos_incidence) + 1.0;
        k = k * (1.0 + (a * a) / (b * b));
        k = min_of(1.0, max_of(0.0, k));
        r.r = k * f->reflection_max[0] + (1.0 - k) * f->reflection_min[0];
        r.g = k * f->reflection_max[1] + (1.0 - k) * f->reflection_min[1];
        r.b = k * f->reflection_max[2] + (1.0 - k) * f->reflection_min[2];
    } else {
        r.r = f->reflection_max[0]; r.g = f->reflection_max[1]; r.b = f->reflection_max[2];
    }
    *weight *= max_of(r.r, max_of(r.g, r.b));
    return r;
}

static int interior_index(const InteriorList *l, const void *key)
{
    for (int i = l->n - 1; i >= 0; i--)
        if (l->key[i] == key)
            return i;
    return -1;
}

/* Fog acts on a ray only where every interior it is inside is hollow
 * (POV-Ray's IsHollowRay). */
static int in_atmosphere(const InteriorList *l)
{
    for (int i = 0; i < l->n; i++)
        if (!l->hollow[i])
            return 0;
    return 1;
}

static void interior_remove(InteriorList *l, int i)
{
    for (; i + 1 < l->n; i++) {
        l->key[i] = l->key[i + 1];
        l->ior[i] = l->ior[i + 1];
        l->hollow[i] = l->hollow[i + 1];
    }
    l->n--;
}

/* Enters m's interior (innermost), unless the list is full. */
static void interior_push(InteriorList *l, const Material *m)
{
    if (l->n >= MAX_INTERIOR_NESTING)
        return;
    l->key[l->n] = m->interior_key;
    l->hollow[l->n] = (unsigned char)m->hollow;
    l->ior[l->n++] = m->ior;
}

void shade_camera_interiors(ShadeContext *ctx, const World *w, Vec3 org, InteriorList *inside)
{
    if (w->nshapes == 0)
        return;
    /* the same origin as the last camera ray's: the same interiors */
    if (ctx->camera_inside_known && ctx->camera_inside_at.x == org.x && ctx->camera_inside_at.y == org.y &&
        ctx->camera_inside_at.z == org.z) {
        interior_copy(inside, &ctx->camera_inside);
        return;
    }
    for (int i = 0; i < w->nshapes; i++) {
        const Material *m = &w->materials[w->shapes[i].material];
        if (shape_inside(&w->shapes[i], org) && interior_index(inside, m->interior_key) < 0)
            interior_push(inside, m);
    }
    interior_copy(&ctx->camera_inside, inside);
    ctx->camera_inside_at = org;
    ctx->camera_inside_known = 1;
}

/* The ior ratio at this surface, and the interior list beyond it
 * (POV-Ray's ComputeRefraction bookkeeping; the atmosphere has ior 1). */
static double refraction_ratio(const InteriorList *inside, const Material *m, InteriorList *beyond)
{
    interior_copy(beyond, inside);
    if (beyond->n == 0) {
        interior_push(beyond, m);
        return 1.0 / m->ior;
    }
    /* the iors read from inside, which beyond copies up to where it is
     * changed (the compiler cannot tell that interior_copy filled them) */
    int at = interior_index(beyond, m->interior_key);
    if (at == beyond->n - 1) { /* leaving the innermost */
        interior_remove(beyond, at);
        return beyond->n == 0 ? m->ior : m->ior / inside->ior[beyond->n - 1];
    }
    if (at >= 0) { /* leaving an overlap */
        interior_remove(beyond, at);
        return 1.0;
    }
    double outer = inside->ior[inside->n - 1];
    interior_push(beyond, m);
    return outer / m->ior;
}

/* The ior ratio the fresnel reflectivity uses (POV-Ray's
 * ComputeRelativeIOR; note it is the inverse of refraction_ratio's). */
static double refraction_ratio_peek(const Ray *ray, const Material *m)
{
    const InteriorList *l = &ray->inside;
    if (l->n == 0)
        return m->ior;
    if (interior_index(l, m->interior_key) >= 0)
        return l->n == 1 ? 1.0 / m->ior : l->ior[l->n - 1] / m->ior;
    return m->ior / l->ior[l->n - 1];
}

static void trace_ray(ShadeContext *ctx, const Ray *ray, double weight, int level, int continued, Radiance *out);
static void shade_hit(ShadeContext *ctx, const Ray *ray, const Hit *hit, const Segment *seg, double weight,
                      int level, Radiance *out);

static void trace_reflection(ShadeContext *ctx, const Ray *ray, const Hit *hit, const LightState *state,
                             Vec3 normal, Vec3 raw_normal, double weight, int level, Radiance *out)
{
    Ray r;
    r.from = *hit;
    r.state = state;
    interior_copy(&r.inside, &ray->inside);
    r.org = hit->point;
    r.not_image = 1;
    r.reflection = 1;
    Vec3 d = v3_madd(ray->dir, normal, -2.0 * v3_dot(ray->dir, normal));
    /* POV-Ray's fix for reflected rays that point into the surface. */
    double n = v3_dot(d, raw_normal);
    if (n < 0.0) {
        if (v3_dot(d, normal) < 0.0)
            d = v3_madd(ray->dir, raw_normal, -2.0 * v3_dot(ray->dir, raw_normal));
        else
            d = v3_madd(d, raw_normal, -2.0 * n);
    }
    r.dir = v3_normalize(d);
    ctx->stats.reflected_rays++;
    trace_ray(ctx, &r, weight, level, 0, out);
}

/* Refracted or transmitted ray; returns 1 on total internal reflection. */
static int trace_refraction(ShadeContext *ctx, const Ray *ray, const Hit *hit, const LightState *state,
                            const Material *m, Vec3 normal, Vec3 raw_normal, double weight, int level, Radiance *out)
{
    Ray r;
    r.from = *hit;
    r.state = state;
    r.org = hit->point;
    r.not_image = ray->not_image;
    r.reflection = ray->reflection;
    double ior = refraction_ratio(&ray->inside, m, &r.inside);
    if (fabs(ior - 1.0) < POV_EPSILON) {
        /* Same ior on both sides: the ray goes straight on, and POV-Ray
         * does not count it as a new trace level. */
        r.dir = ray->dir;
        ctx->stats.transmitted_rays++;
        trace_ray(ctx, &r, weight, level, 1, out);
        return 0;
    }
    double n = v3_dot(ray->dir, normal);
    Vec3 local = normal;
    if (n <= 0.0)
        n = -n;
    else
        local = v3_neg(normal);
    double t = 1.0 + ior * ior * (n * n - 1.0);
    if (t < 0.0) {
        Radiance refl;
        trace_reflection(ctx, ray, hit, state, normal, raw_normal, weight, level, &refl);
        out->r += refl.r;
        out->g += refl.g;
        out->b += refl.b;
        out->transmit += refl.transmit;
        return 1;
    }
    t = ior * n - sqrt(t);
    /* POV-Ray does not normalise the refracted direction here; it is unit
     * length already up to rounding. */
    r.dir = v3_add(v3_scale(ray->dir, ior), v3_scale(local, t));
    ctx->stats.refracted_rays++;
    trace_ray(ctx, &r, weight, level, 0, out);
    return 0;
}

/* The refracted light a surface lets through (fil, trans: what its
 * textures let through, and its grey), added to *out: faded by the
 * interior the ray leaves, and filtered by fil unless totally reflected
 * (POV-Ray's ComputeLightedTexture's refraction part). Returns 1 after a
 * total internal reflection. */
static int add_refraction(ShadeContext *ctx, const Ray *ray, const Hit *hit, const LightState *state,
                          const Material *m, Vec3 normal, Vec3 raw, RGB fil, double trans, double weight, int level,
                          Radiance *out)
{
    double w1 = max_of(fabs(fil.r), max_of(fabs(fil.g), fabs(fil.b)));
    Radiance rfr = { 0, 0, 0, 0 };
    int tir = trace_refraction(ctx, ray, hit, state, m, normal, raw, weight * w1, level, &rfr);
    RGB attc = { 1.0, 1.0, 1.0 };
    if (interior_index(&ray->inside, m->interior_key) >= 0 && fabs(m->fade_distance) > POV_EPSILON)
        attc = interior_fade(m, hit->t);
    if (tir) {
        out->r += attc.r * rfr.r;
        out->g += attc.g * rfr.g;
        out->b += attc.b * rfr.b;
    } else {
        out->r += attc.r * rfr.r * fil.r;
        out->g += attc.g * rfr.g * fil.g;
        out->b += attc.b * rfr.b * fil.b;
        out->transmit = greyscale(attc.r, attc.g, attc.b) * rfr.transmit * trans;
    }
    return tir;
}

void shade_trace(ShadeContext *ctx, const Ray *ray, double weight, int level, Radiance *out)
{
    ctx->tree_rays_left = ctx->max_tree_rays;
    trace_ray(ctx, ray, weight, level, 0, out);
}

/* A ray's hit on one of two coincident surfaces of different materials
 * (trace_coincident_material): counted, a camera ray's apart, and the pair
 * of least materials kept, so that the report names the same objects for
 * any number of threads. */
static void note_coincident(ShadeContext *ctx, const Hit *hit, int camera)
{
    int other = trace_coincident_material(&ctx->tracer, hit);
    if (other < 0)
        return;
    int mine = hit_material(ctx->tracer.world, hit);
    uint64_t a = (uint64_t)(mine < other ? mine : other), b = (uint64_t)(mine < other ? other : mine);
    uint64_t key = (a + 1) << 32 | (b + 1);
    if (camera)
        ctx->stats.coincident_hits++;
    else
        ctx->stats.coincident_secondary++;
    if (ctx->coincident_pair == 0 || key < ctx->coincident_pair)
        ctx->coincident_pair = key;
}

/* POV-Ray's TraceRay: `level` is the trace level so far; a continued
 * (transmitted, same-ior) ray does not start a new level. */
static void trace_ray(ShadeContext *ctx, const Ray *ray, double weight, int level, int continued, Radiance *out)
{
    const World *w = ctx->tracer.world;
    memset(out, 0, sizeof *out);
    if (level >= w->max_trace_level || weight < w->adc_bailout)
        return;
    if (ctx->deadline > 0.0 && (ctx->expired || (++ctx->rays_unchecked >= SHADE_CLOCK_RAYS &&
                                                 (ctx->rays_unchecked = 0, clock_wall() > ctx->deadline)))) {
        ctx->expired = 1;
        return;
    }
    if (ctx->max_tree_rays) {
        if (ctx->tree_overflow || ctx->tree_rays_left == 0) {
            ctx->tree_overflow = 1;
            return;
        }
        ctx->tree_rays_left--;
    }
    Hit hit;
    ctx->tracer.hide = (ray->not_image ? 0u : HIDE_NO_IMAGE) | (ray->reflection ? HIDE_NO_REFLECTION : 0u);
    int found = trace_nearest(&ctx->tracer, ray->org, ray->dir, HUGE_VAL, &ray->from, &hit);
    ctx->tracer.hide = 0;
    if (found)
        note_coincident(ctx, &hit, ctx->depth == 0);
    if (!found) {
        background(w, ray, out);
        if (ctx->quality.volume && w->nfogs && in_atmosphere(&ray->inside))
            fog_apply(w, ray->org, ray->dir, HUGE_VAL, out);
        return;
    }
    if (!continued)
        level++;

    /* The segment ray->org -> hit and, where the method keeps them, a row
     * of light states for the hit. */
    LightState *row = shadow_segment_begin(&ctx->shadow, &hit, ray->from.kind == HIT_NONE);
    Segment seg = { ray->org, ray->dir, &ray->from, ray->state, row, ray->inside.key, ray->inside.n };
    ctx->depth++;
    shade_hit(ctx, ray, &hit, &seg, weight, level, out);
    ctx->depth--;
    shadow_segment_end(&ctx->shadow);
    if (ctx->quality.volume && w->nfogs && in_atmosphere(&ray->inside))
        fog_apply(w, ray->org, ray->dir, hit.t, out);
}

/* A texture's reflectivity (computed before lighting, as POV-Ray does)
 * and its own light: ambient and emission, reduced where it is see-through. */
static void texture_own_light(ShadeContext *ctx, const Ray *ray, const Material *m, double weight, LitTexture *t)
{
    const World *w = ctx->tracer.world;
    const Finish *f = t->finish;
    double cos_incidence = -v3_dot(ray->dir, t->normal);
    t->reflect_weight = weight;
    t->reflec = f->reflection_fresnel
                    ? reflectivity_fresnel(f, cos_incidence, refraction_ratio_peek(ray, m), &t->reflect_weight)
                    : reflectivity(f, cos_incidence, &t->reflect_weight);
    if (f->reflection_metallic != 0.0) {
        double x = fabs(acos(cos_incidence)) / (M_PI / 2.0);
        double F = 0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903;
        F = min_of(1.0, max_of(0.0, F));
        double k = f->reflection_metallic * (1.0 - F);
        t->reflec.r *= 1.0 + k * (t->pigment.r - 1.0);
        t->reflec.g *= 1.0 + k * (t->pigment.g - 1.0);
        t->reflec.b *= 1.0 + k * (t->pigment.b - 1.0);
    }
    const Colour *pc = &t->colour;
    double att = 1.0 - pc->filter - pc->transmit;
    if (w->legacy_layer_light) /* POV-Ray 3.6's formula, kept for its scenes */
        att = 1.0 - (pc->filter * max_of(pc->r, max_of(pc->g, pc->b)) + pc->transmit);
    t->att = att;
    /* POV-Ray's radiosity (at +Q9, its "advanced light") takes ambient's place */
    RGB amb = w->radiosity_replaces_ambient && ctx->quality.volume ? (RGB){ 0, 0, 0 } : w->ambient_light;
    t->acc.r = t->pigment.r * (f->ambient[0] * amb.r * att + f->emission[0] * att);
    t->acc.g = t->pigment.g * (f->ambient[1] * amb.g * att + f->emission[1] * att);
    t->acc.b = t->pigment.b * (f->ambient[2] * amb.b * att + f->emission[2] * att);
}

/* A lit texture's colour: its light, then what shows through it (the
 * refracted or transmitted ray) and what it reflects, each traced with its
 * own weight as POV-Ray traces them for each texture of a texture_map. */
static void texture_colour(ShadeContext *ctx, const Ray *ray, const Hit *hit, const LightState *state,
                           const Material *m, Vec3 raw, double weight, int level, const LitTexture *t, Radiance *out)
{
    const World *w = ctx->tracer.world;
    const Finish *f = t->finish;
    const Colour *pc = &t->colour;
    const RGB pigment = t->pigment;
    out->r = t->acc.r;
    out->g = t->acc.g;
    out->b = t->acc.b;
    out->transmit = 0.0;

    /* What shows through: rgb*filter + transmit. */
    RGB fil = { pigment.r * pc->filter + pc->transmit, pigment.g * pc->filter + pc->transmit,
                pigment.b * pc->filter + pc->transmit };
    if (f->conserve_energy) {
        fil.r *= min_of(1.0, 1.0 - t->reflec.r);
        fil.g *= min_of(1.0, 1.0 - t->reflec.g);
        fil.b *= min_of(1.0, 1.0 - t->reflec.b);
    }
    double trans = min_of(1.0, fabs(greyscale(fil.r, fil.g, fil.b)));

    int tir = trans > w->adc_bailout && ctx->quality.refraction
                  ? add_refraction(ctx, ray, hit, state, m, t->normal, raw, fil, trans, weight, level, out)
                  : 0;

    /* Reflection, skipped after total internal reflection (the layer's
     * normal is the top normal for one-layer textures). */
    if (ctx->quality.reflection && !tir && !(t->reflec.r == 0.0 && t->reflec.g == 0.0 && t->reflec.b == 0.0)) {
        Radiance rfl;
        trace_reflection(ctx, ray, hit, state, t->normal, raw, t->reflect_weight, level, &rfl);
        double e = f->reflection_exponent;
        if (e != 1.0 && e > 0.0) {
            out->r += t->reflec.r * pow(rfl.r, e);
            out->g += t->reflec.g * pow(rfl.g, e);
            out->b += t->reflec.b * pow(rfl.b, e);
        } else {
            out->r += t->reflec.r * rfl.r;
            out->g += t->reflec.g * rfl.g;
            out->b += t->reflec.b * rfl.b;
        }
    }
}

/* The hit shaded with its n textures (one, or a texture_map's): each
 * texture's reflectivity and own light, the lights once for all of them,
 * then each one's refraction and reflection, the colours blended by weight
 * (POV-Ray's ComputeOneTextureColour), the alpha channel's transmittance
 * too. */
static void shade_textures(ShadeContext *ctx, const Ray *ray, const Hit *hit, const Segment *seg, const Material *m,
                           Vec3 raw, Vec3 normal, LitTexture *lit, int n, double weight, int level, Radiance *out)
{
    const LightState *state = (const LightState *)seg->state;
    if (ctx->quality.full_ambient) {
        skip_all_lights(ctx, hit, seg);
        out->r = out->g = out->b = 0.0; /* the pigment colour: a texture_map's textures' blended */
        for (int i = 0; i < n; i++) {
            out->r += lit[i].weight * lit[i].pigment.r;
            out->g += lit[i].weight * lit[i].pigment.g;
            out->b += lit[i].weight * lit[i].pigment.b;
        }
        return;
    }
    int lighted = 0;
    for (int i = 0; i < n; i++) {
        texture_own_light(ctx, ray, m, weight, &lit[i]);
        lighted |= has_highlights_or_diffuse(lit[i].finish);
    }
    if (lighted)
        direct_light(ctx, m, hit, seg, ray->dir, normal, lit, n);
    else
        skip_all_lights(ctx, hit, seg);
    if (n == 1 && lit[0].weight == 1.0) {
        texture_colour(ctx, ray, hit, state, m, raw, weight, level, &lit[0], out);
        return;
    }
    out->r = out->g = out->b = out->transmit = 0.0;
    for (int i = 0; i < n; i++) {
        Radiance c;
        texture_colour(ctx, ray, hit, state, m, raw, weight, level, &lit[i], &c);
        out->r += lit[i].weight * c.r;
        out->g += lit[i].weight * c.g;
        out->b += lit[i].weight * c.b;
        out->transmit += lit[i].weight * c.transmit;
    }
}

static void lit_texture(LitTexture *t, const SurfaceTexture *s)
{
    t->weight = s->weight;
    t->colour = s->colour;
    t->pigment = (RGB){ s->colour.r, s->colour.g, s->colour.b };
    t->finish = s->finish;
    t->normal = s->normal;
}

/* A texture_map's hit: shaded with the textures around its value here (or
 * a mesh face's with a texture per vertex: with the three, pigment.h). Apart
 * (never inlined), so that plain textures' hits, which recurse through
 * shade_hit as deep as the ray tree, keep a small stack frame. */
/* The surface id (world.h) the material code looks up uv coordinates by. */
static int uv_surface(const World *w, const Hit *hit)
{
    return hit->kind == HIT_POLYGON ? world_uv_polygon(w, hit->index)
         : hit->kind == HIT_SHAPE   ? surface_of_shape(hit->index)
                                    : -1;
}

__attribute__((noinline)) static void shade_map_hit(ShadeContext *ctx, const Ray *ray, const Hit *hit,
                                                    const Segment *seg, const Material *m, Vec3 raw, Vec3 normal,
                                                    double weight, int level, Radiance *out)
{
    const World *w = ctx->tracer.world;
    SurfaceTexture found[MAX_SURFACE_TEXTURES];
    LitTexture lit[MAX_SURFACE_TEXTURES];
    int n = material_textures_normals_at(w, m, uv_surface(w, hit), hit->point, normal,
                                         ctx->quality.normal, found);
    for (int i = 0; i < n; i++)
        lit_texture(&lit[i], &found[i]);
    shade_textures(ctx, ray, hit, seg, m, raw, normal, lit, n, weight, level, out);
}

/* The reflected rays of a layered texture's layers: each layer's own, with
 * its normal, reflectivity and weight, not filtered by the layers above
 * (POV-Ray adds them as they are); after total internal reflection those of
 * the layers whose normal is the top layer's are left out, as POV-Ray
 * leaves them. */
static void layers_reflection(ShadeContext *ctx, const Ray *ray, const Hit *hit, const LightState *state, Vec3 raw,
                              const LitTexture *lit, int n, int tir, int level, Radiance *out)
{
    const Vec3 top = lit[0].normal;
    for (int i = 0; i < n; i++) {
        const LitTexture *t = &lit[i];
        if (tir && fabs(top.x - t->normal.x) <= POV_EPSILON && fabs(top.y - t->normal.y) <= POV_EPSILON &&
            fabs(top.z - t->normal.z) <= POV_EPSILON)
            continue;
        if (t->reflec.r == 0.0 && t->reflec.g == 0.0 && t->reflec.b == 0.0)
            continue;
        Radiance rfl;
        trace_reflection(ctx, ray, hit, state, t->normal, raw, t->reflect_weight, level, &rfl);
        double e = t->finish->reflection_exponent;
        if (e != 1.0 && e > 0.0) {
            out->r += t->reflec.r * pow(rfl.r, e);
            out->g += t->reflec.g * pow(rfl.g, e);
            out->b += t->reflec.b * pow(rfl.b, e);
        } else {
            out->r += t->reflec.r * rfl.r;
            out->g += t->reflec.g * rfl.g;
            out->b += t->reflec.b * rfl.b;
        }
    }
}

/* A layered texture's hit (POV-Ray's ComputeLightedTexture over a list of
 * layers): from the top down, each layer's reflectivity and own light with
 * the weight that the layers above leave it, until what they let through
 * (fil: the product of their rgb * filter + transmit, and of 1 -
 * reflectivity where they conserve energy) falls to adc_bailout; the lights
 * once for the layers reached, each layer's light filtered by the layers
 * above it; then the ray through them all, filtered by all (refracted by the
 * top layer's normal), and each layer's reflection. Apart (never inlined),
 * as shade_map_hit. */
__attribute__((noinline)) static void shade_layers_hit(ShadeContext *ctx, const Ray *ray, const Hit *hit,
                                                       const Segment *seg, const Material *m, Vec3 raw,
                                                       double weight, int level, Radiance *out)
{
    const World *w = ctx->tracer.world;
    const LightState *state = (const LightState *)seg->state;
    SurfaceTexture layer[MAX_TEXTURE_LAYERS];
    LitTexture lit[MAX_TEXTURE_LAYERS];
    RGB seen[MAX_TEXTURE_LAYERS]; /* what the layers above let through to layer i */
    int nl = material_layers_at(w, m, uv_surface(w, hit), hit->point, raw, ctx->quality.normal, layer);
    if (ctx->aov && ctx->depth == 1)
        aov_record_hit(ctx->aov, hit->t, hit->point, layer[0].normal);
    RGB fil = { 1, 1, 1 };
    double trans = 1.0;
    int n = 0, lighted = 0;
    for (; n < nl && trans > w->adc_bailout; n++) {
        LitTexture *t = &lit[n];
        lit_texture(t, &layer[n]);
        seen[n] = fil;
        if (!ctx->quality.full_ambient) {
            texture_own_light(ctx, ray, m, weight * trans, t);
            lighted |= has_highlights_or_diffuse(t->finish);
        }
        const Colour *c = &t->colour;
        fil.r *= c->r * c->filter + c->transmit;
        fil.g *= c->g * c->filter + c->transmit;
        fil.b *= c->b * c->filter + c->transmit;
        if (t->finish->conserve_energy && !ctx->quality.full_ambient) {
            fil.r *= min_of(1.0, 1.0 - t->reflec.r);
            fil.g *= min_of(1.0, 1.0 - t->reflec.g);
            fil.b *= min_of(1.0, 1.0 - t->reflec.b);
        }
        trans = min_of(1.0, fabs(greyscale(fil.r, fil.g, fil.b)));
        /* --aov's light loss weighs a layer by a single figure */
        t->weight = greyscale(seen[n].r, seen[n].g, seen[n].b);
    }
    if (ctx->quality.full_ambient) {
        /* POV-Ray keeps the pigment colour of the last layer it reached */
        skip_all_lights(ctx, hit, seg);
        out->r = lit[n - 1].pigment.r;
        out->g = lit[n - 1].pigment.g;
        out->b = lit[n - 1].pigment.b;
        out->transmit = 0.0;
        return;
    }
    if (lighted)
        direct_light(ctx, m, hit, seg, ray->dir, raw, lit, n);
    else
        skip_all_lights(ctx, hit, seg);
    out->r = out->g = out->b = out->transmit = 0.0;
    for (int i = 0; i < n; i++) {
        out->r += lit[i].acc.r * seen[i].r;
        out->g += lit[i].acc.g * seen[i].g;
        out->b += lit[i].acc.b * seen[i].b;
    }

    int tir = trans > w->adc_bailout && ctx->quality.refraction
                  ? add_refraction(ctx, ray, hit, state, m, lit[0].normal, raw, fil, trans, weight, level, out)
                  : 0;
    if (ctx->quality.reflection)
        layers_reflection(ctx, ray, hit, state, raw, lit, n, tir, level, out);
}

static void shade_hit(ShadeContext *ctx, const Ray *ray, const Hit *hitp, const Segment *seg, double weight,
                      int level, Radiance *out)
{
    const World *w = ctx->tracer.world;
    const Hit hit = *hitp;
    const Material *m = &w->materials[hit_material(w, &hit)];
    Vec3 raw = hit.kind == HIT_POLYGON ? world_polygon_shading_normal(w, hit.index, hit.instance, hit.point)
             : hit.kind == HIT_SHAPE   ? shape_normal(&w->shapes[hit.index], hit.point, hit.part)
                                       : w->planes[hit.index].normal;
    const double facing = v3_dot(raw, ray->dir);
    if (facing > 0.0) /* surfaces are two-sided */
        raw = v3_neg(raw);
    /* met from inside (POV-Ray's normal turned away from the ray): its
     * interior_texture (ComputeTextureColour) */
    if (m->inside >= 0 && (facing > 0.0) != (m->inside_turned != 0))
        m = &w->materials[m->inside];
    /* (an instance's polygon has no materials per vertex: flatten.c instances no such mesh) */
    if (m->map >= 0 ||
        (hit.kind == HIT_POLYGON && hit.index < w->npolygons && w->polygons[hit.index].vertex_materials >= 0)) {
        if (ctx->aov && ctx->depth == 1)
            aov_record_hit(ctx->aov, hit.t, hit.point, raw); /* a map's textures have normals each */
        shade_map_hit(ctx, ray, &hit, seg, m, raw, raw, weight, level, out);
        return;
    }
    if (m->below >= 0) {
        shade_layers_hit(ctx, ray, &hit, seg, m, raw, weight, level, out);
        return;
    }
    const SurfaceTexture own =
        material_plain_texture_at(w, m, uv_surface(w, &hit), hit.point, raw, ctx->quality.normal);
    if (ctx->aov && ctx->depth == 1)
        aov_record_hit(ctx->aov, hit.t, hit.point, own.normal);
    LitTexture lit;
    lit_texture(&lit, &own);
    shade_textures(ctx, ray, &hit, seg, m, raw, raw, &lit, 1, weight, level, out);
}

void shade_counters_add(ShadeCounters *t, const ShadeCounters *p)
{
#define SHADE_COUNTER(field, line, label, key, meaning) t->field += p->field;
#include "shade_counters.def"
#undef SHADE_COUNTER
}
