/* The figures of `hstrace compare` between two images (src/tools/image_compare.h):
 * RMSE, PSNR, the largest error and where, the share of pixels over the
 * threshold, NaN handling and the heat map, on small images whose figures are
 * worked out by hand below. */
#include <math.h>
#include <string.h>

#include "image.h"
#include "image_compare.h"
#include "tap.h"

static float *px(Image *img, int x, int y) { return &img->rgba[((size_t)y * img->width + x) * 4]; }

static void fill(Image *img, float v)
{
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++) {
            float *p = px(img, x, y);
            p[0] = p[1] = p[2] = v;
            p[3] = 1;
        }
}

static int near(double a, double b, double tol) { return fabs(a - b) <= tol; }

/* A: 4x3, every channel 0.25. B: A with four channels changed by amounts
 * that floats hold exactly, and one alpha (ignored):
 *   (1,0) R +0.125     (0,1) B +0.0078125 (2^-7, under the threshold)
 *   (2,1) R +0.5       (3,2) G -0.5       (0,0) alpha 0
 * Squared errors: 0.015625 + 0.25 + 0.00006103515625 + 0.25 = 0.51568603515625
 * over 36 samples: RMSE = sqrt(0.51568603515625 / 36) = 0.1196854715;
 * PSNR = 10 log10(36 / 0.51568603515625) = 18.4391713 dB. The largest error,
 * 0.5, is first met at (2,1) in reading order (row 1 before row 2). Over
 * 0.02: (1,0), (2,1), (3,2) = 3 of 12 pixels = 0.25; over 0.125 (strictly):
 * 2 pixels. */
static void test_figures(void)
{
    Image a, b;
    ImageComparison c;
    image_alloc(&a, 4, 3);
    image_alloc(&b, 4, 3);
    fill(&a, 0.25f);
    fill(&b, 0.25f);
    px(&b, 1, 0)[0] += 0.125f;
    px(&b, 0, 1)[2] += 0.0078125f;
    px(&b, 2, 1)[0] += 0.5f;
    px(&b, 3, 2)[1] -= 0.5f;
    px(&b, 0, 0)[3] = 0.0f;

    tap_ok(image_compare(&a, &b, 0.02, &c) == 0 && c.width == 4 && c.height == 3, "compare: 4x3 images");
    tap_ok(near(c.rmse, 0.1196854715, 1e-9), "RMSE over all 36 RGB samples = 0.1196854715 (got %.10f)", c.rmse);
    tap_ok(near(c.psnr, 18.4391713, 1e-6), "PSNR = 10 log10(36 / 0.5156860) = 18.4391713 dB (got %.7f)", c.psnr);
    tap_ok(c.max_error == 0.5 && c.max_x == 2 && c.max_y == 1,
           "max error 0.5, first at (2,1) in reading order (got %g at %d,%d)", c.max_error, c.max_x, c.max_y);
    tap_ok(c.over == 3 && c.share == 0.25, "3 of 12 pixels over 0.02 = 0.25 (got %ld = %g)", c.over, c.share);
    tap_ok(c.nonfinite == 0, "no NaN or infinite pixels");
    image_compare(&a, &b, 0.125, &c);
    tap_ok(c.over == 2 && c.share == 2.0 / 12, "over 0.125 is strict: 2 pixels (got %ld)", c.over);
    image_compare(&b, &a, 0.02, &c);
    tap_ok(near(c.rmse, 0.1196854715, 1e-9) && c.max_x == 2 && c.max_y == 1 && c.over == 3,
           "the figures do not depend on the order of A and B");

    /* NaN and infinity: counted, left out of the figures. */
    px(&b, 3, 0)[1] = NAN;
    px(&a, 1, 2)[2] = INFINITY;
    image_compare(&a, &b, 0.02, &c);
    tap_ok(c.nonfinite == 2 && near(c.rmse, 0.1196854715, 1e-9) && c.max_error == 0.5 && c.over == 3,
           "a NaN in B and an infinity in A: 2 pixels counted apart, the other figures unchanged");

    Image d;
    image_alloc(&d, 3, 4);
    tap_ok(image_compare(&a, &d, 0.02, &c) == -1, "images of other sizes (4x3, 3x4) are refused");
    image_free(&d);
    image_free(&a);
    image_free(&b);
}

static void test_equal(void)
{
    Image a, b;
    ImageComparison c;
    image_alloc(&a, 5, 2);
    image_alloc(&b, 5, 2);
    fill(&a, 0.7f);
    fill(&b, 0.7f);
    image_compare(&a, &b, 0.0, &c);
    tap_ok(c.rmse == 0 && isinf(c.psnr) && c.psnr > 0 && c.max_error == 0 && c.max_x == 0 && c.max_y == 0 &&
               c.over == 0,
           "equal images: RMSE 0, PSNR infinite, max error 0 at (0,0), nothing over a threshold of 0");
    image_free(&a);
    image_free(&b);
}

/* The heat map's colours, from the rules in image_compare.h, threshold 0.02:
 * a difference of 2^-7 (under it) is blue 0.1 + 0.4 * 0.0078125 / 0.02 =
 * 0.25625; 0.5 lies at t = ln(0.5/0.02) / ln(1/0.02) = 0.8228162 of the way
 * from the threshold to 1 on a log scale: red 1, green min(1, 2t) = 1, blue
 * 2t - 1 = 0.6456324; 1 and more is white; NaN magenta. */
static void test_heat_map(void)
{
    Image a, b, map;
    image_alloc(&a, 3, 2);
    image_alloc(&b, 3, 2);
    fill(&a, 0.25f);
    fill(&b, 0.25f);
    px(&b, 1, 0)[2] += 0.0078125f;
    px(&b, 2, 0)[0] += 0.5f;
    px(&b, 0, 1)[1] += 3.0f;
    px(&b, 1, 1)[0] = NAN;
    tap_ok(image_compare_heat_map(&a, &b, 0.02, &map) == 0 && map.width == 3 && map.height == 2,
           "heat map: the size of the images");
    const float *p = px(&map, 0, 0);
    tap_ok(p[0] == 0 && p[1] == 0 && p[2] == 0 && p[3] == 1, "heat map: equal pixel black, opaque");
    p = px(&map, 1, 0);
    tap_ok(p[0] == 0 && p[1] == 0 && near(p[2], 0.25625, 1e-6), "heat map: under the threshold blue 0.25625 (got %g)",
           p[2]);
    p = px(&map, 2, 0);
    tap_ok(p[0] == 1 && p[1] == 1 && near(p[2], 0.6456324, 1e-6), "heat map: error 0.5 is (1, 1, 0.6456324) (got %g %g %g)",
           p[0], p[1], p[2]);
    p = px(&map, 0, 1);
    tap_ok(p[0] == 1 && p[1] == 1 && p[2] == 1, "heat map: error 3 is white");
    p = px(&map, 1, 1);
    tap_ok(p[0] == 1 && p[1] == 0 && p[2] == 1, "heat map: NaN is magenta");
    image_free(&map);

    Image d;
    image_alloc(&d, 2, 3);
    tap_ok(image_compare_heat_map(&a, &d, 0.02, &map) == -1 && map.rgba == NULL,
           "heat map: images of other sizes are refused, nothing allocated");
    image_free(&d);
    image_free(&a);
    image_free(&b);
}

int main(void)
{
    test_figures();
    test_equal();
    test_heat_map();
    return tap_done();
}
