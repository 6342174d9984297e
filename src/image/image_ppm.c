/* PPM: writes binary P6 with maxval 255 in the display encoding (POV-Ray's
 * or an OpenColorIO display transform's); reads P6
 * and P3 (and the grey P5/P2) with maxval up to 65535. */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>

#include "image_codec.h"

int image_ppm_write(FILE *fp, const Image *img, const ImageWriteOptions *opt, char *err, int errlen)
{
    ImageRowEncoder enc;
    unsigned char *row;
    size_t rowbytes = (size_t)img->width * 3;

    if (image_row_encoder_init(&enc, opt, img->width, 255, 0) != 0) {
        image_set_error(err, errlen, "out of memory");
        return -1;
    }
    row = malloc(rowbytes);
    if (row == NULL) {
        image_row_encoder_free(&enc);
        image_set_error(err, errlen, "out of memory");
        return -1;
    }
    if (fprintf(fp, "P6\n%d %d\n255\n", img->width, img->height) < 0)
        goto fail;
    for (int y = 0; y < img->height; y++) {
        if (image_row_encode(&enc, img->rgba + (size_t)y * (size_t)img->width * 4, err, errlen) != 0)
            goto fail;
        for (size_t i = 0; i < (size_t)img->width; i++) {
            row[3 * i] = (unsigned char)enc.samples[4 * i];
            row[3 * i + 1] = (unsigned char)enc.samples[4 * i + 1];
            row[3 * i + 2] = (unsigned char)enc.samples[4 * i + 2];
        }
        if (fwrite(row, 1, rowbytes, fp) != rowbytes)
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

/* Skips whitespace and '#' comments, then reads an unsigned decimal.
 * Returns -1 at end of file or on anything else. */
static long read_number(FILE *fp)
{
    int c;
    long v = 0;

    for (;;) {
        c = getc(fp);
        if (c == '#') {
            while (c != '\n' && c != '\r' && c != EOF)
                c = getc(fp);
        }
        if (c == EOF)
            return -1;
        if (c != ' ' && c != '\t' && c != '\n' && c != '\r' && c != '\v' && c != '\f')
            break;
    }
    if (c < '0' || c > '9')
        return -1;
    while (c >= '0' && c <= '9') {
        if (v > (LONG_MAX - 9) / 10)
            return -1;
        v = v * 10 + (c - '0');
        c = getc(fp);
    }
    /* the character ending the number is consumed, as the format wants for
     * the single whitespace before binary data */
    if (c != EOF && c != ' ' && c != '\t' && c != '\n' && c != '\r' && c != '\v' && c != '\f') {
        if (c == '#')
            ungetc(c, fp);
        else
            return -1;
    }
    return v;
}

int image_ppm_read(FILE *fp, Image *img, double display_gamma, ImageReadExtras *ex, char *err, int errlen)
{
    ImageTransfer t;
    float *lut;
    long w, h, maxval;
    int kind, channels, ascii, wide;
    int c0 = getc(fp), c1 = getc(fp);

    if (c0 == EOF) {
        image_set_error(err, errlen, "file is empty");
        return -1;
    }
    if (c0 != 'P' || (c1 != '3' && c1 != '6' && c1 != '2' && c1 != '5')) {
        image_set_error(err, errlen, "not a PPM file (expected P6 or P3)");
        return -1;
    }
    kind = c1;
    channels = (kind == '3' || kind == '6') ? 3 : 1;
    ascii = kind == '3' || kind == '2';
    w = read_number(fp);
    h = read_number(fp);
    maxval = read_number(fp);
    if (w < 0 || h < 0 || maxval < 0) {
        image_set_error(err, errlen, "corrupt or truncated PPM header");
        return -1;
    }
    if (w == 0 || h == 0 || w > IMAGE_MAX_DIM || h > IMAGE_MAX_DIM || w * h > IMAGE_MAX_PIXELS) {
        image_set_error(err, errlen, "unsupported PPM size %ldx%ld", w, h);
        return -1;
    }
    if (maxval < 1 || maxval > 65535) {
        image_set_error(err, errlen, "invalid PPM maxval %ld (must be 1 to 65535)", maxval);
        return -1;
    }
    wide = maxval > 255;
    if (ex != NULL) {
        ex->grey = channels == 1;
        ex->sample_max = (unsigned)maxval;
    }
    /* The pixels must be there before their memory is asked for: a header
     * of 30 bytes may claim 2^28 pixels (4 GiB). Binary samples take 1 or 2
     * bytes, text ones 2 at least (a digit and a blank). When the stream
     * cannot tell its length, the reading finds out. */
    long here = ftell(fp);
    if (here >= 0 && fseek(fp, 0, SEEK_END) == 0) {
        long end = ftell(fp);
        double need = (double)w * (double)h * channels * (ascii ? 2.0 : wide ? 2.0 : 1.0) - (ascii ? 1.0 : 0.0);
        if (fseek(fp, here, SEEK_SET) != 0 || (end >= here && (double)(end - here) < need)) {
            image_set_error(err, errlen, "PPM pixel data is truncated (%ldx%ld pixels need %.0f bytes, %ld are left)",
                            w, h, need, end - here);
            return -1;
        }
    }
    image_transfer_init(&t, display_gamma);
    lut = image_transfer_decode_table(&t, (unsigned)maxval);
    if (lut == NULL || image_alloc(img, (int)w, (int)h) != 0) {
        free(lut);
        image_set_error(err, errlen, "out of memory for a %ldx%ld image", w, h);
        return -1;
    }
    for (long i = 0; i < w * h; i++) {
        float *px = img->rgba + i * 4;
        for (int ch = 0; ch < channels; ch++) {
            long v;
            if (ascii) {
                v = read_number(fp);
            } else {
                int a = getc(fp), b = 0;
                if (wide && a != EOF)
                    b = getc(fp);
                v = (a == EOF || b == EOF) ? -1 : wide ? (a << 8 | b) : a;
            }
            if (v < 0) {
                free(lut);
                image_set_error(err, errlen, "PPM pixel data is %s", ascii ? "corrupt or truncated" : "truncated");
                return -1;
            }
            if (v > maxval)
                v = maxval; /* out-of-range samples are clamped */
            px[ch] = lut[v];
        }
        if (channels == 1)
            px[1] = px[2] = px[0];
        px[3] = 1.0f;
    }
    free(lut);
    return 0;
}
