/* How far apart two images of the same size are, pixel by pixel, in linear
 * RGB (alpha is ignored): the figures `hstrace compare` reports and the
 * regression tests hold hstrace to, and a heat map of where they differ. */
#ifndef HST_IMAGE_COMPARE_H
#define HST_IMAGE_COMPARE_H

#include "image.h"

typedef struct {
    int width, height;
    double threshold;  /* a pixel is "over" when a channel differs by more */
    double rmse;       /* root mean square difference over all RGB samples */
    double psnr;       /* 10 log10(1 / rmse^2) in dB (peak: linear white, 1.0); INFINITY when rmse is 0 */
    double max_error;  /* largest absolute difference of one channel */
    int max_x, max_y;  /* the first pixel (reading order, row 0 at the top) with it; 0,0 when the images are equal */
    long over;         /* pixels with some channel off by more than threshold */
    double share;      /* over / (width * height) */
    long nonfinite;    /* pixels of A plus pixels of B holding NaN or infinity in a channel;
                        * their samples count in none of the figures above */
} ImageComparison;

/* Compares a with b. Returns 0, or -1 when their sizes differ or one is
 * empty. */
int image_compare(const Image *a, const Image *b, double threshold, ImageComparison *out);

/* Pixels of img holding NaN or infinity in a colour channel. */
long image_count_nonfinite(const Image *img);

/* A heat map of the largest channel difference e at each pixel (fills a
 * fresh `map`, same size, opaque):
 *   e = 0                 black
 *   0 < e <= threshold    blue, dim to mid as e grows (differs, within tolerance)
 *   e > threshold         red, through yellow to white at e >= 1
 *                         (log scale from the threshold, or 1e-4 when smaller)
 *   NaN or infinity       magenta
 * Returns 0, or -1 when the sizes differ or memory runs out. */
int image_compare_heat_map(const Image *a, const Image *b, double threshold, Image *map);

#endif
