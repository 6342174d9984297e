/* The top level: scene statements, #declare values, and the public
 * entry points of parser.h. */
#include <ctype.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "keywords.h"
#include "grammar.h"
#include "truetype_font.h"

/* ---- #declare ------------------------------------------------------------ */

static int is_unsupported_value_keyword(int kw)
{
    switch (kw) {
    case KW_function: case KW_spline: case KW_pattern: case KW_media: case KW_density:
    case KW_fog: case KW_rainbow:
    case KW_density_map: case KW_photons: case KW_radiosity: case KW_interior_texture:
    case KW_trace: case KW_vturbulence: case KW_file_exists:
    case KW_datetime: case KW_now:
        return 1;
    default:
        return 0;
    }
}

/* The value of a declaration, whatever it is. */
static Value parse_rvalue(Parser *p)
{
    Value v;
    memset(&v, 0, sizeof v);
    Token t = *tok_next(p);
    SceneObject *obj;
    SceneLight *light;
    if (t.type == TK_WORD && t.kw >= 0) {
        switch (t.kw) {
        case KW_texture:
            v.kind = VAL_TEXTURE;
            v.texture = gram_texture(p);
            return v;
        case KW_pigment:
            v.kind = VAL_PIGMENT;
            v.pigment = tok_scene_alloc(p, sizeof *v.pigment);
            *v.pigment = p->scene->default_texture.pigment;
            gram_pigment(p, v.pigment);
            return v;
        case KW_finish:
            v.kind = VAL_FINISH;
            v.finish = tok_scene_alloc(p, sizeof *v.finish);
            *v.finish = p->scene->default_texture.finish;
            gram_finish(p, v.finish);
            return v;
        case KW_material:
            v.kind = VAL_MATERIAL;
            gram_material(p, &v.material_texture, &v.material_interior, &t);
            return v;
        case KW_interior:
            v.kind = VAL_INTERIOR;
            v.interior = tok_scene_alloc(p, sizeof *v.interior);
            *v.interior = scene_default_interior();
            gram_interior(p, v.interior);
            return v;
        case KW_normal:
            v.kind = VAL_NORMAL;
            v.normal = gram_normal(p, NULL, &t, 0);
            return v;
        case KW_sky_sphere: /* skies.inc declares its skies */
            v.kind = VAL_SKY_SPHERE;
            v.sky = tok_scene_alloc(p, sizeof *v.sky);
            gram_sky_sphere(p, v.sky);
            return v;
        case KW_camera:
            v.kind = VAL_CAMERA;
            v.camera = tok_scene_alloc(p, sizeof *v.camera);
            gram_camera(p, &t, v.camera);
            return v;
        case KW_transform:
            v.kind = VAL_TRANSFORM;
            v.transform = tok_scene_alloc(p, sizeof *v.transform);
            transform_identity(v.transform);
            expr_transform_block(p, v.transform);
            return v;
        case KW_array:
            return tok_array_value(p, &t);
        case KW_color_map: case KW_colour_map: case KW_pigment_map:
            v.kind = t.kw == KW_pigment_map ? VAL_PIGMENT_MAP : VAL_COLOUR_MAP;
            v.pigment = tok_scene_alloc(p, sizeof *v.pigment);
            memset(v.pigment, 0, sizeof *v.pigment);
            if (t.kw == KW_pigment_map)
                gram_pigment_map(p, v.pigment, &t);
            else
                gram_colour_map(p, v.pigment);
            return v;
        case KW_texture_map:
            v.kind = VAL_TEXTURE_MAP;
            v.texture = tok_scene_alloc(p, sizeof *v.texture);
            memset(v.texture, 0, sizeof *v.texture);
            gram_texture_map(p, v.texture, &t);
            return v;
        case KW_normal_map: case KW_slope_map: {
            SceneNormal *n = tok_scene_alloc(p, sizeof *n);
            memset(n, 0, sizeof *n);
            v.kind = t.kw == KW_normal_map ? VAL_NORMAL_MAP : VAL_SLOPE_MAP;
            if (t.kw == KW_normal_map)
                gram_normal_map(p, n, 0);
            else
                gram_slope_map(p, n);
            v.normal = n;
            return v;
        }
        default:
            break;
        }
        if (gram_object(p, &t, &obj, &light)) {
            v.kind = obj ? VAL_OBJECT : VAL_LIGHT;
            v.object = obj;
            v.light = light;
            return v;
        }
        if (t.kw == KW_material_map) /* POV-Ray's Parse_RValue has no case for it either */
            tok_fail(p, t.pos, "a material_map cannot be declared on its own: write it in a texture "
                                 "(#declare T = texture { material_map { ... } })");
        if (is_unsupported_value_keyword(t.kw))
            tok_unsupported(p, &t);
    }
    if (t.type == TK_WORD && t.kw < 0) {
        Symbol *s = tok_symbol_of(p, &t);
        if (!s)
            tok_fail(p, t.pos, "undeclared identifier '%.*s'", t.len, t.text);
        if (s->value.kind == VAL_UNSUPPORTED)
            tok_use_unsupported(p, &t, &s->value);
        if (s->value.kind != VAL_NUMERIC && s->value.kind != VAL_STRING)
            return gram_copy_value(p, &s->value); /* a copy of a declared object, texture, array ... */
    }
    tok_unget(p);
    if (expr_starts_string(p, &t)) {
        v.kind = VAL_STRING;
        v.string = expr_string(p);
        return v;
    }
    if (!expr_starts_expression(p, &t)) {
        if (t.type == TK_WORD && t.kw >= 0)
            tok_unsupported(p, &t);
        tok_fail_expected(p, &t, "a value after '='");
    }
    v.kind = VAL_NUMERIC;
    v.terms = 1;
    /* As POV-Ray's Parse_RValue: sums and products only. Comparisons, '&',
     * '|' and '?:' need parentheses, so in `array[2] {<1,2> <3,4>}` the second
     * '<' starts the next element, not a comparison. */
    expr_rel_factor(p, v.v, &v.terms);
    if (v.terms > 5)
        v.terms = 5;
    return v;
}

/* After an unsupported keyword in a declaration: skip the rest of the value,
 * directives still obeyed, so the file reads on as POV-Ray would. */
static void skip_poisoned_value(Parser *p, int start_depth)
{
    if (p->brace_depth > start_depth) {
        /* inside the value's braces: read to the one closing the value */
        while (p->brace_depth > start_depth) {
            Token *t = tok_next(p);
            if (t->type == TK_EOF)
                tok_fail(p, t->pos, "expected '}' before the end of the file");
        }
        return;
    }
    /* A value poisoned after it was read whole -- a texture layer that
     * --strict refuses once it is blended -- leaves nothing to skip.
     * Reading on would carry out the directives after it before the value
     * is stored: skies.inc's `#declare O_Cloud2 = union { ... T_Cloud3
     * ... }` right after T_Cloud3 would find T_Cloud3 undeclared. Only
     * when the poisoning token is the last one read may its arguments
     * follow. */
    const Token *last = &p->tok;
    if (last->pos.line != p->poison_by.line || last->pos.column != p->poison_by.column ||
        last->pos.file != p->poison_by.file)
        return;
    /* The keyword itself was unsupported: `sphere {...}`, `array[3] {...}`,
     * `function(x) {...}`, a macro call `Foo(1, 2)`. */
    for (;;) {
        Token *t = tok_next(p);
        if (tok_is_punct(t, '(') || tok_is_punct(t, '[')) {
            Token open = *t;
            tok_skip_balanced_group(p, &open);
            continue;
        }
        if (tok_is_punct(t, '{')) {
            tok_skip_block_body(p);
            return;
        }
        tok_unget(p);
        return;
    }
}

/* Arrays can hold arrays, and `#declare A[0] = A` in a loop nests them one
 * level deeper each time without any nesting in the text: the copy, which
 * recurses through them, is where that depth is bounded. */
static Value copy_value_at(Parser *p, const Value *v, int depth)
{
    Value c = *v;
    if (v->kind == VAL_ARRAY) {
        if (depth > MAX_NESTING)
            tok_fail(p, p->last_pos, "nested too deeply (arrays in arrays more than %d levels)", MAX_NESTING);
        /* POV-Ray copies arrays on assignment: `#declare B = A` and then
         * `#declare B[0] = ...` leaves A as it was. */
        ArrayValue *a = tok_array_new(p, v->array->count);
        a->ndims = v->array->ndims;
        memcpy(a->size, v->array->size, sizeof a->size);
        a->declared_at = v->array->declared_at;
        for (long i = 0; i < a->count; i++)
            a->elems[i].value = copy_value_at(p, &v->array->elems[i].value, depth + 1);
        c.array = a;
    }
    return c;
}

Value gram_copy_value(Parser *p, const Value *v)
{
    return copy_value_at(p, v, 1);
}

/* What a lenient parse reads: a whole right-hand value, or one more
 * `texture {...}` layered on top of the declared texture. */
typedef struct {
    const Token *layer; /* NULL: a value; else the layer's 'texture' */
    Value below;        /* with layer: the texture it goes on top of */
} LenientWhat;

/* Reads what `what` says, turning "unsupported" from anywhere inside it
 * (an error, or a deferred unsupported identifier) into a VAL_UNSUPPORTED
 * value that remembers what and where, instead of failing. */
static Value parse_lenient(Parser *p, const LenientWhat *what)
{
    jmp_buf here;
    jmp_buf *volatile outer = p->poison_jmp;
    volatile int saved_nesting = p->nesting, saved_declaring = p->declaring;
    volatile int saved_args = p->arg_values.n; /* macro calls inside, left half read */
    volatile int start_depth = p->brace_depth;
    const char *volatile outer_deferred = p->deferred_what;
    volatile SourcePos outer_deferred_at = p->deferred_at;
    Value v;
    p->poison_jmp = &here;
    p->declaring++;
    p->deferred_what = NULL;
    if (setjmp(here) == 0) {
        if (what->layer) {
            SceneTexture *top = gram_texture(p);
            v = what->below;
            v.texture = gram_layer_textures(p, top, what->below.texture, what->layer);
        } else {
            v = parse_rvalue(p);
        }
        if (p->deferred_what) {
            memset(&v, 0, sizeof v);
            v.kind = VAL_UNSUPPORTED;
            v.what = p->deferred_what;
            v.declared_at = p->deferred_at;
        }
    } else {
        p->nesting = saved_nesting;
        p->arg_values.n = p->arg_refs.n = saved_args;
        memset(&v, 0, sizeof v);
        v.kind = VAL_UNSUPPORTED;
        v.what = p->poison_what;
        v.declared_at = p->poison_at;
        v.strict_only = p->poison_strict;
        skip_poisoned_value(p, start_depth);
    }
    p->declaring = saved_declaring;
    p->poison_jmp = outer;
    p->deferred_what = outer_deferred;
    p->deferred_at = outer_deferred_at;
    return v;
}

Value gram_value_lenient(Parser *p)
{
    LenientWhat what = { NULL, { 0 } };
    return parse_lenient(p, &what);
}

void gram_declare(Parser *p, const Token *hash, int local)
{
    Token name = *tok_next_name(p);
    if (tok_is_kw(&name, KW_deprecated)) {
        /* #declare deprecated [once] "message" Name = ...: the warning is dropped */
        if (!tok_is_kw(tok_next(p), KW_once))
            tok_unget(p);
        (void)expr_string(p);
        name = *tok_next_name(p);
    }
    if (name.type != TK_WORD)
        tok_fail_expected(p, &name, "an identifier after #declare");
    if (name.kw >= 0)
        tok_fail(p, name.pos, "'%s' is a reserved word and cannot be declared", tok_keyword_name(name.kw));
    if (!name.elem) {
        Symbol *old = tok_symbol_find(p, name.text, name.len);
        if (old && old->value.kind == VAL_MACRO)
            tok_fail(p, name.pos, "'%.*s' is a macro (declared at %s:%d) and cannot be redeclared", name.len,
                       name.text, old->value.declared_at.file, old->value.declared_at.line);
    }
    Token *t = tok_next(p);
    if (tok_is_punct(t, '['))
        tok_fail(p, t->pos, "'%.*s' is not an array", name.len, name.text);
    if (!tok_is_punct(t, '=')) {
        char what[120];
        snprintf(what, sizeof what, "'=' after '#declare %.*s'", name.len > 60 ? 60 : name.len, name.text);
        tok_fail_expected(p, t, what);
    }
    Token first = *tok_peek(p);
    /* The version the value is read under decides whether it needs a ';'
     * (POV-Ray's rule, measured): the lookahead after a value carries out
     * the directives that follow, a `#version` an old include ends with
     * among them, which must not turn its last #declare into an error. */
    const double version_of_value = p->version;
    Value v = gram_value_lenient(p);
    (void)hash;

    /* `texture {...} texture {...}`: POV-Ray layers the textures, the
     * later on top (gram_layer_textures). */
    if (tok_is_kw(&first, KW_texture)) {
        while (tok_next_is_keyword(p, KW_texture)) {
            Token layer = *tok_next(p);
            if (v.kind != VAL_TEXTURE) {
                tok_begin_block(p, "texture");
                tok_skip_block_body(p);
                continue;
            }
            LenientWhat what = { &layer, v };
            v = parse_lenient(p, &what);
        }
    }

    /* Stored before looking for the ';': that lookahead carries out the
     * directives that follow, which may use the new value (or, at the end of
     * a macro's body, close the level a #local belongs to). */
    if (name.elem) {
        Symbol *e = tok_element_of(&name);
        if (e) {
            tok_value_give_up(p, &e->value);
            e->value = v;
        } else {
            tok_value_give_up(p, &v);
        }
    } else
        tok_symbol_set(p, name.text, name.len, local, &v);

    /* POV-Ray 3.5+ wants ';' after float, vector and colour values (a parse
     * error in POV-Ray 3.7 too); after a string or a block it is optional:
     * POV-Ray 3.7 renders `#declare S = "x"` followed by anything. */
    Token *s = tok_next(p);
    if (!tok_is_punct(s, ';')) {
        if (v.kind == VAL_NUMERIC && version_of_value >= 3.5)
            tok_fail_expected(p, s, "';' after the declared value");
        tok_unget(p);
    }
}

/* #default { texture {...} | pigment {...} | finish {...} | normal {...} } */
void gram_default_directive(Parser *p)
{
    tok_begin_block(p, "#default");
    SceneTexture *d = &p->scene->default_texture;
    for (;;) {
        Token *t = tok_next(p);
        if (tok_is_punct(t, '}'))
            break;
        switch (t->type == TK_WORD ? t->kw : -1) {
        case KW_texture: {
            SceneTexture *n = gram_texture(p);
            *d = *n;
            break;
        }
        case KW_pigment: case KW_finish:
            if (d->nmap > 0) /* a default texture_map has no pigment or finish of its own */
                tok_fail(p, t->pos, "#default: %s after a default texture that is a texture_map",
                           tok_keyword_name(t->kw));
            if (t->kw == KW_pigment)
                gram_pigment(p, &d->pigment);
            else
                gram_finish(p, &d->finish);
            break;
        case KW_normal: {
            Token at = *t;
            d->normal = gram_normal(p, d->normal, &at, 0);
            break;
        }
        default:
            if (t->type == TK_WORD && t->kw >= 0)
                tok_unsupported(p, t);
            tok_fail_expected(p, t, "texture, pigment, finish, normal or '}' in #default");
        }
    }
    p->gram->default_changed = 1;
}

/* ---- scene statements ---------------------------------------------------- */

/* max_trace_level's value, after the keyword: at least 1, and at most
 * POV-Ray's limit, with a warning. */
static void max_trace_level(Parser *p)
{
    Token at = *tok_peek(p);
    double v = expr_float(p);
    p->scene->globals.max_trace_level = int_clamped(v, 1, MAX_TRACE_LEVEL_LIMIT);
    if (v > MAX_TRACE_LEVEL_LIMIT) {
        char msg[160];
        snprintf(msg, sizeof msg, "max_trace_level %g is more than POV-Ray's limit, %d: %d is used", v,
                 MAX_TRACE_LEVEL_LIMIT, MAX_TRACE_LEVEL_LIMIT);
        tok_warning(p, at.pos, msg);
    }
}

static void parse_global_settings(Parser *p)
{
    GlobalSettings *g = &p->scene->globals;
    tok_begin_block(p, "global_settings");
    for (;;) {
        Token t = *tok_next(p);
        if (tok_is_punct(&t, '}'))
            return;
        Colour c;
        switch (t.type == TK_WORD ? t.kw : -1) {
        case KW_assumed_gamma: {
            Token *n = tok_next(p);
            double gamma = 0.0; /* srgb */
            if (!tok_is_kw(n, KW_srgb)) {
                tok_unget(p);
                Token at = *tok_peek(p);
                gamma = expr_float(p);
                if (gamma <= 0.0)
                    tok_fail(p, at.pos, "gamma value must be positive");
            }
            if (!p->gamma_set) { /* POV-Ray ignores a second assumed_gamma, value and all */
                g->assumed_gamma = gamma;
                g->assumed_gamma_srgb = gamma == 0.0;
                g->has_assumed_gamma = 1;
            }
            gram_assumed_gamma_seen(p, gamma);
            break;
        }
        case KW_max_trace_level: max_trace_level(p); break;
        case KW_adc_bailout: g->adc_bailout = expr_float(p); break;
        case KW_ambient_light:
            expr_colour(p, &c, 0);
            g->ambient_light = c;
            break;
        case KW_charset: {
            /* how later strings are read (String_To_UCS2): text's characters */
            Token *cs = tok_next(p);
            if (tok_is_kw(cs, KW_utf8))
                p->gram->charset = TTF_CHARSET_UTF8;
            else if (tok_is_kw(cs, KW_sys))
                p->gram->charset = TTF_CHARSET_SYS;
            else if (tok_is_kw(cs, KW_ascii))
                p->gram->charset = TTF_CHARSET_ASCII;
            else
                tok_fail_expected(p, cs, "ascii, utf8 or sys");
            break;
        }
        case KW_radiosity: case KW_photons: case KW_subsurface:
            /* Not modelled: parsed past and ignored, so scenes written for
             * POV-Ray still load (their lighting will differ). */
            if (t.kw == KW_photons)
                tok_note_approximation(p, &t, APPROX_PHOTONS, &p->gram->global_photons);
            else
                tok_approximate(p, &t, APPROX_RADIOSITY, &p->gram->global_approx);
            if (t.kw == KW_radiosity)
                g->radiosity = 1;
            tok_begin_block(p, tok_keyword_name(t.kw));
            tok_skip_block_body(p);
            break;
        case KW_irid_wavelength:
            expr_colour(p, &c, 0);
            break;
        case KW_noise_generator: {
            Token at = *tok_peek(p);
            if (!int_from_double(expr_float(p), 1, 3, &g->noise_generator))
                tok_fail(p, at.pos, "Value for noise_generator in global_settings must be 1, 2, or 3.");
            break;
        }
        case KW_number_of_waves: {
            /* POV-Ray: (int) of the value, at least 1 with a warning */
            Token at = *tok_peek(p);
            double v = expr_float(p);
            if (v > MAX_NUMBER_OF_WAVES)
                tok_fail(p, at.pos, "number_of_waves %g is more than hstrace supports (%d)", v, MAX_NUMBER_OF_WAVES);
            g->number_of_waves = v >= 1.0 ? (int)v : 1;
            if (v < 1.0)
                tok_warning(p, at.pos, "Illegal Value: number_of_waves must be greater than 0. Changed to 1.");
            break;
        }
        case KW_max_intersections: case KW_hf_gray_16:
        case KW_mm_per_unit:
            if (expr_starts_float(p, tok_peek(p)))
                (void)expr_float(p);
            break;
        default:
            if (t.type == TK_WORD && t.kw >= 0)
                tok_unsupported(p, &t);
            tok_fail_expected(p, &t, "a global setting or '}' in 'global_settings'");
        }
    }
}

static void add_object(Parser *p, SceneObject *o, SceneLight *l)
{
    if (l) {
        *(SceneLight *)tok_tvec_push(p, &p->gram->lights) = *l;
        if (l->looks_like) /* an object of the scene, where the light is */
            add_object(p, gram_copy_object(p, l->looks_like), NULL);
        return;
    }
    if (!o->texture && p->gram->default_changed)
        o->texture = gram_default_texture(p); /* POV-Ray binds the default at this point */
    Transform world;
    transform_identity(&world);
    gram_instantiate_union_lights(p, o, &world, 0);
    *(SceneObject **)tok_tvec_push(p, &p->gram->objects) = o;
}

static void parse_statements(Parser *p)
{
    for (;;) {
        Token t = *tok_next(p);
        if (t.type == TK_EOF)
            return;
        SceneObject *o;
        SceneLight *l;
        if (gram_object(p, &t, &o, &l)) {
            add_object(p, o, l);
            continue;
        }
        switch (t.type == TK_WORD ? t.kw : -1) {
        case KW_camera:
            gram_camera(p, &t, &p->scene->camera);
            p->scene->has_camera = 1;
            break;
        case KW_background: {
            tok_begin_block(p, "background");
            expr_colour(p, &p->scene->background, 1);
            tok_expect_punct(p, '}', "the background colour");
            break;
        }
        case KW_global_settings:
            parse_global_settings(p);
            break;
        case KW_sky_sphere:
            gram_sky_sphere(p, &p->scene->sky);
            break;
        case KW_fog:
            gram_fog(p, &t, tok_tvec_push(p, &p->gram->fogs));
            break;
        case KW_default:
            /* `default { ... }` without '#': the older spelling, which POV-Ray
             * 3.7 still reads as #default (several of its sample scenes use it). */
            gram_default_directive(p);
            break;
        case KW_max_trace_level:
            /* POV-Ray 3.0's place for it, which POV-Ray 3.7's Parse_Frame
             * still reads as the global setting, with this warning */
            tok_warning(p, t.pos, "'max_trace_level' should be in global_settings block");
            max_trace_level(p);
            break;
        case KW_max_intersections:
            /* no effect in POV-Ray 3.7 (Parse_Frame reads it and says so) */
            (void)expr_float(p);
            break;
        default:
            if (t.type == TK_WORD && t.kw >= 0)
                tok_unsupported(p, &t); /* fog, sky_sphere, rainbow, media, ... */
            if (t.type == TK_WORD) {
                Symbol *s = tok_symbol_of(p, &t);
                if (s && s->value.kind == VAL_UNSUPPORTED)
                    tok_use_unsupported(p, &t, &s->value);
                if (!s)
                    tok_fail(p, t.pos, "undeclared identifier '%.*s'", t.len, t.text);
                tok_fail(p, t.pos, "'%.*s' cannot stand alone here; use object { %.*s }", t.len, t.text,
                           t.len, t.text);
            }
            tok_fail_expected(p, &t, "an object or a scene statement");
        }
    }
}

/* ---- entry points ------------------------------------------------------ */

static void init_scene(Scene *s)
{
    s->version = 3.7;
    gram_default_camera(&s->camera);
    s->background.transmit = 1.0;
    s->globals.max_trace_level = 5;
    s->globals.adc_bailout = 1.0 / 255.0;
    s->globals.number_of_waves = 10;
    s->globals.ambient_light = (Colour){ 1, 1, 1, 0, 0 };
    s->default_texture.pigment.kind = PIGMENT_SOLID;
    transform_identity(&s->default_texture.pigment.transform);
    s->default_texture.finish = scene_default_finish();
}

/* Everything after the setjmp lives here, so no local of run_parser is
 * modified between setjmp and a longjmp. */
/* The symbols the command line or an INI file declared (Declare=NAME=VALUE),
 * as global #declares made before the scene's first line. */
static void declare_given(Parser *p, SourcePos start)
{
    for (int i = 0; i < p->opts->ndeclares; i++) {
        const ParseDeclare *d = &p->opts->declares[i];
        int len = (int)strlen(d->name), ok = len > 0 && (isalpha((unsigned char)d->name[0]) || d->name[0] == '_');
        for (int k = 1; ok && k < len; k++)
            ok = isalnum((unsigned char)d->name[k]) || d->name[k] == '_';
        if (!ok)
            tok_fail(p, start, "Declare=%s: '%s' is not an identifier", d->name, d->name);
        if (tok_keyword_lookup(d->name, len) >= 0)
            tok_fail(p, start, "Declare=%s: '%s' is a reserved word", d->name, d->name);
        if (tok_symbol_find(p, d->name, len))
            continue; /* declared before: the first value stands */
        Value v;
        memset(&v, 0, sizeof v);
        if (d->string) {
            v.kind = VAL_STRING;
            v.string = arena_strdup(p->temp, d->string);
        } else {
            v.kind = VAL_NUMERIC;
            v.terms = 1;
            v.v[0] = d->number;
        }
        v.declared_at = start;
        tok_symbol_define_global(p, d->name, len, &v);
    }
}

static Scene *parse_everything(Parser *p, const char *name, const char *text, size_t len)
{
    Scene *scene = p->scene;
    SourcePos start = { name, 0, 0 };
    if (text) {
        char *copy = tok_temp_alloc(p, len + 1);
        memcpy(copy, text, len);
        tok_open_buffer(p, name, copy, len, start);
    } else {
        SourceText scene_text;
        if (!tok_source_read(p, name, start, &scene_text))
            tok_fail_io(p, start, "cannot open scene file '%s': %s", name, strerror(errno));
        tok_open_source(p, &scene_text, start);
    }
    declare_given(p, start);
    parse_statements(p);
    tok_debug_end_line(p);
    tok_user_files_close_all(p, 1);
    gram_collect_approximations(p);

    scene->version = p->version;
    scene->version_given = p->version_given;
    scene->nobjects = p->gram->objects.n;
    scene->objects = tok_scene_alloc(p, sizeof(SceneObject *) * (size_t)(p->gram->objects.n ? p->gram->objects.n : 1));
    if (p->gram->objects.n)
        memcpy(scene->objects, p->gram->objects.data, sizeof(SceneObject *) * (size_t)p->gram->objects.n);
    scene->nlights = p->gram->lights.n;
    scene->lights = tok_scene_alloc(p, sizeof(SceneLight) * (size_t)(p->gram->lights.n ? p->gram->lights.n : 1));
    if (p->gram->lights.n)
        memcpy(scene->lights, p->gram->lights.data, sizeof(SceneLight) * (size_t)p->gram->lights.n);
    scene->nfogs = p->gram->fogs.n;
    scene->fogs = tok_scene_alloc(p, sizeof(SceneFog) * (size_t)(p->gram->fogs.n ? p->gram->fogs.n : 1));
    if (p->gram->fogs.n)
        memcpy(scene->fogs, p->gram->fogs.data, sizeof(SceneFog) * (size_t)p->gram->fogs.n);
    arena_set_budget(scene->arena, NULL); /* the budget is the parse's, and ends with it */
    arena_free(p->temp);
    free(p);
    return scene;
}

/* What the token stream reads with the parts above it (TokHooks). */
static const TokHooks gram_hooks = {
    .expression = expr_numeric,
    .number = expr_float,
    .number_full = expr_float_full,
    .string = expr_string,
    .starts_float = expr_starts_float,
    .starts_expression = expr_starts_expression,
    .starts_string = expr_starts_string,
    .value = gram_value_lenient,
    .declare = gram_declare,
    .default_directive = gram_default_directive,
    .version_seen = gram_version_seen,
};

/* The Parser and the grammar's state, allocated (and freed) as one: the
 * Parser first, so that its address is the block's. */
typedef struct {
    Parser parser;
    GramState gram;
} ParserBlock;

static Scene *run_parser(const char *name, const char *text, size_t len, const ParseOptions *opts,
                         ParseError *err)
{
    static const ParseOptions no_options; /* all zero */
    ParseError ignored;
    if (!err)
        err = &ignored;
    memset(err, 0, sizeof *err);
    ParserBlock *block = calloc(1, sizeof *block);
    Parser *p = block ? &block->parser : NULL; /* free(p) frees the block */
    Scene *scene = calloc(1, sizeof *scene);
    Arena *temp = arena_new(), *arena = arena_new();
    if (!p || !scene || !temp || !arena) {
        free(p);
        free(scene);
        arena_free(temp);
        arena_free(arena);
        snprintf(err->file, sizeof err->file, "%s", name);
        snprintf(err->message, sizeof err->message, "out of memory");
        return NULL;
    }
    scene->arena = arena;
    p->scene = scene;
    p->arena = arena;
    p->temp = temp;
    p->opts = opts ? opts : &no_options;
    p->err = err;
    p->hooks = &gram_hooks;
    p->gram = &block->gram;
    p->version = 3.7;
    p->version_given = p->opts->language_version_given;
    tok_tvec_init(&p->controls, sizeof(Control));
    tok_tvec_init(&p->gram->objects, sizeof(SceneObject *));
    tok_tvec_init(&p->gram->lights, sizeof(SceneLight));
    tok_tvec_init(&p->gram->fogs, sizeof(SceneFog));
    tok_tvec_init(&p->rand_streams, sizeof(unsigned));
    tok_tvec_init(&p->user_files, sizeof(struct UserFile *));
    tok_tvec_init(&p->arg_values, sizeof(Value));
    tok_tvec_init(&p->arg_refs, sizeof(Symbol *));
    tok_source_files_init(p);
    tok_symbols_init(p);
    init_scene(scene);
    tok_limits_init_stack(p);
    tok_limits_init_memory(p);
    tok_limits_init_work(p);

    if (setjmp(p->fail)) {
        tok_debug_end_line(p);
        tok_user_files_close_all(p, 0);
        scene_free(p->scene);
        arena_free(p->temp);
        free(p);
        return NULL;
    }
    return parse_everything(p, name, text, len);
}

Scene *parse_scene_file(const char *path, const ParseOptions *opts, ParseError *err)
{
    return run_parser(path, NULL, 0, opts, err);
}

Scene *parse_scene_string(const char *name, const char *text, const ParseOptions *opts, ParseError *err)
{
    return run_parser(name ? name : "<string>", text ? text : "", text ? strlen(text) : 0, opts, err);
}
