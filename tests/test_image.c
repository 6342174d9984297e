/* Image I/O: EXR/PNG/PPM round trips, POV-Ray's display encoding, atomic
 * writes, and resistance to truncated or garbage files. Temporary files go to
 * a fresh folder under $TMPDIR (else /tmp), removed at the end. With $POVRAY
 * set (configure exports it), POV-Ray's own PNG/PPM encoding is checked. */
#include <dirent.h>
#include <errno.h>
#include <float.h>
#include <math.h>
#include <openexr.h>
#include <png.h>
#include <zlib.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "image.h"
#include "image_codec.h"
#include "tap.h"

static char workdir[4096];

static const char *tmp_path(const char *name)
{
    static char buf[8][4200];
    static int next;
    char *p = buf[next++ % 8];
    snprintf(p, sizeof buf[0], "%s/%s", workdir, name);
    return p;
}

static int make_workdir(void)
{
    /* $TMPDIR, else /tmp; the build folder only as a last resort (it is the
     * source tree in an in-tree build). */
    const char *bases[3] = { getenv("TMPDIR"), "/tmp", getenv("top_builddir") };
    for (int i = 0; i < 3; i++) {
        if (bases[i] == NULL || bases[i][0] == '\0')
            continue;
        snprintf(workdir, sizeof workdir, "%s/hst-test-image-XXXXXX", bases[i]);
        if (mkdtemp(workdir) != NULL)
            return 0;
    }
    return -1;
}

static void remove_tree(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    char p[4400];
    if (d == NULL)
        return;
    while ((e = readdir(d)) != NULL) {
        struct stat st;
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
        if (lstat(p, &st) == 0 && S_ISDIR(st.st_mode))
            remove_tree(p);
        else
            unlink(p);
    }
    closedir(d);
    rmdir(dir);
}

/* Names in a folder other than . and .., for checking that no temporary
 * file was left behind. */
static int count_entries(const char *dir, int *hidden)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    int n = 0;
    *hidden = 0;
    if (d == NULL)
        return -1;
    while ((e = readdir(d)) != NULL) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        n++;
        if (e->d_name[0] == '.')
            (*hidden)++;
    }
    closedir(d);
    return n;
}

static unsigned char *slurp(const char *path, long *len)
{
    FILE *f = fopen(path, "rb");
    unsigned char *buf;
    long n;
    *len = -1;
    if (f == NULL)
        return NULL;
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = malloc(n > 0 ? (size_t)n : 1);
    if (buf != NULL && fread(buf, 1, (size_t)n, f) != (size_t)n) {
        free(buf);
        buf = NULL;
    }
    fclose(f);
    if (buf != NULL)
        *len = n;
    return buf;
}

static int spit(const char *path, const void *data, long len)
{
    FILE *f = fopen(path, "wb");
    int ok;
    if (f == NULL)
        return -1;
    ok = fwrite(data, 1, (size_t)len, f) == (size_t)len;
    return fclose(f) == 0 && ok ? 0 : -1;
}

/* A test picture: smooth ramps, values above 1, tiny values, distinct
 * channels, premultiplied alpha (colour <= alpha except a few highlights). */
static void fill_test_image(Image *img, int with_alpha)
{
    for (int y = 0; y < img->height; y++) {
        for (int x = 0; x < img->width; x++) {
            float *p = img->rgba + ((size_t)y * img->width + x) * 4;
            float u = (float)x / (float)(img->width - 1), v = (float)y / (float)(img->height - 1);
            float a = with_alpha ? 0.25f + 0.75f * v : 1.0f;
            p[0] = u * a;
            p[1] = (1.0f - u) * 0.5f * a;
            p[2] = (x % 7 == 0 ? 1e-4f * (float)(y + 1) : u * v * 0.9f) * a;
            p[3] = a;
            if (x == img->width - 1 && y % 3 == 0)
                p[0] = 2.5f; /* a highlight above 1 */
        }
    }
}

/* ---- format detection and buffers ------------------------------------- */

static void test_basics(void)
{
    Image img;
    tap_ok(image_format_from_path("a.exr") == IMAGE_FORMAT_EXR, "format: .exr");
    tap_ok(image_format_from_path("dir.png/b.EXR") == IMAGE_FORMAT_EXR, "format: .EXR, case-insensitive");
    tap_ok(image_format_from_path("x/y.Png") == IMAGE_FORMAT_PNG, "format: .Png");
    tap_ok(image_format_from_path("out.ppm") == IMAGE_FORMAT_PPM, "format: .ppm");
    tap_ok(image_format_from_path("out.tga") == IMAGE_FORMAT_TGA, "format: .tga");
    tap_ok(image_format_from_path("out.BMP") == IMAGE_FORMAT_BMP, "format: .BMP");
    tap_ok(image_format_from_path("out.jpg") == IMAGE_FORMAT_JPEG && image_format_from_path("a.jpeg") == IMAGE_FORMAT_JPEG,
           "format: .jpg and .jpeg");
    tap_ok(image_format_from_path("out.hdr") == IMAGE_FORMAT_HDR, "format: .hdr");
    tap_ok(image_format_from_path("out.gif") == IMAGE_FORMAT_UNKNOWN, "format: .gif unknown");
    tap_ok(image_format_from_path("dir.png/noext") == IMAGE_FORMAT_UNKNOWN, "format: dot only in folder name");
    tap_ok(image_format_from_path("png") == IMAGE_FORMAT_UNKNOWN, "format: no extension");

    tap_ok(image_alloc(&img, 3, 2) == 0 && img.width == 3 && img.height == 2 && img.rgba != NULL &&
               img.rgba[23] == 0.0f,
           "image_alloc gives a zeroed 3x2 buffer");
    image_free(&img);
    tap_ok(img.rgba == NULL && img.width == 0, "image_free clears the image");
    image_free(&img); /* twice is harmless */
    tap_ok(image_alloc(&img, 0, 5) != 0 && img.rgba == NULL, "image_alloc refuses a zero width");
    tap_ok(image_alloc(&img, -3, 5) != 0, "image_alloc refuses a negative width");
    tap_ok(image_alloc(&img, 1 << 20, 1 << 20) != 0, "image_alloc refuses absurd sizes");
}

/* ---- the display encoding ------------------------------------------------ */

static double srgb_formula(double x)
{
    return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

static void test_encoding(void)
{
    ImageTransfer srgb, g22, g1;
    int worst = 0, code_mismatch = 0, inverse_bad = 0;
    double maxerr = 0;

    image_transfer_init(&srgb, 0.0);
    image_transfer_init(&g22, 2.2);
    image_transfer_init(&g1, 1.0);
    tap_ok(srgb.srgb && !g22.srgb && g1.neutral, "display_gamma 0 is sRGB, 2.2 a power law, 1.0 neutral");

    tap_ok(image_transfer_encode(&srgb, 0.0f) == 0.0f, "sRGB encode(0) = 0");
    tap_ok(fabs(image_transfer_encode(&srgb, 1.0f) - 1.0) < 1e-6, "sRGB encode(1) = 1");
    tap_ok(fabs(image_transfer_encode(&srgb, 0.0031308f) - 0.0404500) < 1e-6, "sRGB encode at the knee = 0.04045");
    tap_ok(fabs(image_transfer_encode(&srgb, 0.5f) - 0.7353569831) < 2e-6, "sRGB encode(0.5) = 0.735357");
    tap_ok(fabs(image_transfer_encode(&srgb, 0.18f) - 0.4613561) < 2e-6, "sRGB encode(0.18) = 0.461356");
    tap_ok(fabs(image_transfer_encode(&srgb, 0.001f) - 0.01292) < 1e-7, "sRGB encode(0.001) = 0.01292 (linear part)");
    tap_ok(image_quantize(image_transfer_encode(&srgb, 0.5f), 255) == 188, "0.5 encodes to 188");
    tap_ok(image_quantize(image_transfer_encode(&srgb, 0.18f), 255) == 118, "0.18 encodes to 118");
    tap_ok(image_quantize(image_transfer_encode(&srgb, 0.5f), 65535) == 48192, "0.5 encodes to 48192 in 16 bits");
    tap_ok(image_quantize(-0.5f, 255) == 0 && image_quantize(7.0f, 255) == 255 && image_quantize(NAN, 255) == 0 &&
               image_quantize(INFINITY, 255) == 255 && image_quantize(-INFINITY, 65535) == 0,
           "quantize clamps negative, large, infinite and NaN values");
    tap_ok(image_quantize(0.5f, 1) == 1 && image_quantize(0.49f, 1) == 0 && image_quantize(0.5f, 255) == 128,
           "quantize rounds half up (floor(x*max+0.5))");

    for (int i = 0; i <= 100000; i++) {
        double x = i / 100000.0;
        double e = fabs(image_transfer_encode(&srgb, (float)x) - srgb_formula(x));
        unsigned q = image_quantize(image_transfer_encode(&srgb, (float)x), 255);
        unsigned qd = (unsigned)floor(srgb_formula(x) * 255.0 + 0.5);
        if (e > maxerr)
            maxerr = e;
        if (q != qd) {
            code_mismatch++;
            if ((int)abs((int)q - (int)qd) > worst)
                worst = abs((int)q - (int)qd);
        }
    }
    tap_ok(maxerr < 1e-6, "sRGB encoder follows the formula over 0..1 (max error %.2g)", maxerr);
    tap_diag("8-bit codes differing from the double-precision formula: %d of 100001 (rounding ties only)",
             code_mismatch);
    tap_ok(worst <= 1 && code_mismatch < 50, "8-bit codes equal the formula's except at rounding ties");

    for (unsigned i = 0; i <= 255; i++) {
        float lin = image_transfer_decode(&srgb, (float)i / 255.0f);
        if (image_quantize(image_transfer_encode(&srgb, lin), 255) != i)
            inverse_bad++;
    }
    tap_ok(inverse_bad == 0, "sRGB decode inverts encode for every 8-bit code");

    tap_ok(fabs(image_transfer_encode(&g22, 0.5f) - pow(0.5, 1 / 2.2)) < 1e-6, "gamma 2.2 encode(0.5) = 0.5^(1/2.2)");
    tap_ok(fabs(image_transfer_decode(&g22, 0.5f) - pow(0.5, 2.2)) < 1e-6, "gamma 2.2 decode(0.5) = 0.5^2.2");
    tap_ok(image_transfer_encode(&g22, -1.0f) == 0.0f, "gamma 2.2 encodes negatives as 0");
    tap_ok(image_transfer_encode(&g1, 0.3f) == 0.3f, "gamma 1.0 is the identity");
    tap_ok(fabs(srgb.gama - 0.45455) < 1e-5 && fabs(g22.gama - 1 / 2.2) < 1e-6 && g1.gama == 1.0,
           "PNG gAMA values: 1/2.2 for sRGB and 2.2, 1 for 1.0");

    {
        /* POV-Ray's un-premultiplication for files with alpha */
        ImageTransfer t = srgb;
        unsigned q[4];
        const float half_red[4] = { 0.25f, 0.0f, 0.0f, 0.5f };
        const float bright[4] = { 1.8f, 1.8f, 1.8f, 0.9f };
        const float clear[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
        image_encode_pixel(&t, half_red, 255, 1, q);
        tap_ok(q[0] == 188 && q[1] == 0 && q[2] == 0 && q[3] == 128, "RGBA: premultiplied 0.25/0.5 becomes 0.5 straight");
        image_encode_pixel(&t, bright, 255, 1, q);
        tap_ok(q[3] == 255 && q[0] == 255, "RGBA: a highlight brighter than alpha raises alpha to 1");
        image_encode_pixel(&t, clear, 255, 1, q);
        tap_ok(q[0] == 0 && q[3] == 0, "RGBA: fully transparent black stays 0,0,0,0");
        image_encode_pixel(&t, half_red, 255, 0, q);
        tap_ok(q[0] == 137 && q[1] == 0, "RGB: premultiplied colour is written as is (over black)");
    }
}

/* ---- EXR ------------------------------------------------------------------- */

static int same_float(float a, float b)
{
    return a == b || (isnan(a) && isnan(b));
}

static int near_half(float got, float want)
{
    /* half has 11 significant bits: error at most 2^-11 relative after
     * round to nearest, 2^-25 absolute for subnormals */
    return fabsf(got - want) <= fabsf(want) * (1.0f / 2048.0f) + 6.0e-8f;
}

static void test_exr(void)
{
    Image src, back;
    ImageWriteOptions opt = { 0 };
    char err[512];
    const char *p = tmp_path("round.exr");
    int bad = 0;

    image_alloc(&src, 61, 37); /* odd sizes: partial 16-line blocks */
    fill_test_image(&src, 1);
    src.rgba[0] = -0.75f;      /* negatives survive EXR */
    src.rgba[5] = 65504.0f;    /* largest half */
    src.rgba[10] = 1.0e-7f;    /* half subnormal */
    src.rgba[4 * 100 + 3] = 0.0f;

    opt.exr_float = 1;
    tap_ok(image_write(p, &src, &opt, err, sizeof err) == 0, "EXR float written (%s)", err);
    tap_ok(image_read(p, &back, 0, err, sizeof err) == 0 && back.width == 61 && back.height == 37,
           "EXR float read back (%s)", err);
    for (size_t i = 0; back.rgba && i < (size_t)61 * 37 * 4; i++)
        bad += !same_float(back.rgba[i], src.rgba[i]);
    tap_ok(back.rgba && bad == 0, "EXR float round trip is exact (%d differences)", bad);
    image_free(&back);

    /* the header as the brief wants it, read through the C API */
    {
        exr_context_t ctx;
        exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
        const exr_attr_chlist_t *ch = NULL;
        exr_compression_t comp = EXR_COMPRESSION_LAST_TYPE;
        exr_attr_box2i_t dw, dsp;
        exr_storage_t st;
        int ok = exr_start_read(&ctx, p, &init) == EXR_ERR_SUCCESS;
        ok = ok && exr_get_channels(ctx, 0, &ch) == EXR_ERR_SUCCESS && ch->num_channels == 4;
        ok = ok && strcmp(ch->entries[0].name.str, "A") == 0 && strcmp(ch->entries[1].name.str, "B") == 0 &&
             strcmp(ch->entries[2].name.str, "G") == 0 && strcmp(ch->entries[3].name.str, "R") == 0;
        ok = ok && ch->entries[0].pixel_type == EXR_PIXEL_FLOAT;
        ok = ok && exr_get_compression(ctx, 0, &comp) == EXR_ERR_SUCCESS && comp == EXR_COMPRESSION_ZIP;
        ok = ok && exr_get_storage(ctx, 0, &st) == EXR_ERR_SUCCESS && st == EXR_STORAGE_SCANLINE;
        ok = ok && exr_get_data_window(ctx, 0, &dw) == EXR_ERR_SUCCESS &&
             exr_get_display_window(ctx, 0, &dsp) == EXR_ERR_SUCCESS;
        ok = ok && dw.min.x == 0 && dw.min.y == 0 && dw.max.x == 60 && dw.max.y == 36 && dsp.min.x == 0 &&
             dsp.max.x == 60 && dsp.max.y == 36;
        exr_finish(&ctx);
        tap_ok(ok, "EXR header: scanline, ZIP, channels A,B,G,R float, data window = display window = 0..60,0..36");
    }

    opt.exr_float = 0;
    tap_ok(image_write(p, &src, &opt, err, sizeof err) == 0, "EXR half written over the float one (%s)", err);
    bad = 0;
    tap_ok(image_read(p, &back, 0, err, sizeof err) == 0, "EXR half read back (%s)", err);
    for (size_t i = 0; back.rgba && i < (size_t)61 * 37 * 4; i++)
        bad += !near_half(back.rgba[i], src.rgba[i]);
    tap_ok(back.rgba && bad == 0, "EXR half round trip within half precision (%d outside)", bad);
    tap_ok(back.rgba && back.rgba[5] == 65504.0f && back.rgba[0] == -0.75f && back.rgba[4 * 100 + 3] == 0.0f,
           "EXR half keeps exact halves (65504, -0.75, 0)");
    image_free(&back);

    {
        static const struct {
            ImageExrCompression c;
            const char *name;
        } comps[] = { { IMAGE_EXR_NONE, "none" }, { IMAGE_EXR_RLE, "RLE" }, { IMAGE_EXR_ZIPS, "ZIPS" },
                      { IMAGE_EXR_ZIP, "ZIP" }, { IMAGE_EXR_PIZ, "PIZ" } };
        for (size_t k = 0; k < sizeof comps / sizeof comps[0]; k++) {
            for (int fl = 0; fl <= 1; fl++) {
                opt.exr_compression = comps[k].c;
                opt.exr_float = fl;
                bad = -1;
                if (image_write(p, &src, &opt, err, sizeof err) == 0 && image_read(p, &back, 0, err, sizeof err) == 0) {
                    bad = 0;
                    for (size_t i = 0; i < (size_t)61 * 37 * 4; i++)
                        bad += fl ? !same_float(back.rgba[i], src.rgba[i]) : !near_half(back.rgba[i], src.rgba[i]);
                    image_free(&back);
                }
                tap_ok(bad == 0, "EXR %s %s compression round trip (%s)", fl ? "float" : "half", comps[k].name,
                       bad < 0 ? err : "ok");
            }
        }
        opt.exr_compression = IMAGE_EXR_ZIP;
        opt.exr_float = 0;
    }
    image_free(&src);
}

/* Whether image src written by opt on 1 thread (to `one`) and on 3 (to
 * `three`) makes the same file, byte for byte; 0 also when either write
 * fails (its message in err). */
static int written_alike(const Image *src, ImageWriteOptions opt, const char *one, const char *three, char *err,
                         int errlen)
{
    long n1 = -1, n3 = -2;
    unsigned char *a = NULL, *b = NULL;
    opt.threads = 1;
    if (image_write(one, src, &opt, err, errlen) == 0) {
        opt.threads = 3;
        if (image_write(three, src, &opt, err, errlen) == 0) {
            a = slurp(one, &n1);
            b = slurp(three, &n3);
        }
    }
    int alike = a && b && n1 == n3 && memcmp(a, b, (size_t)n1) == 0;
    free(a);
    free(b);
    return alike;
}

/* An EXR is the same file whatever number of threads encodes its chunks
 * (each compressed on its own, all written in order): written on 1 and on
 * 3 threads, for every compression and both sample types, the two files
 * are equal byte for byte and read back as written. 400 lines make 25
 * chunks of 16 lines (ZIP), 13 of 32 (PIZ), 400 of one (none, RLE, ZIPS):
 * several per thread. */
static void test_exr_threads(void)
{
    static const ImageExrCompression comps[] = { IMAGE_EXR_NONE, IMAGE_EXR_RLE, IMAGE_EXR_ZIPS, IMAGE_EXR_ZIP,
                                                 IMAGE_EXR_PIZ };
    Image src, back;
    char err[512];
    const char *one = tmp_path("one-thread.exr"), *three = tmp_path("three-threads.exr");
    int differ = 0, unread = 0, tried = 0;
    image_alloc(&src, 67, 400);
    fill_test_image(&src, 1);
    for (size_t k = 0; k < sizeof comps / sizeof comps[0]; k++)
        for (int fl = 0; fl <= 1; fl++) {
            ImageWriteOptions opt = { 0 };
            opt.exr_compression = comps[k];
            opt.exr_float = fl;
            tried++;
            differ += !written_alike(&src, opt, one, three, err, (int)sizeof err);
            int bad = -1;
            if (image_read(three, &back, 0, err, sizeof err) == 0) {
                bad = 0;
                for (size_t i = 0; i < (size_t)67 * 400 * 4; i++)
                    bad += fl ? !same_float(back.rgba[i], src.rgba[i]) : !near_half(back.rgba[i], src.rgba[i]);
                image_free(&back);
            }
            unread += bad != 0;
        }
    tap_ok(differ == 0, "EXR: the file written on 3 threads equals the one written on 1, byte for byte, for each "
                        "compression, half and float (%d of %d differ)", differ, tried);
    tap_ok(unread == 0, "EXR: the files written on 3 threads read back as written (%d of %d not)", unread, tried);
    image_free(&src);
}

/* A tiled RGB half EXR written with the C API: 16x16 tiles over 37x21
 * (partial edge tiles), decreasing compression choice by argument. */
static int write_tiled_rgb(const char *path, const Image *img, exr_compression_t comp)
{
    static const char *const names[3] = { "B", "G", "R" };
    static const int slot[3] = { 2, 1, 0 };
    exr_context_t ctx;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    exr_encode_pipeline_t enc;
    int part, started = 0, ok;
    const int T = 16, cx = (img->width + T - 1) / T, cy = (img->height + T - 1) / T;

    memset(&enc, 0, sizeof enc);
    ok = exr_start_write(&ctx, path, EXR_WRITE_FILE_DIRECTLY, &init) == EXR_ERR_SUCCESS;
    ok = ok && exr_add_part(ctx, "", EXR_STORAGE_TILED, &part) == EXR_ERR_SUCCESS;
    ok = ok && exr_initialize_required_attr_simple(ctx, part, img->width, img->height, comp) == EXR_ERR_SUCCESS;
    ok = ok && exr_set_tile_descriptor(ctx, part, T, T, EXR_TILE_ONE_LEVEL, EXR_TILE_ROUND_DOWN) == EXR_ERR_SUCCESS;
    for (int c = 0; c < 3 && ok; c++)
        ok = exr_add_channel(ctx, part, names[c], EXR_PIXEL_HALF, EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1) ==
             EXR_ERR_SUCCESS;
    ok = ok && exr_write_header(ctx) == EXR_ERR_SUCCESS;
    for (int ty = 0; ty < cy && ok; ty++) {
        for (int tx = 0; tx < cx && ok; tx++) {
            exr_chunk_info_t ci;
            ok = exr_write_tile_chunk_info(ctx, part, tx, ty, 0, 0, &ci) == EXR_ERR_SUCCESS;
            if (ok && !started)
                ok = started = exr_encoding_initialize(ctx, part, &ci, &enc) == EXR_ERR_SUCCESS;
            else if (ok)
                ok = exr_encoding_update(ctx, part, &ci, &enc) == EXR_ERR_SUCCESS;
            for (int c = 0; ok && c < enc.channel_count; c++) {
                int k = 0;
                while (strcmp(enc.channels[c].channel_name, names[k]) != 0)
                    k++;
                enc.channels[c].user_data_type = EXR_PIXEL_FLOAT;
                enc.channels[c].user_bytes_per_element = 4;
                enc.channels[c].user_pixel_stride = 16;
                enc.channels[c].user_line_stride = img->width * 16;
                enc.channels[c].encode_from_ptr =
                    (const uint8_t *)(img->rgba + ((size_t)ty * T * img->width + (size_t)tx * T) * 4 + slot[k]);
            }
            if (ok && tx == 0 && ty == 0)
                ok = exr_encoding_choose_default_routines(ctx, part, &enc) == EXR_ERR_SUCCESS;
            ok = ok && exr_encoding_run(ctx, part, &enc) == EXR_ERR_SUCCESS;
        }
    }
    if (started)
        exr_encoding_destroy(ctx, &enc);
    return exr_finish(&ctx) == EXR_ERR_SUCCESS && ok ? 0 : -1;
}

static void test_exr_tiled(void)
{
    static const struct {
        exr_compression_t c;
        const char *name;
    } comps[] = { { EXR_COMPRESSION_ZIP, "ZIP" }, { EXR_COMPRESSION_PIZ, "PIZ" }, { EXR_COMPRESSION_RLE, "RLE" },
                  { EXR_COMPRESSION_NONE, "none" } };
    Image src, back;
    char err[512];
    const char *p = tmp_path("tiled.exr");

    image_alloc(&src, 37, 21);
    fill_test_image(&src, 0);
    for (size_t k = 0; k < sizeof comps / sizeof comps[0]; k++) {
        int bad = -1;
        if (write_tiled_rgb(p, &src, comps[k].c) == 0 && image_read(p, &back, 0, err, sizeof err) == 0) {
            bad = back.width == 37 && back.height == 21 ? 0 : 1;
            for (size_t i = 0; !bad && i < (size_t)37 * 21; i++) {
                bad += !near_half(back.rgba[4 * i], src.rgba[4 * i]) ||
                       !near_half(back.rgba[4 * i + 1], src.rgba[4 * i + 1]) ||
                       !near_half(back.rgba[4 * i + 2], src.rgba[4 * i + 2]) || back.rgba[4 * i + 3] != 1.0f;
            }
            image_free(&back);
        }
        tap_ok(bad == 0, "tiled RGB (no A) %s EXR reads back, alpha 1", comps[k].name);
    }
    image_free(&src);
}

/* ---- PNG ------------------------------------------------------------------- */

/* Compares decoded samples in the encoded domain: within `steps` codes of
 * the original. Colours are compared un-premultiplied. */
static int png_ppm_mismatches(const Image *a, const Image *b, double gamma, unsigned max, int with_alpha, float steps)
{
    ImageTransfer t;
    int bad = 0;
    image_transfer_init(&t, gamma);
    for (size_t i = 0; i < (size_t)a->width * a->height; i++) {
        const float *pa = a->rgba + 4 * i, *pb = b->rgba + 4 * i;
        unsigned qa[4], qb[4];
        image_encode_pixel(&t, pa, max, with_alpha, qa);
        image_encode_pixel(&t, pb, max, with_alpha, qb);
        for (int c = 0; c < (with_alpha ? 4 : 3); c++)
            if (fabsf((float)qa[c] - (float)qb[c]) > steps)
                bad++;
        if (!with_alpha && pb[3] != 1.0f)
            bad++;
    }
    return bad;
}

static int png_chunks(const char *path, int *depth, int *ctype, int *has_srgb, unsigned long *gama)
{
    FILE *f = fopen(path, "rb");
    png_structp png;
    png_infop info;
    png_fixed_point g = 0;
    int intent;
    if (f == NULL)
        return -1;
    png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, NULL);
        fclose(f);
        return -1;
    }
    png_init_io(png, f);
    png_read_info(png, info);
    *depth = png_get_bit_depth(png, info);
    *ctype = png_get_color_type(png, info);
    *has_srgb = png_get_sRGB(png, info, &intent) != 0;
    *gama = png_get_gAMA_fixed(png, info, &g) ? (unsigned long)g : 0;
    png_destroy_read_struct(&png, &info, NULL);
    fclose(f);
    return 0;
}

static void test_png(void)
{
    Image src, back;
    ImageWriteOptions opt = { 0 };
    char err[512];
    const char *p = tmp_path("round.png");

    image_alloc(&src, 67, 29);
    fill_test_image(&src, 0);
    for (int bits16 = 0; bits16 <= 1; bits16++) {
        for (int alpha = 0; alpha <= 1; alpha++) {
            int depth = 0, ctype = 0, srgb = 0, bad = -1;
            unsigned long gama = 0;
            Image *s = &src, withalpha;
            if (alpha) {
                image_alloc(&withalpha, 67, 29);
                fill_test_image(&withalpha, 1);
                s = &withalpha;
            }
            opt.png_16bit = bits16;
            opt.write_alpha = alpha;
            opt.display_gamma = 0.0;
            if (image_write(p, s, &opt, err, sizeof err) == 0 && image_read(p, &back, 0.0, err, sizeof err) == 0) {
                bad = png_ppm_mismatches(s, &back, 0.0, bits16 ? 65535 : 255, alpha, bits16 ? 1.0f : 1.0f);
                image_free(&back);
            }
            tap_ok(bad == 0, "PNG %d-bit %s round trip within one step (%s)", bits16 ? 16 : 8, alpha ? "RGBA" : "RGB",
                   bad < 0 ? err : "ok");
            png_chunks(p, &depth, &ctype, &srgb, &gama);
            tap_ok(depth == (bits16 ? 16 : 8) && ctype == (alpha ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB) &&
                       srgb && gama == 45455,
                   "PNG %d-bit %s: IHDR layout, sRGB chunk and gAMA 45455", bits16 ? 16 : 8, alpha ? "RGBA" : "RGB");
            if (alpha)
                image_free(&withalpha);
        }
    }

    /* a power-law gamma: gAMA 1/2.2, no sRGB chunk, decoded by the same law */
    {
        int depth = 0, ctype = 0, srgb = 1, bad = -1;
        unsigned long gama = 0;
        opt.png_16bit = 0;
        opt.write_alpha = 0;
        opt.display_gamma = 2.2;
        if (image_write(p, &src, &opt, err, sizeof err) == 0 && image_read(p, &back, 2.2, err, sizeof err) == 0) {
            bad = png_ppm_mismatches(&src, &back, 2.2, 255, 0, 1.0f);
            image_free(&back);
        }
        tap_ok(bad == 0, "PNG gamma 2.2 round trip within one step");
        png_chunks(p, &depth, &ctype, &srgb, &gama);
        tap_ok(!srgb && gama == 45455, "PNG gamma 2.2: gAMA 45455 and no sRGB chunk");
    }

    /* exact values: codes 0..255 decode to the sRGB curve */
    {
        Image ramp;
        ImageTransfer t;
        int bad = 0;
        image_transfer_init(&t, 0.0);
        image_alloc(&ramp, 256, 1);
        for (int i = 0; i < 256; i++) {
            ramp.rgba[4 * i] = ramp.rgba[4 * i + 1] = ramp.rgba[4 * i + 2] = image_transfer_decode(&t, i / 255.0f);
            ramp.rgba[4 * i + 3] = 1.0f;
        }
        memset(&opt, 0, sizeof opt);
        if (image_write(p, &ramp, &opt, err, sizeof err) == 0 && image_read(p, &back, 0.0, err, sizeof err) == 0) {
            for (int i = 0; i < 256; i++)
                bad += back.rgba[4 * i] != ramp.rgba[4 * i];
            image_free(&back);
        } else {
            bad = -1;
        }
        tap_ok(bad == 0, "PNG: every 8-bit code survives write and read exactly");
        image_free(&ramp);
    }
    image_free(&src);
}

/* ---- PPM ------------------------------------------------------------------- */

/* The filter type of every row of a PNG (its IDAT chunks inflated): how
 * many rows use each of the five; -1 when the file cannot be taken apart. */
static int png_row_filters(const char *path, int width, int bytes_per_pixel, long count[5])
{
    long len = 0;
    unsigned char *d = slurp(path, &len), *z = NULL;
    size_t zlen = 0;
    for (long i = 8; d && i + 12 <= len;) {
        unsigned long n = (unsigned long)d[i] << 24 | (unsigned long)d[i + 1] << 16 | (unsigned long)d[i + 2] << 8 | d[i + 3];
        if (memcmp(d + i + 4, "IDAT", 4) == 0) {
            unsigned char *grown = realloc(z, zlen + n);
            if (!grown)
                break;
            z = grown;
            memcpy(z + zlen, d + i + 8, n);
            zlen += n;
        }
        i += 12 + (long)n;
    }
    size_t stride = 1 + (size_t)width * (size_t)bytes_per_pixel, cap = stride * 4096;
    unsigned char *raw = malloc(cap);
    uLongf rawlen = (uLongf)cap;
    int rc = z && raw && uncompress(raw, &rawlen, z, (uLong)zlen) == Z_OK && rawlen % stride == 0 ? 0 : -1;
    for (int k = 0; k < 5; k++)
        count[k] = 0;
    for (size_t r = 0; rc == 0 && r < rawlen / stride; r++) {
        if (raw[r * stride] > 4)
            rc = -1;
        else
            count[raw[r * stride]]++;
    }
    free(raw);
    free(z);
    free(d);
    return rc;
}

/* A PNG is the same file whatever number of threads compresses its bands
 * of rows, and its rows decode as encoded whichever of the five filters
 * each took: a picture of 300 rows (10 bands) whose parts make each filter
 * win somewhere (flat rows, rows repeating the one above, horizontal
 * ramps, smooth two-way gradients, noise), written on 1 and on 3 threads,
 * 8 and 16 bits, RGB and RGBA. */
static void test_png_threads(void)
{
    const char *one = tmp_path("one-thread.png"), *three = tmp_path("three-threads.png");
    Image src, back;
    char err[512];
    int differ = 0, wrong = 0, tried = 0, every_filter = 1;
    unsigned seed = 12345;
    image_alloc(&src, 83, 300);
    for (int y = 0; y < src.height; y++)
        for (int x = 0; x < src.width; x++) {
            float *p = src.rgba + ((size_t)y * src.width + x) * 4;
            int part = y / 60;
            for (int c = 0; c < 3; c++) {
                seed = seed * 1103515245u + 12345u;
                float noise = (float)(seed >> 8 & 0xffff) / 65535.0f;
                p[c] = part == 0   ? 0.2f * (float)(c + 1)                           /* flat */
                       : part == 1 ? (float)((x * 7 + c * 5) % 17) / 17.0f           /* columns repeating down */
                       : part == 2 ? (float)x / 83.0f * (0.3f + 0.2f * (float)c)     /* ramps across */
                       : part == 3 ? ((float)x * (float)y) / (83.0f * 300.0f)        /* smooth both ways */
                                   : noise;                                          /* noise */
            }
            p[3] = 0.5f + 0.5f * (float)((x + y) % 5) / 4.0f;
        }
    for (int bits16 = 0; bits16 <= 1; bits16++)
        for (int alpha = 0; alpha <= 1; alpha++) {
            ImageWriteOptions opt = { 0 };
            opt.png_16bit = bits16;
            opt.write_alpha = alpha;
            tried++;
            differ += !written_alike(&src, opt, one, three, err, (int)sizeof err);
            int bad = -1;
            if (image_read(three, &back, 0.0, err, sizeof err) == 0) {
                bad = png_ppm_mismatches(&src, &back, 0.0, bits16 ? 65535 : 255, alpha, 1.0f);
                image_free(&back);
            }
            wrong += bad != 0;
            long count[5];
            int ok = png_row_filters(three, src.width, (alpha ? 4 : 3) * (bits16 ? 2 : 1), count) == 0;
            for (int k = 0; k < 5; k++)
                ok = ok && count[k] > 0;
            if (!ok)
                tap_diag("PNG %d-bit %s rows by filter: %ld none, %ld sub, %ld up, %ld average, %ld Paeth",
                         bits16 ? 16 : 8, alpha ? "RGBA" : "RGB", count[0], count[1], count[2], count[3], count[4]);
            every_filter &= ok;
        }
    tap_ok(differ == 0, "PNG: the file written on 3 threads equals the one written on 1, byte for byte (%d of %d "
                        "differ)", differ, tried);
    tap_ok(wrong == 0, "PNG: 10 bands of rows compressed apart decode within one step, 8 and 16 bits, RGB and RGBA "
                       "(%d of %d not)", wrong, tried);
    tap_ok(every_filter, "PNG: each of the five filters chosen for some row, in each of the 4 files");
    image_free(&src);
}

static void test_ppm(void)
{
    Image src, back;
    ImageWriteOptions opt = { 0 };
    char err[512];
    const char *p = tmp_path("round.ppm");
    unsigned char *data;
    long len;
    int bad = -1;

    image_alloc(&src, 45, 33);
    fill_test_image(&src, 0);
    if (image_write(p, &src, &opt, err, sizeof err) == 0 && image_read(p, &back, 0.0, err, sizeof err) == 0) {
        bad = png_ppm_mismatches(&src, &back, 0.0, 255, 0, 1.0f);
        image_free(&back);
    }
    tap_ok(bad == 0, "PPM round trip within one 8-bit step (%s)", bad < 0 ? err : "ok");
    data = slurp(p, &len);
    tap_ok(data != NULL && len == 13 + 45 * 33 * 3 && memcmp(data, "P6\n45 33\n255\n", 13) == 0,
           "PPM is binary P6 with maxval 255");
    /* same bytes as the PNG encoder: compare with a direct encoding */
    if (data != NULL) {
        ImageTransfer t;
        int diff = 0;
        image_transfer_init(&t, 0.0);
        for (int i = 0; i < 45 * 33; i++) {
            unsigned q[4];
            image_encode_pixel(&t, src.rgba + 4 * i, 255, 0, q);
            for (int c = 0; c < 3; c++)
                diff += data[13 + 3 * i + c] != q[c];
        }
        tap_ok(diff == 0, "PPM bytes are the display encoding of the pixels");
    }
    free(data);

    {
        const char *txt = "P3\n# a comment\n2 1\n# another\n255\n255 0 0   0 128 255\n";
        const char *p3 = tmp_path("ascii.ppm");
        spit(p3, txt, (long)strlen(txt));
        tap_ok(image_read(p3, &back, 0.0, err, sizeof err) == 0 && back.width == 2 && back.rgba[0] == 1.0f &&
                   back.rgba[1] == 0.0f && back.rgba[6] == 1.0f && fabsf(back.rgba[5] - 0.2158605f) < 1e-5f &&
                   back.rgba[3] == 1.0f,
               "PPM P3 with comments reads (%s)", err);
        image_free(&back);
    }
    {
        const unsigned char bin[] = { 'P', '6', '\n', '1', ' ', '1', '\n', '6', '5', '5', '3', '5', '\n',
                                      0xff, 0xff, 0x80, 0x00, 0x00, 0x00 };
        const char *p16 = tmp_path("wide.ppm");
        ImageTransfer t;
        image_transfer_init(&t, 0.0);
        spit(p16, bin, sizeof bin);
        tap_ok(image_read(p16, &back, 0.0, err, sizeof err) == 0 && back.rgba[0] == 1.0f &&
                   fabsf(back.rgba[1] - image_transfer_decode(&t, 32768.0f / 65535.0f)) < 1e-6f && back.rgba[2] == 0.0f,
               "PPM P6 with maxval 65535 reads two bytes a sample (%s)", err);
        image_free(&back);
    }
    image_free(&src);
}

/* ---- Targa, BMP, JPEG, HDR ---------------------------------------------------- */

/* A write and a read through the file `name`; the mismatching samples of the
 * display encoding (png_ppm_mismatches), or -1 with err when either failed. */
static int round_trip(const char *name, const Image *src, const ImageWriteOptions *opt, int with_alpha, float steps,
                      char *err, int errlen)
{
    Image back;
    int bad = -1;
    const char *p = tmp_path(name);
    if (image_write(p, src, opt, err, errlen) == 0 && image_read(p, &back, 0.0, err, errlen) == 0) {
        bad = back.width == src->width && back.height == src->height
                  ? png_ppm_mismatches(src, &back, 0.0, 255, with_alpha, steps)
                  : src->width * src->height;
        image_free(&back);
    }
    return bad;
}

static void test_other_types(void)
{
    Image src, withalpha, back;
    ImageWriteOptions opt = { 0 };
    char err[512] = "";
    int bad;

    image_alloc(&src, 67, 29);
    fill_test_image(&src, 0);
    image_alloc(&withalpha, 67, 29);
    fill_test_image(&withalpha, 1);
    for (int rle = 0; rle <= 1; rle++)
        for (int alpha = 0; alpha <= 1; alpha++) {
            opt.tga_rle = rle;
            opt.write_alpha = alpha;
            bad = round_trip("round.tga", alpha ? &withalpha : &src, &opt, alpha, 0.0f, err, sizeof err);
            tap_ok(bad == 0, "Targa %s %s: every sample survives write and read (%s)", rle ? "RLE" : "plain",
                   alpha ? "RGBA" : "RGB", bad < 0 ? err : "ok");
        }
    opt.tga_rle = 0;
    for (int alpha = 0; alpha <= 1; alpha++) {
        opt.write_alpha = alpha;
        bad = round_trip("round.bmp", alpha ? &withalpha : &src, &opt, alpha, 0.0f, err, sizeof err);
        tap_ok(bad == 0, "BMP %s: every sample survives write and read (%s)", alpha ? "RGBA" : "RGB",
               bad < 0 ? err : "ok");
    }
    opt.write_alpha = 0;
    opt.jpeg_quality = 100;
    bad = round_trip("round.jpg", &src, &opt, 0, 6.0f, err, sizeof err);
    tap_ok(bad == 0, "JPEG at quality 100: every sample within 6 steps of 255 (%s)", bad < 0 ? err : "ok");

    /* HDR: linear, each component within the shared exponent's step */
    {
        const char *p = tmp_path("round.hdr");
        bad = -1;
        if (image_write(p, &src, &opt, err, sizeof err) == 0 && image_read(p, &back, 0.0, err, sizeof err) == 0) {
            bad = 0;
            for (size_t i = 0; i < (size_t)src.width * src.height; i++) {
                const float *a = src.rgba + 4 * i, *b = back.rgba + 4 * i;
                float m = fmaxf(a[0], fmaxf(a[1], a[2]));
                for (int c = 0; c < 3; c++)
                    bad += fabsf(a[c] - b[c]) > m / 128.0f + 1e-30f;
            }
            image_free(&back);
        }
        tap_ok(bad == 0, "HDR: every component within 1/128 of the pixel's largest (%s)", bad < 0 ? err : "ok");
    }

    /* Files as other programs write them. */
    {
        /* a bottom-up 2x2 Targa (descriptor 0), 24 bits: red green / blue white */
        const unsigned char tga[] = { 0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 2, 0, 24, 0,
                                      255, 0, 0, 255, 255, 255, /* bottom row: blue, white */
                                      0, 0, 255, 0, 255, 0 /* top row: red, green */ };
        const char *p = tmp_path("bottom-up.tga");
        spit(p, tga, sizeof tga);
        tap_ok(image_read(p, &back, 0.0, err, sizeof err) == 0 && back.rgba[0] == 1.0f && back.rgba[1] == 0.0f &&
                   back.rgba[5] == 1.0f && back.rgba[10] == 1.0f && back.rgba[12] == 1.0f && back.rgba[13] == 1.0f,
               "a bottom-up Targa reads with its top row first (%s)", err);
        image_free(&back);
    }
    {
        /* a top-down (negative height) 8-bit BMP with a palette of two colours */
        unsigned char bmp[14 + 40 + 8 + 8] = { 'B', 'M' };
        bmp[10] = 14 + 40 + 8;
        bmp[14] = 40;
        bmp[18] = 2;                                   /* width 2 */
        bmp[22] = 0xfe, bmp[23] = bmp[24] = bmp[25] = 0xff; /* height -2 */
        bmp[26] = 1;
        bmp[28] = 8;
        bmp[46] = 2;                                   /* two colours used */
        bmp[54 + 2] = 255;                             /* colour 0: red (BGRA) */
        bmp[54 + 4] = 255;                             /* colour 1: blue */
        bmp[62] = 0, bmp[63] = 1;                      /* row 0: red, blue */
        bmp[66] = 1, bmp[67] = 0;                      /* row 1: blue, red */
        const char *p = tmp_path("palette.bmp");
        spit(p, bmp, sizeof bmp);
        tap_ok(image_read(p, &back, 0.0, err, sizeof err) == 0 && back.rgba[0] == 1.0f && back.rgba[2] == 0.0f &&
                   back.rgba[6] == 1.0f && back.rgba[8 + 2] == 1.0f && back.rgba[12] == 1.0f,
               "a top-down 8-bit BMP with a palette reads (%s)", err);
        image_free(&back);
    }
    {
        /* an HDR of 3 flat pixels: (128,64,32,129) then an old-RLE repeat of 2 */
        const char hdr[] = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 3\n\x80\x40\x20\x81\x01\x01\x01\x02";
        const char *p = tmp_path("old.hdr");
        spit(p, hdr, (long)sizeof hdr - 1);
        tap_ok(image_read(p, &back, 0.0, err, sizeof err) == 0 && back.width == 3 &&
                   back.rgba[0] == 128.5f / 128.0f && back.rgba[1] == 64.5f / 128.0f && back.rgba[8] == back.rgba[0] &&
                   back.rgba[10] == 32.5f / 128.0f,
               "an HDR's flat pixels and old run-length repeat read as Radiance decodes them (%s)", err);
        image_free(&back);
    }
    image_free(&src);
    image_free(&withalpha);
}

/* ---- atomic writes ---------------------------------------------------------- */

static void test_atomic(void)
{
    Image img;
    ImageWriteOptions opt = { 0 };
    char err[512];
    const char *dir = tmp_path("atomic");
    char target[4400], missing[4400];
    unsigned char *before, *after;
    long lb, la;
    int hidden, n;

    mkdir(dir, 0777);
    image_alloc(&img, 256, 256);
    fill_test_image(&img, 0);

    snprintf(missing, sizeof missing, "%s/no/such/folder/x.png", dir);
    tap_ok(image_write(missing, &img, &opt, err, sizeof err) == -1, "write into a missing folder fails");
    tap_ok(strstr(err, "cannot write '") != NULL && strstr(err, missing) != NULL &&
               strstr(err, strerror(ENOENT)) != NULL,
           "message names the file and the reason: %s", err);
    n = count_entries(dir, &hidden);
    tap_ok(n == 0, "nothing was created");

    snprintf(target, sizeof target, "%s/out.exr", dir);
    opt.exr_float = 0;
    tap_ok(image_write(target, &img, &opt, err, sizeof err) == 0, "write an EXR (%s)", err);
    before = slurp(target, &lb);
    n = count_entries(dir, &hidden);
    tap_ok(n == 1 && hidden == 0, "only the target exists after a successful write");
    {
        struct stat st;
        mode_t um = umask(022);
        umask(um);
        tap_ok(stat(target, &st) == 0 && (st.st_mode & 0777) == (0666 & ~um), "new file has mode 0666 & ~umask");
    }

    /* A write that fails half way: limit the file size, as a full disk would.
     * The existing target must be untouched and no temporary left. */
    {
        struct rlimit old, lim;
        void (*oldsig)(int) = signal(SIGXFSZ, SIG_IGN);
        int rc;
        getrlimit(RLIMIT_FSIZE, &old);
        lim = old;
        lim.rlim_cur = 4096;
        opt.exr_float = 1; /* bigger than 4096 bytes in any format */
        setrlimit(RLIMIT_FSIZE, &lim);
        rc = image_write(target, &img, &opt, err, sizeof err);
        setrlimit(RLIMIT_FSIZE, &old);
        tap_ok(rc == -1 && strstr(err, target) != NULL, "EXR write failing half way reports it: %s", err);
        setrlimit(RLIMIT_FSIZE, &lim);
        rc = image_write(tmp_path("atomic/out.png"), &img, &opt, err, sizeof err);
        setrlimit(RLIMIT_FSIZE, &old);
        tap_ok(rc == -1 && strstr(err, "out.png") != NULL, "PNG write failing half way reports it: %s", err);
        setrlimit(RLIMIT_FSIZE, &lim);
        rc = image_write(tmp_path("atomic/out.ppm"), &img, &opt, err, sizeof err);
        setrlimit(RLIMIT_FSIZE, &old);
        tap_ok(rc == -1 && strstr(err, "out.ppm") != NULL, "PPM write failing half way reports it: %s", err);
        signal(SIGXFSZ, oldsig);
        opt.exr_float = 0;
    }
    after = slurp(target, &la);
    tap_ok(before != NULL && after != NULL && la == lb && memcmp(before, after, (size_t)lb) == 0,
           "the existing target is unchanged");
    n = count_entries(dir, &hidden);
    tap_ok(n == 1 && hidden == 0, "no temporary and no partial file left behind (%d entries)", n);
    free(after);

    /* rename onto a folder fails: the temporary must go too */
    {
        char sub[4400];
        snprintf(sub, sizeof sub, "%s/folder.png", dir);
        mkdir(sub, 0777);
        tap_ok(image_write(sub, &img, &opt, err, sizeof err) == -1, "writing over a folder fails: %s", err);
        n = count_entries(dir, &hidden);
        tap_ok(n == 2 && hidden == 0, "no temporary left after a failed rename");
        rmdir(sub);
    }

    tap_ok(image_write(tmp_path("atomic/x.gif"), &img, &opt, err, sizeof err) == -1 && strstr(err, "x.gif"),
           "unknown extension refused: %s", err);
    {
        Image empty = { 0, 0, NULL };
        tap_ok(image_write(target, &empty, &opt, err, sizeof err) == -1, "empty image refused: %s", err);
    }

    /* replacing works and keeps no temporaries */
    fill_test_image(&img, 1);
    tap_ok(image_write(target, &img, &opt, err, sizeof err) == 0, "overwriting the target succeeds");
    after = slurp(target, &la);
    tap_ok(after != NULL && (la != lb || memcmp(before, after, (size_t)lb) != 0), "the target has the new content");
    n = count_entries(dir, &hidden);
    tap_ok(n == 1 && hidden == 0, "still one file in the folder");
    free(before);
    free(after);
    image_free(&img);
}

/* ---- broken files ------------------------------------------------------------ */

static void check_broken(const char *label, const unsigned char *data, long len, int *crashes, int *silent)
{
    const char *p = tmp_path(label);
    Image img;
    char err[512];
    int rc;

    spit(p, data, len);
    err[0] = '\0';
    rc = image_read(p, &img, 0.0, err, sizeof err);
    if (rc == 0)
        image_free(&img);
    else if (err[0] == '\0')
        (*silent)++;
    (void)crashes;
}

static void test_broken(void)
{
    static const char *const names[3] = { "good.exr", "good.png", "good.ppm" };
    Image img, back;
    ImageWriteOptions opt = { 0 };
    char err[512];
    uint32_t seed = 12345;

    image_alloc(&img, 40, 40);
    fill_test_image(&img, 1);
    image_write(tmp_path(names[0]), &img, &opt, err, sizeof err);
    image_write(tmp_path(names[1]), &img, &opt, err, sizeof err);
    image_write(tmp_path(names[2]), &img, &opt, err, sizeof err);

    tap_ok(image_read(tmp_path("does-not-exist.png"), &back, 0, err, sizeof err) == -1 &&
               strstr(err, "does-not-exist.png") && strstr(err, strerror(ENOENT)),
           "missing file: %s", err);
    tap_ok(image_read(workdir, &back, 0, err, sizeof err) == -1 && back.rgba == NULL, "a folder: %s", err);
    spit(tmp_path("empty.png"), "", 0);
    tap_ok(image_read(tmp_path("empty.png"), &back, 0, err, sizeof err) == -1, "empty file: %s", err);
    spit(tmp_path("text.exr"), "hello, this is not an image at all\n", 35);
    tap_ok(image_read(tmp_path("text.exr"), &back, 0, err, sizeof err) == -1, "text file: %s", err);

    for (int f = 0; f < 3; f++) {
        long len;
        unsigned char *good = slurp(tmp_path(names[f]), &len);
        int truncated_ok = 0, truncated_total = 0, silent = 0, crashes = 0;
        if (good == NULL) {
            tap_ok(0, "%s was written", names[f]);
            continue;
        }
        /* every truncation length for the header, then a stride */
        for (long cut = 0; cut < len; cut += cut < 400 ? 1 : 37) {
            Image t;
            const char *p = tmp_path(f == 0 ? "cut.exr" : f == 1 ? "cut.png" : "cut.ppm");
            spit(p, good, cut);
            err[0] = '\0';
            truncated_total++;
            if (image_read(p, &t, 0.0, err, sizeof err) == 0)
                image_free(&t);
            else if (err[0] != '\0')
                truncated_ok++;
        }
        tap_ok(truncated_ok == truncated_total, "%s: all %d truncations give an error with a message", names[f],
               truncated_total);
        /* random byte corruption: must not crash (sanitizers watch), every
         * failure must say why */
        for (int iter = 0; iter < 300; iter++) {
            unsigned char *bad = malloc((size_t)len);
            memcpy(bad, good, (size_t)len);
            for (int k = 0; k < 1 + iter % 8; k++) {
                seed = seed * 1664525u + 1013904223u;
                long pos = (long)((seed >> 8) % (uint32_t)(iter < 150 && len > 400 ? 400 : len));
                seed = seed * 1664525u + 1013904223u;
                bad[pos] = (unsigned char)(seed >> 24);
            }
            check_broken(f == 0 ? "fuzz.exr" : f == 1 ? "fuzz.png" : "fuzz.ppm", bad, len, &crashes, &silent);
            free(bad);
        }
        tap_ok(silent == 0, "%s: 300 corrupted copies read or fail with a message", names[f]);
        /* garbage after a valid magic number */
        {
            unsigned char junk[2048];
            for (size_t i = 0; i < sizeof junk; i++) {
                seed = seed * 1664525u + 1013904223u;
                junk[i] = (unsigned char)(seed >> 24);
            }
            memcpy(junk, good, 8);
            check_broken(f == 0 ? "junk.exr" : f == 1 ? "junk.png" : "junk.ppm", junk, sizeof junk, &crashes, &silent);
            tap_ok(silent == 0, "%s: magic number followed by garbage fails with a message", names[f]);
        }
        free(good);
    }
    {
        const char *huge = "P6\n99999999 99999999\n255\n";
        spit(tmp_path("huge.ppm"), huge, (long)strlen(huge));
        tap_ok(image_read(tmp_path("huge.ppm"), &back, 0, err, sizeof err) == -1, "absurd PPM size: %s", err);
        spit(tmp_path("max0.ppm"), "P6\n1 1\n0\n", 9);
        tap_ok(image_read(tmp_path("max0.ppm"), &back, 0, err, sizeof err) == -1, "PPM maxval 0: %s", err);
    }
    image_free(&img);
}

/* ---- against POV-Ray itself (when $POVRAY names it) --------------------------- */

/* Renders a strip of flat colours whose values are exact in half precision,
 * to EXR (linear, what POV-Ray computed) and to 8 and 16-bit PNG and PPM;
 * re-encoding the EXR must give POV-Ray's bytes exactly. */
static void test_povray(void)
{
    const char *povray = getenv("POVRAY");
    static const char *const outs[4] = { "pov.exr", "pov.png", "pov16.png", "pov.ppm" };
    static const char *const flags[4] = { "+FE", "+FN", "+FN16", "+FP" };
    FILE *f;
    char cmd[16384];
    Image lin;
    int ok = 1;

    if (povray == NULL || povray[0] == '\0' || access(povray, X_OK) != 0) {
        tap_ok(1, "POV-Ray PNG encoding matches # SKIP POVRAY not set");
        return;
    }
    f = fopen(tmp_path("strip.pov"), "w");
    if (f == NULL) {
        tap_ok(0, "scene written");
        return;
    }
    fprintf(f, "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
               "camera { orthographic location <0.5,0.5,-1> look_at <0.5,0.5,0> right x up y }\n"
               "#declare K = 0;\n#while (K < 256)\n"
               " box { <K/256,2/3,0>, <(K+1)/256,1,1> pigment { rgb <K/256, K/1024, K/64> } finish { ambient 1 diffuse 0 } }\n"
               " box { <K/256,1/3,0>, <(K+1)/256,2/3,1> pigment { rgb <K/8192, K/32768, K/2048> } finish { ambient 1 diffuse 0 } }\n"
               " box { <K/256,0,0>, <(K+1)/256,1/3,1> pigment { rgb <(255-K)/512, K/512+0.5, K/128> } finish { ambient 1 diffuse 0 } }\n"
               " #declare K = K + 1;\n#end\n");
    fclose(f);
    for (int i = 0; i < 4 && ok; i++) {
        snprintf(cmd, sizeof cmd, "cd '%s' && '%s' +Istrip.pov +O%s %s +W256 +H3 -A -D -GA -V >/dev/null 2>&1",
                 workdir, povray, outs[i], flags[i]);
        ok = system(cmd) == 0;
    }
    if (!ok || image_read(tmp_path("pov.exr"), &lin, 0, cmd, sizeof cmd) != 0) {
        tap_ok(0, "POV-Ray rendered the strip");
        return;
    }
    for (int i = 1; i < 4; i++) {
        ImageWriteOptions opt = { 0 };
        const char *mine = tmp_path(i == 3 ? "mine.ppm" : "mine.png");
        Image a, b;
        long mism = -1, total = 0;
        opt.png_16bit = i == 2;
        if (image_write(mine, &lin, &opt, cmd, sizeof cmd) == 0) {
            /* compare decoded samples: equal floats means equal codes */
            if (image_read(tmp_path(outs[i]), &a, 0, cmd, sizeof cmd) == 0) {
                if (image_read(mine, &b, 0, cmd, sizeof cmd) == 0) {
                    mism = 0;
                    for (size_t k = 0; k < (size_t)a.width * a.height * 4; k++, total++)
                        mism += a.rgba[k] != b.rgba[k];
                    image_free(&b);
                }
                image_free(&a);
            }
        }
        tap_ok(mism == 0, "%s: our encoding of POV-Ray's EXR equals POV-Ray's own file (%ld of %ld samples differ)",
               outs[i], mism, total);
    }
    image_free(&lin);
}

/* image_read_exr_file: every channel as stored and the header's attributes,
 * back from image_write; rows read by chunks; the header alone. */
static void test_exr_file(void)
{
    const char *p = tmp_path("whole.exr");
    char err[512];
    Image src;
    if (image_alloc(&src, 61, 37) != 0) {
        tap_ok(0, "out of memory");
        return;
    }
    fill_test_image(&src, 1);
    const int w = src.width, h = src.height;
    size_t n = (size_t)w * (size_t)h;
    float *depth = malloc(n * sizeof(float)), *vis = malloc(n * sizeof(float));
    uint32_t *code = malloc(n * sizeof(uint32_t));
    for (size_t i = 0; depth && vis && code && i < n; i++) {
        depth[i] = i % 7 == 0 ? INFINITY : (float)i * 0.37f + 1e-3f; /* no half would hold these */
        vis[i] = (float)(i % 5) * 0.25f;                              /* halves exactly */
        code[i] = (uint32_t)(i * 2654435761u);                         /* over float's 2^24 */
    }
    const ImageChannel extra[3] = { { "Z", IMAGE_CHANNEL_FLOAT, depth }, { "shadow.L1", IMAGE_CHANNEL_HALF, vis },
                                    { "cost.rays", IMAGE_CHANNEL_UINT, code } };
    const ImageAttribute attr[3] = { { "hstrace.options", IMAGE_ATTR_STRING, "--width 61 +SR1", 0, 0.0 },
                                     { "hstrace.threads", IMAGE_ATTR_INT, NULL, 3, 0.0 },
                                     { "hstrace.time.wall", IMAGE_ATTR_DOUBLE, NULL, 0, 0.125 } };
    ImageWriteOptions opt;
    memset(&opt, 0, sizeof opt);
    opt.channels = extra;
    opt.nchannels = 3;
    opt.attributes = attr;
    opt.nattributes = 3;
    opt.have_chromaticities = 1;
    for (int k = 0; k < 8; k++)
        opt.chromaticities[k] = 0.1f * (float)(k + 1);
    opt.exr_compression = IMAGE_EXR_PIZ;
    tap_ok(depth && vis && code && image_write(p, &src, &opt, err, sizeof err) == 0, "EXR with channels and attributes written (%s)", err);

    ImageExrFile f;
    int rc = image_read_exr_file(p, &f, 0, h, err, sizeof err);
    tap_ok(rc == 0 && f.width == w && f.height == h && f.nchannels == 7, "whole EXR read: %dx%d, %d channels (%s)", f.width,
           f.height, f.nchannels, err);
    static const char *const order[7] = { "A", "B", "G", "R", "Z", "cost.rays", "shadow.L1" };
    static const ImageChannelType types[7] = { IMAGE_CHANNEL_HALF, IMAGE_CHANNEL_HALF, IMAGE_CHANNEL_HALF, IMAGE_CHANNEL_HALF,
                                               IMAGE_CHANNEL_FLOAT, IMAGE_CHANNEL_UINT, IMAGE_CHANNEL_HALF };
    int names_ok = rc == 0 && f.nchannels == 7;
    for (int c = 0; names_ok && c < 7; c++)
        names_ok = strcmp(f.channels[c].name, order[c]) == 0 && f.channels[c].type == types[c] && f.channels[c].data;
    tap_ok(names_ok, "channels in the file's order, with their stored types: A B G R Z cost.rays shadow.L1");
    int bad = 0;
    for (size_t i = 0; names_ok && i < n; i++) {
        const float *z = f.channels[4].data, *l = f.channels[6].data;
        const uint32_t *u = f.channels[5].data;
        const float *a = f.channels[0].data, *r = f.channels[3].data;
        bad += !(same_float(z[i], depth[i]) && l[i] == vis[i] && u[i] == code[i] && near_half(r[i], src.rgba[4 * i]) &&
                 near_half(a[i], src.rgba[4 * i + 3]));
    }
    tap_ok(names_ok && bad == 0, "samples as written: float and uint exact, half within half precision (%d off)", bad);
    const ImageExrAttribute *o = rc == 0 ? image_exr_file_attribute(&f, "hstrace.options") : NULL;
    const ImageExrAttribute *t = rc == 0 ? image_exr_file_attribute(&f, "hstrace.threads") : NULL;
    const ImageExrAttribute *d = rc == 0 ? image_exr_file_attribute(&f, "hstrace.time.wall") : NULL;
    const ImageExrAttribute *sw = rc == 0 ? image_exr_file_attribute(&f, "software") : NULL;
    tap_ok(o && o->type == IMAGE_ATTR_STRING && strcmp(o->s, "--width 61 +SR1") == 0 && t && t->type == IMAGE_ATTR_INT &&
               t->i == 3 && d && d->type == IMAGE_ATTR_DOUBLE && d->d == 0.125 && sw && strcmp(sw->s, "hstrace") == 0,
           "string, int and double attributes read back");
    tap_ok(rc == 0 && !image_exr_file_attribute(&f, "dataWindow") && !image_exr_file_attribute(&f, "nothing"),
           "attributes of other types are not listed; a missing one is NULL");
    tap_ok(rc == 0 && f.have_chromaticities && f.chromaticities[0] == 0.1f && f.chromaticities[7] == 0.8f &&
               f.compression == IMAGE_EXR_PIZ,
           "chromaticities and compression read back");

    /* The same half samples written again from the floats read: bit for bit. */
    Image again;
    int again_ok = names_ok && image_alloc(&again, w, h) == 0;
    for (size_t i = 0; again_ok && i < n; i++)
        for (int k = 0; k < 4; k++)
            again.rgba[4 * i + (size_t)k] = ((const float *)f.channels[3 - k].data)[i];
    const char *p2 = tmp_path("whole2.exr");
    opt.exr_compression = IMAGE_EXR_PIZ;
    again_ok = again_ok && image_write(p2, &again, &opt, err, sizeof err) == 0;
    long len1 = 0, len2 = 0;
    unsigned char *b1 = again_ok ? slurp(p, &len1) : NULL, *b2 = again_ok ? slurp(p2, &len2) : NULL;
    tap_ok(b1 && b2 && len1 == len2 && memcmp(b1, b2, (size_t)len1) == 0,
           "halves read as floats and written again make the same file, byte for byte");
    free(b1);
    free(b2);
    if (again_ok)
        image_free(&again);
    image_exr_file_free(&f);
    tap_ok(f.channels == NULL && f.nchannels == 0 && f.attributes == NULL, "image_exr_file_free empties it");

    rc = image_read_exr_file(p, &f, 0, 0, err, sizeof err);
    tap_ok(rc == 0 && f.nchannels == 7 && f.channels[0].data == NULL && image_exr_file_attribute(&f, "hstrace.options"),
           "y0 == y1: the header alone, no samples");
    image_exr_file_free(&f);
    /* ZIP's 16-row chunks: rows 20..21 come from the chunk of rows 16..31. */
    opt.exr_compression = IMAGE_EXR_ZIP;
    rc = image_write(p, &src, &opt, err, sizeof err) || image_read_exr_file(p, &f, 20, 22, err, sizeof err);
    int rows_ok = rc == 0 && f.nchannels == 7;
    const float *z = rows_ok ? f.channels[4].data : NULL;
    for (int y = 0; rows_ok && y < h; y++)
        rows_ok = (y >= 16 && y < 32) ? same_float(z[(size_t)y * (size_t)w + 1], depth[(size_t)y * (size_t)w + 1])
                                      : z[(size_t)y * (size_t)w + 1] == 0.0f;
    tap_ok(rows_ok, "rows 20-21 read as their chunk, rows 16-31; the rest 0 (%s)", err);
    image_exr_file_free(&f);

    rc = image_read_exr_file(tmp_path("none.exr"), &f, 0, 1, err, sizeof err);
    tap_ok(rc == -1 && strstr(err, "none.exr': No such file") && f.nchannels == 0, "a missing file: %s", err);
    rc = image_read_exr_file(workdir, &f, 0, 1, err, sizeof err);
    tap_ok(rc == -1 && strstr(err, "Is a directory"), "a folder: %s", err);
    const char *png = tmp_path("not.exr");
    spit(png, "\211PNG\r\n\032\nxxxxxxxx", 16);
    rc = image_read_exr_file(png, &f, 0, 1, err, sizeof err);
    tap_ok(rc == -1 && strstr(err, "not an EXR file"), "a PNG named .exr: %s", err);
    long len = 0;
    unsigned char *whole = slurp(p, &len);
    rc = whole && spit(png, whole, len / 2) == 0 ? image_read_exr_file(png, &f, 0, h, err, sizeof err) : 0;
    tap_ok(rc == -1 && f.channels == NULL, "half an EXR: an error, nothing kept (%s)", err);
    free(whole);
    free(depth);
    free(vis);
    free(code);
    image_free(&src);
}

int main(void)
{
    if (make_workdir() != 0) {
        tap_ok(0, "cannot create a temporary folder: %s", strerror(errno));
        return tap_done();
    }
    tap_diag("temporary files in %s", workdir);
    test_basics();
    test_encoding();
    test_exr();
    test_exr_threads();
    test_exr_tiled();
    test_exr_file();
    test_png();
    test_png_threads();
    test_ppm();
    test_other_types();
    test_atomic();
    test_broken();
    test_povray();
    remove_tree(workdir);
    return tap_done();
}
