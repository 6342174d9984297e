/* Shadow masks from +Q3/+Q4 render pairs, compared with edges and
 * silhouettes told apart from interior errors (rules in mask_compare.h). */
#include "mask_compare.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "image_compare.h"

/* A pixel is in a shadow mask when some channel changes by more than this
 * between the +Q3 and +Q4 renders. Renders are often half floats: 11
 * significant bits, so neighbouring representable values are 2^-11 = 4.9e-4
 * apart below 1.0, 9.8e-4 below 2.0 and 1.95e-3 below 4.0. A float rounding
 * difference inside a renderer (the same light sum computed in another order)
 * can flip the rounding to half by one step; 2e-3 is above one step for any
 * value below 4, far brighter than lit surfaces usually are, so rounding
 * cannot make a mask pixel. Per channel rather than summed over RGB, so
 * one-step flips in three channels cannot add up, and so the shadow of a
 * saturated coloured light (one channel) counts in full. A light whose
 * contribution is below 2e-3 in every channel casts a shadow of at most about
 * one 8-bit sRGB code value in dark regions (and less elsewhere): not
 * visible, not counted. */
#define MASK_EPSILON 2e-3
/* Silhouettes and texture edges, in a shadowless (+Q3) render: neighbouring
 * pixels differing by more than this in a channel. Within one surface the
 * change from one pixel to the next comes from the lights' angles and
 * distances and is well below 0.01 at 320x240 (larger only very close to a
 * fading light or inside a tight highlight); across an object edge the
 * pigment or the facing changes and the jump is larger. */
#define SILHOUETTE_JUMP 0.05

enum { AGREE = 0, AT_EDGE = 1, AWAY = 3 }; /* verdicts */

/* Is q3 brighter than q4 in some channel (brighter_only), or different? */
static int changed(const float *q3, const float *q4, int brighter_only)
{
    for (int k = 0; k < 3; k++) {
        double d = (double)q3[k] - q4[k];
        if (brighter_only ? d > MASK_EPSILON : fabs(d) > MASK_EPSILON)
            return 1;
    }
    return 0;
}

/* edge[i] = 1 where pixel i differs from one of its 8 neighbours by more
 * than `jump` in a channel of img (RGBA), or (mask != NULL) in mask value. */
static void find_edges(const unsigned char *mask, const float *img, double jump, int w, int h, unsigned char *edge)
{
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            edge[i] = 0;
            for (int dy = -1; dy <= 1 && !edge[i]; dy++)
                for (int dx = -1; dx <= 1 && !edge[i]; dx++) {
                    int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h)
                        continue;
                    size_t j = (size_t)ny * w + nx;
                    if (mask && mask[i] != mask[j])
                        edge[i] = 1;
                    for (int k = 0; k < 3; k++)
                        if (fabs((double)img[i * 4 + k] - img[j * 4 + k]) > jump)
                            edge[i] = 1;
                }
        }
}

/* Is there an edge pixel within one pixel (8-neighbourhood) of (x,y)? */
static int near(const unsigned char *edge, int w, int h, int x, int y)
{
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            int nx = x + dx, ny = y + dy;
            if (nx >= 0 && ny >= 0 && nx < w && ny < h && edge[(size_t)ny * w + nx])
                return 1;
        }
    return 0;
}

/* B's shadow loss is at least A's in every channel: A let more light
 * through (or the same). */
static int b_blocks_more(const float *aloss, const float *bloss, double tol)
{
    for (int k = 0; k < 3; k++)
        if (bloss[k] < aloss[k] - tol)
            return 0;
    return 1;
}

static void paint_map(Image *map, const unsigned char *am, const unsigned char *bm, const unsigned char *verdict,
                      const unsigned char *sil)
{
    size_t n = (size_t)map->width * map->height;
    for (size_t i = 0; i < n; i++) {
        float c[3] = {0, 0, 0};
        float v = verdict[i] == AWAY ? 1.0f : 0.45f;
        if (verdict[i] && am[i] && !bm[i]) {
            c[0] = v; /* red: shadowed in A only */
        } else if (verdict[i] && !am[i] && bm[i]) {
            c[1] = v; /* green: shadowed in B only */
        } else if (verdict[i]) {
            c[0] = c[2] = v; /* magenta: shadowed in both, from other lights */
        } else if (am[i]) {
            c[0] = c[1] = c[2] = 0.2f; /* grey: shadowed in both */
        } else if (sil[i]) {
            c[2] = 0.15f; /* dark blue: silhouette */
        }
        float *o = &map->rgba[i * 4];
        o[0] = c[0];
        o[1] = c[1];
        o[2] = c[2];
        o[3] = 1;
    }
}

int mask_compare(const Image *a3, const Image *a4, const Image *b3, const Image *b4, const MaskCompareOptions *opt,
                 MaskComparison *out, Image *map)
{
    const Image *img[4] = {a3, a4, b3, b4};
    int w = a3->width, h = a3->height;
    for (int k = 0; k < 4; k++)
        if (!img[k]->rgba || img[k]->width != w || img[k]->height != h || w <= 0 || h <= 0)
            return -1;
    size_t n = (size_t)w * h;
    double tol = opt->loss_tolerance;
    unsigned char *buf = calloc(n, 8);
    /* shadow losses, +Q3 minus +Q4, as RGBA: A's, B's */
    float *aloss = malloc(n * 4 * sizeof *aloss), *bloss = malloc(n * 4 * sizeof *bloss);
    if (!buf || !aloss || !bloss || (map && image_alloc(map, w, h))) {
        free(buf);
        free(aloss);
        free(bloss);
        return -1;
    }
    unsigned char *am = buf, *bm = buf + n;                   /* the masks */
    unsigned char *aedge = buf + 2 * n, *bedge = buf + 3 * n; /* their shadow edges */
    unsigned char *asil = buf + 4 * n, *bsil = buf + 5 * n;   /* silhouettes */
    unsigned char *verdict = buf + 6 * n, *sil = buf + 7 * n;
    for (size_t i = 0; i < n * 4; i++) {
        aloss[i] = a3->rgba[i] - a4->rgba[i];
        bloss[i] = b3->rgba[i] - b4->rgba[i];
    }

    MaskComparison c = {.width = w, .height = h, .interior_x = -1, .interior_y = -1};
    for (int k = 0; k < 4; k++)
        c.nonfinite += image_count_nonfinite(img[k]);
    for (size_t i = 0; i < n; i++) {
        am[i] = (unsigned char)changed(&a3->rgba[i * 4], &a4->rgba[i * 4], 1);
        bm[i] = (unsigned char)changed(&b3->rgba[i * 4], &b4->rgba[i * 4], 0);
        c.a_pixels += am[i];
        c.b_pixels += bm[i];
    }
    find_edges(am, aloss, tol, w, h, aedge);
    find_edges(bm, bloss, tol, w, h, bedge);
    find_edges(NULL, a3->rgba, SILHOUETTE_JUMP, w, h, asil);
    find_edges(NULL, b3->rgba, SILHOUETTE_JUMP, w, h, bsil);

    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            sil[i] = asil[i] || bsil[i];
            int loss_off = 0;
            for (int k = 0; k < 3; k++)
                loss_off |= fabs((double)aloss[i * 4 + k] - bloss[i * 4 + k]) > tol;
            if (am[i] == bm[i] && !loss_off)
                continue;
            c.other_lights += am[i] == bm[i];
            if (near(aedge, w, h, x, y) && near(bedge, w, h, x, y)) {
                c.shadow_edge++;
                verdict[i] = AT_EDGE;
            } else if (near(asil, w, h, x, y) && near(bsil, w, h, x, y)) {
                c.silhouette++;
                verdict[i] = AT_EDGE;
            } else if (opt->allow_a_leaks && b_blocks_more(aloss + i * 4, bloss + i * 4, tol) && bm[i] >= am[i]) {
                c.a_leaks++;
                verdict[i] = AWAY;
            } else {
                verdict[i] = AWAY;
                if (c.interior == 0) {
                    c.interior_x = x;
                    c.interior_y = y;
                }
                c.interior++;
            }
        }
    c.disagree = c.shadow_edge + c.silhouette + c.interior + c.a_leaks;
    c.share = (double)c.disagree / (double)n;
    if (map)
        paint_map(map, am, bm, verdict, sil);
    free(buf);
    free(aloss);
    free(bloss);
    *out = c;
    return 0;
}

int mask_pair_from_loss(const Image *render, const float *const loss[3], Image *q3, Image *q4)
{
    int w = render->width, h = render->height;
    if (image_alloc(q3, w, h) || image_alloc(q4, w, h)) {
        image_free(q3);
        image_free(q4);
        return -1;
    }
    size_t n = (size_t)w * h;
    memcpy(q4->rgba, render->rgba, n * 4 * sizeof(float));
    memcpy(q3->rgba, render->rgba, n * 4 * sizeof(float));
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++)
            q3->rgba[i * 4 + k] += loss[k][i];
    return 0;
}
