/* libFuzzer entry points for the image readers `hstrace compare` uses:
 * compiled once per format, with FUZZ_EXR, FUZZ_PNG, FUZZ_PPM, FUZZ_TGA,
 * FUZZ_BMP, FUZZ_JPG or FUZZ_HDR defined. The input is the file's bytes:
 * all but EXR are read through fmemopen,
 * EXR (read from a file descriptor, with seeks) through a memfd; the EXR
 * target also reads the analysis channels by name, as the AOV tools do.
 * Built and run by tests/fuzz/run.sh (`make fuzz`). */
#define _GNU_SOURCE /* memfd_create */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <unistd.h>

#include "image_codec.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    Image img = { 0 };
    char err[256];
#if defined(FUZZ_EXR)
    int fd = memfd_create("fuzz.exr", MFD_CLOEXEC);
    if (fd < 0)
        return 0;
    if (size && write(fd, data, size) != (ssize_t)size) {
        close(fd);
        return 0;
    }
    /* as image_read does: the image freed whatever the answer */
    if (lseek(fd, 0, SEEK_SET) == 0)
        (void)image_exr_read(fd, &img, err, (int)sizeof err);
    image_free(&img);
    static const char *const names[] = { "Z", "N.X", "N.Y", "N.Z", "hst.depth" };
    float *planes[5] = { NULL, NULL, NULL, NULL, NULL };
    int w, h;
    if (lseek(fd, 0, SEEK_SET) == 0 && image_exr_read_planes(fd, names, 5, planes, &w, &h, err, (int)sizeof err) >= 0)
        for (int i = 0; i < 5; i++)
            free(planes[i]);
    close(fd);
#else
    if (size == 0)
        return 0;
    FILE *fp = fmemopen((void *)data, size, "rb");
    if (!fp)
        return 0;
    /* PNG, Targa and BMP are read twice: as the image layer reads them,
     * and as a scene's picture is (straight colours, a palette kept
     * indexed: image_read_for_scene) */
    ImageReadExtras ex = { .keep_straight = 1 };
#if defined(FUZZ_PNG)
    (void)image_png_read(fp, &img, 0.0, NULL, err, (int)sizeof err);
    image_free(&img);
    rewind(fp);
    (void)image_png_read(fp, &img, 0.0, &ex, err, (int)sizeof err);
#elif defined(FUZZ_TGA)
    (void)image_tga_read(fp, &img, 0.0, NULL, err, (int)sizeof err);
    image_free(&img);
    rewind(fp);
    (void)image_tga_read(fp, &img, 0.0, &ex, err, (int)sizeof err);
#elif defined(FUZZ_BMP)
    (void)image_bmp_read(fp, &img, 0.0, NULL, err, (int)sizeof err);
    image_free(&img);
    rewind(fp);
    (void)image_bmp_read(fp, &img, 0.0, &ex, err, (int)sizeof err);
#elif defined(FUZZ_JPG)
    (void)image_jpeg_read(fp, &img, 0.0, err, (int)sizeof err);
#elif defined(FUZZ_HDR)
    (void)image_hdr_read(fp, &img, err, (int)sizeof err);
#else
    (void)image_ppm_read(fp, &img, 0.0, NULL, err, (int)sizeof err);
#endif
    image_free(&img); /* as image_read does, whatever the answer */
    free(ex.index);
    fclose(fp);
#endif
    return 0;
}
