/* texture (plain, or patterned by a texture_map), pigment, finish, interior
 * (normal: parse_normal.c).
 *
 * Each block starts from its identifier when one comes first, otherwise
 * from the default (POV-Ray copies the default texture), then applies what
 * is written. Pigments hstrace evaluates: solid colours, POV-Ray 3.7's
 * patterns (gram_pattern_support; their values are src/material's) with
 * turbulence and uv_mapping, and image_map (its file read through
 * ParseOptions.load_image); pigment_map, average and blend lists whose
 * entries have patterns of their own. aoi, facets, function, object,
 * pavement, tiling and slope (and average as a texture's pattern) are
 * approximated by one colour. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "grammar.h"

#define MAX_SEARCH_DIRS 128 /* as #include searches */

SceneTexture *gram_default_texture(Parser *p)
{
    SceneTexture *t = tok_scene_alloc(p, sizeof *t);
    *t = p->scene->default_texture;
    return t;
}

static void join_notes(Parser *p, const ApproxNote **to, const ApproxNote *from);
static void set_texture_map(Parser *p, SceneTexture *tex, const TextureMapEntry *entries, int n, const Token *at);

/* The identifier at t when it holds `kind`; errors for other identifiers. */
const Value *gram_block_identifier(Parser *p, const Token *t, ValueKind kind, const char *block)
{
    if (t->type != TK_WORD || t->kw >= 0)
        return NULL;
    Symbol *s = tok_symbol_of(p, t);
    if (!s)
        tok_fail(p, t->pos, "undeclared identifier '%.*s'", t->len, t->text);
    if (s->value.kind == VAL_UNSUPPORTED)
        tok_use_unsupported(p, t, &s->value);
    if (s->value.kind == kind)
        return &s->value;
    if (kind == VAL_PIGMENT && s->value.kind == VAL_NUMERIC)
        return NULL; /* a colour identifier: the caller reads it as a colour */
    tok_fail(p, t->pos, "'%.*s' cannot be used in a %s", t->len, t->text, block);
}

void gram_skip_normal(Parser *p)
{
    tok_begin_block(p, "normal");
    tok_skip_block_body(p);
}

/* ---- pigments ------------------------------------------------------------ */


PatternSupport gram_pattern_support(int kw)
{
    switch (kw) {
    case KW_checker: case KW_hexagon: case KW_gradient:
    case KW_bozo: case KW_spotted: case KW_bumps: case KW_granite: case KW_wrinkles:
    case KW_agate: case KW_marble: case KW_wood: case KW_spiral1: case KW_spiral2:
    case KW_brick: case KW_leopard: case KW_onion: case KW_radial: case KW_quilted:
    case KW_dents: case KW_ripples: case KW_waves:
    case KW_planar: case KW_spherical: case KW_cylindrical: case KW_boxed:
    case KW_square: case KW_triangular: case KW_cubic: case KW_cells: case KW_crackle:
    case KW_mandel: case KW_julia: case KW_magnet: case KW_pigment_pattern:
        return PAT_EVALUATED;
    /* POV-Ray 3.7's other patterns: one colour stands for them (average
     * pigments are pigment_items' own, average normals parse_normal.c's) */
    case KW_aoi: case KW_average: case KW_facets: case KW_function: case KW_object:
    case KW_pavement: case KW_tiling: case KW_slope:
        return PAT_APPROXIMATED;
    case KW_image_map: case KW_image_pattern: case KW_density_file:
        return PAT_UNSUPPORTED; /* they need an image or a density file */
    default:
        return PAT_NONE;
    }
}

int gram_pattern_list_count(int kw)
{
    switch (kw) {
    case KW_checker: case KW_brick: return 2;
    case KW_hexagon: return 3;
    case KW_square: return 4;
    case KW_triangular: case KW_cubic: return 6;
    default: return 0;
    }
}

/* ---- image_map ------------------------------------------------------------ */

/* The image file `name`, found as #include files are (the including file's
 * folder, the current folder, the include folders); NULL when none has it. */
static char *find_image_file(Parser *p, const char *name)
{
    if (name[0] == '/')
        return access(name, R_OK) == 0 ? tok_temp_strndup(p, name, strlen(name)) : NULL;
    const char *dirs[MAX_SEARCH_DIRS];
    int nd = tok_search_dirs(p, dirs, MAX_SEARCH_DIRS);
    for (int i = 0; i < nd; i++) {
        size_t n = strlen(dirs[i]) + strlen(name) + 2;
        char *path = tok_temp_alloc(p, n);
        snprintf(path, n, "%s/%s", dirs[i], name);
        if (access(path, R_OK) == 0)
            return path;
    }
    return NULL;
}

char *gram_find_image_file(Parser *p, const char *name) { return find_image_file(p, name); }

/* A linear value into the scene's working space (assumed_gamma), as
 * POV-Ray transcodes an image's colours. */
static float to_working(float x, double gamma)
{
    if (gamma == 1.0 || x <= 0.0f)
        return x;
    if (gamma == 0.0)
        return x <= 0.0031308f ? x * 12.92f : 1.055f * powf(x, 1.0f / 2.4f) - 0.055f;
    return (float)pow(x, 1.0 / gamma);
}

/* What hstrace does not do of image_map, at `at`: as any unsupported
 * keyword, an error, or in a #declare a value that is one when used. */
static _Noreturn void image_map_unsupported(Parser *p, const Token *at, const char *what)
{
    Token t = *at;
    t.text = tok_temp_strndup(p, what, strlen(what));
    t.len = (int)strlen(what);
    tok_unsupported(p, &t);
}

/* POV-Ray 3.7's Parse_Image, after the '{' of `block` (image_map,
 * bump_map): [type] "file" [gamma G|srgb] [premultiplied 0], the picture
 * read into pig (kind PIGMENT_IMAGE_MAP, not once, not interpolated).
 * gamma_correct: colours (image_map), decoded and taken to the working
 * gamma as POV-Ray does at this point of the scene (image_gamma.c); data
 * (bump_map) are the file's values as they are, or decoded by a `gamma`
 * given, and left linear. */
SceneImage *gram_image_source(Parser *p, Pigment *pig, const Token *at, const char *block, int gamma_correct)
{
    Token *t = tok_next(p);
    int kw = t->type == TK_WORD ? t->kw : -1;
    switch (kw) {
    case KW_png: case KW_jpeg: case KW_tga: case KW_ppm: case KW_pgm: case KW_exr: case KW_hdr: case KW_bmp:
        break; /* the type: hstrace tells files apart by their first bytes */
    case KW_gif: case KW_iff: case KW_tiff: case KW_sys: case KW_function:
        tok_unsupported(p, t);
    default:
        tok_unget(p);
    }
    Token name_at = *tok_peek(p);
    char *name = expr_string(p);
    int override_given = 0;  /* `gamma G`: decodes the file whatever it says */
    double override = 0.0;   /* 0: srgb */
    int premultiplied = -1;  /* -1: the format's own reading */
    for (;;) {
        Token *o = tok_next(p);
        if (tok_is_kw(o, KW_gamma)) {
            override_given = 1;
            if (tok_is_kw(tok_peek(p), KW_srgb)) {
                (void)tok_next(p);
                override = 0.0;
            } else {
                Token vt = *tok_peek(p);
                override = expr_float(p);
                if (!(override > 0.0))
                    tok_fail(p, vt.pos, "gamma value must be positive.");
            }
        } else if (tok_is_kw(o, KW_premultiplied)) {
            premultiplied = (int)expr_float(p) != 0; /* POV-Ray's premultiplyOverride */
        } else {
            tok_unget(p);
            break;
        }
    }
    if (!p->opts->load_image) /* a parse without the image layer (the parser's own tests) */
        image_map_unsupported(p, at, block);
    char *path = find_image_file(p, name);
    if (!path)
        tok_fail(p, name_at.pos, "cannot find the image '%s' (looked in the current folder, the scene's folder and the "
                   "include folders)", name);
    LoadedPicture pic;
    char why[256] = "";
    const ImageGammaPlan plan = gram_image_gamma_plan(p, gamma_correct, override_given, override);
    size_t left = tok_limits_memory_left(p); /* 0 would mean no limit: at least a byte */
    if (p->opts->load_image(p->opts->load_image_user, path, plan.decode, plan.untagged, premultiplied,
                            left ? left : 1, &pic, why,
                            (int)sizeof why)) {
        free(pic.rgba);
        free(pic.index);
        tok_fail(p, name_at.pos, "%s: %s", block, why[0] ? why : "unreadable image");
    }
    const int w = pic.width, h = pic.height;
    SceneImage *im = tok_scene_alloc(p, sizeof *im);
    size_t n = (size_t)w * (size_t)h * 4;
    float *kept = NULL;
    unsigned char *index = NULL;
    /* in the scene's arena: the parse's memory budget counts them (a
     * failed tok_scene_alloc leaves by the parse's error path: free the file's first) */
    if (n > 0 && !(kept = arena_alloc(p->arena, n * sizeof *kept))) {
        free(pic.rgba);
        free(pic.index);
        tok_fail_memory(p, name_at.pos);
    }
    if (n > 0)
        memcpy(kept, pic.rgba, n * sizeof *kept);
    free(pic.rgba);
    if (pic.index && !(index = arena_alloc(p->arena, (size_t)w * (size_t)h))) {
        free(pic.index);
        tok_fail_memory(p, name_at.pos);
    }
    if (pic.index)
        memcpy(index, pic.index, (size_t)w * (size_t)h);
    free(pic.index);
    /* the working gamma in effect when the picture is parsed (none before
     * assumed_gamma: image_gamma.c) */
    double wg = pic.as_stored ? 1.0 : plan.working;
    double sum[3] = { 0, 0, 0 };
    for (size_t i = 0; i < (size_t)w * (size_t)h; i++) {
        for (int c = 0; c < 3; c++) {
            kept[4 * i + c] = to_working(kept[4 * i + c], wg);
            sum[c] += kept[4 * i + c];
        }
        if (kept[4 * i + 3] < 1.0f)
            im->has_alpha = 1;
    }
    im->width = w;
    im->height = h;
    im->rgba = kept;
    im->path = path;
    im->premultiplied = pic.premultiplied;
    if (index) {
        /* POV-Ray's colour map: each entry's colour in the working space,
         * filter 0 and transmit 1 - alpha (what `filter N`, `transmit all`
         * ... change) */
        im->index = index;
        im->npalette = pic.ncolours;
        im->palette = tok_scene_alloc(p, sizeof *im->palette * (size_t)pic.ncolours);
        for (int i = 0; i < pic.ncolours; i++) {
            for (int c = 0; c < 3; c++)
                im->palette[i][c] = to_working(pic.palette[i][c], wg);
            im->palette[i][3] = 0.0f;
            im->palette[i][4] = 1.0f - pic.palette[i][3];
        }
    }
    pig->kind = PIGMENT_IMAGE_MAP;
    pig->image = im;
    pig->nmap = 0;
    pig->map = NULL;
    pig->image_once = 0;
    pig->image_interpolate = 0;
    pig->image_filter_all = pig->image_transmit_all = 0.0;
    /* where one colour must stand for the picture: its mean */
    double count = (double)w * (double)h;
    pig->colour = (Colour){ sum[0] / count, sum[1] / count, sum[2] / count, 0.0, 0.0 };
    return im;
}

int gram_image_interpolation(Parser *p, const Token *at)
{
    int v = (int)expr_float(p);
    if (v == 3)
        image_map_unsupported(p, at, "interpolate 3 (bicubic; 0, 2 and 4 are supported)");
    if (v != 0 && v != 2 && v != 4)
        tok_fail(p, at->pos, "Invalid interpolate value.");
    return v;
}

int gram_image_map_type(Parser *p, const Token *at)
{
    /* POV-Ray's Parse_Image_Map: 0 planar, 1 spherical, 2 cylindrical, 5
     * torus; any other value it refuses */
    int v = (int)expr_float(p);
    if (v != 0 && v != 1 && v != 2 && v != 5)
        tok_fail(p, at->pos, "invalid map_type %d (POV-Ray: \"Invalid map_type value.\"; 0 planar, 1 spherical, "
                               "2 cylindrical and 5 torus are valid)", v);
    return v;
}

/* After 'image_map': POV-Ray 3.7's Parse_Image_Map for what exporters
 * write: the picture, then once, interpolate 0/2/4, map_type,
 * use_colour/use_index, filter all F, transmit all T. */
static void parse_image_map(Parser *p, Pigment *pig, const Token *at)
{
    tok_begin_block(p, "image_map");
    SceneImage *im = gram_image_source(p, pig, at, "image_map", 1); /* its own: filter N ... may change it */
    for (;;) {
        Token *o = tok_next(p);
        if (tok_is_punct(o, '}'))
            return;
        Token here = *o;
        switch (o->type == TK_WORD ? o->kw : -1) {
        case KW_once: pig->image_once = 1; break;
        case KW_interpolate: pig->image_interpolate = gram_image_interpolation(p, &here); break;
        case KW_map_type: pig->image_map_type = gram_image_map_type(p, &here); break;
        case KW_use_colour: case KW_use_color: case KW_use_index: break;
        case KW_filter: case KW_transmit: {
            /* POV-Ray's Parse_Image_Map: `filter all F` adds F to every
             * pixel's filter (a colour-mapped picture: sets every entry's
             * to F); `filter N, F` sets entry N's, colour-mapped only.
             * transmit the same. */
            const int slot = here.kw == KW_filter ? 3 : 4;
            if (tok_is_kw(tok_peek(p), KW_all)) {
                (void)tok_next(p);
                double v = expr_float(p);
                if (slot == 3)
                    pig->image_filter_all = v;
                else
                    pig->image_transmit_all = v;
                for (int i = 0; i < im->npalette; i++)
                    im->palette[i][slot] = (float)v;
                break;
            }
            Token rt = *tok_peek(p);
            int reg = (int)(expr_float(p) + 0.01);
            if (im->npalette == 0)
                tok_fail(p, here.pos, "Keyword '%s' cannot be used with non color-mapped image.",
                           tok_keyword_name(here.kw));
            if (reg < 0 || reg >= im->npalette)
                tok_fail(p, rt.pos, "%s color register value out of range.", slot == 3 ? "FILTER" : "TRANSMIT");
            expr_comma(p);
            im->palette[reg][slot] = (float)expr_float(p);
            break;
        }
        default:
            if (o->type == TK_WORD && o->kw >= 0)
                tok_unsupported(p, o); /* repeat, offset, ... */
            tok_fail_expected(p, o, "once, interpolate, map_type, filter all, transmit all or '}' in 'image_map'");
        }
    }
}

/* The default colours of the patterns that take a list (POV-Ray's
 * Check_Default_Map, Hex_Default_Map, Brick_Default_Map and the
 * Cubic_Entries that square, triangular and cubic share), and the
 * black-to-white map of patterns given no colour_map. */
static const Colour *default_list_colours(int kw)
{
    static const Colour hexagon[3] = { { 0, 0, 1, 0, 0 }, { 0, 1, 0, 0, 0 }, { 1, 0, 0, 0, 0 } };
    static const Colour brick[2] = { { 0.5, 0.5, 0.5, 0, 0 }, { 0.6, 0.15, 0.15, 0, 0 } };
    static const Colour cubic[6] = { { 1, 0, 0, 0, 0 }, { 0, 1, 0, 0, 0 }, { 0, 0, 1, 0, 0 },
                                     { 1, 1, 0, 0, 0 }, { 0, 1, 1, 0, 0 }, { 1, 0, 1, 0, 0 } };
    switch (kw) {
    case KW_brick: return brick;
    case KW_square: case KW_triangular: case KW_cubic: return cubic;
    default: return hexagon;
    }
}

static void set_map(Parser *p, Pigment *pig, const ColourMapEntry *entries, int n)
{
    ColourMapEntry *m = tok_scene_alloc(p, sizeof *m * (size_t)(n ? n : 1));
    pig->map_pigments = 0;
    for (int i = 0; i < n; i++) {
        m[i] = entries[i];
        pig->map_pigments |= m[i].pigment != NULL;
    }
    pig->map = m;
    pig->nmap = n;
}

/* A blend list's or pigment_map's entry pigment as the entry keeps it:
 * NULL for a plain colour; a copy for one with a pattern of its own, but
 * NULL (its representative colour standing for it, noted at `at`) for one
 * seen at the surface's (u, v), which a pigment's point does not give. */
static const Pigment *entry_pigment(Parser *p, const Pigment *entry, const Token *at, const ApproxNote **notes)
{
    if (entry->kind == PIGMENT_SOLID)
        return NULL;
    if (entry->uv_mapping) {
        tok_approximate(p, at, APPROX_PATTERN, notes);
        return NULL;
    }
    Pigment *copy = tok_scene_alloc(p, sizeof *copy);
    *copy = *entry;
    return copy;
}

static void set_grey_map(Parser *p, Pigment *pig)
{
    ColourMapEntry e[2] = { { 0.0, { 0, 0, 0, 0, 0 }, NULL }, { 1.0, { 1, 1, 1, 0, 0 }, NULL } };
    set_map(p, pig, e, 2);
}

/* POV-Ray's default colour maps of the patterns that have their own
 * (pigment.cpp there); the others default to black to white. */
static void set_default_map(Parser *p, Pigment *pig, int kw)
{
    static const ColourMapEntry bozo[6] = {
        { 0.4, { 1, 1, 1, 0, 0 }, NULL }, { 0.4, { 0, 1, 0, 0, 0 }, NULL }, { 0.6, { 0, 1, 0, 0, 0 }, NULL },
        { 0.6, { 0, 0, 1, 0, 0 }, NULL }, { 0.8, { 0, 0, 1, 0, 0 }, NULL }, { 0.8, { 1, 0, 0, 0, 0 }, NULL },
    };
    static const ColourMapEntry wood[2] = { { 0.6, { 0.666, 0.312, 0.2, 0, 0 }, NULL },
                                            { 0.6, { 0.4, 0.1333, 0.066, 0, 0 }, NULL } };
    static const ColourMapEntry agate[6] = {
        { 0.0, { 1.0, 1.0, 1.0, 0, 0 }, NULL }, { 0.5, { 0.95, 0.75, 0.5, 0, 0 }, NULL },
        { 0.5, { 0.9, 0.7, 0.5, 0, 0 }, NULL }, { 0.6, { 0.9, 0.7, 0.4, 0, 0 }, NULL },
        { 0.6, { 1.0, 0.7, 0.4, 0, 0 }, NULL }, { 1.0, { 0.6, 0.3, 0.0, 0, 0 }, NULL },
    };
    static const ColourMapEntry marble[3] = { { 0.0, { 0.9, 0.8, 0.8, 0, 0 }, NULL },
                                              { 0.9, { 0.9, 0.08, 0.08, 0, 0 }, NULL },
                                              { 0.9, { 0.0, 0.0, 0.0, 0, 0 }, NULL } };
    static const ColourMapEntry mandel[5] = {
        { 0.001, { 0, 0, 0, 0, 0 }, NULL }, { 0.001, { 0, 1, 1, 0, 0 }, NULL }, { 0.012, { 1, 1, 0, 0, 0 }, NULL },
        { 0.015, { 1, 0, 1, 0, 0 }, NULL }, { 0.1, { 0, 1, 1, 0, 0 }, NULL },
    };
    static const ColourMapEntry radial[4] = { { 0.0, { 0, 1, 1, 0, 0 }, NULL }, { 0.333, { 1, 1, 0, 0, 0 }, NULL },
                                              { 0.666, { 1, 0, 1, 0, 0 }, NULL }, { 1.0, { 0, 1, 1, 0, 0 }, NULL } };
    switch (kw) {
    case KW_mandel: set_map(p, pig, mandel, 5); break; /* mandel's alone: not julia's or magnet's */
    case KW_radial: set_map(p, pig, radial, 4); break;
    case KW_bozo: set_map(p, pig, bozo, 6); break;
    case KW_wood: set_map(p, pig, wood, 2); break;
    case KW_agate: set_map(p, pig, agate, 6); break;
    case KW_marble: set_map(p, pig, marble, 3); break;
    default: set_grey_map(p, pig); break;
    }
}

/* POV-Ray's Check_Turb: the turbulence that `turbulence`, `octaves`,
 * `omega` and `lambda` written in the pigment change -- the last warp when
 * it is such a classic one, else a new one appended. Warp lists are shared
 * between copies of a pigment, so the list is copied before any change. */
PatternTurbulence *gram_classic_turbulence(Parser *p, Pigment *pig)
{
    int n = pig->nturbulence;
    int append = n == 0 || !pig->turbulence[n - 1].classic;
    PatternTurbulence *list = tok_scene_alloc(p, sizeof *list * (size_t)(n + append));
    for (int i = 0; i < n; i++)
        list[i] = pig->turbulence[i];
    if (append) {
        PatternTurbulence *t = &list[n];
        t->classic = 1;
        t->amount = v3(0, 0, 0);
        t->octaves = 6;
        t->omega = 0.5;
        t->lambda = 2.0;
        n++;
    }
    pig->turbulence = list;
    pig->nturbulence = n;
    return &list[n - 1];
}

int gram_octaves_value(double v)
{
    return int_clamped(v, 1, 10); /* POV-Ray's limits */
}

/* warp { ... }: turbulence is modelled, the other warps are approximated
 * (ignored). */
void gram_warp(Parser *p, Pigment *pig, const Token *at)
{
    tok_begin_block(p, "warp");
    Token *t = tok_next(p);
    if (!tok_is_kw(t, KW_turbulence)) {
        tok_approximate(p, at, APPROX_WARP, &pig->approx);
        tok_skip_block_body(p);
        return;
    }
    PatternTurbulence w = { 0, expr_vector(p), 6, 0.5, 2.0 };
    for (;;) {
        t = tok_next(p);
        if (tok_is_kw(t, KW_octaves))
            w.octaves = gram_octaves_value(expr_float(p));
        else if (tok_is_kw(t, KW_omega))
            w.omega = gram_single(expr_float(p));
        else if (tok_is_kw(t, KW_lambda))
            w.lambda = gram_single(expr_float(p));
        else if (tok_is_punct(t, '}'))
            break;
        else
            tok_fail_expected(p, t, "octaves, omega, lambda or '}' in 'warp { turbulence }'");
    }
    PatternTurbulence *list = tok_scene_alloc(p, sizeof *list * (size_t)(pig->nturbulence + 1));
    for (int i = 0; i < pig->nturbulence; i++)
        list[i] = pig->turbulence[i];
    list[pig->nturbulence] = w;
    pig->turbulence = list;
    pig->nturbulence++;
}

/* The colours after checker, hexagon, brick, square, triangular or cubic
 * (kw; POV-Ray's Parse_Blend_List): up to `count` colours, or `pigment {}`
 * items, commas optional; the missing ones are POV-Ray's defaults. */
static void parse_colour_list(Parser *p, Pigment *pig, int kw, int count)
{
    ColourMapEntry e[6];
    int i = 0;
    int pigments = tok_is_kw(tok_peek(p), KW_pigment);
    while (i < count) {
        Token *t = tok_peek(p);
        if (pigments) {
            if (!tok_is_kw(t, KW_pigment))
                break;
            Token at = *tok_next(p);
            Pigment item = p->scene->default_texture.pigment;
            item.approx = NULL;
            gram_pigment(p, &item);
            e[i].pigment = entry_pigment(p, &item, &at, &pig->approx);
            for (const ApproxNote *n = item.approx; n; n = n->next) { /* the item's notes join the list's */
                ApproxNote *c = tok_scene_alloc(p, sizeof *c);
                *c = *n;
                c->next = pig->approx;
                pig->approx = c;
            }
            e[i].colour = item.colour;
        } else {
            if (!expr_starts_expression(p, t))
                break;
            expr_colour(p, &e[i].colour, 1);
            e[i].pigment = NULL;
        }
        e[i].value = i;
        i++;
        expr_comma(p);
    }
    for (; i < count; i++) {
        e[i].value = i;
        e[i].colour = default_list_colours(kw)[i];
        e[i].pigment = NULL;
    }
    set_map(p, pig, e, count);
}

/* color_map { [value colour] ... }, also the old [v1 v2 colour c1 colour c2]
 * form (POV-Ray's Parse_Colour_Map); equal neighbours are merged as there. */
/* The start of a blend map's next entry (color_map, pigment_map): returns 0
 * at the map's closing '}', else reads '[' and the entry's value (POV-Ray
 * keeps it in single precision; `optional`: 1 when left out, as average's
 * entries may). */
int gram_blend_map_entry(Parser *p, const char *map, const TempVec *entries, int optional, double *value)
{
    Token *t = tok_next(p);
    if (tok_is_punct(t, '}'))
        return 0;
    if (t->type == TK_WORD && t->kw < 0) {
        Symbol *s = tok_symbol_find(p, t->text, t->len);
        if (s && s->value.kind == VAL_UNSUPPORTED)
            tok_use_unsupported(p, t, &s->value);
        tok_fail(p, t->pos, "expected '[' or '}' in '%s', found '%.*s' (a declared %s stands alone: %s { Name })",
                   map, t->len, t->text, map, map);
    }
    if (!tok_is_punct(t, '[')) {
        char what[48];
        snprintf(what, sizeof what, "'[' or '}' in '%s'", map);
        tok_fail_expected(p, t, what);
    }
    if (entries->n >= 256)
        tok_fail(p, t->pos, "Blend_Map too long (more than 256 entries)");
    *value = optional && !expr_starts_float(p, tok_peek(p)) ? 1.0 : gram_single(expr_float(p));
    expr_comma(p);
    return 1;
}

const Value *gram_map_identifier(Parser *p, ValueKind kind, const char *map)
{
    Token *t = tok_peek(p);
    if (t->type != TK_WORD || t->kw >= 0)
        return NULL;
    Token at = *t;
    Symbol *s = tok_symbol_of(p, &at);
    if (!s || s->value.kind == VAL_MACRO)
        return NULL; /* undeclared: gram_blend_map_entry says so; a macro's call is read as entries */
    (void)tok_next(p);
    if (s->value.kind == VAL_UNSUPPORTED)
        tok_use_unsupported(p, &at, &s->value);
    if (s->value.kind != kind)
        tok_fail(p, at.pos, "'%.*s' is %s, not a %s (POV-Ray: \"Wrong identifier type\")", at.len, at.text,
                   tok_value_kind_name(s->value.kind), map);
    char after[64];
    snprintf(after, sizeof after, "a declared %s in '%s'", map, map);
    tok_expect_punct(p, '}', after);
    return &s->value;
}

void gram_colour_map(Parser *p, Pigment *pig)
{
    tok_begin_block(p, "color_map");
    const Value *id = gram_map_identifier(p, VAL_COLOUR_MAP, "color_map");
    if (id) {
        set_map(p, pig, id->pigment->map, id->pigment->nmap);
        return;
    }
    TempVec entries;
    tok_tvec_init(&entries, sizeof(ColourMapEntry));
    double v;
    while (gram_blend_map_entry(p, "color_map", &entries, 0, &v)) {
        Token *c = tok_peek(p);
        if (expr_starts_float(p, c)) { /* old style: a second value, then two colours */
            double v2 = gram_single(expr_float(p));
            ColourMapEntry *a = tok_tvec_push(p, &entries);
            a->value = v;
            expr_colour(p, &a->colour, 1);
            ColourMapEntry *b = tok_tvec_push(p, &entries);
            b->value = v2;
            expr_colour(p, &b->colour, 1);
        } else {
            ColourMapEntry *a = tok_tvec_push(p, &entries);
            a->value = v;
            expr_colour(p, &a->colour, 1);
        }
        tok_expect_punct(p, ']', "a color_map entry");
    }
    if (entries.n < 1)
        tok_fail(p, p->tok.pos, "Must have at least one color in color map.");
    ColourMapEntry *e = entries.data;
    int n = 1;
    for (int i = 1; i < entries.n; i++) {
        if (memcmp(&e[i], &e[n - 1], sizeof e[i]) == 0)
            continue;
        e[n++] = e[i];
    }
    set_map(p, pig, e, n);
}

/* A keyword's arguments when hstrace does not use them: expressions (with
 * commas between) and blocks, so that `spiral2 8`, `warp { ... }` or
 * `brick colour A, colour B` are read past. */
void gram_skip_arguments(Parser *p)
{
    for (;;) {
        Token *t = tok_peek(p);
        if (tok_is_punct(t, '{')) {
            tok_next(p);
            tok_skip_block_body(p);
            return;
        }
        if (!expr_starts_expression(p, t))
            return;
        double e[5];
        int terms = 5;
        if (expr_starts_colour(p, t)) {
            Colour ignored;
            expr_colour(p, &ignored, 1);
        } else {
            expr_numeric(p, e, &terms);
        }
        expr_comma(p); /* `julia <.3, .44> 30`: commas are optional */
    }
}

int gram_pattern_modifier(int kw)
{
    switch (kw) {
    case KW_brick_size: case KW_mortar: case KW_form: case KW_metric: case KW_offset:
    case KW_solid: case KW_control0: case KW_control1: case KW_exponent: case KW_max_iteration:
    case KW_interior: case KW_exterior: case KW_orientation: case KW_accuracy:
    case KW_number_of_sides: case KW_number_of_tiles: case KW_pattern: case KW_type: case KW_repeat:
    case KW_map_type: case KW_interpolate: case KW_once: case KW_altitude:
    case KW_density_map: case KW_coords:
        return 1;
    default:
        return 0;
    }
}

/* The representative colour of a patterned pigment: its map at 0.5. */
static void set_representative(Pigment *pig)
{
    if (pig->nmap > 0)
        pig->colour = colour_map_at(pig->map, pig->nmap, 0.5);
}

static void pigment_items(Parser *p, Pigment *pig, int close);
static void start_fractal(Parser *p, Pigment *pig, int kw);
static int own_modifier(Parser *p, Pigment *pig, int kw);

/* pigment_map { [value pigment] ... }: each entry's pigment is read in
 * full, and the map blends the entries' colours at the point (an entry
 * seen at the surface's (u, v) by its representative colour, noted). */
void gram_pigment_map(Parser *p, Pigment *pig, const Token *at)
{
    tok_begin_block(p, "pigment_map");
    const Value *id = gram_map_identifier(p, VAL_PIGMENT_MAP, "pigment_map");
    if (id) {
        set_map(p, pig, id->pigment->map, id->pigment->nmap);
        join_notes(p, &pig->approx, id->pigment->approx);
        return;
    }
    TempVec entries;
    tok_tvec_init(&entries, sizeof(ColourMapEntry));
    double v;
    while (gram_blend_map_entry(p, "pigment_map", &entries, 1, &v)) {
        Pigment entry = p->scene->default_texture.pigment;
        entry.approx = NULL;
        if (expr_starts_colour(p, tok_peek(p))) {
            expr_colour(p, &entry.colour, 1);
            entry.kind = PIGMENT_SOLID;
            tok_expect_punct(p, ']', "a pigment_map entry");
        } else {
            pigment_items(p, &entry, ']');
        }
        const Pigment *own = entry_pigment(p, &entry, at, &pig->approx);
        for (const ApproxNote *n = entry.approx; n; n = n->next) {
            ApproxNote *c = tok_scene_alloc(p, sizeof *c);
            *c = *n;
            c->next = pig->approx;
            pig->approx = c;
        }
        ColourMapEntry *e = tok_tvec_push(p, &entries);
        e->value = v;
        e->colour = entry.colour;
        e->pigment = own;
    }
    if (entries.n < 1)
        tok_fail(p, p->tok.pos, "Must have at least one entry in pigment_map.");
    set_map(p, pig, entries.data, entries.n);
}

void gram_pigment(Parser *p, Pigment *pig)
{
    tok_begin_block(p, "pigment");
    pigment_items(p, pig, '}');
}

/* A pattern hstrace evaluates, at its keyword `kw` (already read), in a
 * pigment or a texture: the kind and what comes with it (gradient's vector,
 * the spirals' arms, agate's turbulence), frequency, phase and wave back to
 * POV-Ray's defaults. Colours (checker's and hexagon's list, the default
 * colour map) are the caller's. */
void gram_start_pattern(Parser *p, Pigment *pig, int kw)
{
    pig->frequency = 1.0;
    pig->phase = 0.0;
    pig->wave = WAVE_RAMP;
    switch (kw) {
    case KW_gradient: {
        Token vt = *tok_peek(p);
        Vec3 g = expr_vector(p);
        if (v3_length(g) == 0.0)
            tok_fail(p, vt.pos, "the gradient vector must not be zero");
        pig->gradient = v3_normalize(g);
        pig->kind = PIGMENT_GRADIENT;
        break;
    }
    case KW_checker: case KW_hexagon:
        pig->kind = kw == KW_checker ? PIGMENT_CHECKER : PIGMENT_HEXAGON;
        pig->frequency = 0.0; /* as POV-Ray: the value is the colour's (or texture's) index */
        break;
    case KW_bozo: case KW_spotted: case KW_bumps: pig->kind = PIGMENT_BOZO; break;
    case KW_granite: pig->kind = PIGMENT_GRANITE; break;
    case KW_wrinkles: pig->kind = PIGMENT_WRINKLES; break;
    case KW_marble: pig->kind = PIGMENT_MARBLE; pig->wave = WAVE_TRIANGLE; break;
    case KW_wood: pig->kind = PIGMENT_WOOD; pig->wave = WAVE_TRIANGLE; break;
    case KW_agate:
        pig->kind = PIGMENT_AGATE;
        pig->agate_turb = 1.0;
        (void)gram_classic_turbulence(p, pig); /* agate's own turbulence */
        break;
    case KW_spiral1: case KW_spiral2:
        pig->kind = kw == KW_spiral1 ? PIGMENT_SPIRAL1 : PIGMENT_SPIRAL2;
        pig->arms = (short)int_as_povray(expr_float(p)); /* POV-Ray keeps (short)(int)v */
        pig->wave = WAVE_TRIANGLE;
        break;
    case KW_brick:
        if (pig->kind != PIGMENT_BRICK) { /* `brick` again keeps its size and mortar */
            pig->brick_size = v3(8.0, 3.0, 4.5);
            pig->mortar = gram_single(0.5 - POV_EPSILON * 2.0);
        }
        pig->kind = PIGMENT_BRICK;
        pig->frequency = 0.0;
        break;
    case KW_square: case KW_triangular: case KW_cubic:
        pig->kind = kw == KW_square ? PIGMENT_SQUARE : kw == KW_triangular ? PIGMENT_TRIANGULAR : PIGMENT_CUBIC;
        pig->frequency = 0.0; /* the value is the tile's index */
        break;
    case KW_quilted:
        pig->kind = PIGMENT_QUILTED;
        pig->control0 = pig->control1 = 1.0;
        pig->frequency = 0.0;
        break;
    case KW_leopard: pig->kind = PIGMENT_LEOPARD; break;
    case KW_onion: pig->kind = PIGMENT_ONION; break;
    case KW_radial: pig->kind = PIGMENT_RADIAL; break;
    case KW_dents: pig->kind = PIGMENT_DENTS; break;
    case KW_ripples: pig->kind = PIGMENT_RIPPLES; break;
    case KW_waves: pig->kind = PIGMENT_WAVES; break;
    case KW_planar: pig->kind = PIGMENT_PLANAR; break;
    case KW_spherical: pig->kind = PIGMENT_SPHERICAL; break;
    case KW_cylindrical: pig->kind = PIGMENT_CYLINDRICAL; break;
    case KW_boxed: pig->kind = PIGMENT_BOXED; break;
    case KW_cells: pig->kind = PIGMENT_CELLS; break;
    case KW_crackle:
        pig->kind = PIGMENT_CRACKLE;
        pig->crackle_solid = 0;
        pig->crackle_form = v3(-1.0, 1.0, 0.0);
        pig->crackle_metric = 2.0;
        pig->crackle_offset = 0.0;
        break;
    case KW_mandel: case KW_julia: case KW_magnet:
        start_fractal(p, pig, kw);
        break;
    case KW_pigment_pattern: {
        /* a pigment of its own (POV-Ray's Create_Pigment: black), read in full */
        Pigment *inner = tok_scene_alloc(p, sizeof *inner);
        memset(inner, 0, sizeof *inner);
        inner->kind = PIGMENT_SOLID;
        inner->frequency = 1.0;
        transform_identity(&inner->transform);
        tok_begin_block(p, "pigment_pattern");
        pigment_items(p, inner, '}');
        join_notes(p, &pig->approx, inner->approx);
        pig->inner = inner;
        pig->kind = PIGMENT_PIGMENT_PATTERN;
        break;
    }
    }
}

/* mandel ITERATIONS, julia <c>, ITERATIONS, magnet 1|2 mandel ITERATIONS,
 * magnet 1|2 julia <c>, ITERATIONS (POV-Ray's Parse_Pattern), with the
 * default exterior (type 1, factor 1) and interior (type 0, factor 1). */
static void start_fractal(Parser *p, Pigment *pig, int kw)
{
    pig->kind = PIGMENT_FRACTAL;
    pig->exponent = 2;
    pig->interior_type = 0;
    pig->exterior_type = 1;
    pig->interior_factor = pig->exterior_factor = 1.0;
    int julia = kw == KW_julia, magnet = 0;
    if (kw == KW_magnet) {
        Token at = *tok_peek(p);
        int type = int_as_povray(expr_float(p));
        Token *which = tok_next(p);
        if (!tok_is_kw(which, KW_mandel) && !tok_is_kw(which, KW_julia))
            tok_fail(p, which->pos, "Invalid magnet pattern found. Valid types are 'mandel' and 'julia'.");
        julia = tok_is_kw(which, KW_julia);
        if (type != 1 && type != 2)
            tok_fail(p, at.pos, "Invalid magnet-%s pattern type found. Valid types are 1 and 2.",
                     julia ? "julia" : "mandel");
        magnet = type;
        pig->exponent = 0;
    }
    if (julia) {
        double c[2];
        gram_uv_vector(p, c);
        pig->fractal_u = c[0];
        pig->fractal_v = c[1];
        expr_comma(p);
    }
    pig->iterations = int_as_povray(expr_float(p));
    if (magnet == 1)
        pig->fractal = julia ? FRACTAL_MAGNET1J : FRACTAL_MAGNET1M;
    else if (magnet == 2)
        pig->fractal = julia ? FRACTAL_MAGNET2J : FRACTAL_MAGNET2M;
    else
        pig->fractal = julia ? FRACTAL_JULIA : FRACTAL_MANDEL;
}

/* The modifiers of one kind of pattern (brick_size, mortar, control0,
 * control1, metric, form, offset, solid, exponent, interior, exterior),
 * when pig is of that kind. Returns 1 when `kw` was one, read. */
static int own_modifier(Parser *p, Pigment *pig, int kw)
{
    switch (pig->kind) {
    case PIGMENT_BRICK:
        if (kw == KW_brick_size) {
            pig->brick_size = expr_vector(p);
            return 1;
        }
        if (kw == KW_mortar) {
            pig->mortar = gram_single(expr_float(p) - POV_EPSILON * 2.0);
            return 1;
        }
        return 0;
    case PIGMENT_QUILTED:
        if (kw == KW_control0 || kw == KW_control1) {
            double v = gram_single(expr_float(p));
            if (kw == KW_control0)
                pig->control0 = v;
            else
                pig->control1 = v;
            return 1;
        }
        return 0;
    case PIGMENT_CRACKLE:
        switch (kw) {
        case KW_metric: pig->crackle_metric = expr_vector(p).x; return 1; /* a vector of old: x alone counts */
        case KW_form: pig->crackle_form = expr_vector(p); return 1;
        case KW_offset: pig->crackle_offset = expr_float(p); return 1;
        case KW_solid: pig->crackle_solid = 1; return 1;
        default: return 0;
        }
    case PIGMENT_FRACTAL:
        if (kw == KW_interior || kw == KW_exterior) {
            Token at = *tok_peek(p);
            int type = int_as_povray(expr_float(p));
            int top = kw == KW_interior ? 6 : 8;
            if (type < 0 || type > top)
                tok_fail(p, at.pos, "Invalid fractal pattern %s type. Valid types are 0 to %d.",
                         kw == KW_interior ? "interior" : "exterior", top);
            expr_comma(p);
            double factor = expr_float(p);
            if (kw == KW_interior) {
                pig->interior_type = type;
                pig->interior_factor = factor;
            } else {
                pig->exterior_type = type;
                pig->exterior_factor = factor;
            }
            return 1;
        }
        if (kw == KW_exponent && (pig->fractal == FRACTAL_MANDEL || pig->fractal == FRACTAL_JULIA)) {
            Token at = *tok_peek(p);
            int e = int_as_povray(expr_float(p));
            if (e < 2 || e > 33) {
                tok_warning(p, at.pos, "Invalid fractal pattern exponent found. Supported exponents are 2 to 33. "
                                       "Using default exponent 2.");
                e = 2;
            }
            pig->exponent = e;
            return 1;
        }
        return 0;
    default:
        return 0;
    }
}

/* The modifiers every pattern has (POV-Ray's Parse_Pattern), in a pigment
 * or a patterned texture: frequency, phase, the waves, turbulence and its
 * octaves, omega and lambda, warp, noise_generator, agate_turb. Returns 1
 * when t (already read) was one, its arguments read. */
int gram_pattern_modifier_item(Parser *p, Pigment *pig, const Token *t)
{
    Token here = *t; /* t may not outlive the next token read */
    if (here.type == TK_WORD && here.kw >= 0 && own_modifier(p, pig, here.kw))
        return 1;
    switch (here.type == TK_WORD ? here.kw : -1) {
    /* POV-Ray keeps these in single precision (SNGL): so do the values */
    case KW_frequency: pig->frequency = gram_single(expr_float(p)); return 1;
    case KW_phase: pig->phase = gram_single(expr_float(p)); return 1;
    case KW_ramp_wave: pig->wave = WAVE_RAMP; return 1;
    case KW_sine_wave: pig->wave = WAVE_SINE; return 1;
    case KW_triangle_wave: pig->wave = WAVE_TRIANGLE; return 1;
    case KW_scallop_wave: pig->wave = WAVE_SCALLOP; return 1;
    case KW_cubic_wave: pig->wave = WAVE_CUBIC; return 1;
    case KW_poly_wave:
        pig->wave = WAVE_POLY;
        pig->wave_exponent = expr_starts_float(p, tok_peek(p)) ? gram_single(expr_float(p)) : 1.0;
        return 1;
    case KW_turbulence: {
        PatternTurbulence *turb = gram_classic_turbulence(p, pig);
        turb->amount = expr_vector(p);
        return 1;
    }
    case KW_octaves: gram_classic_turbulence(p, pig)->octaves = gram_octaves_value(expr_float(p)); return 1;
    case KW_omega: gram_classic_turbulence(p, pig)->omega = gram_single(expr_float(p)); return 1;
    case KW_lambda: gram_classic_turbulence(p, pig)->lambda = gram_single(expr_float(p)); return 1;
    case KW_warp: gram_warp(p, pig, &here); return 1;
    case KW_noise_generator: {
        Token vt = *tok_peek(p);
        if (!int_from_double(expr_float(p), 0, 3, &pig->noise_generator))
            tok_fail(p, vt.pos, "Value for noise_generator must be 0, 1, 2, or 3.");
        return 1;
    }
    case KW_agate_turb:
        pig->agate_turb = gram_single(expr_float(p));
        (void)gram_classic_turbulence(p, pig);
        return 1;
    default:
        return 0;
    }
}

/* The items of a pigment up to `close` ('}' of a block, ']' of a
 * pigment_map entry). */
static void pigment_items(Parser *p, Pigment *pig, int close)
{
    int approximated = 0; /* the pattern is not evaluated: colour map at 0.5 */
    int uv_here = 0;      /* this block said uv_mapping: what follows is seen at (u, v, 0) */
    int mandel_map = 0;   /* the map is mandel's default, given at its keyword */
    Token average_at;     /* where `average` was, when it was */
    Colour quick;         /* quick_color, shown instead below +Q6 (ParseOptions.quick_colours) */
    int has_quick = 0;
    for (;;) {
        Token *t = tok_next(p);
        if (tok_is_punct(t, close))
            break;
        Token at = *t;
        const Value *id = gram_block_identifier(p, t, VAL_PIGMENT, "pigment");
        if (id) {
            /* `uv_mapping DECLARED`: POV-Ray's uv_mapping pattern holds the
             * declared pigment, evaluated at (u, v, 0) through the
             * pigment's own transforms (Parse_Item_Into_Blend_List) */
            *pig = *id->pigment;
            if (uv_here)
                pig->uv_mapping = 1;
            approximated = 0;
            continue;
        }
        if (expr_starts_colour(p, t)) {
            tok_unget(p);
            expr_colour(p, &pig->colour, 1);
            pig->kind = PIGMENT_SOLID;
            pig->nmap = 0;
            approximated = 0;
            continue;
        }
        /* after a uv-mapped identifier, transforms are the uv_mapping
         * pattern's own warps, which POV-Ray does not apply to its entry */
        Transform wrapper_warp;
        transform_identity(&wrapper_warp);
        if (expr_transform_item(p, t, pig->uv_mapping && !uv_here ? &wrapper_warp : &pig->transform))
            continue;
        int kw = t->type == TK_WORD ? t->kw : -1;
        if (kw == KW_quick_color || kw == KW_quick_colour) {
            expr_colour(p, &quick, 1);
            has_quick = 1;
            continue;
        }
        if (kw == KW_average) { /* in a pigment: the mean of its pigment_map's pigments */
            approximated = 0;
            mandel_map = 0;
            average_at = at;
            gram_start_pattern(p, pig, kw);
            pig->kind = PIGMENT_AVERAGE;
            continue;
        }
        switch (gram_pattern_support(kw)) {
        case PAT_EVALUATED:
            approximated = 0;
            gram_start_pattern(p, pig, kw);
            if (gram_pattern_list_count(kw))
                parse_colour_list(p, pig, kw, gram_pattern_list_count(kw));
            mandel_map = 0;
            if (pig->nmap == 0) {
                set_default_map(p, pig, kw);
                mandel_map = kw == KW_mandel;
            }
            continue;
        case PAT_APPROXIMATED:
            tok_approximate(p, &at, APPROX_PATTERN, &pig->approx);
            approximated = 1;
            pig->kind = PIGMENT_SOLID;
            pig->nmap = 0;
            gram_skip_arguments(p); /* `function { ... }`, `tiling 3`, ... */
            if (pig->nmap == 0)
                set_grey_map(p, pig);
            continue;
        case PAT_UNSUPPORTED:
            if (kw == KW_image_map) {
                parse_image_map(p, pig, &at);
                approximated = 0;
                continue;
            }
            tok_unsupported(p, &at);
        case PAT_NONE:
            break;
        }
        if (gram_pattern_modifier_item(p, pig, t))
            continue;
        switch (kw) {
        case KW_color_map:
        case KW_colour_map:
            gram_colour_map(p, pig);
            mandel_map = 0;
            continue;
        case KW_pigment_map:
            gram_pigment_map(p, pig, &at);
            mandel_map = 0;
            continue;
        case KW_texture_map: case KW_material_map:
            tok_fail(p, at.pos, "%s can only be used in a texture, not in a pigment", tok_keyword_name(kw));
        case KW_uv_mapping: {
            /* POV-Ray: a new pigment, made of the rest of this block, seen
             * at the surface's (u, v, 0); what came before is dropped. */
            const ApproxNote *notes = pig->approx;
            *pig = p->scene->default_texture.pigment;
            pig->approx = notes;
            transform_identity(&pig->transform);
            pig->uv_mapping = 1;
            uv_here = 1;
            approximated = 0;
            continue;
        }
        default:
            break;
        }
        if (kw >= 0 && gram_pattern_modifier(kw)) {
            /* modifiers of patterns hstrace does not evaluate */
            gram_skip_arguments(p);
            continue;
        }
        if (kw >= 0)
            tok_unsupported(p, t);
        tok_fail_expected(p, t, "a colour, a pattern, a transform or '}' in 'pigment'");
    }
    if (pig->kind == PIGMENT_AVERAGE && pig->nmap == 0)
        tok_fail(p, average_at.pos, "an average pigment needs a pigment_map");
    /* POV-Ray picks the default map after the pigment (Post_Pigment), by
     * the final kind: mandel of exponent 3 or more takes the grey one */
    if (mandel_map && pig->kind == PIGMENT_FRACTAL && pig->exponent != 2)
        set_grey_map(p, pig);
    if (pig->kind != PIGMENT_SOLID || approximated)
        set_representative(pig);
    if (approximated) {
        pig->kind = PIGMENT_SOLID;
        pig->nmap = 0;
        pig->map = NULL;
    }
    if (has_quick && p->opts->quick_colours) {
        /* POV-Ray below +Q6 (Q_QUICKC): the quick colour is the pigment */
        pig->kind = PIGMENT_SOLID;
        pig->nmap = 0;
        pig->map = NULL;
        pig->colour = quick;
    }
}

/* `albedo` after diffuse/phong/specular: the value is rescaled at the end. */
static int allow_albedo(Parser *p)
{
    if (tok_is_kw(tok_next(p), KW_albedo))
        return 1;
    tok_unget(p);
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
    Token *t = tok_next(p);
    if (!tok_is_punct(t, '{')) {
        tok_unget(p);
        expr_colour(p, &c, 0); /* old syntax: one colour */
        colour_to_rgb(f->reflection_max, &c);
        colour_to_rgb(f->reflection_min, &c);
        f->reflection_falloff = 1.0;
        f->reflection_fresnel = 0;
        return;
    }
    expr_colour(p, &c, 0);
    colour_to_rgb(f->reflection_min, &c);
    expr_comma(p);
    int second = 0;
    t = tok_peek(p);
    if (expr_starts_expression(p, t)) {
        expr_colour(p, &c, 0);
        second = 1;
    }
    colour_to_rgb(f->reflection_max, &c);
    for (;;) {
        t = tok_next(p);
        if (tok_is_punct(t, '}'))
            return;
        if (tok_is_kw(t, KW_fresnel)) {
            Token at = *t;
            double v = 1.0;
            if (expr_starts_float(p, tok_peek(p)))
                v = expr_float(p);
            if (!int_from_double(v, 0, 1, &f->reflection_fresnel))
                tok_fail(p, at.pos, "fresnel must be true or false");
            if (!second && f->reflection_fresnel)
                memset(f->reflection_min, 0, sizeof f->reflection_min);
        } else if (tok_is_kw(t, KW_falloff)) {
            f->reflection_falloff = expr_float(p);
        } else if (tok_is_kw(t, KW_exponent)) {
            (void)expr_float(p); /* reflection exponent: not modelled */
        } else if (tok_is_kw(t, KW_metallic)) {
            f->reflection_metallic = expr_starts_float(p, tok_peek(p)) ? expr_float(p) : 1.0;
        } else {
            tok_fail_expected(p, t, "fresnel, falloff, exponent, metallic or '}' in 'reflection'");
        }
    }
}

/* A finish's subsurface block, after 'subsurface': its colours read and
 * dropped (POV-Ray's Parse_Finish takes translucency and anisotropy, each
 * a colour, in any order). */
static void subsurface_block(Parser *p)
{
    tok_begin_block(p, "subsurface");
    for (;;) {
        Token *t = tok_next(p);
        if (tok_is_punct(t, '}'))
            return;
        if (!tok_is_kw(t, KW_translucency) && !tok_is_kw(t, KW_anisotropy))
            tok_fail_expected(p, t, "translucency, anisotropy or '}' in 'subsurface'");
        Colour ignored;
        expr_colour(p, &ignored, 0);
    }
}

void gram_finish(Parser *p, Finish *f)
{
    int diffuse_albedo = 0, phong_albedo = 0, specular_albedo = 0;
    tok_begin_block(p, "finish");
    for (;;) {
        Token *t = tok_next(p);
        if (tok_is_punct(t, '}'))
            break;
        const Value *id = gram_block_identifier(p, t, VAL_FINISH, "finish");
        if (id) {
            *f = *id->finish;
            continue;
        }
        Colour c;
        switch (t->type == TK_WORD ? t->kw : -1) {
        case KW_ambient:
            expr_colour(p, &c, 0);
            colour_to_rgb(f->ambient, &c);
            break;
        case KW_emission:
            expr_colour(p, &c, 0);
            colour_to_rgb(f->emission, &c);
            break;
        case KW_diffuse: {
            /* POV-Ray 3.7's Parse_Finish: `diffuse [albedo] Amount [,]
             * [Backside]`, the comma optional (Parse_Comma) and the backside
             * read wherever an expression starts (Allow_Float, default 0):
             * Blender's exporter writes `diffuse 0.8 0`. A minus sign joins
             * the amount instead (`diffuse 0.8 -0.2` is 0.6), as there. */
            diffuse_albedo = allow_albedo(p);
            f->diffuse = expr_float(p);
            expr_comma(p);
            Token back = *tok_peek(p);
            if (expr_starts_expression(p, &back) && expr_float(p) != 0.0) {
                /* light from behind the surface: not modelled */
                static const char what[] = "diffuse's backside value";
                back.text = what;
                back.len = (int)sizeof what - 1;
                tok_approximate(p, &back, APPROX_FINISH, &f->approx);
            }
            break;
        }
        case KW_brilliance: f->brilliance = expr_float(p); break;
        case KW_crand: {
            const Token at = *t; /* (the float's tokens come after: t is not kept) */
            f->crand = expr_float(p);
            if (f->crand != 0.0)
                tok_approximate(p, &at, APPROX_FINISH, &f->approx);
            break;
        }
        case KW_phong:
            phong_albedo = allow_albedo(p);
            f->phong = expr_float(p);
            break;
        case KW_phong_size: f->phong_size = expr_float(p); break;
        case KW_specular:
            specular_albedo = allow_albedo(p);
            f->specular = expr_float(p);
            break;
        case KW_roughness: f->roughness = expr_float(p); break;
        case KW_metallic:
            f->metallic = expr_starts_float(p, tok_peek(p)) ? expr_float(p) : 1.0;
            break;
        case KW_reflection: parse_reflection(p, f); break;
        case KW_reflection_exponent: (void)expr_float(p); break;
        case KW_conserve_energy: f->conserve_energy = 1; break;
        case KW_irid: /* iridescence: parsed past, not modelled */
            tok_approximate(p, t, APPROX_FINISH, &f->approx);
            tok_begin_block(p, "irid");
            tok_skip_block_body(p);
            break;
        case KW_ior: case KW_refraction: /* pre-3.0 spellings of interior settings */
            (void)expr_float(p);
            break;
        case KW_caustics: /* POV-Ray 3.7 still takes it here, unscaled (Parse_Finish) */
            f->caustics = (float)expr_float(p); /* single precision, as POV-Ray keeps it */
            break;
        case KW_subsurface:
            /* `subsurface { translucency C anisotropy C }`, as Blender's
             * exporter writes it: POV-Ray 3.7 uses it only where
             * global_settings turns subsurface light transport on (trace.cpp:
             * useSubsurface && UseSubsurface), which hstrace reports as
             * approximated there; elsewhere the finish is as without it. */
            subsurface_block(p);
            break;
        default:
            if (t->type == TK_WORD && t->kw >= 0)
                tok_unsupported(p, t);
            tok_fail_expected(p, t, "a finish item or '}' in 'finish'");
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

void gram_interior(Parser *p, Interior *in)
{
    tok_begin_block(p, "interior");
    for (;;) {
        Token *t = tok_next(p);
        if (tok_is_punct(t, '}'))
            return;
        const Value *id = gram_block_identifier(p, t, VAL_INTERIOR, "interior");
        if (id) {
            *in = *id->interior;
            continue;
        }
        switch (t->type == TK_WORD ? t->kw : -1) {
        case KW_ior: in->ior = expr_float(p); break;
        case KW_fade_distance: in->fade_distance = expr_float(p); break;
        case KW_fade_power: in->fade_power = expr_float(p); break;
        case KW_fade_color:
        case KW_fade_colour: expr_colour(p, &in->fade_colour, 0); break;
        case KW_caustics: /* fake caustics, in shadows (shadow_conventional.c) */
            in->caustics = (float)(expr_float(p) * 45.0); /* Parse_Interior's scale, in single precision */
            break;
        case KW_dispersion: case KW_dispersion_samples: {
            /* dispersion: not modelled */
            Token at = *t;
            double v = expr_float(p);
            if (at.kw == KW_dispersion && v != 1.0)
                tok_approximate(p, &at, APPROX_DISPERSION, &in->approx);
            break;
        }
        default:
            if (t->type == TK_WORD && t->kw >= 0)
                tok_unsupported(p, t);
            tok_fail_expected(p, t, "ior, fade_distance, fade_power, fade_colour or '}' in 'interior'");
        }
    }
}

void gram_material(Parser *p, const SceneTexture **tex, const Interior **in, const Token *at)
{
    tok_begin_block(p, "material");
    int first = 1;
    for (;;) {
        Token *t = tok_next(p);
        if (tok_is_punct(t, '}'))
            return;
        Token here = *t;
        /* a material identifier, as POV-Ray takes it: only first */
        const Value *id = first ? gram_block_identifier(p, t, VAL_MATERIAL, "material") : NULL;
        first = 0;
        if (id) {
            if (id->material_texture)
                *tex = *tex ? gram_layer_textures(p, id->material_texture, *tex, &here) : id->material_texture;
            if (id->material_interior) {
                /* POV-Ray's Parse_Material gives each use of a declared
                 * material an interior of its own (a copy): two objects of
                 * one transparent material are two interiors to the rays
                 * that cross both, e.g. a brick's studs inside the brick
                 * stacked on it (the interior's identity is its address:
                 * Material.interior_key) */
                Interior *own = tok_scene_alloc(p, sizeof *own);
                *own = *id->material_interior;
                *in = own;
            }
            continue;
        }
        if (tok_is_kw(t, KW_texture)) {
            SceneTexture *layer = gram_texture(p);
            *tex = *tex ? gram_layer_textures(p, layer, *tex, &here) : layer;
            continue;
        }
        if (tok_is_kw(t, KW_interior)) {
            Interior *next_in = tok_scene_alloc(p, sizeof *next_in);
            *next_in = *in ? **in : scene_default_interior();
            gram_interior(p, next_in);
            *in = next_in;
            continue;
        }
        /* A transform moves the textures given so far, not the object
         * (POV-Ray's Transform_Textures); an interior holds nothing hstrace
         * places in space. */
        Transform moved;
        transform_identity(&moved);
        if (expr_transform_item(p, t, &moved)) {
            if (*tex) {
                SceneTexture *copy = tok_scene_alloc(p, sizeof *copy);
                *copy = **tex;
                if (!copy->pigment.uv_mapping)
                    transform_compose(&copy->pigment.transform, &moved);
                copy->normal = gram_normal_transformed(p, copy->normal, &moved);
                copy->below = gram_layers_moved(p, copy->below, &moved);
                *tex = copy;
            }
            continue;
        }
        if (t->type == TK_WORD && t->kw >= 0)
            tok_unsupported(p, t); /* interior_texture, ... */
        if (t->type == TK_WORD && t->kw < 0)
            tok_fail_expected(p, t, "a material identifier (only first), texture, interior, a transform or '}' in 'material'");
        tok_fail_expected(p, t, "texture, interior, a transform or '}' in 'material'");
    }
    (void)at;
}

/* ---- textures and texture_map ------------------------------------------------- */

/* What hstrace does not do of a texture, at `at`, named by `what`: as any
 * unsupported keyword, an error, or in a #declare a value that is one when
 * used. */
static _Noreturn void texture_unsupported(Parser *p, const Token *at, const char *what)
{
    Token t = *at;
    t.text = tok_temp_strndup(p, what, strlen(what));
    t.len = (int)strlen(what);
    tok_unsupported(p, &t);
}

/* The notes of `from` (a texture_map's entry) joined to `*to` (the map's),
 * each place once, so that the report sees them from the map alone. */
static void join_notes(Parser *p, const ApproxNote **to, const ApproxNote *from)
{
    for (; from; from = from->next) {
        int seen = 0;
        for (const ApproxNote *n = *to; n && !seen; n = n->next)
            seen = n == from || (n->kind == from->kind && n->pos.line == from->pos.line &&
                                 n->pos.column == from->pos.column && n->pos.file == from->pos.file);
        if (seen)
            continue;
        ApproxNote *c = tok_scene_alloc(p, sizeof *c);
        *c = *from;
        c->next = *to;
        *to = c;
    }
}

static void texture_items(Parser *p, SceneTexture *tex, int close);

/* The entries of a patterned texture, in the order written: the map's
 * depth (at most MAX_TEXTURE_MAP_DEPTH) and its entries' notes. */
static void set_texture_map(Parser *p, SceneTexture *tex, const TextureMapEntry *entries, int n, const Token *at)
{
    TextureMapEntry *m = tok_scene_alloc(p, sizeof *m * (size_t)n);
    int depth = 0;
    for (int i = 0; i < n; i++) {
        m[i] = entries[i];
        m[i].texture = gram_layers_blended(p, m[i].texture, at);
        const SceneTexture *e = m[i].texture;
        if (e->map_depth > depth)
            depth = e->map_depth;
        join_notes(p, &tex->approx, e->approx);
        join_notes(p, &tex->approx, e->pigment.approx);
        join_notes(p, &tex->approx, e->finish.approx);
    }
    if (depth + 1 > MAX_TEXTURE_MAP_DEPTH) {
        char what[96];
        snprintf(what, sizeof what, "texture_map nested more than %d deep", MAX_TEXTURE_MAP_DEPTH);
        texture_unsupported(p, at, what);
    }
    tex->map = m;
    tex->nmap = n;
    tex->map_depth = depth + 1;
}

/* texture_map { [value texture items] ... } (POV-Ray's Parse_Blend_Map for
 * textures): each entry a texture as written in texture { }, from the
 * default texture, a texture identifier, pigment, finish, or a pattern and
 * a texture_map of its own. */
void gram_texture_map(Parser *p, SceneTexture *tex, const Token *at)
{
    tok_begin_block(p, "texture_map");
    const Value *id = gram_map_identifier(p, VAL_TEXTURE_MAP, "texture_map");
    if (id) {
        set_texture_map(p, tex, id->texture->map, id->texture->nmap, at);
        return;
    }
    tok_nesting_enter(p, at);
    TempVec entries;
    tok_tvec_init(&entries, sizeof(TextureMapEntry));
    double v;
    while (gram_blend_map_entry(p, "texture_map", &entries, 0, &v)) {
        SceneTexture *e = gram_default_texture(p);
        e->pos = p->tok.pos;
        texture_items(p, e, ']');
        TextureMapEntry *slot = tok_tvec_push(p, &entries);
        slot->value = v;
        slot->texture = e;
    }
    if (entries.n < 1)
        tok_fail(p, p->tok.pos, "Must have at least one entry in map.");
    tok_nesting_leave(p);
    set_texture_map(p, tex, entries.data, entries.n, at);
}

/* checker, hexagon, brick, square, triangular and cubic in a texture: up
 * to `count` `texture { }` items, commas optional, the missing ones the
 * default texture (POV-Ray's Parse_Blend_List for textures); entry i has
 * the value i. */
static void parse_texture_list(Parser *p, SceneTexture *tex, int count, const Token *at)
{
    TextureMapEntry e[6];
    int i = 0;
    tok_nesting_enter(p, at);
    for (; i < count && tok_is_kw(tok_peek(p), KW_texture); i++) {
        (void)tok_next(p);
        e[i].value = i;
        e[i].texture = gram_texture(p);
        expr_comma(p);
    }
    tok_nesting_leave(p);
    for (; i < count; i++) {
        SceneTexture *d = gram_default_texture(p);
        d->pos = at->pos;
        e[i].value = i;
        e[i].texture = d;
    }
    set_texture_map(p, tex, e, count, at);
}

/* A texture made of other textures (a pattern's texture_map or list,
 * tiles, a material_map): its own pigment cleared for the pattern that
 * chooses among them (its notes of approximations kept), and no normal of
 * its own (its textures have theirs). */
static void clear_for_pattern(SceneTexture *tex)
{
    Pigment *pig = &tex->pigment;
    const ApproxNote *notes = pig->approx;
    memset(pig, 0, sizeof *pig); /* PIGMENT_SOLID, colour 0 */
    pig->approx = notes;
    transform_identity(&pig->transform);
    tex->normal = NULL;
}

/* A patterned texture (POV-Ray's Parse_Pattern for a texture), from its
 * pattern keyword `at` (read) to `close`: the pattern, its modifiers and
 * transforms, and its texture_map (checker and hexagon: their list of
 * textures instead). */
static void parse_patterned_texture(Parser *p, SceneTexture *tex, const Token *at, int close)
{
    int kw = at->kw;
    Pigment *pig = &tex->pigment;
    /* the pattern of the texture itself: none of the default pigment's colours */
    clear_for_pattern(tex);
    gram_start_pattern(p, pig, kw);
    int listed = gram_pattern_list_count(kw) > 0;
    if (listed)
        parse_texture_list(p, tex, gram_pattern_list_count(kw), at);
    for (;;) {
        Token *t = tok_next(p);
        if (tok_is_punct(t, close))
            break;
        Token here = *t;
        if (expr_transform_item(p, t, &pig->transform))
            continue;
        if (gram_pattern_modifier_item(p, pig, t))
            continue;
        switch (here.type == TK_WORD ? here.kw : -1) {
        case KW_texture_map:
            if (listed)
                tok_fail(p, here.pos, "texture_map cannot be used with %s (it takes a list of textures)",
                           tok_keyword_name(kw));
            gram_texture_map(p, tex, &here);
            continue;
        case KW_no_bump_scale:
            /* POV-Ray then moves the entries' normals through the map's
             * transforms unnormalised: not modelled */
            tok_approximate(p, &here, APPROX_NORMAL, &tex->approx);
            continue;
        case KW_color_map: case KW_colour_map: case KW_pigment_map:
            tok_fail(p, here.pos, "%s can only be used in a pigment, not in a texture", tok_keyword_name(here.kw));
        case KW_pigment: case KW_finish: case KW_normal:
            tok_fail(p, here.pos, "a patterned texture (%s ... texture_map) has no %s of its own: give it in the "
                       "textures of its texture_map", tok_keyword_name(kw), tok_keyword_name(here.kw));
        default:
            break;
        }
        if (here.type == TK_WORD && here.kw >= 0 && gram_pattern_support(here.kw) == PAT_NONE &&
            !gram_pattern_modifier(here.kw))
            tok_unsupported(p, &here);
        tok_fail_expected(p, &here, "a pattern modifier, texture_map, a transform or the end of a patterned texture");
    }
    if (tex->nmap == 0)
        tok_fail(p, at->pos, "Patterned texture must have texture_map.");
}

/* tiles { texture { } ... tile2 texture { } ... } after 'tiles' (`at`), as
 * POV-Ray's Parse_Tiles: a checker texture whose first tile's textures
 * (layered, the last on top) are the map's entry 1 and the second tile's
 * its entry 0 ("to keep compatible with old tiles"). A tile without a
 * texture is refused: POV-Ray refuses the first, and stops with a
 * segmentation fault on the second. */
static void parse_tiles(Parser *p, SceneTexture *tex, const Token *at)
{
    tok_begin_block(p, "tiles");
    tok_nesting_enter(p, at);
    clear_for_pattern(tex);
    gram_start_pattern(p, &tex->pigment, KW_checker);
    SceneTexture *tile[2] = { NULL, NULL }; /* the first tile, then tile2 */
    for (int k = 0; k < 2; k++) {
        if (k == 1) {
            Token *t = tok_next(p);
            if (!tok_is_kw(t, KW_tile2))
                tok_fail_expected(p, t, "texture or tile2 in 'tiles'");
        }
        while (tok_is_kw(tok_peek(p), KW_texture)) {
            Token here = *tok_next(p);
            SceneTexture *layer = gram_texture(p);
            tile[k] = tile[k] ? gram_layer_textures(p, layer, tile[k], &here) : layer;
        }
        if (!tile[k])
            tok_fail(p, p->tok.pos, k == 0 ? "First texture missing from tiles" : "Second texture missing from tiles");
    }
    Token *end = tok_next(p);
    if (!tok_is_punct(end, '}'))
        tok_fail_expected(p, end, "texture or '}' after tile2 in 'tiles'");
    tok_nesting_leave(p);
    TextureMapEntry e[2] = { { .value = 0.0, .texture = tile[1] }, { .value = 1.0, .texture = tile[0] } };
    set_texture_map(p, tex, e, 2, at);
}

/* material_map { [type] "file" [gamma G] [premultiplied B] once
 * interpolate map_type texture { } ... } after 'material_map' (`at`), as
 * POV-Ray's Parse_Material_Map: the picture (read as data, not gamma
 * corrected, as POV-Ray reads it), then the textures it chooses among. */
static void parse_material_map(Parser *p, SceneTexture *tex, const Token *at)
{
    tok_begin_block(p, "material_map");
    tok_nesting_enter(p, at);
    Pigment *pig = &tex->pigment;
    clear_for_pattern(tex);
    gram_image_source(p, pig, at, "material_map", 0);
    TempVec entries;
    tok_tvec_init(&entries, sizeof(TextureMapEntry));
    for (;;) {
        Token *o = tok_next(p);
        if (tok_is_punct(o, '}'))
            break;
        Token here = *o;
        int kw = o->type == TK_WORD ? o->kw : -1;
        if (entries.n > 0 && kw != KW_texture) /* the picture's options come before the textures */
            tok_fail_expected(p, &here, "texture or '}' in 'material_map'");
        switch (kw) {
        case KW_once: pig->image_once = 1; continue;
        case KW_interpolate: pig->image_interpolate = gram_image_interpolation(p, &here); continue;
        case KW_map_type: pig->image_map_type = gram_image_map_type(p, &here); continue;
        case KW_texture: {
            if (entries.n >= 256)
                tok_fail(p, here.pos, "more than 256 textures in a material_map");
            TextureMapEntry *slot = tok_tvec_push(p, &entries);
            slot->value = entries.n - 1;
            slot->texture = gram_texture(p);
            continue;
        }
        case KW_repeat: case KW_offset:
            tok_unsupported(p, &here);
        default:
            tok_fail_expected(p, &here, "once, interpolate, map_type or texture in 'material_map'");
        }
    }
    if (entries.n < 1)
        tok_fail(p, p->tok.pos, "a material_map needs at least one texture (POV-Ray: \"texture expected\")");
    tok_nesting_leave(p);
    set_texture_map(p, tex, entries.data, entries.n, at);
    tex->material_map = 1;
}

/* After a texture_map texture (an identifier, or the default texture when
 * that is one): only transforms, as POV-Ray's Parse_Texture_Transform;
 * they move the map's pattern, and with it its textures. */
static void texture_map_transforms(Parser *p, SceneTexture *tex, int close, const Token *what)
{
    for (;;) {
        Token *t = tok_next(p);
        if (tok_is_punct(t, close))
            return;
        Transform ignored;
        transform_identity(&ignored);
        if (expr_transform_item(p, t, tex->pigment.uv_mapping ? &ignored : &tex->pigment.transform))
            continue;
        char msg[160];
        snprintf(msg, sizeof msg, "a transform or the end of the texture after %.*s (a texture_map texture: its "
                 "pigments and finishes are its entries')", what->len > 40 ? 40 : what->len, what->text);
        tok_fail_expected(p, t, msg);
    }
}

/* The items of a texture up to `close` ('}' of a block, ']' of a
 * texture_map entry), on `tex` (a copy of the default texture). A
 * texture_map texture is a pattern first, or a texture identifier of one,
 * first; anything else is a plain texture. */
static void texture_items(Parser *p, SceneTexture *tex, int close)
{
    int first = 1; /* nothing given yet: a pattern may start a texture_map texture */
    if (tex->nmap > 0) { /* a default texture that is a texture_map */
        Token here = p->tok;
        texture_map_transforms(p, tex, close, &here);
        return;
    }
    int only_ids = 1; /* nothing but identifiers so far: a pigment, normal or finish one may follow */
    for (;;) {
        Token *t = tok_next(p);
        if (tok_is_punct(t, close))
            return;
        Token here = *t;
        /* POV-Ray's [pnf_ids]: `texture { Jade }` with Jade a pigment (old
         * scenes and textures.inc's pigments write them so), before the
         * texture's blocks */
        const Symbol *pnf = here.type == TK_WORD && here.kw < 0 && only_ids ? tok_symbol_of(p, &here) : NULL;
        if (pnf && (pnf->value.kind == VAL_PIGMENT || pnf->value.kind == VAL_FINISH || pnf->value.kind == VAL_NORMAL) &&
            tex->nmap == 0) {
            if (pnf->value.kind == VAL_PIGMENT)
                tex->pigment = *pnf->value.pigment;
            else if (pnf->value.kind == VAL_FINISH)
                tex->finish = *pnf->value.finish;
            else
                tex->normal = pnf->value.normal;
            first = 0;
            continue;
        }
        const Value *id = gram_block_identifier(p, t, VAL_TEXTURE, "texture");
        if (id) {
            SourcePos pos = tex->pos;
            if (id->texture->nmap > 0 && !first)
                tok_fail(p, here.pos, "'%.*s' is a texture_map texture: it must come first in the texture",
                           here.len, here.text);
            *tex = *id->texture;
            tex->pos = pos;
            if (tex->nmap > 0) {
                texture_map_transforms(p, tex, close, &here);
                return;
            }
            first = 0;
            continue;
        }
        int kw = here.type == TK_WORD ? here.kw : -1;
        switch (kw) {
        case KW_pigment: gram_pigment(p, &tex->pigment); first = only_ids = 0; continue;
        case KW_finish: gram_finish(p, &tex->finish); first = only_ids = 0; continue;
        case KW_normal:
            tex->normal = gram_normal(p, tex->normal, &here, 1);
            first = only_ids = 0;
            continue;
        case KW_no_bump_scale: continue;
        case KW_uv_mapping: {
            /* POV-Ray's Parse_Texture: with nothing before it, uv_mapping
             * makes a uv_mapping pattern of a texture read from the rest of
             * the block (Parse_Pattern, Parse_Item_Into_Blend_List); its
             * pigment and normal are seen at the surface's (u, v, 0), placed
             * by the transforms inside. After a pigment, an identifier or a
             * transform POV-Ray stops at it ("'}' expected"). */
            if (!first)
                tok_fail_expected(p, &here, "'}' (uv_mapping must come first in its texture)");
            texture_items(p, tex, close);
            const SceneTexture *mapped = gram_texture_uv_mapped(p, tex);
            if (mapped != tex)
                *tex = *mapped;
            return;
        }
        case KW_texture: /* `texture { }` in a texture, or around a texture_map entry */
            tok_fail_expected(p, &here, close == ']' ? "the items of a texture (without 'texture { }' around them) in a "
                                                   "texture_map entry"
                                                 : "pigment, normal, finish, a pattern, a transform or '}' in 'texture'");
        case KW_texture_map:
            tok_fail(p, here.pos, "texture_map needs a pattern before it (texture { gradient y texture_map { ... } })");
        case KW_material_map:
            if (!first)
                tok_fail(p, here.pos, "material_map must come first in its texture (only transforms may follow "
                                        "it)");
            parse_material_map(p, tex, &here);
            texture_map_transforms(p, tex, close, &here);
            return;
        case KW_tiles:
            if (!first)
                tok_fail(p, here.pos, "tiles must come first in its texture (only transforms may follow it)");
            parse_tiles(p, tex, &here);
            texture_map_transforms(p, tex, close, &here);
            return;
        default:
            if (expr_starts_colour(p, &here))
                tok_fail_expected(p, &here, close == ']' ? "a texture's items (pigment { ... } ...), not a colour, in a "
                                                       "texture_map entry"
                                                     : "pigment { colour ... }, not a colour, in 'texture'");
            break;
        }
        /* A transform moves the pigment and the normal (a uv-mapped one is
         * not moved by the texture's transforms). */
        Transform moved;
        transform_identity(&moved);
        if (expr_transform_item(p, t, &moved)) {
            if (!tex->pigment.uv_mapping)
                transform_compose(&tex->pigment.transform, &moved);
            tex->normal = gram_normal_transformed(p, tex->normal, &moved);
            tex->below = gram_layers_moved(p, tex->below, &moved);
            first = only_ids = 0;
            continue;
        }
        if (kw >= 0 && gram_pattern_support(kw) != PAT_NONE) {
            if (!first)
                tok_fail(p, here.pos, "a texture patterned by %s cannot have a pigment, normal, finish, texture "
                           "identifier or transform before its pattern", tok_keyword_name(kw));
            if (gram_pattern_support(kw) == PAT_EVALUATED) {
                parse_patterned_texture(p, tex, &here, close);
                return;
            }
            /* A pattern hstrace does not evaluate: say that the texture is
             * patterned by it, not that the pattern is (Arbaro's trees write
             * patterned textures). */
            char patterned[96];
            snprintf(patterned, sizeof patterned, "texture_map (a texture patterned by %.*s)",
                     here.len > 40 ? 40 : here.len, here.text);
            texture_unsupported(p, &here, patterned);
        }
        if (kw >= 0)
            tok_unsupported(p, &here);
        tok_fail_expected(p, &here, "pigment, normal, finish, a pattern, a transform or '}' in 'texture'");
    }
}

SceneTexture *gram_texture(Parser *p)
{
    Token kw = p->tok;
    tok_begin_block(p, "texture");
    SceneTexture *tex = gram_default_texture(p);
    tex->pos = kw.pos;
    texture_items(p, tex, '}');
    return tex;
}

/* ---- layered textures ------------------------------------------------------ */

/* POV-Ray's greyscale weights (base/types.h). */
static double greyscale(double r, double g, double b) { return 0.297 * r + 0.589 * g + 0.114 * b; }

static int layer_count(const SceneTexture *t)
{
    int n = 0;
    for (; t; t = t->below)
        n++;
    return n;
}

/* The layers of `upper` (copied), then those of `lower` under them. A
 * layer that lets no light through anywhere ends the stack: POV-Ray's
 * ComputeLightedTexture stops at it, and its ComputeShadowTexture lets no
 * light through it, whatever lies below. */
static SceneTexture *stack_layers(Parser *p, const SceneTexture *upper, const SceneTexture *lower)
{
    SceneTexture *top = NULL, **link = &top;
    for (const SceneTexture *l = upper; l; l = l->below) {
        SceneTexture *c = tok_scene_alloc(p, sizeof *c);
        *c = *l;
        c->below = NULL;
        *link = c;
        if (pigment_is_opaque(&c->pigment))
            return top;
        link = (SceneTexture **)&c->below;
    }
    *link = (SceneTexture *)lower;
    return top;
}

/* `texture { B } texture { T }`: T lies on B, each layer kept whole (its
 * pigment, normal and finish), shaded as POV-Ray's ComputeLightedTexture
 * shades a layered texture and filtering shadow rays as its
 * ComputeShadowTexture (shade.c, pigment.c). A layer that is a texture_map
 * is not followed. */
SceneTexture *gram_layer_textures(Parser *p, const SceneTexture *top, const SceneTexture *below, const Token *at)
{
    if (top->nmap > 0 || below->nmap > 0)
        texture_unsupported(p, at, "texture_map in layered textures");
    if (layer_count(top) + layer_count(below) > MAX_TEXTURE_LAYERS) {
        char what[64];
        snprintf(what, sizeof what, "more than %d texture layers", MAX_TEXTURE_LAYERS);
        texture_unsupported(p, at, what);
    }
    return stack_layers(p, top, below);
}

/* The layers of `tex` moved by `moved`, as POV-Ray's Transform_Textures
 * moves every layer (a uv-mapped pigment keeps its place). */
const SceneTexture *gram_layers_moved(Parser *p, const SceneTexture *tex, const Transform *moved)
{
    if (!tex)
        return NULL;
    SceneTexture *c = tok_scene_alloc(p, sizeof *c);
    *c = *tex;
    if (!c->pigment.uv_mapping)
        transform_compose(&c->pigment.transform, moved);
    c->normal = gram_normal_transformed(p, c->normal, moved);
    c->below = gram_layers_moved(p, tex->below, moved);
    return c;
}

/* A layered texture where hstrace shades only plain ones (an entry of a
 * texture_map, a mesh face's texture per vertex): its layers blended into
 * one pigment as ComputeLightedTexture weighs them for ambient and diffuse
 * light -- each layer's colour times its opacity times what the layers
 * above let through -- with the top layer's finish and normal. An
 * approximation (the lower layers' finishes, normals and filter colours
 * are lost, and patterns stand by their representative colour), noted at
 * `at`. */
const SceneTexture *gram_layers_blended(Parser *p, const SceneTexture *tex, const Token *at)
{
    if (!tex->below)
        return tex;
    SceneTexture *r = tok_scene_alloc(p, sizeof *r);
    *r = *tex;
    r->below = NULL;
    double lit[3] = { 0, 0, 0 }, fil[3] = { 1, 1, 1 };
    for (const SceneTexture *l = tex; l; l = l->below) {
        const Colour *c = &l->pigment.colour;
        if (fmin(1.0, fabs(greyscale(fil[0], fil[1], fil[2]))) <= 1.0 / 255.0)
            break; /* POV-Ray's adc_bailout default: the rest cannot show */
        double rgb[3] = { c->r, c->g, c->b }, opacity = 1.0 - c->filter - c->transmit;
        for (int k = 0; k < 3; k++) {
            lit[k] += rgb[k] * opacity * fil[k];
            fil[k] *= rgb[k] * c->filter + c->transmit;
        }
        if (l != tex) { /* the lower layers' notes, on the blend */
            join_notes(p, &r->approx, l->approx);
            join_notes(p, &r->pigment.approx, l->pigment.approx);
        }
    }
    double t = fmin(1.0, fmax(0.0, greyscale(fil[0], fil[1], fil[2])));
    Pigment *pig = &r->pigment;
    pig->kind = PIGMENT_SOLID;
    pig->nmap = 0;
    pig->map = NULL;
    pig->colour.r = t < 1.0 ? lit[0] / (1.0 - t) : 0.0;
    pig->colour.g = t < 1.0 ? lit[1] / (1.0 - t) : 0.0;
    pig->colour.b = t < 1.0 ? lit[2] / (1.0 - t) : 0.0;
    pig->colour.filter = 0.0;
    pig->colour.transmit = t;
    tok_approximate(p, at, APPROX_LAYERS, &r->approx);
    return r;
}

/* ---- sky_sphere ------------------------------------------------------------ */

void gram_sky_sphere(Parser *p, SkySphere *sky)
{
    tok_begin_block(p, "sky_sphere");
    TempVec pigments;
    tok_tvec_init(&pigments, sizeof(Pigment));
    Transform tr;
    transform_identity(&tr);
    for (;;) {
        Token *t = tok_next(p);
        if (tok_is_punct(t, '}'))
            break;
        if (expr_transform_item(p, t, &tr))
            continue;
        if (tok_is_kw(t, KW_pigment)) {
            Pigment *pig = tok_tvec_push(p, &pigments);
            *pig = p->scene->default_texture.pigment;
            pig->approx = NULL;
            Token at = *t;
            gram_pigment(p, pig);
            if (pig->uv_mapping && pig->kind != PIGMENT_SOLID) /* as POV-Ray: a sky has no uv */
                tok_fail(p, at.pos, "uv_mapping cannot be used in a sky_sphere pigment");
            continue;
        }
        if (t->type == TK_WORD && t->kw < 0) {
            /* A declared sky sphere (skies.inc's S_Cloud1 ...), as POV-Ray
             * only as the first item: its pigments and transform, then more. */
            Symbol *sym = tok_symbol_of(p, t);
            if (!sym)
                tok_fail(p, t->pos, "undeclared identifier '%.*s'", t->len, t->text);
            if (sym->value.kind == VAL_UNSUPPORTED)
                tok_use_unsupported(p, t, &sym->value);
            if (sym->value.kind != VAL_SKY_SPHERE)
                tok_fail(p, t->pos, "'%.*s' is %s, not a sky_sphere", t->len, t->text,
                           tok_value_kind_name(sym->value.kind));
            if (pigments.n > 0 || !transform_is_identity(&tr))
                tok_fail(p, t->pos, "a sky_sphere identifier must come first in 'sky_sphere'");
            const SkySphere *from = sym->value.sky;
            for (int i = 0; i < from->npigments; i++)
                *(Pigment *)tok_tvec_push(p, &pigments) = from->pigments[i];
            tr = from->transform;
            continue;
        }
        if (tok_is_kw(t, KW_emission)) { /* 3.7.1: scales the sky; 1 is the default */
            Colour c;
            Token at = *t;
            expr_colour(p, &c, 0);
            if (c.r != 1.0 || c.g != 1.0 || c.b != 1.0)
                tok_unsupported(p, &at);
            continue;
        }
        if (t->type == TK_WORD && t->kw >= 0)
            tok_unsupported(p, t);
        tok_fail_expected(p, t, "pigment, a transform or '}' in 'sky_sphere'");
    }
    /* A second sky_sphere replaces the first, as in POV-Ray. */
    sky->npigments = pigments.n;
    sky->pigments = tok_scene_alloc(p, sizeof(Pigment) * (size_t)(pigments.n ? pigments.n : 1));
    if (pigments.n)
        memcpy(sky->pigments, pigments.data, sizeof(Pigment) * (size_t)pigments.n);
    sky->transform = tr;
}
