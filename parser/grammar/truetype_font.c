/* TrueType fonts as POV-Ray 3.7's truetype.cpp reads them (ProcessFontFile,
 * ProcessCharMap, ExtractGlyphOutline, ConvertOutlineToGlyph,
 * ProcessKernTable, ProcessHmtxTable), through FreeType. Written anew from
 * reading them. */
#include "truetype_font.h"

#include <config.h>

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void say(char *err, size_t n, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, n, fmt, ap);
    va_end(ap);
}

#ifndef HAVE_FREETYPE

TtfFont *ttf_open(const char *path, int charset, char *err, size_t errlen)
{
    (void)path;
    (void)charset;
    say(err, errlen, "text: hstrace was built without FreeType (install libfreetype-dev and configure again)");
    return NULL;
}
void ttf_close(TtfFont *f) { (void)f; }
int ttf_units_per_em(const TtfFont *f) { (void)f; return 1; }
unsigned ttf_char_index(TtfFont *f, unsigned ch) { (void)f; (void)ch; return 0; }
int ttf_glyph(TtfFont *f, unsigned index, unsigned ch, TtfGlyph *g, char *err, size_t errlen)
{
    (void)f; (void)index; (void)ch; (void)g;
    say(err, errlen, "built without FreeType");
    return -1;
}
void ttf_glyph_free(TtfGlyph *g) { (void)g; }
void ttf_metrics(const TtfFont *f, unsigned metrics, int *advance, int *lsb)
{
    (void)f; (void)metrics;
    *advance = *lsb = 0;
}
void ttf_kerning(const TtfFont *f, unsigned left, unsigned right, int *kx, int *ky)
{
    (void)f; (void)left; (void)right;
    *kx = *ky = 0;
}

#else

#include <errno.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_TRUETYPE_TABLES_H
#include FT_TRUETYPE_TAGS_H

/* Kern coverage bits (ProcessNewTTF) */
enum { KERN_HORIZONTAL = 0x01, KERN_MINIMUM = 0x02, KERN_CROSS_STREAM = 0x04, KERN_OVERRIDE = 0x08 };
/* Composite glyph flags (ExtractGlyphOutline) */
enum { ARG_1_AND_2_ARE_WORDS = 0x0001, ARGS_ARE_XY_VALUES = 0x0002, USE_MY_METRICS = 0x0200 };
#define MAX_COMPOSITE_DEPTH 16

typedef struct {
    unsigned left, right;
    int value;
} KernPair;

typedef struct {
    unsigned coverage;
    int npairs;
    KernPair *pairs;
} KernTable;

struct TtfFont {
    FT_Library lib;
    FT_Face face;
    int units_per_em;
    int num_glyphs;
    unsigned long *loca;      /* num_glyphs + 1 byte offsets into glyf */
    unsigned long glyf_size;
    int nmetrics;             /* numberOfHMetrics */
    int *advance, *lsb;       /* num_glyphs each */
    int nkern;
    KernTable *kern;
    FT_CharMap cmap;          /* the map ProcessCharMap settles on, or NULL */
};

static unsigned be16(const unsigned char *p) { return (unsigned)p[0] << 8 | p[1]; }
static int sbe16(const unsigned char *p) { return (int)(short)(unsigned short)be16(p); }
static unsigned long be32(const unsigned char *p)
{
    return (unsigned long)p[0] << 24 | (unsigned long)p[1] << 16 | (unsigned long)p[2] << 8 | p[3];
}

/* A whole sfnt table (NULL when absent), and its length. */
static unsigned char *load_table(FT_Face face, FT_ULong tag, FT_ULong *len)
{
    *len = 0;
    if (FT_Load_Sfnt_Table(face, tag, 0, NULL, len) || *len == 0)
        return NULL;
    unsigned char *buf = malloc(*len);
    if (buf && FT_Load_Sfnt_Table(face, tag, 0, buf, len)) {
        free(buf);
        return NULL;
    }
    return buf;
}

/* ProcessKernTable: format 0 subtables read in turn; others skipped. */
static int read_kern(TtfFont *f)
{
    FT_ULong len;
    unsigned char *k = load_table(f->face, TTAG_kern, &len);
    if (!k)
        return 0;
    int rc = 0;
    size_t at = 2;
    if (len < 4)
        goto done;
    int n = (int)be16(k + at);
    at += 2;
    f->kern = calloc((size_t)(n ? n : 1), sizeof *f->kern);
    if (!f->kern) {
        rc = -1;
        goto done;
    }
    f->nkern = n;
    for (int i = 0; i < n; i++) {
        if (at + 6 > len)
            break;
        unsigned length = be16(k + at + 2);
        f->kern[i].coverage = be16(k + at + 4);
        at += 6;
        if ((f->kern[i].coverage >> 8) != 0) {
            at += length >= 6 ? length - 6 : 0;
            continue;
        }
        if (at + 8 > len)
            break;
        int np = (int)be16(k + at);
        at += 8;
        if (at + 6 * (size_t)np > len)
            np = (int)((len - at) / 6);
        f->kern[i].pairs = malloc(sizeof *f->kern[i].pairs * (size_t)(np ? np : 1));
        if (!f->kern[i].pairs) {
            rc = -1;
            goto done;
        }
        f->kern[i].npairs = np;
        for (int j = 0; j < np; j++, at += 6) {
            f->kern[i].pairs[j].left = be16(k + at);
            f->kern[i].pairs[j].right = be16(k + at + 2);
            f->kern[i].pairs[j].value = sbe16(k + at + 4);
        }
    }
done:
    free(k);
    return rc;
}

/* The loca offsets and the horizontal metrics (ProcessLocaTable,
 * ProcessHheaTable, ProcessHmtxTable). */
static int read_tables(TtfFont *f, char *err, size_t errlen)
{
    FT_Face face = f->face;
    TT_Header *head = FT_Get_Sfnt_Table(face, FT_SFNT_HEAD);
    TT_HoriHeader *hhea = FT_Get_Sfnt_Table(face, FT_SFNT_HHEA);
    TT_MaxProfile *maxp = FT_Get_Sfnt_Table(face, FT_SFNT_MAXP);
    if (!head || !hhea || !maxp) {
        say(err, errlen, "not a TrueType font (no head, hhea or maxp table)");
        return -1;
    }
    f->units_per_em = head->Units_Per_EM;
    f->num_glyphs = maxp->numGlyphs;
    f->nmetrics = hhea->number_Of_HMetrics;
    /* POV-Ray refuses nothing here but a bad magic number (ProcessHeadTable);
     * the rest it would read as garbage: refused instead */
    if (f->units_per_em < 16 || f->units_per_em > 16384 || f->num_glyphs <= 0 || f->nmetrics <= 0) {
        say(err, errlen, "invalid TrueType font data");
        return -1;
    }
    FT_ULong len, glen = 0;
    if (FT_Load_Sfnt_Table(face, TTAG_glyf, 0, NULL, &glen)) {
        say(err, errlen, "not a TrueType outline font (no glyf table)");
        return -1;
    }
    f->glyf_size = glen;
    unsigned char *loca = load_table(face, TTAG_loca, &len);
    f->loca = calloc((size_t)f->num_glyphs + 1, sizeof *f->loca);
    f->advance = calloc((size_t)f->num_glyphs, sizeof *f->advance);
    f->lsb = calloc((size_t)f->num_glyphs, sizeof *f->lsb);
    if (!loca || !f->loca || !f->advance || !f->lsb) {
        free(loca);
        say(err, errlen, "cannot read the font's glyph locations");
        return -1;
    }
    const int long_offsets = head->Index_To_Loc_Format != 0;
    for (int i = 0; i <= f->num_glyphs; i++) {
        size_t at = (size_t)i * (long_offsets ? 4 : 2);
        if (at + (long_offsets ? 4 : 2) > len)
            f->loca[i] = i > 0 ? f->loca[i - 1] : 0;
        else
            f->loca[i] = long_offsets ? be32(loca + at) : (unsigned long)be16(loca + at) << 1;
    }
    free(loca);
    unsigned char *hmtx = load_table(face, TTAG_hmtx, &len);
    if (!hmtx) {
        say(err, errlen, "the font has no hmtx table");
        return -1;
    }
    int last_aw = 0;
    size_t at = 0;
    for (int i = 0; i < f->num_glyphs; i++) {
        if (i < f->nmetrics) {
            if (at + 4 <= len) {
                last_aw = (int)be16(hmtx + at);
                f->lsb[i] = sbe16(hmtx + at + 2);
            }
            at += 4;
        } else {
            if (at + 2 <= len)
                f->lsb[i] = sbe16(hmtx + at);
            at += 2;
        }
        f->advance[i] = last_aw;
    }
    free(hmtx);
    return 0;
}

/* OpenFontFile's order of preference among the character maps, by the
 * scene's charset; ProcessCharMap compares the platform alone. */
static void choose_cmap(TtfFont *f, int charset)
{
    static const int ascii_order[4] = { 1, 3, 0, 3 };
    static const int unicode_order[4] = { 0, 3, 1, 3 };
    const int *order = charset == TTF_CHARSET_ASCII ? ascii_order : unicode_order;
    f->cmap = NULL;
    for (int j = 0; j < 4 && !f->cmap; j++)
        for (int i = 0; i < f->face->num_charmaps; i++) {
            FT_CharMap m = f->face->charmaps[i];
            if (m->platform_id != order[j])
                continue;
            long format = FT_Get_CMap_Format(m);
            /* the first of formats 0, 4 and 6 answers, found or not */
            if (format == 0 || format == 4 || format == 6) {
                f->cmap = m;
                break;
            }
        }
}

/* Why the font file at `path` is no regular file, or NULL when it is (or
 * cannot be opened: FreeType then says so). FreeType's own open waits for
 * ever on a FIFO for a writer; opened here with O_NONBLOCK, a FIFO is
 * refused at once, as the scene's other files are. */
static const char *irregular_file(const char *path)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return NULL;
    struct stat st;
    const char *why = fstat(fd, &st) != 0    ? strerror(errno)
                      : S_ISDIR(st.st_mode)  ? strerror(EISDIR)
                      : S_ISFIFO(st.st_mode) ? "a FIFO, not a regular file"
                      : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device, not a regular file"
                      : !S_ISREG(st.st_mode) ? "not a regular file"
                                             : NULL;
    close(fd);
    return why;
}

TtfFont *ttf_open(const char *path, int charset, char *err, size_t errlen)
{
    TtfFont *f = calloc(1, sizeof *f);
    if (!f) {
        say(err, errlen, "out of memory");
        return NULL;
    }
    if (FT_Init_FreeType(&f->lib)) {
        free(f);
        say(err, errlen, "cannot start FreeType");
        return NULL;
    }
    const char *irregular = irregular_file(path);
    if (irregular) {
        say(err, errlen, "cannot read the font file '%s': %s", path, irregular);
        ttf_close(f);
        return NULL;
    }
    /* a TrueType collection: its first font, as POV-Ray takes it */
    if (FT_New_Face(f->lib, path, 0, &f->face)) {
        say(err, errlen, "cannot read the font file '%s'", path);
        ttf_close(f);
        return NULL;
    }
    if (!FT_IS_SFNT(f->face) || read_tables(f, err, errlen)) {
        if (!FT_IS_SFNT(f->face))
            say(err, errlen, "'%s' is not a TrueType font", path);
        ttf_close(f);
        return NULL;
    }
    if (read_kern(f)) {
        say(err, errlen, "out of memory");
        ttf_close(f);
        return NULL;
    }
    choose_cmap(f, charset);
    return f;
}

void ttf_close(TtfFont *f)
{
    if (!f)
        return;
    for (int i = 0; i < f->nkern; i++)
        free(f->kern[i].pairs);
    free(f->kern);
    free(f->loca);
    free(f->advance);
    free(f->lsb);
    if (f->face)
        FT_Done_Face(f->face);
    FT_Done_FreeType(f->lib);
    free(f);
}

int ttf_units_per_em(const TtfFont *f) { return f->units_per_em; }

unsigned ttf_char_index(TtfFont *f, unsigned ch)
{
    if (!f->cmap || FT_Set_Charmap(f->face, f->cmap))
        return 0;
    unsigned index = FT_Get_Char_Index(f->face, ch);
    /* ProcessFormat4Glyph: a character below 0x100 not found is looked for
     * again in the private use area, where symbol fonts keep theirs */
    if (index == 0 && ch < 0x100 && FT_Get_CMap_Format(f->cmap) == 4)
        index = FT_Get_Char_Index(f->face, ch + 0xF000);
    return index & 0xFFFF;
}

/* ExtractGlyphOutline's flat form: points, contour ends, header bounds. */
typedef struct {
    int npoints, ncontours;
    double *x, *y;
    unsigned char *on;
    int *ends;
    int xmin, ymin, xmax, ymax;
    unsigned metrics;
} Outline;

static void outline_free(Outline *o)
{
    free(o->x);
    free(o->y);
    free(o->on);
    free(o->ends);
    memset(o, 0, sizeof *o);
}

/* C's conversion of a double to a short, as POV-Ray assigns a point's em
 * coordinate to a header bound of a composite glyph. */
static int to_short(double v)
{
    if (!(v > -32768.0 && v < 32768.0))
        return 0;
    return (short)(int)v;
}

static int extract(TtfFont *f, unsigned index, unsigned ch, Outline *o, int depth, char *err, size_t errlen);

/* The glyph at `index` read as POV-Ray reads it: at its loca offset, so
 * that an empty glyph (no bytes of its own) is read as the glyph whose
 * bytes start there (the next one that has any). */
static unsigned stored_glyph(const TtfFont *f, unsigned index)
{
    unsigned k = index;
    while ((int)k < f->num_glyphs && f->loca[k + 1] == f->loca[index])
        k++;
    return k;
}

static int read_header(TtfFont *f, unsigned index, int *nc, int box[4])
{
    unsigned char h[10];
    FT_ULong len = sizeof h;
    unsigned long at = f->loca[index];
    if (at + sizeof h > f->glyf_size || FT_Load_Sfnt_Table(f->face, TTAG_glyf, (FT_Long)at, h, &len))
        return -1;
    *nc = sbe16(h);
    for (int i = 0; i < 4; i++)
        box[i] = sbe16(h + 2 + 2 * i);
    return 0;
}

static int append_points(Outline *o, int n, int nc)
{
    double *x = realloc(o->x, sizeof *x * (size_t)(o->npoints + n + 1));
    if (x)
        o->x = x;
    double *y = realloc(o->y, sizeof *y * (size_t)(o->npoints + n + 1));
    if (y)
        o->y = y;
    unsigned char *on = realloc(o->on, (size_t)(o->npoints + n + 1));
    if (on)
        o->on = on;
    int *ends = realloc(o->ends, sizeof *ends * (size_t)(o->ncontours + nc + 1));
    if (ends)
        o->ends = ends;
    return x && y && on && ends ? 0 : -1;
}

static int extract_simple(TtfFont *f, unsigned stored, Outline *o, char *err, size_t errlen)
{
    if (FT_Load_Glyph(f->face, stored, FT_LOAD_NO_SCALE | FT_LOAD_NO_RECURSE | FT_LOAD_NO_HINTING)) {
        say(err, errlen, "cannot read glyph %u of the font", stored);
        return -1;
    }
    const FT_Outline *ol = &f->face->glyph->outline;
    if (ol->n_contours <= 0)
        return 0;
    if (append_points(o, ol->n_points, ol->n_contours))
        return -1;
    const double em = (double)f->units_per_em;
    for (int i = 0; i < ol->n_points; i++) {
        long cx = ol->points[i].x, cy = ol->points[i].y;
        /* POV-Ray widens the header's bounds to the points it reads */
        if (cx > o->xmax) o->xmax = (int)cx;
        if (cx < o->xmin) o->xmin = (int)cx;
        if (cy > o->ymax) o->ymax = (int)cy;
        if (cy < o->ymin) o->ymin = (int)cy;
        o->x[i] = (double)cx / em;
        o->y[i] = (double)cy / em;
        o->on[i] = FT_CURVE_TAG(ol->tags[i]) == FT_CURVE_TAG_ON;
    }
    for (int k = 0; k < ol->n_contours; k++)
        o->ends[k] = ol->contours[k];
    o->npoints = ol->n_points;
    o->ncontours = ol->n_contours;
    return 0;
}

/* A composite glyph: its parts placed by their offsets and 2x2 matrices as
 * POV-Ray places them (x' = xx x + yx y, y' = xy x + yy y, the second and
 * third numbers of the file's matrix taken the other way round from the
 * specification), parts given by point numbers left out, byte offsets read
 * unsigned; the header's bounds compared with the parts' em coordinates. */
static int extract_composite(TtfFont *f, unsigned stored, unsigned ch, Outline *o, int depth, char *err,
                             size_t errlen)
{
    if (FT_Load_Glyph(f->face, stored, FT_LOAD_NO_SCALE | FT_LOAD_NO_RECURSE | FT_LOAD_NO_HINTING)) {
        say(err, errlen, "cannot read glyph %u of the font", stored);
        return -1;
    }
    FT_GlyphSlot slot = f->face->glyph;
    if (slot->format != FT_GLYPH_FORMAT_COMPOSITE)
        return 0;
    const unsigned nsub = slot->num_subglyphs;
    const double em = (double)f->units_per_em;
    typedef struct {
        FT_Int index;
        FT_UInt flags;
        FT_Int arg1, arg2;
        FT_Matrix m;
    } Part;
    Part *parts = malloc(sizeof *parts * (nsub ? nsub : 1));
    if (!parts)
        return -1;
    for (unsigned i = 0; i < nsub; i++)
        if (FT_Get_SubGlyph_Info(slot, i, &parts[i].index, &parts[i].flags, &parts[i].arg1, &parts[i].arg2,
                                 &parts[i].m)) {
            free(parts);
            say(err, errlen, "cannot read glyph %u of the font", stored);
            return -1;
        }
    int rc = 0;
    for (unsigned i = 0; i < nsub && rc == 0; i++) {
        const Part *pt = &parts[i];
        if (!(pt->flags & ARGS_ARE_XY_VALUES))
            continue;
        int a1 = pt->arg1, a2 = pt->arg2;
        if (!(pt->flags & ARG_1_AND_2_ARE_WORDS)) {
            a1 &= 0xFF;
            a2 &= 0xFF;
        }
        if (pt->flags & USE_MY_METRICS)
            o->metrics = (unsigned)pt->index;
        Outline sub;
        memset(&sub, 0, sizeof sub);
        rc = extract(f, (unsigned)pt->index, ch, &sub, depth + 1, err, errlen);
        if (rc == 0 && sub.ncontours > 0) {
            const double xs = pt->m.xx / 65536.0, s01 = pt->m.yx / 65536.0;
            const double s10 = pt->m.xy / 65536.0, ys = pt->m.yy / 65536.0;
            const double xoff = (double)a1 / em, yoff = (double)a2 / em;
            rc = append_points(o, sub.npoints, sub.ncontours);
            for (int k = 0; rc == 0 && k < sub.ncontours; k++)
                o->ends[o->ncontours + k] = sub.ends[k] + o->npoints;
            for (int k = 0; rc == 0 && k < sub.npoints; k++) {
                const int n = o->npoints + k;
                o->on[n] = sub.on[k];
                o->x[n] = xs * sub.x[k] + s01 * sub.y[k] + xoff;
                o->y[n] = s10 * sub.x[k] + ys * sub.y[k] + yoff;
                if (o->x[n] < o->xmin) o->xmin = to_short(o->x[n]);
                if (o->x[n] > o->xmax) o->xmax = to_short(o->x[n]);
                if (o->y[n] < o->ymin) o->ymin = to_short(o->y[n]);
                if (o->y[n] > o->ymax) o->ymax = to_short(o->y[n]);
            }
            if (rc == 0) {
                o->ncontours += sub.ncontours;
                o->npoints += sub.npoints;
            }
        }
        outline_free(&sub);
    }
    free(parts);
    return rc;
}

static int extract(TtfFont *f, unsigned index, unsigned ch, Outline *o, int depth, char *err, size_t errlen)
{
    o->metrics = index;
    if (ch == ' ') /* a space is never read: no contours, bounds 0 */
        return 0;
    if (depth > MAX_COMPOSITE_DEPTH) {
        say(err, errlen, "glyph %u of the font nests its parts too deeply", index);
        return -1;
    }
    if ((int)index >= f->num_glyphs) {
        say(err, errlen, "glyph %u is not in the font", index);
        return -1;
    }
    const unsigned stored = stored_glyph(f, index);
    int nc, box[4];
    if ((int)stored >= f->num_glyphs || read_header(f, stored, &nc, box))
        return 0; /* no bytes left to read: nothing drawn */
    o->xmin = box[0];
    o->ymin = box[1];
    o->xmax = box[2];
    o->ymax = box[3];
    if (nc > 0)
        return extract_simple(f, stored, o, err, errlen);
    if (nc < 0)
        return extract_composite(f, stored, ch, o, depth, err, errlen);
    return 0;
}

int ttf_glyph(TtfFont *f, unsigned index, unsigned ch, TtfGlyph *g, char *err, size_t errlen)
{
    memset(g, 0, sizeof *g);
    Outline o;
    memset(&o, 0, sizeof o);
    if (extract(f, index, ch, &o, 0, err, errlen)) {
        outline_free(&o);
        return -1;
    }
    /* ConvertOutlineToGlyph: each contour closed by a copy of its first
     * point */
    g->start = malloc(sizeof *g->start * (size_t)(o.ncontours + 1));
    g->x = malloc(sizeof *g->x * (size_t)(o.npoints + o.ncontours + 1));
    g->y = malloc(sizeof *g->y * (size_t)(o.npoints + o.ncontours + 1));
    g->on_curve = malloc((size_t)(o.npoints + o.ncontours + 1));
    if (!g->start || !g->x || !g->y || !g->on_curve) {
        outline_free(&o);
        ttf_glyph_free(g);
        say(err, errlen, "out of memory");
        return -1;
    }
    int n = 0, first = 0;
    for (int k = 0; k < o.ncontours; k++) {
        g->start[k] = n;
        int last = o.ends[k];
        if (last < first || last >= o.npoints) { /* a malformed contour: left out */
            g->start[k] = n;
            continue;
        }
        for (int i = first; i <= last; i++, n++) {
            g->x[n] = o.x[i];
            g->y[n] = o.y[i];
            g->on_curve[n] = o.on[i];
        }
        g->x[n] = o.x[first];
        g->y[n] = o.y[first];
        g->on_curve[n] = o.on[first];
        n++;
        first = last + 1;
    }
    g->start[o.ncontours] = n;
    g->ncontours = o.ncontours;
    g->xmin = o.xmin;
    g->ymin = o.ymin;
    g->xmax = o.xmax;
    g->ymax = o.ymax;
    g->metrics = o.metrics;
    outline_free(&o);
    return 0;
}

void ttf_glyph_free(TtfGlyph *g)
{
    free(g->start);
    free(g->x);
    free(g->y);
    free(g->on_curve);
    memset(g, 0, sizeof *g);
}

void ttf_metrics(const TtfFont *f, unsigned metrics, int *advance, int *lsb)
{
    if ((int)metrics >= f->num_glyphs) {
        *advance = *lsb = 0;
        return;
    }
    *advance = f->advance[metrics];
    *lsb = f->lsb[metrics];
}

void ttf_kerning(const TtfFont *f, unsigned left, unsigned right, int *kx, int *ky)
{
    short x = 0, y = 0;
    short min_x = (short)-f->units_per_em, min_y = (short)-f->units_per_em;
    for (int j = 0; j < f->nkern; j++) {
        /* ProcessNewTTF reads the coverage of the first subtable for every
         * one of them */
        const unsigned coverage = f->kern[0].coverage;
        if (!(coverage & KERN_HORIZONTAL))
            continue;
        const KernTable *t = &f->kern[j];
        for (int k = 0; k < t->npairs; k++) {
            const KernPair *kp = &t->pairs[k];
            if (kp->left == left && kp->right == right) {
                const short v = (short)kp->value;
                if (coverage & KERN_MINIMUM) {
                    if (coverage & KERN_CROSS_STREAM)
                        min_y = v;
                    else
                        min_x = v;
                } else if (coverage & KERN_CROSS_STREAM) {
                    if (v == (short)0x8000)
                        y = 0;
                    else
                        y = (coverage & KERN_OVERRIDE) ? v : (short)(y + v);
                } else {
                    x = (coverage & KERN_OVERRIDE) ? v : (short)(x + v);
                }
                break;
            }
            if (kp->left > left) /* the pairs are sorted on the left glyph */
                break;
        }
    }
    *kx = x > min_x ? x : min_x;
    *ky = y > min_y ? y : min_y;
}

#endif
