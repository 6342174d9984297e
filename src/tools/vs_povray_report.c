/* The outputs of `hstrace vs-povray`: table, JSON and HTML page. */
#include "vs_povray_report.h"

#include <math.h>
#include <string.h>

#include "compare_report.h"
#include "json_write.h"

enum { COL_METHOD, COL_WALL, COL_CPU, COL_SHADOW, COL_SPEEDUP, COL_RMSE, COL_EDGE, COL_INTERIOR, COL_DISAGREE, NCOLS };

static const char *const heading[NCOLS] = {"method", "wall (s)", "CPU (s)", "shadows (s)",
                                           "speed-up", "RMSE", "mask edge", "mask interior", "vs shadow ray"};

/* What each column means, for the legends. */
static const char *const meaning[NCOLS] = {
    "POV-Ray, or hstrace with that shadow method",
    "the whole program, start to exit (POV-Ray's includes a start-up wait of its own)",
    "the program's user + system CPU time: the work done",
    "hstrace's own shadow-testing time (time.shadow_testing of --stats-json), summed over threads",
    "POV-Ray's wall time over the row's",
    "root mean square difference from POV-Ray's image, linear RGB",
    "shadow-mask pixels (+Q3 against +Q4) disagreeing with POV-Ray's at a shadow edge or silhouette: ties",
    "shadow-mask pixels disagreeing with POV-Ray's elsewhere: errors",
    "a method that is not exact (embree): its decisions that differ from the exact shadow ray's, of those made, "
    "in one more full render with --verify-shadows (untimed); - for the exact methods, which the tests hold to none",
};

/* The one formatter of every figure, for the table, the page and tests. */
static void cell(const VsRow *row, int is_povray, int col, char *buf, size_t n)
{
    switch (col) {
    case COL_METHOD:
        snprintf(buf, n, "%s", row->name);
        return;
    case COL_WALL:
        snprintf(buf, n, "%.3f", row->wall);
        return;
    case COL_CPU:
        snprintf(buf, n, "%.3f", row->cpu);
        return;
    case COL_SHADOW:
        if (isfinite(row->shadow))
            snprintf(buf, n, "%.3f", row->shadow);
        else
            snprintf(buf, n, "-");
        return;
    case COL_SPEEDUP:
        if (isfinite(row->speedup))
            snprintf(buf, n, "%.2f", row->speedup);
        else
            snprintf(buf, n, "-");
        return;
    default:
        break;
    }
    if (is_povray) {
        snprintf(buf, n, "-");
        return;
    }
    switch (col) {
    case COL_RMSE:
        snprintf(buf, n, "%.6f", row->image.rmse);
        break;
    case COL_EDGE:
        snprintf(buf, n, "%ld", row->mask.shadow_edge + row->mask.silhouette);
        break;
    case COL_DISAGREE:
        if (row->verified >= 0)
            snprintf(buf, n, "%lld of %lld", row->disagreements, row->verified);
        else
            snprintf(buf, n, "-");
        break;
    default:
        snprintf(buf, n, "%ld", row->mask.interior);
        break;
    }
}

static const VsRow *row_at(const VsResult *r, int i)
{
    return i == 0 ? &r->povray : &r->rows[i - 1];
}

static void heading_line(FILE *f, const VsResult *r)
{
    fprintf(f, "hstrace vs-povray: %s, %dx%d pixels, %d thread%s, median of %d run%s\n", r->scene, r->width,
            r->height, r->threads, r->threads == 1 ? "" : "s", r->runs, r->runs == 1 ? "" : "s");
}

void vs_report_text(FILE *f, const VsResult *r)
{
    heading_line(f, r);
    fprintf(f, "POV-Ray %s (%s), hstrace %s\n", r->povray_version, r->povray_path, r->hstrace_version);
    if (r->povray_options[0])
        fprintf(f, "POV-Ray options declared by the scene: %s\n", r->povray_options);
    fprintf(f, "\n");
    char buf[64];
    int width[NCOLS];
    for (int c = 0; c < NCOLS; c++) {
        width[c] = (int)strlen(heading[c]);
        for (int i = 0; i <= r->nrows; i++) {
            cell(row_at(r, i), i == 0, c, buf, sizeof buf);
            if ((int)strlen(buf) > width[c])
                width[c] = (int)strlen(buf);
        }
    }
    for (int c = 0; c < NCOLS; c++)
        fprintf(f, c == 0 ? "%-*s" : "  %*s", width[c], heading[c]);
    fprintf(f, "\n");
    for (int i = 0; i <= r->nrows; i++) {
        for (int c = 0; c < NCOLS; c++) {
            cell(row_at(r, i), i == 0, c, buf, sizeof buf);
            fprintf(f, c == 0 ? "%-*s" : "  %*s", width[c], buf);
        }
        fprintf(f, "\n");
    }
    fprintf(f, "\n");
    for (int c = 1; c < NCOLS; c++)
        fprintf(f, "%-13s  %s\n", heading[c], meaning[c]);
}

void vs_report_json(FILE *f, const VsResult *r)
{
    fprintf(f, "{\n");
    json_key_string(f, "  ", "scene", r->scene, 0);
    fprintf(f, "  \"width\": %d,\n  \"height\": %d,\n  \"threads\": %d,\n  \"runs\": %d,\n", r->width, r->height,
            r->threads, r->runs);
    json_key_number(f, "  ", "threshold", r->threshold, 0);
    json_key_string(f, "  ", "command", r->command, 0);
    json_key_string(f, "  ", "hstrace_version", r->hstrace_version, 0);
    json_key_string(f, "  ", "povray_version", r->povray_version, 0);
    json_key_string(f, "  ", "povray_path", r->povray_path, 0);
    json_key_string(f, "  ", "povray_options", r->povray_options, 0);
    json_key_string(f, "  ", "date", r->date, 0);
    json_key_string(f, "  ", "machine", r->machine, 0);
    fprintf(f, "  \"povray\": {\"wall\": ");
    json_write_number(f, r->povray.wall);
    fprintf(f, ", \"cpu\": ");
    json_write_number(f, r->povray.cpu);
    if (r->povray.render_png[0]) {
        fprintf(f, ", \"render_png\": ");
        json_write_string(f, r->povray.render_png);
    }
    fprintf(f, "},\n  \"methods\": [");
    for (int i = 0; i < r->nrows; i++) {
        const VsRow *w = &r->rows[i];
        const MaskComparison *m = &w->mask;
        fprintf(f, "%s\n    {\n", i ? "," : "");
        json_key_string(f, "      ", "method", w->name, 0);
        json_key_number(f, "      ", "wall", w->wall, 0);
        json_key_number(f, "      ", "cpu", w->cpu, 0);
        json_key_number(f, "      ", "shadow_testing", w->shadow, 0);
        json_key_number(f, "      ", "speedup", w->speedup, 0);
        if (w->verified >= 0)
            fprintf(f, "      \"verified\": %lld,\n      \"disagreements\": %lld,\n", w->verified, w->disagreements);
        else
            fprintf(f, "      \"verified\": null,\n      \"disagreements\": null,\n");
        compare_json_image_fields(f, "      ", &w->image);
        json_key_count(f, "      ", "nonfinite_pixels", w->image.nonfinite, 0);
        fprintf(f, "      \"mask\": {\n");
        compare_json_mask_fields(f, "        ", m, "povray_pixels", "hstrace_pixels");
        json_key_count(f, "        ", "edge", m->shadow_edge + m->silhouette, 1);
        fprintf(f, "      }");
        if (w->render_png[0]) {
            fprintf(f, ",\n      \"render_png\": ");
            json_write_string(f, w->render_png);
            fprintf(f, ",\n      \"diff_png\": ");
            json_write_string(f, w->diff_png);
            fprintf(f, ",\n      \"mask_png\": ");
            json_write_string(f, w->mask_png);
        }
        fprintf(f, "\n    }");
    }
    fprintf(f, "\n  ]\n}\n");
}

/* ---- HTML ----------------------------------------------------------------- */

static void html_text(FILE *f, const char *s)
{
    for (; *s; s++) {
        switch (*s) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        default: fputc(*s, f); break;
        }
    }
}

static const char *base_name(const char *path)
{
    const char *s = strrchr(path, '/');
    return s && s[1] ? s + 1 : path;
}

/* One image with its caption, shown at a whole multiple of its size (at
 * least 320 pixels wide), pixels kept sharp. */
static void html_figure(FILE *f, const VsResult *r, const char *src, const char *caption)
{
    int scale = r->width >= 320 ? 1 : (320 + r->width - 1) / r->width;
    fprintf(f, "<figure><img src=\"");
    html_text(f, src);
    fprintf(f, "\" width=\"%d\" height=\"%d\" alt=\"", r->width * scale, r->height * scale);
    html_text(f, caption);
    fprintf(f, "\"><figcaption>");
    html_text(f, caption);
    fprintf(f, "</figcaption></figure>\n");
}

static void html_swatch(FILE *f, const char *colour, const char *text)
{
    fprintf(f, "<span class=\"key\"><span class=\"swatch\" style=\"background:%s\"></span>", colour);
    html_text(f, text);
    fprintf(f, "</span>\n");
}

static void html_table(FILE *f, const VsResult *r)
{
    char buf[64];
    fprintf(f, "<table>\n<thead><tr>");
    for (int c = 0; c < NCOLS; c++) {
        fprintf(f, "<th title=\"");
        html_text(f, meaning[c]);
        fprintf(f, "\">");
        html_text(f, heading[c]);
        fprintf(f, "</th>");
    }
    fprintf(f, "</tr></thead>\n<tbody>\n");
    for (int i = 0; i <= r->nrows; i++) {
        const VsRow *w = row_at(r, i);
        fprintf(f, "<tr%s>", i > 0 && w->mask.interior ? " class=\"bad\"" : "");
        for (int c = 0; c < NCOLS; c++) {
            cell(w, i == 0, c, buf, sizeof buf);
            fprintf(f, c == 0 ? "<th scope=\"row\">" : "<td>");
            html_text(f, buf);
            fprintf(f, c == 0 ? "</th>" : "</td>");
        }
        fprintf(f, "</tr>\n");
    }
    fprintf(f, "</tbody>\n</table>\n<dl class=\"legend\">\n");
    for (int c = 1; c < NCOLS; c++) {
        fprintf(f, "<dt>");
        html_text(f, heading[c]);
        fprintf(f, "</dt><dd>");
        html_text(f, meaning[c]);
        fprintf(f, "</dd>\n");
    }
    fprintf(f, "</dl>\n");
}

static void html_about(FILE *f, const VsResult *r)
{
    fprintf(f, "<h2>How this was made</h2>\n<dl class=\"about\">\n<dt>Command</dt><dd><code>");
    html_text(f, r->command);
    fprintf(f, "</code></dd>\n<dt>Scene</dt><dd><code>");
    html_text(f, r->scene);
    fprintf(f, "</code></dd>\n<dt>hstrace</dt><dd>");
    html_text(f, r->hstrace_version);
    fprintf(f, "</dd>\n<dt>POV-Ray</dt><dd>");
    html_text(f, r->povray_version);
    fprintf(f, " (<code>");
    html_text(f, r->povray_path);
    fprintf(f, "</code>)</dd>\n");
    if (r->povray_options[0]) {
        fprintf(f, "<dt>POV-Ray options declared by the scene</dt><dd><code>");
        html_text(f, r->povray_options);
        fprintf(f, "</code></dd>\n");
    }
    fprintf(f, "<dt>Renders</dt><dd>%dx%d pixels, %d thread%s for both programs, no anti-aliasing, linear "
               "half-float OpenEXR compared; full renders at +Q9; POV-Ray's shadow mask from +Q3 and +Q4 renders, "
               "hstrace's from a +Q4 render with its shadow channels (--aov shadow); "
               "times are medians of %d run%s</dd>\n",
            r->width, r->height, r->threads, r->threads == 1 ? "" : "s", r->runs, r->runs == 1 ? "" : "s");
    fprintf(f, "<dt>Date</dt><dd>");
    html_text(f, r->date);
    fprintf(f, "</dd>\n<dt>Machine</dt><dd>");
    html_text(f, r->machine);
    fprintf(f, "</dd>\n</dl>\n");
}

void vs_report_html(FILE *f, const VsResult *r)
{
    const char *name = base_name(r->scene);
    fprintf(f, "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>");
    html_text(f, name);
    fprintf(f, ": hstrace against POV-Ray</title>\n<style>\n"
               "body { font-family: sans-serif; margin: 2em; color: #222; max-width: 100em; }\n"
               "table { border-collapse: collapse; margin: 1em 0; }\n"
               "th, td { padding: 0.25em 0.8em; border-bottom: 1px solid #ccc; }\n"
               "td { text-align: right; font-variant-numeric: tabular-nums; }\n"
               "tbody th { text-align: left; font-weight: normal; }\n"
               "tr.bad td { color: #b00; }\n"
               ".row { display: flex; flex-wrap: wrap; gap: 1em; }\n"
               "figure { margin: 0; }\n"
               "figure img { image-rendering: pixelated; display: block; background: #000; }\n"
               "figcaption { font-size: 0.9em; margin-top: 0.3em; }\n"
               ".key { margin-right: 1.5em; white-space: nowrap; font-size: 0.9em; }\n"
               ".swatch { display: inline-block; width: 1em; height: 1em; vertical-align: middle;"
               " margin-right: 0.3em; border: 1px solid #888; }\n"
               "dl.legend dt, dl.about dt { font-weight: bold; float: left; clear: left; width: 11em; }\n"
               "dl.legend dd, dl.about dd { margin-left: 12em; margin-bottom: 0.3em; }\n"
               "code { font-size: 0.95em; }\n"
               "</style>\n</head>\n<body>\n<h1>");
    html_text(f, name);
    fprintf(f, ": hstrace against POV-Ray</h1>\n<p>");
    html_text(f, r->scene);
    fprintf(f, ", %dx%d pixels, %d thread%s, median of %d run%s. POV-Ray ", r->width, r->height, r->threads,
            r->threads == 1 ? "" : "s", r->runs, r->runs == 1 ? "" : "s");
    html_text(f, r->povray_version);
    fprintf(f, ", hstrace ");
    html_text(f, r->hstrace_version);
    fprintf(f, ".</p>\n");
    html_table(f, r);

    fprintf(f, "<h2>Renders</h2>\n<div class=\"row\">\n");
    char caption[160];
    snprintf(caption, sizeof caption, "POV-Ray %s", r->povray_version);
    if (r->povray.render_png[0])
        html_figure(f, r, r->povray.render_png, caption);
    for (int i = 0; i < r->nrows; i++) {
        snprintf(caption, sizeof caption, "hstrace, %s shadows", r->rows[i].name);
        html_figure(f, r, r->rows[i].render_png, caption);
    }
    fprintf(f, "</div>\n");

    fprintf(f, "<h2>Differences from POV-Ray</h2>\n<p>The largest channel difference at each pixel:</p>\n<p>\n");
    char text[96];
    html_swatch(f, "#000", "equal");
    snprintf(text, sizeof text, "within %g", r->threshold);
    html_swatch(f, "linear-gradient(90deg, #000059, #0000bc)", text);
    snprintf(text, sizeof text, "over %g, red through yellow to white at 1 (log scale)", r->threshold);
    html_swatch(f, "linear-gradient(90deg, #f00, #ff0, #fff)", text);
    html_swatch(f, "#f0f", "NaN or infinity");
    fprintf(f, "</p>\n<div class=\"row\">\n");
    for (int i = 0; i < r->nrows; i++) {
        snprintf(caption, sizeof caption, "%s against POV-Ray: RMSE %.6f", r->rows[i].name, r->rows[i].image.rmse);
        html_figure(f, r, r->rows[i].diff_png, caption);
    }
    fprintf(f, "</div>\n");

    fprintf(f, "<h2>Shadow masks against POV-Ray's</h2>\n<p>Which pixels are shadowed at the first hit, from "
               "renders without (+Q3) and with (+Q4) shadows (hstrace: a +Q4 render and its shadow.loss "
               "channels):</p>\n<p>\n");
    html_swatch(f, "#000", "lit in both");
    html_swatch(f, "#7c7c7c", "shadowed in both");
    html_swatch(f, "#00006c", "silhouette");
    html_swatch(f, "linear-gradient(90deg, #b30000 50%, #f00 50%)", "shadowed by POV-Ray only");
    html_swatch(f, "linear-gradient(90deg, #00b300 50%, #0f0 50%)", "shadowed by hstrace only");
    html_swatch(f, "linear-gradient(90deg, #b300b3 50%, #f0f 50%)", "shadowed in both, by other lights");
    fprintf(f, "</p>\n<p>Disagreements are dim (left half of a key) at a shadow edge or silhouette, bright "
               "(right half) elsewhere: those are errors.</p>\n<div class=\"row\">\n");
    for (int i = 0; i < r->nrows; i++) {
        const MaskComparison *m = &r->rows[i].mask;
        snprintf(caption, sizeof caption, "%s: %ld at edges, %ld interior", r->rows[i].name,
                 m->shadow_edge + m->silhouette, m->interior);
        html_figure(f, r, r->rows[i].mask_png, caption);
    }
    fprintf(f, "</div>\n");
    html_about(f, r);
    fprintf(f, "</body>\n</html>\n");
}
