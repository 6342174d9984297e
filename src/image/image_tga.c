/* Targa: writes what POV-Ray 3.7 writes for +FT (type 2, uncompressed) and
 * +FC (type 10, run-length encoded): 24-bit BGR, or 32-bit BGRA with
 * straight alpha under +UA, rows from the top, in POV-Ray's display encoding,
 * followed by a TGA 2.0 extension area and footer naming the software (no
 * date: the same render gives the same bytes). Reads true-colour and grey
 * Targa files (types 2, 3, 10, 11; 15/16, 24 and 32 bits; either row order)
 * as the comparison tools need them. */
#include <stdlib.h>
#include <string.h>

#include "image_codec.h"

#define TGA_HEADER 18
#define TGA_EXTENSION 495
#define TGA_FOOTER 26

/* One row of pixels (bpp bytes each) as run-length packets: a run of two or
 * more equal pixels is one repeat packet, anything else goes into raw
 * packets; both hold at most 128 pixels. */
static int write_rle_row(FILE *fp, const unsigned char *px, int width, int bpp)
{
    int x = 0;
    while (x < width) {
        int run = 1;
        while (x + run < width && run < 128 && memcmp(px + (size_t)(x + run) * (size_t)bpp, px + (size_t)x * (size_t)bpp, (size_t)bpp) == 0)
            run++;
        if (run >= 2) {
            if (putc(0x80 | (run - 1), fp) == EOF || fwrite(px + (size_t)x * (size_t)bpp, (size_t)bpp, 1, fp) != 1)
                return -1;
            x += run;
            continue;
        }
        /* raw: up to the next pair of equal pixels */
        int n = 1;
        while (x + n < width && n < 128 &&
               !(x + n + 1 < width && memcmp(px + (size_t)(x + n) * (size_t)bpp, px + (size_t)(x + n + 1) * (size_t)bpp, (size_t)bpp) == 0))
            n++;
        if (putc(n - 1, fp) == EOF || fwrite(px + (size_t)x * (size_t)bpp, (size_t)bpp, (size_t)n, fp) != (size_t)n)
            return -1;
        x += n;
    }
    return 0;
}

int image_tga_write(FILE *fp, const Image *img, const ImageWriteOptions *opt, char *err, int errlen)
{
    ImageRowEncoder enc;
    const int alpha = opt->write_alpha != 0, bpp = alpha ? 4 : 3;
    unsigned char header[TGA_HEADER] = { 0 };
    unsigned char ext[TGA_EXTENSION] = { 0 };
    unsigned char foot[TGA_FOOTER] = { 0 };
    unsigned char *row;
    long offset;

    if (img->width > 65535 || img->height > 65535) {
        image_set_error(err, errlen, "Targa files hold at most 65535x65535 pixels");
        return -1;
    }
    if (image_row_encoder_init(&enc, opt, img->width, 255, alpha) != 0) {
        image_set_error(err, errlen, "out of memory");
        return -1;
    }
    row = malloc((size_t)img->width * (size_t)bpp);
    if (row == NULL) {
        image_row_encoder_free(&enc);
        image_set_error(err, errlen, "out of memory");
        return -1;
    }
    header[2] = opt->tga_rle ? 10 : 2;
    image_put_le16(header + 12, (unsigned)img->width);
    image_put_le16(header + 14, (unsigned)img->height);
    header[16] = (unsigned char)(alpha ? 32 : 24);
    header[17] = alpha ? 0x28 : 0x20; /* top-left origin; 8 alpha bits */
    if (fwrite(header, 1, sizeof header, fp) != sizeof header)
        goto fail;
    for (int y = 0; y < img->height; y++) {
        if (image_row_encode(&enc, img->rgba + (size_t)y * (size_t)img->width * 4, err, errlen) != 0)
            goto fail;
        for (int x = 0; x < img->width; x++) {
            const unsigned *q = enc.samples + 4 * (size_t)x;
            unsigned char *o = row + (size_t)x * (size_t)bpp;
            o[0] = (unsigned char)q[2];
            o[1] = (unsigned char)q[1];
            o[2] = (unsigned char)q[0];
            if (alpha)
                o[3] = (unsigned char)q[3];
        }
        if (opt->tga_rle ? write_rle_row(fp, row, img->width, bpp) != 0
                         : fwrite(row, (size_t)bpp, (size_t)img->width, fp) != (size_t)img->width)
            goto fail;
    }
    /* TGA 2.0: the extension area (its size, the software's name) and the
     * footer that points to it. */
    offset = ftell(fp);
    if (offset < 0)
        goto fail;
    image_put_le16(ext, TGA_EXTENSION);
    snprintf((char *)ext + 426, 41, "%s", opt->software ? opt->software : "hstrace");
    ext[494] = alpha ? 3 : 0; /* attributes: straight alpha, or none */
    image_put_le32(foot, (unsigned long)offset);
    memcpy(foot + 8, "TRUEVISION-XFILE.", 18);
    if (fwrite(ext, 1, sizeof ext, fp) != sizeof ext || fwrite(foot, 1, sizeof foot, fp) != sizeof foot)
        goto fail;
    image_row_encoder_free(&enc);
    free(row);
    return 0;

fail:
    image_row_encoder_free(&enc);
    free(row);
    return -1;
}

/* Reading ------------------------------------------------------------------ */

typedef struct {
    FILE *fp;
    int bpp;         /* bytes per pixel: 1 (grey), 2, 3 or 4 */
    int rle;
    int left;        /* pixels left in the current packet */
    int repeat;      /* the packet repeats one pixel */
    unsigned char px[4];
} TgaStream;

/* The next pixel's bytes, through the packets of an RLE file. */
static int next_pixel(TgaStream *s, unsigned char out[4])
{
    if (!s->rle)
        return fread(out, (size_t)s->bpp, 1, s->fp) == 1 ? 0 : -1;
    if (s->left == 0) {
        int c = getc(s->fp);
        if (c == EOF)
            return -1;
        s->left = (c & 0x7f) + 1;
        s->repeat = (c & 0x80) != 0;
        if (s->repeat && fread(s->px, (size_t)s->bpp, 1, s->fp) != 1)
            return -1;
    }
    s->left--;
    if (s->repeat)
        memcpy(out, s->px, (size_t)s->bpp);
    else if (fread(out, (size_t)s->bpp, 1, s->fp) != 1)
        return -1;
    return 0;
}

int image_tga_read(FILE *fp, Image *img, double display_gamma, ImageReadExtras *ex, char *err, int errlen)
{
    unsigned char h[TGA_HEADER];
    ImageTransfer t;
    TgaStream s = { fp, 0, 0, 0, 0, { 0 } };
    float *lut, *lut5;
    int w, ht, type, depth, desc, top, alpha_bits;

    if (fread(h, 1, sizeof h, fp) != sizeof h) {
        image_set_error(err, errlen, "not a Targa file (header truncated)");
        return -1;
    }
    type = h[2];
    w = h[12] | h[13] << 8;
    ht = h[14] | h[15] << 8;
    depth = h[16];
    desc = h[17];
    alpha_bits = desc & 0x0f;
    if (h[1] != 0 || (type != 2 && type != 3 && type != 10 && type != 11)) {
        image_set_error(err, errlen, "unsupported Targa file (type %d%s; true-colour and grey only)", type,
                        h[1] ? " with a colour map" : "");
        return -1;
    }
    if ((type == 3 || type == 11) ? depth != 8 : depth != 15 && depth != 16 && depth != 24 && depth != 32) {
        image_set_error(err, errlen, "unsupported Targa pixel depth %d", depth);
        return -1;
    }
    if (ex != NULL)
        ex->grey = type == 3 || type == 11;
    if (w == 0 || ht == 0 || (long)w * ht > IMAGE_MAX_PIXELS) {
        image_set_error(err, errlen, "unsupported Targa size %dx%d", w, ht);
        return -1;
    }
    if (desc & 0x10) {
        image_set_error(err, errlen, "unsupported Targa file (rows stored right to left)");
        return -1;
    }
    top = (desc & 0x20) != 0;
    s.bpp = (depth + 7) / 8;
    s.rle = type >= 9;
    /* the image id, skipped */
    for (int i = 0; i < h[0]; i++)
        if (getc(fp) == EOF) {
            image_set_error(err, errlen, "Targa file is truncated");
            return -1;
        }
    if (!s.rle) {
        /* The pixels must be there before their memory is asked for. */
        long here = ftell(fp);
        if (here >= 0 && fseek(fp, 0, SEEK_END) == 0) {
            long end = ftell(fp);
            double need = (double)w * ht * s.bpp;
            if (fseek(fp, here, SEEK_SET) != 0 || (end >= here && (double)(end - here) < need)) {
                image_set_error(err, errlen, "Targa pixel data is truncated");
                return -1;
            }
        }
    }
    image_transfer_init(&t, display_gamma);
    lut = image_transfer_decode_table(&t, 255);
    lut5 = image_transfer_decode_table(&t, 31);
    /* Rows arrive in the file's order and the image grows with them, so a
     * short RLE file claiming 65535x4096 pixels costs what it holds. */
    int cap = ht < 64 ? ht : 64;
    if (lut == NULL || lut5 == NULL || image_alloc(img, w, cap) != 0) {
        free(lut);
        free(lut5);
        image_set_error(err, errlen, "out of memory for a %dx%d image", w, ht);
        return -1;
    }
    for (int y = 0; y < ht; y++) {
        if (image_grow_rows(img, y, ht, &cap)) {
            free(lut);
            free(lut5);
            image_set_error(err, errlen, "out of memory for a %dx%d image", w, ht);
            return -1;
        }
        float *px = img->rgba + (size_t)y * (size_t)w * 4;
        for (int x = 0; x < w; x++, px += 4) {
            unsigned char b[4] = { 0, 0, 0, 255 };
            float a = 1.0f;
            if (next_pixel(&s, b) != 0) {
                free(lut);
                free(lut5);
                image_set_error(err, errlen, "Targa pixel data is truncated");
                return -1;
            }
            if (s.bpp == 1) {
                px[0] = px[1] = px[2] = lut[b[0]];
            } else if (s.bpp == 2) {
                unsigned v = (unsigned)(b[0] | b[1] << 8);
                px[0] = lut5[v >> 10 & 31];
                px[1] = lut5[v >> 5 & 31];
                px[2] = lut5[v & 31];
                if (depth == 16 && alpha_bits == 1)
                    a = (v & 0x8000) ? 1.0f : 0.0f;
            } else {
                px[0] = lut[b[2]];
                px[1] = lut[b[1]];
                px[2] = lut[b[0]];
                if (s.bpp == 4 && alpha_bits == 8)
                    a = (float)b[3] / 255.0f;
            }
            /* Targa alpha is straight; the image holds premultiplied
             * unless the caller keeps it straight. */
            if (ex == NULL || !ex->keep_straight) {
                px[0] *= a;
                px[1] *= a;
                px[2] *= a;
            }
            px[3] = a;
        }
    }
    free(lut);
    free(lut5);
    img->height = ht;
    if (!top) /* bottom-up rows: turn the image over */
        for (int y = 0; y < ht / 2; y++) {
            float *a = img->rgba + (size_t)y * (size_t)w * 4, *b = img->rgba + (size_t)(ht - 1 - y) * (size_t)w * 4;
            for (size_t i = 0; i < (size_t)w * 4; i++) {
                float tmp = a[i];
                a[i] = b[i];
                b[i] = tmp;
            }
        }
    return 0;
}
