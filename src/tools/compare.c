/* `hstrace compare`: read the images, compare them, report, write the maps,
 * and say by the exit status whether the limits were met. */
#include "compare.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compare_options.h"
#include "compare_report.h"
#include "image.h"
#include "image_compare.h"
#include "mask_compare.h"
#include "memory_budget.h"

#define PROGRAM "hstrace compare"

/* The image module's messages read "cannot read 'PATH': reason"; this
 * command names the file first, as "PATH: reason", so the reason alone. */
static const char *reason(const char *err, const char *verb, const char *path)
{
    size_t nv = strlen(verb), np = strlen(path);
    if (strncmp(err, verb, nv) == 0 && strncmp(err + nv, " '", 2) == 0 && strncmp(err + nv + 2, path, np) == 0 &&
        strncmp(err + nv + 2 + np, "': ", 3) == 0)
        return err + nv + 2 + np + 3;
    return err;
}

static int write_image(const char *path, const Image *img)
{
    ImageWriteOptions wo;
    char err[1024];
    memset(&wo, 0, sizeof wo); /* half-float EXR, 8-bit sRGB PNG and PPM */
    if (image_write(path, img, &wo, err, sizeof err) == 0)
        return 0;
    fprintf(stderr, PROGRAM ": %s: cannot write: %s\n", path, reason(err, "cannot write", path));
    return -1;
}

/* B's +Q3/+Q4 pair from its shadow.loss channels; 0, or -1 with a message. */
static int mask_pair_from_channels(const char *path, const Image *render, Image *q3, Image *q4)
{
    static const char *const names[3] = {"shadow.loss.R", "shadow.loss.G", "shadow.loss.B"};
    float *loss[3];
    int w, h;
    char err[1024];
    int rc = image_read_exr_channels(path, names, 3, loss, &w, &h, err, sizeof err);
    if (rc) {
        fprintf(stderr, PROGRAM ": %s: %s%s\n", path, reason(err, "cannot read", path),
                rc > 0 ? ": B's shadow mask needs --mask-b B3 B4, or B rendered by hstrace with --aov shadow" : "");
        return -1;
    }
    rc = 0;
    if (w != render->width || h != render->height) {
        fprintf(stderr, PROGRAM ": %s: shadow channels of %dx%d pixels in a %dx%d image\n", path, w, h,
                render->width, render->height);
        rc = -1;
    } else if (mask_pair_from_loss(render, (const float *const *)loss, q3, q4)) {
        fprintf(stderr, PROGRAM ": out of memory\n");
        rc = -1;
    }
    for (int k = 0; k < 3; k++)
        free(loss[k]);
    return rc;
}

/* The sizes the images declare, held to each other and to the memory
 * budget before any is decoded: a PNG of 260 KB may declare 16384x16384
 * pixels, 4 GiB decoded, and a file of another size is refused without
 * being read. A header that cannot tell is left to the decoding, which
 * says what is wrong with its file. Returns 0, or -1 with a message. */
static int check_sizes(const CompareOptions *opt, const char *const *path, int nread)
{
    int w[6], h[6], known[6];
    char err[1024];
    for (int k = 0; k < nread; k++) {
        int rc = image_read_size(path[k], &w[k], &h[k], err, sizeof err);
        if (rc < 0) {
            fprintf(stderr, PROGRAM ": %s: %s\n", path[k], reason(err, "cannot read", path[k]));
            return -1;
        }
        known[k] = rc == 0;
    }
    int first = -1;
    for (int k = 0; k < nread; k++) {
        if (!known[k])
            continue;
        if (first < 0) {
            first = k;
        } else if (w[k] != w[first] || h[k] != h[first]) {
            fprintf(stderr, PROGRAM ": %s: %dx%d pixels, but %s has %dx%d\n", path[k], w[k], h[k], path[first],
                    w[first], h[first]);
            return -1;
        }
    }
    if (first < 0)
        return 0;
    /* Per pixel: each image read (linear RGBA floats), B's three shadow
     * planes and the pair made of them, the heat map and the mask map. */
    double per_pixel = 16.0 * nread + (opt->mask_b_from_aov ? 12.0 + 32.0 : 0.0) + (opt->diff ? 16.0 : 0.0) +
                       (opt->mask_map ? 16.0 : 0.0);
    double need = per_pixel * (double)w[first] * (double)h[first];
    size_t budget = opt->max_memory ? opt->max_memory : memory_budget_default();
    if (need <= (double)budget)
        return 0;
    char needs[32], limit[32];
    memory_size_text(needs, sizeof needs, need >= (double)SIZE_MAX ? SIZE_MAX : (size_t)need);
    memory_size_text(limit, sizeof limit, budget);
    fprintf(stderr, PROGRAM ": %s: %dx%d pixels: comparing would take %s, more than the memory budget of %s "
            "(--max-memory sets it)\n", path[first], w[first], h[first], needs, limit);
    return -1;
}

int compare_main(int argc, char **argv)
{
    CompareOptions opt;
    char err[1024];
    if (compare_options_parse(argc, argv, &opt, err, sizeof err)) {
        fprintf(stderr, PROGRAM ": %s\n", err);
        return COMPARE_EXIT_TROUBLE;
    }
    if (opt.help) {
        compare_options_usage(stdout);
        return COMPARE_EXIT_WITHIN;
    }

    /* A, B, then A's +Q3 and +Q4, B's +Q3 and +Q4 (read, or made from B's
     * shadow channels). */
    const char *path[6] = {opt.a, opt.b, opt.mask_a[0], opt.mask_a[1], opt.mask_b[0], opt.mask_b[1]};
    int nimages = opt.mask_a[0] ? 6 : 2, nread = opt.mask_b_from_aov ? 4 : nimages;
    Image img[6], diff, map;
    memset(img, 0, sizeof img);
    memset(&diff, 0, sizeof diff);
    memset(&map, 0, sizeof map);
    int status = COMPARE_EXIT_TROUBLE;
    if (check_sizes(&opt, path, nread))
        goto done;
    for (int k = 0; k < nread; k++)
        if (image_read(path[k], &img[k], 0.0, err, sizeof err)) {
            fprintf(stderr, PROGRAM ": %s: %s\n", path[k], reason(err, "cannot read", path[k]));
            goto done;
        }
    if (opt.mask_b_from_aov && mask_pair_from_channels(opt.b, &img[1], &img[4], &img[5]))
        goto done;
    for (int k = 1; k < nimages; k++)
        if (img[k].width != img[0].width || img[k].height != img[0].height) {
            fprintf(stderr, PROGRAM ": %s: %dx%d pixels, but %s has %dx%d\n", path[k], img[k].width, img[k].height,
                    path[0], img[0].width, img[0].height);
            goto done;
        }

    CompareResult r;
    memset(&r, 0, sizeof r);
    if (image_compare(&img[0], &img[1], opt.threshold, &r.image) ||
        (opt.diff && image_compare_heat_map(&img[0], &img[1], opt.threshold, &diff))) {
        fprintf(stderr, PROGRAM ": out of memory\n");
        goto done;
    }
    if (nimages == 6) {
        MaskCompareOptions mo = {.loss_tolerance = opt.threshold, .allow_a_leaks = opt.allow_a_leaks};
        if (mask_compare(&img[2], &img[3], &img[4], &img[5], &mo, &r.masks, opt.mask_map ? &map : NULL)) {
            fprintf(stderr, PROGRAM ": out of memory\n");
            goto done;
        }
        r.has_masks = 1;
    }
    compare_judge(&opt, &r);
    if (opt.json)
        compare_report_json(stdout, &opt, &r);
    else
        compare_report_text(stdout, &opt, &r);
    fflush(stdout);
    status = r.within ? COMPARE_EXIT_WITHIN : COMPARE_EXIT_OUTSIDE;
    if (opt.diff && write_image(opt.diff, &diff))
        status = COMPARE_EXIT_TROUBLE;
    if (opt.mask_map && write_image(opt.mask_map, &map))
        status = COMPARE_EXIT_TROUBLE;
done:
    for (int k = 0; k < nimages; k++)
        image_free(&img[k]);
    image_free(&diff);
    image_free(&map);
    return status;
}
