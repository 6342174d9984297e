/* The command line of `hstrace vs-povray SCENE.pov [options]`: its own
 * options (methods, runs, outputs) and the render options, which are checked
 * by the renderer's own parser (options.h) and passed to every hstrace
 * render; their size, threads and include folders go to POV-Ray too. */
#ifndef HST_VS_POVRAY_OPTIONS_H
#define HST_VS_POVRAY_OPTIONS_H

#include <stdio.h>

#include "options.h"
#include "shadow.h"

#define VS_MAX_METHODS 8
#define VS_MAX_RUNS 100
/* The methods compared when --methods is not given. */
#define VS_DEFAULT_METHODS "conventional,cache,volume,hst"
/* --methods all: those, and embree when built in. */
#define VS_ALL_METHODS "conventional,cache,volume,hst,embree"

typedef struct {
    const char *scene;                             /* as given */
    const ShadowMethod *methods[VS_MAX_METHODS];   /* --methods, in order */
    int nmethods;
    int runs;                                      /* --runs: full renders timed per program */
    const char *report;                            /* --report DIR, or NULL */
    int json;                                      /* --json */
    int help;
    /* The render options as given (the scene left out), for hstrace's
     * command lines; NULL-terminated, malloc'd (vs_povray_options_free). */
    char **render_args;
    int nrender_args;
    Options render; /* what they mean: width, height, threads (0: not given), include paths */
} VsPovrayOptions;

/* Fills opt from argv, where argv[0] is "vs-povray". Returns 0, or -1 with a
 * message in err (opt is then released). */
int vs_povray_options_parse(int argc, char **argv, VsPovrayOptions *opt, char *err, int errlen);
void vs_povray_options_free(VsPovrayOptions *opt);
void vs_povray_options_usage(FILE *f);

#endif
