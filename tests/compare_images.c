/* compare_images: the figures the regression tests assert, computed in
 * linear RGB from EXR files (PNG and PPM are decoded back to linear too).
 *
 *   compare_images full A B [--rmse R] [--threshold T] [--share S]
 *       RMSE over all RGB samples of all pixels, the largest error and where,
 *       and the share of pixels with any channel off by more than T (default
 *       0.02). Exit 0 when RMSE <= R and share <= S (defaults 0.01 and 0.01).
 *
 *   compare_images mask POV_Q3 POV_Q4 HST_Q3 HST_Q4 [--share S] [--map FILE] [--pov-leaks-ok 1]
 *       Compares shadow masks. POV-Ray's mask is where its +Q3 (no shadows)
 *       render is brighter than its +Q4 (shadows) render; hstrace's is where
 *       its own +Q3 and +Q4 renders differ at all (either way: hstrace being
 *       brighter with shadows would be a bug, and counts as a difference).
 *       With three lights nearly every pixel is in shadow from one of them,
 *       so the masks alone say little; the shadow loss (+Q3 minus +Q4, per
 *       channel) tells which lights are blocked, since they differ in colour
 *       and strength. A pixel disagrees when it is in one mask only, or when
 *       the two renderers' shadow losses differ by more than 0.02 in a
 *       channel (the same per-pixel tolerance as `full`): shadowed in both,
 *       but from different lights.
 *       Exit 0 when at most S of the pixels disagree (default 0.001 = 0.1%)
 *       AND every disagreeing pixel is explained by an edge:
 *         - it lies within one pixel (8-neighbourhood) of a shadow edge in
 *           POV-Ray's render pair AND within one pixel of one in hstrace's:
 *           the same shadow edge is in both, displaced by about a pixel; or
 *         - it lies within one pixel of a silhouette in POV-Ray's +Q3 render
 *           AND within one pixel of one in hstrace's +Q3 render: the visible
 *           surface changes there, and sub-pixel differences in geometry
 *           decide which surface (and so which shadow) a pixel shows.
 *       A shadow-edge pixel is one whose mask value differs from one of its 8
 *       neighbours', or whose shadow loss differs from a neighbour's by more
 *       than 0.02 in a channel. Requiring the edge in both matters: a pixel on
 *       which the masks disagree is nearly always on a boundary of one of them
 *       (an isolated wrong pixel is a boundary of the mask it is wrong in), so
 *       "a boundary of either mask" would excuse any stray shadow pixel and
 *       any missing shadow up to 3 pixels wide.
 *       --pov-leaks-ok 1: disagreeing pixels away from any edge where
 *       hstrace's shadow loss is at least POV-Ray's in every channel (POV-Ray
 *       let more light through: its ray/triangle test leaks through the
 *       shared edges of a mesh, hstrace's is watertight) are counted apart as
 *       POV-Ray's leaks instead of failing; for scenes built to aim shadow
 *       rays at shared edges. Pixels where hstrace lets more light through
 *       still fail.
 *       --map FILE writes the verdict as an image: black lit in both, dark
 *       grey shadowed in both, dark blue silhouettes; disagreements in red
 *       (shadowed in POV-Ray only), green (in hstrace only) or magenta
 *       (shadowed in both, from other lights), dim when at an edge, bright
 *       when not.
 *
 *   compare_images encoded LINEAR DISPLAY --curve srgb|povray|gamma|raw [--gamma G] [--steps N]
 *       Checks the display encoding of a PNG or PPM: every RGB sample of
 *       DISPLAY (read as its integer codes) against the code the curve gives
 *       the same sample of LINEAR (an EXR): srgb is IEC 61966-2-1's formula
 *       in double precision, povray hstrace's own POV-Ray encoder, gamma a
 *       pure power 1/G (default 2.2), raw no curve; all clamp to 0..1 and
 *       round. Exit 0 when no sample is more than N codes off (default 1).
 *
 * Prints its figures on one line. Exit status 1 when outside the limits (or
 * when an image holds NaN or infinite values), 2 on bad usage, unreadable
 * files or mismatched sizes. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "image.h"
#include "image_codec.h"

/* A pixel is in a shadow mask when some channel changes by more than this
 * between the +Q3 and +Q4 renders. The renders are half floats: 11
 * significant bits, so neighbouring representable values are 2^-11 = 4.9e-4
 * apart below 1.0, 9.8e-4 below 2.0 and 1.95e-3 below 4.0. A float rounding
 * difference inside a renderer (the same light sum computed in another order)
 * can flip the rounding to half by one step; 2e-3 is above one step for any
 * value below 4, far brighter than these scenes, so rounding cannot make a
 * mask pixel. Per channel rather than summed over RGB, so one-step flips in
 * three channels cannot add up, and so the shadow of a saturated coloured
 * light (one channel) counts in full. A light whose contribution is below
 * 2e-3 in every channel casts a shadow of at most about one 8-bit sRGB code
 * value in dark regions (and less elsewhere): not visible, not counted. */
#define MASK_EPSILON 2e-3
/* Silhouettes and texture edges, in a shadowless (+Q3) render: neighbouring
 * pixels differing by more than this in a channel. Within one surface the
 * change from one pixel to the next comes from the lights' angles and
 * distances and is well below 0.01 at 320x240 (larger only very close to a
 * fading light or inside a tight highlight); across an object edge the
 * pigment or the facing changes and the jump is larger. */
#define SILHOUETTE_JUMP 0.05
/* Shadow losses (+Q3 minus +Q4) of the two renderers agree when no channel
 * differs by more than this: the per-pixel tolerance of the full-image test.
 * Also the jump between neighbouring pixels' losses that makes a shadow
 * edge: hard shadows jump by a light's whole contribution. */
#define LOSS_TOL 0.02

static int load(const char *path, Image *img)
{
    char err[512];
    img->rgba = NULL;
    if (image_read(path, img, 0.0, err, sizeof err)) {
        fprintf(stderr, "compare_images: %s\n", err);
        return -1;
    }
    if (img->width <= 0 || img->height <= 0 || !img->rgba) {
        fprintf(stderr, "compare_images: '%s' holds no pixels\n", path);
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

static long count_nonfinite(const Image *img)
{
    long bad = 0;
    size_t n = (size_t)img->width * img->height;
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++)
            if (!isfinite(img->rgba[i * 4 + k])) {
                bad++;
                break;
            }
    return bad;
}

/* Options after the file names: `--name value`. Unknown options, missing or
 * malformed values are usage errors. */
typedef struct {
    const char *name;
    double *value; /* a non-negative number, or NULL for a string option */
    const char **str;
} Option;

static int parse_options(int argc, char **argv, int first, const Option *opts, int nopts)
{
    for (int i = first; i < argc; i += 2) {
        const Option *o = NULL;
        for (int j = 0; j < nopts; j++)
            if (strcmp(argv[i], opts[j].name) == 0)
                o = &opts[j];
        if (!o) {
            fprintf(stderr, "compare_images: unknown argument '%s'\n", argv[i]);
            return -1;
        }
        if (i + 1 >= argc) {
            fprintf(stderr, "compare_images: %s needs a value\n", argv[i]);
            return -1;
        }
        if (o->str) {
            *o->str = argv[i + 1];
            continue;
        }
        char *end;
        double v = strtod(argv[i + 1], &end);
        if (end == argv[i + 1] || *end != '\0' || !isfinite(v) || v < 0) {
            fprintf(stderr, "compare_images: %s wants a non-negative number, not '%s'\n", argv[i], argv[i + 1]);
            return -1;
        }
        *o->value = v;
    }
    return 0;
}

static void usage(void)
{
    fprintf(stderr, "usage: compare_images full A B [--rmse R] [--threshold T] [--share S]\n"
                    "       compare_images mask POV_Q3 POV_Q4 HST_Q3 HST_Q4 [--share S] [--map FILE] [--pov-leaks-ok 1]\n"
                    "       compare_images encoded LINEAR DISPLAY --curve srgb|povray|gamma|raw [--gamma G] [--steps N]\n");
}

static int full(int argc, char **argv)
{
    double rmse_max = 0.01, threshold = 0.02, share_max = 0.01;
    const Option opts[] = {{"--rmse", &rmse_max, NULL}, {"--threshold", &threshold, NULL}, {"--share", &share_max, NULL}};
    if (parse_options(argc, argv, 4, opts, 3)) {
        usage();
        return 2;
    }
    Image a, b;
    if (load(argv[2], &a))
        return 2;
    if (load(argv[3], &b)) {
        image_free(&a);
        return 2;
    }
    if (!same_size(&a, &b, argv[2], argv[3])) {
        image_free(&a);
        image_free(&b);
        return 2;
    }
    long bad = count_nonfinite(&a) + count_nonfinite(&b);
    double se = 0, worst = 0;
    int wx = 0, wy = 0;
    long over = 0;
    for (int y = 0; y < a.height; y++)
        for (int x = 0; x < a.width; x++) {
            const float *p = px(&a, x, y), *q = px(&b, x, y);
            int off = 0;
            for (int k = 0; k < 3; k++) {
                double d = fabs((double)p[k] - q[k]);
                if (!isfinite(d))
                    continue; /* counted in `bad`, which fails the test */
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
    int ok = rmse <= rmse_max && share <= share_max && bad == 0;
    printf("rmse %.5f (limit %.3f), max error %.4f at (%d,%d), pixels off by > %.3f: %ld = %.3f%% (limit %.2f%%)",
           rmse, rmse_max, worst, wx, wy, threshold, over, 100 * share, 100 * share_max);
    if (bad)
        printf(", %ld pixels hold NaN or infinity", bad);
    printf("\n");
    image_free(&a);
    image_free(&b);
    return ok ? 0 : 1;
}

static double srgb_formula(double x)
{
    return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1 / 2.4) - 0.055;
}

static int encoded(int argc, char **argv)
{
    double steps = 1, gamma = 2.2;
    const char *curve = NULL;
    const Option opts[] = {{"--steps", &steps, NULL}, {"--gamma", &gamma, NULL}, {"--curve", NULL, &curve}};
    if (parse_options(argc, argv, 4, opts, 3) || curve == NULL ||
        (strcmp(curve, "srgb") && strcmp(curve, "povray") && strcmp(curve, "gamma") && strcmp(curve, "raw")) ||
        !(gamma > 0)) {
        usage();
        return 2;
    }
    Image lin, disp;
    char err[512];
    if (load(argv[2], &lin))
        return 2;
    /* Gamma 1 reads the codes as they are: sample = code / 255. */
    disp.rgba = NULL;
    if (image_read(argv[3], &disp, 1.0, err, sizeof err)) {
        fprintf(stderr, "compare_images: %s\n", err);
        image_free(&lin);
        return 2;
    }
    if (!same_size(&lin, &disp, argv[2], argv[3])) {
        image_free(&lin);
        image_free(&disp);
        return 2;
    }
    ImageTransfer pov;
    image_transfer_init(&pov, 0.0);
    long off = 0, n = (long)lin.width * lin.height;
    double worst = 0;
    for (long i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) {
            float x = lin.rgba[4 * i + k];
            double e;
            if (strcmp(curve, "povray") == 0)
                e = image_transfer_encode(&pov, x);
            else if (strcmp(curve, "srgb") == 0)
                e = srgb_formula(x > 0 ? x : 0);
            else if (strcmp(curve, "gamma") == 0)
                e = pow(x > 0 ? x : 0, 1 / gamma);
            else
                e = x;
            long want = (long)image_quantize((float)e, 255);
            long got = lround(disp.rgba[4 * i + k] * 255.0);
            double d = fabs((double)(got - want));
            off += d > 0;
            if (d > worst)
                worst = d;
        }
    printf("curve %s: %ld of %ld samples differ, by at most %.0f codes (limit %.0f)\n", curve, off, 3 * n, worst,
           steps);
    image_free(&lin);
    image_free(&disp);
    return worst <= steps ? 0 : 1;
}

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
 * than `jump` in a channel of img, or (mask != NULL) in mask value. */
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

static int write_map(const char *path, const unsigned char *pm, const unsigned char *hm, const unsigned char *verdict,
                     const unsigned char *sil, int w, int h)
{
    Image map;
    if (image_alloc(&map, w, h)) {
        fprintf(stderr, "compare_images: out of memory\n");
        return -1;
    }
    for (size_t i = 0; i < (size_t)w * h; i++) {
        float c[3] = {0, 0, 0};
        float v = verdict[i] == 3 ? 1.0f : 0.45f; /* bright: not at an edge */
        if (verdict[i] && pm[i] && !hm[i]) {
            c[0] = v; /* red: shadowed in POV-Ray only */
        } else if (verdict[i] && !pm[i] && hm[i]) {
            c[1] = v; /* green: shadowed in hstrace only */
        } else if (verdict[i]) {
            c[0] = c[2] = v; /* magenta: shadowed in both, from other lights */
        } else if (pm[i]) {
            c[0] = c[1] = c[2] = 0.2f; /* grey: shadowed in both */
        } else if (sil[i]) {
            c[2] = 0.15f; /* dark blue: silhouette */
        }
        float *o = &map.rgba[i * 4];
        o[0] = c[0];
        o[1] = c[1];
        o[2] = c[2];
        o[3] = 1;
    }
    ImageWriteOptions wo;
    memset(&wo, 0, sizeof wo);
    char err[512];
    int rc = image_write(path, &map, &wo, err, sizeof err);
    if (rc)
        fprintf(stderr, "compare_images: %s\n", err);
    image_free(&map);
    return rc;
}

/* hstrace's shadow loss is at least POV-Ray's in every channel: POV-Ray let
 * more light through (or the same). */
static int hstrace_blocks_more(const float *ploss, const float *hloss)
{
    for (int k = 0; k < 3; k++)
        if (hloss[k] < ploss[k] - LOSS_TOL)
            return 0;
    return 1;
}

static int mask(int argc, char **argv)
{
    double share_max = 0.001, pov_leaks_ok = 0.0;
    const char *map_path = NULL;
    const Option opts[] = {{"--share", &share_max, NULL}, {"--map", NULL, &map_path}, {"--pov-leaks-ok", &pov_leaks_ok, NULL}};
    if (parse_options(argc, argv, 6, opts, 3)) {
        usage();
        return 2;
    }
    Image img[4]; /* POV-Ray +Q3, +Q4, hstrace +Q3, +Q4 */
    int loaded = 0, status = 2;
    unsigned char *buf = NULL;
    for (; loaded < 4; loaded++)
        if (load(argv[2 + loaded], &img[loaded]))
            goto done;
    for (int k = 1; k < 4; k++)
        if (!same_size(&img[0], &img[k], argv[2], argv[2 + k]))
            goto done;

    int w = img[0].width, h = img[0].height;
    size_t n = (size_t)w * h;
    buf = calloc(n, 8);
    if (!buf) {
        fprintf(stderr, "compare_images: out of memory\n");
        goto done;
    }
    unsigned char *pm = buf, *hm = buf + n;              /* the masks */
    unsigned char *pedge = buf + 2 * n, *hedge = buf + 3 * n; /* their boundaries */
    unsigned char *psil = buf + 4 * n, *hsil = buf + 5 * n;   /* silhouettes */
    /* 0 agree, 1 disagree at an edge or silhouette, 3 disagree elsewhere */
    unsigned char *verdict = buf + 6 * n, *sil = buf + 7 * n;
    /* shadow losses, +Q3 minus +Q4, as RGBA images: POV-Ray's, hstrace's */
    float *ploss = malloc(n * 4 * sizeof *ploss), *hloss = malloc(n * 4 * sizeof *hloss);
    if (!ploss || !hloss) {
        free(ploss);
        free(hloss);
        fprintf(stderr, "compare_images: out of memory\n");
        goto done;
    }
    for (size_t i = 0; i < n * 4; i++) {
        ploss[i] = img[0].rgba[i] - img[1].rgba[i];
        hloss[i] = img[2].rgba[i] - img[3].rgba[i];
    }

    long bad = 0;
    for (int k = 0; k < 4; k++)
        bad += count_nonfinite(&img[k]);
    long pov_count = 0, hst_count = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            pm[i] = (unsigned char)changed(px(&img[0], x, y), px(&img[1], x, y), 1);
            hm[i] = (unsigned char)changed(px(&img[2], x, y), px(&img[3], x, y), 0);
            pov_count += pm[i];
            hst_count += hm[i];
        }
    find_edges(pm, ploss, LOSS_TOL, w, h, pedge);
    find_edges(hm, hloss, LOSS_TOL, w, h, hedge);
    find_edges(NULL, img[0].rgba, SILHOUETTE_JUMP, w, h, psil);
    find_edges(NULL, img[2].rgba, SILHOUETTE_JUMP, w, h, hsil);

    long on_shadow_edge = 0, on_silhouette = 0, unexplained = 0, other_lights = 0, pov_leaks = 0;
    int ux = -1, uy = -1;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            sil[i] = psil[i] || hsil[i];
            int loss_off = 0;
            for (int k = 0; k < 3; k++)
                loss_off |= fabs((double)ploss[i * 4 + k] - hloss[i * 4 + k]) > LOSS_TOL;
            if (pm[i] == hm[i] && !loss_off)
                continue;
            other_lights += pm[i] == hm[i];
            if (near(pedge, w, h, x, y) && near(hedge, w, h, x, y)) {
                on_shadow_edge++;
                verdict[i] = 1;
            } else if (near(psil, w, h, x, y) && near(hsil, w, h, x, y)) {
                on_silhouette++;
                verdict[i] = 1;
            } else if (pov_leaks_ok != 0.0 && hstrace_blocks_more(ploss + i * 4, hloss + i * 4) && hm[i] >= pm[i]) {
                pov_leaks++; /* more light in POV-Ray: through a shared edge */
                verdict[i] = 3;
            } else {
                verdict[i] = 3;
                if (unexplained == 0) {
                    ux = x;
                    uy = y;
                }
                unexplained++;
            }
        }
    free(ploss);
    free(hloss);
    long disagree = on_shadow_edge + on_silhouette + unexplained + pov_leaks;
    double share = (double)disagree / n;
    int ok = share <= share_max && unexplained == 0 && bad == 0;
    printf("shadow masks: POV-Ray %ld px, hstrace %ld px; disagree on %ld px = %.4f%% (limit %.2f%%; "
           "%ld shadowed in both from other lights): %ld at shadow edges, %ld at silhouettes, %ld elsewhere",
           pov_count, hst_count, disagree, 100 * share, 100 * share_max, other_lights, on_shadow_edge, on_silhouette,
           unexplained);
    if (pov_leaks_ok != 0.0)
        printf(", %ld away from edges where POV-Ray lets more light through (its leaks through shared edges)", pov_leaks);
    if (unexplained)
        printf(" (first at %d,%d)", ux, uy);
    if (bad)
        printf(", %ld pixels hold NaN or infinity", bad);
    printf("\n");
    status = ok ? 0 : 1;
    if (map_path && write_map(map_path, pm, hm, verdict, sil, w, h))
        status = 2;
done:
    free(buf);
    for (int k = 0; k < loaded; k++)
        image_free(&img[k]);
    return status;
}

int main(int argc, char **argv)
{
    if (argc >= 4 && strcmp(argv[1], "full") == 0)
        return full(argc, argv);
    if (argc >= 6 && strcmp(argv[1], "mask") == 0)
        return mask(argc, argv);
    if (argc >= 4 && strcmp(argv[1], "encoded") == 0)
        return encoded(argc, argv);
    usage();
    return 2;
}
