/* OpenEXR through the library's C API (libOpenEXRCore). Writes one scanline
 * part, channels A,B,G,R as half or float, data window = display window,
 * and the working space's chromaticities when given.
 * Reads part 0 of any scanline or tiled file (level 0 of mip/rip maps),
 * channels R,G,B,A (or Y as grey); missing colour is 0, missing A is 1. */
#include <errno.h>
#include <openexr.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "image_codec.h"
#include "parallel.h"

typedef struct {
    int fd;
    char *err;
    int errlen;
    int have_err; /* keep the first message, the root cause */
} ExrIO;

static void keep_first_error(ExrIO *io, const char *msg)
{
    if (io != NULL && !io->have_err && msg != NULL) {
        image_set_error(io->err, io->errlen, "%s", msg);
        io->have_err = 1;
    }
}

/* Reading: the context takes no lock in read mode, so the handler may ask
 * it for its user data. */
static void on_exr_read_error(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
    void *ud = NULL;

    (void)code;
    if (ctxt == NULL || exr_get_user_data(ctxt, &ud) != EXR_ERR_SUCCESS)
        return;
    keep_first_error(ud, msg);
}

/* Writing: a write-mode context calls its error handler with its own mutex
 * held, and exr_get_user_data takes that mutex again -- a deadlock (a full
 * disk, an attribute name of 32 or more bytes). So the writer's ExrIO is
 * found through this thread's own pointer instead: one thread writes a file
 * from exr_start_write to exr_finish, and each thread has its own pointer,
 * so no state is shared between threads. */
static _Thread_local ExrIO *exr_writing;

static void on_exr_write_error(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
    (void)ctxt;
    (void)code;
    keep_first_error(exr_writing, msg);
}

static int64_t exr_fd_write(exr_const_context_t ctxt, void *ud, const void *buf, uint64_t sz, uint64_t off,
                            exr_stream_error_func_ptr_t error_cb)
{
    ExrIO *io = ud;
    const char *p = buf;
    uint64_t done = 0;

    while (done < sz) {
        ssize_t n = pwrite(io->fd, p + done, (size_t)(sz - done), (off_t)(off + done));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            int e = n < 0 ? errno : EIO;
            error_cb(ctxt, EXR_ERR_WRITE_IO, "%s", strerror(e));
            errno = e;
            return -1;
        }
        done += (uint64_t)n;
    }
    return (int64_t)sz;
}

static int64_t exr_fd_read(exr_const_context_t ctxt, void *ud, void *buf, uint64_t sz, uint64_t off,
                           exr_stream_error_func_ptr_t error_cb)
{
    ExrIO *io = ud;
    char *p = buf;
    uint64_t done = 0;

    while (done < sz) {
        ssize_t n = pread(io->fd, p + done, (size_t)(sz - done), (off_t)(off + done));
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            error_cb(ctxt, EXR_ERR_READ_IO, "%s", strerror(errno));
            return -1;
        }
        if (n == 0)
            break; /* end of file: the library reports the short read */
        done += (uint64_t)n;
    }
    return (int64_t)done;
}

static int64_t exr_fd_size(exr_const_context_t ctxt, void *ud)
{
    ExrIO *io = ud;
    struct stat st;
    (void)ctxt;
    if (fstat(io->fd, &st) != 0)
        return -1;
    return (int64_t)st.st_size;
}

static exr_compression_t exr_compression_of(ImageExrCompression c)
{
    switch (c) {
    case IMAGE_EXR_NONE: return EXR_COMPRESSION_NONE;
    case IMAGE_EXR_RLE: return EXR_COMPRESSION_RLE;
    case IMAGE_EXR_ZIPS: return EXR_COMPRESSION_ZIPS;
    case IMAGE_EXR_PIZ: return EXR_COMPRESSION_PIZ;
    case IMAGE_EXR_ZIP:
    default: return EXR_COMPRESSION_ZIP;
    }
}

/* A failed call: make sure some message is there, then give up. */
static int exr_fail(ExrIO *io, exr_result_t rv)
{
    if (!io->have_err) {
        image_set_error(io->err, io->errlen, "%s", exr_get_default_error_message(rv));
        io->have_err = 1;
    }
    return -1;
}

static exr_pixel_type_t exr_type_of(ImageChannelType t)
{
    return t == IMAGE_CHANNEL_UINT ? EXR_PIXEL_UINT : t == IMAGE_CHANNEL_FLOAT ? EXR_PIXEL_FLOAT : EXR_PIXEL_HALF;
}

static exr_result_t set_attribute(exr_context_t ctx, int part, const ImageAttribute *a)
{
    switch (a->type) {
    case IMAGE_ATTR_INT: return exr_attr_set_int(ctx, part, a->name, a->i);
    case IMAGE_ATTR_DOUBLE: return exr_attr_set_double(ctx, part, a->name, a->d);
    case IMAGE_ATTR_STRING:
    default: return exr_attr_set_string(ctx, part, a->name, a->s ? a->s : "");
    }
}

/* Offsets into an RGBA pixel; extra channels are planes of their own. */
static const char *const rgba_names[4] = { "A", "B", "G", "R" };
static const int rgba_offsets[4] = { 3, 2, 1, 0 };

/* Points the pipeline's channels at the image's samples of its chunk. */
static exr_result_t point_channels(exr_encode_pipeline_t *enc, const exr_chunk_info_t *cinfo, const Image *img,
                                   const ImageWriteOptions *opt)
{
    const int w = img->width;
    const int nextra = opt->channels ? opt->nchannels : 0;
    for (int c = 0; c < enc->channel_count; c++) {
        exr_coding_channel_info_t *ch = &enc->channels[c];
        int k = 0;
        while (k < 4 && strcmp(ch->channel_name, rgba_names[k]) != 0)
            k++;
        if (k < 4) {
            /* The library converts our float samples to the channel type. */
            ch->user_data_type = EXR_PIXEL_FLOAT;
            ch->user_bytes_per_element = 4;
            ch->user_pixel_stride = 4 * (int32_t)sizeof(float);
            ch->user_line_stride = w * 4 * (int32_t)sizeof(float);
            ch->encode_from_ptr =
                (const uint8_t *)(img->rgba + (size_t)(cinfo->start_y) * (size_t)w * 4 + rgba_offsets[k]);
            continue;
        }
        int e = 0;
        while (e < nextra && strcmp(ch->channel_name, opt->channels[e].name) != 0)
            e++;
        if (e == nextra)
            return EXR_ERR_INVALID_ARGUMENT;
        /* A plane of 4-byte samples: floats, or uint32 for UINT. */
        const ImageChannel *x = &opt->channels[e];
        ch->user_data_type = x->type == IMAGE_CHANNEL_UINT ? EXR_PIXEL_UINT : EXR_PIXEL_FLOAT;
        ch->user_bytes_per_element = 4;
        ch->user_pixel_stride = 4;
        ch->user_line_stride = w * 4;
        ch->encode_from_ptr = (const uint8_t *)x->data + (size_t)cinfo->start_y * (size_t)w * 4;
    }
    return EXR_ERR_SUCCESS;
}

/* A chunk encoded: its bytes as the file takes them. */
typedef struct {
    void *bytes;
    uint64_t size;
} ExrChunkBytes;

/* The pipeline's last step, instead of writing: the chunk's bytes kept
 * (those the library's own step would write: the compressed buffer, which
 * is the packed one when nothing is compressed), to be written in order. */
static exr_result_t keep_chunk(exr_encode_pipeline_t *enc)
{
    ExrChunkBytes *c = enc->encoding_user_data;
    c->bytes = malloc(enc->compressed_bytes > 0 ? enc->compressed_bytes : 1);
    if (!c->bytes)
        return EXR_ERR_OUT_OF_MEMORY;
    memcpy(c->bytes, enc->compressed_buffer, enc->compressed_bytes);
    c->size = enc->compressed_bytes;
    return EXR_ERR_SUCCESS;
}

/* A share of the chunks, encoded on one thread with its own pipeline:
 * chunks first, first + stride, ... Its errors go to its own message. */
typedef struct {
    exr_context_t ctx;
    int part;
    const Image *img;
    const ImageWriteOptions *opt;
    const exr_chunk_info_t *cinfo; /* every chunk's */
    ExrChunkBytes *out;            /* ... and its bytes */
    int nchunks, first, stride;
    exr_result_t rv;
    ExrIO io;
    char msg[256];
} ExrEncodeJob;

static void *encode_chunks(void *arg)
{
    ExrEncodeJob *job = arg;
    ExrIO *caller = exr_writing; /* (job 0 runs on the writing thread) */
    exr_writing = &job->io;
    exr_encode_pipeline_t enc;
    memset(&enc, 0, sizeof enc);
    int started = 0;
    exr_result_t rv = EXR_ERR_SUCCESS;
    for (int i = job->first; i < job->nchunks && rv == EXR_ERR_SUCCESS; i += job->stride) {
        if (!started) {
            rv = exr_encoding_initialize(job->ctx, job->part, &job->cinfo[i], &enc);
            started = rv == EXR_ERR_SUCCESS;
            if (started)
                rv = point_channels(&enc, &job->cinfo[i], job->img, job->opt);
            if (rv == EXR_ERR_SUCCESS)
                rv = exr_encoding_choose_default_routines(job->ctx, job->part, &enc);
        } else {
            rv = exr_encoding_update(job->ctx, job->part, &job->cinfo[i], &enc);
            if (rv == EXR_ERR_SUCCESS)
                rv = point_channels(&enc, &job->cinfo[i], job->img, job->opt);
        }
        if (rv != EXR_ERR_SUCCESS)
            break;
        /* written later, in order, by the writing thread */
        enc.yield_until_ready_fn = NULL;
        enc.write_fn = keep_chunk;
        enc.encoding_user_data = &job->out[i];
        rv = exr_encoding_run(job->ctx, job->part, &enc);
    }
    if (started)
        exr_encoding_destroy(job->ctx, &enc);
    job->rv = rv;
    exr_writing = caller;
    return NULL;
}

/* Chunks a job takes at least: fewer are not worth a thread. */
#define EXR_CHUNKS_PER_JOB 8

/* Encodes every chunk, on up to opt->threads threads, and writes them in
 * order: the same bytes for any number of threads (each chunk is
 * compressed on its own). */
static exr_result_t write_chunks(exr_context_t ctx, int part, const Image *img, const ImageWriteOptions *opt,
                                 int lines, ExrIO *io)
{
    const int h = img->height;
    const int nchunks = (h + lines - 1) / lines;
    exr_chunk_info_t *cinfo = calloc((size_t)nchunks, sizeof *cinfo);
    ExrChunkBytes *out = calloc((size_t)nchunks, sizeof *out);
    int njobs = parallel_jobs(nchunks, EXR_CHUNKS_PER_JOB, opt->threads > 1 ? opt->threads : 1);
    ExrEncodeJob *jobs = calloc((size_t)njobs, sizeof *jobs);
    exr_result_t rv = EXR_ERR_SUCCESS;
    if (!cinfo || !out || !jobs)
        rv = EXR_ERR_OUT_OF_MEMORY;
    for (int i = 0; i < nchunks && rv == EXR_ERR_SUCCESS; i++)
        rv = exr_write_scanline_chunk_info(ctx, part, i * lines, &cinfo[i]);
    if (rv == EXR_ERR_SUCCESS) {
        for (int j = 0; j < njobs; j++)
            jobs[j] = (ExrEncodeJob){ ctx, part, img, opt, cinfo, out, nchunks, j, njobs, EXR_ERR_SUCCESS,
                                      { io->fd, jobs[j].msg, (int)sizeof jobs[j].msg, 0 }, { 0 } };
        parallel_run(njobs, encode_chunks, jobs, sizeof *jobs);
        for (int j = 0; j < njobs && rv == EXR_ERR_SUCCESS; j++) {
            rv = jobs[j].rv;
            if (rv != EXR_ERR_SUCCESS && jobs[j].io.have_err)
                keep_first_error(io, jobs[j].msg);
        }
    }
    for (int i = 0; i < nchunks && rv == EXR_ERR_SUCCESS; i++)
        rv = exr_write_scanline_chunk(ctx, part, cinfo[i].start_y, out[i].bytes, out[i].size);
    for (int i = 0; out && i < nchunks; i++)
        free(out[i].bytes);
    free(jobs);
    free(out);
    free(cinfo);
    return rv;
}

int image_exr_write(int fd, const Image *img, const ImageWriteOptions *opt, char *err, int errlen)
{
    ExrIO io = { fd, err, errlen, 0 };
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    exr_context_t ctx = NULL;
    exr_pixel_type_t ptype = opt->exr_float ? EXR_PIXEL_FLOAT : EXR_PIXEL_HALF;
    const int w = img->width, h = img->height;
    const int nextra = opt->channels ? opt->nchannels : 0;
    int part, lines;
    exr_result_t rv;

    init.user_data = &io;
    init.write_fn = exr_fd_write;
    init.error_handler_fn = on_exr_write_error;
    exr_writing = &io;

    rv = exr_start_write(&ctx, "image.exr", EXR_WRITE_FILE_DIRECTLY, &init);
    if (rv != EXR_ERR_SUCCESS)
        goto fail;
    rv = exr_add_part(ctx, "", EXR_STORAGE_SCANLINE, &part);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_initialize_required_attr_simple(ctx, part, w, h, exr_compression_of(opt->exr_compression));
    for (int c = 0; c < 4 && rv == EXR_ERR_SUCCESS; c++)
        rv = exr_add_channel(ctx, part, rgba_names[c], ptype, EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1);
    for (int c = 0; c < nextra && rv == EXR_ERR_SUCCESS; c++)
        rv = exr_add_channel(ctx, part, opt->channels[c].name, exr_type_of(opt->channels[c].type),
                             EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_set_lineorder(ctx, part, EXR_LINEORDER_INCREASING_Y);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_attr_set_string(ctx, part, "software", "hstrace");
    if (rv == EXR_ERR_SUCCESS && opt->have_chromaticities) {
        const float *c = opt->chromaticities;
        exr_attr_chromaticities_t chroma = { c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7] };
        rv = exr_attr_set_chromaticities(ctx, part, "chromaticities", &chroma);
    }
    for (int a = 0; opt->attributes && a < opt->nattributes && rv == EXR_ERR_SUCCESS; a++)
        rv = set_attribute(ctx, part, &opt->attributes[a]);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_write_header(ctx);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_get_scanlines_per_chunk(ctx, part, &lines);
    if (rv == EXR_ERR_SUCCESS)
        rv = write_chunks(ctx, part, img, opt, lines, &io);
    if (rv != EXR_ERR_SUCCESS)
        goto fail;
    rv = exr_finish(&ctx);
    exr_writing = NULL;
    if (rv != EXR_ERR_SUCCESS)
        return exr_fail(&io, rv);
    return 0;

fail:
    if (ctx != NULL)
        exr_finish(&ctx);
    exr_writing = NULL;
    return exr_fail(&io, rv);
}

/* Where each wanted channel goes in an RGBA pixel, -1 to skip it. */
static int channel_slot(const char *name, int grey_only)
{
    if (strcmp(name, "R") == 0) return 0;
    if (strcmp(name, "G") == 0) return 1;
    if (strcmp(name, "B") == 0) return 2;
    if (strcmp(name, "A") == 0) return 3;
    if (grey_only && strcmp(name, "Y") == 0) return 0;
    return -1;
}

/* Scratch pixels for one chunk: 8 floats a pixel, RGBA in the first four.
 * The padding is deliberate: OpenEXR 3.1.x picks hand-written routines for
 * 3 or 4 half channels decoded to tightly interleaved floats, and up to 3.2
 * the 4-channel ones put the channels in reverse order (fixed upstream in
 * 3.3, commit 6fdcad4a). With a pixel stride of 32 bytes none of them
 * matches and the library uses its generic unpacker. */
#define SCRATCH_STRIDE 8

typedef struct {
    float *buf;
    size_t cap; /* in pixels */
} Scratch;

/* Decodes one chunk covering pixels (x0,y0)..(x0+cw-1,y0+ch-1) of the
 * image and stores its RGBA floats there. */
static exr_result_t decode_chunk(exr_const_context_t ctx, int part, const exr_chunk_info_t *cinfo, int x0, int y0,
                                 Image *img, int grey_only, exr_decode_pipeline_t *dec, int *started, Scratch *sc)
{
    exr_result_t rv;
    size_t npix;
    const int cw = cinfo->width, chh = cinfo->height;

    if (x0 < 0 || y0 < 0 || cw <= 0 || chh <= 0 || cw > img->width - x0 || chh > img->height - y0)
        return EXR_ERR_CORRUPT_CHUNK;
    npix = (size_t)cw * (size_t)chh;
    if (npix > sc->cap) {
        float *nb = realloc(sc->buf, npix * SCRATCH_STRIDE * sizeof(float));
        if (nb == NULL)
            return EXR_ERR_OUT_OF_MEMORY;
        sc->buf = nb;
        sc->cap = npix;
    }
    for (size_t i = 0; i < npix; i++) {
        float *p = sc->buf + i * SCRATCH_STRIDE;
        p[0] = p[1] = p[2] = 0.0f;
        p[3] = 1.0f;
    }
    if (!*started) {
        rv = exr_decoding_initialize(ctx, part, cinfo, dec);
        if (rv != EXR_ERR_SUCCESS)
            return rv;
        *started = 1;
    } else {
        rv = exr_decoding_update(ctx, part, cinfo, dec);
        if (rv != EXR_ERR_SUCCESS)
            return rv;
    }
    for (int c = 0; c < dec->channel_count; c++) {
        exr_coding_channel_info_t *ch = &dec->channels[c];
        int slot = channel_slot(ch->channel_name, grey_only);
        if (slot < 0 || ch->x_samples != 1 || ch->y_samples != 1 || ch->width != cw || ch->height != chh) {
            ch->decode_to_ptr = NULL;
            continue;
        }
        ch->user_data_type = EXR_PIXEL_FLOAT; /* half and uint converted by the library */
        ch->user_bytes_per_element = 4;
        ch->user_pixel_stride = SCRATCH_STRIDE * (int32_t)sizeof(float);
        ch->user_line_stride = cw * SCRATCH_STRIDE * (int32_t)sizeof(float);
        ch->decode_to_ptr = (uint8_t *)(sc->buf + slot);
    }
    rv = exr_decoding_choose_default_routines(ctx, part, dec);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_decoding_run(ctx, part, dec);
    if (rv != EXR_ERR_SUCCESS)
        return rv;
    for (int y = 0; y < chh; y++) {
        const float *src = sc->buf + (size_t)y * (size_t)cw * SCRATCH_STRIDE;
        float *dst = img->rgba + ((size_t)(y0 + y) * (size_t)img->width + (size_t)x0) * 4;
        for (int x = 0; x < cw; x++, src += SCRATCH_STRIDE, dst += 4)
            memcpy(dst, src, 4 * sizeof(float));
    }
    return EXR_ERR_SUCCESS;
}

/* Starts reading the file behind io and reads the first part's layout:
 * what both readers below need before they decode anything. */
static exr_result_t start_read_part0(exr_context_t *ctx, ExrIO *io, exr_storage_t *storage, exr_attr_box2i_t *dw,
                                     const exr_attr_chlist_t **chans)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.user_data = io;
    init.read_fn = exr_fd_read;
    init.size_fn = exr_fd_size;
    init.error_handler_fn = on_exr_read_error;
    init.max_image_width = IMAGE_MAX_DIM;
    init.max_image_height = IMAGE_MAX_DIM;
    init.max_tile_width = IMAGE_MAX_DIM;
    init.max_tile_height = IMAGE_MAX_DIM;
    int nparts = 0;
    exr_result_t rv = exr_start_read(ctx, "image.exr", &init);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_get_count(*ctx, &nparts);
    if (rv == EXR_ERR_SUCCESS && nparts < 1)
        rv = EXR_ERR_FILE_BAD_HEADER;
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_get_storage(*ctx, 0, storage);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_get_data_window(*ctx, 0, dw);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_get_channels(*ctx, 0, chans);
    return rv;
}

/* Every chunk has an 8-byte entry in the offset table: a file too short
 * for its table cannot hold the data window it claims (a few hundred
 * corrupt bytes may claim 2^27 pixels), and no memory is asked for it.
 * 1 when the table is missing (the message set, *rv the library's error
 * or success), 0 when it fits. */
/* The data window's width and height, when an Image can hold them; else
 * -1 with the reason in err. */
static int data_window_size(exr_attr_box2i_t dw, int *w, int *h, char *err, int errlen)
{
    int64_t lw = (int64_t)dw.max.x - dw.min.x + 1, lh = (int64_t)dw.max.y - dw.min.y + 1;
    if (lw <= 0 || lh <= 0 || lw > IMAGE_MAX_DIM || lh > IMAGE_MAX_DIM || lw * lh > IMAGE_MAX_PIXELS) {
        image_set_error(err, errlen, "unsupported EXR data window (%lldx%lld)", (long long)lw, (long long)lh);
        return -1;
    }
    *w = (int)lw;
    *h = (int)lh;
    return 0;
}

static int chunk_table_missing(exr_context_t ctx, ExrIO *io, int w, int h, exr_result_t *rv)
{
    int32_t nchunks = 0;
    int64_t size = exr_fd_size(ctx, io);
    *rv = exr_get_chunk_count(ctx, 0, &nchunks);
    if (*rv != EXR_ERR_SUCCESS)
        return 1;
    if (size >= 0 && (int64_t)nchunks * 8 > size) {
        image_set_error(io->err, io->errlen, "truncated EXR file: its %dx%d data window needs %d chunks, the file holds %lld bytes",
                        w, h, (int)nchunks, (long long)size);
        return 1;
    }
    return 0;
}

int image_exr_read(int fd, Image *img, char *err, int errlen)
{
    ExrIO io = { fd, err, errlen, 0 };
    exr_context_t ctx = NULL;
    exr_decode_pipeline_t dec;
    Scratch sc = { NULL, 0 };
    exr_storage_t storage;
    exr_attr_box2i_t dw;
    const exr_attr_chlist_t *chans = NULL;
    int started = 0, have_rgb = 0, have_y = 0, grey_only, w, h;
    exr_result_t rv;

    memset(&dec, 0, sizeof dec);
    rv = start_read_part0(&ctx, &io, &storage, &dw, &chans);
    if (rv != EXR_ERR_SUCCESS)
        goto fail;
    if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED) {
        image_set_error(err, errlen, "deep EXR images are not supported");
        goto fail_quiet;
    }
    for (int c = 0; c < chans->num_channels; c++) {
        const char *n = chans->entries[c].name.str;
        if (strcmp(n, "R") == 0 || strcmp(n, "G") == 0 || strcmp(n, "B") == 0)
            have_rgb = 1;
        else if (strcmp(n, "Y") == 0)
            have_y = 1;
    }
    if (!have_rgb && !have_y) {
        image_set_error(err, errlen, "EXR file has no R, G, B or Y channel");
        goto fail_quiet;
    }
    grey_only = !have_rgb;
    if (data_window_size(dw, &w, &h, err, errlen))
        goto fail_quiet;
    if (chunk_table_missing(ctx, &io, w, h, &rv)) {
        if (rv != EXR_ERR_SUCCESS)
            goto fail;
        goto fail_quiet;
    }
    if (image_alloc(img, w, h) != 0) {
        image_set_error(err, errlen, "out of memory for a %dx%d image", w, h);
        goto fail_quiet;
    }
    /* No pre-fill: every pixel belongs to exactly one chunk, and each chunk
     * fills all four channels (missing ones from the scratch defaults), so
     * memory is only touched as valid data arrives. */

    if (storage == EXR_STORAGE_SCANLINE) {
        int lines;
        rv = exr_get_scanlines_per_chunk(ctx, 0, &lines);
        if (rv != EXR_ERR_SUCCESS)
            goto fail;
        if (lines < 1)
            lines = 1;
        for (int64_t y = dw.min.y; y <= dw.max.y; y += lines) {
            exr_chunk_info_t cinfo;
            rv = exr_read_scanline_chunk_info(ctx, 0, (int)y, &cinfo);
            if (rv == EXR_ERR_SUCCESS)
                rv = decode_chunk(ctx, 0, &cinfo, cinfo.start_x - dw.min.x, cinfo.start_y - dw.min.y, img,
                                  grey_only, &dec, &started, &sc);
            if (rv != EXR_ERR_SUCCESS)
                goto fail;
        }
    } else {
        int32_t tw, th, lw, lh, cx, cy;
        rv = exr_get_tile_sizes(ctx, 0, 0, 0, &tw, &th);
        if (rv == EXR_ERR_SUCCESS)
            rv = exr_get_level_sizes(ctx, 0, 0, 0, &lw, &lh);
        if (rv != EXR_ERR_SUCCESS)
            goto fail;
        if (tw < 1 || th < 1 || lw != w || lh != h) {
            rv = EXR_ERR_BAD_CHUNK_LEADER;
            goto fail;
        }
        cx = (int32_t)(((int64_t)lw + tw - 1) / tw);
        cy = (int32_t)(((int64_t)lh + th - 1) / th);
        for (int ty = 0; ty < cy; ty++) {
            for (int tx = 0; tx < cx; tx++) {
                exr_chunk_info_t cinfo;
                rv = exr_read_tile_chunk_info(ctx, 0, tx, ty, 0, 0, &cinfo);
                if (rv == EXR_ERR_SUCCESS)
                    rv = decode_chunk(ctx, 0, &cinfo, (int)((int64_t)tx * tw), (int)((int64_t)ty * th), img,
                                      grey_only, &dec, &started, &sc);
                if (rv != EXR_ERR_SUCCESS)
                    goto fail;
            }
        }
    }
    if (started)
        exr_decoding_destroy(ctx, &dec);
    exr_finish(&ctx);
    free(sc.buf);
    if (grey_only) {
        for (size_t i = 0; i < (size_t)w * (size_t)h; i++)
            img->rgba[4 * i + 1] = img->rgba[4 * i + 2] = img->rgba[4 * i];
    }
    return 0;

fail:
    exr_fail(&io, rv);
fail_quiet:
    if (started)
        exr_decoding_destroy(ctx, &dec);
    if (ctx != NULL)
        exr_finish(&ctx);
    free(sc.buf);
    image_free(img);
    return -1;
}

/* Named channels of a scanline file as float planes (image_read_exr_channels). */
/* Decodes the chunks of part 0 holding rows [y0, y1) (counted from the data
 * window's top) into planes of their own, never interleaved: for each of
 * the n channels names[k], data[k] (w*h samples of 4 bytes, row 0 at the
 * top) as types[k] (EXR_PIXEL_FLOAT, half converted; or EXR_PIXEL_UINT).
 * Other channels are skipped. Returns EXR_ERR_SUCCESS or the error. */
static exr_result_t decode_rows(exr_context_t ctx, exr_attr_box2i_t dw, int w, int h, int y0, int y1, int n,
                                const char *const *names, void *const *data, const exr_pixel_type_t *types)
{
    exr_decode_pipeline_t dec;
    int lines, started = 0;
    memset(&dec, 0, sizeof dec);
    exr_result_t rv = exr_get_scanlines_per_chunk(ctx, 0, &lines);
    if (lines < 1)
        lines = 1;
    /* from the chunk holding row y0: chunks start every `lines` rows from
     * the data window's top */
    for (int64_t y = dw.min.y + (int64_t)(y0 / lines) * lines; rv == EXR_ERR_SUCCESS && y < dw.min.y + (int64_t)y1;
         y += lines) {
        exr_chunk_info_t cinfo;
        rv = exr_read_scanline_chunk_info(ctx, 0, (int)y, &cinfo);
        if (rv == EXR_ERR_SUCCESS)
            rv = started ? exr_decoding_update(ctx, 0, &cinfo, &dec) : exr_decoding_initialize(ctx, 0, &cinfo, &dec);
        if (rv != EXR_ERR_SUCCESS)
            break;
        started = 1;
        int64_t row = cinfo.start_y - dw.min.y;
        if (row < 0 || cinfo.height < 1 || row + cinfo.height > h || cinfo.width != w) {
            rv = EXR_ERR_CORRUPT_CHUNK;
            break;
        }
        for (int c = 0; c < dec.channel_count; c++) {
            exr_coding_channel_info_t *ch = &dec.channels[c];
            ch->decode_to_ptr = NULL;
            for (int k = 0; k < n; k++)
                if (strcmp(ch->channel_name, names[k]) == 0) {
                    ch->user_data_type = types[k];
                    ch->user_bytes_per_element = 4;
                    ch->user_pixel_stride = 4;
                    ch->user_line_stride = w * 4;
                    ch->decode_to_ptr = (uint8_t *)data[k] + (size_t)row * (size_t)w * 4;
                }
        }
        rv = exr_decoding_choose_default_routines(ctx, 0, &dec);
        if (rv == EXR_ERR_SUCCESS)
            rv = exr_decoding_run(ctx, 0, &dec);
    }
    if (started)
        exr_decoding_destroy(ctx, &dec);
    return rv;
}

int image_exr_read_planes(int fd, const char *const *names, int n, float **planes, int *width, int *height,
                          char *err, int errlen)
{
    ExrIO io = { fd, err, errlen, 0 };
    exr_context_t ctx = NULL;
    exr_storage_t storage;
    exr_attr_box2i_t dw;
    const exr_attr_chlist_t *chans = NULL;
    int w = 0, h = 0, status = -1;
    exr_result_t rv;

    for (int k = 0; k < n; k++)
        planes[k] = NULL;
    rv = start_read_part0(&ctx, &io, &storage, &dw, &chans);
    if (rv != EXR_ERR_SUCCESS)
        goto fail;
    if (storage != EXR_STORAGE_SCANLINE) {
        image_set_error(err, errlen, "analysis channels are read from scanline EXR files only");
        goto fail_quiet;
    }
    for (int k = 0; k < n; k++) {
        int found = 0;
        for (int c = 0; c < chans->num_channels && !found; c++)
            found = strcmp(chans->entries[c].name.str, names[k]) == 0 && chans->entries[c].x_sampling == 1 &&
                    chans->entries[c].y_sampling == 1;
        if (!found) {
            image_set_error(err, errlen, "no channel '%s'", names[k]);
            status = 1;
            goto fail_quiet;
        }
    }
    if (data_window_size(dw, &w, &h, err, errlen))
        goto fail_quiet;
    if (chunk_table_missing(ctx, &io, w, h, &rv)) {
        if (rv != EXR_ERR_SUCCESS)
            goto fail;
        goto fail_quiet;
    }
    for (int k = 0; k < n; k++)
        if (!(planes[k] = calloc((size_t)w * (size_t)h, sizeof(float)))) {
            image_set_error(err, errlen, "out of memory for a %dx%d image", w, h);
            goto fail_quiet;
        }
    {
        /* every channel asked for, as floats */
        void **data = malloc(sizeof *data * (size_t)(n > 0 ? n : 1));
        exr_pixel_type_t *types = malloc(sizeof *types * (size_t)(n > 0 ? n : 1));
        if (!data || !types) {
            free(data);
            free(types);
            image_set_error(err, errlen, "out of memory");
            goto fail_quiet;
        }
        for (int k = 0; k < n; k++) {
            data[k] = planes[k];
            types[k] = EXR_PIXEL_FLOAT;
        }
        rv = decode_rows(ctx, dw, w, h, 0, h, n, names, data, types);
        free(data);
        free(types);
        if (rv != EXR_ERR_SUCCESS)
            goto fail;
    }
    exr_finish(&ctx);
    *width = w;
    *height = h;
    return 0;

fail:
    exr_fail(&io, rv);
fail_quiet:
    if (ctx != NULL)
        exr_finish(&ctx);
    for (int k = 0; k < n; k++) {
        free(planes[k]);
        planes[k] = NULL;
    }
    return status;
}

/* ---- every channel and the header (image_read_exr_file) -------------------- */

static ImageExrCompression compression_of_exr(exr_compression_t c)
{
    switch (c) {
    case EXR_COMPRESSION_NONE: return IMAGE_EXR_NONE;
    case EXR_COMPRESSION_RLE: return IMAGE_EXR_RLE;
    case EXR_COMPRESSION_ZIPS: return IMAGE_EXR_ZIPS;
    case EXR_COMPRESSION_PIZ: return IMAGE_EXR_PIZ;
    default: return IMAGE_EXR_ZIP; /* ZIP, and the lossy kinds, which a copy must not repeat */
    }
}

static char *copy_string(const char *s, int32_t n)
{
    char *c = malloc((size_t)n + 1);
    if (c) {
        memcpy(c, s, (size_t)n);
        c[n] = '\0';
    }
    return c;
}

/* The header's string, int and double attributes and its chromaticities
 * into f. 0, or -1 with the message set. */
static int read_attributes(exr_const_context_t ctx, ImageExrFile *f, ExrIO *io)
{
    int32_t count = 0;
    exr_result_t rv = exr_get_attribute_count(ctx, 0, &count);
    if (rv != EXR_ERR_SUCCESS)
        return exr_fail(io, rv);
    f->attributes = count > 0 ? calloc((size_t)count, sizeof *f->attributes) : NULL;
    if (count > 0 && !f->attributes) {
        image_set_error(io->err, io->errlen, "out of memory");
        return -1;
    }
    for (int32_t k = 0; k < count; k++) {
        const exr_attribute_t *a = NULL;
        rv = exr_get_attribute_by_index(ctx, 0, EXR_ATTR_LIST_FILE_ORDER, k, &a);
        if (rv != EXR_ERR_SUCCESS)
            return exr_fail(io, rv);
        if (a->type == EXR_ATTR_CHROMATICITIES && strcmp(a->name, "chromaticities") == 0 && a->chromaticities) {
            const exr_attr_chromaticities_t *c = a->chromaticities;
            const float v[8] = { c->red_x, c->red_y, c->green_x, c->green_y,
                                 c->blue_x, c->blue_y, c->white_x, c->white_y };
            memcpy(f->chromaticities, v, sizeof v);
            f->have_chromaticities = 1;
            continue;
        }
        if (a->type != EXR_ATTR_STRING && a->type != EXR_ATTR_INT && a->type != EXR_ATTR_DOUBLE)
            continue;
        ImageExrAttribute *o = &f->attributes[f->nattributes];
        o->name = copy_string(a->name, (int32_t)strlen(a->name));
        if (a->type == EXR_ATTR_STRING) {
            o->type = IMAGE_ATTR_STRING;
            o->s = a->string && a->string->length > 0 ? copy_string(a->string->str, a->string->length)
                                                      : copy_string("", 0);
        } else if (a->type == EXR_ATTR_INT) {
            o->type = IMAGE_ATTR_INT;
            o->i = a->i;
        } else {
            o->type = IMAGE_ATTR_DOUBLE;
            o->d = a->d;
        }
        f->nattributes++;
        if (!o->name || (o->type == IMAGE_ATTR_STRING && !o->s)) {
            image_set_error(io->err, io->errlen, "out of memory");
            return -1;
        }
    }
    return 0;
}

int image_exr_read_file(int fd, ImageExrFile *f, int y0, int y1, char *err, int errlen)
{
    ExrIO io = { fd, err, errlen, 0 };
    exr_context_t ctx = NULL;
    exr_storage_t storage;
    exr_attr_box2i_t dw;
    exr_compression_t compression;
    const exr_attr_chlist_t *chans = NULL;
    int w = 0, h = 0;
    exr_result_t rv;

    memset(f, 0, sizeof *f);
    rv = start_read_part0(&ctx, &io, &storage, &dw, &chans);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_get_compression(ctx, 0, &compression);
    if (rv != EXR_ERR_SUCCESS)
        goto fail;
    if (storage != EXR_STORAGE_SCANLINE) {
        image_set_error(err, errlen, "not a scanline EXR file (tiled or deep)");
        goto fail_quiet;
    }
    if (data_window_size(dw, &w, &h, err, errlen))
        goto fail_quiet;
    f->width = w;
    f->height = h;
    f->compression = compression_of_exr(compression);
    f->channels = chans->num_channels > 0 ? calloc((size_t)chans->num_channels, sizeof *f->channels) : NULL;
    if (chans->num_channels > 0 && !f->channels) {
        image_set_error(err, errlen, "out of memory");
        goto fail_quiet;
    }
    for (int c = 0; c < chans->num_channels; c++) {
        const exr_attr_chlist_entry_t *e = &chans->entries[c];
        if (e->x_sampling != 1 || e->y_sampling != 1) {
            image_set_error(err, errlen, "channel '%s' is subsampled (%dx%d)", e->name.str, e->x_sampling,
                            e->y_sampling);
            goto fail_quiet;
        }
        ImageExrChannel *o = &f->channels[f->nchannels];
        o->type = e->pixel_type == EXR_PIXEL_UINT ? IMAGE_CHANNEL_UINT
                  : e->pixel_type == EXR_PIXEL_FLOAT ? IMAGE_CHANNEL_FLOAT : IMAGE_CHANNEL_HALF;
        if (!(o->name = copy_string(e->name.str, e->name.length))) {
            image_set_error(err, errlen, "out of memory");
            goto fail_quiet;
        }
        f->nchannels++;
    }
    if (read_attributes(ctx, f, &io))
        goto fail_quiet;

    y0 = y0 < 0 ? 0 : y0;
    y1 = y1 > h ? h : y1;
    if (y0 < y1) {
        if (chunk_table_missing(ctx, &io, w, h, &rv)) {
            if (rv != EXR_ERR_SUCCESS)
                goto fail;
            goto fail_quiet;
        }
        for (int c = 0; c < f->nchannels; c++)
            if (!(f->channels[c].data = calloc((size_t)w * (size_t)h, 4))) {
                image_set_error(err, errlen, "out of memory for a %dx%d image", w, h);
                goto fail_quiet;
            }
        /* each channel as stored: half and float as floats, uint as uint32 */
        const char **names = malloc(sizeof *names * (size_t)(f->nchannels > 0 ? f->nchannels : 1));
        void **data = malloc(sizeof *data * (size_t)(f->nchannels > 0 ? f->nchannels : 1));
        exr_pixel_type_t *types = malloc(sizeof *types * (size_t)(f->nchannels > 0 ? f->nchannels : 1));
        if (!names || !data || !types) {
            free(names);
            free(data);
            free(types);
            image_set_error(err, errlen, "out of memory");
            goto fail_quiet;
        }
        for (int k = 0; k < f->nchannels; k++) {
            names[k] = f->channels[k].name;
            data[k] = f->channels[k].data;
            types[k] = f->channels[k].type == IMAGE_CHANNEL_UINT ? EXR_PIXEL_UINT : EXR_PIXEL_FLOAT;
        }
        rv = decode_rows(ctx, dw, w, h, y0, y1, f->nchannels, names, data, types);
        free(names);
        free(data);
        free(types);
        if (rv != EXR_ERR_SUCCESS)
            goto fail;
    }
    exr_finish(&ctx);
    return 0;

fail:
    exr_fail(&io, rv);
fail_quiet:
    if (ctx != NULL)
        exr_finish(&ctx);
    image_exr_file_free(f);
    return -1;
}

const ImageExrAttribute *image_exr_file_attribute(const ImageExrFile *f, const char *name)
{
    for (int k = 0; k < f->nattributes; k++)
        if (strcmp(f->attributes[k].name, name) == 0)
            return &f->attributes[k];
    return NULL;
}

void image_exr_file_free(ImageExrFile *f)
{
    for (int c = 0; c < f->nchannels; c++) {
        free(f->channels[c].name);
        free(f->channels[c].data);
    }
    for (int k = 0; k < f->nattributes; k++) {
        free(f->attributes[k].name);
        free(f->attributes[k].s);
    }
    free(f->channels);
    free(f->attributes);
    memset(f, 0, sizeof *f);
}
