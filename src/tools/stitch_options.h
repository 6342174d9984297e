/* The command line of `hstrace stitch PART... -o FULL`: the partial renders
 * (EXR files hstrace wrote with +SR +ER +SC +EC) and the file for the whole. */
#ifndef HST_STITCH_OPTIONS_H
#define HST_STITCH_OPTIONS_H

#include <stdio.h>

typedef struct {
    const char **parts; /* in the order given; malloc'd (stitch_options_free) */
    int nparts;
    const char *output; /* -o / --output */
    int help;
} StitchOptions;

/* Fills opt from argv, where argv[0] is "stitch". Returns 0, or -1 with a
 * message in err (opt is then released). */
int stitch_options_parse(int argc, char **argv, StitchOptions *opt, char *err, int errlen);
void stitch_options_free(StitchOptions *opt);
void stitch_options_usage(FILE *f);

#endif
