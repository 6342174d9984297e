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
/* The members of an image comparison (rmse, psnr, max_error, max_error_at,
 * pixels_over_threshold) and of a mask comparison (a_key, b_key: the two
 * renderers' shadowed pixels; disagree, share, other_lights, shadow_edge,
 * silhouette, interior, first_interior_at, nonfinite_pixels), one per line,
 * each followed by a comma: the JSON of `hstrace compare` and of
 * `hstrace vs-povray` share them. */
void compare_json_image_fields(FILE *f, const char *indent, const ImageComparison *c);
void compare_json_mask_fields(FILE *f, const char *indent, const MaskComparison *m, const char *a_key,
                              const char *b_key);

void compare_report_json(FILE *f, const CompareOptions *opt, const CompareResult *r);

#endif
