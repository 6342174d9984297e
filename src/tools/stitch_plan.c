/* The parts' areas and options lines (stitch_plan.h). */
#include "stitch_plan.h"

#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <stdio.h>

/* A whole number written as hstrace writes one (%d), 0 or more. */
static int whole_number(const char *s, int *out)
{
    if (*s < '0' || *s > '9')
        return -1;
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (*end != '\0' || errno || v > INT_MAX)
        return -1;
    *out = (int)v;
    return 0;
}

void stitch_line_free(StitchLine *l)
{
    free(l->text);
    free(l->word);
    free(l->own);
    memset(l, 0, sizeof *l);
}

int stitch_line_parse(const char *options, StitchLine *l, char *err, int errlen)
{
    memset(l, 0, sizeof *l);
    l->threads = -1;
    size_t n = strlen(options);
    int nwords = 1;
    for (size_t i = 0; i < n; i++)
        nwords += options[i] == ' ';
    l->text = malloc(n + 1);
    l->word = calloc((size_t)nwords, sizeof *l->word);
    l->own = calloc((size_t)nwords, 1);
    if (!l->text || !l->word || !l->own) {
        snprintf(err, (size_t)errlen, "out of memory");
        stitch_line_free(l);
        return -1;
    }
    memcpy(l->text, options, n + 1);
    l->word[l->nwords++] = l->text;
    for (char *c = l->text; *c; c++)
        if (*c == ' ') {
            *c = '\0';
            l->word[l->nwords++] = c + 1;
        }

    /* POV-Ray's rows and columns, counted from 1, ends included. */
    int value[4] = { 0, 0, 0, 0 }, have[4] = { 0, 0, 0, 0 };
    static const char *const area_switch[4] = { "+SR", "+ER", "+SC", "+EC" };
    int have_width = 0, have_height = 0;
    for (int k = 0; k < l->nwords; k++) {
        const char *w = l->word[k];
        const char *next = k + 1 < l->nwords ? l->word[k + 1] : "";
        if (strcmp(w, "--threads") == 0) {
            l->own[k] = 1;
            if (k + 1 < l->nwords) {
                l->own[k + 1] = 1;
                if (whole_number(next, &l->threads))
                    l->threads = -1;
                k++;
            }
            continue;
        }
        if ((strcmp(w, "--width") == 0 || strcmp(w, "--height") == 0) && !(w[2] == 'w' ? have_width : have_height)) {
            int *size = w[2] == 'w' ? &l->width : &l->height;
            if (whole_number(next, size) || *size < 1) {
                snprintf(err, (size_t)errlen, "'%s %s' is no image size", w, next);
                stitch_line_free(l);
                return -1;
            }
            *(w[2] == 'w' ? &have_width : &have_height) = 1;
            continue;
        }
        for (int s = 0; s < 4; s++)
            if (strncmp(w, area_switch[s], 3) == 0) {
                if (whole_number(w + 3, &value[s]) || have[s]) {
                    snprintf(err, (size_t)errlen, "'%s' is no area switch as hstrace writes one", w);
                    stitch_line_free(l);
                    return -1;
                }
                have[s] = 1;
                l->own[k] = 1;
            }
    }
    if (!have_width || !have_height) {
        snprintf(err, (size_t)errlen, "no --width and --height in it");
        stitch_line_free(l);
        return -1;
    }
    l->has_area = have[0] || have[1] || have[2] || have[3];
    l->area = (StitchArea){ 0, 0, l->width, l->height };
    if (!l->has_area)
        return 0;
    if (!(have[0] && have[1] && have[2] && have[3])) {
        snprintf(err, (size_t)errlen, "its area lacks one of +SR +ER +SC +EC");
        stitch_line_free(l);
        return -1;
    }
    if (value[0] < 1 || value[0] > value[1] || value[1] > l->height || value[2] < 1 || value[2] > value[3] ||
        value[3] > l->width) {
        snprintf(err, (size_t)errlen, "its area +SR%d +ER%d +SC%d +EC%d is not inside its %dx%d image", value[0],
                 value[1], value[2], value[3], l->width, l->height);
        stitch_line_free(l);
        return -1;
    }
    l->area = (StitchArea){ value[2] - 1, value[0] - 1, value[3], value[1] };
    return 0;
}

/* The next word at or after k that is not one of the line's own. */
static int next_shared(const StitchLine *l, int k)
{
    while (k < l->nwords && l->own[k])
        k++;
    return k;
}

int stitch_line_agree(const StitchLine *a, const StitchLine *b, int *ia, int *ib)
{
    int i = next_shared(a, 0), j = next_shared(b, 0);
    while (i < a->nwords && j < b->nwords && strcmp(a->word[i], b->word[j]) == 0) {
        i = next_shared(a, i + 1);
        j = next_shared(b, j + 1);
    }
    *ia = i < a->nwords ? i : -1;
    *ib = j < b->nwords ? j : -1;
    return *ia < 0 && *ib < 0;
}

void stitch_line_option(const StitchLine *l, int k, char *buf, int buflen)
{
    const char *w = l->word[k];
    /* A value follows its long option ("--nth 4"); switches (+Q9, -J) and
     * KEY=VALUE words stand alone. */
    if (k > 0 && strncmp(l->word[k - 1], "--", 2) == 0 && w[0] != '-' && w[0] != '+')
        snprintf(buf, (size_t)buflen, "%s %s", l->word[k - 1], w);
    else
        snprintf(buf, (size_t)buflen, "%s", w);
}

char *stitch_line_whole(const StitchLine *l, int keep_threads)
{
    size_t len = 1;
    for (int k = 0; k < l->nwords; k++)
        len += strlen(l->word[k]) + 1;
    char *s = malloc(len), *o = s;
    if (!s)
        return NULL;
    for (int k = 0; k < l->nwords; k++) {
        const char *w = l->word[k];
        /* The area goes; --threads and its value stay when asked. */
        int threads = strcmp(w, "--threads") == 0 || (k > 0 && strcmp(l->word[k - 1], "--threads") == 0);
        if (l->own[k] && !(threads && keep_threads))
            continue;
        if (o != s)
            *o++ = ' ';
        size_t n = strlen(w);
        memcpy(o, w, n);
        o += n;
    }
    *o = '\0';
    return s;
}

static int max_int(int a, int b) { return a > b ? a : b; }
static int min_int(int a, int b) { return a < b ? a : b; }

int stitch_find_overlap(const StitchArea *a, int n, int *i, int *j, StitchArea *both)
{
    for (int p = 0; p < n; p++)
        for (int q = p + 1; q < n; q++) {
            StitchArea s = { max_int(a[p].x0, a[q].x0), max_int(a[p].y0, a[q].y0), min_int(a[p].x1, a[q].x1),
                             min_int(a[p].y1, a[q].y1) };
            if (s.x0 < s.x1 && s.y0 < s.y1) {
                *i = p;
                *j = q;
                *both = s;
                return 1;
            }
        }
    return 0;
}

typedef struct {
    int x0, x1;
} Span;

static int by_start(const void *a, const void *b)
{
    const Span *s = a, *t = b;
    return (s->x0 > t->x0) - (s->x0 < t->x0);
}

/* The first columns of row y that no area covers: 1 with [*x0, *x1), or 0. */
static int row_gap(const StitchArea *a, int n, int width, int y, Span *spans, int *x0, int *x1)
{
    int m = 0;
    for (int k = 0; k < n; k++)
        if (a[k].y0 <= y && y < a[k].y1)
            spans[m++] = (Span){ a[k].x0, a[k].x1 };
    qsort(spans, (size_t)m, sizeof *spans, by_start);
    int covered = 0; /* columns [0, covered) are covered */
    for (int k = 0; k < m; k++) {
        if (spans[k].x0 > covered) {
            *x0 = covered;
            *x1 = spans[k].x0;
            return 1;
        }
        covered = max_int(covered, spans[k].x1);
    }
    if (covered < width) {
        *x0 = covered;
        *x1 = width;
        return 1;
    }
    return 0;
}

int stitch_find_gap(const StitchArea *a, int n, int width, int height, StitchArea *gap)
{
    Span *spans = malloc(sizeof *spans * (size_t)(n > 0 ? n : 1));
    if (!spans)
        return -1;
    /* A row's cover only shrinks where an area ends, so the first row
     * with a gap is row 0 or the row below some area. */
    int found = 0;
    StitchArea best = { 0, 0, 0, 0 };
    for (int k = -1; k < n; k++) {
        int y = k < 0 ? 0 : a[k].y1, x0, x1;
        if (y >= height || (found && y >= best.y0))
            continue;
        if (row_gap(a, n, width, y, spans, &x0, &x1)) {
            best = (StitchArea){ x0, y, x1, height };
            found = 1;
        }
    }
    free(spans);
    if (!found)
        return 0;
    /* Down to the first area below that meets those columns. */
    for (int k = 0; k < n; k++)
        if (a[k].y0 > best.y0 && a[k].y0 < best.y1 && a[k].x0 < best.x1 && a[k].x1 > best.x0)
            best.y1 = a[k].y0;
    *gap = best;
    return 1;
}
