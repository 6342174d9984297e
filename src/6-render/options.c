/* Command-line parsing. */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "options.h"

#include "aov.h"
#include "grid.h"
#include "shadow.h"
#include "shadow_embree.h"
#include "shadow_volumes.h"

#define MAX_DIMENSION 32768

static int parse_int(const char *s, int lo, int hi, int *out)
{
    if (!s || !*s)
        return -1;
    errno = 0;
    char *end;
    long v = strtol(s, &end, 10);
    if (errno || *end || v < lo || v > hi)
        return -1;
    *out = (int)v;
    return 0;
}

/* A size in bytes: a whole or decimal number, then K, M, G or T (powers
 * of 1024; "KiB", "MB" ... and lower case too), none for bytes. */
static int parse_size(const char *s, size_t *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || errno || !(v > 0.0))
        return -1;
    double unit = 1.0;
    switch (*end) {
    case 'k': case 'K': unit = 1024.0; end++; break;
    case 'm': case 'M': unit = 1024.0 * 1024.0; end++; break;
    case 'g': case 'G': unit = 1024.0 * 1024.0 * 1024.0; end++; break;
    case 't': case 'T': unit = 1024.0 * 1024.0 * 1024.0 * 1024.0; end++; break;
    default: break;
    }
    if (unit > 1.0 && *end == 'i')
        end++;
    if (*end == 'B' || *end == 'b')
        end++;
    if (*end != '\0')
        return -1;
    double bytes = v * unit;
    if (bytes < 1.0 || bytes > 1e18)
        return -1;
    *out = (size_t)bytes;
    return 0;
}

/* A whole number from 1 to 10^15 (the work budgets). */
static int parse_count(const char *s, long *out)
{
    char *end;
    errno = 0;
    long long v = strtoll(s, &end, 10);
    if (end == s || *end || errno || v < 1 || v > 1000000000000000LL)
        return -1;
    *out = (long)v;
    return 0;
}

/* "N" or "NxNxN". */
static int parse_grid(const char *s, int g[3])
{
    int a, b, c;
    char tail;
    if (sscanf(s, "%dx%dx%d%c", &a, &b, &c, &tail) == 3) {
        g[0] = a; g[1] = b; g[2] = c;
    } else if (sscanf(s, "%d%c", &a, &tail) == 1) {
        g[0] = g[1] = g[2] = a;
    } else {
        return -1;
    }
    for (int i = 0; i < 3; i++)
        if (g[i] < 1 || g[i] > 4096)
            return -1;
    if ((double)g[0] * g[1] * g[2] > 1 << 28)
        return -1;
    return 0;
}

void options_usage(FILE *f)
{
    fprintf(f,
            "usage: hstrace SCENE.pov [options]\n"
            "       hstrace compare A B [options]   (see hstrace compare --help)\n"
            "       hstrace vs-povray SCENE.pov [options]   (see hstrace vs-povray --help)\n"
            "\n"
            "Renders a POV-Ray scene made of polygons, with hybrid shadow testing; compares\n"
            "two images and two renderers' shadow masks; or measures every shadow method\n"
            "against POV-Ray on a scene.\n"
            "\n"
            "  -o, --output FILE      image to write (.exr, .png or .ppm; default SCENE.png)\n"
            "      --width N          image width in pixels (default 320)\n"
            "      --height N         image height in pixels (default 240)\n"
            "      --shadows METHOD   shadow test (default hst), one of:\n"
            "                         %s;\n"
            "                         embree is Embree 3's float shadow ray, for comparison:\n"
            "                         not exact (--verify-shadows counts its disagreements)%s\n"
            "      --nth N|auto|per-point  hst's switching threshold N_th: fixed, the measured\n"
            "                         cost of a shadow ray over that of counting one shadow polygon\n"
            "                         (default), or the paper's eq. (7) per shading point\n"
            "      --volumes auto|always  hst: build a light's shadow volumes only where the cost\n"
            "                         model, measured before building, says they repay their\n"
            "                         build on this image, else shadow rays only (default auto);\n"
            "                         always: every light's, as the paper does\n"
            "      --pixel-coherence on|off  hst: carry depth counts from the previous pixel's\n"
            "                         hit instead of the eye where cheaper (default on)\n"
            "      --tolerance R      margin of the shadow tests, relative to the scene's\n"
            "                         coordinates (default 1e-9; for measuring speed against error)\n"
            "      --plane-precision double|float|float-naive  how volume and hst test the\n"
            "                         shadow polygons' planes: double (default); float with a\n"
            "                         margin widened for float's rounding (same decisions); float\n"
            "                         with the double margin (for measuring the error)\n"
            "      --verify-shadows   also fire the exact shadow ray at every decision and count\n"
            "                         disagreements (--stats shows them)\n"
            "      --verify-reference as --verify-shadows, and check both against a brute-force\n"
            "                         long-double reference (slow; for measuring error)\n"
            "      --threads N        render threads (default: all cores); the image does not depend on N\n"
            "      --grid N|NxNxN     grid cells per axis (default: chosen from the polygon count)\n"
            "      --include-path DIR folder searched for #include files (repeatable)\n"
            "      --strict           refuse what hstrace only approximates (normal, patterns other\n"
            "                         than checker/hexagon/gradient, area_light, ...: see the man page)\n"
            "      --max-memory SIZE  memory the scene may take while it is parsed, e.g. 512M or 8G\n"
            "                         (default: a quarter of the physical memory)\n"
            "      --max-parse-seconds S  stop a parse running longer (default: no time limit)\n"
            "      --max-repeated-tokens N  tokens loops and macro calls may read again, a long\n"
            "                         one counting one per 16 bytes (default 20000000: stops an\n"
            "                         endless loop within seconds)\n"
            "      --max-macro-calls N     macro calls in all (default 2000000)\n"
            "      --max-loop-iterations N #while/#for iterations in all (default 10000000)\n"
            "      --exr-float        write 32-bit float EXR channels instead of half\n"
            "      --aov LIST         EXR only: add analysis channels, comma separated groups of\n"
            "                         Z, N, P, shadow, hst, depth, cost, or all (see the man page)\n"
            "      --png16            write 16-bit PNG\n"
            "      --ocio-config FILE OpenColorIO config for PNG/PPM output (default: $OCIO, else\n"
            "                         hstrace's own); without this, --display, --view, --colorspace\n"
            "                         and $OCIO, PNG/PPM get POV-Ray's sRGB encoding\n"
            "      --display NAME     OCIO display (default: the config's default display)\n"
            "      --view NAME        OCIO view of that display (default: the display's default)\n"
            "      --colorspace NAME  OCIO working space the render is in and the EXR is tagged\n"
            "                         with (default: the config's scene_linear role)\n"
            "      --stats            print timings and counts on stderr\n"
            "      --stats-json FILE  write the same statistics as JSON\n"
            "      --help             show this help\n"
            "      --version          show the version\n"
            "\n"
            "POV-Ray switches: +Wn +Hn +Oname +Iname +Ldir +WTn +Qn (quality: <=3 no shadows,\n"
            "4-5 shadows, 6-7 also refraction, >=8 also reflection; default 9); -A -D +D -V\n"
            "are accepted and change nothing; +A is refused (no anti-aliasing).\n"
            "\n"
            "Exit status: 0 success, 1 bad usage (also a display, view or colour space the\n"
            "config lacks), 2 scene error, 3 input/output error (also a missing or broken\n"
            "colour config).\n",
            shadow_method_names(), shadow_embree_built() ? "" : ";\n                         not in this build (configure found no Embree)");
}

/* Takes the value of a long option: "--name=value" or "--name value". */
static const char *option_value(int argc, char **argv, int *i, const char *name, char *err, int errlen)
{
    const char *arg = argv[*i];
    size_t n = strlen(name);
    if (arg[n] == '=')
        return arg + n + 1;
    if (*i + 1 >= argc) {
        snprintf(err, (size_t)errlen, "option '%s' needs a value", name);
        return NULL;
    }
    return argv[++*i];
}

static int is_long(const char *arg, const char *name)
{
    size_t n = strlen(name);
    return strncmp(arg, name, n) == 0 && (arg[n] == '\0' || arg[n] == '=');
}

/* The same two helpers for the subcommands' parsers (compare_options.c). */
const char *options_value(int argc, char **argv, int *i, const char *name, char *err, int errlen)
{
    return option_value(argc, argv, i, name, err, errlen);
}

int options_is_long(const char *arg, const char *name)
{
    return is_long(arg, name);
}

static int add_include(Options *opt, const char *dir, char *err, int errlen)
{
    if (opt->ninclude_paths >= MAX_INCLUDE_PATHS) {
        snprintf(err, (size_t)errlen, "too many include paths (at most %d)", MAX_INCLUDE_PATHS);
        return -1;
    }
    opt->include_paths[opt->ninclude_paths++] = dir;
    return 0;
}

/* POV-Ray switches: +X or -X followed by a value where it has one. */
static int parse_pov_switch(const char *arg, Options *opt, char *err, int errlen)
{
    const char *s = arg + 1;
    int on = arg[0] == '+';
    if (strncmp(s, "WT", 2) == 0 || strncmp(s, "wt", 2) == 0) {
        if (parse_int(s + 2, 1, 1024, &opt->threads)) {
            snprintf(err, (size_t)errlen, "'%s': thread count must be 1 to 1024", arg);
            return -1;
        }
        return 0;
    }
    switch (s[0]) {
    case 'W': case 'w':
        if (parse_int(s + 1, 1, MAX_DIMENSION, &opt->width)) {
            snprintf(err, (size_t)errlen, "'%s': width must be 1 to %d", arg, MAX_DIMENSION);
            return -1;
        }
        return 0;
    case 'H': case 'h':
        if (parse_int(s + 1, 1, MAX_DIMENSION, &opt->height)) {
            snprintf(err, (size_t)errlen, "'%s': height must be 1 to %d", arg, MAX_DIMENSION);
            return -1;
        }
        return 0;
    case 'Q': case 'q':
        if (parse_int(s + 1, 0, 11, &opt->quality)) {
            snprintf(err, (size_t)errlen, "'%s': quality must be 0 to 11", arg);
            return -1;
        }
        return 0;
    case 'O': case 'o':
        if (!s[1]) break;
        opt->output = s + 1;
        return 0;
    case 'I': case 'i':
        if (!s[1]) break;
        opt->scene = s + 1;
        return 0;
    case 'L': case 'l':
        if (!s[1]) break;
        return add_include(opt, s + 1, err, errlen);
    case 'A': case 'a':
        if (on) {
            snprintf(err, (size_t)errlen, "'%s': anti-aliasing is not supported by hstrace", arg);
            return -1;
        }
        return 0;
    case 'D': case 'd':
        return 0; /* no display window either way */
    case 'V': case 'v':
        return 0; /* verbosity */
    default:
        break;
    }
    snprintf(err, (size_t)errlen, "unknown POV-Ray switch '%s'", arg);
    return -1;
}

int options_parse(int argc, char **argv, Options *opt, char *err, int errlen)
{
    memset(opt, 0, sizeof *opt);
    opt->width = 320;
    opt->height = 240;
    opt->quality = 9;
    opt->shadows = "hst";
    opt->nth = NTH_AUTO;
    opt->pixel_coherence = 1;
    opt->tolerance = GRID_TOLERANCE;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            opt->help = 1;
        } else if (strcmp(a, "--version") == 0) {
            opt->version = 1;
        } else if (strcmp(a, "-o") == 0 || is_long(a, "--output")) {
            if (!(v = option_value(argc, argv, &i, strcmp(a, "-o") == 0 ? "-o" : "--output", err, errlen)))
                return -1;
            opt->output = v;
        } else if (is_long(a, "--width") || is_long(a, "--height")) {
            int is_w = is_long(a, "--width");
            if (!(v = option_value(argc, argv, &i, is_w ? "--width" : "--height", err, errlen)))
                return -1;
            if (parse_int(v, 1, MAX_DIMENSION, is_w ? &opt->width : &opt->height)) {
                snprintf(err, (size_t)errlen, "%s '%s': must be a whole number from 1 to %d",
                         is_w ? "--width" : "--height", v, MAX_DIMENSION);
                return -1;
            }
        } else if (is_long(a, "--shadows")) {
            if (!(v = option_value(argc, argv, &i, "--shadows", err, errlen)))
                return -1;
            const ShadowMethod *m = shadow_method_find(v);
            if (!m) {
                snprintf(err, (size_t)errlen, "unknown shadow method '%s' (valid: %s)", v, shadow_method_names());
                return -1;
            }
            if (shadow_method_unavailable(m)) {
                snprintf(err, (size_t)errlen, "--shadows %s: %s", v, shadow_method_unavailable(m));
                return -1;
            }
            opt->shadows = v;
        } else if (is_long(a, "--nth")) {
            if (!(v = option_value(argc, argv, &i, "--nth", err, errlen)))
                return -1;
            char *end;
            double n = strtod(v, &end);
            if (strcmp(v, "auto") == 0) {
                opt->nth = NTH_AUTO;
            } else if (strcmp(v, "per-point") == 0) {
                opt->nth = NTH_PER_POINT;
            } else if (end != v && *end == '\0' && n >= 0.0 && n <= 1e9) {
                opt->nth = n;
            } else {
                snprintf(err, (size_t)errlen, "--nth '%s': expected auto, per-point or a number from 0 to 1e9", v);
                return -1;
            }
        } else if (is_long(a, "--plane-precision")) {
            if (!(v = option_value(argc, argv, &i, "--plane-precision", err, errlen)))
                return -1;
            if (strcmp(v, "double") == 0)
                opt->plane_precision = PLANES_DOUBLE;
            else if (strcmp(v, "float") == 0)
                opt->plane_precision = PLANES_FLOAT;
            else if (strcmp(v, "float-naive") == 0)
                opt->plane_precision = PLANES_FLOAT_NAIVE;
            else {
                snprintf(err, (size_t)errlen, "--plane-precision '%s': expected double, float or float-naive", v);
                return -1;
            }
        } else if (is_long(a, "--tolerance")) {
            if (!(v = option_value(argc, argv, &i, "--tolerance", err, errlen)))
                return -1;
            char *end;
            double t = strtod(v, &end);
            if (end == v || *end != '\0' || !(t >= 0.0 && t <= 1e-3)) {
                snprintf(err, (size_t)errlen, "--tolerance '%s': expected a number from 0 to 1e-3", v);
                return -1;
            }
            opt->tolerance = t;
        } else if (is_long(a, "--volumes")) {
            if (!(v = option_value(argc, argv, &i, "--volumes", err, errlen)))
                return -1;
            if (strcmp(v, "auto") == 0 || strcmp(v, "always") == 0) {
                opt->volumes_always = strcmp(v, "always") == 0;
            } else {
                snprintf(err, (size_t)errlen, "--volumes '%s': expected auto or always", v);
                return -1;
            }
        } else if (is_long(a, "--pixel-coherence")) {
            if (!(v = option_value(argc, argv, &i, "--pixel-coherence", err, errlen)))
                return -1;
            if (strcmp(v, "on") == 0 || strcmp(v, "off") == 0) {
                opt->pixel_coherence = strcmp(v, "on") == 0;
            } else {
                snprintf(err, (size_t)errlen, "--pixel-coherence '%s': expected on or off", v);
                return -1;
            }
        } else if (strcmp(a, "--verify-shadows") == 0) {
            opt->verify_shadows = opt->verify_shadows > 1 ? opt->verify_shadows : 1;
        } else if (strcmp(a, "--verify-reference") == 0) {
            opt->verify_shadows = 2;
        } else if (is_long(a, "--threads")) {
            if (!(v = option_value(argc, argv, &i, "--threads", err, errlen)))
                return -1;
            if (parse_int(v, 1, 1024, &opt->threads)) {
                snprintf(err, (size_t)errlen, "--threads '%s': must be 1 to 1024", v);
                return -1;
            }
        } else if (is_long(a, "--grid")) {
            if (!(v = option_value(argc, argv, &i, "--grid", err, errlen)))
                return -1;
            if (parse_grid(v, opt->grid)) {
                snprintf(err, (size_t)errlen, "--grid '%s': expected N or NxNxN, each 1 to 4096", v);
                return -1;
            }
        } else if (is_long(a, "--include-path")) {
            if (!(v = option_value(argc, argv, &i, "--include-path", err, errlen)) ||
                add_include(opt, v, err, errlen))
                return -1;
        } else if (strcmp(a, "--stats") == 0) {
            opt->stats = 1;
        } else if (strcmp(a, "--strict") == 0) {
            opt->strict = 1;
        } else if (is_long(a, "--max-memory")) {
            if (!(v = option_value(argc, argv, &i, "--max-memory", err, errlen)))
                return -1;
            if (parse_size(v, &opt->max_memory)) {
                snprintf(err, (size_t)errlen, "--max-memory '%s': expected a size such as 512M or 8G", v);
                return -1;
            }
        } else if (is_long(a, "--max-parse-seconds")) {
            if (!(v = option_value(argc, argv, &i, "--max-parse-seconds", err, errlen)))
                return -1;
            char *end;
            double s = strtod(v, &end);
            if (end == v || *end != '\0' || !(s > 0.0 && s <= 1e9)) {
                snprintf(err, (size_t)errlen, "--max-parse-seconds '%s': expected a number of seconds above 0", v);
                return -1;
            }
            opt->max_parse_seconds = s;
        } else if (is_long(a, "--max-repeated-tokens") || is_long(a, "--max-macro-calls") ||
                   is_long(a, "--max-loop-iterations")) {
            static const char *const names[] = { "--max-repeated-tokens", "--max-macro-calls", "--max-loop-iterations" };
            long *slots[] = { &opt->max_repeated_tokens, &opt->max_macro_calls, &opt->max_loop_iterations };
            int k = 0;
            while (!is_long(a, names[k]))
                k++;
            if (!(v = option_value(argc, argv, &i, names[k], err, errlen)))
                return -1;
            if (parse_count(v, slots[k])) {
                snprintf(err, (size_t)errlen, "%s '%s': expected a whole number from 1 to 10^15", names[k], v);
                return -1;
            }
        } else if (is_long(a, "--stats-json")) {
            if (!(v = option_value(argc, argv, &i, "--stats-json", err, errlen)))
                return -1;
            opt->stats_json = v;
        } else if (strcmp(a, "--exr-float") == 0) {
            opt->exr_float = 1;
        } else if (is_long(a, "--aov")) {
            if (!(v = option_value(argc, argv, &i, "--aov", err, errlen)) || aov_parse(v, &opt->aov, err, errlen))
                return -1;
        } else if (strcmp(a, "--png16") == 0) {
            opt->png16 = 1;
        } else if (is_long(a, "--ocio-config") || is_long(a, "--display") || is_long(a, "--view") ||
                   is_long(a, "--colorspace")) {
            static const char *const names[] = { "--ocio-config", "--display", "--view", "--colorspace" };
            const char **slots[] = { &opt->ocio_config, &opt->display, &opt->view, &opt->colorspace };
            int k = 0;
            while (!is_long(a, names[k]))
                k++;
            if (!(v = option_value(argc, argv, &i, names[k], err, errlen)))
                return -1;
            if (v[0] == '\0') {
                snprintf(err, (size_t)errlen, "%s: the name is empty", names[k]);
                return -1;
            }
            *slots[k] = v;
        } else if ((a[0] == '+' || a[0] == '-') && a[1] && a[1] != '-') {
            if (parse_pov_switch(a, opt, err, errlen))
                return -1;
        } else if (a[0] == '-' && a[1] == '-') {
            snprintf(err, (size_t)errlen, "unknown option '%s' (see --help)", a);
            return -1;
        } else if (!opt->scene) {
            opt->scene = a;
        } else {
            snprintf(err, (size_t)errlen, "more than one scene given ('%s' and '%s')", opt->scene, a);
            return -1;
        }
    }
    if (!opt->help && !opt->version && !opt->scene) {
        snprintf(err, (size_t)errlen, "no scene file given (see --help)");
        return -1;
    }
    if ((double)opt->width * opt->height > (double)(1 << 28)) {
        snprintf(err, (size_t)errlen, "image of %dx%d pixels is too large (at most 268435456 pixels)", opt->width,
                 opt->height);
        return -1;
    }
    return 0;
}
