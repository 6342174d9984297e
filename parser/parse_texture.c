/* texture, pigment, finish, interior (and normal, which is read and dropped).
 *
 * Each block starts from its identifier when one comes first, otherwise
 * from the default (POV-Ray copies the default texture), then applies what
 * is written. Only solid pigments are modelled; a pattern is "not supported". */
#include <math.h>
#include <string.h>

#include "parser_internal.h"

SceneTexture *new_default_texture(Parser *p)
{
    SceneTexture *t = palloc(p, sizeof *t);
    *t = p->scene->default_texture;
    return t;
}

/* The identifier at t when it holds `kind`; errors for other identifiers. */
static const Value *block_identifier(Parser *p, const Token *t, ValueKind kind, const char *block)
{
    if (t->type != TK_WORD || t->kw >= 0)
        return NULL;
    Symbol *s = token_symbol(p, t);
    if (!s)
        parse_fail(p, t->pos, "undeclared identifier '%.*s'", t->len, t->text);
    if (s->value.kind == VAL_UNSUPPORTED)
        use_unsupported(p, t, &s->value);
    if (s->value.kind == kind)
        return &s->value;
    if (kind == VAL_PIGMENT && s->value.kind == VAL_NUMERIC)
        return NULL; /* a colour identifier: the caller reads it as a colour */
    parse_fail(p, t->pos, "'%.*s' cannot be used in a %s", t->len, t->text, block);
}

void skip_normal(Parser *p)
{
    begin_block(p, "normal");
    skip_block_body(p);
}

void parse_pigment(Parser *p, Pigment *pig)
{
    begin_block(p, "pigment");
    for (;;) {
        Token *t = next(p);
        if (is_punct(t, '}'))
            return;
        const Value *id = block_identifier(p, t, VAL_PIGMENT, "pigment");
        if (id) {
            *pig = *id->pigment;
            continue;
        }
        if (token_starts_colour(p, t)) {
            unget(p);
            parse_colour(p, &pig->colour, 1);
            pig->kind = PIGMENT_SOLID;
            continue;
        }
        if (parse_transform_item(p, t, &pig->transform))
            continue;
        if (is_kw(t, KW_quick_color) || is_kw(t, KW_quick_colour)) {
            Colour ignored;
            parse_colour(p, &ignored, 1);
            continue;
        }
        if (t->type == TK_WORD && t->kw >= 0)
            unsupported(p, t); /* a pattern, warp, turbulence, ... */
        fail_expected(p, t, "a colour, a transform or '}' in 'pigment'");
    }
}

/* `albedo` after diffuse/phong/specular: the value is rescaled at the end. */
static int allow_albedo(Parser *p)
{
    if (is_kw(next(p), KW_albedo))
        return 1;
    unget(p);
    return 0;
}

static void colour_to_rgb(double out[3], const Colour *c)
{
    out[0] = c->r;
    out[1] = c->g;
    out[2] = c->b;
}

static void parse_reflection(Parser *p, Finish *f)
{
    Colour c;
    Token *t = next(p);
    if (!is_punct(t, '{')) {
        unget(p);
        parse_colour(p, &c, 0); /* old syntax: one colour */
        colour_to_rgb(f->reflection_max, &c);
        colour_to_rgb(f->reflection_min, &c);
        f->reflection_falloff = 1.0;
        f->reflection_fresnel = 0;
        return;
    }
    parse_colour(p, &c, 0);
    colour_to_rgb(f->reflection_min, &c);
    parse_comma(p);
    int second = 0;
    t = peek(p);
    if (token_starts_expression(p, t)) {
        parse_colour(p, &c, 0);
        second = 1;
    }
    colour_to_rgb(f->reflection_max, &c);
    for (;;) {
        t = next(p);
        if (is_punct(t, '}'))
            return;
        if (is_kw(t, KW_fresnel)) {
            double v = 1.0;
            if (token_starts_float(p, peek(p)))
                v = parse_float(p);
            f->reflection_fresnel = (int)v;
            if (f->reflection_fresnel < 0 || f->reflection_fresnel > 1)
                parse_fail(p, t->pos, "fresnel must be true or false");
            if (!second && f->reflection_fresnel)
                memset(f->reflection_min, 0, sizeof f->reflection_min);
        } else if (is_kw(t, KW_falloff)) {
            f->reflection_falloff = parse_float(p);
        } else if (is_kw(t, KW_exponent)) {
            (void)parse_float(p); /* reflection exponent: not modelled */
        } else if (is_kw(t, KW_metallic)) {
            f->reflection_metallic = token_starts_float(p, peek(p)) ? parse_float(p) : 1.0;
        } else {
            fail_expected(p, t, "fresnel, falloff, exponent, metallic or '}' in 'reflection'");
        }
    }
}

void parse_finish(Parser *p, Finish *f)
{
    int diffuse_albedo = 0, phong_albedo = 0, specular_albedo = 0;
    begin_block(p, "finish");
    for (;;) {
        Token *t = next(p);
        if (is_punct(t, '}'))
            break;
        const Value *id = block_identifier(p, t, VAL_FINISH, "finish");
        if (id) {
            *f = *id->finish;
            continue;
        }
        Colour c;
        switch (t->type == TK_WORD ? t->kw : -1) {
        case KW_ambient:
            parse_colour(p, &c, 0);
            colour_to_rgb(f->ambient, &c);
            break;
        case KW_emission:
            parse_colour(p, &c, 0);
            colour_to_rgb(f->emission, &c);
            break;
        case KW_diffuse:
            diffuse_albedo = allow_albedo(p);
            f->diffuse = parse_float(p);
            if (is_punct(next(p), ',')) {
                if (parse_float(p) != 0.0)
                    parse_fail(p, t->pos, "'diffuse' with a backside value is not supported by hstrace");
            } else {
                unget(p);
            }
            break;
        case KW_brilliance: f->brilliance = parse_float(p); break;
        case KW_crand: f->crand = parse_float(p); break;
        case KW_phong:
            phong_albedo = allow_albedo(p);
            f->phong = parse_float(p);
            break;
        case KW_phong_size: f->phong_size = parse_float(p); break;
        case KW_specular:
            specular_albedo = allow_albedo(p);
            f->specular = parse_float(p);
            break;
        case KW_roughness: f->roughness = parse_float(p); break;
        case KW_metallic:
            f->metallic = token_starts_float(p, peek(p)) ? parse_float(p) : 1.0;
            break;
        case KW_reflection: parse_reflection(p, f); break;
        case KW_reflection_exponent: (void)parse_float(p); break;
        case KW_conserve_energy: f->conserve_energy = 1; break;
        case KW_irid: /* iridescence: parsed past, not modelled */
            begin_block(p, "irid");
            skip_block_body(p);
            break;
        case KW_ior: case KW_caustics: case KW_refraction: /* pre-3.0 spellings of interior settings */
            (void)parse_float(p);
            break;
        default:
            if (t->type == TK_WORD && t->kw >= 0)
                unsupported(p, t);
            fail_expected(p, t, "a finish item or '}' in 'finish'");
        }
    }
    /* POV-Ray's albedo rescaling; its roughness is the reciprocal of ours. */
    if (diffuse_albedo)
        f->diffuse *= (f->brilliance + 1.0) / 2.0;
    if (phong_albedo)
        f->phong *= (f->phong_size + 1.0) / 2.0;
    if (specular_albedo && f->roughness != 0.0) {
        double r = 1.0 / f->roughness;
        f->specular *= (r + 2.0) / (4.0 * (2.0 - pow(2.0, -r / 2.0)));
    }
}

void parse_interior(Parser *p, Interior *in)
{
    begin_block(p, "interior");
    for (;;) {
        Token *t = next(p);
        if (is_punct(t, '}'))
            return;
        const Value *id = block_identifier(p, t, VAL_INTERIOR, "interior");
        if (id) {
            *in = *id->interior;
            continue;
        }
        switch (t->type == TK_WORD ? t->kw : -1) {
        case KW_ior: in->ior = parse_float(p); break;
        case KW_fade_distance: in->fade_distance = parse_float(p); break;
        case KW_fade_power: in->fade_power = parse_float(p); break;
        case KW_fade_color:
        case KW_fade_colour: parse_colour(p, &in->fade_colour, 0); break;
        case KW_caustics: case KW_dispersion: case KW_dispersion_samples:
            (void)parse_float(p); /* photon and dispersion settings: not modelled */
            break;
        default:
            if (t->type == TK_WORD && t->kw >= 0)
                unsupported(p, t);
            fail_expected(p, t, "ior, fade_distance, fade_power, fade_colour or '}' in 'interior'");
        }
    }
}

SceneTexture *parse_texture(Parser *p)
{
    Token kw = p->tok;
    begin_block(p, "texture");
    SceneTexture *tex = new_default_texture(p);
    tex->pos = kw.pos;
    for (;;) {
        Token *t = next(p);
        if (is_punct(t, '}'))
            return tex;
        const Value *id = block_identifier(p, t, VAL_TEXTURE, "texture");
        if (id) {
            *tex = *id->texture;
            tex->pos = kw.pos;
            continue;
        }
        switch (t->type == TK_WORD ? t->kw : -1) {
        case KW_pigment: parse_pigment(p, &tex->pigment); break;
        case KW_finish: parse_finish(p, &tex->finish); break;
        case KW_normal: skip_normal(p); break;
        default:
            if (parse_transform_item(p, t, &tex->pigment.transform))
                break;
            if (t->type == TK_WORD && t->kw >= 0)
                unsupported(p, t);
            fail_expected(p, t, "pigment, normal, finish, a transform or '}' in 'texture'");
        }
    }
}
