/* libFuzzer entry point: `hstrace stitch` (stitch.c), its parts' headers
 * read, their options lines planned (stitch_plan.c), their agreement and
 * cover checked, their pixels gathered and the whole written, as the
 * command does all of it.
 *
 * The input is one part, or two divided at the first "\n%%part%%\n":
 * written to a.exr (and b.exr) in a private temporary folder, made on the
 * first input, and stitched into full.exr there:
 *
 *   hstrace stitch FOLDER/a.exr [FOLDER/b.exr] -o FOLDER/full.exr
 *
 * The exit status must be one the man page gives (0, 1 or 3), and a
 * whole written must read back at the size and with the options the
 * first part's header gives. Built and run by tests/fuzz/run.sh
 * (`make fuzz`); replayed by tests/fuzz-replay.sh. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "image.h"
#include "stitch.h"

static char folder[4096], part_a[4200], part_b[4200], whole[4200];

static void remove_folder(void)
{
    (void)unlink(part_a);
    (void)unlink(part_b);
    (void)unlink(whole);
    (void)rmdir(folder);
}

/* The private folder, made once. 0, or -1 when it cannot be made. */
static int make_folder(void)
{
    if (folder[0])
        return 0;
    const char *tmp = getenv("TMPDIR");
    snprintf(folder, sizeof folder, "%s/hstfuzzstitch.XXXXXX", tmp && tmp[0] ? tmp : "/tmp");
    if (!mkdtemp(folder)) {
        perror("fuzz_stitch: mkdtemp");
        folder[0] = '\0';
        return -1;
    }
    snprintf(part_a, sizeof part_a, "%s/a.exr", folder);
    snprintf(part_b, sizeof part_b, "%s/b.exr", folder);
    snprintf(whole, sizeof whole, "%s/full.exr", folder);
    atexit(remove_folder);
    return 0;
}

static int write_file(const char *path, const uint8_t *data, size_t n)
{
    FILE *fp = fopen(path, "wb");
    if (!fp)
        return -1;
    int bad = n && fwrite(data, 1, n, fp) != n;
    return fclose(fp) || bad ? -1 : 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char sep[] = "\n%%part%%\n";
    const size_t nsep = sizeof sep - 1;
    if (make_folder())
        return 0;
    size_t first = size;
    for (size_t i = 0; i + nsep <= size; i++)
        if (memcmp(data + i, sep, nsep) == 0) {
            first = i;
            break;
        }
    const int two = first < size;
    (void)unlink(whole);
    if (write_file(part_a, data, first) || (two && write_file(part_b, data + first + nsep, size - first - nsep)))
        return 0;
    char *argv[6];
    int argc = 0;
    argv[argc++] = "stitch";
    argv[argc++] = part_a;
    if (two)
        argv[argc++] = part_b;
    argv[argc++] = "-o";
    argv[argc++] = whole;
    argv[argc] = NULL;
    int status = stitch_main(argc, argv, "hstrace");
    if (status != STITCH_EXIT_OK && status != STITCH_EXIT_USAGE && status != STITCH_EXIT_IO)
        abort(); /* an exit status the man page does not give */
    if (status == STITCH_EXIT_OK) {
        /* the whole, read back: the first part's size, a whole image's options */
        ImageExrFile a, w;
        char err[1024];
        int ra = image_read_exr_file(part_a, &a, 0, 0, err, (int)sizeof err);
        int rw = image_read_exr_file(whole, &w, 0, 0, err, (int)sizeof err);
        if (ra || rw || a.width != w.width || a.height != w.height || a.nchannels != w.nchannels ||
            !image_exr_file_attribute(&w, "hstrace.options") || !image_exr_file_attribute(&w, "hstrace.stitch"))
            abort();
        image_exr_file_free(&a);
        image_exr_file_free(&w);
    }
    return 0;
}
