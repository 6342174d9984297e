/* stitch_plan.h: the options line hstrace writes read back (the area, the
 * size, the words parts may differ in), lines that are not hstrace's
 * refused with a reason, and the overlap and gap searches held against a
 * pixel-by-pixel count on random tilings with pieces taken out or added. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stitch_plan.h"
#include "tap.h"

#define LINE "--width 64 --height 48 +Q9 --shadows hst --grid 48x24x26 --threads 2"

static void test_lines(void)
{
    char err[256] = "";
    StitchLine a, b;
    int rc = stitch_line_parse(LINE " +SR17 +ER30 +SC5 +EC64", &a, err, sizeof err);
    tap_ok(rc == 0 && a.width == 64 && a.height == 48 && a.threads == 2 && a.has_area && a.area.x0 == 4 &&
               a.area.y0 == 16 && a.area.x1 == 64 && a.area.y1 == 30,
           "+SR17 +ER30 +SC5 +EC64 of 64x48: columns [4, 64), rows [16, 30), 2 threads (%s)", err);
    rc = stitch_line_parse(LINE, &b, err, sizeof err);
    tap_ok(rc == 0 && !b.has_area && b.area.x0 == 0 && b.area.y1 == 48 && b.area.x1 == 64,
           "no area: the whole image");
    int ia, ib;
    tap_ok(stitch_line_agree(&a, &b, &ia, &ib) && ia < 0 && ib < 0, "lines agree but for the area");
    char *whole = stitch_line_whole(&a, 1), *bare = stitch_line_whole(&a, 0);
    tap_ok(whole && strcmp(whole, LINE) == 0, "the whole's line keeps --threads when asked: '%s'", whole);
    tap_ok(bare && strcmp(bare, "--width 64 --height 48 +Q9 --shadows hst --grid 48x24x26") == 0,
           "... and drops it otherwise: '%s'", bare);
    free(whole);
    free(bare);
    stitch_line_free(&b);

    rc = stitch_line_parse("--width 64 --height 48 +Q9 --shadows cache --grid 48x24x26 --threads 1 +SR1 +ER16 +SC1 +EC64",
                           &b, err, sizeof err);
    char wa[64] = "", wb[64] = "";
    int differ = rc == 0 && !stitch_line_agree(&a, &b, &ia, &ib) && ia >= 0 && ib >= 0;
    if (differ) {
        stitch_line_option(&a, ia, wa, (int)sizeof wa);
        stitch_line_option(&b, ib, wb, (int)sizeof wb);
    }
    tap_ok(differ && strcmp(wa, "--shadows hst") == 0 && strcmp(wb, "--shadows cache") == 0,
           "the first difference named with its option: '%s' / '%s' (threads and area ignored)", wa, wb);
    stitch_line_free(&b);
    rc = stitch_line_parse(LINE " +A0.3", &b, err, sizeof err);
    tap_ok(rc == 0 && !stitch_line_agree(&a, &b, &ia, &ib) && ia < 0 && ib >= 0 && strcmp(b.word[ib], "+A0.3") == 0,
           "a word one line has and the other not: the other ran out");
    stitch_line_free(&b);
    stitch_line_free(&a);

    static const struct {
        const char *line, *why;
    } bad[] = {
        { "+Q9 --threads 2", "no --width and --height" },
        { "--width 64 --height x", "'--height x' is no image size" },
        { "--width 0 --height 48", "'--width 0' is no image size" },
        { "--width 64 --height 48 +SR1 +ER16", "lacks one of +SR +ER +SC +EC" },
        { "--width 64 --height 48 +SR1 +ER49 +SC1 +EC64", "+SR1 +ER49 +SC1 +EC64 is not inside its 64x48 image" },
        { "--width 64 --height 48 +SR0 +ER4 +SC1 +EC64", "is not inside" },
        { "--width 64 --height 48 +SR9 +ER4 +SC1 +EC64", "is not inside" },
        { "--width 64 --height 48 +SR0.5 +ER4 +SC1 +EC64", "'+SR0.5' is no area switch" },
        { "--width 64 --height 48 +SR1 +SR2 +ER4 +SC1 +EC64", "'+SR2' is no area switch" },
        { "--width 64 --height 48 +SR99999999999 +ER4 +SC1 +EC64", "no area switch" },
        { "", "no --width and --height" },
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        err[0] = '\0';
        rc = stitch_line_parse(bad[k].line, &a, err, sizeof err);
        tap_ok(rc == -1 && strstr(err, bad[k].why) && a.word == NULL, "'%s' refused: %s", bad[k].line, err);
        stitch_line_free(&a);
    }
}

/* ---- overlaps and gaps against a count of every pixel ----------------------- */

static unsigned next_random(unsigned *s)
{
    *s = *s * 1103515245u + 12345u;
    return (*s >> 16) & 0x7fff;
}

/* Cuts [x0,x1) x [y0,y1) into pieces by random cuts, down to depth 0. */
static void cut(StitchArea r, int depth, unsigned *seed, StitchArea *out, int *n, int max)
{
    int w = r.x1 - r.x0, h = r.y1 - r.y0;
    if (depth == 0 || *n >= max - 1 || (w < 2 && h < 2)) {
        out[(*n)++] = r;
        return;
    }
    StitchArea a = r, b = r;
    if ((w >= h && w >= 2) || h < 2) {
        int at = r.x0 + 1 + (int)(next_random(seed) % (unsigned)(w - 1));
        a.x1 = b.x0 = at;
    } else {
        int at = r.y0 + 1 + (int)(next_random(seed) % (unsigned)(h - 1));
        a.y1 = b.y0 = at;
    }
    cut(a, depth - 1, seed, out, n, max);
    cut(b, depth - 1, seed, out, n, max);
}

static void test_cover(void)
{
    enum { W = 37, H = 23, MAX = 64 };
    int overlap_bad = 0, gap_bad = 0, tilings = 0;
    unsigned seed = 12345;
    for (int t = 0; t < 2000; t++) {
        StitchArea a[MAX + 1];
        int n = 0;
        cut((StitchArea){ 0, 0, W, H }, 1 + (int)(next_random(&seed) % 6), &seed, a, &n, MAX);
        int kind = (int)(next_random(&seed) % 3); /* 0 whole, 1 a piece out, 2 a piece added */
        if (kind == 1 && n > 1) {
            a[next_random(&seed) % (unsigned)n] = a[n - 1];
            n--;
        } else if (kind == 2) {
            int x0 = (int)(next_random(&seed) % W), y0 = (int)(next_random(&seed) % H);
            a[n++] = (StitchArea){ x0, y0, x0 + 1 + (int)(next_random(&seed) % (unsigned)(W - x0)),
                                   y0 + 1 + (int)(next_random(&seed) % (unsigned)(H - y0)) };
        }
        tilings++;
        /* The count: how many areas hold each pixel. */
        int count[H][W];
        memset(count, 0, sizeof count);
        for (int k = 0; k < n; k++)
            for (int y = a[k].y0; y < a[k].y1; y++)
                for (int x = a[k].x0; x < a[k].x1; x++)
                    count[y][x]++;
        int twice = 0, first_gap_y = -1, first_gap_x = -1;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                twice |= count[y][x] > 1;
                if (count[y][x] == 0 && first_gap_y < 0) {
                    first_gap_y = y;
                    first_gap_x = x;
                }
            }
        int i, j;
        StitchArea both;
        int found = stitch_find_overlap(a, n, &i, &j, &both);
        if (found != twice)
            overlap_bad++;
        if (found) {
            /* The rectangle named is in both areas and every pixel of it held twice. */
            for (int y = both.y0; y < both.y1; y++)
                for (int x = both.x0; x < both.x1; x++)
                    overlap_bad += count[y][x] < 2 || x < a[i].x0 || x >= a[i].x1 || y < a[j].y0 || y >= a[j].y1;
            continue;
        }
        StitchArea gap;
        int g = stitch_find_gap(a, n, W, H, &gap);
        if (g != (first_gap_y >= 0)) {
            gap_bad++;
            continue;
        }
        if (g) {
            /* Begins at the first uncovered pixel in reading order, holds
             * no covered pixel, and cannot grow by a column at its row. */
            gap_bad += gap.y0 != first_gap_y || gap.x0 != first_gap_x || gap.x1 <= gap.x0 || gap.y1 <= gap.y0;
            for (int y = gap.y0; y < gap.y1; y++)
                for (int x = gap.x0; x < gap.x1; x++)
                    gap_bad += count[y][x] != 0;
            gap_bad += gap.x1 < W && count[gap.y0][gap.x1] == 0;
        }
    }
    tap_ok(overlap_bad == 0, "overlaps: found exactly where a pixel is held twice, in %d random tilings (%d wrong)",
           tilings, overlap_bad);
    tap_ok(gap_bad == 0, "gaps: the first uncovered pixel, a rectangle no area touches (%d wrong)", gap_bad);
    StitchArea none[1];
    StitchArea gap;
    tap_ok(stitch_find_gap(none, 0, 5, 4, &gap) == 1 && gap.x0 == 0 && gap.y0 == 0 && gap.x1 == 5 && gap.y1 == 4,
           "no areas: the whole image is the gap");
}

int main(void)
{
    test_lines();
    test_cover();
    return tap_done();
}
