/* height_field { [type] "file" [gamma G] [premultiplied B] [water_level W]
 * [smooth] modifiers }, as POV-Ray 3.7's Parse_HField reads it: the picture's
 * samples become heights in 0..65535 by POV-Ray's image_height_at, kept with
 * z = 0 at the picture's bottom row (Compute_HField). The engine scales them
 * to the unit square (flatten.c, src/geometry/height_field.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "grammar.h"

/* POV-Ray's greyscale weights (colour.h's RED2GRAY ...), which
 * image_height_at applies to pictures of more than 8 bits a channel. */
#define RED_TO_GREY 0.297
#define GREEN_TO_GREY 0.589
#define BLUE_TO_GREY 0.114

/* One sample as its file stores it, from the value the loader decoded with
 * gamma 1 (the stored value over the largest one, to float precision). */
static unsigned stored_sample(float decoded, unsigned max)
{
    double v = floor((double)decoded * max + 0.5);
    return v < 0.0 ? 0u : v > max ? max : (unsigned)v;
}

/* The height of a pixel, as POV-Ray 3.7's image_height_at computes it in
 * its own precision: a palette picture's index times 256; a grey one's
 * value (in float) times 65535; a colour one of more than 8 bits its
 * greyscale times 65535; an 8-bit colour one red as the high byte and green
 * as the low. Each truncated to POV-Ray's unsigned short. */
static unsigned short pixel_height(const LoadedPicture *pic, size_t i)
{
    if (pic->index)
        return (unsigned short)(pic->index[i] * 256u);
    const float *c = &pic->rgba[4 * i];
    const unsigned max = pic->sample_max ? pic->sample_max : 255u;
    const float fmax = (float)max;
    if (pic->grey) {
        float g = (float)stored_sample(c[0], max) / fmax;
        return (unsigned short)(g * 65535.0f);
    }
    float r = (float)stored_sample(c[0], max) / fmax;
    float g = (float)stored_sample(c[1], max) / fmax;
    float b = (float)stored_sample(c[2], max) / fmax;
    if (max > 255u)
        return (unsigned short)((float)(RED_TO_GREY * r + GREEN_TO_GREY * g + BLUE_TO_GREY * b) * 65535.0f);
    return (unsigned short)((r * 256.0 + g) * 255.0);
}

/* The picture after `height_field {`: its heights into o. */
static void read_heights(Parser *p, SceneObject *o)
{
    Token *t = tok_next(p);
    int kw = t->type == TK_WORD ? t->kw : -1;
    switch (kw) {
    case KW_png: case KW_tga: case KW_ppm: case KW_pgm: case KW_bmp: case KW_jpeg:
        break; /* the type: hstrace tells files apart by their first bytes */
    case KW_function: /* height_field { function W, H { ... } }: hstrace has no user functions */
    case KW_gif: case KW_iff: case KW_tiff: case KW_sys: case KW_pot: case KW_exr: case KW_hdr:
        tok_unsupported(p, t);
    default:
        tok_unget(p);
    }
    Token name_at = *tok_peek(p);
    char *name = expr_string(p);
    /* `gamma` and `premultiplied` do not change a height field: POV-Ray
     * reads its picture with no gamma correction, and ignores alpha */
    for (;;) {
        Token *o2 = tok_next(p);
        if (tok_is_kw(o2, KW_gamma)) {
            if (tok_is_kw(tok_peek(p), KW_srgb))
                (void)tok_next(p);
            else
                (void)expr_float(p);
        } else if (tok_is_kw(o2, KW_premultiplied)) {
            (void)expr_float(p);
        } else {
            tok_unget(p);
            break;
        }
    }
    if (!p->opts->load_image) /* a parse without the image layer (the parser's own tests) */
        tok_fail(p, name_at.pos, "height_field: pictures cannot be read here");
    char *path = gram_find_image_file(p, name);
    if (!path)
        tok_fail(p, name_at.pos, "cannot find the image '%s' (looked in the current folder, the scene's folder and the "
                   "include folders)", name);
    LoadedPicture pic;
    char why[256] = "";
    size_t left = tok_limits_memory_left(p); /* 0 would mean no limit: at least a byte */
    /* gamma 1: the values as stored */
    if (p->opts->load_image(p->opts->load_image_user, path, 1.0, IMAGE_GAMMA_FILE_DEFAULT, 0, left ? left : 1, &pic,
                            why, (int)sizeof why)) {
        free(pic.rgba);
        free(pic.index);
        tok_fail(p, name_at.pos, "height_field: %s", why[0] ? why : "unreadable image");
    }
    if (pic.width < 2 || pic.height < 2) {
        free(pic.rgba);
        free(pic.index);
        tok_fail(p, name_at.pos, "height_field: the picture '%s' is %dx%d pixels; a height field needs 2x2 at least",
                 name, pic.width, pic.height);
    }
    const size_t n = (size_t)pic.width * (size_t)pic.height;
    unsigned short *h = arena_alloc(p->arena, n * sizeof *h);
    if (!h) {
        free(pic.rgba);
        free(pic.index);
        tok_fail_memory(p, name_at.pos);
    }
    /* POV-Ray's map row z is the picture's row height - 1 - z */
    for (int z = 0; z < pic.height; z++)
        for (int x = 0; x < pic.width; x++)
            h[(size_t)z * (size_t)pic.width + (size_t)x] =
                pixel_height(&pic, (size_t)(pic.height - 1 - z) * (size_t)pic.width + (size_t)x);
    free(pic.rgba);
    free(pic.index);
    o->u.height_field.nx = pic.width;
    o->u.height_field.nz = pic.height;
    o->u.height_field.heights = h;
}

SceneObject *gram_height_field(Parser *p, const Token *kw)
{
    tok_begin_block(p, "height_field");
    SceneObject *o = gram_new_object(p, OBJ_HEIGHT_FIELD, kw);
    read_heights(p, o);
    for (;;) {
        Token *t = tok_next(p);
        if (tok_is_kw(t, KW_water_level)) {
            double level = expr_float(p);
            if (p->version_given && p->version < 2.0) /* POV-Ray 1's levels were in 0..256 */
                level /= 256.0;
            o->u.height_field.water = 65536.0 * level;
        } else if (tok_is_kw(t, KW_smooth)) {
            o->u.height_field.smooth = 1;
        } else {
            tok_unget(p);
            break;
        }
    }
    gram_object_mods(p, o, "height_field");
    return o;
}
