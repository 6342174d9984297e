/* camera and light_source.
 *
 * The camera follows POV-Ray 3.5+ (Parse_Camera, languageVersion >= 350):
 * modifiers are collected in any order, then applied in a fixed order --
 * right, direction, angle, up, sky, location, look_at -- and the transforms
 * last. The stored vectors are the final, world-space ones. */
#include <math.h>
#include <string.h>

#include "grammar.h"

void gram_default_camera(SceneCamera *cam)
{
    memset(cam, 0, sizeof *cam);
    cam->kind = CAMERA_PERSPECTIVE;
    cam->location = v3(0, 0, 0);
    cam->direction = v3(0, 0, 1);
    cam->up = v3(0, 1, 0);
    cam->right = v3(1.33, 0, 0);
    cam->angle = 90.0; /* POV-Ray's Camera::Init */
    cam->h_angle = 360.0;
    cam->v_angle = 180.0;
}

/* The camera type a keyword names, -1 for none (cylinder's number follows). */
static int camera_kind_of(int kw)
{
    switch (kw) {
    case KW_perspective: return CAMERA_PERSPECTIVE;
    case KW_orthographic: return CAMERA_ORTHOGRAPHIC;
    case KW_fisheye: return CAMERA_FISHEYE;
    case KW_ultra_wide_angle: return CAMERA_ULTRA_WIDE_ANGLE;
    case KW_omnimax: return CAMERA_OMNIMAX;
    case KW_panoramic: return CAMERA_PANORAMIC;
    case KW_cylinder: return CAMERA_CYLINDER_1;
    case KW_spherical: return CAMERA_SPHERICAL;
    default: return -1;
    }
}

static void transform_camera(SceneCamera *cam, const Transform *tr)
{
    cam->location = transform_point(tr, cam->location);
    cam->direction = transform_direction(tr, cam->direction);
    cam->up = transform_direction(tr, cam->up);
    cam->right = transform_direction(tr, cam->right);
}

static const double CAMERA_EPSILON = 1e-10; /* POV-Ray's EPSILON */

void gram_camera(Parser *p, const Token *kw, SceneCamera *cam)
{
    tok_begin_block(p, "camera");
    Transform tr;
    transform_identity(&tr);

    /* `camera { Declared transforms }`: only transforms may follow. */
    Token *t = tok_next(p);
    if (t->type == TK_WORD && t->kw < 0) {
        Symbol *s = tok_symbol_of(p, t);
        if (!s)
            tok_fail(p, t->pos, "undeclared identifier '%.*s'", t->len, t->text);
        if (s->value.kind == VAL_UNSUPPORTED)
            tok_use_unsupported(p, t, &s->value);
        if (s->value.kind != VAL_CAMERA)
            tok_fail(p, t->pos, "'%.*s' is not a camera", t->len, t->text);
        *cam = *s->value.camera;
        cam->pos = kw->pos;
        for (;;) {
            t = tok_next(p);
            if (tok_is_punct(t, '}'))
                break;
            if (!expr_transform_item(p, t, &tr))
                tok_fail_expected(p, t, "a transform or '}' after a camera identifier");
        }
        transform_camera(cam, &tr);
        return;
    }
    tok_unget(p);

    SceneCamera c;
    gram_default_camera(&c);
    c.pos = kw->pos;
    Vec3 sky = v3(0, 1, 0), look_at = v3(0, 0, 1);
    int had_up = 0, had_right = 0, had_angle = 0, had_look_at = 0;
    double angle = 0.0;
    Token angle_tok = *kw;

    /* The type, first; POV-Ray takes the last of several in a row. */
    for (;;) {
        t = tok_next(p);
        int kind = t->type == TK_WORD ? camera_kind_of(t->kw) : -1;
        if (kind < 0) {
            if (tok_is_kw(t, KW_mesh_camera))
                tok_unsupported(p, t);
            tok_unget(p);
            break;
        }
        if (t->kw == KW_cylinder) {
            SourcePos at = tok_peek(p)->pos;
            double n = expr_float(p);
            /* POV-Ray truncates the number to an integer */
            if (!(n > 0.0 && n < 5.0) || (int)n < 1)
                tok_fail(p, at, "invalid cylinder camera type, valid are types 1 to 4 (POV-Ray: \"Invalid cylinder "
                                "camera type, valid are types 1 to 4.\")");
            kind = CAMERA_CYLINDER_1 + ((int)n - 1);
        }
        c.kind = (CameraKind)kind;
    }

    for (;;) {
        t = tok_next(p);
        if (tok_is_punct(t, '}'))
            break;
        if (expr_transform_item(p, t, &tr))
            continue;
        switch (t->type == TK_WORD ? t->kw : -1) {
        case KW_location: c.location = expr_vector(p); break;
        case KW_look_at: look_at = expr_vector(p); had_look_at = 1; break;
        case KW_direction: c.direction = expr_vector(p); break;
        case KW_up: c.up = expr_vector(p); had_up = 1; break;
        case KW_right: c.right = expr_vector(p); had_right = 1; break;
        case KW_sky: sky = expr_vector(p); break;
        case KW_angle:
            angle_tok = *t;
            if (c.kind == CAMERA_SPHERICAL) {
                /* POV-Ray's Parse_Camera: the horizontal angle, then
                 * optionally the vertical one (half the horizontal) */
                c.h_angle = expr_float(p);
                if (c.h_angle < 0.0)
                    tok_fail(p, t->pos, "negative horizontal angle not allowed");
                expr_comma(p);
                c.v_angle = expr_starts_float(p, tok_peek(p)) ? expr_float(p) : c.h_angle * 0.5;
                if (c.v_angle < 0.0)
                    tok_fail(p, t->pos, "negative vertical angle not allowed");
                break;
            }
            if (c.kind == CAMERA_ORTHOGRAPHIC && !expr_starts_float(p, tok_peek(p)))
                angle = 0.0;
            else
                angle = expr_float(p);
            if (angle < 0.0)
                tok_fail(p, t->pos, "negative viewing angle");
            had_angle = 1;
            break;
        case KW_perspective: case KW_orthographic: case KW_fisheye: case KW_ultra_wide_angle:
        case KW_omnimax: case KW_panoramic: case KW_spherical: case KW_cylinder: case KW_mesh_camera:
            tok_fail(p, t->pos, "the camera type must come first in 'camera'");
        case KW_aperture: case KW_blur_samples: case KW_focal_point: case KW_confidence: case KW_variance:
            /* focal blur: a pinhole camera stands for it */
            tok_approximate(p, t, APPROX_FOCAL_BLUR, &c.approx);
            if (t->kw == KW_blur_samples) { /* one count, or min, max */
                (void)expr_float(p);
                if (tok_is_punct(tok_peek(p), ',')) {
                    tok_next(p);
                    (void)expr_float(p);
                }
            } else if (t->kw == KW_focal_point) {
                (void)expr_vector(p);
            } else {
                (void)expr_float(p);
            }
            break;
        case KW_normal: /* camera ray perturbation: ignored */
            tok_approximate(p, t, APPROX_FOCAL_BLUR, &c.approx);
            gram_skip_normal(p);
            break;
        case KW_bokeh:
            tok_unsupported(p, t);
        default:
            tok_fail_expected(p, t, "a camera item or '}' in 'camera'");
        }
    }

    if (had_angle)
        c.angle = angle;
    if (had_angle && (c.kind == CAMERA_PERSPECTIVE || c.kind == CAMERA_ORTHOGRAPHIC)) {
        if (angle >= 180.0)
            tok_fail(p, angle_tok.pos, "viewing angle has to be smaller than 180 degrees");
        if (angle > 0.0) {
            double right_len = v3_length(c.right);
            c.direction = v3_scale(v3_normalize(c.direction), right_len / tan(angle * M_PI / 360.0) / 2.0);
        }
    }
    if (had_look_at) {
        double dir_len = v3_length(c.direction), up_len = v3_length(c.up), right_len = v3_length(c.right);
        double handedness = v3_dot(v3_cross(c.up, c.direction), c.right);
        Vec3 d = v3_sub(look_at, c.location);
        if (v3_dot(d, d) < CAMERA_EPSILON)
            tok_fail(p, kw->pos, "camera location and look_at point must be different");
        d = v3_normalize(d);
        Vec3 old_right = c.right;
        c.right = v3_cross(sky, d);
        if (fabs(c.right.x) < CAMERA_EPSILON && fabs(c.right.y) < CAMERA_EPSILON &&
            fabs(c.right.z) < CAMERA_EPSILON)
            c.right = old_right; /* POV-Ray warns and keeps the given right */
        c.right = v3_normalize(c.right);
        c.up = v3_cross(d, c.right);
        c.direction = v3_scale(d, dir_len);
        c.right = v3_scale(c.right, handedness > 0.0 ? right_len : -right_len);
        c.up = v3_scale(c.up, up_len);
    }
    if (c.kind == CAMERA_ORTHOGRAPHIC && ((!had_up && !had_right) || had_angle)) {
        /* Same image area as the perspective camera would show at look_at. */
        Vec3 la = had_look_at ? look_at : v3(0, 0, 1);
        double k1 = v3_length(v3_sub(la, c.location)), k2 = v3_length(c.direction);
        if (k1 > CAMERA_EPSILON && k2 > CAMERA_EPSILON) {
            c.right = v3_scale(c.right, k1 / k2);
            c.up = v3_scale(c.up, k1 / k2);
        }
    }
    transform_camera(&c, &tr);
    *cam = c;
}

void gram_transform_light(Parser *p, SceneLight *l, const Transform *tr)
{
    l->location = transform_point(tr, l->location);
    l->point_at = transform_point(tr, l->point_at);
    l->area.axis1 = transform_direction(tr, l->area.axis1);
    l->area.axis2 = transform_direction(tr, l->area.axis2);
    if (l->looks_like) {
        SceneObject *o = tok_scene_alloc(p, sizeof *o);
        *o = *l->looks_like;
        gram_transform_object(o, tr);
        /* POV-Ray moves the child with Translate_Object when the light is
         * translated, else with Transform_Object, which makes a sphere its
         * ellipsoid whatever the transform */
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                if (tr->m[i][j] != (i == j ? 1.0 : 0.0))
                    o->general_transform = 1;
        l->looks_like = o;
    }
}

/* looks_like { OBJECT MODIFIERS }, after the keyword, as POV-Ray's
 * Parse_Light_Source reads it: the object as written, then moved to where
 * the light is at this point, then the modifiers written after it in the
 * block; it casts no shadow. */
static void light_looks_like(Parser *p, SceneLight *l, const Token *kw)
{
    if (l->looks_like)
        tok_fail(p, kw->pos, "only one looks_like allowed per light_source (POV-Ray: \"Only one looks_like allowed "
                             "per light_source.\")");
    tok_begin_block(p, "looks_like");
    Token t = *tok_next(p);
    SceneObject *o = NULL;
    SceneLight *inner = NULL;
    if (!gram_object(p, &t, &o, &inner) || !o)
        tok_fail_expected(p, &t, "an object in 'looks_like'");
    Transform to_light;
    transform_identity(&to_light);
    transform_translate(&to_light, l->location);
    gram_transform_object(o, &to_light);
    gram_object_mods(p, o, "looks_like");
    o->no_shadow = 1;
    l->looks_like = o;
}

SceneLight *gram_light_source(Parser *p, const Token *kw)
{
    tok_begin_block(p, "light_source");
    SceneLight *l = tok_scene_alloc(p, sizeof *l);
    l->kind = LIGHT_POINT;
    l->pos = kw->pos;
    l->point_at = (Vec3){ 0.0, 0.0, 1.0 }; /* POV-Ray's default */
    l->area.adaptive = 100; /* POV-Ray's: subdivide to every sample */
    l->location = expr_vector(p);
    expr_comma(p);
    expr_colour(p, &l->colour, 0);
    int area = 0, circular = 0;
    SourcePos circular_at = { 0 }, orient_at = { 0 };
    for (;;) {
        Token *t = tok_next(p);
        if (tok_is_punct(t, '}'))
            break;
        /* As in POV-Ray, a transform moves what is set so far: a point_at
         * written after it is taken as written. */
        Transform tr;
        transform_identity(&tr);
        if (expr_transform_item(p, t, &tr)) {
            gram_transform_light(p, l, &tr);
            continue;
        }
        switch (t->type == TK_WORD ? t->kw : -1) {
        case KW_shadowless: l->shadowless = 1; break;
        case KW_looks_like: light_looks_like(p, l, t); break;
        case KW_parallel: l->kind = LIGHT_PARALLEL; break;
        case KW_spotlight: /* POV-Ray's defaults, reset each time the keyword is written */
            l->beam = BEAM_SPOT;
            l->beam_radius = cos(30.0 * M_PI / 180.0);
            l->beam_falloff = cos(45.0 * M_PI / 180.0);
            l->beam_tightness = 0.0;
            break;
        case KW_cylinder:
            l->beam = BEAM_CYLINDER;
            l->kind = LIGHT_PARALLEL;
            l->beam_radius = 0.75;
            l->beam_falloff = 1.0;
            l->beam_tightness = 0.0;
            break;
        case KW_tightness:
        case KW_radius:
        case KW_falloff: {
            if (l->beam == BEAM_NONE)
                tok_fail(p, t->pos, "'%s' needs 'spotlight' or 'cylinder' before it in 'light_source'",
                           tok_keyword_name(t->kw));
            int item = t->kw; /* t is the parser's current token: expr_float moves it */
            double v = expr_float(p);
            if (item == KW_tightness)
                l->beam_tightness = v;
            else if (item == KW_radius)
                l->beam_radius = l->beam == BEAM_SPOT ? cos(v * M_PI / 180.0) : v;
            else
                l->beam_falloff = l->beam == BEAM_SPOT ? cos(v * M_PI / 180.0) : v;
            break;
        }
        case KW_point_at: l->point_at = expr_vector(p); break;
        case KW_fade_distance: l->fade_distance = expr_float(p); break;
        case KW_fade_power: l->fade_power = expr_float(p); break;
        case KW_media_attenuation: { /* fog on the light's rays: not modelled */
            Token at = *t;
            if (!expr_starts_float(p, tok_peek(p)) || expr_float(p) > 0.0) {
                p->gram->media_attenuation_seen = 1;
                if (p->gram->fogs.n > 0) /* else the fog, when it comes, reports it */
                    tok_approximate(p, &at, APPROX_FOG, &l->approx);
            }
            break;
        }
        case KW_media_interaction: /* only matters with media, which is unsupported */
            if (expr_starts_float(p, tok_peek(p)))
                (void)expr_float(p);
            break;
        case KW_photons: /* photon settings: parsed past, not modelled */
            tok_note_approximation(p, t, APPROX_PHOTONS, &l->photons);
            tok_begin_block(p, "photons");
            tok_skip_block_body(p);
            break;
        case KW_area_light: { /* POV-Ray's Parse_Light_Source: sizes truncated to integers */
            SourcePos area_at = t->pos; /* t is the parser's current token: expr_float moves it */
            area = 1;
            l->area.axis1 = expr_vector(p);
            expr_comma(p);
            l->area.axis2 = expr_vector(p);
            expr_comma(p);
            double size[2];
            for (int k = 0; k < 2; k++) {
                if (k)
                    expr_comma(p);
                SourcePos at = tok_peek(p)->pos;
                size[k] = expr_float(p);
                /* POV-Ray refuses 0; a negative size would index its
                 * sample grid out of bounds, so it is refused alike. */
                if (!(size[k] >= 1.0))
                    tok_fail(p, at, "area size must be greater than zero (POV-Ray: \"Area size must be greater "
                                      "than zero.\"), not %g", size[k]);
            }
            if (size[0] * size[1] > (double)MAX_AREA_LIGHT_SAMPLES)
                tok_fail(p, area_at, "an area_light of %g x %g samples is more than hstrace's limit of %d",
                           size[0], size[1], MAX_AREA_LIGHT_SAMPLES);
            l->area.size1 = (int)size[0];
            l->area.size2 = (int)size[1];
            break;
        }
        /* area_light's modifiers, in any order around it. Without an
         * area_light POV-Ray ignores them (orient, circular and
         * area_illumination with a warning), but circular at the end it
         * refuses. */
        case KW_adaptive: l->area.adaptive = (int)expr_float(p); break;
        case KW_jitter: l->area.jitter = 1; break;
        case KW_orient:
            l->area.orient = 1;
            orient_at = t->pos;
            break;
        case KW_circular:
            if (!circular)
                circular_at = t->pos;
            circular = 1;
            l->area.circular = 1;
            break;
        case KW_area_illumination:
            l->area.full_area = expr_starts_float(p, tok_peek(p)) ? expr_float(p) > 0.0 : 1;
            break;
        default:
            if (t->type == TK_WORD && t->kw >= 0)
                tok_unsupported(p, t); /* projected_through, fill_light, ... */
            tok_fail_expected(p, t, "a light_source item or '}' in 'light_source'");
        }
    }
    if (circular && (!area || l->area.size1 <= 1 || l->area.size2 <= 1))
        tok_fail(p, circular_at, "'circular' %s (POV-Ray: \"Circular area light must have more than 1 point per "
                                   "axis\")", area ? "with an area_light of 1 point along an axis" : "without an area_light");
    if (!area)
        l->area = (AreaLight){ .adaptive = 100 }; /* the modifiers change nothing */
    if (l->area.orient) {
        /* POV-Ray's Parse_Object_Mods: orient makes the light circular, and
         * takes axis 1's length for both axes */
        if (!l->area.circular)
            tok_warning(p, orient_at, "orient makes the area light circular (POV-Ray: \"Orient can only be used with "
                                        "circular area lights. This area light is now circular.\")");
        if (fabs(v3_length(l->area.axis1) - v3_length(l->area.axis2)) > 1e-10)
            tok_warning(p, orient_at, "with orient, only the first axis's length is used for both");
        l->area.circular = 1;
        if (l->area.size1 <= 1 || l->area.size2 <= 1)
            l->area.circular = 0; /* POV-Ray: warns, and the light is not circular after all */
    }
    return l;
}
