/* exr_channels: what an EXR holds, channel by channel, read with the
 * OpenEXR library's C API alone (none of hstrace's image code), so that
 * tests/stitch.sh can tell two files' pixels identical bit for bit.
 *
 *   exr_channels FILE.exr [X0 Y0 X1 Y1]
 *
 * Prints the size, then per channel (in the file's order, sorted by name)
 * its name, its type (half, float, uint) and the FNV-1a 64 hash of its
 * samples' bits as stored, row by row, over the whole image or over the
 * rectangle [X0, X1) x [Y0, Y1). Two files print the same lines when every
 * channel's samples are the same bits. Exit 0, or 2 with a message on an
 * unreadable file. */
#include <openexr.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *type_name(exr_pixel_type_t t)
{
    return t == EXR_PIXEL_HALF ? "half" : t == EXR_PIXEL_FLOAT ? "float" : t == EXR_PIXEL_UINT ? "uint" : "?";
}

int main(int argc, char **argv)
{
    if (argc != 2 && argc != 6) {
        fprintf(stderr, "usage: exr_channels FILE.exr [X0 Y0 X1 Y1]\n");
        return 2;
    }
    exr_context_t ctx;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    const exr_attr_chlist_t *cl;
    exr_attr_box2i_t dw;
    exr_storage_t storage;
    int lines;
    if (exr_start_read(&ctx, argv[1], &init) != EXR_ERR_SUCCESS) {
        fprintf(stderr, "exr_channels: cannot read '%s'\n", argv[1]);
        return 2;
    }
    if (exr_get_storage(ctx, 0, &storage) != EXR_ERR_SUCCESS || storage != EXR_STORAGE_SCANLINE ||
        exr_get_channels(ctx, 0, &cl) != EXR_ERR_SUCCESS || exr_get_data_window(ctx, 0, &dw) != EXR_ERR_SUCCESS ||
        exr_get_scanlines_per_chunk(ctx, 0, &lines) != EXR_ERR_SUCCESS || lines < 1) {
        fprintf(stderr, "exr_channels: '%s' is no scanline EXR\n", argv[1]);
        exr_finish(&ctx);
        return 2;
    }
    int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1, n = cl->num_channels;
    int x0 = 0, y0 = 0, x1 = w, y1 = h;
    if (argc == 6) {
        x0 = atoi(argv[2]);
        y0 = atoi(argv[3]);
        x1 = atoi(argv[4]);
        y1 = atoi(argv[5]);
        if (x0 < 0 || y0 < 0 || x1 > w || y1 > h || x0 >= x1 || y0 >= y1) {
            fprintf(stderr, "exr_channels: the rectangle lies outside the %dx%d image\n", w, h);
            exr_finish(&ctx);
            return 2;
        }
    }
    /* Each channel decoded as stored (no conversion), 4 bytes a sample at
     * most: the bits themselves. */
    uint8_t **plane = calloc((size_t)n, sizeof *plane);
    int ok = plane != NULL;
    for (int k = 0; ok && k < n; k++)
        ok = (plane[k] = calloc((size_t)w * (size_t)h, 4)) != NULL;
    exr_decode_pipeline_t dec = EXR_DECODE_PIPELINE_INITIALIZER;
    int started = 0;
    for (int y = 0; ok && y < h; y += lines) {
        exr_chunk_info_t ci;
        ok = exr_read_scanline_chunk_info(ctx, 0, y + dw.min.y, &ci) == EXR_ERR_SUCCESS &&
             (started ? exr_decoding_update(ctx, 0, &ci, &dec) : exr_decoding_initialize(ctx, 0, &ci, &dec)) ==
                 EXR_ERR_SUCCESS;
        started |= ok;
        for (int c = 0; ok && c < dec.channel_count; c++) {
            exr_coding_channel_info_t *ch = &dec.channels[c];
            int k = 0;
            while (k < n && strcmp(cl->entries[k].name.str, ch->channel_name) != 0)
                k++;
            if (k == n) {
                ok = 0;
                break;
            }
            int bytes = cl->entries[k].pixel_type == EXR_PIXEL_HALF ? 2 : 4;
            ch->user_data_type = cl->entries[k].pixel_type;
            ch->user_bytes_per_element = (int16_t)bytes;
            ch->user_pixel_stride = bytes;
            ch->user_line_stride = bytes * w;
            ch->decode_to_ptr = plane[k] + (size_t)(ci.start_y - dw.min.y) * (size_t)w * (size_t)bytes;
        }
        ok = ok && exr_decoding_choose_default_routines(ctx, 0, &dec) == EXR_ERR_SUCCESS &&
             exr_decoding_run(ctx, 0, &dec) == EXR_ERR_SUCCESS;
    }
    if (started)
        exr_decoding_destroy(ctx, &dec);
    if (ok) {
        printf("%dx%d\n", w, h);
        for (int k = 0; k < n; k++) {
            size_t bytes = cl->entries[k].pixel_type == EXR_PIXEL_HALF ? 2 : 4;
            uint64_t hash = 0xcbf29ce484222325ULL; /* FNV-1a offset basis and prime */
            for (int y = y0; y < y1; y++) {
                const uint8_t *p = plane[k] + ((size_t)y * (size_t)w + (size_t)x0) * bytes;
                for (size_t i = 0; i < (size_t)(x1 - x0) * bytes; i++) {
                    hash ^= p[i];
                    hash *= 0x100000001b3ULL;
                }
            }
            printf("%s %s %016llx\n", cl->entries[k].name.str, type_name(cl->entries[k].pixel_type),
                   (unsigned long long)hash);
        }
    } else {
        fprintf(stderr, "exr_channels: cannot decode '%s'\n", argv[1]);
    }
    for (int k = 0; plane && k < n; k++)
        free(plane[k]);
    free(plane);
    exr_finish(&ctx);
    return ok ? 0 : 2;
}
