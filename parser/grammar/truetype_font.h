/* A TrueType font read as POV-Ray 3.7's text object reads it
 * (source/backend/shape/truetype.cpp): glyph outlines in font units divided
 * by the units per em, the glyph's bounds as its header gives them, the
 * horizontal metrics, the format 0 kerning pairs and the character maps in
 * POV-Ray's order of preference. FreeType reads the file (outlines unscaled,
 * FT_LOAD_NO_SCALE; the tables POV-Ray reads itself through
 * FT_Load_Sfnt_Table); POV-Ray's own choices and slips are kept here, each
 * named where it is reproduced. Without FreeType every call fails with
 * "built without FreeType". */
#ifndef HST_TRUETYPE_FONT_H
#define HST_TRUETYPE_FONT_H

#include <stddef.h>

typedef struct TtfFont TtfFont;

/* How the scene's strings are read (global_settings charset), which
 * decides the character maps tried first (OpenFontFile). */
enum { TTF_CHARSET_ASCII = 0, TTF_CHARSET_UTF8 = 1, TTF_CHARSET_SYS = 2 };

/* One glyph as ConvertOutlineToGlyph leaves it: contour k holds the points
 * start[k] .. start[k + 1] - 1, its last one a copy of its first. */
typedef struct {
    int ncontours;
    int *start;               /* ncontours + 1 */
    double *x, *y;            /* font units / units per em */
    unsigned char *on_curve;
    /* the header's bounds in font units, widened to the points as
     * ExtractGlyphOutline widens them (a composite glyph's with its slip) */
    int xmin, ymin, xmax, ymax;
    unsigned metrics;         /* the glyph whose metrics it takes (myMetrics) */
} TtfGlyph;

/* The font at path; NULL with a message in err when it cannot be read. */
TtfFont *ttf_open(const char *path, int charset, char *err, size_t errlen);
void ttf_close(TtfFont *f);

int ttf_units_per_em(const TtfFont *f);

/* ProcessCharMap: the glyph index of character ch (0: none). */
unsigned ttf_char_index(TtfFont *f, unsigned ch);

/* ExtractGlyphInfo: glyph `index`, asked for as character ch (a space is
 * never read). Returns 0, or -1 with a message in err. */
int ttf_glyph(TtfFont *f, unsigned index, unsigned ch, TtfGlyph *g, char *err, size_t errlen);
void ttf_glyph_free(TtfGlyph *g);

/* The advance width and left side bearing of glyph `metrics`, in font
 * units (the hmtx table, the last advance repeated). */
void ttf_metrics(const TtfFont *f, unsigned metrics, int *advance, int *lsb);

/* ProcessNewTTF's kerning between glyph `left` (the previous character's
 * index) and glyph `right` (this one's metrics), in font units, after
 * POV-Ray's floor of minus one em. */
void ttf_kerning(const TtfFont *f, unsigned left, unsigned right, int *kx, int *ky);

#endif
