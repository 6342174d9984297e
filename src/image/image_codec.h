/* Internal interface between image.c (dispatch, atomic writes) and the
 * per-format codecs, plus the display encoding shared by PNG and PPM. Not for
 * use outside the image module (the unit test includes it to check the
 * encoder). */
#ifndef HST_IMAGE_CODEC_H
#define HST_IMAGE_CODEC_H

#include <stdio.h>

#include "image.h"

/* ---- display encoding (image_encoding.c) --------------------------------
 * POV-Ray 3.7's integer encoding for a linear working space
 * (assumed_gamma 1), in single precision as POV-Ray computes it:
 *   sRGB:      e = x <= 0.0031308f ? x*12.92f : 1.055f*powf(x, 1/2.4f) - 0.055f
 *   power law: e = powf(max(x,0), 1/gamma)   (no curve when |1-gamma| <= 0.01)
 *   quantize:  q = floorf(clamp(e, 0, 1) * max + 0.5f)
 * No dithering (POV-Ray's default). */
typedef struct {
    int srgb;      /* 1: sRGB transfer function */
    int neutral;   /* 1: identity (power law within 1% of 1) */
    float enc_exp; /* power-law exponent applied when encoding (1/gamma) */
    double gama;   /* value for the PNG gAMA chunk (1/2.2 for sRGB) */
} ImageTransfer;

void image_transfer_init(ImageTransfer *t, double display_gamma);
float image_transfer_encode(const ImageTransfer *t, float linear);
float image_transfer_decode(const ImageTransfer *t, float encoded);
/* POV-Ray's IntEncode: clamps to 0..1 (NaN gives 0) and rounds half up. */
unsigned image_quantize(float encoded, unsigned max);

/* One pixel of premultiplied linear RGBA to integer samples in 0..max.
 * Without alpha the premultiplied colour is encoded as it is (composited on
 * black). With alpha the colour is un-premultiplied first, as POV-Ray does,
 * raising the opacity of pixels brighter than their alpha (by POV-Ray's
 * greyscale weights 0.297/0.589/0.114) so highlights on transparent objects
 * survive the clamp. out[3] is set only when with_alpha. */
void image_encode_pixel(const ImageTransfer *t, const float rgba[4], unsigned max, int with_alpha, unsigned out[4]);

/* One row at a time, for the writers: POV-Ray's encoding (image_encode_pixel)
 * or, with a display transform, the same un-premultiplied colour through
 * OpenColorIO's display/view transform instead of the curve, then the same
 * quantization. */
typedef struct {
    ImageTransfer transfer;       /* the curve, and the PNG gAMA value */
    const ColourDisplay *display; /* NULL: the curve */
    unsigned max;
    int with_alpha, width;
    unsigned *samples; /* 4 per pixel; [3] set only with alpha */
    float *scratch;    /* 3 per pixel, for the display transform */
    /* 8-bit samples by the curve: threshold[k - 1] the least float whose
     * sample is k (image_encode_thresholds), so that a sample is a search
     * of 255 floats rather than a powf; NULL: none (encoded as they come) */
    float *threshold;
} ImageRowEncoder;

/* Returns 0, or -1 when out of memory. */
int image_row_encoder_init(ImageRowEncoder *e, const ImageWriteOptions *opt, int width, unsigned max,
                           int with_alpha);
/* Encodes width pixels of linear premultiplied RGBA into e->samples.
 * Returns 0, or -1 with a message when the display transform fails. */
int image_row_encode(ImageRowEncoder *e, const float *rgba, char *err, int errlen);
void image_row_encoder_free(ImageRowEncoder *e);

/* Decoding table for integer samples 0..max (max <= 65535): linear values.
 * Returns NULL when out of memory. Free with free(). */
float *image_transfer_decode_table(const ImageTransfer *t, unsigned max);

/* For readers whose image grows with the rows decoded, so that a few
 * corrupt bytes claiming 2^28 pixels cost only what the file holds: before
 * row y of an image of `rows` rows, of which *cap are allocated, doubles the
 * allocation when y reaches it. Returns 0, or -1 when out of memory (the
 * image as it was). */
int image_grow_rows(Image *img, int y, int rows, int *cap);

/* ---- little-endian fields (Targa, BMP) ---------------------------------- */
static inline void image_put_le16(unsigned char *p, unsigned v)
{
    p[0] = (unsigned char)(v & 0xff);
    p[1] = (unsigned char)(v >> 8 & 0xff);
}

static inline void image_put_le32(unsigned char *p, unsigned long v)
{
    image_put_le16(p, (unsigned)(v & 0xffff));
    image_put_le16(p + 2, (unsigned)(v >> 16 & 0xffff));
}

/* ---- errors --------------------------------------------------------------- */
#if defined(__GNUC__)
#define HST_PRINTF(a, b) __attribute__((format(printf, a, b)))
#else
#define HST_PRINTF(a, b)
#endif
void image_set_error(char *err, int errlen, const char *fmt, ...) HST_PRINTF(3, 4);

/* ---- codecs --------------------------------------------------------------
 * Writers get the open descriptor of the temporary file (the EXR writer) or
 * a FILE wrapping it (the others; the caller closes it), and report errors as
 * a bare reason ("disk full"); image_write adds "cannot write 'path': ".
 * Readers fill a fresh Image and report the bare reason likewise. */
int image_exr_write(int fd, const Image *img, const ImageWriteOptions *opt, char *err, int errlen);
int image_png_write(FILE *fp, const Image *img, const ImageWriteOptions *opt, char *err, int errlen);
int image_ppm_write(FILE *fp, const Image *img, const ImageWriteOptions *opt, char *err, int errlen);
int image_tga_write(FILE *fp, const Image *img, const ImageWriteOptions *opt, char *err, int errlen);
int image_bmp_write(FILE *fp, const Image *img, const ImageWriteOptions *opt, char *err, int errlen);
int image_jpeg_write(FILE *fp, const Image *img, const ImageWriteOptions *opt, char *err, int errlen);
int image_hdr_write(FILE *fp, const Image *img, const ImageWriteOptions *opt, char *err, int errlen);

int image_exr_read(int fd, Image *img, char *err, int errlen);
/* Named channels as float planes: 0, 1 when one is missing, -1 on error. */
int image_exr_read_planes(int fd, const char *const *names, int n, float **planes, int *width, int *height,
                          char *err, int errlen);
/* The header and rows [y0, y1) of every channel (image_read_exr_file). */
int image_exr_read_file(int fd, ImageExrFile *f, int y0, int y1, char *err, int errlen);
/* ex: NULL, or image_read_ex's extras (keep_straight; PNG and BMP: palettes). */
int image_png_read(FILE *fp, Image *img, double display_gamma, ImageReadExtras *ex, char *err, int errlen);
int image_ppm_read(FILE *fp, Image *img, double display_gamma, ImageReadExtras *ex, char *err, int errlen);
int image_tga_read(FILE *fp, Image *img, double display_gamma, ImageReadExtras *ex, char *err, int errlen);
int image_bmp_read(FILE *fp, Image *img, double display_gamma, ImageReadExtras *ex, char *err, int errlen);
int image_jpeg_read(FILE *fp, Image *img, double display_gamma, char *err, int errlen);
int image_hdr_read(FILE *fp, Image *img, char *err, int errlen);

/* The width and height a file of format fmt declares, read from its header
 * at fp's position (image_size.c). Returns 0, or -1 when the header cannot
 * tell (damaged, cut short, or an empty image): then the decoder reads the
 * file and says what is wrong with it. */
int image_header_size(FILE *fp, ImageFormat fmt, long *width, long *height);

#endif
