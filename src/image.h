/* Images: linear RGBA float buffers, and the files they are written to and
 * read from (OpenEXR through its C API, PNG, PPM). */
#ifndef HST_IMAGE_H
#define HST_IMAGE_H

#include "colour.h"

typedef struct {
    int width, height;
    float *rgba; /* width*height*4, row 0 at the top, linear light; colour
                  * premultiplied by alpha, as in POV-Ray and EXR files */
} Image;

typedef enum { IMAGE_FORMAT_UNKNOWN, IMAGE_FORMAT_EXR, IMAGE_FORMAT_PNG, IMAGE_FORMAT_PPM } ImageFormat;

/* EXR compression; the zero default is ZIP (16 scanlines a block), what
 * POV-Ray 3.7 writes. */
typedef enum {
    IMAGE_EXR_ZIP = 0, IMAGE_EXR_NONE, IMAGE_EXR_RLE, IMAGE_EXR_ZIPS, IMAGE_EXR_PIZ
} ImageExrCompression;

typedef struct {
    int exr_float;      /* 1: 32-bit float channels; 0: half (default) */
    int png_16bit;      /* 1: 16-bit PNG; 0: 8-bit (default) */
    int write_alpha;    /* include alpha in PNG (EXR always has RGBA) */
    /* Display encoding for PNG/PPM, as POV-Ray 3.7 does: 0 means sRGB, any
     * other value a power-law gamma (file_gamma). */
    double display_gamma;
    /* OpenColorIO's display/view transform for PNG and PPM, replacing the
     * curve above (display_gamma is then unused; no gAMA or sRGB chunk is
     * written, since the view's curve is the config's to say); NULL:
     * POV-Ray's encoding. */
    const ColourDisplay *display;
    ImageExrCompression exr_compression; /* 0: ZIP */
    /* The EXR's chromaticities attribute (CIE xy of red, green, blue and
     * white), written when have_chromaticities. */
    int have_chromaticities;
    float chromaticities[8];
} ImageWriteOptions;

int image_alloc(Image *img, int width, int height);
void image_free(Image *img);

ImageFormat image_format_from_path(const char *path);

/* Write to a temporary file beside `path` and rename it into place, so an
 * interrupted or failed write never leaves a truncated image. Returns 0 on
 * success, or -1 with a message in err. */
int image_write(const char *path, const Image *img, const ImageWriteOptions *opt, char *err, int errlen);

/* Read an EXR, PNG or PPM into linear RGBA (PNG/PPM are decoded from sRGB, or
 * the gamma given, back to linear). Returns 0, or -1 with a message. */
int image_read(const char *path, Image *img, double display_gamma, char *err, int errlen);

#endif
