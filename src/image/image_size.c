/* The size an image file declares, from its header alone: what the memory
 * budget is checked against before a single pixel is decoded (a PNG of
 * 260 KB may declare 16384x16384 pixels, 4 GiB once decoded), and what
 * `hstrace compare` holds two files to before reading either.
 *
 * Each reader here knows only where its format keeps the width and the
 * height; whatever else is wrong with a file is for its decoder to find and
 * say. A header this cannot make sense of is "unknown", never an error: the
 * decoder then reads the file and names what is wrong with it; so is a
 * header the decoder is sure to refuse (a Targa with a colour map, a
 * compressed BMP, an XYZE HDR), so that its message, not a size, is what
 * `hstrace compare` says. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "image_codec.h"

static unsigned long be16(const unsigned char *p) { return (unsigned long)p[0] << 8 | p[1]; }
static unsigned long be32(const unsigned char *p) { return be16(p) << 16 | be16(p + 2); }
static unsigned long le16(const unsigned char *p) { return (unsigned long)p[1] << 8 | p[0]; }
static unsigned long le32(const unsigned char *p) { return le16(p + 2) << 16 | le16(p); }

/* PNG: IHDR, the first chunk, right after the signature. */
static int png_size(FILE *fp, long *w, long *h)
{
    unsigned char b[24];
    if (fread(b, 1, sizeof b, fp) != sizeof b || memcmp(b + 12, "IHDR", 4) != 0)
        return -1;
    *w = (long)be32(b + 16);
    *h = (long)be32(b + 20);
    return 0;
}

/* JPEG: the frame header (SOF0..SOF15 but DHT, JPG and DAC), which comes
 * before the first scan; every segment before it is skipped by its length. */
static int jpeg_size(FILE *fp, long *w, long *h)
{
    unsigned char b[7];
    if (fread(b, 1, 2, fp) != 2 || b[0] != 0xff || b[1] != 0xd8)
        return -1;
    for (;;) {
        int c = getc(fp);
        if (c != 0xff)
            return -1;
        while ((c = getc(fp)) == 0xff) /* fill bytes */
            ;
        if (c == EOF || c == 0xd9 || c == 0xda) /* end of image, start of scan: no frame */
            return -1;
        if (c == 0x01 || (c >= 0xd0 && c <= 0xd7)) /* markers without a length */
            continue;
        if (fread(b, 1, 2, fp) != 2 || be16(b) < 2)
            return -1;
        long len = (long)be16(b) - 2;
        if (c >= 0xc0 && c <= 0xcf && c != 0xc4 && c != 0xc8 && c != 0xcc) {
            if (len < 5 || fread(b, 1, 5, fp) != 5)
                return -1;
            *h = (long)be16(b + 1); /* 0: the height comes later (DNL), which the decoder refuses */
            *w = (long)be16(b + 3);
            return 0;
        }
        if (fseek(fp, len, SEEK_CUR) != 0)
            return -1;
    }
}

/* OpenEXR: the dataWindow attribute (box2i) of the first header, among
 * attributes of a name, a type name, a 4-byte size and the value. */
static int read_name(FILE *fp, char *buf, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        int c = getc(fp);
        if (c == EOF)
            return -1;
        buf[i] = (char)c;
        if (c == 0)
            return 0;
    }
    return -1;
}

static int exr_size(FILE *fp, long *w, long *h)
{
    unsigned char b[16];
    if (fread(b, 1, 8, fp) != 8 || be32(b) != 0x762f3101UL)
        return -1;
    for (int k = 0; k < 100000; k++) {
        char name[256], type[256];
        if (read_name(fp, name, sizeof name) || name[0] == '\0' || read_name(fp, type, sizeof type) ||
            fread(b, 1, 4, fp) != 4)
            return -1;
        unsigned long size = le32(b);
        if (strcmp(name, "dataWindow") == 0 && strcmp(type, "box2i") == 0 && size == 16) {
            if (fread(b, 1, 16, fp) != 16)
                return -1;
            /* as signed 32-bit numbers, the difference in 64 bits */
            int64_t x0 = (int32_t)le32(b), y0 = (int32_t)le32(b + 4), x1 = (int32_t)le32(b + 8),
                    y1 = (int32_t)le32(b + 12);
            if (x1 < x0 || y1 < y0 || x1 - x0 >= INT32_MAX || y1 - y0 >= INT32_MAX)
                return -1;
            *w = (long)(x1 - x0 + 1);
            *h = (long)(y1 - y0 + 1);
            return 0;
        }
        if (size > INT32_MAX || fseek(fp, (long)size, SEEK_CUR) != 0)
            return -1;
    }
    return -1;
}

/* Targa: width and height at bytes 12 to 15 (no signature: known by the name). */
static int tga_size(FILE *fp, long *w, long *h)
{
    unsigned char b[18];
    if (fread(b, 1, sizeof b, fp) != sizeof b || b[1] != 0 || (b[2] != 2 && b[2] != 3 && b[2] != 10 && b[2] != 11))
        return -1; /* image_tga_read's types: true-colour and grey, plain or run-length */
    *w = (long)le16(b + 12);
    *h = (long)le16(b + 14);
    return 0;
}

/* BMP: the info header's width and height, a negative height for rows from the top. */
static int bmp_size(FILE *fp, long *w, long *h)
{
    unsigned char b[34];
    if (fread(b, 1, sizeof b, fp) != sizeof b || b[0] != 'B' || b[1] != 'M')
        return -1;
    unsigned long bits = le16(b + 28);
    if ((bits != 8 && bits != 24 && bits != 32) || le32(b + 30) != 0)
        return -1; /* image_bmp_read's: uncompressed 8, 24 and 32 bits */
    *w = (long)(int32_t)le32(b + 18);
    *h = labs((long)(int32_t)le32(b + 22));
    return 0;
}

/* PPM and PGM: "P6", then width and height in text, with # comments. */
static long ppm_number(FILE *fp)
{
    int c;
    for (;;) {
        c = getc(fp);
        if (c == '#')
            while (c != '\n' && c != EOF)
                c = getc(fp);
        if (c == EOF)
            return -1;
        if (c != ' ' && c != '\t' && c != '\n' && c != '\r' && c != '\v' && c != '\f')
            break;
    }
    long v = 0;
    if (c < '0' || c > '9')
        return -1;
    for (; c >= '0' && c <= '9'; c = getc(fp))
        if ((v = v * 10 + (c - '0')) > INT32_MAX)
            return -1;
    return v;
}

static int ppm_size(FILE *fp, long *w, long *h)
{
    if (getc(fp) != 'P')
        return -1;
    int k = getc(fp);
    if (k != '2' && k != '3' && k != '5' && k != '6')
        return -1;
    *w = ppm_number(fp);
    *h = ppm_number(fp);
    return *w < 0 || *h < 0 ? -1 : 0;
}

/* Radiance HDR: header lines up to an empty one, then "-Y height +X width". */
static int hdr_line(FILE *fp, char *buf, size_t n)
{
    size_t i = 0;
    int c;
    while ((c = getc(fp)) != EOF && c != '\n') {
        if (i + 1 >= n)
            return -1;
        buf[i++] = (char)c;
    }
    buf[i] = '\0';
    return c == EOF ? -1 : 0;
}

static int hdr_size(FILE *fp, long *w, long *h)
{
    char line[512];
    if (hdr_line(fp, line, sizeof line) || line[0] != '#' || line[1] != '?')
        return -1;
    for (int k = 0;; k++) {
        if (k > 1000 || hdr_line(fp, line, sizeof line))
            return -1;
        if (line[0] == '\0')
            break;
        if (strncmp(line, "FORMAT=", 7) == 0 && strcmp(line + 7, "32-bit_rle_rgbe") != 0)
            return -1; /* image_hdr_read's only */
    }
    int hh, ww;
    if (hdr_line(fp, line, sizeof line) || sscanf(line, "-Y %d +X %d", &hh, &ww) != 2)
        return -1;
    *w = ww;
    *h = hh;
    return 0;
}

int image_header_size(FILE *fp, ImageFormat fmt, long *width, long *height)
{
    long w = -1, h = -1;
    int rc;
    switch (fmt) {
    case IMAGE_FORMAT_PNG: rc = png_size(fp, &w, &h); break;
    case IMAGE_FORMAT_JPEG: rc = jpeg_size(fp, &w, &h); break;
    case IMAGE_FORMAT_EXR: rc = exr_size(fp, &w, &h); break;
    case IMAGE_FORMAT_TGA: rc = tga_size(fp, &w, &h); break;
    case IMAGE_FORMAT_BMP: rc = bmp_size(fp, &w, &h); break;
    case IMAGE_FORMAT_PPM: rc = ppm_size(fp, &w, &h); break;
    case IMAGE_FORMAT_HDR: rc = hdr_size(fp, &w, &h); break;
    default: rc = -1; break;
    }
    /* An empty image, like a damaged header, is for the decoder to refuse,
     * and so is a size past every reader's limits (IMAGE_MAX_DIM a side,
     * IMAGE_MAX_PIXELS in all; libjpeg's 65500): the reader's own message
     * says which. */
    if (rc != 0 || w <= 0 || h <= 0 || w > IMAGE_MAX_DIM || h > IMAGE_MAX_DIM || w * h > IMAGE_MAX_PIXELS)
        return -1;
    *width = w;
    *height = h;
    return 0;
}
