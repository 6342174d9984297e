/* compare_images: the figures the regression tests assert, computed in
 * linear RGB from EXR (or PNG/PPM) files.
 *
 *   compare_images full A B [--rmse R] [--threshold T] [--share S]
 *       RMSE over all RGB samples, the largest error and where, and the share
 *       of pixels with any channel off by more than T (default 0.02). Exit 0
 *       when RMSE <= R and share <= S (defaults 0.01 and 0.01 = 1%).
 *
 *   compare_images mask POV_Q3 POV_Q4 HST_Q3 HST_Q4 [--share S]
 *       POV-Ray's shadow mask is where its +Q3 render is brighter than its +Q4
 *       render; hstrace's is where its own +Q3 and +Q4 renders differ. Exit 0
 *       when the masks disagree on at most S of the pixels (default 0.001 =
 *       0.1%) and every disagreeing pixel lies within one pixel of a shadow
 *       edge (a boundary of either mask) or an object silhouette.
 *
 * Exit status 2 on unreadable files or mismatched sizes. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "image.h"

/* Renders are stored as half floats: about 3 decimal digits. A pixel counts
 * as changed when a channel moves by more than a few half-float steps at
 * full brightness, well below any shadow a light of 1/100 strength casts. */
#define MASK_EPSILON 2e-3
/* Neighbouring pixels of one surface differ by far less than this in a
 * shadowless (+Q3) render; across a silhouette or a colour edge they differ
 * by more. */
#define SILHOUETTE_JUMP 0.05

static int load(const char *path, Image *img)
{
    char err[512];
    if (image_read(path, img, 0.0, err, sizeof err)) {
        fprintf(stderr, "compare_images: %s\n", err);
        return -1;
    }
    return 0;
}

static int same_size(const Image *a, const Image *b, const char *na, const char *nb)
{
    if (a->width == b->width && a->height == b->height)
        return 1;
    fprintf(stderr, "compare_images: '%s' is %dx%d but '%s' is %dx%d\n", na, a->width, a->height, nb, b->width,
            b->height);
    return 0;
}

static const float *px(const Image *img, int x, int y) { return &img->rgba[((size_t)y * img->width + x) * 4]; }

static double option(int argc, char **argv, const char *name, double def)
{
    for (int i = 0; i + 1 < argc; i++)
        if (strcmp(argv[i], name) == 0)
            return atof(argv[i + 1]);
    return def;
}

static int full(int argc, char **argv)
{
    Image a, b;
    if (load(argv[2], &a) || load(argv[3], &b))
        return 2;
    if (!same_size(&a, &b, argv[2], argv[3]))
        return 2;
    double rmse_max = option(argc, argv, "--rmse", 0.01);
    double threshold = option(argc, argv, "--threshold", 0.02);
    double share_max = option(argc, argv, "--share", 0.01);
    double se = 0, worst = 0;
    int wx = 0, wy = 0;
    long over = 0;
    for (int y = 0; y < a.height; y++)
        for (int x = 0; x < a.width; x++) {
            const float *p = px(&a, x, y), *q = px(&b, x, y);
            int off = 0;
            for (int k = 0; k < 3; k++) {
                double d = fabs((double)p[k] - q[k]);
                se += d * d;
                if (d > worst) {
                    worst = d;
                    wx = x;
                    wy = y;
                }
                off |= d > threshold;
            }
            over += off;
        }
    long n = (long)a.width * a.height;
    double rmse = sqrt(se / (3.0 * n)), share = (double)over / n;
    int ok = rmse <= rmse_max && share <= share_max;
    printf("rmse %.5f (limit %.3f), max error %.4f at (%d,%d), pixels off by > %.3f: %ld = %.3f%% (limit %.2f%%)\n",
           rmse, rmse_max, worst, wx, wy, threshold, over, 100 * share, 100 * share_max);
    image_free(&a);
    image_free(&b);
    return ok ? 0 : 1;
}

static int differs(const float *p, const float *q, int brighter_only)
{
    for (int k = 0; k < 3; k++) {
        double d = (double)p[k] - q[k];
        if (brighter_only ? d > MASK_EPSILON : fabs(d) > MASK_EPSILON)
            return 1;
    }
    return 0;
}

/* Is (x,y) within one pixel (8-neighbourhood) of a boundary of `mask`, or of
 * a jump in `q3`? */
static int near_edge(const unsigned char *pov_mask, const unsigned char *hst_mask, const Image *pov_q3,
                     const Image *hst_q3, int x, int y)
{
    int w = pov_q3->width, h = pov_q3->height;
    for (int dy = -2; dy <= 2; dy++)
        for (int dx = -2; dx <= 2; dx++) {
            /* a boundary between pixels a and b, a within one pixel of (x,y) */
            int ax = x + dx, ay = y + dy;
            if (abs(dx) > 1 || abs(dy) > 1 || ax < 0 || ay < 0 || ax >= w || ay >= h)
                continue;
            for (int ny = -1; ny <= 1; ny++)
                for (int nx = -1; nx <= 1; nx++) {
                    int bx = ax + nx, by = ay + ny;
                    if (bx < 0 || by < 0 || bx >= w || by >= h || (nx == 0 && ny == 0))
                        continue;
                    size_t ia = (size_t)ay * w + ax, ib = (size_t)by * w + bx;
                    if (pov_mask[ia] != pov_mask[ib] || hst_mask[ia] != hst_mask[ib])
                        return 1;
                    const float *p = px(pov_q3, ax, ay), *q = px(pov_q3, bx, by);
                    const float *r = px(hst_q3, ax, ay), *s = px(hst_q3, bx, by);
                    for (int k = 0; k < 3; k++)
                        if (fabs((double)p[k] - q[k]) > SILHOUETTE_JUMP || fabs((double)r[k] - s[k]) > SILHOUETTE_JUMP)
                            return 1;
                }
        }
    return 0;
}

static int mask(int argc, char **argv)
{
    Image pq3, pq4, hq3, hq4;
    if (load(argv[2], &pq3) || load(argv[3], &pq4) || load(argv[4], &hq3) || load(argv[5], &hq4))
        return 2;
    if (!same_size(&pq3, &pq4, argv[2], argv[3]) || !same_size(&pq3, &hq3, argv[2], argv[4]) ||
        !same_size(&pq3, &hq4, argv[2], argv[5]))
        return 2;
    double share_max = option(argc, argv, "--share", 0.001);
    int w = pq3.width, h = pq3.height;
    size_t n = (size_t)w * h;
    unsigned char *pm = calloc(n, 1), *hm = calloc(n, 1);
    if (!pm || !hm) {
        fprintf(stderr, "compare_images: out of memory\n");
        return 2;
    }
    long pov_count = 0, hst_count = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            pm[i] = (unsigned char)differs(px(&pq3, x, y), px(&pq4, x, y), 1);
            hm[i] = (unsigned char)differs(px(&hq3, x, y), px(&hq4, x, y), 0);
            pov_count += pm[i];
            hst_count += hm[i];
        }
    long edge = 0, interior = 0;
    int ix = -1, iy = -1;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            if (pm[i] == hm[i])
                continue;
            if (near_edge(pm, hm, &pq3, &hq3, x, y)) {
                edge++;
            } else {
                if (interior == 0) {
                    ix = x;
                    iy = y;
                }
                interior++;
            }
        }
    double share = (double)(edge + interior) / n;
    int ok = share <= share_max && interior == 0;
    printf("shadow masks: POV-Ray %ld px, hstrace %ld px; disagree on %ld px = %.4f%% (limit %.2f%%): "
           "%ld on edges, %ld interior",
           pov_count, hst_count, edge + interior, 100 * share, 100 * share_max, edge, interior);
    if (interior)
        printf(" (first at %d,%d)", ix, iy);
    printf("\n");
    free(pm);
    free(hm);
    image_free(&pq3);
    image_free(&pq4);
    image_free(&hq3);
    image_free(&hq4);
    return ok ? 0 : 1;
}

int main(int argc, char **argv)
{
    if (argc >= 4 && strcmp(argv[1], "full") == 0)
        return full(argc, argv);
    if (argc >= 6 && strcmp(argv[1], "mask") == 0)
        return mask(argc, argv);
    fprintf(stderr, "usage: compare_images full A B [--rmse R] [--threshold T] [--share S]\n"
                    "       compare_images mask POV_Q3 POV_Q4 HST_Q3 HST_Q4 [--share S]\n");
    return 2;
}
