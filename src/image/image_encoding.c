/* The display encoding of PNG and PPM files, as POV-Ray 3.7 computes it, or
 * through an OpenColorIO display transform. */
#include "image_codec.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

void image_transfer_init(ImageTransfer *t, double display_gamma)
{
    t->srgb = 0;
    t->neutral = 0;
    t->enc_exp = 1.0f;
    if (!(display_gamma > 0.0) || !isfinite(display_gamma)) {
        /* 0 (and anything unusable) selects the sRGB curve, POV-Ray's
         * default File_Gamma; PNG readers are told it is about 2.2. */
        t->srgb = 1;
        t->gama = 1.0 / 2.2f;
        return;
    }
    /* POV-Ray keeps the encoding exponent as a float (1.0f/gamma) and treats
     * a power law within 1% of 1 as no curve at all. */
    t->enc_exp = 1.0f / (float)display_gamma;
    t->neutral = fabs(1.0 - t->enc_exp) <= 0.01;
    t->gama = t->neutral ? 1.0 : 1.0f / (1.0f / t->enc_exp);
}

float image_transfer_encode(const ImageTransfer *t, float x)
{
    if (t->srgb) {
        if (x <= 0.0031308f)
            return x * 12.92f;
        return 1.055f * powf(x, 1.0f / 2.4f) - 0.055f;
    }
    if (t->neutral)
        return x;
    return powf(x > 0.0f ? x : 0.0f, t->enc_exp);
}

float image_transfer_decode(const ImageTransfer *t, float x)
{
    if (t->srgb) {
        if (x < 0.04045f)
            return x / 12.92f;
        return powf((x + 0.055f) / 1.055f, 2.4f);
    }
    if (t->neutral)
        return x;
    return powf(x > 0.0f ? x : 0.0f, 1.0f / t->enc_exp);
}

unsigned image_quantize(float e, unsigned max)
{
    if (!(e > 0.0f)) /* negative, zero or NaN */
        return 0;
    if (e > 1.0f)
        e = 1.0f;
    return (unsigned)floorf(e * (float)max + 0.5f);
}

/* The colour POV-Ray encodes and the alpha it stores (see image_codec.h). */
static float straight_colour(const float rgba[4], int with_alpha, float rgb[3])
{
    float r = rgba[0], g = rgba[1], b = rgba[2], a = 1.0f;

    if (with_alpha) {
        /* POV-Ray's greyscale() sums in double with these weights. */
        float bright = (float)(0.297 * r + 0.589 * g + 0.114 * b);
        float div;
        a = rgba[3];
        if (bright > a)
            a = bright < 1.0f ? bright : 1.0f;
        /* Fully transparent: divide by a tiny alpha instead (POV-Ray's
         * ALPHA_EPSILON); the stored alpha stays 0. */
        div = a == 0.0f ? 1.0e-6f : a;
        r /= div;
        g /= div;
        b /= div;
    }
    rgb[0] = r;
    rgb[1] = g;
    rgb[2] = b;
    return a;
}

void image_encode_pixel(const ImageTransfer *t, const float rgba[4], unsigned max, int with_alpha, unsigned out[4])
{
    float rgb[3];
    float a = straight_colour(rgba, with_alpha, rgb);

    if (with_alpha)
        out[3] = image_quantize(a, max);
    out[0] = image_quantize(image_transfer_encode(t, rgb[0]), max);
    out[1] = image_quantize(image_transfer_encode(t, rgb[1]), max);
    out[2] = image_quantize(image_transfer_encode(t, rgb[2]), max);
}

/* The sample of a colour channel x, 8 bits, by the curve: what
 * image_encode_pixel computes for it. */
static unsigned sample8(const ImageTransfer *t, float x) { return image_quantize(image_transfer_encode(t, x), 255); }

static float float_of_bits(uint32_t b)
{
    float f;
    memcpy(&f, &b, sizeof f);
    return f;
}

/* sample8 by the thresholds: how many are at or below x (8 halvings,
 * for building the start table below). */
static unsigned sample8_search(const float *th, float x)
{
    if (!(x > 0.0f))
        return 0; /* negative, zero or NaN: 0, as image_quantize gives */
    unsigned n = 0;
    for (unsigned step = 128; step > 0; step /= 2)
        if (th[n + step - 1] <= x) /* before each step n <= 256 - 2 step: in range */
            n += step;
    return n;
}

/* The positive floats below 2 fall in 2^15 runs of 2^15 consecutive bit
 * patterns (a 256th of a binade each: at most one or two thresholds in a
 * run, the curve being no steeper than that); START_RUNS of them. */
#define START_RUNS (1u << 15)

/* sample8 by the thresholds th and the sample at each run's start: one
 * load and a step or two, where eight dependent halvings per channel cost
 * more than the powf they replace. */
static inline unsigned sample8_by(const float *th, const unsigned char *start, float x)
{
    if (!(x > 0.0f))
        return 0;
    uint32_t b;
    memcpy(&b, &x, sizeof b);
    if (b >= START_RUNS << 15)
        return sample8_search(th, x); /* 2 and beyond (255 on any curve here), and infinity */
    unsigned n = start[b >> 15];
    while (n < 255 && th[n] <= x)
        n++;
    return n;
}

/* The 255 thresholds of sample8 (threshold[k - 1]: the least positive
 * float whose sample is k or more, found by bisection over the positive
 * floats, whose bit patterns are ordered as their values), or NULL where
 * they cannot stand for it. The curve is monotone and its float
 * evaluation within a unit in the last place of it (powf's error is below
 * 0.82 of one), so the two can differ only where the encoded value lies
 * within a few units of a rounding point of the quantization, which is
 * within a few floats of a threshold: every float within 64 of each
 * threshold is checked against sample8, and any difference drops the
 * table. x <= 0 and NaN are 0 either way. */
static float *encode_thresholds(const ImageTransfer *t)
{
    /* the thresholds, then each run's start sample (sample8_by) */
    float *th = malloc(255 * sizeof *th + START_RUNS);
    if (!th)
        return NULL;
    const uint32_t inf = 0x7f800000u;
    for (unsigned k = 1; k <= 255; k++) {
        uint32_t lo = 0, hi = inf; /* sample8(lo) < k <= sample8(hi) */
        while (hi - lo > 1) {
            uint32_t mid = lo + (hi - lo) / 2;
            if (sample8(t, float_of_bits(mid)) >= k)
                hi = mid;
            else
                lo = mid;
        }
        th[k - 1] = float_of_bits(hi);
    }
    for (unsigned k = 1; k <= 255; k++) {
        uint32_t at;
        memcpy(&at, &th[k - 1], sizeof at);
        for (uint32_t b = at > 64 ? at - 64 : 1; b <= at + 64 && b < inf; b++) {
            float x = float_of_bits(b);
            if (sample8_search(th, x) != sample8(t, x)) {
                free(th);
                return NULL;
            }
        }
    }
    unsigned char *start = (unsigned char *)(th + 255);
    for (uint32_t r = 0; r < START_RUNS; r++)
        start[r] = (unsigned char)sample8_search(th, float_of_bits(r << 15));
    return th;
}


int image_row_encoder_init(ImageRowEncoder *e, const ImageWriteOptions *opt, int width, unsigned max,
                           int with_alpha)
{
    image_transfer_init(&e->transfer, opt->display_gamma);
    e->display = opt->display;
    e->max = max;
    e->with_alpha = with_alpha != 0;
    e->width = width;
    e->samples = malloc((size_t)width * 4 * sizeof *e->samples);
    e->scratch = e->display != NULL ? malloc((size_t)width * 3 * sizeof *e->scratch) : NULL;
    /* (a table costs some 8000 powf: for rows of a real image only) */
    e->threshold = e->display == NULL && max == 255 && width >= 64 ? encode_thresholds(&e->transfer) : NULL;
    if (e->samples == NULL || (e->display != NULL && e->scratch == NULL)) {
        image_row_encoder_free(e);
        return -1;
    }
    return 0;
}

int image_row_encode(ImageRowEncoder *e, const float *rgba, char *err, int errlen)
{
    unsigned *q = e->samples;

    if (e->display == NULL) {
        /* A pixel the same as the one before (a background, a flat
         * colour) takes its encoding: the same numbers, without the three
         * powf (a few per cent of a large render). */
        for (int x = 0; x < e->width; x++) {
            const float *p = rgba + 4 * (size_t)x;
            unsigned *out = q + 4 * (size_t)x;
            if (x > 0 && memcmp(p, p - 4, 4 * sizeof *p) == 0) {
                memcpy(out, out - 4, 4 * sizeof *q);
            } else if (e->threshold) {
                float rgb[3];
                float a = straight_colour(p, e->with_alpha, rgb);
                if (e->with_alpha)
                    out[3] = image_quantize(a, e->max);
                for (int c = 0; c < 3; c++)
                    out[c] = sample8_by(e->threshold, (const unsigned char *)(e->threshold + 255), rgb[c]);
            } else {
                image_encode_pixel(&e->transfer, p, e->max, e->with_alpha, out);
            }
        }
        return 0;
    }
    for (int x = 0; x < e->width; x++) {
        float a = straight_colour(rgba + 4 * (size_t)x, e->with_alpha, e->scratch + 3 * (size_t)x);
        if (e->with_alpha)
            q[4 * (size_t)x + 3] = image_quantize(a, e->max);
    }
    if (colour_display_apply(e->display, e->scratch, e->width, err, errlen) != 0)
        return -1;
    for (int x = 0; x < e->width; x++)
        for (int c = 0; c < 3; c++)
            q[4 * (size_t)x + (size_t)c] = image_quantize(e->scratch[3 * (size_t)x + (size_t)c], e->max);
    return 0;
}

void image_row_encoder_free(ImageRowEncoder *e)
{
    free(e->samples);
    free(e->scratch);
    free(e->threshold);
    e->samples = NULL;
    e->scratch = NULL;
    e->threshold = NULL;
}

float *image_transfer_decode_table(const ImageTransfer *t, unsigned max)
{
    float *lut = malloc(((size_t)max + 1) * sizeof *lut);
    if (lut == NULL)
        return NULL;
    for (unsigned i = 0; i <= max; i++)
        lut[i] = image_transfer_decode(t, (float)i / (float)max);
    return lut;
}

int image_grow_rows(Image *img, int y, int rows, int *cap)
{
    if (y < *cap)
        return 0;
    int more = *cap * 2 < rows ? *cap * 2 : rows;
    float *bigger = realloc(img->rgba, (size_t)more * (size_t)img->width * 4 * sizeof(float));
    if (bigger == NULL)
        return -1;
    img->rgba = bigger;
    *cap = more;
    return 0;
}

void image_set_error(char *err, int errlen, const char *fmt, ...)
{
    va_list ap;
    if (err == NULL || errlen <= 0)
        return;
    va_start(ap, fmt);
    vsnprintf(err, (size_t)errlen, fmt, ap);
    va_end(ap);
}
