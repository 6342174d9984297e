/* The verdict of `hstrace compare` and its text and JSON output. */
#include "compare_report.h"

#include <math.h>

#include "json_write.h"

static double figure(const CompareResult *r, CompareLimit l)
{
    switch (l) {
    case COMPARE_MAX_RMSE: return r->image.rmse;
    case COMPARE_MIN_PSNR: return r->image.psnr;
    case COMPARE_MAX_ERROR: return r->image.max_error;
    case COMPARE_MAX_SHARE: return r->image.share;
    case COMPARE_MAX_MASK_SHARE: return r->masks.share;
    case COMPARE_MAX_INTERIOR: return (double)r->masks.interior;
    default: return NAN;
    }
}

static long nonfinite(const CompareResult *r)
{
    return r->image.nonfinite + (r->has_masks ? r->masks.nonfinite : 0);
}

void compare_judge(const CompareOptions *opt, CompareResult *r)
{
    int any = 0;
    r->within = 1;
    for (int l = 0; l < COMPARE_NLIMITS; l++) {
        r->exceeded[l] = 0;
        if (!opt->has_limit[l] || (compare_limits[l].needs_masks && !r->has_masks))
            continue;
        any = 1;
        double v = figure(r, (CompareLimit)l);
        r->exceeded[l] = compare_limits[l].is_minimum ? !(v >= opt->limit[l]) : !(v <= opt->limit[l]);
        if (r->exceeded[l])
            r->within = 0;
    }
    r->nonfinite_fails = any && nonfinite(r) > 0;
    if (r->nonfinite_fails)
        r->within = 0;
}

/* A figure or a limit as the text output shows it. */
static void print_value(FILE *f, CompareLimit l, double v)
{
    switch (l) {
    case COMPARE_MIN_PSNR:
        if (isinf(v))
            fprintf(f, "inf dB");
        else
            fprintf(f, "%.2f dB", v);
        break;
    case COMPARE_MAX_SHARE:
    case COMPARE_MAX_MASK_SHARE:
        fprintf(f, "%.4g%%", 100 * v);
        break;
    case COMPARE_MAX_INTERIOR:
        fprintf(f, "%.0f", v);
        break;
    default:
        fprintf(f, "%.6g", v);
        break;
    }
}

void compare_report_text(FILE *f, const CompareOptions *opt, const CompareResult *r)
{
    const ImageComparison *c = &r->image;
    fprintf(f, "%s vs %s: %dx%d pixels, linear RGB\n", opt->a, opt->b, c->width, c->height);
    fprintf(f, "  RMSE %.6f, PSNR ", c->rmse);
    print_value(f, COMPARE_MIN_PSNR, c->psnr);
    fprintf(f, ", max error %.6f at (%d,%d)\n", c->max_error, c->max_x, c->max_y);
    fprintf(f, "  pixels off by more than %g: %ld = %.4f%%\n", c->threshold, c->over, 100 * c->share);
    if (c->nonfinite)
        fprintf(f, "  %ld pixels hold NaN or infinity\n", c->nonfinite);
    if (r->has_masks) {
        const MaskComparison *m = &r->masks;
        fprintf(f, "  shadow masks: A %ld px, B %ld px; disagree on %ld px = %.4f%% (%ld shadowed in both, from other "
                   "lights)\n",
                m->a_pixels, m->b_pixels, m->disagree, 100 * m->share, m->other_lights);
        fprintf(f, "  disagreements: %ld at shadow edges, %ld at silhouettes, %ld interior", m->shadow_edge,
                m->silhouette, m->interior);
        if (m->interior)
            fprintf(f, " (first at %d,%d)", m->interior_x, m->interior_y);
        if (opt->allow_a_leaks)
            fprintf(f, ", %ld where A lets more light through (A's leaks)", m->a_leaks);
        fprintf(f, "\n");
        if (m->nonfinite)
            fprintf(f, "  %ld pixels of the shadow-mask renders hold NaN or infinity\n", m->nonfinite);
    }
    int any = 0;
    for (int l = 0; l < COMPARE_NLIMITS; l++) {
        if (!opt->has_limit[l])
            continue;
        const CompareLimitInfo *info = &compare_limits[l];
        fprintf(f, "%s%s ", any ? ", " : r->within ? "within limits: " : "outside limits: ", info->figure);
        print_value(f, (CompareLimit)l, figure(r, (CompareLimit)l));
        fprintf(f, " %s ", info->is_minimum ? (r->exceeded[l] ? "<" : ">=") : (r->exceeded[l] ? ">" : "<="));
        print_value(f, (CompareLimit)l, opt->limit[l]);
        fprintf(f, " (%s)", info->option);
        any = 1;
    }
    if (r->nonfinite_fails)
        fprintf(f, ", %ld pixels hold NaN or infinity", nonfinite(r));
    if (any)
        fprintf(f, "\n");
}

void compare_json_image_fields(FILE *f, const char *indent, const ImageComparison *c)
{
    json_key_number(f, indent, "rmse", c->rmse, 0);
    json_key_number(f, indent, "psnr", c->psnr, 0);
    json_key_number(f, indent, "max_error", c->max_error, 0);
    fprintf(f, "%s\"max_error_at\": [%d, %d],\n", indent, c->max_x, c->max_y);
    json_key_count(f, indent, "pixels_over_threshold", c->over, 0);
}

void compare_json_mask_fields(FILE *f, const char *indent, const MaskComparison *m, const char *a_key,
                              const char *b_key)
{
    json_key_count(f, indent, a_key, m->a_pixels, 0);
    json_key_count(f, indent, b_key, m->b_pixels, 0);
    json_key_count(f, indent, "disagree", m->disagree, 0);
    json_key_number(f, indent, "share", m->share, 0);
    json_key_count(f, indent, "other_lights", m->other_lights, 0);
    json_key_count(f, indent, "shadow_edge", m->shadow_edge, 0);
    json_key_count(f, indent, "silhouette", m->silhouette, 0);
    json_key_count(f, indent, "interior", m->interior, 0);
    if (m->interior)
        fprintf(f, "%s\"first_interior_at\": [%d, %d],\n", indent, m->interior_x, m->interior_y);
    else
        fprintf(f, "%s\"first_interior_at\": null,\n", indent);
    json_key_count(f, indent, "nonfinite_pixels", m->nonfinite, 0);
}

void compare_report_json(FILE *f, const CompareOptions *opt, const CompareResult *r)
{
    const ImageComparison *c = &r->image;
    fprintf(f, "{\n  \"a\": ");
    json_write_string(f, opt->a);
    fprintf(f, ",\n  \"b\": ");
    json_write_string(f, opt->b);
    fprintf(f, ",\n");
    json_key_count(f, "  ", "width", c->width, 0);
    json_key_count(f, "  ", "height", c->height, 0);
    json_key_number(f, "  ", "threshold", c->threshold, 0);
    compare_json_image_fields(f, "  ", c);
    json_key_number(f, "  ", "share_over_threshold", c->share, 0);
    json_key_count(f, "  ", "nonfinite_pixels", c->nonfinite, 0);
    fprintf(f, "  \"masks\": ");
    if (r->has_masks) {
        const MaskComparison *m = &r->masks;
        const char *names[4] = {"a3", "a4", "b3", "b4"};
        const char *paths[4] = {opt->mask_a[0], opt->mask_a[1], opt->mask_b[0], opt->mask_b[1]};
        fprintf(f, "{\n");
        for (int k = 0; k < 4; k++) {
            fprintf(f, "    \"%s\": ", names[k]);
            if (paths[k])
                json_write_string(f, paths[k]);
            else
                fprintf(f, "null"); /* B's pair made from B's shadow channels */
            fprintf(f, ",\n");
        }
        fprintf(f, "    \"b_from_channels\": %s,\n", opt->mask_b_from_aov ? "true" : "false");
        compare_json_mask_fields(f, "    ", m, "a_pixels", "b_pixels");
        fprintf(f, "    \"allow_a_leaks\": %s,\n", opt->allow_a_leaks ? "true" : "false");
        json_key_count(f, "    ", "a_leaks", m->a_leaks, 1);
        fprintf(f, "  }");
    } else {
        fprintf(f, "null");
    }
    fprintf(f, ",\n  \"limits\": {");
    int any = 0;
    for (int l = 0; l < COMPARE_NLIMITS; l++)
        if (opt->has_limit[l]) {
            fprintf(f, "%s\"%s\": ", any ? ", " : "", compare_limits[l].key);
            json_write_number(f, opt->limit[l]);
            any = 1;
        }
    fprintf(f, "},\n  \"exceeded\": [");
    any = 0;
    for (int l = 0; l < COMPARE_NLIMITS; l++)
        if (r->exceeded[l]) {
            fprintf(f, "%s\"%s\"", any ? ", " : "", compare_limits[l].key);
            any = 1;
        }
    if (r->nonfinite_fails)
        fprintf(f, "%s\"nonfinite\"", any ? ", " : "");
    fprintf(f, "],\n  \"within_limits\": %s\n}\n", r->within ? "true" : "false");
}
