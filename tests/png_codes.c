/* png_codes: compares the sample codes of two PNG files, read with libpng
 * alone (none of hstrace's image code), for tests/encoding.sh.
 *
 *   png_codes A.png B.png
 *
 * Both must have the same size, bit depth and colour type; then every
 * sample (channel of a pixel, as stored: 8 or 16 bits) of A is compared with
 * B's. Prints the size, the format, how many samples differ and the largest
 * difference, and the first differing samples with their codes. Exit 0 when
 * no sample differs, 1 when some do, 2 on unreadable or unlike files. */
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    png_uint_32 width, height;
    int depth, colour_type, channels;
    png_bytep data; /* rows, each width * channels * depth / 8 bytes */
    size_t row_bytes;
    png_bytep *rows; /* while reading (in memory, so that a longjmp keeps it) */
} Png;

static int png_load(const char *path, Png *p)
{
    memset(p, 0, sizeof *p);
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "png_codes: cannot open '%s'\n", path);
        return -1;
    }
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        fprintf(stderr, "png_codes: '%s' is not a readable PNG\n", path);
        png_destroy_read_struct(&png, &info, NULL);
        free(p->rows);
        p->rows = NULL;
        free(p->data);
        p->data = NULL;
        fclose(f);
        return -1;
    }
    png_init_io(png, f);
    png_read_info(png, info);
    p->width = png_get_image_width(png, info);
    p->height = png_get_image_height(png, info);
    p->depth = png_get_bit_depth(png, info);
    p->colour_type = png_get_color_type(png, info);
    p->channels = png_get_channels(png, info);
    p->row_bytes = png_get_rowbytes(png, info);
    p->data = malloc(p->row_bytes * p->height);
    p->rows = malloc(sizeof *p->rows * p->height);
    if (!p->data || !p->rows)
        png_error(png, "out of memory");
    for (png_uint_32 y = 0; y < p->height; y++)
        p->rows[y] = p->data + y * p->row_bytes;
    png_read_image(png, p->rows);
    png_read_end(png, NULL);
    png_destroy_read_struct(&png, &info, NULL);
    free(p->rows);
    p->rows = NULL;
    fclose(f);
    return 0;
}

static unsigned sample(const Png *p, png_uint_32 x, png_uint_32 y, int c)
{
    const png_byte *row = p->data + y * p->row_bytes;
    size_t i = (size_t)x * (size_t)p->channels + (size_t)c;
    return p->depth == 16 ? (unsigned)row[2 * i] << 8 | row[2 * i + 1] : row[i];
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: png_codes A.png B.png\n");
        return 2;
    }
    Png a, b;
    if (png_load(argv[1], &a))
        return 2;
    if (png_load(argv[2], &b)) {
        free(a.data);
        return 2;
    }
    int status = 2;
    if (a.width != b.width || a.height != b.height || a.depth != b.depth || a.colour_type != b.colour_type ||
        a.depth < 8) {
        fprintf(stderr, "png_codes: %ux%u, %d bits, colour type %d against %ux%u, %d bits, colour type %d\n",
                (unsigned)a.width, (unsigned)a.height, a.depth, a.colour_type, (unsigned)b.width, (unsigned)b.height,
                b.depth, b.colour_type);
    } else {
        long differ = 0, total = 0, shown = 0;
        unsigned worst = 0;
        for (png_uint_32 y = 0; y < a.height; y++)
            for (png_uint_32 x = 0; x < a.width; x++)
                for (int c = 0; c < a.channels; c++) {
                    unsigned u = sample(&a, x, y, c), v = sample(&b, x, y, c), d = u > v ? u - v : v - u;
                    total++;
                    if (!d)
                        continue;
                    differ++;
                    worst = d > worst ? d : worst;
                    if (shown++ < 10)
                        printf("pixel (%u, %u) channel %d: %u against %u\n", (unsigned)x, (unsigned)y, c, u, v);
                }
        printf("%ux%u, %d bits, %d channels: %ld of %ld samples differ, by at most %u\n", (unsigned)a.width,
               (unsigned)a.height, a.depth, a.channels, differ, total, worst);
        status = differ ? 1 : 0;
    }
    free(a.data);
    free(b.data);
    return status;
}
