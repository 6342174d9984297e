/* What `hstrace compare` found: the figures, the limits they were held to,
 * and their output as text or JSON. */
#ifndef HST_COMPARE_REPORT_H
#define HST_COMPARE_REPORT_H

#include <stdio.h>

#include "compare_options.h"
#include "image_compare.h"
#include "mask_compare.h"

typedef struct {
    ImageComparison image;
    int has_masks;
    MaskComparison masks;
    int exceeded[COMPARE_NLIMITS]; /* a limit given and not met */
    int nonfinite_fails;           /* NaN or infinite pixels while a limit was given */
    int within;                    /* 1 when no limit was exceeded */
} CompareResult;

/* Holds r's figures to the limits in opt: fills exceeded, nonfinite_fails
 * and within. */
void compare_judge(const CompareOptions *opt, CompareResult *r);

/* A few lines for people (stdout), or one JSON object. */
void compare_report_text(FILE *f, const CompareOptions *opt, const CompareResult *r);
void compare_report_json(FILE *f, const CompareOptions *opt, const CompareResult *r);

#endif
