/* BMP: writes what POV-Ray 3.7 writes for +FB, byte for byte: a 40-byte
 * BITMAPINFOHEADER, uncompressed (BI_RGB), rows from the bottom, 24-bit BGR
 * with rows padded to 4 bytes, or 32-bit BGRA with straight alpha under +UA,
 * in POV-Ray's display encoding. Reads uncompressed BMP files of 8 (with a
 * palette), 24 and 32 bits, either row order, as the comparison tools need
 * them. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "image_codec.h"

#define BMP_FILE_HEADER 14
#define BMP_INFO_HEADER 40

static unsigned long get32(const unsigned char *p)
{
    return (unsigned long)p[0] | (unsigned long)p[1] << 8 | (unsigned long)p[2] << 16 | (unsigned long)p[3] << 24;
}

int image_bmp_write(FILE *fp, const Image *img, const ImageWriteOptions *opt, char *err, int errlen)
{
    ImageRowEncoder enc;
    const int alpha = opt->write_alpha != 0, bpp = alpha ? 4 : 3;
    const size_t stride = ((size_t)img->width * (size_t)(bpp * 8) + 31) / 32 * 4;
    const unsigned long long size = (unsigned long long)stride * (unsigned long long)img->height;
    unsigned char h[BMP_FILE_HEADER + BMP_INFO_HEADER] = { 0 };
    unsigned char *row;

    if (size + sizeof h > 0xffffffffull) {
        image_set_error(err, errlen, "BMP files hold at most 4 GiB of pixels");
        return -1;
    }
    if (image_row_encoder_init(&enc, opt, img->width, 255, alpha) != 0) {
        image_set_error(err, errlen, "out of memory");
        return -1;
    }
    row = calloc(stride, 1);
    if (row == NULL) {
        image_row_encoder_free(&enc);
        image_set_error(err, errlen, "out of memory");
        return -1;
    }
    h[0] = 'B';
    h[1] = 'M';
    image_put_le32(h + 2, (unsigned long)(size + sizeof h));
    image_put_le32(h + 10, sizeof h);
    image_put_le32(h + 14, BMP_INFO_HEADER);
    image_put_le32(h + 18, (unsigned long)img->width);
    image_put_le32(h + 22, (unsigned long)img->height);
    image_put_le16(h + 26, 1);
    image_put_le16(h + 28, (unsigned)(bpp * 8));
    image_put_le32(h + 34, (unsigned long)size); /* BI_RGB (0) at 30; no resolution or palette */
    if (fwrite(h, 1, sizeof h, fp) != sizeof h)
        goto fail;
    for (int y = img->height - 1; y >= 0; y--) {
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
        if (fwrite(row, 1, stride, fp) != stride)
            goto fail;
    }
    image_row_encoder_free(&enc);
    free(row);
    return 0;

fail:
    image_row_encoder_free(&enc);
    free(row);
    return -1;
}

int image_bmp_read(FILE *fp, Image *img, double display_gamma, ImageReadExtras *ex, char *err, int errlen)
{
    unsigned char h[BMP_FILE_HEADER + BMP_INFO_HEADER];
    unsigned char palette[256][4];
    ImageTransfer t;
    float *lut;
    unsigned char *row;
    long w, ht;
    int bits, top, ncolours = 0, any_alpha = 0;
    unsigned long data, info, compression;

    if (fread(h, 1, sizeof h, fp) != sizeof h || h[0] != 'B' || h[1] != 'M') {
        image_set_error(err, errlen, "not a BMP file (bad signature or truncated header)");
        return -1;
    }
    data = get32(h + 10);
    info = get32(h + 14);
    if (info < BMP_INFO_HEADER || info > 1024) {
        image_set_error(err, errlen, "unsupported BMP header of %lu bytes", info);
        return -1;
    }
    w = (long)get32(h + 18);
    ht = (long)(int32_t)get32(h + 22);
    bits = h[28] | h[29] << 8;
    compression = get32(h + 30);
    top = ht < 0; /* a negative height: rows from the top */
    if (top)
        ht = -ht;
    if (w <= 0 || w > IMAGE_MAX_DIM || ht <= 0 || ht > IMAGE_MAX_DIM || w * ht > IMAGE_MAX_PIXELS) {
        image_set_error(err, errlen, "unsupported BMP size %ldx%ld", w, ht);
        return -1;
    }
    if ((bits != 8 && bits != 24 && bits != 32) || compression != 0) {
        image_set_error(err, errlen, "unsupported BMP file (%d bits, compression %lu; uncompressed 8, 24 and 32 bits only)",
                        bits, compression);
        return -1;
    }
    if (fseek(fp, (long)(BMP_FILE_HEADER + info), SEEK_SET) != 0) {
        image_set_error(err, errlen, "BMP file is truncated");
        return -1;
    }
    if (bits == 8) {
        unsigned long used = get32(h + 46);
        ncolours = used == 0 || used > 256 ? 256 : (int)used;
        if (fread(palette, 4, (size_t)ncolours, fp) != (size_t)ncolours) {
            image_set_error(err, errlen, "BMP palette is truncated");
            return -1;
        }
    }
    const size_t stride = ((size_t)w * (size_t)bits + 31) / 32 * 4;
    /* The pixels must be there before their memory is asked for. */
    if (fseek(fp, 0, SEEK_END) != 0) {
        image_set_error(err, errlen, "BMP file cannot be read");
        return -1;
    }
    long end = ftell(fp);
    if (end < 0 || (double)end < (double)data + (double)stride * (double)ht || fseek(fp, (long)data, SEEK_SET) != 0) {
        image_set_error(err, errlen, "BMP pixel data is truncated (%ldx%ld pixels need %.0f bytes)", w, ht,
                        (double)stride * (double)ht);
        return -1;
    }
    image_transfer_init(&t, display_gamma);
    lut = image_transfer_decode_table(&t, 255);
    row = malloc(stride);
    /* 8 bits: kept indexed for whoever asks (POV-Ray 3.7 keeps BMP palettes so) */
    unsigned char *index = bits == 8 && ex != NULL ? malloc((size_t)w * (size_t)ht) : NULL;
    if (lut == NULL || row == NULL || (bits == 8 && ex != NULL && index == NULL) ||
        image_alloc(img, (int)w, (int)ht) != 0) {
        free(lut);
        free(row);
        free(index);
        image_set_error(err, errlen, "out of memory for a %ldx%ld image", w, ht);
        return -1;
    }
    for (long r = 0; r < ht; r++) {
        if (fread(row, 1, stride, fp) != stride) {
            free(lut);
            free(row);
            free(index);
            image_set_error(err, errlen, "BMP pixel data is truncated");
            return -1;
        }
        long y = top ? r : ht - 1 - r;
        float *px = img->rgba + (size_t)y * (size_t)w * 4;
        for (long x = 0; x < w; x++, px += 4) {
            int entry = bits == 8 && row[x] < ncolours ? row[x] : 0;
            if (index != NULL)
                index[(size_t)y * (size_t)w + (size_t)x] = (unsigned char)entry;
            const unsigned char *b = bits == 8 ? palette[entry] : row + x * (bits / 8);
            px[0] = lut[b[2]];
            px[1] = lut[b[1]];
            px[2] = lut[b[0]];
            /* 32 bits: the fourth byte is alpha where the writer put one
             * (POV-Ray's +UA does); decided below for the whole image. */
            px[3] = bits == 32 ? (float)b[3] / 255.0f : 1.0f;
            if (bits == 32 && b[3] != 0)
                any_alpha = 1;
        }
    }
    if (index != NULL) {
        ex->ncolours = ncolours;
        for (int i = 0; i < ncolours; i++) {
            ex->palette[i][0] = lut[palette[i][2]];
            ex->palette[i][1] = lut[palette[i][1]];
            ex->palette[i][2] = lut[palette[i][0]];
            ex->palette[i][3] = 1.0f;
        }
        ex->index = index;
    }
    free(lut);
    free(row);
    /* A 32-bit file whose fourth bytes are all zero carries no alpha (BI_RGB
     * calls the byte unused); otherwise alpha is straight, stored
     * premultiplied unless the caller keeps it straight. */
    int keep = ex != NULL && ex->keep_straight;
    for (size_t i = 0; i < (size_t)w * (size_t)ht; i++) {
        float *px = img->rgba + 4 * i;
        if (bits == 32 && !any_alpha)
            px[3] = 1.0f;
        if (!keep) {
            px[0] *= px[3];
            px[1] *= px[3];
            px[2] *= px[3];
        }
    }
    return 0;
}
