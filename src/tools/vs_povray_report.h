/* What `hstrace vs-povray` measured, and its three outputs: the table
 * (stdout), JSON (--json, and DIR/vs-povray.json) and the HTML page of
 * --report DIR. Every figure is formatted by one function, so the page
 * shows exactly the table's values. */
#ifndef HST_VS_POVRAY_REPORT_H
#define HST_VS_POVRAY_REPORT_H

#include <stdio.h>

#include "image_compare.h"
#include "mask_compare.h"
#include "vs_povray_options.h"

/* One program: POV-Ray or hstrace with one shadow method. */
typedef struct {
    const char *name;       /* "povray", or the method's name */
    double wall;            /* median wall time of the full (+Q9) renders, seconds, whole process */
    double cpu;             /* median user + system CPU time of the same renders */
    double shadow;          /* hstrace: median shadow-testing time (time.shadow_testing of
                             * --stats-json, summed over threads); NAN for POV-Ray, which has none */
    double speedup;         /* POV-Ray's wall time over this one's */
    ImageComparison image;  /* the +Q9 render against POV-Ray's */
    MaskComparison mask;    /* the +Q3/+Q4 shadow mask against POV-Ray's */
    /* A method that is not exact (ShadowMethod.inexact): decisions checked
     * and disagreements with the exact shadow ray in an untimed full render
     * with --verify-shadows; -1 for the others and POV-Ray. */
    long long verified, disagreements;
    /* Files of the report, relative to its folder ("" when none). */
    char render_png[64], diff_png[64], mask_png[64];
} VsRow;

typedef struct {
    const char *scene;       /* as given */
    int width, height, threads, runs;
    double threshold;        /* per-channel tolerance of the comparisons */
    const char *command;     /* the command line, quoted for a POSIX shell */
    const char *hstrace_version;
    char povray_version[96]; /* from POV-Ray's banner ("3.7.0.10.unofficial"), or "unknown" */
    const char *povray_path;
    const char *povray_options; /* from the scene's "// povray-reference-options:" line, or "" */
    char date[40];           /* UTC, ISO 8601 */
    char machine[160];       /* operating system, processor architecture, cores */
    VsRow povray;
    VsRow rows[VS_MAX_METHODS]; /* one per method, in --methods order */
    int nrows;
} VsResult;

/* The table as plain text, with a heading and a legend. */
void vs_report_text(FILE *f, const VsResult *r);
/* One JSON object. */
void vs_report_json(FILE *f, const VsResult *r);
/* The page: self-contained HTML (inline style, no scripts, nothing fetched)
 * referring to the PNG files named in the rows, in the same folder. */
void vs_report_html(FILE *f, const VsResult *r);

#endif
