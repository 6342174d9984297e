/* PNG through libpng: 8 or 16 bits, RGB or RGBA, encoded like POV-Ray 3.7
 * (see image_codec.h) with gAMA, sRGB (for the sRGB curve) and sBIT chunks,
 * or through an OpenColorIO display transform (sBIT only).
 *
 * Writing, libpng makes the header chunks and the file's end; the image
 * data between (IDAT) is made here, in bands of PNG_BAND_ROWS rows
 * compressed side by side on the render's threads: each band's rows are
 * encoded, filtered as libpng filters by default (per row, the one of the
 * five filters whose bytes, taken as signed, sum smallest in magnitude)
 * and deflated on their own, ending on a full flush, so that the bands
 * follow one another as one zlib stream (the way pigz splits its work;
 * the header before the first, the Adler-32 of all the bytes, combined
 * from the bands', after the last). Bands do not depend on the thread
 * count: the file is the same for any. Reading is libpng's. */
#include <png.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "image_codec.h"
#include "parallel.h"

typedef struct {
    char *err;
    int errlen;
} PngErr;

static void on_png_error(png_structp png, png_const_charp msg)
{
    PngErr *pe = png_get_error_ptr(png);
    if (pe != NULL)
        image_set_error(pe->err, pe->errlen, "%s", msg);
    png_longjmp(png, 1);
}

static void on_png_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg;
}

/* Rows compressed as one piece: small enough for two threads to share a
 * picture of a few hundred rows, large enough that restarting the
 * compressor's window costs little (a band of a 640-pixel RGB picture is
 * 60 KiB). */
#define PNG_BAND_ROWS 32

/* The filters of PNG's filter method 0 (png_set_filter's values < 5). */
enum { FILTER_NONE, FILTER_SUB, FILTER_UP, FILTER_AVERAGE, FILTER_PAETH, FILTERS };

/* The filters' loops take 16 bytes at a time where GCC's vectorizer is
 * let loose on them (its -O2 cost model keeps loops of unknown length
 * scalar): callgrind on desk's 1280x960 PNG, the filters' instructions
 * fall to some third. */
#if defined(__GNUC__) && !defined(__clang__)
#define PNG_VECTORIZE __attribute__((optimize("tree-loop-vectorize", "vect-cost-model=dynamic")))
#else
#define PNG_VECTORIZE
#endif

/* Row `cur` (n bytes, bpp bytes a pixel) filtered by filter f against the
 * row above (`up`, zeros for the first row) into out: a loop per filter,
 * the first pixel (no left neighbour: 0) apart. */
PNG_VECTORIZE static void filter_row(int f, const unsigned char *restrict cur, const unsigned char *restrict up, size_t n,
                       size_t bpp, unsigned char *restrict out)
{
    size_t i;
    switch (f) {
    case FILTER_NONE:
        memcpy(out, cur, n);
        break;
    case FILTER_SUB:
        for (i = 0; i < bpp; i++)
            out[i] = cur[i];
        for (; i < n; i++)
            out[i] = (unsigned char)(cur[i] - cur[i - bpp]);
        break;
    case FILTER_UP:
        for (i = 0; i < n; i++)
            out[i] = (unsigned char)(cur[i] - up[i]);
        break;
    case FILTER_AVERAGE:
        for (i = 0; i < bpp; i++)
            out[i] = (unsigned char)(cur[i] - up[i] / 2);
        for (; i < n; i++)
            out[i] = (unsigned char)(cur[i] - (cur[i - bpp] + up[i]) / 2);
        break;
    default: /* FILTER_PAETH: with no left neighbour, the predictor is the byte above */
        for (i = 0; i < bpp; i++)
            out[i] = (unsigned char)(cur[i] - up[i]);
        /* paeth() without branches, so that the compiler can take several
         * bytes at once: p - a = b - c, p - b = a - c, p - c = a + b - 2c */
        for (; i < n; i++) {
            int a = cur[i - bpp], b = up[i], c = up[i - bpp];
            int pa = abs(b - c), pb = abs(a - c), pc = abs(a + b - 2 * c);
            int pred = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
            out[i] = (unsigned char)(cur[i] - pred);
        }
        break;
    }
}

/* The sum of the bytes' magnitudes, taken as signed. */
PNG_VECTORIZE static unsigned long signed_magnitudes(const unsigned char *b, size_t n)
{
    unsigned long sum = 0;
    for (size_t i = 0; i < n; i++) {
        int v = (signed char)b[i];
        sum += (unsigned long)(v < 0 ? -v : v);
    }
    return sum;
}

/* The filter libpng's default heuristic takes: least sum of the filtered
 * bytes' magnitudes as signed, the first such in filter order. out: the
 * row filtered by it, its filter byte first (n + 1 bytes); try: n bytes. */
static void filter_best(const unsigned char *cur, const unsigned char *up, size_t n, size_t bpp,
                        unsigned char *out, unsigned char *try)
{
    unsigned long best = (unsigned long)-1;
    for (int f = 0; f < FILTERS; f++) {
        filter_row(f, cur, up, n, bpp, try);
        unsigned long sum = signed_magnitudes(try, n);
        if (sum < best) {
            best = sum;
            out[0] = (unsigned char)f;
            memcpy(out + 1, try, n);
        }
    }
}

/* A band compressed: its deflate data (a full flush at its end, the final
 * block for the last band) and the Adler-32 of its filtered bytes. */
typedef struct {
    unsigned char *z;
    size_t zlen;
    uLong adler;
    uLong raw;          /* its filtered bytes */
} PngBand;

/* A share of the bands, on one thread: bands first, first + stride, ... */
typedef struct {
    const Image *img;
    const ImageWriteOptions *opt;
    int depth, alpha;
    int nbands, first, stride;
    PngBand *band;
    int failed;
    char why[256];
} PngJob;

/* Row y encoded as the file stores it (big-endian 16-bit samples). */
static int encode_row(ImageRowEncoder *enc, const Image *img, int y, int depth, int nch, unsigned char *o,
                      char *why, int whylen)
{
    if (image_row_encode(enc, img->rgba + (size_t)y * (size_t)img->width * 4, why, whylen) != 0)
        return -1;
    const unsigned *q = enc->samples;
    for (int x = 0; x < img->width; x++, q += 4)
        for (int c = 0; c < nch; c++) {
            if (depth == 16) {
                *o++ = (unsigned char)(q[c] >> 8);
                *o++ = (unsigned char)(q[c] & 0xff);
            } else {
                *o++ = (unsigned char)q[c];
            }
        }
    return 0;
}

static void *compress_bands(void *arg)
{
    PngJob *job = arg;
    const Image *img = job->img;
    const int nch = job->alpha ? 4 : 3;
    const size_t bpp = (size_t)nch * (size_t)(job->depth / 8), n = (size_t)img->width * bpp;
    ImageRowEncoder enc;
    if (image_row_encoder_init(&enc, job->opt, img->width, job->depth == 16 ? 65535u : 255u, job->alpha) != 0) {
        job->failed = 1;
        snprintf(job->why, sizeof job->why, "out of memory");
        return NULL;
    }
    unsigned char *rows = malloc(2 * n + 2 * (n + 1) * PNG_BAND_ROWS + 1);
    unsigned char *up = rows, *cur = rows + n, *filtered = rows + 2 * n, *try = filtered + (n + 1) * PNG_BAND_ROWS;
    for (int b = job->first; b < job->nbands && !job->failed && rows; b += job->stride) {
        int y0 = b * PNG_BAND_ROWS, y1 = y0 + PNG_BAND_ROWS < img->height ? y0 + PNG_BAND_ROWS : img->height;
        /* the row above the band, for its first row's filters */
        if (y0 == 0)
            memset(up, 0, n);
        else if (encode_row(&enc, img, y0 - 1, job->depth, nch, up, job->why, (int)sizeof job->why) != 0)
            job->failed = 1;
        size_t raw = 0;
        for (int y = y0; y < y1 && !job->failed; y++) {
            if (encode_row(&enc, img, y, job->depth, nch, cur, job->why, (int)sizeof job->why) != 0) {
                job->failed = 1;
                break;
            }
            filter_best(cur, up, n, bpp, filtered + raw, try);
            raw += n + 1;
            unsigned char *t = up;
            up = cur;
            cur = t;
        }
        if (job->failed)
            break;
        PngBand *band = &job->band[b];
        band->raw = (uLong)raw;
        band->adler = adler32(adler32(0L, Z_NULL, 0), filtered, (uInt)raw);
        z_stream zs;
        memset(&zs, 0, sizeof zs);
        /* raw deflate (no zlib header of its own): the bands make one stream */
        if (deflateInit2(&zs, Z_DEFAULT_COMPRESSION, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) {
            job->failed = 1;
            snprintf(job->why, sizeof job->why, "out of memory");
            break;
        }
        size_t room = deflateBound(&zs, (uLong)raw) + 16;
        band->z = malloc(room);
        int last = b == job->nbands - 1;
        zs.next_in = filtered;
        zs.avail_in = (uInt)raw;
        zs.next_out = band->z;
        zs.avail_out = (uInt)room;
        int rc = band->z ? deflate(&zs, last ? Z_FINISH : Z_FULL_FLUSH) : Z_MEM_ERROR;
        if (rc != (last ? Z_STREAM_END : Z_OK) || zs.avail_in != 0) {
            job->failed = 1;
            snprintf(job->why, sizeof job->why, "compressing the PNG's rows failed");
        }
        band->zlen = room - zs.avail_out;
        deflateEnd(&zs);
    }
    if (!rows && !job->failed) {
        job->failed = 1;
        snprintf(job->why, sizeof job->why, "out of memory");
    }
    free(rows);
    image_row_encoder_free(&enc);
    return NULL;
}

/* Bands of at least this many a job: fewer are not worth a thread. */
#define PNG_BANDS_PER_JOB 2

/* The bands, compressed on up to opt->threads threads. Returns 0, or -1
 * with the first failing job's message in why. */
static int compress_image(const Image *img, const ImageWriteOptions *opt, int depth, int alpha, PngBand *band,
                          int nbands, char *why, int whylen)
{
    int njobs = parallel_jobs(nbands, PNG_BANDS_PER_JOB, opt->threads > 1 ? opt->threads : 1);
    PngJob *jobs = calloc((size_t)njobs, sizeof *jobs);
    if (!jobs) {
        image_set_error(why, whylen, "out of memory");
        return -1;
    }
    for (int j = 0; j < njobs; j++)
        jobs[j] = (PngJob){ img, opt, depth, alpha, nbands, j, njobs, band, 0, { 0 } };
    parallel_run(njobs, compress_bands, jobs, sizeof *jobs);
    int failed = 0;
    for (int j = 0; j < njobs && !failed; j++)
        if (jobs[j].failed) {
            image_set_error(why, whylen, "%s", jobs[j].why);
            failed = 1;
        }
    free(jobs);
    return failed ? -1 : 0;
}

/* Everything libpng does for a write, outside the function that calls
 * setjmp so that no local of that one changes after it: the header
 * chunks, the bands as IDAT chunks (the zlib header before the first, the
 * Adler-32 after the last), the end. */
static void png_write_body(png_structp png, png_infop info, const Image *img, const ImageRowEncoder *enc, int depth,
                           const PngBand *band, int nbands, unsigned char *chunk)
{
    const int alpha = enc->with_alpha;
    png_color_8 sbit;
    png_text text;

    png_set_IHDR(png, info, (png_uint_32)img->width, (png_uint_32)img->height, depth,
                 alpha ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    memset(&sbit, 0, sizeof sbit);
    sbit.red = sbit.green = sbit.blue = (png_byte)depth;
    if (alpha)
        sbit.alpha = (png_byte)depth;
    png_set_sBIT(png, info, &sbit);
    /* As POV-Ray: gAMA 1/2.2 (45455) plus sRGB (perceptual) for the sRGB
     * curve, gAMA 1/gamma for a power law. A display transform's curve is
     * the config's business: no chunk claims one. */
    if (enc->display == NULL) {
        png_set_gAMA(png, info, enc->transfer.gama);
        if (enc->transfer.srgb)
            png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    }
    memset(&text, 0, sizeof text);
    text.compression = PNG_TEXT_COMPRESSION_NONE;
    text.key = (png_charp) "Software";
    text.text = (png_charp) "hstrace";
    text.text_length = strlen(text.text);
    png_set_text(png, info, &text, 1);
    png_write_info(png, info);

    /* zlib's header: deflate with a 32 KiB window, the default level (CMF
     * 0x78; FLG 0x9C makes CMF FLG a multiple of 31) */
    uLong adler = adler32(0L, Z_NULL, 0);
    for (int b = 0; b < nbands; b++) {
        int first = b == 0, last = b == nbands - 1;
        size_t len = band[b].zlen + (first ? 2 : 0) + (last ? 4 : 0);
        unsigned char *o = chunk;
        if (first) {
            *o++ = 0x78;
            *o++ = 0x9C;
        }
        memcpy(o, band[b].z, band[b].zlen);
        o += band[b].zlen;
        adler = adler32_combine(adler, band[b].adler, (z_off_t)band[b].raw);
        if (last) {
            *o++ = (unsigned char)(adler >> 24);
            *o++ = (unsigned char)(adler >> 16);
            *o++ = (unsigned char)(adler >> 8);
            *o++ = (unsigned char)adler;
        }
        png_write_chunk(png, (png_const_bytep) "IDAT", chunk, len);
    }
    png_write_chunk(png, (png_const_bytep) "IEND", NULL, 0);
}

/* What the libpng part of a write needs, behind one pointer, so that the
 * function calling setjmp keeps no local that changes after it. */
typedef struct {
    FILE *fp;
    const Image *img;
    const ImageRowEncoder *enc;
    int depth;
    const PngBand *band;
    int nbands;
    unsigned char *chunk; /* room for the largest IDAT chunk (a band, the zlib header and trailer) */
    PngErr pe;
} PngFile;

/* The file: libpng's header chunks, the bands, the end. Returns 0, or -1
 * with libpng's message (or "out of memory") in f->pe. */
static int png_write_file(PngFile *f)
{
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &f->pe, on_png_error, on_png_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (info == NULL) {
        png_destroy_write_struct(&png, NULL);
        image_set_error(f->pe.err, f->pe.errlen, "out of memory");
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return -1;
    }
    png_init_io(png, f->fp);
    png_write_body(png, info, f->img, f->enc, f->depth, f->band, f->nbands, f->chunk);
    png_destroy_write_struct(&png, &info);
    return 0;
}

int image_png_write(FILE *fp, const Image *img, const ImageWriteOptions *opt, char *err, int errlen)
{
    ImageRowEncoder enc;
    const int depth = opt->png_16bit ? 16 : 8;
    const int alpha = opt->write_alpha != 0;
    const int nbands = (img->height + PNG_BAND_ROWS - 1) / PNG_BAND_ROWS;

    /* (the encoder here only tells the header what the bands' encoders do) */
    if (image_row_encoder_init(&enc, opt, 1, depth == 16 ? 65535u : 255u, alpha) != 0) {
        image_set_error(err, errlen, "out of memory");
        return -1;
    }
    PngBand *band = calloc((size_t)(nbands > 0 ? nbands : 1), sizeof *band);
    int status;
    if (!band) {
        image_set_error(err, errlen, "out of memory");
        status = -1;
    } else if (compress_image(img, opt, depth, alpha, band, nbands, err, errlen) != 0) {
        status = -1;
    } else {
        /* the chunks' room made here, so that libpng's longjmp on a failed
         * write leaks nothing */
        size_t most = 0;
        for (int b = 0; b < nbands; b++)
            most = band[b].zlen > most ? band[b].zlen : most;
        PngFile f = { fp, img, &enc, depth, band, nbands, malloc(most + 6), { err, errlen } };
        if (!f.chunk) {
            image_set_error(err, errlen, "out of memory");
            status = -1;
        } else {
            status = png_write_file(&f);
        }
        free(f.chunk);
    }
    for (int b = 0; band && b < nbands; b++)
        free(band[b].z);
    free(band);
    image_row_encoder_free(&enc);
    return status;
}

/* What libpng reads: the first chunk's start (read ahead, so that the size
 * its IHDR declares is checked before libpng acts on it), then the file. A
 * short read is a truncated file, said so (libpng's own reader says "Read
 * Error"). */
typedef struct {
    FILE *fp;
    unsigned char head[24]; /* length, "IHDR", width, height, bit depth, ... */
    size_t head_len, head_pos;
} PngSource;

static void png_source_read(png_structp png, png_bytep data, size_t n)
{
    PngSource *src = png_get_io_ptr(png);
    size_t k = 0;
    while (k < n && src->head_pos < src->head_len)
        data[k++] = src->head[src->head_pos++];
    if (k < n && fread(data + k, 1, n - k, src->fp) != n - k)
        png_error(png, ferror(src->fp) ? "read error" : "PNG data is truncated (the file ends early)");
}

static unsigned long png_be32(const unsigned char *p)
{
    return (unsigned long)p[0] << 24 | (unsigned long)p[1] << 16 | (unsigned long)p[2] << 8 | p[3];
}

/* Working state of a read, kept behind one pointer so that nothing the error
 * path needs lives in a local changed after setjmp. */
typedef struct {
    png_structp png;
    png_infop info;
    unsigned char *row;
    float *lut;
    PngSource src;
    long file_bytes; /* what the file holds after its signature; -1: unknown */
    size_t raw_rowbytes; /* a row as stored (before expansion to RGB) */
    char msg[128];
    /* A palette picture read indexed (ImageReadExtras): its entries as
     * stored, and the indices, grown with the rows as the image is. */
    int ncolours;
    png_color plte[256];
    unsigned char trns[256];
    unsigned char *index;
} PngRead;

int image_png_read(FILE *fp, Image *img, double display_gamma, ImageReadExtras *ex, char *err, int errlen)
{
    PngErr pe = { err, errlen };
    PngRead *st = calloc(1, sizeof *st);
    ImageTransfer t;
    png_uint_32 w, h;
    int depth, ctype, nch, wide, passes;
    unsigned max;
    unsigned char sig[8];

    if (st == NULL) {
        image_set_error(err, errlen, "out of memory");
        return -1;
    }
    if (fread(sig, 1, 8, fp) != 8 || png_sig_cmp(sig, 0, 8) != 0) {
        free(st);
        image_set_error(err, errlen, "not a PNG file (bad signature or truncated)");
        return -1;
    }
    /* The size in the header, refused before anything is allocated for it:
     * an empty image (which libpng cannot even write) or one past
     * IMAGE_MAX_DIM a side or IMAGE_MAX_PIXELS in all. */
    st->src.fp = fp;
    st->file_bytes = -1;
    {
        long here = ftell(fp);
        if (here >= 0 && fseek(fp, 0, SEEK_END) == 0) {
            st->file_bytes = ftell(fp) - here;
            if (fseek(fp, here, SEEK_SET) != 0)
                st->file_bytes = -1;
        }
    }
    st->src.head_len = fread(st->src.head, 1, sizeof st->src.head, fp);
    if (st->src.head_len == sizeof st->src.head && memcmp(st->src.head + 4, "IHDR", 4) == 0) {
        unsigned long hw = png_be32(st->src.head + 8), hh = png_be32(st->src.head + 12);
        if (hw == 0 || hh == 0 || hw > IMAGE_MAX_DIM || hh > IMAGE_MAX_DIM ||
            (unsigned long long)hw * hh > (unsigned long long)IMAGE_MAX_PIXELS) {
            free(st);
            image_set_error(err, errlen, "unsupported PNG size %lux%lu", hw, hh);
            return -1;
        }
    }
    st->png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &pe, on_png_error, on_png_warning);
    st->info = st->png ? png_create_info_struct(st->png) : NULL;
    if (st->info == NULL) {
        png_destroy_read_struct(&st->png, NULL, NULL);
        free(st);
        image_set_error(err, errlen, "out of memory");
        return -1;
    }
    if (setjmp(png_jmpbuf(st->png))) {
        png_destroy_read_struct(&st->png, &st->info, NULL);
        free(st->row);
        free(st->lut);
        free(st->index);
        free(st);
        image_free(img);
        if (err != NULL && errlen > 0 && err[0] == '\0')
            image_set_error(err, errlen, "corrupt PNG file");
        return -1;
    }
    png_set_user_limits(st->png, IMAGE_MAX_DIM, IMAGE_MAX_DIM);
    /* A corrupt length must not make libpng allocate gigabytes for an
     * ancillary chunk (zTXt, iCCP, ...). */
    png_set_chunk_malloc_max(st->png, 16u << 20);
    png_set_chunk_cache_max(st->png, 1000);
    {
        /* Metadata chunks are of no use here: skip them unread (libpng
         * would otherwise buffer whatever length a corrupt one claims). */
        static const png_byte skip[] = "tEXt\0zTXt\0iTXt\0iCCP\0sPLT\0eXIf\0tIME\0";
        png_set_keep_unknown_chunks(st->png, PNG_HANDLE_CHUNK_NEVER, NULL, 0);
        png_set_keep_unknown_chunks(st->png, PNG_HANDLE_CHUNK_NEVER, skip, (int)(sizeof skip / 5));
    }
    png_set_read_fn(st->png, &st->src, png_source_read);
    png_set_sig_bytes(st->png, 8);
    png_read_info(st->png, st->info);
    st->raw_rowbytes = png_get_rowbytes(st->png, st->info);
    w = png_get_image_width(st->png, st->info);
    h = png_get_image_height(st->png, st->info);
    if ((unsigned long)w * h > (unsigned long)IMAGE_MAX_PIXELS)
        png_error(st->png, "image too large");

    if (ex != NULL) { /* as stored, before the expansion below */
        int stored_type = png_get_color_type(st->png, st->info);
        ex->grey = stored_type == PNG_COLOR_TYPE_GRAY || stored_type == PNG_COLOR_TYPE_GRAY_ALPHA;
        ex->sample_max = png_get_bit_depth(st->png, st->info) == 16 ? 65535u : 255u;
    }
    if (ex != NULL && png_get_color_type(st->png, st->info) == PNG_COLOR_TYPE_PALETTE) {
        /* Kept indexed, as POV-Ray 3.7 keeps palette PNGs: one byte per
         * pixel, each the entry it shows, the entries' colours below. */
        png_colorp plte = NULL;
        int n = 0;
        if (!png_get_PLTE(st->png, st->info, &plte, &n) || n < 1 || n > 256)
            png_error(st->png, "palette PNG without a valid PLTE chunk");
        st->ncolours = n;
        memcpy(st->plte, plte, sizeof *plte * (size_t)n);
        memset(st->trns, 255, sizeof st->trns);
        png_bytep trns = NULL;
        int ntrns = 0;
        if (png_get_valid(st->png, st->info, PNG_INFO_tRNS) && png_get_tRNS(st->png, st->info, &trns, &ntrns, NULL) &&
            trns != NULL)
            memcpy(st->trns, trns, (size_t)(ntrns < n ? ntrns : n));
        png_set_packing(st->png);
    } else {
        /* Everything to 8 or 16-bit RGB or RGBA, 16-bit samples big-endian. */
        png_set_expand(st->png);
        png_set_gray_to_rgb(st->png);
    }
    passes = png_set_interlace_handling(st->png);
    png_read_update_info(st->png, st->info);
    depth = png_get_bit_depth(st->png, st->info);
    ctype = png_get_color_type(st->png, st->info);
    nch = png_get_channels(st->png, st->info);
    if (st->ncolours > 0 ? depth != 8 || nch != 1
                         : (depth != 8 && depth != 16) || (nch != 3 && nch != 4) || !(ctype & PNG_COLOR_MASK_COLOR))
        png_error(st->png, "unsupported PNG layout");
    wide = depth == 16;
    max = wide ? 65535u : 255u;

    {
        /* as POV-Ray 3.7 without `gamma`: an sRGB chunk, else a gAMA chunk
         * (its encoding gamma), else sRGB */
        double file_gamma = 0.0, decode = display_gamma;
        if (decode == IMAGE_GAMMA_AS_POVRAY) {
            if (png_get_valid(st->png, st->info, PNG_INFO_sRGB))
                decode = 0.0;
            else if (png_get_valid(st->png, st->info, PNG_INFO_gAMA) && png_get_gAMA(st->png, st->info, &file_gamma) &&
                     file_gamma > 0.0)
                decode = 1.0 / file_gamma;
            else /* POV-Ray's defaultGamma (3.6 scenes: the working gamma), else sRGB */
                decode = ex != NULL && ex->untagged_given ? ex->untagged_gamma : 0.0;
        }
        image_transfer_init(&t, decode);
    }
    st->lut = image_transfer_decode_table(&t, max);
    /* The image grows with the rows decoded (a non-interlaced file): a few
     * corrupt bytes may claim 2^28 pixels, and memory follows the data the
     * file holds, not its header. Interlaced files need all rows at once,
     * reserved before their data is read: first the file must be able to
     * hold them. Deflate makes at most 1032 bytes of one (258 per 2 bits),
     * so a file of a few hundred bytes cannot inflate to the 805 MB of
     * rows, as stored, of a 16384x16384 RGB header (it reserved 5 GB). */
    if (passes > 1 && st->file_bytes >= 0 &&
        (double)st->raw_rowbytes * (double)h > 1032.0 * (double)st->file_bytes + 65536.0) {
        snprintf(st->msg, sizeof st->msg, "interlaced PNG data of %ld bytes is too small for %lux%lu pixels",
                 st->file_bytes, (unsigned long)w, (unsigned long)h);
        png_error(st->png, st->msg);
    }
    int rows_cap = passes > 1 || h < 64 ? (int)h : 64;
    if (st->lut == NULL || image_alloc(img, (int)w, rows_cap) != 0)
        png_error(st->png, "out of memory");
    st->row = malloc(png_get_rowbytes(st->png, st->info));
    if (st->row == NULL)
        png_error(st->png, "out of memory");

    {
        /* Interlaced images: libpng fills each row over several passes, so
         * every row needs its own buffer until the last pass. */
        if (passes > 1) {
            size_t rb = png_get_rowbytes(st->png, st->info);
            unsigned char *all = malloc(rb * h);
            if (all == NULL)
                png_error(st->png, "out of memory");
            free(st->row);
            st->row = all;
            for (int p = 0; p < passes; p++)
                for (png_uint_32 y = 0; y < h; y++)
                    png_read_row(st->png, all + rb * y, NULL);
        }
        int index_rows = 0;
        for (png_uint_32 y = 0; y < h; y++) {
            const unsigned char *in;
            if (image_grow_rows(img, (int)y, (int)h, &rows_cap))
                png_error(st->png, "out of memory");
            if (st->ncolours > 0 && (int)y >= index_rows) { /* the indices grow as the rows do */
                unsigned char *more = realloc(st->index, (size_t)rows_cap * w);
                if (more == NULL)
                    png_error(st->png, "out of memory");
                st->index = more;
                index_rows = rows_cap;
            }
            float *px = img->rgba + (size_t)y * w * 4;
            if (passes > 1) {
                in = st->row + png_get_rowbytes(st->png, st->info) * y;
            } else {
                png_read_row(st->png, st->row, NULL);
                in = st->row;
            }
            for (png_uint_32 x = 0; x < w; x++, px += 4) {
                unsigned v[4] = { 0, 0, 0, max };
                if (st->ncolours > 0) {
                    /* an index past the palette (a damaged file) shows entry 0 */
                    unsigned i = in[x] < st->ncolours ? in[x] : 0;
                    st->index[(size_t)y * w + x] = (unsigned char)i;
                    v[0] = st->plte[i].red;
                    v[1] = st->plte[i].green;
                    v[2] = st->plte[i].blue;
                    v[3] = st->trns[i];
                } else {
                    for (int c = 0; c < nch; c++) {
                        v[c] = wide ? (unsigned)(in[0] << 8 | in[1]) : in[0];
                        in += wide ? 2 : 1;
                    }
                }
                /* PNG alpha is straight; the image holds premultiplied
                 * unless the caller keeps it straight. */
                float a = (float)v[3] / (float)max, k = ex != NULL && ex->keep_straight ? 1.0f : a;
                px[0] = st->lut[v[0]] * k;
                px[1] = st->lut[v[1]] * k;
                px[2] = st->lut[v[2]] * k;
                px[3] = a;
            }
        }
    }
    img->height = (int)h;
    png_read_end(st->png, NULL);
    png_destroy_read_struct(&st->png, &st->info, NULL);
    if (ex != NULL && st->ncolours > 0) {
        ex->ncolours = st->ncolours;
        for (int i = 0; i < st->ncolours; i++) {
            ex->palette[i][0] = st->lut[st->plte[i].red];
            ex->palette[i][1] = st->lut[st->plte[i].green];
            ex->palette[i][2] = st->lut[st->plte[i].blue];
            ex->palette[i][3] = (float)st->trns[i] / 255.0f;
        }
        ex->index = st->index;
        st->index = NULL;
    }
    free(st->index);
    free(st->row);
    free(st->lut);
    free(st);
    return 0;
}
