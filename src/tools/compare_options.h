/* The command line of `hstrace compare A B [options]`: the two images, the
 * optional +Q3/+Q4 pairs for the shadow masks, the per-pixel threshold, the
 * limits that decide the exit status, and the outputs. */
#ifndef HST_COMPARE_OPTIONS_H
#define HST_COMPARE_OPTIONS_H

#include <stddef.h>
#include <stdio.h>

/* The limits, one option each. A limit given and not met makes the exit
 * status 1. */
typedef enum {
    COMPARE_MAX_RMSE,
    COMPARE_MIN_PSNR,
    COMPARE_MAX_ERROR,
    COMPARE_MAX_SHARE,
    COMPARE_MAX_MASK_SHARE,
    COMPARE_MAX_INTERIOR,
    COMPARE_NLIMITS
} CompareLimit;

typedef struct {
    const char *option;  /* "--max-rmse" */
    const char *key;     /* "max_rmse": its name in the JSON output */
    const char *figure;  /* "rmse": the figure it bounds, as the text output names it */
    int is_minimum;      /* the figure must be at least the limit (else at most) */
    int needs_masks;     /* bounds a shadow-mask figure: only with --mask-a/--mask-b */
} CompareLimitInfo;

extern const CompareLimitInfo compare_limits[COMPARE_NLIMITS];

#define COMPARE_DEFAULT_THRESHOLD 0.02

typedef struct {
    const char *a, *b;
    const char *mask_a[2], *mask_b[2]; /* +Q3 and +Q4 renders; NULL without --mask-a/--mask-b */
    int mask_b_from_aov;               /* --mask-a without --mask-b: B's mask from B's shadow channels */
    double threshold;                  /* --threshold */
    double limit[COMPARE_NLIMITS];
    int has_limit[COMPARE_NLIMITS];
    int allow_a_leaks;                 /* --allow-a-leaks */
    const char *diff;                  /* --diff FILE: heat map of |A - B| */
    const char *mask_map;              /* --mask-map FILE: the shadow-mask verdicts */
    int json;                          /* --json */
    size_t max_memory;                 /* --max-memory: what the images may take (0: memory_budget_default) */
    int help;
} CompareOptions;

/* Fills opt from argv, where argv[0] is "compare". Returns 0, or -1 with a
 * message in err. */
int compare_options_parse(int argc, char **argv, CompareOptions *opt, char *err, int errlen);
void compare_options_usage(FILE *f);

#endif
