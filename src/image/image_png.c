/* PNG through libpng: 8 or 16 bits, RGB or RGBA, encoded like POV-Ray 3.7
 * (see image_codec.h) with gAMA, sRGB (for the sRGB curve) and sBIT chunks,
 * or through an OpenColorIO display transform (sBIT only). */
#include <png.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

#include "image_codec.h"

typedef struct {
    char *err;
    int errlen;
} PngErr;

static void on_png_error(png_structp png, png_const_charp msg)
{
    PngErr *pe = png_get_error_ptr(png);
    if (pe != NULL)
        image_set_error(pe->err, pe->errlen, "%s", msg);
    png_longjmp(png, 1);
}

static void on_png_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg;
}

/* Everything libpng does for a write, outside the function that calls
 * setjmp so that no local of that one changes after it. */
static void png_write_body(png_structp png, png_infop info, const Image *img, ImageRowEncoder *enc, int depth,
                           unsigned char *row)
{
    const int alpha = enc->with_alpha;
    const int nch = alpha ? 4 : 3;
    png_color_8 sbit;
    png_text text;

    png_set_IHDR(png, info, (png_uint_32)img->width, (png_uint_32)img->height, depth,
                 alpha ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    memset(&sbit, 0, sizeof sbit);
    sbit.red = sbit.green = sbit.blue = (png_byte)depth;
    if (alpha)
        sbit.alpha = (png_byte)depth;
    png_set_sBIT(png, info, &sbit);
    /* As POV-Ray: gAMA 1/2.2 (45455) plus sRGB (perceptual) for the sRGB
     * curve, gAMA 1/gamma for a power law. A display transform's curve is
     * the config's business: no chunk claims one. */
    if (enc->display == NULL) {
        png_set_gAMA(png, info, enc->transfer.gama);
        if (enc->transfer.srgb)
            png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    }
    memset(&text, 0, sizeof text);
    text.compression = PNG_TEXT_COMPRESSION_NONE;
    text.key = (png_charp) "Software";
    text.text = (png_charp) "hstrace";
    text.text_length = strlen(text.text);
    png_set_text(png, info, &text, 1);
    png_write_info(png, info);

    for (int y = 0; y < img->height; y++) {
        const unsigned *q = enc->samples;
        unsigned char *o = row;
        char why[256];
        if (image_row_encode(enc, img->rgba + (size_t)y * (size_t)img->width * 4, why, (int)sizeof why) != 0)
            png_error(png, why);
        for (int x = 0; x < img->width; x++, q += 4) {
            for (int c = 0; c < nch; c++) {
                if (depth == 16) {
                    *o++ = (unsigned char)(q[c] >> 8);
                    *o++ = (unsigned char)(q[c] & 0xff);
                } else {
                    *o++ = (unsigned char)q[c];
                }
            }
        }
        png_write_row(png, row);
    }
    png_write_end(png, info);
}

int image_png_write(FILE *fp, const Image *img, const ImageWriteOptions *opt, char *err, int errlen)
{
    PngErr pe = { err, errlen };
    png_structp png;
    png_infop info;
    ImageRowEncoder enc;
    const int depth = opt->png_16bit ? 16 : 8;
    const int alpha = opt->write_alpha != 0;
    unsigned char *row;

    if (image_row_encoder_init(&enc, opt, img->width, depth == 16 ? 65535u : 255u, alpha) != 0) {
        image_set_error(err, errlen, "out of memory");
        return -1;
    }
    row = malloc((size_t)img->width * (size_t)(alpha ? 4 : 3) * (size_t)(depth / 8));
    if (row == NULL) {
        image_row_encoder_free(&enc);
        image_set_error(err, errlen, "out of memory");
        return -1;
    }
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &pe, on_png_error, on_png_warning);
    info = png ? png_create_info_struct(png) : NULL;
    if (info == NULL) {
        png_destroy_write_struct(&png, NULL);
        image_row_encoder_free(&enc);
        free(row);
        image_set_error(err, errlen, "out of memory");
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        image_row_encoder_free(&enc);
        free(row);
        return -1;
    }
    png_init_io(png, fp);
    png_write_body(png, info, img, &enc, depth, row);
    png_destroy_write_struct(&png, &info);
    image_row_encoder_free(&enc);
    free(row);
    return 0;
}

/* What libpng reads: the first chunk's start (read ahead, so that the size
 * its IHDR declares is checked before libpng acts on it), then the file. A
 * short read is a truncated file, said so (libpng's own reader says "Read
 * Error"). */
typedef struct {
    FILE *fp;
    unsigned char head[24]; /* length, "IHDR", width, height, bit depth, ... */
    size_t head_len, head_pos;
} PngSource;

static void png_source_read(png_structp png, png_bytep data, size_t n)
{
    PngSource *src = png_get_io_ptr(png);
    size_t k = 0;
    while (k < n && src->head_pos < src->head_len)
        data[k++] = src->head[src->head_pos++];
    if (k < n && fread(data + k, 1, n - k, src->fp) != n - k)
        png_error(png, ferror(src->fp) ? "read error" : "PNG data is truncated (the file ends early)");
}

static unsigned long png_be32(const unsigned char *p)
{
    return (unsigned long)p[0] << 24 | (unsigned long)p[1] << 16 | (unsigned long)p[2] << 8 | p[3];
}

/* Working state of a read, kept behind one pointer so that nothing the error
 * path needs lives in a local changed after setjmp. */
typedef struct {
    png_structp png;
    png_infop info;
    unsigned char *row;
    float *lut;
    PngSource src;
    long file_bytes; /* what the file holds after its signature; -1: unknown */
    size_t raw_rowbytes; /* a row as stored (before expansion to RGB) */
    char msg[128];
    /* A palette picture read indexed (ImageReadExtras): its entries as
     * stored, and the indices, grown with the rows as the image is. */
    int ncolours;
    png_color plte[256];
    unsigned char trns[256];
    unsigned char *index;
} PngRead;

int image_png_read(FILE *fp, Image *img, double display_gamma, ImageReadExtras *ex, char *err, int errlen)
{
    PngErr pe = { err, errlen };
    PngRead *st = calloc(1, sizeof *st);
    ImageTransfer t;
    png_uint_32 w, h;
    int depth, ctype, nch, wide, passes;
    unsigned max;
    unsigned char sig[8];

    if (st == NULL) {
        image_set_error(err, errlen, "out of memory");
        return -1;
    }
    if (fread(sig, 1, 8, fp) != 8 || png_sig_cmp(sig, 0, 8) != 0) {
        free(st);
        image_set_error(err, errlen, "not a PNG file (bad signature or truncated)");
        return -1;
    }
    /* The size in the header, refused before anything is allocated for it:
     * an empty image (which libpng cannot even write) or one past
     * IMAGE_MAX_DIM a side or IMAGE_MAX_PIXELS in all. */
    st->src.fp = fp;
    st->file_bytes = -1;
    {
        long here = ftell(fp);
        if (here >= 0 && fseek(fp, 0, SEEK_END) == 0) {
            st->file_bytes = ftell(fp) - here;
            if (fseek(fp, here, SEEK_SET) != 0)
                st->file_bytes = -1;
        }
    }
    st->src.head_len = fread(st->src.head, 1, sizeof st->src.head, fp);
    if (st->src.head_len == sizeof st->src.head && memcmp(st->src.head + 4, "IHDR", 4) == 0) {
        unsigned long hw = png_be32(st->src.head + 8), hh = png_be32(st->src.head + 12);
        if (hw == 0 || hh == 0 || hw > IMAGE_MAX_DIM || hh > IMAGE_MAX_DIM ||
            (unsigned long long)hw * hh > (unsigned long long)IMAGE_MAX_PIXELS) {
            free(st);
            image_set_error(err, errlen, "unsupported PNG size %lux%lu", hw, hh);
            return -1;
        }
    }
    st->png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &pe, on_png_error, on_png_warning);
    st->info = st->png ? png_create_info_struct(st->png) : NULL;
    if (st->info == NULL) {
        png_destroy_read_struct(&st->png, NULL, NULL);
        free(st);
        image_set_error(err, errlen, "out of memory");
        return -1;
    }
    if (setjmp(png_jmpbuf(st->png))) {
        png_destroy_read_struct(&st->png, &st->info, NULL);
        free(st->row);
        free(st->lut);
        free(st->index);
        free(st);
        image_free(img);
        if (err != NULL && errlen > 0 && err[0] == '\0')
            image_set_error(err, errlen, "corrupt PNG file");
        return -1;
    }
    png_set_user_limits(st->png, IMAGE_MAX_DIM, IMAGE_MAX_DIM);
    /* A corrupt length must not make libpng allocate gigabytes for an
     * ancillary chunk (zTXt, iCCP, ...). */
    png_set_chunk_malloc_max(st->png, 16u << 20);
    png_set_chunk_cache_max(st->png, 1000);
    {
        /* Metadata chunks are of no use here: skip them unread (libpng
         * would otherwise buffer whatever length a corrupt one claims). */
        static const png_byte skip[] = "tEXt\0zTXt\0iTXt\0iCCP\0sPLT\0eXIf\0tIME\0";
        png_set_keep_unknown_chunks(st->png, PNG_HANDLE_CHUNK_NEVER, NULL, 0);
        png_set_keep_unknown_chunks(st->png, PNG_HANDLE_CHUNK_NEVER, skip, (int)(sizeof skip / 5));
    }
    png_set_read_fn(st->png, &st->src, png_source_read);
    png_set_sig_bytes(st->png, 8);
    png_read_info(st->png, st->info);
    st->raw_rowbytes = png_get_rowbytes(st->png, st->info);
    w = png_get_image_width(st->png, st->info);
    h = png_get_image_height(st->png, st->info);
    if ((unsigned long)w * h > (unsigned long)IMAGE_MAX_PIXELS)
        png_error(st->png, "image too large");

    if (ex != NULL) { /* as stored, before the expansion below */
        int stored_type = png_get_color_type(st->png, st->info);
        ex->grey = stored_type == PNG_COLOR_TYPE_GRAY || stored_type == PNG_COLOR_TYPE_GRAY_ALPHA;
        ex->sample_max = png_get_bit_depth(st->png, st->info) == 16 ? 65535u : 255u;
    }
    if (ex != NULL && png_get_color_type(st->png, st->info) == PNG_COLOR_TYPE_PALETTE) {
        /* Kept indexed, as POV-Ray 3.7 keeps palette PNGs: one byte per
         * pixel, each the entry it shows, the entries' colours below. */
        png_colorp plte = NULL;
        int n = 0;
        if (!png_get_PLTE(st->png, st->info, &plte, &n) || n < 1 || n > 256)
            png_error(st->png, "palette PNG without a valid PLTE chunk");
        st->ncolours = n;
        memcpy(st->plte, plte, sizeof *plte * (size_t)n);
        memset(st->trns, 255, sizeof st->trns);
        png_bytep trns = NULL;
        int ntrns = 0;
        if (png_get_valid(st->png, st->info, PNG_INFO_tRNS) && png_get_tRNS(st->png, st->info, &trns, &ntrns, NULL) &&
            trns != NULL)
            memcpy(st->trns, trns, (size_t)(ntrns < n ? ntrns : n));
        png_set_packing(st->png);
    } else {
        /* Everything to 8 or 16-bit RGB or RGBA, 16-bit samples big-endian. */
        png_set_expand(st->png);
        png_set_gray_to_rgb(st->png);
    }
    passes = png_set_interlace_handling(st->png);
    png_read_update_info(st->png, st->info);
    depth = png_get_bit_depth(st->png, st->info);
    ctype = png_get_color_type(st->png, st->info);
    nch = png_get_channels(st->png, st->info);
    if (st->ncolours > 0 ? depth != 8 || nch != 1
                         : (depth != 8 && depth != 16) || (nch != 3 && nch != 4) || !(ctype & PNG_COLOR_MASK_COLOR))
        png_error(st->png, "unsupported PNG layout");
    wide = depth == 16;
    max = wide ? 65535u : 255u;

    {
        /* as POV-Ray 3.7 without `gamma`: an sRGB chunk, else a gAMA chunk
         * (its encoding gamma), else sRGB */
        double file_gamma = 0.0, decode = display_gamma;
        if (decode == IMAGE_GAMMA_AS_POVRAY) {
            if (png_get_valid(st->png, st->info, PNG_INFO_sRGB))
                decode = 0.0;
            else if (png_get_valid(st->png, st->info, PNG_INFO_gAMA) && png_get_gAMA(st->png, st->info, &file_gamma) &&
                     file_gamma > 0.0)
                decode = 1.0 / file_gamma;
            else /* POV-Ray's defaultGamma (3.6 scenes: the working gamma), else sRGB */
                decode = ex != NULL && ex->untagged_given ? ex->untagged_gamma : 0.0;
        }
        image_transfer_init(&t, decode);
    }
    st->lut = image_transfer_decode_table(&t, max);
    /* The image grows with the rows decoded (a non-interlaced file): a few
     * corrupt bytes may claim 2^28 pixels, and memory follows the data the
     * file holds, not its header. Interlaced files need all rows at once,
     * reserved before their data is read: first the file must be able to
     * hold them. Deflate makes at most 1032 bytes of one (258 per 2 bits),
     * so a file of a few hundred bytes cannot inflate to the 805 MB of
     * rows, as stored, of a 16384x16384 RGB header (it reserved 5 GB). */
    if (passes > 1 && st->file_bytes >= 0 &&
        (double)st->raw_rowbytes * (double)h > 1032.0 * (double)st->file_bytes + 65536.0) {
        snprintf(st->msg, sizeof st->msg, "interlaced PNG data of %ld bytes is too small for %lux%lu pixels",
                 st->file_bytes, (unsigned long)w, (unsigned long)h);
        png_error(st->png, st->msg);
    }
    int rows_cap = passes > 1 || h < 64 ? (int)h : 64;
    if (st->lut == NULL || image_alloc(img, (int)w, rows_cap) != 0)
        png_error(st->png, "out of memory");
    st->row = malloc(png_get_rowbytes(st->png, st->info));
    if (st->row == NULL)
        png_error(st->png, "out of memory");

    {
        /* Interlaced images: libpng fills each row over several passes, so
         * every row needs its own buffer until the last pass. */
        if (passes > 1) {
            size_t rb = png_get_rowbytes(st->png, st->info);
            unsigned char *all = malloc(rb * h);
            if (all == NULL)
                png_error(st->png, "out of memory");
            free(st->row);
            st->row = all;
            for (int p = 0; p < passes; p++)
                for (png_uint_32 y = 0; y < h; y++)
                    png_read_row(st->png, all + rb * y, NULL);
        }
        int index_rows = 0;
        for (png_uint_32 y = 0; y < h; y++) {
            const unsigned char *in;
            if (image_grow_rows(img, (int)y, (int)h, &rows_cap))
                png_error(st->png, "out of memory");
            if (st->ncolours > 0 && (int)y >= index_rows) { /* the indices grow as the rows do */
                unsigned char *more = realloc(st->index, (size_t)rows_cap * w);
                if (more == NULL)
                    png_error(st->png, "out of memory");
                st->index = more;
                index_rows = rows_cap;
            }
            float *px = img->rgba + (size_t)y * w * 4;
            if (passes > 1) {
                in = st->row + png_get_rowbytes(st->png, st->info) * y;
            } else {
                png_read_row(st->png, st->row, NULL);
                in = st->row;
            }
            for (png_uint_32 x = 0; x < w; x++, px += 4) {
                unsigned v[4] = { 0, 0, 0, max };
                if (st->ncolours > 0) {
                    /* an index past the palette (a damaged file) shows entry 0 */
                    unsigned i = in[x] < st->ncolours ? in[x] : 0;
                    st->index[(size_t)y * w + x] = (unsigned char)i;
                    v[0] = st->plte[i].red;
                    v[1] = st->plte[i].green;
                    v[2] = st->plte[i].blue;
                    v[3] = st->trns[i];
                } else {
                    for (int c = 0; c < nch; c++) {
                        v[c] = wide ? (unsigned)(in[0] << 8 | in[1]) : in[0];
                        in += wide ? 2 : 1;
                    }
                }
                /* PNG alpha is straight; the image holds premultiplied
                 * unless the caller keeps it straight. */
                float a = (float)v[3] / (float)max, k = ex != NULL && ex->keep_straight ? 1.0f : a;
                px[0] = st->lut[v[0]] * k;
                px[1] = st->lut[v[1]] * k;
                px[2] = st->lut[v[2]] * k;
                px[3] = a;
            }
        }
    }
    img->height = (int)h;
    png_read_end(st->png, NULL);
    png_destroy_read_struct(&st->png, &st->info, NULL);
    if (ex != NULL && st->ncolours > 0) {
        ex->ncolours = st->ncolours;
        for (int i = 0; i < st->ncolours; i++) {
            ex->palette[i][0] = st->lut[st->plte[i].red];
            ex->palette[i][1] = st->lut[st->plte[i].green];
            ex->palette[i][2] = st->lut[st->plte[i].blue];
            ex->palette[i][3] = (float)st->trns[i] / 255.0f;
        }
        ex->index = st->index;
        st->index = NULL;
    }
    free(st->index);
    free(st->row);
    free(st->lut);
    free(st);
    return 0;
}
