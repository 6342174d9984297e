/* POV-Ray 3.7's anti-aliasing methods 1 and 2 (antialias.h). */
#include "antialias.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "noise.h"

#define POV_EPSILON 1.0e-10 /* POV-Ray's EPSILON, which ends its sample loops */

/* ---- POV-Ray's jitter -------------------------------------------------------
 * POV-Ray 3.7 offsets a sample by an entry of a 256-entry table picked by
 * hashing the sample's coordinates through its noise hash table. The table
 * is, entry by entry (worked out from its values, which it reproduces all):
 * in 16-bit fixed point, the parity of i's bits in bits 15 and 1, i's Gray
 * code from bit 8 up and i's lowest bit in bit 7, modulo 2^16, less one
 * half; POV-Ray keeps each with 6 decimals, in single precision. Built once,
 * then only read. */
static float jitter_table[256];
static pthread_once_t jitter_once = PTHREAD_ONCE_INIT;

static void build_jitter_table(void)
{
    for (unsigned i = 0; i < 256; i++) {
        unsigned parity = 0;
        for (unsigned b = i; b; b >>= 1)
            parity ^= b & 1u;
        unsigned k = (parity * 32770u + (i ^ (i >> 1)) * 256u + (i & 1u) * 128u) & 0xffffu;
        char printed[32];
        snprintf(printed, sizeof printed, "%.6f", k / 65536.0 - 0.5);
        jitter_table[i] = strtof(printed, NULL);
    }
}

/* POV-Ray's Jitter2d for a sample at pixel coordinates (x, y): the offsets
 * in x and in y, each from -0.5 to 0.5. */
static void jitter(double x, double y, double *jx, double *jy)
{
    pthread_once(&jitter_once, build_jitter_table);
    int x1 = (int)(x * 1021.0), y1 = (int)(y * 1019.0), x2 = (int)(x * 1019.0), y2 = (int)(y * 1021.0);
    *jx = jitter_table[noise_hash((unsigned)(((int)noise_hash((unsigned)(x1 & 0xfff)) ^ y1) & 0xfff)) & 0xffu];
    *jy = jitter_table[noise_hash((unsigned)(((int)noise_hash((unsigned)(x2 & 0xfff)) ^ y2) & 0xfff)) & 0xffu];
}

typedef struct {
    const Antialias *aa;
    float threshold;  /* as POV-Ray reads it: single precision */
    float encode;     /* the gamma curve's exponent, 1 / Antialias_Gamma (0: none) */
    float decode;     /* the working gamma's (0: none) */
    double jitter;    /* the jitter's scale, in pixels (0: none) */
    AaTrace trace;
    void *user;
} Sampler;

static AaColour encoded(const Sampler *s, AaColour c)
{
    if (s->decode > 0.0f)
        for (int i = 0; i < 3; i++)
            c.c[i] = powf(fmaxf(c.c[i], 0.0f), s->decode);
    if (s->encode > 0.0f)
        for (int i = 0; i < 3; i++)
            c.c[i] = powf(fmaxf(c.c[i], 0.0f), s->encode);
    return c;
}

/* Red, green, blue and transmit's absolute differences of two encoded
 * colours, summed. */
static int differ_encoded(const Sampler *s, const AaColour *ga, const AaColour *gb)
{
    float d = fabsf(ga->c[0] - gb->c[0]) + fabsf(ga->c[1] - gb->c[1]) + fabsf(ga->c[2] - gb->c[2]) +
              fabsf(ga->c[3] - gb->c[3]);
    return d >= s->threshold;
}

static int differ(const Sampler *s, AaColour a, AaColour b)
{
    AaColour ga = encoded(s, a), gb = encoded(s, b);
    return differ_encoded(s, &ga, &gb);
}

static void add(AaColour *a, const AaColour *b)
{
    for (int i = 0; i < 4; i++)
        a->c[i] += b->c[i];
}

static void scale(AaColour *a, double by)
{
    for (int i = 0; i < 4; i++)
        a->c[i] = (float)(a->c[i] * by);
}

/* A sample at (x, y), moved by the jitter when it is on. */
static void trace_at(const Sampler *s, double x, double y, AaColour *out)
{
    if (s->jitter > 0.0) {
        double jx, jy;
        jitter(x, y, &jx, &jy);
        x += jx * s->jitter;
        y += jy * s->jitter;
    }
    s->trace(s->user, x, y, out);
}

/* Method 1: a depth x depth grid across pixel (x, y), averaged with the
 * centre sample already in *col. */
static void supersample(const Sampler *s, double x, double y, AaColour *col)
{
    int depth = s->aa->depth;
    double step = 1.0 / depth, range = 0.5 - step * 0.5;
    for (double yy = -range; yy <= range + POV_EPSILON; yy += step) {
        for (double xx = -range; xx <= range + POV_EPSILON; xx += step) {
            AaColour t;
            trace_at(s, x + xx, y + yy, &t);
            add(col, &t);
        }
    }
    for (int i = 0; i < 4; i++)
        col->c[i] /= (float)(depth * depth + 1);
}

static int method1(const Sampler *s, int left, int top, int right, int bottom, AaColour *out)
{
    int bw = right - left + 1, bh = bottom - top + 1;
    /* The row above the block and the column left of it: compared with,
     * never supersampled (they count as done). */
    AaColour *above = malloc(sizeof *above * (size_t)bw), *beside = malloc(sizeof *beside * (size_t)bh);
    unsigned char *done = calloc((size_t)bw * (size_t)bh, 1);
    /* Each colour's encoding beside it (enc_*), made once when the colour
     * is made or supersampled: every pixel is compared with its left and
     * upper neighbours, and encoding took three powf each time (some 8% of
     * an anti-aliased render). The same encodings, so the same answers. */
    AaColour *enc = malloc(sizeof *enc * (size_t)bw * (size_t)bh), *enc_above = malloc(sizeof *enc_above * (size_t)bw),
             *enc_beside = malloc(sizeof *enc_beside * (size_t)bh);
    if (!above || !beside || !done || !enc || !enc_above || !enc_beside) {
        free(above);
        free(beside);
        free(done);
        free(enc);
        free(enc_above);
        free(enc_beside);
        return -1;
    }
    for (int x = left; x <= right; x++) {
        s->trace(s->user, x, top - 1.0, &above[x - left]);
        enc_above[x - left] = encoded(s, above[x - left]);
    }
    for (int y = top; y <= bottom; y++) {
        s->trace(s->user, left - 1.0, y, &beside[y - top]);
        enc_beside[y - top] = encoded(s, beside[y - top]);
        for (int x = left; x <= right; x++) {
            const int at = (y - top) * bw + (x - left);
            AaColour *cur = &out[at], *enc_cur = &enc[at];
            s->trace(s->user, x, y, cur);
            *enc_cur = encoded(s, *cur);
            AaColour *lft = x > left ? cur - 1 : &beside[y - top];
            AaColour *enc_lft = x > left ? enc_cur - 1 : &enc_beside[y - top];
            AaColour *up = y > top ? cur - bw : &above[x - left];
            AaColour *enc_up = y > top ? enc_cur - bw : &enc_above[x - left];
            unsigned char *cur_done = &done[at];
            int left_open = x > left && !cur_done[-1], up_open = y > top && !cur_done[-bw];
            int left_diff = differ_encoded(s, enc_lft, enc_cur), up_diff = differ_encoded(s, enc_up, enc_cur);
            if (left_open && left_diff) {
                supersample(s, x - 1.0, y, lft);
                *enc_lft = encoded(s, *lft);
                cur_done[-1] = 1;
            }
            if (up_open && up_diff) {
                supersample(s, x, y - 1.0, up);
                *enc_up = encoded(s, *up);
                cur_done[-bw] = 1;
            }
            if (left_diff || up_diff) {
                supersample(s, x, y, cur);
                *enc_cur = encoded(s, *cur);
                *cur_done = 1;
            }
        }
    }
    free(above);
    free(beside);
    free(done);
    free(enc);
    free(enc_above);
    free(enc_beside);
    return 0;
}

/* Method 2's samples of one pixel: a (2^depth + 1)^2 lattice, each point
 * traced at most once. */
typedef struct {
    AaColour *c;
    unsigned char *have;
    int size;
} Lattice;

static AaColour *at(Lattice *l, int i, int j)
{
    return &l->c[i + j * l->size];
}

static void sample_once(const Sampler *s, Lattice *l, int i, int j, double x, double y)
{
    if (!l->have[i + j * l->size]) {
        trace_at(s, x, y, at(l, i, j));
        l->have[i + j * l->size] = 1;
    }
}

/* The square of the lattice from (i, j), `step` wide, centred on (x, y),
 * half of it d: its mean, cut in four while its corners differ. */
static AaColour subdivide(const Sampler *s, Lattice *l, double x, double y, double d, int i, int j, int step,
                          int level)
{
    AaColour c00 = *at(l, i, j), c01 = *at(l, i, j + step), c10 = *at(l, i + step, j), c11 = *at(l, i + step, j + step);
    int h = step / 2;
    if (level > 0 && (differ(s, c00, c01) || differ(s, c00, c10) || differ(s, c00, c11) || differ(s, c01, c10) ||
                      differ(s, c01, c11) || differ(s, c10, c11))) {
        sample_once(s, l, i, j + h, x - d, y);
        sample_once(s, l, i + h, j, x, y - d);
        sample_once(s, l, i + step, j + h, x + d, y);
        sample_once(s, l, i + h, j + step, x, y + d);
        sample_once(s, l, i + h, j + h, x, y);
        double d2 = d * 0.5;
        AaColour q[4] = { subdivide(s, l, x - d2, y - d2, d2, i, j, h, level - 1),
                          subdivide(s, l, x - d2, y + d2, d2, i, j + h, h, level - 1),
                          subdivide(s, l, x + d2, y - d2, d2, i + h, j, h, level - 1),
                          subdivide(s, l, x + d2, y + d2, d2, i + h, j + h, h, level - 1) };
        add(&q[0], &q[1]);
        add(&q[0], &q[2]);
        add(&q[0], &q[3]);
        scale(&q[0], 0.25);
        return q[0];
    }
    add(&c00, &c01);
    add(&c00, &c10);
    add(&c00, &c11);
    scale(&c00, 0.25);
    return c00;
}

static int method2(const Sampler *s, int left, int top, int right, int bottom, AaColour *out)
{
    int bw = right - left + 1, bh = bottom - top + 1, cw = bw + 1;
    int size = (1 << s->aa->depth) + 1;
    /* Every pixel's upper-left corner, and the row and column past the block. */
    AaColour *corner = malloc(sizeof *corner * (size_t)cw * (size_t)(bh + 1));
    Lattice l = { malloc(sizeof(AaColour) * (size_t)size * (size_t)size), malloc((size_t)size * (size_t)size), size };
    if (!corner || !l.c || !l.have) {
        free(corner);
        free(l.c);
        free(l.have);
        return -1;
    }
    for (int y = top; y <= bottom + 1; y++)
        for (int x = left; x <= right + 1; x++)
            s->trace(s->user, x - 0.5, y - 0.5, &corner[(y - top) * cw + (x - left)]);
    int last = size - 1;
    for (int y = top; y <= bottom; y++) {
        for (int x = left; x <= right; x++) {
            memset(l.have, 0, (size_t)size * (size_t)size);
            const AaColour *c = &corner[(y - top) * cw + (x - left)];
            *at(&l, 0, 0) = c[0];
            *at(&l, 0, last) = c[cw];
            *at(&l, last, 0) = c[1];
            *at(&l, last, last) = c[cw + 1];
            l.have[0] = l.have[last * size] = l.have[last] = l.have[last + last * size] = 1;
            out[(y - top) * bw + (x - left)] = subdivide(s, &l, x, y, 0.5, 0, 0, last, s->aa->depth - 1);
        }
    }
    free(corner);
    free(l.c);
    free(l.have);
    return 0;
}

int antialias_block(const Antialias *aa, int left, int top, int right, int bottom, AaTrace trace, void *user,
                    AaColour *out)
{
    /* The jitter's amount is spread over the samples' spacing, as POV-Ray
     * spreads it: depth for method 1, 2^depth + 1 for method 2. */
    double spacing = aa->method == 2 ? (double)((1 << aa->depth) + 1) : (double)aa->depth;
    Sampler s = { aa, (float)aa->threshold, aa->gamma > 0.0 ? (float)(1.0 / aa->gamma) : 0.0f,
                  aa->work_gamma > 0.0 && aa->work_gamma != 1.0 ? (float)aa->work_gamma : 0.0f,
                  aa->jitter > 0.0 ? aa->jitter / spacing : 0.0, trace, user };
    return aa->method == 2 ? method2(&s, left, top, right, bottom, out) : method1(&s, left, top, right, bottom, out);
}
