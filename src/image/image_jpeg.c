/* JPEG through libjpeg (Debian's libjpeg-turbo): writes what POV-Ray 3.7
 * writes for +FJ: baseline YCbCr without chroma subsampling, at the quality
 * of POV-Ray's Compression key (0 and 1 mean 85, its default), with a
 * comment naming the software (no date: the same render gives the same
 * bytes), in POV-Ray's display encoding; JPEG has no alpha. Reads baseline
 * and progressive JPEG (grey or colour), every warning of libjpeg's about
 * corrupt data taken as an error. */
#include <setjmp.h>
#include <stdio.h> /* before jpeglib.h, which uses FILE and size_t */
#include <stdlib.h>
#include <string.h>

#include <jpeglib.h>

#include "image_codec.h"

/* libjpeg reports through these: a fatal error or a warning longjmps back
 * with its message. */
typedef struct {
    struct jpeg_error_mgr mgr;
    jmp_buf jump;
    char *err;
    int errlen;
} JpegErr;

static void on_jpeg_error(j_common_ptr cinfo)
{
    JpegErr *je = (JpegErr *)cinfo->err;
    char msg[JMSG_LENGTH_MAX];
    (*cinfo->err->format_message)(cinfo, msg);
    image_set_error(je->err, je->errlen, "%s", msg);
    longjmp(je->jump, 1);
}

/* Level -1 is a warning (corrupt data, a premature end): an error here, so
 * that a damaged file is never compared as if it were whole. Trace messages
 * (levels 0 and up) are dropped. */
static void on_jpeg_message(j_common_ptr cinfo, int level)
{
    if (level < 0)
        on_jpeg_error(cinfo);
}

static void jpeg_write_body(struct jpeg_compress_struct *cinfo, FILE *fp, const Image *img,
                            const ImageWriteOptions *opt, ImageRowEncoder *enc, unsigned char *row)
{
    int quality = opt->jpeg_quality <= 1 ? 85 : opt->jpeg_quality > 100 ? 100 : opt->jpeg_quality;
    char comment[128];
    jpeg_stdio_dest(cinfo, fp);
    cinfo->image_width = (JDIMENSION)img->width;
    cinfo->image_height = (JDIMENSION)img->height;
    cinfo->input_components = 3;
    cinfo->in_color_space = JCS_RGB;
    jpeg_set_defaults(cinfo);
    jpeg_set_colorspace(cinfo, JCS_YCbCr);
    jpeg_set_quality(cinfo, quality, TRUE);
    /* as POV-Ray: no chroma subsampling, to keep small colour details */
    cinfo->comp_info[0].h_samp_factor = 1;
    cinfo->comp_info[0].v_samp_factor = 1;
    jpeg_start_compress(cinfo, TRUE);
    snprintf(comment, sizeof comment, "Software: %s\n", opt->software ? opt->software : "hstrace");
    jpeg_write_marker(cinfo, JPEG_COM, (const JOCTET *)comment, (unsigned)strlen(comment));
    for (int y = 0; y < img->height; y++) {
        JSAMPROW rows[1] = { row };
        char why[256];
        if (image_row_encode(enc, img->rgba + (size_t)y * (size_t)img->width * 4, why, (int)sizeof why) != 0) {
            JpegErr *je = (JpegErr *)cinfo->err;
            image_set_error(je->err, je->errlen, "%s", why);
            longjmp(je->jump, 1);
        }
        for (int x = 0; x < img->width; x++)
            for (int c = 0; c < 3; c++)
                row[3 * (size_t)x + (size_t)c] = (unsigned char)enc->samples[4 * (size_t)x + (size_t)c];
        jpeg_write_scanlines(cinfo, rows, 1);
    }
    jpeg_finish_compress(cinfo);
}

/* Working state kept behind one pointer, so that nothing the error path
 * needs lives in a local changed after setjmp. */
typedef struct {
    JpegErr je;
    ImageRowEncoder enc;
    unsigned char *row;
    float *lut;
    /* libjpeg's own state, here too: it changes after setjmp */
    struct jpeg_compress_struct cinfo;
    struct jpeg_decompress_struct dinfo;
} JpegState;

int image_jpeg_write(FILE *fp, const Image *img, const ImageWriteOptions *opt, char *err, int errlen)
{
    JpegState *st = calloc(1, sizeof *st);

    if (img->width > JPEG_MAX_DIMENSION || img->height > JPEG_MAX_DIMENSION) {
        free(st);
        image_set_error(err, errlen, "JPEG files hold at most %ldx%ld pixels", (long)JPEG_MAX_DIMENSION, (long)JPEG_MAX_DIMENSION);
        return -1;
    }
    if (st == NULL || image_row_encoder_init(&st->enc, opt, img->width, 255, 0) != 0) {
        free(st);
        image_set_error(err, errlen, "out of memory");
        return -1;
    }
    st->row = malloc((size_t)img->width * 3);
    if (st->row == NULL) {
        image_row_encoder_free(&st->enc);
        free(st);
        image_set_error(err, errlen, "out of memory");
        return -1;
    }
    st->je.err = err;
    st->je.errlen = errlen;
    st->cinfo.err = jpeg_std_error(&st->je.mgr);
    st->je.mgr.error_exit = on_jpeg_error;
    st->je.mgr.emit_message = on_jpeg_message;
    if (setjmp(st->je.jump)) {
        jpeg_destroy_compress(&st->cinfo);
        image_row_encoder_free(&st->enc);
        free(st->row);
        free(st);
        return -1;
    }
    jpeg_create_compress(&st->cinfo);
    jpeg_write_body(&st->cinfo, fp, img, opt, &st->enc, st->row);
    jpeg_destroy_compress(&st->cinfo);
    image_row_encoder_free(&st->enc);
    free(st->row);
    free(st);
    return 0;
}

static void jpeg_read_body(struct jpeg_decompress_struct *cinfo, FILE *fp, Image *img, double display_gamma,
                           JpegState *st)
{
    ImageTransfer t;
    /* What the file holds after its start, for the bound below. */
    long here = ftell(fp), bytes = -1;
    if (here >= 0 && fseek(fp, 0, SEEK_END) == 0) {
        bytes = ftell(fp) - here;
        if (fseek(fp, here, SEEK_SET) != 0)
            bytes = -1;
    }
    jpeg_stdio_src(cinfo, fp);
    /* A progressive file keeps every coefficient: a few corrupt bytes may
     * claim 2^28 pixels. libjpeg-turbo refuses to go past this much
     * (it has no backing store) with an error. */
    cinfo->mem->max_memory_to_use = 512L << 20;
    jpeg_read_header(cinfo, TRUE);
    if ((unsigned long)cinfo->image_width * cinfo->image_height > (unsigned long)IMAGE_MAX_PIXELS ||
        cinfo->image_width > IMAGE_MAX_DIM || cinfo->image_height > IMAGE_MAX_DIM) {
        image_set_error(st->je.err, st->je.errlen, "unsupported JPEG size %ux%u", (unsigned)cinfo->image_width,
                        (unsigned)cinfo->image_height);
        longjmp(st->je.jump, 1);
    }
    /* A decompression bomb: arithmetic coding turns a few hundred bytes
     * into a uniform 45000x1800 image without a warning. Real files hold
     * far fewer pixels per byte (a uniform 4:2:0 Huffman-coded image about
     * 170); past 4096 the file is refused rather than memory spent on it. */
    if (bytes >= 0 && (double)cinfo->image_width * (double)cinfo->image_height > 4096.0 * (double)(bytes + 1)) {
        image_set_error(st->je.err, st->je.errlen, "JPEG data of %ld bytes is too small for %ux%u pixels", bytes,
                        (unsigned)cinfo->image_width, (unsigned)cinfo->image_height);
        longjmp(st->je.jump, 1);
    }
    cinfo->out_color_space = JCS_RGB;
    jpeg_start_decompress(cinfo);
    const int w = (int)cinfo->output_width, h = (int)cinfo->output_height;
    image_transfer_init(&t, display_gamma);
    st->lut = image_transfer_decode_table(&t, 255);
    st->row = malloc((size_t)w * 3);
    /* the image grows with the rows decoded */
    int cap = h < 64 ? h : 64;
    if (st->lut == NULL || st->row == NULL || image_alloc(img, w, cap) != 0) {
        image_set_error(st->je.err, st->je.errlen, "out of memory for a %dx%d image", w, h);
        longjmp(st->je.jump, 1);
    }
    for (int y = 0; y < h; y++) {
        JSAMPROW rows[1] = { st->row };
        if (image_grow_rows(img, y, h, &cap)) {
            image_set_error(st->je.err, st->je.errlen, "out of memory for a %dx%d image", w, h);
            longjmp(st->je.jump, 1);
        }
        if (jpeg_read_scanlines(cinfo, rows, 1) != 1) {
            image_set_error(st->je.err, st->je.errlen, "JPEG data is truncated");
            longjmp(st->je.jump, 1);
        }
        float *px = img->rgba + (size_t)y * (size_t)w * 4;
        for (int x = 0; x < w; x++, px += 4) {
            px[0] = st->lut[st->row[3 * x]];
            px[1] = st->lut[st->row[3 * x + 1]];
            px[2] = st->lut[st->row[3 * x + 2]];
            px[3] = 1.0f;
        }
        img->height = y + 1;
    }
    jpeg_finish_decompress(cinfo);
}

int image_jpeg_read(FILE *fp, Image *img, double display_gamma, char *err, int errlen)
{
    JpegState *st = calloc(1, sizeof *st);

    if (st == NULL) {
        image_set_error(err, errlen, "out of memory");
        return -1;
    }
    st->je.err = err;
    st->je.errlen = errlen;
    st->dinfo.err = jpeg_std_error(&st->je.mgr);
    st->je.mgr.error_exit = on_jpeg_error;
    st->je.mgr.emit_message = on_jpeg_message;
    if (setjmp(st->je.jump)) {
        jpeg_destroy_decompress(&st->dinfo);
        free(st->row);
        free(st->lut);
        free(st);
        image_free(img);
        if (err != NULL && errlen > 0 && err[0] == '\0')
            image_set_error(err, errlen, "corrupt JPEG file");
        return -1;
    }
    jpeg_create_decompress(&st->dinfo);
    jpeg_read_body(&st->dinfo, fp, img, display_gamma, st);
    jpeg_destroy_decompress(&st->dinfo);
    free(st->row);
    free(st->lut);
    free(st);
    return 0;
}
