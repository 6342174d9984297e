/* text { ttf "FILE" | internal N, "STRING", THICKNESS, OFFSET modifiers },
 * as POV-Ray 3.7's Parse_TrueType and ProcessNewTTF make it: a union of one
 * glyph object per character (scene.h's OBJ_GLYPH), each moved to its place
 * along the string by the font's advance widths, left side bearings and
 * kerning and by OFFSET after each character, the union turned by POV-Ray's
 * tiny rotation of 0.001 degrees about each axis before the modifiers.
 * The font is read by truetype_font.c. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "grammar.h"
#include "truetype_font.h"

/* POV-Ray's built-in fonts (Internal_Font_File): the same bytes as the
 * font files POV-Ray installs among its include files, read from there. */
static const char *internal_font_name(int id)
{
    switch (id) {
    case 1: return "timrom.ttf";
    case 2: return "cyrvetic.ttf";
    case 3: return "crystal.ttf";
    default: return "povlogo.ttf";
    }
}

/* The font file `name`, found as POV-Ray's Locate_File finds a font: as
 * #include files are found, then, for a name without a '.', with ".ttf"
 * appended. */
static char *find_font(Parser *p, const char *name)
{
    char *path = gram_find_image_file(p, name);
    if (path || strchr(name, '.'))
        return path;
    size_t n = strlen(name) + 5;
    char *with_ext = tok_temp_alloc(p, n);
    snprintf(with_ext, n, "%s.ttf", name);
    return gram_find_image_file(p, with_ext);
}

/* The string's characters as String_To_UCS2 makes them under the scene's
 * charset (escapes already read by the lexer): ASCII keeps 7 bits and
 * makes any other byte a space (before #version 3.5, the byte itself);
 * UTF-8 is decoded. Returns how many, in out (room for strlen(s)). */
static int string_characters(Parser *p, const char *s, const Token *at, unsigned *out)
{
    const unsigned char *u = (const unsigned char *)s;
    const int charset = p->gram->charset;
    int n = 0;
    int warned = 0;
    if (charset == TTF_CHARSET_SYS) {
        /* the system's own encoding (POV_CONVERT_TEXT_TO_UCS2) */
        Token what = *at;
        what.text = "text under charset sys";
        what.len = (int)strlen(what.text);
        tok_unsupported(p, &what);
    }
    for (size_t i = 0; u[i];) {
        if (charset == TTF_CHARSET_UTF8) {
            unsigned c = u[i];
            int more = c < 0x80 ? 0 : c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : 0;
            unsigned cp = more == 0 ? c : more == 1 ? c & 0x1F : more == 2 ? c & 0x0F : c & 0x07;
            i++;
            for (int k = 0; k < more && u[i]; k++, i++) {
                if ((u[i] & 0xC0) != 0x80)
                    tok_fail(p, at->pos, "text: the string is not valid UTF-8");
                cp = cp << 6 | (u[i] & 0x3F);
            }
            out[n++] = cp & 0xFFFF; /* POV-Ray's characters are 16 bits (UCS2) */
        } else {
            unsigned c = u[i++];
            if (p->version < 3.5) {
                out[n++] = c;
            } else if (c & 0x80) {
                if (!warned)
                    tok_warning(p, at->pos, "Non-ASCII character has been replaced by space character.");
                warned = 1;
                out[n++] = ' ';
            } else {
                out[n++] = c;
            }
        }
    }
    return n;
}

/* A glyph in the scene's memory, shared by the characters that use it. */
static const SceneGlyph *scene_glyph(Parser *p, const TtfGlyph *g, int units_per_em)
{
    SceneGlyph *sg = tok_scene_alloc(p, sizeof *sg);
    const int npoints = g->start[g->ncontours];
    int *start = tok_scene_alloc(p, sizeof *start * (size_t)(g->ncontours + 1));
    double *x = tok_scene_alloc(p, sizeof *x * (size_t)(npoints + 1));
    double *y = tok_scene_alloc(p, sizeof *y * (size_t)(npoints + 1));
    unsigned char *on = tok_scene_alloc(p, (size_t)(npoints + 1));
    memcpy(start, g->start, sizeof *start * (size_t)(g->ncontours + 1));
    memcpy(x, g->x, sizeof *x * (size_t)npoints);
    memcpy(y, g->y, sizeof *y * (size_t)npoints);
    memcpy(on, g->on_curve, (size_t)npoints);
    sg->ncontours = g->ncontours;
    sg->start = start;
    sg->x = x;
    sg->y = y;
    sg->on_curve = on;
    sg->xmin = g->xmin;
    sg->ymin = g->ymin;
    sg->xmax = g->xmax;
    sg->ymax = g->ymax;
    sg->units_per_em = units_per_em;
    return sg;
}

/* TrueType::Compute_BBox of glyph object g, placed by its transform: the
 * header's bounds from z = -TTF_Tolerance to depth + TTF_Tolerance, in
 * single precision, carried through the transform. */
static void glyph_extent(SceneObject *g, const SceneGlyph *sg, double depth, double funit)
{
    const double tol = 1.0e-6;
    const double xmin = sg->xmin * funit, ymin = sg->ymin * funit, xmax = sg->xmax * funit, ymax = sg->ymax * funit;
    const double zmin = -tol, zmax = depth + tol;
    g->extent_lower[0] = (float)xmin;
    g->extent_lower[1] = (float)ymin;
    g->extent_lower[2] = (float)zmin;
    g->extent_lengths[0] = (float)(xmax - xmin);
    g->extent_lengths[1] = (float)(ymax - ymin);
    g->extent_lengths[2] = (float)(zmax - zmin);
    g->has_extent = 1;
    gram_extent_transform(g, &g->transform);
}

typedef struct {
    unsigned ch, index, metrics;
    int xmin;
    const SceneGlyph *glyph;
} KnownGlyph;

/* ProcessNewTTF: the glyph objects of the string, placed, and the text's
 * bounding box. The font is closed here, before a glyph that cannot be
 * read is reported (tok_fail does not return). */
static void lay_out(Parser *p, SceneObject *text, TtfFont *font, const unsigned *chars, int n, double depth,
                    Vec3 offset, const Token *at, TempVec *children)
{
    const int upem = ttf_units_per_em(font);
    const double funit = 1.0 / (double)upem;
    TempVec known;
    tok_tvec_init(&known, sizeof(KnownGlyph));
    Vec3 total = v3(0.0, 0.0, 0.0);
    unsigned last_index = 0;
    /* CSG::Compute_BBox of the union: around its glyphs' boxes */
    double box_min[3] = { 2.0e10, 2.0e10, 2.0e10 }, box_max[3] = { -2.0e10, -2.0e10, -2.0e10 };
    char err[256];
    for (int i = 0; i < n; i++) {
        /* ProcessCharacter: the glyph already read for this character, or
         * for this glyph index, else read now */
        const KnownGlyph *kg = NULL;
        for (int k = 0; k < known.n && !kg; k++)
            if (((KnownGlyph *)known.data)[k].ch == chars[i])
                kg = &((KnownGlyph *)known.data)[k];
        unsigned index = kg ? kg->index : ttf_char_index(font, chars[i]);
        for (int k = 0; k < known.n && !kg; k++)
            if (((KnownGlyph *)known.data)[k].index == index)
                kg = &((KnownGlyph *)known.data)[k];
        if (!kg) {
            TtfGlyph g;
            if (ttf_glyph(font, index, chars[i], &g, err, sizeof err)) {
                ttf_close(font);
                tok_fail(p, at->pos, "text: %s", err);
            }
            KnownGlyph *nk = tok_tvec_push(p, &known);
            nk->ch = chars[i];
            nk->index = index;
            nk->metrics = g.metrics;
            nk->xmin = g.xmin;
            nk->glyph = scene_glyph(p, &g, upem);
            ttf_glyph_free(&g);
            kg = nk;
        }
        int advance, lsb;
        ttf_metrics(font, kg->metrics, &advance, &lsb);
        Vec3 place;
        if (i == 0) {
            /* the first glyph's left edge at the origin */
            total.x = -kg->xmin * funit;
            place = total;
            total.x = (advance - lsb) * funit;
        } else {
            int kx, ky;
            ttf_kerning(font, last_index, kg->metrics, &kx, &ky);
            /* its left edge at the previous advance, its bearing and the
             * kerning; POV-Ray's offset moves along z are not applied */
            place = v3(total.x + (double)(lsb - kg->xmin + kx) * funit, total.y + (double)ky * funit, 0.0);
            total.x += (advance + kx) * funit;
        }
        total = v3_add(total, offset);
        SceneObject *g = gram_new_object(p, OBJ_GLYPH, at);
        g->pos = text->pos;
        g->u.glyph.glyph = kg->glyph;
        g->u.glyph.depth = depth;
        transform_translate(&g->transform, place);
        glyph_extent(g, kg->glyph, depth, funit);
        double lo[3], hi[3];
        gram_extent_min_max(g, lo, hi);
        for (int k = 0; k < 3; k++) {
            box_min[k] = fmin(box_min[k], lo[k]);
            box_max[k] = fmax(box_max[k], hi[k]);
        }
        *(SceneObject **)tok_tvec_push(p, children) = g;
        last_index = index;
    }
    ttf_close(font);
    /* no glyph (an empty string): POV-Ray keeps the box of everything,
     * which min_extent and max_extent report as +-1e10 (measured) */
    const int empty = box_min[0] > box_max[0] || box_min[1] > box_max[1] || box_min[2] > box_max[2];
    for (int k = 0; k < 3; k++)
        if (empty || box_max[k] - box_min[k] > 1.0e6) /* CRITICAL_LENGTH: the box of everything */
            box_min[0] = box_min[1] = box_min[2] = -1.0e10, box_max[0] = box_max[1] = box_max[2] = 1.0e10;
    gram_extent_from_min_max(text, box_min, box_max);
}

/* String_To_UCS2 reads \uXXXX as the character XXXX; hstrace's lexer
 * has read the string already, without that escape: refused where a
 * written string holds one. */
static void refuse_unicode_escape(Parser *p, const Token *string_at)
{
    if (string_at->type != TK_STRING)
        return;
    for (int i = 0; i + 1 < string_at->len; i++) {
        if (string_at->text[i] != '\\')
            continue;
        if (string_at->text[i + 1] == 'u') {
            Token what = *string_at;
            what.text = "the escape \\u in a text string";
            what.len = (int)strlen(what.text);
            tok_unsupported(p, &what);
        }
        i++; /* the escaped character */
    }
}

SceneObject *gram_text(Parser *p, const Token *kw)
{
    tok_begin_block(p, "text");
    SceneObject *o = gram_new_object(p, OBJ_UNION, kw);
    Token font_at = *tok_next(p);
    const char *name;
    if (tok_is_kw(&font_at, KW_ttf)) {
        font_at = *tok_peek(p);
        name = expr_string(p);
    } else if (tok_is_kw(&font_at, KW_internal)) {
        font_at = *tok_peek(p);
        double id = expr_float(p);
        name = internal_font_name(fabs(id) < 1e9 ? (int)id : 0);
    } else {
        tok_fail_expected(p, &font_at, "ttf or internal");
    }
    expr_comma(p);
    Token string_at = *tok_peek(p);
    const char *string = expr_string(p);
    refuse_unicode_escape(p, &string_at);
    expr_comma(p);
    double depth = expr_float(p);
    expr_comma(p);
    Vec3 offset = expr_vector(p);

    unsigned *chars = tok_temp_alloc(p, sizeof *chars * (strlen(string) + 1));
    int n = string_characters(p, string, &string_at, chars);
    char *path = find_font(p, name);
    if (!path)
        tok_fail(p, font_at.pos,
                 "cannot find the font file '%s' (looked in the current folder, the scene's folder and the "
                 "include folders)",
                 name);
    char err[512];
    TtfFont *font = ttf_open(path, p->gram->charset, err, sizeof err);
    if (!font)
        tok_fail(p, font_at.pos, "%s", err);
    TempVec children;
    tok_tvec_init(&children, sizeof(SceneObject *));
    lay_out(p, o, font, chars, n, depth, offset, &string_at, &children);
    o->u.csg.nchildren = children.n;
    o->u.csg.children = tok_scene_alloc(p, sizeof(SceneObject *) * (size_t)(children.n ? children.n : 1));
    if (children.n)
        memcpy(o->u.csg.children, children.data, sizeof(SceneObject *) * (size_t)children.n);
    o->depth = 1;
    /* Parse_TrueType: "this tiny rotation should fix cracks in text that
     * lies along an axis", before any modifier */
    Transform tiny;
    transform_identity(&tiny);
    transform_rotate(&tiny, v3(0.001, 0.001, 0.001));
    transform_compose(&o->transform, &tiny);
    gram_extent_transform(o, &tiny);
    gram_object_mods(p, o, "text");
    return o;
}
