/* The options' table (options_table.h) and the handlers of the rows whose
 * values are more than a number, a word or a text. */
#include <ctype.h>
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "options_table.h"

#include "animation.h"
#include "aov.h"
#include "grid.h"
#include "shadow.h"
#include "shadow_embree.h"
#include "shadow_registry.h"
#include "shadow_volumes.h"

#define MAX_DIMENSION 32768
#define MAX_DIMENSION_TEXT "32768"

/* ---- value parsers (OPT_PARSED) ------------------------------------------- */

/* --nth: auto, per-point or a number from 0 to 1e9. */
static int parse_nth(const char *v, void *slot)
{
    NthSetting *nth = slot;
    char *end;
    double n = strtod(v, &end);
    if (strcmp(v, "auto") == 0)
        *nth = (NthSetting){ NTH_AUTO, 0.0 };
    else if (strcmp(v, "per-point") == 0)
        *nth = (NthSetting){ NTH_PER_POINT, 0.0 };
    else if (end != v && *end == '\0' && n >= 0.0 && n <= 1e9)
        *nth = (NthSetting){ NTH_FIXED, n };
    else
        return -1;
    return 0;
}

/* --grid: "N" or "NxNxN". */
static int parse_grid(const char *s, void *slot)
{
    int *g = slot;
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

/* Bits_Per_Color: PNG's depth (over 8: 16 bits), 1 to 16. */
static int parse_bits(const char *v, void *slot)
{
    int bits;
    if (option_parse_int(v, 1, 16, &bits))
        return -1;
    *(int *)slot = bits > 8;
    return 0;
}

/* ---- handlers (OPT_CUSTOM) ------------------------------------------------ */

static int shadows_option(const OptionRow *row, const char *arg, const char *v, Options *opt, char *err, int errlen)
{
    (void)row;
    const ShadowMethod *m = shadow_method_find(v);
    if (!m) {
        snprintf(err, (size_t)errlen, "unknown shadow method '%s' (valid: %s)", v, shadow_method_names());
        return -1;
    }
    if (shadow_method_unavailable(m)) {
        snprintf(err, (size_t)errlen, "%s %s: %s", arg, v, shadow_method_unavailable(m));
        return -1;
    }
    opt->shadows = v;
    return 0;
}

static void shadows_help(FILE *f, const char *indent)
{
    fprintf(f, "%s%s;\n%sembree is Embree 3's float shadow ray, for comparison:\n"
            "%snot exact (--verify-shadows counts its disagreements)%s%s%s\n",
            indent, shadow_method_names(), indent, indent, shadow_embree_built() ? "" : ";\n",
            shadow_embree_built() ? "" : indent, shadow_embree_built() ? "" : "not in this build (configure found no Embree)");
}

static int aov_option(const OptionRow *row, const char *arg, const char *v, Options *opt, char *err, int errlen)
{
    (void)row; (void)arg;
    return aov_parse(v, &opt->aov, err, errlen);
}

/* +A[threshold] / -A. */
static int antialias_switch(const OptionRow *row, const char *arg, const char *v, Options *opt, char *err,
                            int errlen)
{
    (void)row;
    int on = arg[0] == '+';
    opt->antialias_on = on;
    opt->antialias_positioned = 0;
    if (on)
        snprintf(opt->antialias_by, sizeof opt->antialias_by, "'%s'", arg);
    if (*v && (option_parse_double(v, &opt->aa_threshold) || opt->aa_threshold < 0.0)) {
        snprintf(err, (size_t)errlen, "'%s': the anti-aliasing threshold is a number from 0", arg);
        return -1;
    }
    return 0;
}

/* +J[amount] / -J. */
static int jitter_switch(const OptionRow *row, const char *arg, const char *v, Options *opt, char *err, int errlen)
{
    (void)row;
    opt->jitter_on = arg[0] == '+';
    if (*v && (option_parse_double(v, &opt->jitter_amount) || opt->jitter_amount < 0.0)) {
        snprintf(err, (size_t)errlen, "'%s': the jitter amount is a number from 0", arg);
        return -1;
    }
    return 0;
}

/* +MV3.7 and the INI key Version=3.7: the only language version hstrace
 * reads. arg is the switch ("+MV3.7") or the key ("Version"). */
static int version_switch(const OptionRow *row, const char *arg, const char *v, Options *opt, char *err, int errlen)
{
    (void)row;
    double x;
    if (option_parse_double(v, &x) || fabs(x - 3.7) > 1e-9) {
        int sw = arg[0] == '+' || arg[0] == '-';
        snprintf(err, (size_t)errlen, "%s%s%s%s%s: hstrace reads scenes as POV-Ray 3.7 does (+MV3.7 only, or "
                 "Version=3.7)", sw ? "'" : "", arg, sw ? "" : "=", sw ? "" : v, sw ? "'" : "");
        return -1;
    }
    opt->language_version_given = 1;
    return 0;
}

/* POV-Ray's +F: the output file's type (+FN[bits] PNG, +FE EXR, +FP PPM,
 * +FT Targa, +FC compressed Targa, +FB BMP, +FJ JPEG, +FH Radiance HDR;
 * -F none). Digits after the type are POV-Ray's bits per colour: PNG's
 * depth, ignored by the types that have one depth. */
static int output_type_switch(const OptionRow *row, const char *arg, const char *t, Options *opt, char *err,
                              int errlen)
{
    (void)row;
    if (arg[0] != '+') {
        opt->no_output = 1;
        return 0;
    }
    opt->no_output = 0;
    int type = toupper((unsigned char)t[0]);
    if (type == 'S') {
        snprintf(err, (size_t)errlen, "'%s': the system's own image type is not supported by hstrace (+FN PNG, +FE EXR, "
                 "+FP PPM, +FT/+FC Targa, +FB BMP, +FJ JPEG, +FH HDR)", arg);
        return -1;
    }
    if (!type || !strchr("NEPTCBJH", type)) {
        snprintf(err, (size_t)errlen, "'%s': unknown output type (+FN PNG, +FE EXR, +FP PPM, +FT/+FC Targa, +FB BMP, "
                 "+FJ JPEG, +FH HDR)", arg);
        return -1;
    }
    if (toupper((unsigned char)t[1]) == 'G') {
        snprintf(err, (size_t)errlen, "'%s': greyscale output is not supported by hstrace", arg);
        return -1;
    }
    int bits = 8;
    if (t[1] && option_parse_int(t + 1, 1, 16, &bits)) {
        snprintf(err, (size_t)errlen, "'%s': bits per colour must be 1 to 16", arg);
        return -1;
    }
    if (type == 'P' && bits > 8) {
        snprintf(err, (size_t)errlen, "'%s': 16-bit PPM output is not supported by hstrace (+FN16 writes 16-bit PNG)", arg);
        return -1;
    }
    if (type == 'N')
        opt->png16 = bits > 8;
    opt->output_type = type;
    return 0;
}

/* POV-Ray's console streams: +GA all, +GD debug, +GF fatal, +GR render,
 * +GS statistics, +GW warning (on, or off with -), +GP append to their
 * files. hstrace writes its streams to the standard error only: a file name
 * after the letter is refused (redirect the standard error instead); fatal
 * errors are shown whatever -GF or -GA say, since the exit status alone
 * would not tell what went wrong. */
static int stream_switch(const OptionRow *row, const char *arg, const char *v, Options *opt, char *err, int errlen)
{
    (void)row; (void)v;
    int on = arg[0] == '+';
    int which = toupper((unsigned char)arg[2]);
    if (!which || !strchr("ADFRSWP", which) || (which == 'P' && arg[3])) {
        snprintf(err, (size_t)errlen, "unknown POV-Ray switch '%s'", arg);
        return -1;
    }
    if (arg[3]) {
        snprintf(err, (size_t)errlen, "'%s': hstrace writes its messages to the standard error only (redirect it to "
                 "keep them in a file)", arg);
        return -1;
    }
    if (which == 'A' || which == 'D')
        opt->debug_console = on;
    if (which == 'A' || which == 'W')
        opt->warning_console = on;
    if (which == 'A' || which == 'R')
        opt->render_console = on;
    if (which == 'A' || which == 'S')
        opt->statistics_console = on;
    return 0;
}

/* Declare=NAME=VALUE: a number, or a string in double quotes. */
static int declare_key(const OptionRow *row, const char *arg, const char *text, Options *opt, char *err, int errlen)
{
    (void)row; (void)arg;
    const char *eq = strchr(text, '=');
    if (!eq || eq == text) {
        snprintf(err, (size_t)errlen, "Declare=%s: expected Declare=NAME=VALUE", text);
        return -1;
    }
    OptionDeclare d = { option_own_string(opt, text, (size_t)(eq - text)), 0.0, NULL };
    const char *value = eq + 1, *quote = strchr(value, '"');
    if (quote) {
        const char *close = strchr(quote + 1, '"');
        if (!close) {
            snprintf(err, (size_t)errlen, "Declare=%s: the string is not closed", text);
            return -1;
        }
        d.string = option_own_string(opt, quote + 1, (size_t)(close - quote - 1));
    } else {
        char *end;
        errno = 0;
        double v = strtod(value, &end);
        if (end == value || *end != '\0' || !isfinite(v) || !isfinite(pov_declared_value(v))) {
            snprintf(err, (size_t)errlen, "Declare=%s: the value must be a number (within float's range) or a string "
                     "in double quotes", text);
            return -1;
        }
        d.number = pov_declared_value(v);
    }
    OptionDeclare *grown = realloc(opt->declares, sizeof *grown * (size_t)(opt->ndeclares + 1));
    if (!d.name || (quote && !d.string) || !grown) {
        free(grown == opt->declares ? NULL : grown);
        snprintf(err, (size_t)errlen, "out of memory");
        return -1;
    }
    opt->declares = grown;
    opt->declares[opt->ndeclares++] = d;
    return 0;
}

/* A gamma option as POV-Ray 3.7 reads one (frontend/processrenderoptions.cpp,
 * the gamma keys' special handler; vfe/vfecontrol.cpp refuses a power law
 * below 0.001): "sRGB" (any case), else a power-law gamma from 0.001, 1
 * being no curve at all. POV-Ray 3.7.0 knows no other curve (no bt709).
 * Into *out: 0 for sRGB, else the power. 0, or -1 with the message. */
#define GAMMA_MIN 0.001
static int parse_gamma_key(const OptionRow *row, const char *value, double *out, char *err, int errlen)
{
    double v;
    if (strcasecmp(value, "srgb") == 0) {
        *out = 0.0;
        return 0;
    }
    if (option_parse_double(value, &v) || !(v >= GAMMA_MIN)) {
        snprintf(err, (size_t)errlen, "%s=%s: expected sRGB or a power-law gamma from %g (POV-Ray 3.7 knows no "
                 "other curve)", row->ini, value, GAMMA_MIN);
        return -1;
    }
    *out = v;
    return 0;
}

/* Display_Gamma: the working and file gamma of a scene that turns gamma
 * correction off (options.h). */
static int display_gamma_key(const OptionRow *row, const char *arg, const char *value, Options *opt, char *err,
                             int errlen)
{
    (void)arg;
    return parse_gamma_key(row, value, &opt->display_gamma, err, errlen);
}

/* File_Gamma: the encoding of the integer output types (options.h). */
static int file_gamma_key(const OptionRow *row, const char *arg, const char *value, Options *opt, char *err,
                          int errlen)
{
    (void)arg;
    return parse_gamma_key(row, value, &opt->file_gamma, err, errlen);
}

/* ---- the rows --------------------------------------------------------------
 * The long options first, in the order --help lists them; then the settings
 * only POV-Ray's switches and INI keys give; then the INI keys hstrace
 * ignores or refuses, with why. */

#define ANY_NUMBER -DBL_MAX, DBL_MAX
#define FROM_ZERO 0.0, DBL_MAX
/* A key (or switch, or both: NULL for none) POV-Ray 3.7 takes and hstrace
 * refuses, with what it is about; ..._ON: refused only when on (off is
 * POV-Ray's default and asks for nothing). */
#define UNSUPPORTED(key, sw, why) { .ini = key, .pov = sw, .type = OPT_UNSUPPORTED, .reason = why }
#define UNSUPPORTED_ON(key, sw, why) \
    { .ini = key, .pov = sw, .type = OPT_UNSUPPORTED, .ini_as = INI_AS_ON_OFF, .reason = why }
/* A key or switch that cannot change the image or the files, and why; the
 * switch takes nothing after it (+B5 is no switch, as in POV-Ray), but
 * ..._VALUE's takes a value (+BM2). */
#define IGNORED(key, sw, why) { .ini = key, .pov = sw, .type = OPT_IGNORED, .reason = why }
#define IGNORED_VALUE(key, sw, why) { .ini = key, .pov = sw, .type = OPT_IGNORED, .ignore_rest = 1, .reason = why }

static const OptionWord plane_words[] = {
    { "double", PLANES_DOUBLE }, { "float", PLANES_FLOAT }, { "float-naive", PLANES_FLOAT_NAIVE }, { NULL, 0 }
};
static const OptionWord volumes_words[] = { { "auto", 0 }, { "always", 1 }, { NULL, 0 } };
static const OptionWord on_off_words[] = { { "on", 1 }, { "off", 0 }, { NULL, 0 } };
static const OptionWord instancing_words[] = { { "auto", 1 }, { "off", 0 }, { NULL, 0 } };

const OptionRow option_rows[] = {
    { .name = "--output", .short_name = "-o", .pov = "+O", .ini = "Output_File_Name", .type = OPT_STRING,
      .field = OPTION_FIELD(output), .value_name = "FILE",
      .help = "image to write (.exr .png .ppm .tga .bmp .jpg .hdr; default SCENE.png)" },
    { .name = "--width", .pov = "+W", .ini = "Width", .ini_as = INI_AS_SWITCH, .type = OPT_INT,
      .field = OPTION_FIELD(width), .lo = 1, .hi = MAX_DIMENSION, .dflt = "320", .value_name = "N",
      .help = "image width in pixels (default 320)",
      .expect = "must be a whole number from 1 to " MAX_DIMENSION_TEXT,
      .pov_expect = "width must be 1 to " MAX_DIMENSION_TEXT },
    { .name = "--height", .pov = "+H", .ini = "Height", .ini_as = INI_AS_SWITCH, .type = OPT_INT,
      .field = OPTION_FIELD(height), .lo = 1, .hi = MAX_DIMENSION, .dflt = "240", .value_name = "N",
      .help = "image height in pixels (default 240)",
      .expect = "must be a whole number from 1 to " MAX_DIMENSION_TEXT,
      .pov_expect = "height must be 1 to " MAX_DIMENSION_TEXT },
    { .name = "--shadows", .type = OPT_CUSTOM, .handler = shadows_option, .dflt = "hst", .value_name = "METHOD",
      .help = "shadow test (default hst), one of:", .help_tail = shadows_help },
    { .name = "--nth", .type = OPT_PARSED, .parse = parse_nth, .field = OPTION_FIELD(nth), .dflt = "auto",
      .value_name = "N|auto|per-point",
      .help = "hst's switching threshold N_th: fixed, the measured\n"
              "cost of a shadow ray over that of counting one shadow polygon\n"
              "(default), or the paper's eq. (7) per shading point",
      .expect = "expected auto, per-point or a number from 0 to 1e9" },
    { .name = "--volumes", .type = OPT_WORDS, .words = volumes_words, .field = OPTION_FIELD(volumes_always),
      .dflt = "auto", .value_name = "auto|always",
      .help = "hst: build a light's shadow volumes only where the cost\n"
              "model, measured before building, says they repay their\n"
              "build on this image, else shadow rays only (default auto);\n"
              "always: every light's, as the paper does",
      .expect = "expected auto or always" },
    { .name = "--instancing", .type = OPT_WORDS, .words = instancing_words, .field = OPTION_FIELD(instancing),
      .dflt = "auto", .value_name = "auto|off",
      .help = "auto: a mesh placed two or more times is kept once and\n"
              "each copy placed by its transform (less memory, a faster\n"
              "build), where the shadow method takes instances (hst\n"
              "without area lights or --volumes always, conventional,\n"
              "cache, light-buffer, embree); off: every copy flattened",
      .expect = "expected auto or off" },
    { .name = "--pixel-coherence", .type = OPT_WORDS, .words = on_off_words, .field = OPTION_FIELD(pixel_coherence),
      .dflt = "on", .value_name = "on|off",
      .help = "hst: carry depth counts from the previous pixel's\n"
              "hit instead of the eye where cheaper (default on)",
      .expect = "expected on or off" },
    /* GRID_TOLERANCE's value, read as the option reads it. */
    { .name = "--tolerance", .type = OPT_REAL, .field = OPTION_FIELD(tolerance), .lo = 0.0, .hi = 1e-3,
      .dflt = "1e-9", .value_name = "R",
      .help = "margin of the shadow tests, relative to the scene's\n"
              "coordinates (default 1e-9; for measuring speed against error)",
      .expect = "expected a number from 0 to 1e-3" },
    { .name = "--plane-precision", .type = OPT_WORDS, .words = plane_words, .field = OPTION_FIELD(plane_precision),
      .dflt = "double", .value_name = "double|float|float-naive",
      .help = "how volume and hst test the\n"
              "shadow polygons' planes: double (default); float with a\n"
              "margin widened for float's rounding (same decisions); float\n"
              "with the double margin (for measuring the error)",
      .expect = "expected double, float or float-naive" },
    { .name = "--verify-shadows", .type = OPT_FLAG, .field = OPTION_FIELD(verify_shadows), .lo = 1,
      .help = "also fire the exact shadow ray at every decision and count\n"
              "disagreements (--stats shows them)" },
    { .name = "--verify-reference", .type = OPT_FLAG, .field = OPTION_FIELD(verify_shadows), .lo = 2,
      .help = "as --verify-shadows, and check both against a brute-force\n"
              "long-double reference (slow; for measuring error)" },
    { .name = "--threads", .pov = "+WT", .ini = "Work_Threads", .ini_as = INI_AS_SWITCH, .type = OPT_INT,
      .field = OPTION_FIELD(threads), .lo = 1, .hi = 1024, .value_name = "N",
      .help = "render threads (default: all cores); the image does not depend on N",
      .expect = "must be 1 to 1024", .pov_expect = "thread count must be 1 to 1024" },
    { .name = "--grid", .type = OPT_PARSED, .parse = parse_grid, .field = OPTION_FIELD(grid),
      .value_name = "N|NxNxN", .help = "grid cells per axis (default: chosen from the polygon count)",
      .expect = "expected N or NxNxN, each 1 to 4096" },
    { .name = "--include-path", .pov = "+L", .ini = "Library_Path", .type = OPT_LIST, .value_name = "DIR",
      .help = "folder searched for #include files (repeatable)" },
    { .name = "--strict", .type = OPT_FLAG, .field = OPTION_FIELD(strict), .lo = 1,
      .help = "refuse what hstrace only approximates (patterns and normals it\n"
              "does not model, warps, layered textures, radiosity, photons,\n"
              "focal blur, ...: APPROXIMATIONS in the man page)" },
    /* No default here: the parser's own is a quarter of the physical memory. */
    { .name = "--max-memory", .type = OPT_SIZE, .field = OPTION_FIELD(max_memory), .value_name = "SIZE",
      .help = "memory the scene may take while it is parsed, and the world\n"
              "built from it, e.g. 512M or 8G (default: a quarter of the\n"
              "physical memory)",
      .expect = "expected a size such as 512M or 8G" },
    { .name = "--max-parse-seconds", .type = OPT_REAL, .field = OPTION_FIELD(max_parse_seconds), .lo = 0.0,
      .lo_open = 1, .hi = 1e9, .value_name = "S",
      .help = "stop a parse, or the parse and the world's build together,\n"
              "running longer (default: no time limit)",
      .expect = "expected a number of seconds above 0" },
    { .name = "--max-render-seconds", .type = OPT_REAL, .field = OPTION_FIELD(max_render_seconds), .lo = 0.0,
      .lo_open = 1, .hi = 1e9, .value_name = "S",
      .help = "stop a render running longer, writing no image\n"
              "(status 2; default: no time limit)",
      .expect = "expected a number of seconds above 0" },
    /* A ray tree that splits at every level (reflecting, see-through
     * surfaces with adc_bailout 0) is 2^max_trace_level rays in one pixel:
     * it would never end (POV-Ray crashes). 2^20 rays, about a second, is
     * far beyond what a pixel of a scene that can be rendered holds. */
    { .name = "--max-tree-rays", .type = OPT_COUNT, .field = OPTION_FIELD(max_tree_rays), .lo = 0,
      .dflt = "1048576", .value_name = "N",
      .help = "rays one camera ray's tree of reflected and transmitted rays\n"
              "may hold, else no image (status 2; default 1048576, 0: none)",
      .expect = "expected a whole number from 0 to 10^15" },
    /* The parse's budgets: no default here, the parser has its own. */
    { .name = "--max-repeated-tokens", .type = OPT_COUNT, .field = OPTION_FIELD(max_repeated_tokens), .lo = 1,
      .value_name = "N",
      .help = "tokens loops and macro calls may read again, a long\n"
              "one counting one per 16 bytes (default 20000000: stops an\n"
              "endless loop within seconds)",
      .expect = "expected a whole number from 1 to 10^15" },
    { .name = "--max-macro-calls", .type = OPT_COUNT, .field = OPTION_FIELD(max_macro_calls), .lo = 1,
      .value_name = "N", .help = "macro calls in all (default 2000000)",
      .expect = "expected a whole number from 1 to 10^15" },
    { .name = "--max-loop-iterations", .type = OPT_COUNT, .field = OPTION_FIELD(max_loop_iterations), .lo = 1,
      .value_name = "N", .help = "#while/#for iterations in all (default 10000000)",
      .expect = "expected a whole number from 1 to 10^15" },
    { .name = "--exr-float", .type = OPT_FLAG, .field = OPTION_FIELD(exr_float), .lo = 1,
      .help = "write 32-bit float EXR channels instead of half" },
    { .name = "--aov", .type = OPT_CUSTOM, .handler = aov_option, .value_name = "LIST",
      .help = "EXR only: add analysis channels, comma separated groups of\n"
              "Z, N, P, shadow, hst, depth, cost, or all (see the man page)" },
    { .name = "--png16", .type = OPT_FLAG, .field = OPTION_FIELD(png16), .lo = 1, .help = "write 16-bit PNG" },
    { .name = "--ocio-config", .type = OPT_NAME, .field = OPTION_FIELD(ocio_config), .value_name = "FILE",
      .help = "OpenColorIO config for PNG/PPM output (default: $OCIO, else\n"
              "hstrace's own); without this, --display, --view, --colorspace\n"
              "and $OCIO, PNG/PPM get POV-Ray's sRGB encoding" },
    { .name = "--display", .type = OPT_NAME, .field = OPTION_FIELD(display), .value_name = "NAME",
      .help = "OCIO display (default: the config's default display)" },
    { .name = "--view", .type = OPT_NAME, .field = OPTION_FIELD(view), .value_name = "NAME",
      .help = "OCIO view of that display (default: the display's default)" },
    { .name = "--colorspace", .type = OPT_NAME, .field = OPTION_FIELD(colorspace), .value_name = "NAME",
      .help = "OCIO working space the render is in and the EXR is tagged\n"
              "with (default: the config's scene_linear role)" },
    { .name = "--stats", .type = OPT_FLAG, .field = OPTION_FIELD(stats), .lo = 1,
      .help = "print timings and counts on stderr" },
    { .name = "--stats-json", .type = OPT_STRING, .field = OPTION_FIELD(stats_json), .value_name = "FILE",
      .help = "write the same statistics as JSON" },
    { .name = "--help", .type = OPT_FLAG, .field = OPTION_FIELD(help), .lo = 1, .help = "show this help" },
    { .short_name = "-h", .type = OPT_FLAG, .field = OPTION_FIELD(help), .lo = 1 }, /* not in --help */
    /* POV-Ray's Unix front end's own (vfe/unix/unixoptions.cpp, Standard_Options),
     * not in --help: the man page's POV-RAY OPTIONS names them */
    { .short_name = "-help", .type = OPT_FLAG, .field = OPTION_FIELD(help), .lo = 1 },
    { .short_name = "-?", .type = OPT_FLAG, .field = OPTION_FIELD(help), .lo = 1 },
    { .short_name = "-version", .type = OPT_FLAG, .field = OPTION_FIELD(version), .lo = 1 },
    { .short_name = "--V", .type = OPT_FLAG, .field = OPTION_FIELD(version), .lo = 1 },
    { .short_name = "--benchmark", .type = OPT_UNSUPPORTED, .reason = "POV-Ray's built-in benchmark scene" },
    { .short_name = "-benchmark", .type = OPT_UNSUPPORTED, .reason = "POV-Ray's built-in benchmark scene" },
    { .name = "--version", .type = OPT_FLAG, .field = OPTION_FIELD(version), .lo = 1, .help = "show the version" },
    /* options_parse looks for it before anything else is read */
    { .name = "--no-povray-ini", .type = OPT_FLAG, .field = OPTION_FIELD(no_povray_ini), .lo = 1,
      .help = "read no povray.ini (by default the one POV-Ray 3.7 reads:\n"
              "$POVINI, ./povray.ini, the user's, the system's; see FILES)" },
    { .name = "--povray-options", .type = OPT_FLAG, .field = OPTION_FIELD(povray_options), .lo = 1,
      .help = "list POV-Ray 3.7's INI keys and switches, each honoured,\n"
              "ignored or refused, and why" },

    /* ---- POV-Ray's switches and INI keys only (--help's paragraphs) ----
     * Every key and switch of POV-Ray 3.7's own tables (RenderOptions_INI_Table
     * and RenderOptions_Cmd_Table in frontend/processrenderoptions.cpp of
     * 3.7.0.10) has a row: honoured, ignored with why, or refused with why
     * (--povray-options lists them; the man page's POV-RAY OPTIONS too). */
    { .pov = "+I", .ini = "Input_File_Name", .type = OPT_STRING, .field = OPTION_FIELD(scene) },
    { .pov = "+Q", .ini = "Quality", .ini_as = INI_AS_SWITCH, .type = OPT_INT, .field = OPTION_FIELD(quality),
      .lo = 0, .hi = 11, .dflt = "9", .pov_expect = "quality must be 0 to 11" },
    { .pov = "+F", .ini = "Output_File_Type", .ini_as = INI_AS_SWITCH, .type = OPT_CUSTOM,
      .handler = output_type_switch, .given = OPTION_FIELD(output_type_given) },
    { .ini = "Output_To_File", .type = OPT_BOOL, .inverted = 1, .field = OPTION_FIELD(no_output) },
    { .ini = "Bits_Per_Color", .type = OPT_PARSED, .parse = parse_bits, .field = OPTION_FIELD(png16),
      .ini_expect = "1 to 16" },
    { .ini = "Bits_Per_Colour", .type = OPT_PARSED, .parse = parse_bits, .field = OPTION_FIELD(png16),
      .ini_expect = "1 to 16" }, /* POV-Ray's other spelling */
    /* POV-Ray keeps 0..255; JPEG's quality is it, up to 100 */
    { .ini = "Compression", .type = OPT_INT, .field = OPTION_FIELD(jpeg_quality), .lo = 0, .hi = 255,
      .ini_expect = "0 to 255" },
    { .pov = "+UA", .ini = "Output_Alpha", .ini_as = INI_AS_ON_OFF, .type = OPT_SIGN,
      .field = OPTION_FIELD(output_alpha) },
    { .ini = "Declare", .type = OPT_CUSTOM, .handler = declare_key },
    { .ini = "Include_Ini", .type = OPT_INCLUDE_INI },
    /* Gamma, as POV-Ray 3.7 applies it (options.h). */
    { .ini = "Display_Gamma", .type = OPT_CUSTOM, .handler = display_gamma_key },
    { .ini = "File_Gamma", .type = OPT_CUSTOM, .handler = file_gamma_key },
    { .pov = "+MV", .ini = "Version", .type = OPT_CUSTOM, .handler = version_switch },
    /* Anti-aliasing, as POV-Ray 3.7's. */
    { .pov = "+A", .ini = "Antialias", .ini_as = INI_AS_ON_OFF, .type = OPT_CUSTOM, .handler = antialias_switch },
    { .ini = "Antialias_Threshold", .type = OPT_REAL, .field = OPTION_FIELD(aa_threshold), .lo = 0.0,
      .hi = DBL_MAX, .dflt = "0.3", .ini_expect = "a number from 0" },
    { .pov = "+AM", .ini = "Sampling_Method", .type = OPT_INT, .field = OPTION_FIELD(aa_method), .lo = 1, .hi = 2,
      .dflt = "1", .pov_expect = "the sampling method is 1 or 2", .ini_expect = "1 or 2" },
    { .pov = "+R", .ini = "Antialias_Depth", .type = OPT_INT, .field = OPTION_FIELD(aa_depth), .lo = 1, .hi = 9,
      .dflt = "3", .pov_expect = "the anti-aliasing depth is 1 to 9", .ini_expect = "1 to 9" },
    { .pov = "+AG", .ini = "Antialias_Gamma", .type = OPT_REAL, .field = OPTION_FIELD(aa_gamma), .lo = 0.0,
      .hi = DBL_MAX, .dflt = "2.5", .pov_expect = "the anti-aliasing gamma is a number from 0",
      .ini_expect = "a number from 0" },
    { .pov = "+J", .ini = "Jitter", .ini_as = INI_AS_ON_OFF, .type = OPT_CUSTOM, .handler = jitter_switch,
      .dflt = "on" },
    { .ini = "Jitter_Amount", .type = OPT_REAL, .field = OPTION_FIELD(jitter_amount), .lo = 0.0, .hi = DBL_MAX,
      .dflt = "1", .ini_expect = "a number from 0" },
    /* The blocks POV-Ray renders, which its anti-aliasing decides in (from
     * 4 pixels: vfe/vfecontrol.cpp refuses less; a larger one than the
     * render area is the area, backend/scene/view.cpp). */
    { .pov = "+BS", .ini = "Render_Block_Size", .ini_as = INI_AS_SWITCH, .type = OPT_INT,
      .field = OPTION_FIELD(render_block_size), .lo = 4, .hi = 1000000000, .dflt = "32",
      .pov_expect = "the render block size is a whole number from 4" },
    /* No display window: main says so once (not for povray.ini's). */
    { .pov = "+D", .ini = "Display", .ini_as = INI_AS_ON_OFF, .type = OPT_SIGN,
      .field = OPTION_FIELD(display_asked), .ignore_rest = 1,
      .reason = "the display window: hstrace has none (a note says so)" },
    { .pov = "+P", .ini = "Pause_When_Done", .ini_as = INI_AS_ON_OFF, .type = OPT_SIGN,
      .field = OPTION_FIELD(pause_asked), .reason = "waits at the display window: hstrace has none (a note says so)" },
    /* The console streams: one handler reads the letter. */
    { .pov = "+GA", .ini = "All_Console", .ini_as = INI_AS_ON_OFF, .type = OPT_CUSTOM, .handler = stream_switch,
      .dflt = "on" },
    { .pov = "+GD", .ini = "Debug_Console", .ini_as = INI_AS_ON_OFF, .type = OPT_CUSTOM, .handler = stream_switch },
    { .pov = "+GF", .ini = "Fatal_Console", .ini_as = INI_AS_ON_OFF, .type = OPT_CUSTOM, .handler = stream_switch,
      .reason = "errors are always shown (an exit status alone would not say what went wrong)" },
    { .pov = "+GR", .ini = "Render_Console", .ini_as = INI_AS_ON_OFF, .type = OPT_CUSTOM,
      .handler = stream_switch },
    { .pov = "+GS", .ini = "Statistic_Console", .ini_as = INI_AS_ON_OFF, .type = OPT_CUSTOM,
      .handler = stream_switch },
    { .pov = "+GW", .ini = "Warning_Console", .ini_as = INI_AS_ON_OFF, .type = OPT_CUSTOM,
      .handler = stream_switch },
    { .pov = "+GP", .ini = "Append_File", .ini_as = INI_AS_ON_OFF, .type = OPT_CUSTOM, .handler = stream_switch,
      .reason = "appends to the console files, which hstrace does not write" },
    /* Animation (animation.h). Frame numbers are those of +KFF: a larger
     * one names no frame. */
    { .pov = "+KFI", .ini = "Initial_Frame", .ini_as = INI_AS_SWITCH, .type = OPT_INT,
      .field = OPTION_FIELD(initial_frame), .lo = 0, .hi = 1000000000, .dflt = "1",
      .pov_expect = "expected a frame number from 0" },
    { .pov = "+KFF", .ini = "Final_Frame", .ini_as = INI_AS_SWITCH, .type = OPT_INT,
      .field = OPTION_FIELD(final_frame), .lo = 0, .hi = 1000000000, .dflt = "1",
      .pov_expect = "expected a frame number from 0" },
    { .pov = "+KI", .ini = "Initial_Clock", .ini_as = INI_AS_SWITCH, .type = OPT_REAL,
      .field = OPTION_FIELD(initial_clock), .lo = -DBL_MAX, .hi = DBL_MAX, .pov_expect = "expected a number" },
    { .pov = "+KF", .ini = "Final_Clock", .ini_as = INI_AS_SWITCH, .type = OPT_REAL,
      .field = OPTION_FIELD(final_clock), .lo = -DBL_MAX, .hi = DBL_MAX, .dflt = "1",
      .pov_expect = "expected a number" },
    { .pov = "+KC", .ini = "Cyclic_Animation", .ini_as = INI_AS_ON_OFF, .type = OPT_SIGN,
      .field = OPTION_FIELD(cyclic), .ignore_rest = 1 },
    { .pov = "+K", .ini = "Clock", .ini_as = INI_AS_SWITCH, .type = OPT_REAL, .field = OPTION_FIELD(clock),
      .given = OPTION_FIELD(have_clock), .lo = -DBL_MAX, .hi = DBL_MAX, .pov_expect = "expected a number" },
    { .pov = "+SF", .ini = "Subset_Start_Frame", .ini_as = INI_AS_SWITCH, .type = OPT_REAL,
      .field = OPTION_FIELD(subset_start), .given = OPTION_FIELD(have_subset_start), .lo = 0.0, .hi = 1e9,
      .pov_expect = "expected a frame number or fraction from 0 to 1000000000" },
    { .pov = "+EF", .ini = "Subset_End_Frame", .ini_as = INI_AS_SWITCH, .type = OPT_REAL,
      .field = OPTION_FIELD(subset_end), .given = OPTION_FIELD(have_subset_end), .lo = 0.0, .hi = 1e9,
      .pov_expect = "expected a frame number or fraction from 0 to 1000000000" },
    /* Every n-th frame; below 1 is 1, as POV-Ray takes it. */
    { .pov = "+STP", .ini = "Frame_Step", .ini_as = INI_AS_SWITCH, .type = OPT_INT,
      .field = OPTION_FIELD(frame_step), .lo = -1000000000, .hi = 1000000000, .dflt = "1",
      .pov_expect = "expected a whole number" },
    /* Partial renders. No image has more rows or columns than
     * MAX_DIMENSION: a larger value names none (the image's own size is
     * checked at the end of options_parse). */
    { .pov = "+SR", .ini = "Start_Row", .ini_as = INI_AS_SWITCH, .type = OPT_REAL,
      .field = OPTION_FIELD(start_row), .given = OPTION_FIELD(have_start_row), .lo = 0.0, .hi = MAX_DIMENSION,
      .pov_expect = "expected a row or column (or fraction) from 0 to " MAX_DIMENSION_TEXT },
    { .pov = "+ER", .ini = "End_Row", .ini_as = INI_AS_SWITCH, .type = OPT_REAL,
      .field = OPTION_FIELD(end_row), .given = OPTION_FIELD(have_end_row), .lo = 0.0, .hi = MAX_DIMENSION,
      .pov_expect = "expected a row or column (or fraction) from 0 to " MAX_DIMENSION_TEXT },
    { .pov = "+SC", .ini = "Start_Column", .ini_as = INI_AS_SWITCH, .type = OPT_REAL,
      .field = OPTION_FIELD(start_col), .given = OPTION_FIELD(have_start_col), .lo = 0.0, .hi = MAX_DIMENSION,
      .pov_expect = "expected a row or column (or fraction) from 0 to " MAX_DIMENSION_TEXT },
    { .pov = "+EC", .ini = "End_Column", .ini_as = INI_AS_SWITCH, .type = OPT_REAL,
      .field = OPTION_FIELD(end_col), .given = OPTION_FIELD(have_end_col), .lo = 0.0, .hi = MAX_DIMENSION,
      .pov_expect = "expected a row or column (or fraction) from 0 to " MAX_DIMENSION_TEXT },

    /* ---- POV-Ray's keys and switches that cannot change the image or the files ---- */
    /* hstrace never leaves a partial image behind (it writes whole files),
     * so there is nothing to continue: the whole image is rendered. */
    IGNORED("Continue_Trace", "+C", "continues an interrupted render: hstrace writes whole files only, so it "
            "renders the whole image"),
    IGNORED("Verbose", "+V", "POV-Ray's verbose messages"),
    IGNORED_VALUE("Preview_Start_Size", "+SP", "the mosaic preview of the display window: hstrace has none"),
    IGNORED_VALUE("Preview_End_Size", "+EP", "the mosaic preview of the display window: hstrace has none"),
    IGNORED("Draw_Vistas", "+UD", "draws the vista buffer in the display window: hstrace has none"),
    IGNORED("Video_Mode", NULL, "the display window's mode: hstrace has none"),
    IGNORED("Palette", NULL, "the display window's palette: hstrace has none"),
    IGNORED_VALUE("Test_Abort", "+X", "polls the keyboard to stop a render (hstrace stops on a signal)"),
    IGNORED("Test_Abort_Count", NULL, "how often +X polls the keyboard"),
    IGNORED("Bounding", "+B", "POV-Ray's bounding: speed only (hstrace bounds in its own hierarchy)"),
    IGNORED_VALUE("Bounding_Method", "+BM", "POV-Ray's bounding: speed only (hstrace bounds in its own hierarchy)"),
    IGNORED_VALUE("Bounding_Threshold", "+MB", "POV-Ray's bounding: speed only (hstrace bounds in its own hierarchy)"),
    IGNORED("BSP_BaseAccessCost", NULL, "tunes POV-Ray's BSP tree: speed only"),
    IGNORED("BSP_ChildAccessCost", NULL, "tunes POV-Ray's BSP tree: speed only"),
    IGNORED("BSP_ISectCost", NULL, "tunes POV-Ray's BSP tree: speed only"),
    IGNORED("BSP_MaxDepth", NULL, "tunes POV-Ray's BSP tree: speed only"),
    IGNORED("BSP_MissChance", NULL, "tunes POV-Ray's BSP tree: speed only"),
    IGNORED("Light_Buffer", "+UL", "POV-Ray's light buffer: speed only, and POV-Ray 3.7 ignores it too"),
    IGNORED("Vista_Buffer", "+UV", "POV-Ray's vista buffer: speed only, and POV-Ray 3.7 ignores it too"),
    IGNORED("Remove_Bounds", "+UR", "POV-Ray's bounding: speed only"),
    IGNORED("Split_Unions", "+SU", "POV-Ray's bounding: speed only"),
    IGNORED_VALUE("Render_Block_Step", "+RS", "the order the blocks are rendered in: the image does not depend on it"),
    IGNORED_VALUE("Render_Pattern", "+RP", "the order the blocks are rendered in: the image does not depend on it"),
    IGNORED_VALUE("Max_Image_Buffer_Memory", "+MI", "POV-Ray's image buffer on disk: hstrace keeps the image in memory"),
    IGNORED_VALUE("Warning_Level", "+WL", "which of POV-Ray's own warnings it prints"),
    IGNORED("Buffer_Output", NULL, "no longer used by POV-Ray 3.7 (it warns and goes on)"),
    IGNORED("Buffer_Size", NULL, "no longer used by POV-Ray 3.7 (it warns and goes on)"),
    IGNORED("Create_Histogram", NULL, "no longer used by POV-Ray 3.7 (it warns and goes on)"),
    IGNORED("Histogram_Type", NULL, "no longer used by POV-Ray 3.7 (it warns and goes on)"),
    IGNORED("Histogram_Name", NULL, "no longer used by POV-Ray 3.7 (it warns and goes on)"),
    IGNORED("Histogram_Grid_Size", NULL, "no longer used by POV-Ray 3.7 (it warns and goes on)"),
    /* What only matters with a setting refused below. */
    IGNORED("Odd_Field", "+UO", "which field Field_Render renders (refused when on)"),
    IGNORED("Dither_Method", NULL, "how Dither dithers (refused when on)"),
    IGNORED_VALUE("Radiosity_File_Name", "+RF", "the file Radiosity_From_File and Radiosity_To_File use (refused when on)"),
    IGNORED("Radiosity_Vain_Pretrace", "+RVP", "radiosity's pretrace: hstrace approximates radiosity "
            "(APPROXIMATIONS in the man page)"),
    IGNORED("High_Reproducibility", "+HR", "radiosity's reproducibility: hstrace approximates radiosity "
            "(APPROXIMATIONS in the man page)"),
    IGNORED("Pre_Scene_Return", NULL, "acts on Pre_Scene_Command's exit status (the command is refused)"),
    IGNORED("Pre_Frame_Return", NULL, "acts on Pre_Frame_Command's exit status (the command is refused)"),
    IGNORED("Post_Scene_Return", NULL, "acts on Post_Scene_Command's exit status (the command is refused)"),
    IGNORED("Post_Frame_Return", NULL, "acts on Post_Frame_Command's exit status (the command is refused)"),
    IGNORED("User_Abort_Return", NULL, "acts on User_Abort_Command's exit status (the command is refused)"),
    IGNORED("Fatal_Error_Return", NULL, "acts on Fatal_Error_Command's exit status (the command is refused)"),

    /* ---- POV-Ray's keys and switches for what hstrace does not do ---- */
    UNSUPPORTED_ON("Field_Render", "+UF", "field rendering"),
    UNSUPPORTED_ON("Dither", "+TH", "dithering"),
    UNSUPPORTED_ON("Grayscale_Output", NULL, "greyscale output"),
    UNSUPPORTED_ON("Radiosity_From_File", "+RFI", "radiosity files"),
    UNSUPPORTED_ON("Radiosity_To_File", "+RFO", "radiosity files"),
    UNSUPPORTED_ON("Real_Time_Raytracing", "+RTR", "real-time ray tracing (a display loop)"),
    UNSUPPORTED_ON("Clockless_Animation", "+KLA", "clockless animation (real-time ray tracing's)"),
    UNSUPPORTED("Create_Ini", "+GI", "writing INI files"),
    UNSUPPORTED("Include_Header", "+HI", "an include file for every scene"),
    UNSUPPORTED("Pre_Scene_Command", NULL, "shell-out commands"),
    UNSUPPORTED("Pre_Frame_Command", NULL, "shell-out commands"),
    UNSUPPORTED("Post_Scene_Command", NULL, "shell-out commands"),
    UNSUPPORTED("Post_Frame_Command", NULL, "shell-out commands"),
    UNSUPPORTED("User_Abort_Command", NULL, "shell-out commands"),
    UNSUPPORTED("Fatal_Error_Command", NULL, "shell-out commands"),
    UNSUPPORTED("All_File", NULL, "console files"),
    UNSUPPORTED("Debug_File", NULL, "console files"),
    UNSUPPORTED("Fatal_File", NULL, "console files"),
    UNSUPPORTED("Render_File", NULL, "console files"),
    UNSUPPORTED("Statistic_File", NULL, "console files"),
    UNSUPPORTED("Warning_File", NULL, "console files"),
};

const size_t option_nrows = sizeof option_rows / sizeof option_rows[0];
