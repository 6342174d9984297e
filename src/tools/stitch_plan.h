/* What `hstrace stitch` decides before it reads a pixel: where each part
 * lies, read from the options line hstrace writes into every EXR
 * (hstrace.options, see the man page's EXR header), whether the parts'
 * lines agree, and whether their areas fill the image exactly once. No
 * files here: stitch.c reads them and says what is wrong. */
#ifndef HST_STITCH_PLAN_H
#define HST_STITCH_PLAN_H

/* Pixels [x0, x1) x [y0, y1), row 0 at the top. */
typedef struct {
    int x0, y0, x1, y1;
} StitchArea;

/* An options line cut into its words (split at every space, so that the
 * words joined by single spaces are the line again). */
typedef struct {
    char *text;   /* the copy the words point into */
    char **word;
    int nwords;
    char *own;    /* per word: 1 for the words a part may differ in (the area, --threads N) */
    int width, height;
    int threads;  /* --threads' value, -1 when absent */
    int has_area; /* +SR +ER +SC +EC given: a partial render */
    StitchArea area; /* the whole image when !has_area */
} StitchLine;

/* Reads a part's hstrace.options. Returns 0, or -1 with the reason in err
 * (no --width or --height, an area incomplete or outside the image).
 * stitch_line_free either way. */
int stitch_line_parse(const char *options, StitchLine *l, char *err, int errlen);
void stitch_line_free(StitchLine *l);

/* Do a and b agree but for their own words? 1 when they do; else 0, with
 * *ia and *ib the first words that differ (either -1 when its line ended
 * first). */
int stitch_line_agree(const StitchLine *a, const StitchLine *b, int *ia, int *ib);

/* Word k as a reader wants it named: with the option it is the value of
 * ("--shadows cache", not "cache"), else alone ("+Q4"). */
void stitch_line_option(const StitchLine *l, int k, char *buf, int buflen);

/* The line of the whole image: l without its area, and without --threads
 * unless keep_threads (the parts used different thread counts). malloc'd;
 * NULL when out of memory. */
char *stitch_line_whole(const StitchLine *l, int keep_threads);

/* The first two areas (in the order given, i < j) that share a pixel, and
 * the rectangle they share: 1, or 0 when none do. */
int stitch_find_overlap(const StitchArea *a, int n, int *i, int *j, StitchArea *both);

/* Where areas that do not overlap leave the width x height image
 * uncovered: 1 with the topmost, then leftmost, gap's first row, its
 * columns there, and the rows down to the first area below that meets
 * those columns (a rectangle no area touches); 0 when they fill it.
 * Returns -1 when out of memory. */
int stitch_find_gap(const StitchArea *a, int n, int width, int height, StitchArea *gap);

#endif
