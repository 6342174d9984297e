/* Pixel-by-pixel figures between two images, and their heat map. */
#include "image_compare.h"

#include <math.h>
#include <stddef.h>

static int same_size(const Image *a, const Image *b)
{
    return a->rgba && b->rgba && a->width > 0 && a->height > 0 && a->width == b->width && a->height == b->height;
}

static int finite_pixel(const float *p)
{
    return isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]);
}

long image_count_nonfinite(const Image *img)
{
    long bad = 0;
    size_t n = (size_t)img->width * (size_t)img->height;
    for (size_t i = 0; i < n; i++)
        bad += !finite_pixel(&img->rgba[i * 4]);
    return bad;
}

int image_compare(const Image *a, const Image *b, double threshold, ImageComparison *out)
{
    if (!same_size(a, b))
        return -1;
    ImageComparison c = {.width = a->width, .height = a->height, .threshold = threshold};
    c.nonfinite = image_count_nonfinite(a) + image_count_nonfinite(b);
    double se = 0;
    for (int y = 0; y < a->height; y++)
        for (int x = 0; x < a->width; x++) {
            size_t i = ((size_t)y * a->width + x) * 4;
            int off = 0;
            for (int k = 0; k < 3; k++) {
                double d = fabs((double)a->rgba[i + k] - b->rgba[i + k]);
                if (!isfinite(d))
                    continue; /* counted in nonfinite */
                se += d * d;
                if (d > c.max_error) {
                    c.max_error = d;
                    c.max_x = x;
                    c.max_y = y;
                }
                off |= d > threshold;
            }
            c.over += off;
        }
    double n = (double)a->width * a->height;
    c.rmse = sqrt(se / (3.0 * n));
    c.psnr = c.rmse > 0 ? -20.0 * log10(c.rmse) : INFINITY;
    c.share = c.over / n;
    *out = c;
    return 0;
}

int image_compare_heat_map(const Image *a, const Image *b, double threshold, Image *map)
{
    if (!same_size(a, b) || image_alloc(map, a->width, a->height))
        return -1;
    /* Above the threshold: t runs 0..1 on a log scale from lo to 1. */
    double lo = threshold > 1e-4 ? threshold : 1e-4;
    size_t n = (size_t)a->width * a->height;
    for (size_t i = 0; i < n; i++) {
        const float *p = &a->rgba[i * 4], *q = &b->rgba[i * 4];
        float *o = &map->rgba[i * 4];
        o[3] = 1.0f;
        if (!finite_pixel(p) || !finite_pixel(q)) {
            o[0] = o[2] = 1.0f;
            continue;
        }
        double e = 0;
        for (int k = 0; k < 3; k++)
            e = fmax(e, fabs((double)p[k] - q[k]));
        if (e == 0)
            continue;
        if (e <= threshold) {
            o[2] = (float)(0.1 + 0.4 * e / threshold);
            continue;
        }
        double t = lo >= 1.0 ? 1.0 : log(e / lo) / log(1.0 / lo);
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        o[0] = 1.0f;
        o[1] = (float)fmin(1.0, 2.0 * t);
        o[2] = (float)fmax(0.0, 2.0 * t - 1.0);
    }
    return 0;
}
