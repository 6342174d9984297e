/* Command-line parsing for `hstrace stitch`. */
#include "stitch_options.h"

#include <stdlib.h>
#include <string.h>

#include "image.h"
#include "options.h"

void stitch_options_usage(FILE *f)
{
    fprintf(f,
            "usage: hstrace stitch PART.exr... -o FULL.exr\n"
            "\n"
            "Joins partial renders (hstrace SCENE.pov +SRn +ERn +SCn +ECn -o PART.exr, one per\n"
            "job of a Slurm job array or GNU parallel) into the image a single render makes,\n"
            "bit for bit, every channel included (--aov). Each part's area comes from its EXR\n"
            "header (hstrace.options); a part without one is the whole image. The parts must\n"
            "come from the same scene (hstrace.sceneHash), hstrace version and options (the\n"
            "thread count aside), and fill the image exactly once: overlaps and gaps are\n"
            "refused, naming the files and the rows and columns. FULL is written only then,\n"
            "atomically, with the parts' channels and a header for the whole.\n"
            "\n"
            "  -o, --output FULL.exr  the stitched image (EXR)\n"
            "      --help             show this help\n"
            "\n"
            "Exit status: 0 written, 1 bad usage or parts that do not make one image,\n"
            "3 a part unreadable or not an EXR written by hstrace, or FULL unwritable.\n");
}

void stitch_options_free(StitchOptions *opt)
{
    free(opt->parts);
    opt->parts = NULL;
    opt->nparts = 0;
}

int stitch_options_parse(int argc, char **argv, StitchOptions *opt, char *err, int errlen)
{
    memset(opt, 0, sizeof *opt);
    opt->parts = calloc((size_t)(argc > 1 ? argc : 1), sizeof *opt->parts);
    if (!opt->parts) {
        snprintf(err, (size_t)errlen, "out of memory");
        return -1;
    }
    int only_files = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v;
        if (only_files || a[0] != '-' || a[1] == '\0') {
            opt->parts[opt->nparts++] = a;
        } else if (strcmp(a, "--") == 0) {
            only_files = 1;
        } else if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            opt->help = 1;
        } else if (strcmp(a, "-o") == 0 || options_is_long(a, "--output")) {
            if (!(v = options_value(argc, argv, &i, a[1] == 'o' ? "-o" : "--output", err, errlen)))
                goto fail;
            if (opt->output) {
                snprintf(err, (size_t)errlen, "-o given twice ('%s' and '%s')", opt->output, v);
                goto fail;
            }
            opt->output = v;
        } else {
            snprintf(err, (size_t)errlen, "unknown option '%s' (see hstrace stitch --help)", a);
            goto fail;
        }
    }
    if (opt->help)
        return 0;
    if (opt->nparts == 0) {
        snprintf(err, (size_t)errlen, "no parts given: hstrace stitch PART.exr... -o FULL.exr (see --help)");
        goto fail;
    }
    if (!opt->output) {
        snprintf(err, (size_t)errlen, "no output given: hstrace stitch PART.exr... -o FULL.exr (see --help)");
        goto fail;
    }
    /* Only EXR keeps what a part holds: every channel at its type, and the
     * header that says how the image was made. */
    if (image_format_from_path(opt->output) != IMAGE_FORMAT_EXR) {
        snprintf(err, (size_t)errlen, "-o '%s': the stitched image is an EXR file (-o FULL.exr), as the parts are",
                 opt->output);
        goto fail;
    }
    /* A second run over a glob (part*.exr) would take the last result for
     * a part of its own. */
    for (int k = 0; k < opt->nparts; k++)
        if (strcmp(opt->parts[k], opt->output) == 0) {
            snprintf(err, (size_t)errlen, "-o '%s' is also given as a part", opt->output);
            goto fail;
        }
    return 0;
fail:
    stitch_options_free(opt);
    return -1;
}
