/* Format detection, and the atomic write / read dispatch. */
#include "image.h"
#include "scene.h"

#include <errno.h>
#include <math.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "atomic_file.h"
#include "image_codec.h"
#include "memory_budget.h"

static double decode_working(double c, double gamma)
{
    if (c <= 0.0)
        return c;
    if (gamma == 0.0)
        return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
    return pow(c, gamma);
}

void image_decode_working_gamma(Image *img, double gamma)
{
    if (gamma == 1.0)
        return;
    size_t n = (size_t)img->width * (size_t)img->height;
    for (size_t i = 0; i < n; i++) {
        float *px = &img->rgba[4 * i];
        double a = px[3];
        if (a <= 0.0)
            continue;
        for (int k = 0; k < 3; k++)
            px[k] = (float)(a * decode_working(px[k] / a, gamma));
    }
}

ImageFormat image_format_from_path(const char *path)
{
    const char *dot, *slash;

    if (path == NULL)
        return IMAGE_FORMAT_UNKNOWN;
    dot = strrchr(path, '.');
    slash = strrchr(path, '/');
    if (dot == NULL || (slash != NULL && dot < slash))
        return IMAGE_FORMAT_UNKNOWN;
    if (strcasecmp(dot, ".exr") == 0)
        return IMAGE_FORMAT_EXR;
    if (strcasecmp(dot, ".png") == 0)
        return IMAGE_FORMAT_PNG;
    if (strcasecmp(dot, ".ppm") == 0)
        return IMAGE_FORMAT_PPM;
    if (strcasecmp(dot, ".tga") == 0)
        return IMAGE_FORMAT_TGA;
    if (strcasecmp(dot, ".bmp") == 0)
        return IMAGE_FORMAT_BMP;
    if (strcasecmp(dot, ".jpg") == 0 || strcasecmp(dot, ".jpeg") == 0)
        return IMAGE_FORMAT_JPEG;
    if (strcasecmp(dot, ".hdr") == 0)
        return IMAGE_FORMAT_HDR;
    return IMAGE_FORMAT_UNKNOWN;
}

/* Runs the codec on the temporary file; returns 0, or -1 with the reason in
 * why (errno text when the codec left none). */
static int write_codec(AtomicFile *af, ImageFormat fmt, const Image *img, const ImageWriteOptions *opt,
                       char *why, int whylen)
{
    FILE *fp;
    int rc;

    why[0] = '\0';
    if (fmt == IMAGE_FORMAT_EXR) {
        errno = 0;
        return image_exr_write(af->fd, img, opt, why, whylen);
    }
    fp = fdopen(af->fd, "wb");
    if (fp == NULL)
        return -1;
    errno = 0;
    switch (fmt) {
    case IMAGE_FORMAT_PNG: rc = image_png_write(fp, img, opt, why, whylen); break;
    case IMAGE_FORMAT_TGA: rc = image_tga_write(fp, img, opt, why, whylen); break;
    case IMAGE_FORMAT_BMP: rc = image_bmp_write(fp, img, opt, why, whylen); break;
    case IMAGE_FORMAT_JPEG: rc = image_jpeg_write(fp, img, opt, why, whylen); break;
    case IMAGE_FORMAT_HDR: rc = image_hdr_write(fp, img, opt, why, whylen); break;
    default: rc = image_ppm_write(fp, img, opt, why, whylen); break;
    }
    /* fclose flushes: a full disk shows up here at the latest. */
    if (ferror(fp) && rc == 0)
        rc = -1;
    af->fd = -1;
    if (fclose(fp) != 0 && rc == 0)
        rc = -1;
    return rc;
}

int image_write(const char *path, const Image *img, const ImageWriteOptions *opt, char *err, int errlen)
{
    static const ImageWriteOptions defaults = { 0 };
    ImageFormat fmt = image_format_from_path(path);
    AtomicFile af;
    char why[256];

    if (err != NULL && errlen > 0)
        err[0] = '\0';
    if (opt == NULL)
        opt = &defaults;
    if (path == NULL || path[0] == '\0') {
        image_set_error(err, errlen, "cannot write an image: no file name given");
        return -1;
    }
    if (fmt == IMAGE_FORMAT_UNKNOWN) {
        image_set_error(err, errlen, "cannot write '%s': unknown image format (use .exr, .png, .ppm, .tga, .bmp, .jpg or .hdr)", path);
        return -1;
    }
    if (img == NULL || img->rgba == NULL || img->width <= 0 || img->height <= 0 ||
        img->width > IMAGE_MAX_DIM || img->height > IMAGE_MAX_DIM) {
        image_set_error(err, errlen, "cannot write '%s': empty or invalid image", path);
        return -1;
    }
    if (atomic_file_open(&af, path) != 0) {
        int e = errno;
        struct stat st;
        if (e == EACCES && stat(path, &st) == 0 && S_ISREG(st.st_mode))
            image_set_error(err, errlen, "cannot write '%s': %s (the file is read-only: it is left as it is)", path,
                            strerror(e));
        else
            image_set_error(err, errlen, "cannot write '%s': %s", path, strerror(e));
        return -1;
    }
    if (write_codec(&af, fmt, img, opt, why, (int)sizeof why) != 0) {
        int e = errno;
        atomic_file_abort(&af);
        if (why[0] == '\0')
            snprintf(why, sizeof why, "%s", e ? strerror(e) : "write error");
        image_set_error(err, errlen, "cannot write '%s': %s", path, why);
        return -1;
    }
    if (atomic_file_commit(&af) != 0) {
        image_set_error(err, errlen, "cannot write '%s': %s", path, strerror(errno));
        return -1;
    }
    return 0;
}

/* Which codec reads this file: by its first bytes, falling back to the
 * extension for files too short to tell and for Targa (which has no
 * signature at its start). */
static ImageFormat sniff(int fd, const char *path)
{
    unsigned char m[8];
    ssize_t n = pread(fd, m, sizeof m, 0);

    if (n >= 4 && m[0] == 0x76 && m[1] == 0x2f && m[2] == 0x31 && m[3] == 0x01)
        return IMAGE_FORMAT_EXR;
    if (n >= 8 && memcmp(m, "\211PNG\r\n\032\n", 8) == 0)
        return IMAGE_FORMAT_PNG;
    if (n >= 2 && m[0] == 'P' && (m[1] == '3' || m[1] == '6' || m[1] == '2' || m[1] == '5'))
        return IMAGE_FORMAT_PPM;
    if (n >= 3 && m[0] == 0xff && m[1] == 0xd8 && m[2] == 0xff)
        return IMAGE_FORMAT_JPEG;
    if (n >= 2 && m[0] == 'B' && m[1] == 'M')
        return IMAGE_FORMAT_BMP;
    if (n >= 2 && m[0] == '#' && m[1] == '?')
        return IMAGE_FORMAT_HDR;
    ImageFormat by_name = image_format_from_path(path);
    return n < 8 || by_name == IMAGE_FORMAT_TGA ? by_name : IMAGE_FORMAT_UNKNOWN;
}

/* Opens a picture to read: a regular file only. O_NONBLOCK, so that a FIFO
 * is refused at once rather than waited on for a writer (an image_map
 * naming one hung the parse); a device (/dev/zero) could be read for
 * ever. Returns the descriptor, or -1 with the message. */
static int open_image(const char *path, char *err, int errlen)
{
    struct stat st;
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        image_set_error(err, errlen, "cannot read '%s': %s", path, strerror(errno));
        return -1;
    }
    const char *irregular = fstat(fd, &st) != 0    ? strerror(errno)
                            : S_ISDIR(st.st_mode)  ? strerror(EISDIR)
                            : S_ISFIFO(st.st_mode) ? "a FIFO, not a regular file"
                            : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device, not a regular file"
                            : !S_ISREG(st.st_mode) ? "not a regular file"
                                                   : NULL;
    if (irregular) {
        close(fd);
        image_set_error(err, errlen, "cannot read '%s': %s", path, irregular);
        return -1;
    }
    int flags = fcntl(fd, F_GETFL);
    if (flags >= 0)
        (void)fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    return fd;
}

/* The size the header of the open file declares (image_header_size), read
 * through a descriptor of its own, the file's offset put back at its start
 * for the decoder. Returns 0, or -1 when the header cannot tell. */
static int declared_size(int fd, ImageFormat fmt, long *w, long *h)
{
    int copy = dup(fd);
    FILE *fp = copy >= 0 ? fdopen(copy, "rb") : NULL;
    if (fp == NULL) {
        if (copy >= 0)
            close(copy);
        return -1;
    }
    int rc = image_header_size(fp, fmt, w, h);
    fclose(fp);
    if (lseek(fd, 0, SEEK_SET) != 0)
        return -1;
    return rc;
}

int image_read_size(const char *path, int *width, int *height, char *err, int errlen)
{
    if (err != NULL && errlen > 0)
        err[0] = '\0';
    int fd = open_image(path, err, errlen);
    if (fd < 0)
        return -1;
    long w, h;
    ImageFormat fmt = sniff(fd, path);
    int rc = fmt != IMAGE_FORMAT_UNKNOWN && declared_size(fd, fmt, &w, &h) == 0;
    close(fd);
    if (!rc)
        return 1;
    *width = (int)w;
    *height = (int)h;
    return 0;
}

/* The memory budget held against the size the header declares: 0 when the
 * picture fits (or the header cannot tell: the decoder's own checks bound
 * it), -1 with the budget's message. */
static int within_budget(int fd, ImageFormat fmt, const char *path, const ImageReadExtras *ex, char *err,
                         int errlen)
{
    long w, h;
    if (ex == NULL || ex->max_bytes == 0 || declared_size(fd, fmt, &w, &h) != 0)
        return 0;
    double need = (double)w * (double)h * (double)(ex->bytes_per_pixel ? ex->bytes_per_pixel : 16);
    if (need <= (double)ex->max_bytes)
        return 0;
    char needs[32], left[32];
    memory_size_text(needs, sizeof needs, need >= (double)SIZE_MAX ? SIZE_MAX : (size_t)need);
    memory_size_text(left, sizeof left, ex->max_bytes);
    image_set_error(err, errlen,
                    "cannot read '%s': its %ldx%ld pixels would take %s, more than the %s left of the memory budget "
                    "(--max-memory sets it)",
                    path, w, h, needs, left);
    return -1;
}

int image_read(const char *path, Image *img, double display_gamma, char *err, int errlen)
{
    return image_read_ex(path, img, display_gamma, NULL, err, errlen);
}

int image_read_ex(const char *path, Image *img, double display_gamma, ImageReadExtras *ex, char *err, int errlen)
{
    char why[256];
    ImageFormat fmt;
    int fd, rc;

    if (err != NULL && errlen > 0)
        err[0] = '\0';
    if (img != NULL) {
        img->width = img->height = 0;
        img->rgba = NULL;
    }
    if (ex != NULL) {
        ex->premultiplied = !ex->keep_straight;
        ex->ncolours = 0;
        ex->index = NULL;
        ex->grey = 0;
        ex->sample_max = 255;
    }
    if (path == NULL || img == NULL) {
        image_set_error(err, errlen, "cannot read an image: no file name given");
        return -1;
    }
    fd = open_image(path, err, errlen);
    if (fd < 0)
        return -1;
    fmt = sniff(fd, path);
    if (fmt != IMAGE_FORMAT_UNKNOWN && within_budget(fd, fmt, path, ex, err, errlen)) {
        close(fd);
        return -1;
    }
    why[0] = '\0';
    if (ex != NULL)
        ex->format = fmt;
    /* POV-Ray's defaults (the PNG reader looks at its chunks itself) */
    if (display_gamma == IMAGE_GAMMA_AS_POVRAY && fmt != IMAGE_FORMAT_PNG) {
        if (ex != NULL && ex->untagged_given)
            display_gamma = ex->untagged_gamma;
        else
            display_gamma = fmt == IMAGE_FORMAT_PPM ? 1.0 : 0.0;
    }
    if (fmt == IMAGE_FORMAT_EXR) {
        rc = image_exr_read(fd, img, why, (int)sizeof why);
        close(fd);
        if (ex != NULL)
            ex->premultiplied = 1; /* as stored */
    } else if (fmt != IMAGE_FORMAT_UNKNOWN) {
        FILE *fp = fdopen(fd, "rb");
        if (fp == NULL) {
            image_set_error(err, errlen, "cannot read '%s': %s", path, strerror(errno));
            close(fd);
            return -1;
        }
        switch (fmt) {
        case IMAGE_FORMAT_PNG: rc = image_png_read(fp, img, display_gamma, ex, why, (int)sizeof why); break;
        case IMAGE_FORMAT_TGA: rc = image_tga_read(fp, img, display_gamma, ex, why, (int)sizeof why); break;
        case IMAGE_FORMAT_BMP: rc = image_bmp_read(fp, img, display_gamma, ex, why, (int)sizeof why); break;
        case IMAGE_FORMAT_JPEG: rc = image_jpeg_read(fp, img, display_gamma, why, (int)sizeof why); break;
        case IMAGE_FORMAT_HDR: rc = image_hdr_read(fp, img, why, (int)sizeof why); break;
        default: rc = image_ppm_read(fp, img, display_gamma, ex, why, (int)sizeof why); break;
        }
        fclose(fp);
    } else {
        close(fd);
        snprintf(why, sizeof why, "not an EXR, PNG, PPM, Targa, BMP, JPEG or HDR file");
        rc = -1;
    }
    if (rc != 0) {
        image_free(img);
        if (ex != NULL) {
            free(ex->index);
            ex->index = NULL;
            ex->ncolours = 0;
        }
        image_set_error(err, errlen, "cannot read '%s': %s", path, why[0] ? why : "unreadable image");
        return -1;
    }
    return 0;
}

int image_read_exr_channels(const char *path, const char *const *names, int n, float **planes, int *width,
                            int *height, char *err, int errlen)
{
    char why[256];
    int fd = open_image(path, err, errlen);
    if (fd < 0)
        return -1;
    why[0] = '\0';
    int rc = sniff(fd, path) == IMAGE_FORMAT_EXR
                 ? image_exr_read_planes(fd, names, n, planes, width, height, why, (int)sizeof why)
                 : (snprintf(why, sizeof why, "not an EXR file"), 1);
    close(fd);
    if (rc != 0)
        image_set_error(err, errlen, "cannot read '%s': %s", path, why[0] ? why : "unreadable image");
    return rc;
}

int image_read_exr_file(const char *path, ImageExrFile *f, int y0, int y1, char *err, int errlen)
{
    char why[256];
    memset(f, 0, sizeof *f);
    if (err != NULL && errlen > 0)
        err[0] = '\0';
    int fd = open_image(path, err, errlen);
    if (fd < 0)
        return -1;
    why[0] = '\0';
    int rc = sniff(fd, path) == IMAGE_FORMAT_EXR ? image_exr_read_file(fd, f, y0, y1, why, (int)sizeof why)
                                                 : (snprintf(why, sizeof why, "not an EXR file"), -1);
    close(fd);
    if (rc != 0)
        image_set_error(err, errlen, "cannot read '%s': %s", path, why[0] ? why : "unreadable image");
    return rc;
}

/* `gamma G` on a linear file (EXR, HDR): POV-Ray decodes its values as
 * stored with G too (SetEncodedRGBAValue's float form). */
static void decode_linear_override(Image *img, double gamma)
{
    ImageTransfer t;
    image_transfer_init(&t, gamma);
    size_t n = (size_t)img->width * (size_t)img->height;
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++)
            img->rgba[4 * i + k] = image_transfer_decode(&t, img->rgba[4 * i + k]);
}

int image_read_for_scene(void *user, const char *path, double decoding_gamma, double untagged_gamma,
                         int premultiplied, size_t max_bytes, LoadedPicture *out, char *err, int errlen)
{
    (void)user;
    Image img;
    ImageReadExtras ex;
    memset(&ex, 0, sizeof ex);
    ex.keep_straight = 1;
    ex.untagged_given = untagged_gamma != IMAGE_GAMMA_AS_POVRAY;
    ex.untagged_gamma = untagged_gamma;
    /* The pixels as read (16 bytes), the parser's copy of them (16), and a
     * colour-mapped picture's indices, read and copied (1 + 1). */
    ex.max_bytes = max_bytes;
    ex.bytes_per_pixel = 34;
    memset(out, 0, sizeof *out);
    if (image_read_ex(path, &img, decoding_gamma, &ex, err, errlen))
        return -1;
    const int linear_format = ex.format == IMAGE_FORMAT_EXR || ex.format == IMAGE_FORMAT_HDR;
    if (linear_format && decoding_gamma != IMAGE_GAMMA_AS_POVRAY && decoding_gamma != 1.0)
        decode_linear_override(&img, decoding_gamma);
    /* POV-Ray 3.7 reads a PPM or PGM with no gamma given as it stands, and
     * keeps it out of the working gamma's transcoding as well */
    out->as_stored = ex.format == IMAGE_FORMAT_PPM && decoding_gamma == IMAGE_GAMMA_AS_POVRAY && !ex.untagged_given;
    out->width = img.width;
    out->height = img.height;
    out->rgba = img.rgba; /* the parser frees it, and the index */
    /* POV-Ray's premultiplyOverride: the file's colours read the other way */
    out->premultiplied = premultiplied < 0 ? ex.premultiplied : premultiplied;
    out->ncolours = ex.ncolours;
    out->index = ex.index;
    out->grey = ex.grey;
    out->sample_max = ex.sample_max;
    for (int i = 0; i < ex.ncolours; i++)
        for (int c = 0; c < 4; c++)
            out->palette[i][c] = ex.palette[i][c];
    return 0;
}
