/* Command-line parsing for `hstrace vs-povray`. */
#include "vs_povray_options.h"

#include <stdlib.h>
#include <string.h>

#include "shadow_embree.h"
#include "shadow_registry.h"

void vs_povray_options_usage(FILE *f)
{
    fprintf(f,
            "usage: hstrace vs-povray SCENE.pov [options] [render options]\n"
            "\n"
            "Renders SCENE with POV-Ray and with hstrace under each shadow method, at the same\n"
            "size and thread count, and prints one table: wall time, CPU time, shadow-testing\n"
            "time, speed-up against POV-Ray, RMSE against POV-Ray's image and disagreements with\n"
            "POV-Ray's shadow mask (from +Q3/+Q4 renders), at edges and in the interior; for\n"
            "a method that is not exact (embree), also its disagreements with the exact\n"
            "shadow ray, from one more render with --verify-shadows.\n"
            "\n"
            "      --methods LIST     shadow methods to compare, comma separated, or all (those\n"
            "                         and embree when built in; default %s; valid: %s)\n"
            "      --runs N           time N full renders per program and report the median\n"
            "                         (default 1, at most %d)\n"
            "      --report DIR       also write DIR/index.html: the table, the images side by\n"
            "                         side, heat maps and shadow-mask maps against POV-Ray\n"
            "                         (PNG files beside it), and DIR/vs-povray.json\n"
            "      --json             print the figures as JSON instead of the table\n"
            "      --help             show this help\n"
            "\n"
            "Render options are those of hstrace SCENE.pov (see hstrace --help), given to every\n"
            "hstrace render: --width/--height/+W/+H and --threads/+WT (default: all cores) and\n"
            "--include-path/+L go to POV-Ray too. Not accepted: -o/--output/+O, --shadows, +Q,\n"
            "--stats, --stats-json.\n"
            "POV-Ray is the program HSTRACE_POVRAY names, or povray in PATH.\n"
            "\n"
            "Exit status: 0 done, 1 bad usage, 2 hstrace rejected the scene, 3 input/output\n"
            "error, 4 POV-Ray not found, 5 POV-Ray failed on the scene.\n",
            VS_DEFAULT_METHODS, shadow_method_names(), VS_MAX_RUNS);
}

void vs_povray_options_free(VsPovrayOptions *opt)
{
    /* (the render options hold what the povray.ini read allocated) */
    options_free(&opt->render);
    free(opt->render_args);
    opt->render_args = NULL;
    opt->nrender_args = 0;
}

/* "hst,conventional" (commas or spaces) or "all" into opt->methods. */
static int parse_methods(const char *list, VsPovrayOptions *opt, char *err, int errlen)
{
    if (strcmp(list, "all") == 0)
        list = shadow_embree_built() ? VS_ALL_METHODS : VS_DEFAULT_METHODS;
    char *copy = strdup(list);
    if (!copy) {
        snprintf(err, (size_t)errlen, "out of memory");
        return -1;
    }
    int rc = 0;
    char *save = NULL;
    opt->nmethods = 0;
    for (char *t = strtok_r(copy, ", ", &save); t; t = strtok_r(NULL, ", ", &save)) {
        const ShadowMethod *m = shadow_method_find(t);
        if (!m) {
            snprintf(err, (size_t)errlen, "--methods: unknown shadow method '%s' (valid: %s, or all)", t,
                     shadow_method_names());
            rc = -1;
            break;
        }
        if (shadow_method_unavailable(m)) {
            snprintf(err, (size_t)errlen, "--methods: %s: %s", t, shadow_method_unavailable(m));
            rc = -1;
            break;
        }
        for (int k = 0; k < opt->nmethods && rc == 0; k++)
            if (opt->methods[k] == m) {
                snprintf(err, (size_t)errlen, "--methods: '%s' given twice", t);
                rc = -1;
            }
        if (rc)
            break;
        if (opt->nmethods == VS_MAX_METHODS) {
            snprintf(err, (size_t)errlen, "--methods: at most %d methods", VS_MAX_METHODS);
            rc = -1;
            break;
        }
        opt->methods[opt->nmethods++] = m;
    }
    if (rc == 0 && opt->nmethods == 0) {
        snprintf(err, (size_t)errlen, "--methods: no method given (valid: %s, or all)", shadow_method_names());
        rc = -1;
    }
    free(copy);
    return rc;
}

/* Render options that vs-povray sets itself. */
static int check_render_options(const VsPovrayOptions *opt, char *err, int errlen)
{
    const Options *r = &opt->render;
    for (int i = 0; i < opt->nrender_args; i++)
        if (options_is_long(opt->render_args[i], "--shadows")) {
            snprintf(err, (size_t)errlen, "--shadows: hstrace vs-povray renders with every method of --methods "
                                          "(default %s)", VS_DEFAULT_METHODS);
            return -1;
        }
    if (r->version) {
        snprintf(err, (size_t)errlen, "unknown option '--version' (see hstrace vs-povray --help)");
        return -1;
    }
    if (r->output) {
        snprintf(err, (size_t)errlen, "-o, --output, +O: hstrace vs-povray writes no image of its own "
                                      "(--report DIR writes the renders)");
        return -1;
    }
    if (r->stats || r->stats_json) {
        snprintf(err, (size_t)errlen, "--stats, --stats-json: hstrace vs-povray reads every render's statistics "
                                      "itself (--json prints its figures)");
        return -1;
    }
    if (r->quality != 9) {
        snprintf(err, (size_t)errlen, "+Q%d: hstrace vs-povray renders at +Q9, and at +Q3 and +Q4 for the "
                                      "shadow masks", r->quality);
        return -1;
    }
    return 0;
}

int vs_povray_options_parse(int argc, char **argv, VsPovrayOptions *opt, char *err, int errlen)
{
    memset(opt, 0, sizeof *opt);
    opt->runs = 1;
    const char *methods = VS_DEFAULT_METHODS;
    /* The render options, as the renderer's parser takes them: a program
     * name first, NULL last. */
    char program[] = "hstrace";
    char **rargv = calloc((size_t)argc + 2, sizeof *rargv);
    if (!rargv) {
        snprintf(err, (size_t)errlen, "out of memory");
        return -1;
    }
    int rargc = 0;
    rargv[rargc++] = program;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            opt->help = 1;
        } else if (strcmp(a, "--json") == 0) {
            opt->json = 1;
        } else if (options_is_long(a, "--methods")) {
            if (!(v = options_value(argc, argv, &i, "--methods", err, errlen)))
                goto fail;
            methods = v;
        } else if (options_is_long(a, "--runs")) {
            if (!(v = options_value(argc, argv, &i, "--runs", err, errlen)))
                goto fail;
            char *end;
            long n = strtol(v, &end, 10);
            if (end == v || *end || n < 1 || n > VS_MAX_RUNS) {
                snprintf(err, (size_t)errlen, "--runs '%s': must be a whole number from 1 to %d", v, VS_MAX_RUNS);
                goto fail;
            }
            opt->runs = (int)n;
        } else if (options_is_long(a, "--report")) {
            if (!(v = options_value(argc, argv, &i, "--report", err, errlen)))
                goto fail;
            if (!*v) {
                snprintf(err, (size_t)errlen, "--report: the folder name is empty");
                goto fail;
            }
            opt->report = v;
        } else {
            rargv[rargc++] = argv[i];
        }
    }
    if (opt->help) {
        free(rargv);
        return 0;
    }
    if (parse_methods(methods, opt, err, errlen))
        goto fail;
    if (options_parse(rargc, rargv, &opt->render, err, errlen))
        goto fail;
    /* The scene is one of the arguments (or follows +I in one): leave it
     * out of the render options, whose copies name it themselves. */
    opt->scene = opt->render.scene;
    int k = 1;
    while (k < rargc && rargv[k] != opt->scene &&
           !((rargv[k][0] == '+' || rargv[k][0] == '-') && rargv[k][1] && rargv[k] + 2 == opt->scene))
        k++;
    if (k < rargc) {
        memmove(&rargv[k], &rargv[k + 1], (size_t)(rargc - k) * sizeof *rargv);
        rargc--;
    }
    /* Keep the arguments after the program name. */
    memmove(&rargv[0], &rargv[1], (size_t)rargc * sizeof *rargv);
    opt->render_args = rargv;
    opt->nrender_args = rargc - 1;
    opt->render.scene = opt->scene;
    if (check_render_options(opt, err, errlen)) {
        vs_povray_options_free(opt);
        return -1;
    }
    return 0;
fail:
    options_free(&opt->render);
    free(rargv);
    opt->render_args = NULL;
    return -1;
}
