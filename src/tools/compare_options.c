/* Command-line parsing for `hstrace compare`. */
#include "compare_options.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "image.h"
#include "options.h"

const CompareLimitInfo compare_limits[COMPARE_NLIMITS] = {
    [COMPARE_MAX_RMSE] = {"--max-rmse", "max_rmse", "rmse", 0, 0},
    [COMPARE_MIN_PSNR] = {"--min-psnr", "min_psnr", "psnr", 1, 0},
    [COMPARE_MAX_ERROR] = {"--max-error", "max_error", "max error", 0, 0},
    [COMPARE_MAX_SHARE] = {"--max-share", "max_share", "share over threshold", 0, 0},
    [COMPARE_MAX_MASK_SHARE] = {"--max-mask-share", "max_mask_share", "mask disagreement share", 0, 1},
    [COMPARE_MAX_INTERIOR] = {"--max-interior", "max_interior", "interior disagreements", 0, 1},
};

void compare_options_usage(FILE *f)
{
    fprintf(f,
            "usage: hstrace compare A B [options]\n"
            "\n"
            "Compares two images of the same size (EXR, PNG, PPM, Targa, BMP, JPEG or HDR) in\n"
            "linear RGB: RMSE, PSNR, the largest channel error and where, and the share of\n"
            "pixels off by more than a threshold. With --mask-a and --mask-b, also the shadow\n"
            "masks of two renderers.\n"
            "\n"
            "      --threshold T      a pixel is off when a channel differs by more (default %g);\n"
            "                         also the shadow-loss tolerance of the mask comparison\n"
            "      --mask-a A3 A4     A's renders without (+Q3) and with (+Q4) shadows: the reference\n"
            "      --mask-b B3 B4     B's renders without and with shadows: under test; without it,\n"
            "                         B's mask comes from B's shadow channels (hstrace --aov shadow)\n"
            "      --allow-a-leaks    count interior disagreements where A lets more light through\n"
            "                         than B apart, as A's leaks, not as errors\n"
            "      --diff FILE        write a heat map of |A - B| (.exr, .png, .ppm, .tga, .bmp, .jpg, .hdr)\n"
            "      --mask-map FILE    write the shadow-mask verdicts as an image\n"
            "      --json             print the figures as JSON\n"
            "      --max-memory SIZE  memory the images may take, e.g. 512M or 8G (default: a quarter\n"
            "                         of the physical memory); checked from their headers\n"
            "      --help             show this help\n"
            "\n"
            "Limits (exit status 1 when one given is not met; NaN or infinite pixels fail any):\n"
            "      --max-rmse R       RMSE over all RGB samples\n"
            "      --min-psnr DB      PSNR in dB (peak 1.0)\n"
            "      --max-error E      largest difference of one channel\n"
            "      --max-share S      share of pixels off by more than the threshold (0.01 = 1%%)\n"
            "      --max-mask-share S share of pixels where the shadow masks disagree\n"
            "      --max-interior N   disagreeing mask pixels away from shadow edges and silhouettes\n"
            "\n"
            "Exit status: 0 within the limits given, 1 not, 2 bad usage or unreadable,\n"
            "mismatched or unwritable images.\n",
            COMPARE_DEFAULT_THRESHOLD);
}

/* A number in [lo, hi]; whole numbers only when `whole`. */
static int parse_number(const char *s, double lo, double hi, int whole, double *out)
{
    char *end;
    double v = strtod(s, &end);
    if (end == s || *end != '\0' || !isfinite(v) || v < lo || v > hi || (whole && v != floor(v)))
        return -1;
    *out = v;
    return 0;
}

static int check_image_name(const char *option, const char *path, char *err, int errlen)
{
    if (image_format_from_path(path) != IMAGE_FORMAT_UNKNOWN)
        return 0;
    snprintf(err, (size_t)errlen, "%s '%s': unknown image format (use .exr, .png, .ppm, .tga, .bmp, .jpg or .hdr)", option, path);
    return -1;
}

/* --mask-a / --mask-b: the two file names that follow. */
static int take_pair(int argc, char **argv, int *i, const char *pair[2], char *err, int errlen)
{
    const char *name = argv[*i];
    if (*i + 2 >= argc) {
        snprintf(err, (size_t)errlen, "%s needs two images: the renders without (+Q3) and with (+Q4) shadows", name);
        return -1;
    }
    pair[0] = argv[++*i];
    pair[1] = argv[++*i];
    return 0;
}

/* One limit option, as "--name value" or "--name=value"; 1 when arg is none. */
static int parse_limit(int argc, char **argv, int *i, CompareOptions *opt, char *err, int errlen)
{
    for (int l = 0; l < COMPARE_NLIMITS; l++) {
        const char *name = compare_limits[l].option;
        if (!options_is_long(argv[*i], name))
            continue;
        const char *v = options_value(argc, argv, i, name, err, errlen);
        if (!v)
            return -1;
        int ok;
        switch (l) {
        case COMPARE_MIN_PSNR:
            ok = parse_number(v, -1e9, 1e9, 0, &opt->limit[l]) == 0;
            break;
        case COMPARE_MAX_SHARE:
        case COMPARE_MAX_MASK_SHARE:
            ok = parse_number(v, 0, 1, 0, &opt->limit[l]) == 0;
            break;
        case COMPARE_MAX_INTERIOR:
            ok = parse_number(v, 0, 1e15, 1, &opt->limit[l]) == 0;
            break;
        default:
            ok = parse_number(v, 0, 1e300, 0, &opt->limit[l]) == 0;
            break;
        }
        if (!ok) {
            snprintf(err, (size_t)errlen, "%s '%s': expected %s", name, v,
                     l == COMPARE_MIN_PSNR ? "a number of dB"
                     : l == COMPARE_MAX_INTERIOR ? "a whole number of pixels, 0 or more"
                     : l == COMPARE_MAX_SHARE || l == COMPARE_MAX_MASK_SHARE ? "a fraction from 0 to 1"
                                                                              : "a number, 0 or more");
            return -1;
        }
        opt->has_limit[l] = 1;
        return 0;
    }
    return 1;
}

int compare_options_parse(int argc, char **argv, CompareOptions *opt, char *err, int errlen)
{
    memset(opt, 0, sizeof *opt);
    opt->threshold = COMPARE_DEFAULT_THRESHOLD;
    int only_files = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v;
        int rc;
        if (only_files || a[0] != '-' || a[1] == '\0') {
            if (!opt->a) {
                opt->a = a;
            } else if (!opt->b) {
                opt->b = a;
            } else {
                snprintf(err, (size_t)errlen, "more than two images given ('%s'); shadow-mask renders follow "
                                              "--mask-a and --mask-b", a);
                return -1;
            }
        } else if (strcmp(a, "--") == 0) {
            only_files = 1;
        } else if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            opt->help = 1;
        } else if (strcmp(a, "--json") == 0) {
            opt->json = 1;
        } else if (strcmp(a, "--allow-a-leaks") == 0) {
            opt->allow_a_leaks = 1;
        } else if (strcmp(a, "--mask-a") == 0) {
            if (take_pair(argc, argv, &i, opt->mask_a, err, errlen))
                return -1;
        } else if (strcmp(a, "--mask-b") == 0) {
            if (take_pair(argc, argv, &i, opt->mask_b, err, errlen))
                return -1;
        } else if (options_is_long(a, "--threshold")) {
            if (!(v = options_value(argc, argv, &i, "--threshold", err, errlen)))
                return -1;
            if (parse_number(v, 0, 1e300, 0, &opt->threshold)) {
                snprintf(err, (size_t)errlen, "--threshold '%s': expected a number, 0 or more", v);
                return -1;
            }
        } else if (options_is_long(a, "--diff")) {
            if (!(v = options_value(argc, argv, &i, "--diff", err, errlen)) ||
                check_image_name("--diff", v, err, errlen))
                return -1;
            opt->diff = v;
        } else if (options_is_long(a, "--mask-map")) {
            if (!(v = options_value(argc, argv, &i, "--mask-map", err, errlen)) ||
                check_image_name("--mask-map", v, err, errlen))
                return -1;
            opt->mask_map = v;
        } else if (options_is_long(a, "--max-memory")) {
            if (!(v = options_value(argc, argv, &i, "--max-memory", err, errlen)))
                return -1;
            if (options_parse_size(v, &opt->max_memory)) {
                snprintf(err, (size_t)errlen, "--max-memory '%s': expected a size such as 512M or 8G", v);
                return -1;
            }
        } else if ((rc = parse_limit(argc, argv, &i, opt, err, errlen)) <= 0) {
            if (rc < 0)
                return -1;
        } else {
            snprintf(err, (size_t)errlen, "unknown option '%s' (see hstrace compare --help)", a);
            return -1;
        }
    }
    if (opt->help)
        return 0;
    if (!opt->b) {
        snprintf(err, (size_t)errlen, "two images needed: hstrace compare A B [options] (see --help)");
        return -1;
    }
    int masks = opt->mask_a[0] != NULL;
    if (!masks && opt->mask_b[0]) {
        snprintf(err, (size_t)errlen, "--mask-b given without --mask-a: shadow masks need A's pair of renders");
        return -1;
    }
    /* B an EXR with analysis channels stands for its own pair. */
    opt->mask_b_from_aov = masks && !opt->mask_b[0];
    const char *mask_only = NULL;
    for (int l = 0; l < COMPARE_NLIMITS; l++)
        if (opt->has_limit[l] && compare_limits[l].needs_masks)
            mask_only = compare_limits[l].option;
    if (opt->mask_map)
        mask_only = "--mask-map";
    if (opt->allow_a_leaks)
        mask_only = "--allow-a-leaks";
    if (mask_only && !masks) {
        snprintf(err, (size_t)errlen, "%s needs the shadow masks: --mask-a A3 A4 [--mask-b B3 B4]", mask_only);
        return -1;
    }
    return 0;
}
