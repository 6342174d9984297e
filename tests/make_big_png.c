/* Writes a PNG of WIDTH x HEIGHT grey pixels, all black, for the memory
 * budget's tests (tests/hostile.sh): 16384x16384 deflates to about 260 KB
 * and decodes to 4 GiB of linear RGBA, so it is made at test time rather
 * than kept in the tree.
 * Usage: make_big_png WIDTH HEIGHT FILE.png */
#include <png.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: make_big_png WIDTH HEIGHT FILE.png\n");
        return 1;
    }
    long w = strtol(argv[1], NULL, 10), h = strtol(argv[2], NULL, 10);
    if (w < 1 || h < 1 || w > 1000000 || h > 1000000) {
        fprintf(stderr, "make_big_png: bad size %sx%s\n", argv[1], argv[2]);
        return 1;
    }
    FILE *fp = fopen(argv[3], "wb");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    png_bytep row = calloc((size_t)w, 1);
    if (!fp || !info || !row) {
        fprintf(stderr, "make_big_png: cannot write %s\n", argv[3]);
        return 1;
    }
    if (setjmp(png_jmpbuf(png))) {
        fprintf(stderr, "make_big_png: libpng failed on %s\n", argv[3]);
        return 1;
    }
    png_init_io(png, fp);
    png_set_user_limits(png, 0x7fffffff, 0x7fffffff);
    png_set_compression_level(png, 9);
    png_set_filter(png, 0, PNG_FILTER_NONE); /* rows of zeros: no filter to try */
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (long y = 0; y < h; y++)
        png_write_row(png, row);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    free(row);
    return fclose(fp) == 0 ? 0 : 1;
}
