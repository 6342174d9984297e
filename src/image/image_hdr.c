/* Radiance HDR (RGBE): writes what POV-Ray 3.7 writes for +FH: linear light,
 * each pixel's shared exponent computed as POV-Ray computes it (in single
 * precision, no dithering), scanlines run-length encoded per component
 * ("new" RLE) when 8 to 32767 pixels wide and flat otherwise, a header naming
 * the software (no creation time: the same render gives the same bytes).
 * HDR has no alpha: colours are composited on black. Reads "-Y H +X W"
 * files, flat, old and new RLE. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "image_codec.h"

#define HDR_MIN_RLE 8
#define HDR_MAX_RLE 0x7fff

/* POV-Ray's GetRGBE: the largest component's mantissa and exponent, in
 * float as POV-Ray keeps them; each component truncated to a byte. */
static void rgbe_of(const float rgba[4], unsigned char out[4])
{
    float r = rgba[0], g = rgba[1], b = rgba[2];
    float d = r > g ? r : g;
    int e;
    if (b > d)
        d = b;
    if (!(d > 1.0e-32f)) { /* NaN too */
        out[0] = out[1] = out[2] = out[3] = 0;
        return;
    }
    float m = frexpf(d, &e);
    float scale = (float)((double)m * 256.0 / (double)d);
    float c[3] = { r * scale, g * scale, b * scale };
    for (int i = 0; i < 3; i++)
        out[i] = (unsigned char)(c[i] > 0.0f ? (c[i] < 255.0f ? c[i] : 255.0f) : 0.0f);
    float x = (float)e + 128.0f;
    out[3] = (unsigned char)(x > 0.0f ? (x < 255.0f ? x : 255.0f) : 0.0f);
}

/* One component of a scanline in new RLE: runs of 3 or more equal bytes as
 * run packets (up to 127), the rest as literal packets (up to 128). */
static int write_rle_component(FILE *fp, const unsigned char *rgbe, int width, int k)
{
    int x = 0;
    while (x < width) {
        int run = 1;
        while (x + run < width && run < 127 && rgbe[4 * (x + run) + k] == rgbe[4 * x + k])
            run++;
        if (run >= 3) {
            if (putc(128 + run, fp) == EOF || putc(rgbe[4 * x + k], fp) == EOF)
                return -1;
            x += run;
            continue;
        }
        /* literal bytes up to the next run of three */
        int n = 1;
        while (x + n < width && n < 128 &&
               !(x + n + 2 < width && rgbe[4 * (x + n) + k] == rgbe[4 * (x + n + 1) + k] &&
                 rgbe[4 * (x + n) + k] == rgbe[4 * (x + n + 2) + k]))
            n++;
        if (putc(n, fp) == EOF)
            return -1;
        for (int i = 0; i < n; i++)
            if (putc(rgbe[4 * (x + i) + k], fp) == EOF)
                return -1;
        x += n;
    }
    return 0;
}

int image_hdr_write(FILE *fp, const Image *img, const ImageWriteOptions *opt, char *err, int errlen)
{
    unsigned char *rgbe = malloc((size_t)img->width * 4);
    const int rle = img->width >= HDR_MIN_RLE && img->width <= HDR_MAX_RLE;

    if (rgbe == NULL) {
        image_set_error(err, errlen, "out of memory");
        return -1;
    }
    if (fprintf(fp, "#?RADIANCE\nSOFTWARE=%s\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n",
                opt->software ? opt->software : "hstrace", img->height, img->width) < 0)
        goto fail;
    for (int y = 0; y < img->height; y++) {
        const float *px = img->rgba + (size_t)y * (size_t)img->width * 4;
        for (int x = 0; x < img->width; x++)
            rgbe_of(px + 4 * (size_t)x, rgbe + 4 * (size_t)x);
        if (!rle) {
            if (fwrite(rgbe, 4, (size_t)img->width, fp) != (size_t)img->width)
                goto fail;
            continue;
        }
        if (putc(2, fp) == EOF || putc(2, fp) == EOF || putc(img->width >> 8, fp) == EOF ||
            putc(img->width & 255, fp) == EOF)
            goto fail;
        for (int k = 0; k < 4; k++)
            if (write_rle_component(fp, rgbe, img->width, k) != 0)
                goto fail;
    }
    free(rgbe);
    return 0;

fail:
    free(rgbe);
    return -1;
}

/* Reading ------------------------------------------------------------------ */

/* One header line without its newline; -1 at the end of the file or when
 * longer than the buffer. */
static int read_line(FILE *fp, char *buf, size_t len)
{
    size_t n = 0;
    int c;
    while ((c = getc(fp)) != EOF && c != '\n') {
        if (n + 1 >= len)
            return -1;
        buf[n++] = (char)c;
    }
    buf[n] = '\0';
    return c == EOF ? -1 : 0;
}

/* A scanline of width pixels into rgbe; first holds its first four bytes.
 * Returns 0, or -1 with the reason. */
static int read_scanline(FILE *fp, unsigned char *rgbe, int width, const unsigned char first[4], const char **why)
{
    if (width >= HDR_MIN_RLE && width <= HDR_MAX_RLE && first[0] == 2 && first[1] == 2 && !(first[2] & 0x80)) {
        if ((first[2] << 8 | first[3]) != width) {
            *why = "HDR scanline length does not match the image width";
            return -1;
        }
        for (int k = 0; k < 4; k++)
            for (int x = 0; x < width;) {
                int c = getc(fp);
                if (c == EOF) {
                    *why = "HDR pixel data is truncated";
                    return -1;
                }
                int n = c > 128 ? c - 128 : c;
                if (n == 0 || x + n > width) {
                    *why = "corrupt HDR run length";
                    return -1;
                }
                if (c > 128) {
                    int v = getc(fp);
                    if (v == EOF) {
                        *why = "HDR pixel data is truncated";
                        return -1;
                    }
                    for (int i = 0; i < n; i++)
                        rgbe[4 * (x + i) + k] = (unsigned char)v;
                } else {
                    for (int i = 0; i < n; i++) {
                        int v = getc(fp);
                        if (v == EOF) {
                            *why = "HDR pixel data is truncated";
                            return -1;
                        }
                        rgbe[4 * (x + i) + k] = (unsigned char)v;
                    }
                }
                x += n;
            }
        return 0;
    }
    /* flat pixels, where (1,1,1,n) repeats the previous pixel (old RLE, its
     * counts shifted by 8 bits for each repeat code in a row) */
    int shift = 0;
    for (int x = 0; x < width;) {
        unsigned char p[4];
        if (x == 0)
            memcpy(p, first, 4);
        else if (fread(p, 1, 4, fp) != 4) {
            *why = "HDR pixel data is truncated";
            return -1;
        }
        if (p[0] == 1 && p[1] == 1 && p[2] == 1) {
            if (x == 0 || shift > 16) {
                *why = "corrupt HDR repeat code";
                return -1;
            }
            long n = (long)p[3] << shift;
            if (x + n > width) {
                *why = "corrupt HDR repeat code";
                return -1;
            }
            for (long i = 0; i < n; i++, x++)
                memcpy(rgbe + 4 * x, rgbe + 4 * (x - 1), 4);
            shift += 8;
            continue;
        }
        memcpy(rgbe + 4 * x, p, 4);
        x++;
        shift = 0;
    }
    return 0;
}

int image_hdr_read(FILE *fp, Image *img, char *err, int errlen)
{
    char line[512];
    int w = 0, h = 0;
    const char *why = NULL;
    unsigned char *rgbe;

    if (read_line(fp, line, sizeof line) != 0 || (strcmp(line, "#?RADIANCE") != 0 && strcmp(line, "#?RGBE") != 0)) {
        image_set_error(err, errlen, "not a Radiance HDR file (expected #?RADIANCE)");
        return -1;
    }
    for (int lines = 0;; lines++) {
        if (lines > 1000 || read_line(fp, line, sizeof line) != 0) {
            image_set_error(err, errlen, "HDR header is truncated or too long");
            return -1;
        }
        if (line[0] == '\0')
            break;
        if (strncmp(line, "FORMAT=", 7) == 0 && strcmp(line + 7, "32-bit_rle_rgbe") != 0) {
            image_set_error(err, errlen, "unsupported HDR format '%s' (32-bit_rle_rgbe only)", line + 7);
            return -1;
        }
    }
    if (read_line(fp, line, sizeof line) != 0 || sscanf(line, "-Y %d +X %d", &h, &w) != 2) {
        image_set_error(err, errlen, "unsupported HDR resolution line (\"-Y height +X width\" only)");
        return -1;
    }
    if (w <= 0 || h <= 0 || w > IMAGE_MAX_DIM || h > IMAGE_MAX_DIM || (long)w * h > IMAGE_MAX_PIXELS) {
        image_set_error(err, errlen, "unsupported HDR size %dx%d", w, h);
        return -1;
    }
    rgbe = malloc((size_t)w * 4);
    /* the image grows with the rows decoded */
    int cap = h < 64 ? h : 64;
    if (rgbe == NULL || image_alloc(img, w, cap) != 0) {
        free(rgbe);
        image_set_error(err, errlen, "out of memory for a %dx%d image", w, h);
        return -1;
    }
    for (int y = 0; y < h; y++) {
        unsigned char first[4];
        if (image_grow_rows(img, y, h, &cap)) {
            why = "out of memory";
            break;
        }
        if (fread(first, 1, 4, fp) != 4) {
            why = "HDR pixel data is truncated";
            break;
        }
        if (read_scanline(fp, rgbe, w, first, &why) != 0)
            break;
        float *px = img->rgba + (size_t)y * (size_t)w * 4;
        for (int x = 0; x < w; x++, px += 4) {
            const unsigned char *q = rgbe + 4 * x;
            /* the usual decoding: an exponent of 0 is black */
            float f = q[3] ? ldexpf(1.0f, q[3] - (128 + 8)) : 0.0f;
            px[0] = ((float)q[0] + 0.5f) * f;
            px[1] = ((float)q[1] + 0.5f) * f;
            px[2] = ((float)q[2] + 0.5f) * f;
            px[3] = 1.0f;
        }
    }
    free(rgbe);
    if (why != NULL) {
        image_set_error(err, errlen, "%s", why);
        return -1;
    }
    img->height = h;
    return 0;
}
