/* `hstrace stitch`: read every part's header, refuse parts that do not make
 * one image, then copy each part's area of every channel into the whole and
 * write it once, atomically.
 *
 * What the parts must share, from the header hstrace writes (the man
 * page's EXR header): hstrace.sceneHash (the scene's bytes; the path may
 * differ between machines), hstrace.version, the size, the channels and
 * their types, the chromaticities, and hstrace.options once the area and
 * --threads are left out (the thread count never changes a pixel). The
 * rest (timings, the command line, the calibrated costs and the volume
 * plan, which are timed) may differ; the whole keeps what all parts agree
 * on. */
#include "stitch.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "antialias.h"
#include "image.h"
#include "shell_words.h"
#include "stitch_options.h"
#include "stitch_plan.h"

#define PROGRAM "hstrace stitch"

typedef struct {
    const char *path;
    ImageExrFile head; /* the header; no samples */
    StitchLine line;
} Part;

/* The image module's messages read "cannot read 'PATH': reason"; this
 * command names the file first, as "PATH: reason", so the reason alone. */
static const char *reason(const char *err, const char *path)
{
    static const char verb[] = "cannot read '";
    size_t nv = sizeof verb - 1, np = strlen(path);
    if (strncmp(err, verb, nv) == 0 && strncmp(err + nv, path, np) == 0 && strncmp(err + nv + np, "': ", 3) == 0)
        return err + nv + np + 3;
    return err;
}

static const char *string_attribute(const ImageExrFile *f, const char *name)
{
    const ImageExrAttribute *a = image_exr_file_attribute(f, name);
    return a && a->type == IMAGE_ATTR_STRING ? a->s : NULL;
}

static int channel_index(const ImageExrFile *f, const char *name)
{
    for (int c = 0; c < f->nchannels; c++)
        if (strcmp(f->channels[c].name, name) == 0)
            return c;
    return -1;
}

static const char *type_name(ImageChannelType t)
{
    return t == IMAGE_CHANNEL_FLOAT ? "float" : t == IMAGE_CHANNEL_UINT ? "uint" : "half";
}

/* Reads part p's header and options line. Returns 0, or the exit status
 * with the message printed. */
static int read_part(Part *p)
{
    char err[1024];
    if (image_read_exr_file(p->path, &p->head, 0, 0, err, sizeof err)) {
        fprintf(stderr, PROGRAM ": %s: %s\n", p->path, reason(err, p->path));
        return STITCH_EXIT_IO;
    }
    const char *options = string_attribute(&p->head, "hstrace.options");
    if (!options || !string_attribute(&p->head, "hstrace.sceneHash")) {
        fprintf(stderr, PROGRAM ": %s: not an EXR rendered by hstrace: its header has no %s\n", p->path,
                options ? "hstrace.sceneHash" : "hstrace.options");
        return STITCH_EXIT_IO;
    }
    /* R, G, B and A of one type: what image_write writes them as. */
    static const char *const rgba[4] = { "R", "G", "B", "A" };
    const int r = channel_index(&p->head, "R");
    for (int k = 0; k < 4; k++) {
        int c = channel_index(&p->head, rgba[k]);
        if (c < 0 || r < 0 || p->head.channels[c].type != p->head.channels[r].type ||
            p->head.channels[c].type == IMAGE_CHANNEL_UINT) {
            fprintf(stderr, PROGRAM ": %s: not an EXR rendered by hstrace: no channels R, G, B and A of one type\n",
                    p->path);
            return STITCH_EXIT_IO;
        }
    }
    if (stitch_line_parse(options, &p->line, err, sizeof err)) {
        fprintf(stderr, PROGRAM ": %s: its hstrace.options cannot be read: %s\n", p->path, err);
        return STITCH_EXIT_IO;
    }
    if (p->line.width != p->head.width || p->line.height != p->head.height) {
        fprintf(stderr, PROGRAM ": %s: %dx%d pixels, but its hstrace.options says --width %d --height %d\n", p->path,
                p->head.width, p->head.height, p->line.width, p->line.height);
        return STITCH_EXIT_IO;
    }
    return 0;
}

/* Does part q agree with part p (the first) on everything but its area and
 * thread count? 0, or STITCH_EXIT_USAGE with the message printed. */
static int agree(const Part *p, const Part *q)
{
    const char *hp = string_attribute(&p->head, "hstrace.sceneHash"), *hq = string_attribute(&q->head, "hstrace.sceneHash");
    if (strcmp(hp, hq) != 0) {
        const char *sp = string_attribute(&p->head, "hstrace.scene"), *sq = string_attribute(&q->head, "hstrace.scene");
        fprintf(stderr, PROGRAM ": %s: rendered from another scene than %s (%s, hstrace.sceneHash %s; %s has %s, %s)\n",
                q->path, p->path, sq ? sq : "?", hq, p->path, sp ? sp : "?", hp);
        return STITCH_EXIT_USAGE;
    }
    const char *vp = string_attribute(&p->head, "hstrace.version"), *vq = string_attribute(&q->head, "hstrace.version");
    if (strcmp(vp ? vp : "", vq ? vq : "") != 0) {
        fprintf(stderr, PROGRAM ": %s: rendered by hstrace %s, %s by hstrace %s\n", q->path, vq ? vq : "(unknown)",
                p->path, vp ? vp : "(unknown)");
        return STITCH_EXIT_USAGE;
    }
    if (p->head.width != q->head.width || p->head.height != q->head.height) {
        fprintf(stderr, PROGRAM ": %s: %dx%d pixels, but %s has %dx%d\n", q->path, q->head.width, q->head.height,
                p->path, p->head.width, p->head.height);
        return STITCH_EXIT_USAGE;
    }
    for (int c = 0; c < p->head.nchannels; c++) {
        const ImageExrChannel *cp = &p->head.channels[c];
        int k = channel_index(&q->head, cp->name);
        if (k < 0) {
            fprintf(stderr, PROGRAM ": %s: no channel '%s', which %s has (other --aov?)\n", q->path, cp->name, p->path);
            return STITCH_EXIT_USAGE;
        }
        if (q->head.channels[k].type != cp->type) {
            fprintf(stderr, PROGRAM ": %s: channel '%s' is %s, in %s %s (other --exr-float?)\n", q->path, cp->name,
                    type_name(q->head.channels[k].type), p->path, type_name(cp->type));
            return STITCH_EXIT_USAGE;
        }
    }
    for (int c = 0; c < q->head.nchannels; c++)
        if (channel_index(&p->head, q->head.channels[c].name) < 0) {
            fprintf(stderr, PROGRAM ": %s: channel '%s', which %s has not (other --aov?)\n", q->path,
                    q->head.channels[c].name, p->path);
            return STITCH_EXIT_USAGE;
        }
    if (p->head.have_chromaticities != q->head.have_chromaticities ||
        memcmp(p->head.chromaticities, q->head.chromaticities, sizeof p->head.chromaticities) != 0) {
        fprintf(stderr, PROGRAM ": %s: other chromaticities (working colour space) than %s\n", q->path, p->path);
        return STITCH_EXIT_USAGE;
    }
    int ip, iq;
    if (!stitch_line_agree(&p->line, &q->line, &ip, &iq)) {
        char wp[256] = "", wq[256] = "";
        if (ip >= 0)
            stitch_line_option(&p->line, ip, wp, (int)sizeof wp);
        if (iq >= 0)
            stitch_line_option(&q->line, iq, wq, (int)sizeof wq);
        if (ip >= 0 && iq >= 0)
            fprintf(stderr, PROGRAM ": %s: rendered with other options than %s: '%s', where %s has '%s' (hstrace.options)\n",
                    q->path, p->path, wq, p->path, wp);
        else
            fprintf(stderr, PROGRAM ": %s: rendered with other options than %s: %s '%s', which %s %s (hstrace.options)\n",
                    q->path, p->path, iq >= 0 ? "with" : "without", iq >= 0 ? wq : wp, p->path,
                    iq >= 0 ? "has not" : "has");
        return STITCH_EXIT_USAGE;
    }
    return 0;
}

/* "rows 21-48, columns 1-64": an area as POV-Ray counts rows and columns. */
static void describe(char *buf, size_t n, StitchArea a)
{
    snprintf(buf, n, "rows %d-%d, columns %d-%d", a.y0 + 1, a.y1, a.x0 + 1, a.x1);
}

/* Overlaps and gaps: 0 when the areas fill the image once, else
 * STITCH_EXIT_USAGE (or STITCH_EXIT_IO when out of memory) with the message
 * printed. */
static int check_cover(const Part *part, const StitchArea *area, int n)
{
    char where[128];
    int i, j;
    StitchArea both;
    if (stitch_find_overlap(area, n, &i, &j, &both)) {
        describe(where, sizeof where, both);
        if (strcmp(part[i].path, part[j].path) == 0)
            fprintf(stderr, PROGRAM ": %s is given twice\n", part[i].path);
        else
            fprintf(stderr, PROGRAM ": %s and %s overlap: %s are in both\n", part[i].path, part[j].path, where);
        return STITCH_EXIT_USAGE;
    }
    StitchArea gap;
    int rc = stitch_find_gap(area, n, part[0].head.width, part[0].head.height, &gap);
    if (rc < 0) {
        fprintf(stderr, PROGRAM ": out of memory\n");
        return STITCH_EXIT_IO;
    }
    if (rc > 0) {
        describe(where, sizeof where, gap);
        fprintf(stderr, PROGRAM ": no part holds %s of the %dx%d image (a part rendered with +SR%d +ER%d +SC%d +EC%d "
                        "is missing)\n",
                where, part[0].head.width, part[0].head.height, gap.y0 + 1, gap.y1, gap.x0 + 1, gap.x1);
        return STITCH_EXIT_USAGE;
    }
    return 0;
}

/* POV-Ray's anti-aliasing method 1 decides in 32-pixel blocks (+BS's, when
 * the options say) laid from the area's corner, as POV-Ray's partial
 * renders do: a part whose edges are off that grid has pixels a single
 * render may not have. Said, not refused: the image is still anti-aliased
 * throughout. */
static void warn_antialias(const Part *part, int n)
{
    int am1 = 0, block = ANTIALIAS_BLOCK;
    for (int k = 0; k < part[0].line.nwords; k++) {
        const char *w = part[0].line.word[k];
        am1 |= strcmp(w, "+AM1") == 0;
        if (strncmp(w, "+BS", 3) == 0 && atoi(w + 3) >= 4)
            block = atoi(w + 3);
    }
    if (!am1)
        return;
    for (int k = 0; k < n; k++) {
        StitchArea a = part[k].line.area;
        int w = part[k].head.width, h = part[k].head.height;
        if (a.x0 % block || a.y0 % block || (a.x1 != w && a.x1 % block) || (a.y1 != h && a.y1 % block)) {
            char where[128];
            describe(where, sizeof where, a);
            fprintf(stderr,
                    PROGRAM ": warning: %s (%s): anti-aliasing method 1 (+AM1) works in %d-pixel blocks laid from the "
                            "area's corner, as POV-Ray's does; off that grid its pixels can differ from a single "
                            "render's (areas on multiples of %d rows and columns, or +AM2, stitch exactly)\n",
                    part[k].path, where, block, block);
            return;
        }
    }
}

static int same_attribute(const ImageExrAttribute *a, const ImageExrAttribute *b);

/* Which sub-scheme decided a shadow and what it cost (hst.L*, depth.L*,
 * cost.*) depend on the volume plan and N_th, which --volumes auto and
 * --nth auto set by timing each run: parts that timed differently record
 * their own, where the colours are the same. Said, not refused. */
static void warn_analysis(const Part *part, int n)
{
    int timed = 0;
    const ImageExrFile *f = &part[0].head;
    for (int c = 0; c < f->nchannels; c++)
        timed |= strncmp(f->channels[c].name, "hst.", 4) == 0 || strncmp(f->channels[c].name, "depth.", 6) == 0 ||
                 strncmp(f->channels[c].name, "cost.", 5) == 0;
    static const char *const timed_by[2] = { "hstrace.volumes", "hstrace.nth" };
    for (int t = 0; timed && t < 2; t++)
        for (int k = 1; k < n; k++) {
            const ImageExrAttribute *a = image_exr_file_attribute(f, timed_by[t]);
            const ImageExrAttribute *b = image_exr_file_attribute(&part[k].head, timed_by[t]);
            if ((a || b) && !same_attribute(a, b)) {
                fprintf(stderr,
                        PROGRAM ": warning: %s: another %s than %s's: its analysis channels hst.*, depth.* and "
                                "cost.* record its own sub-schemes and costs (the colours are the same; --volumes "
                                "always and --nth N fix them)\n",
                        part[k].path, timed_by[t], part[0].path);
                return;
            }
        }
}

static int same_attribute(const ImageExrAttribute *a, const ImageExrAttribute *b)
{
    if (!a || !b || a->type != b->type)
        return 0;
    return a->type == IMAGE_ATTR_STRING ? strcmp(a->s, b->s) == 0
           : a->type == IMAGE_ATTR_INT  ? a->i == b->i
                                        : memcmp(&a->d, &b->d, sizeof a->d) == 0;
}

/* The header of the whole: part 0's hstrace.* attributes that every part
 * shares, but for the timings (each part's, not the whole's); the options
 * line without the area (and without --threads when the parts' differ);
 * the command line of this run; and which parts it was stitched from. */
typedef struct {
    ImageAttribute attr[64];
    int n;
    char *options, *command_line, *stitch;
} Header;

/* Returns the number of attributes, or -1 when out of memory (free_header
 * either way). The attributes point into part[0]'s header and into h. */
static int build_header(Header *h, const Part *part, int n, int argc, char **argv, const char *self)
{
    memset(h, 0, sizeof *h);
    int threads_agree = 1;
    for (int k = 1; k < n; k++)
        threads_agree &= part[k].line.threads == part[0].line.threads;
    h->options = stitch_line_whole(&part[0].line, threads_agree);
    /* "hstrace stitch a.exr b.exr -o full.exr", quoted as the shell reads it. */
    char *words = shell_quote_words(argc - 1, argv + 1), *me = shell_quote_words(1, (char *const *)&self);
    if (words && me) {
        size_t len = strlen(me) + strlen(words) + 16;
        if ((h->command_line = malloc(len)))
            snprintf(h->command_line, len, "%s stitch%s%s", me, argc > 1 ? " " : "", words);
    }
    free(words);
    free(me);
    size_t len = 64;
    for (int k = 0; k < n; k++)
        len += strlen(part[k].path) + 64;
    if ((h->stitch = malloc(len))) {
        size_t at = (size_t)snprintf(h->stitch, len, "%d part%s:", n, n == 1 ? "" : "s");
        for (int k = 0; k < n && at < len; k++) {
            StitchArea a = part[k].line.area;
            at += (size_t)snprintf(h->stitch + at, len - at, "%s %s +SR%d +ER%d +SC%d +EC%d", k ? ";" : "",
                                   part[k].path, a.y0 + 1, a.y1, a.x0 + 1, a.x1);
        }
    }
    if (!h->options || !h->command_line || !h->stitch)
        return -1;
    const int max = (int)(sizeof h->attr / sizeof h->attr[0]) - 2;
    const ImageExrFile *f = &part[0].head;
    for (int a = 0; a < f->nattributes && h->n < max; a++) {
        const ImageExrAttribute *x = &f->attributes[a];
        if (strncmp(x->name, "hstrace.", 8) != 0 || strncmp(x->name, "hstrace.time.", 13) == 0)
            continue;
        ImageAttribute out = { x->name, x->type, x->s, x->i, x->d };
        if (strcmp(x->name, "hstrace.options") == 0) {
            out.s = h->options;
        } else if (strcmp(x->name, "hstrace.commandLine") == 0) {
            out.s = h->command_line;
        } else {
            int shared = 1;
            for (int k = 1; k < n && shared; k++)
                shared = same_attribute(x, image_exr_file_attribute(&part[k].head, x->name));
            if (!shared)
                continue;
        }
        h->attr[h->n++] = out;
    }
    h->attr[h->n++] = (ImageAttribute){ "hstrace.stitch", IMAGE_ATTR_STRING, h->stitch, 0, 0.0 };
    h->attr[h->n++] = (ImageAttribute){ "hstrace.stitch.parts", IMAGE_ATTR_INT, NULL, n, 0.0 };
    return h->n;
}

static void free_header(Header *h)
{
    free(h->options);
    free(h->command_line);
    free(h->stitch);
    memset(h, 0, sizeof *h);
}

/* Reads every part's area of every channel into out (part 0's channel
 * layout, planes allocated here). Returns 0, or the exit status with the
 * message printed. */
static int gather(const Part *part, int n, ImageExrFile *out)
{
    const ImageExrFile *f0 = &part[0].head;
    const size_t w = (size_t)f0->width, npix = w * (size_t)f0->height;
    memset(out, 0, sizeof *out);
    out->width = f0->width;
    out->height = f0->height;
    out->channels = calloc((size_t)f0->nchannels, sizeof *out->channels);
    if (!out->channels) {
        fprintf(stderr, PROGRAM ": out of memory\n");
        return STITCH_EXIT_IO;
    }
    out->nchannels = f0->nchannels;
    for (int c = 0; c < f0->nchannels; c++) {
        out->channels[c].type = f0->channels[c].type;
        if (!(out->channels[c].data = calloc(npix, 4))) {
            fprintf(stderr, PROGRAM ": out of memory for a %dx%d image of %d channels\n", f0->width, f0->height,
                    f0->nchannels);
            return STITCH_EXIT_IO;
        }
    }
    for (int k = 0; k < n; k++) {
        StitchArea a = part[k].line.area;
        ImageExrFile f;
        char err[1024];
        /* The rows of the part's area only: a strip of a tall image reads
         * its own chunks, not the whole file. */
        if (image_read_exr_file(part[k].path, &f, a.y0, a.y1, err, sizeof err)) {
            fprintf(stderr, PROGRAM ": %s: cannot read its pixels: %s\n", part[k].path, reason(err, part[k].path));
            return STITCH_EXIT_IO;
        }
        /* The header read again must be the one checked: a file replaced
         * meanwhile (a job still writing it) is refused, not mixed in. */
        const char *o0 = string_attribute(&part[k].head, "hstrace.options"), *o1 = string_attribute(&f, "hstrace.options");
        int same = f.width == out->width && f.height == out->height && f.nchannels == out->nchannels && o1 &&
                   strcmp(o0, o1) == 0;
        for (int c = 0; same && c < f0->nchannels; c++) {
            int j = channel_index(&f, f0->channels[c].name);
            same = j >= 0 && f.channels[j].type == f0->channels[c].type;
            if (!same)
                break;
            const size_t bytes = (size_t)(a.x1 - a.x0) * 4;
            for (int y = a.y0; y < a.y1; y++) {
                size_t at = ((size_t)y * w + (size_t)a.x0) * 4;
                memcpy((unsigned char *)out->channels[c].data + at, (const unsigned char *)f.channels[j].data + at, bytes);
            }
        }
        image_exr_file_free(&f);
        if (!same) {
            fprintf(stderr, PROGRAM ": %s: changed while it was read\n", part[k].path);
            return STITCH_EXIT_IO;
        }
    }
    return 0;
}

/* Writes the whole: R, G, B, A as an RGBA image, the other channels as
 * image_write's extra planes. Returns 0, or the exit status with the
 * message printed. */
static int write_whole(const char *path, const ImageExrFile *whole, const ImageExrFile *f0, const Header *h)
{
    Image img;
    if (image_alloc(&img, whole->width, whole->height)) {
        fprintf(stderr, PROGRAM ": out of memory\n");
        return STITCH_EXIT_IO;
    }
    static const char *const rgba[4] = { "R", "G", "B", "A" };
    const size_t npix = (size_t)whole->width * (size_t)whole->height;
    int exr_float = 0;
    for (int k = 0; k < 4; k++) {
        int c = channel_index(f0, rgba[k]);
        const float *plane = whole->channels[c].data;
        exr_float = f0->channels[c].type == IMAGE_CHANNEL_FLOAT;
        for (size_t i = 0; i < npix; i++)
            img.rgba[4 * i + (size_t)k] = plane[i];
    }
    ImageChannel *extra = calloc((size_t)f0->nchannels, sizeof *extra);
    if (!extra) {
        image_free(&img);
        fprintf(stderr, PROGRAM ": out of memory\n");
        return STITCH_EXIT_IO;
    }
    int nextra = 0;
    for (int c = 0; c < f0->nchannels; c++) {
        const char *name = f0->channels[c].name;
        if (strcmp(name, "R") && strcmp(name, "G") && strcmp(name, "B") && strcmp(name, "A"))
            extra[nextra++] = (ImageChannel){ name, f0->channels[c].type, whole->channels[c].data };
    }
    ImageWriteOptions wo;
    memset(&wo, 0, sizeof wo);
    wo.exr_float = exr_float;
    wo.exr_compression = f0->compression;
    wo.have_chromaticities = f0->have_chromaticities;
    memcpy(wo.chromaticities, f0->chromaticities, sizeof wo.chromaticities);
    wo.channels = extra;
    wo.nchannels = nextra;
    wo.attributes = h->attr;
    wo.nattributes = h->n;
    char err[1024];
    int rc = image_write(path, &img, &wo, err, sizeof err);
    if (rc)
        fprintf(stderr, PROGRAM ": %s\n", err);
    free(extra);
    image_free(&img);
    return rc ? STITCH_EXIT_IO : 0;
}

int stitch_main(int argc, char **argv, const char *self)
{
    StitchOptions opt;
    char err[1024];
    if (stitch_options_parse(argc, argv, &opt, err, sizeof err)) {
        fprintf(stderr, PROGRAM ": %s\n", err);
        return STITCH_EXIT_USAGE;
    }
    if (opt.help) {
        stitch_options_usage(stdout);
        stitch_options_free(&opt);
        return STITCH_EXIT_OK;
    }
    const int n = opt.nparts;
    Part *part = calloc((size_t)n, sizeof *part);
    StitchArea *area = calloc((size_t)n, sizeof *area);
    ImageExrFile whole;
    Header header;
    memset(&whole, 0, sizeof whole);
    memset(&header, 0, sizeof header);
    int status = part && area ? STITCH_EXIT_OK : STITCH_EXIT_IO;
    if (status)
        fprintf(stderr, PROGRAM ": out of memory\n");
    /* Every header first: a refusal costs no pixel read. */
    for (int k = 0; k < n && status == STITCH_EXIT_OK; k++) {
        part[k].path = opt.parts[k];
        status = read_part(&part[k]);
        if (status == STITCH_EXIT_OK && k > 0)
            status = agree(&part[0], &part[k]);
        if (status == STITCH_EXIT_OK)
            area[k] = part[k].line.area;
    }
    if (status == STITCH_EXIT_OK)
        status = check_cover(part, area, n);
    if (status == STITCH_EXIT_OK) {
        warn_antialias(part, n);
        warn_analysis(part, n);
    }
    if (status == STITCH_EXIT_OK && build_header(&header, part, n, argc, argv, self) < 0) {
        fprintf(stderr, PROGRAM ": out of memory\n");
        status = STITCH_EXIT_IO;
    }
    if (status == STITCH_EXIT_OK)
        status = gather(part, n, &whole);
    if (status == STITCH_EXIT_OK)
        status = write_whole(opt.output, &whole, &part[0].head, &header);
    if (status == STITCH_EXIT_OK)
        printf("%s: %dx%d pixels, %d channels, stitched from %d part%s\n", opt.output, whole.width, whole.height,
               whole.nchannels, n, n == 1 ? "" : "s");
    image_exr_file_free(&whole);
    free_header(&header);
    for (int k = 0; part && k < n; k++) {
        image_exr_file_free(&part[k].head);
        stitch_line_free(&part[k].line);
    }
    free(part);
    free(area);
    stitch_options_free(&opt);
    return status;
}
