/* Command-line parsing. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "options.h"

#include "animation.h"
#include "aov.h"
#include "ini_file.h"
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
            "       hstrace FILE.ini[SECTION] [more INI files, switches, KEY=VALUE] [options]\n"
            "       hstrace compare A B [options]   (see hstrace compare --help)\n"
            "       hstrace vs-povray SCENE.pov [options]   (see hstrace vs-povray --help)\n"
            "\n"
            "Renders a POV-Ray scene made of polygons, with hybrid shadow testing; compares\n"
            "two images and two renderers' shadow masks; or measures every shadow method\n"
            "against POV-Ray on a scene.\n"
            "\n"
            "  -o, --output FILE      image to write (.exr .png .ppm .tga .bmp .jpg .hdr; default SCENE.png)\n"
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
            "4-5 shadows, 6-7 also refraction, >=8 also reflection; default 9); +FN[16] (PNG),\n"
            "+FE (EXR), +FP (PPM), +FT / +FC (Targa, plain / run-length), +FB (BMP), +FJ (JPEG,\n"
            "quality from the INI key Compression, default 85), +FH (Radiance HDR): the output\n"
            "type, +Oname without an extension gets its extension; +FS (system), +FNG (grey)\n"
            "and 16-bit PPM are refused; -F: write no image; -D -V are\n"
            "accepted and change nothing, +D with a note (no display window). A scene named\n"
            "without an extension is NAME.pov, as in POV-Ray.\n"
            "Anti-aliasing as POV-Ray 3.7's: +A[threshold] (0.3), -A, +AM1 / +AM2 (method),\n"
            "+Rn (depth, 3), +J[amount] / -J (POV-Ray's own jitter, on by default).\n"
            "+UA: an alpha channel (PNG, Targa, BMP; EXR always has one), the background\n"
            "transparent, as POV-Ray 3.7's; -UA (the default) composites it.\n"
            "+C (continue: hstrace leaves no partial image, so it renders all), +MV3.7,\n"
            "+SPn +EPn (mosaic preview: no display) are accepted; +P (pause) with a note, -P.\n"
            "Console streams: +GA -GA (all), +GD -GD (#debug), +GW -GW (warnings), +GR -GR\n"
            "(progress line), +GS -GS (--stats), +GF -GF +GP accepted; errors are always\n"
            "shown; a stream to a file (+GW name) and +GI name (an INI file) are refused.\n"
            "On a terminal a progress line shows the pixels done and the time left.\n"
            "Animation: +KFIn +KFFn (first and last frame), +KIf +KFf (their clocks), +KC\n"
            "(cyclic), +SFn +EFn (the frames rendered), +Kf (a still's clock); each frame is\n"
            "parsed and rendered anew and written to NAMEnn.EXT, as POV-Ray numbers them.\n"
            "Partial renders: +SRn +ERn +SCn +ECn (rows and columns from 1, or fractions below\n"
            "1), the rest of the image black, as POV-Ray writes them.\n"
            "POV-Ray INI files (FILE.ini, FILE.ini[SECTION]) and INI options given as KEY=VALUE\n"
            "(Input_File_Name, Output_File_Name, Width, Height, Quality, Work_Threads,\n"
            "Library_Path, Output_File_Type, Bits_Per_Color, Declare=NAME=VALUE, Initial_Frame,\n"
            "...: see the man page); settings apply in order, later ones winning.\n"
            "\n"
            "Exit status: 0 success, 1 bad usage (also a mistake in an INI file, a display,\n"
            "view or colour space the config lacks), 2 scene error, 3 input/output error (also\n"
            "an unreadable INI file, a missing or broken colour config).\n",
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

/* POV-Ray's +F: the output file's type (+FN[bits] PNG, +FE EXR, +FP PPM,
 * +FT Targa, +FC compressed Targa, +FB BMP, +FJ JPEG, +FH Radiance HDR;
 * -F none). Digits after the type are POV-Ray's bits per colour: PNG's
 * depth, ignored by the types that have one depth. */
static int output_type_switch(const char *arg, int on, Options *opt, char *err, int errlen)
{
    const char *t = arg + 2;
    if (!on) {
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
    if (t[1] && parse_int(t + 1, 1, 16, &bits)) {
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
static int stream_switch(const char *arg, int on, Options *opt, char *err, int errlen)
{
    int which = toupper((unsigned char)arg[2]);
    if (which == 'I') {
        snprintf(err, (size_t)errlen, "'%s': writing INI files is not supported by hstrace", arg);
        return -1;
    }
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

static int parse_double(const char *s, double *out)
{
    if (!s || !*s)
        return -1;
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (errno || *end || !isfinite(v))
        return -1;
    *out = v;
    return 0;
}

/* Animation's switches (+KFIn +KFFn +KIf +KFf +KC, +SFx +EFx, +Kf) and the
 * partial renders' (+SR +ER +SC +EC), which hstrace does not do yet. */
static int animation_switch(const char *arg, Options *opt, char *err, int errlen)
{
    const char *s = arg + 1;
    char a = (char)toupper((unsigned char)s[0]), b = (char)toupper((unsigned char)s[1]);
    char c = b ? (char)toupper((unsigned char)s[2]) : '\0';
    int bad = 0;
    if (a == 'K' && b == 'F' && (c == 'I' || c == 'F')) {
        int *slot = c == 'I' ? &opt->initial_frame : &opt->final_frame;
        bad = parse_int(s + 3, 0, 1000000000, slot);
    } else if (a == 'K' && b == 'C') {
        opt->cyclic = arg[0] == '+';
    } else if (a == 'K' && (b == 'I' || b == 'F')) {
        bad = parse_double(s + 2, b == 'I' ? &opt->initial_clock : &opt->final_clock);
    } else if (a == 'K') {
        bad = parse_double(s + 1, &opt->clock);
        opt->have_clock = 1;
    } else if ((a == 'S' || a == 'E') && b == 'F') {
        double *slot = a == 'S' ? &opt->subset_start : &opt->subset_end;
        bad = parse_double(s + 2, slot) || *slot < 0.0;
        if (a == 'S')
            opt->have_subset_start = 1;
        else
            opt->have_subset_end = 1;
    } else if ((a == 'S' || a == 'E') && b == 'P') {
        /* The mosaic preview's block sizes: they change only what a display
         * window would show first, and hstrace has none. */
        int size;
        bad = parse_int(s + 2, 1, 64, &size);
    } else if ((a == 'S' || a == 'E') && (b == 'R' || b == 'C')) {
        double *slot = a == 'S' ? (b == 'R' ? &opt->start_row : &opt->start_col)
                                : (b == 'R' ? &opt->end_row : &opt->end_col);
        int *have = a == 'S' ? (b == 'R' ? &opt->have_start_row : &opt->have_start_col)
                             : (b == 'R' ? &opt->have_end_row : &opt->have_end_col);
        bad = parse_double(s + 2, slot) || *slot < 0.0;
        *have = 1;
    } else {
        snprintf(err, (size_t)errlen, "unknown POV-Ray switch '%s'", arg);
        return -1;
    }
    if (bad) {
        snprintf(err, (size_t)errlen, "'%s': expected %s", arg,
                 a == 'K' && b == 'F' && (c == 'I' || c == 'F') ? "a frame number from 0" : "a number");
        return -1;
    }
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
    if (toupper((unsigned char)s[0]) == 'K' || ((toupper((unsigned char)s[0]) == 'S' || toupper((unsigned char)s[0]) == 'E') &&
                                               s[1] != '\0'))
        return animation_switch(arg, opt, err, errlen);
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
        if (toupper((unsigned char)s[1]) == 'M') {
            if (parse_int(s + 2, 1, 2, &opt->aa_method)) {
                snprintf(err, (size_t)errlen, "'%s': the sampling method is 1 or 2", arg);
                return -1;
            }
            return 0;
        }
        opt->antialias_on = on;
        opt->antialias_positioned = 0;
        if (on)
            snprintf(opt->antialias_by, sizeof opt->antialias_by, "'%s'", arg);
        if (s[1] && (parse_double(s + 1, &opt->aa_threshold) || opt->aa_threshold < 0.0)) {
            snprintf(err, (size_t)errlen, "'%s': the anti-aliasing threshold is a number from 0", arg);
            return -1;
        }
        return 0;
    case 'C': case 'c':
        if (s[1])
            break;
        /* Continue an interrupted render: hstrace never leaves a partial
         * image behind (it writes whole files), so there is nothing to
         * continue and the render is made whole. */
        return 0;
    case 'U': case 'u':
        if (toupper((unsigned char)s[1]) != 'A' || s[2])
            break;
        opt->output_alpha = on;
        return 0;
    case 'M': case 'm': {
        double v;
        if (toupper((unsigned char)s[1]) != 'V')
            break;
        if (parse_double(s + 2, &v) || fabs(v - 3.7) > 1e-9) {
            snprintf(err, (size_t)errlen, "'%s': hstrace reads scenes as POV-Ray 3.7 does (+MV3.7 only)", arg);
            return -1;
        }
        return 0;
    }
    case 'R': case 'r':
        if (parse_int(s + 1, 1, 9, &opt->aa_depth)) {
            snprintf(err, (size_t)errlen, "'%s': the anti-aliasing depth is 1 to 9", arg);
            return -1;
        }
        return 0;
    case 'J': case 'j':
        opt->jitter_on = on;
        if (s[1] && (parse_double(s + 1, &opt->jitter_amount) || opt->jitter_amount < 0.0)) {
            snprintf(err, (size_t)errlen, "'%s': the jitter amount is a number from 0", arg);
            return -1;
        }
        return 0;
    case 'F': case 'f':
        return output_type_switch(arg, on, opt, err, errlen);
    case 'D': case 'd':
        opt->display_asked = on; /* no display window: main says so once */
        return 0;
    case 'V': case 'v':
        return 0; /* verbosity */
    case 'P': case 'p':
        if (s[1])
            break;
        opt->pause_asked = on; /* no display window: main says so once */
        return 0;
    case 'G': case 'g':
        return stream_switch(arg, on, opt, err, errlen);
    default:
        break;
    }
    snprintf(err, (size_t)errlen, "unknown POV-Ray switch '%s'", arg);
    return -1;
}

/* ---- INI options and files (ini_file.h) ---------------------------------- */

/* A string the options own (freed by options_free). */
static char *own_string(Options *opt, const char *s, size_t n)
{
    char **grown = realloc(opt->strings, sizeof *grown * (size_t)(opt->nstrings + 1));
    if (!grown)
        return NULL;
    opt->strings = grown;
    char *copy = malloc(n + 1);
    if (!copy)
        return NULL;
    memcpy(copy, s, n);
    copy[n] = '\0';
    opt->strings[opt->nstrings++] = copy;
    return copy;
}

/* POV-Ray's truth values (ProcessOptions::IsTrue/IsFalse). */
static int parse_bool(const char *v, int *out)
{
    static const char *const yes[] = { "on", "true", "yes", "1" }, *const no[] = { "off", "false", "no", "0" };
    for (int i = 0; i < 4; i++) {
        if (strcasecmp(v, yes[i]) == 0)
            return *out = 1, 0;
        if (strcasecmp(v, no[i]) == 0)
            return *out = 0, 0;
    }
    return -1;
}

/* Declare=NAME=VALUE: a number, or a string in double quotes. */
static int add_declare(Options *opt, const char *text, char *err, int errlen)
{
    const char *eq = strchr(text, '=');
    if (!eq || eq == text) {
        snprintf(err, (size_t)errlen, "Declare=%s: expected Declare=NAME=VALUE", text);
        return -1;
    }
    OptionDeclare d = { own_string(opt, text, (size_t)(eq - text)), 0.0, NULL };
    const char *value = eq + 1, *quote = strchr(value, '"');
    if (quote) {
        const char *close = strchr(quote + 1, '"');
        if (!close) {
            snprintf(err, (size_t)errlen, "Declare=%s: the string is not closed", text);
            return -1;
        }
        d.string = own_string(opt, quote + 1, (size_t)(close - quote - 1));
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

/* The INI keys hstrace knows (POV-Ray 3.7's names, case ignored). */
typedef enum {
    KEY_SWITCH,   /* the same as the switch PREFIX followed by the value */
    KEY_BOOL,     /* on/off as the switch +PREFIX / -PREFIX */
    KEY_SCENE, KEY_OUTPUT, KEY_LIBRARY, KEY_DECLARE, KEY_BITS, KEY_COMPRESSION, KEY_INCLUDE_INI,
    KEY_AA,       /* anti-aliasing's settings (prefix: which) */
    KEY_IGNORED,  /* no effect on the image or the files (display, consoles, bounding) */
    KEY_UNSUPPORTED /* POV-Ray's, not hstrace's yet */
} KeyKind;

typedef struct {
    const char *name;
    KeyKind kind;
    const char *prefix; /* KEY_SWITCH, KEY_BOOL: the switch; KEY_UNSUPPORTED: what it is about */
} IniKey;

static const IniKey ini_keys[] = {
    { "Input_File_Name", KEY_SCENE, NULL },
    { "Output_File_Name", KEY_OUTPUT, NULL },
    { "Width", KEY_SWITCH, "+W" },
    { "Height", KEY_SWITCH, "+H" },
    { "Quality", KEY_SWITCH, "+Q" },
    { "Work_Threads", KEY_SWITCH, "+WT" },
    { "Output_File_Type", KEY_SWITCH, "+F" },
    { "Library_Path", KEY_LIBRARY, NULL },
    { "Bits_Per_Color", KEY_BITS, NULL },
    { "Declare", KEY_DECLARE, NULL },
    { "Include_Ini", KEY_INCLUDE_INI, NULL },
    { "Antialias", KEY_BOOL, "A" },
    { "Output_To_File", KEY_BOOL, "F" },
    { "Antialias_Threshold", KEY_AA, "threshold" },
    { "Antialias_Depth", KEY_AA, "depth" },
    { "Antialias_Gamma", KEY_AA, "gamma" },
    { "Sampling_Method", KEY_AA, "method" },
    { "Jitter_Amount", KEY_AA, "amount" },
    { "Jitter", KEY_BOOL, "J" },
    { "Display", KEY_BOOL, "D" },
    { "Display_Gamma", KEY_IGNORED, NULL },
    { "Verbose", KEY_IGNORED, NULL },
    { "Pause_When_Done", KEY_BOOL, "P" },
    { "Draw_Vistas", KEY_IGNORED, NULL },
    { "Preview_Start_Size", KEY_IGNORED, NULL },
    { "Preview_End_Size", KEY_IGNORED, NULL },
    { "Test_Abort", KEY_IGNORED, NULL },
    { "Test_Abort_Count", KEY_IGNORED, NULL },
    { "Bounding", KEY_IGNORED, NULL },
    { "Bounding_Method", KEY_IGNORED, NULL },
    { "Bounding_Threshold", KEY_IGNORED, NULL },
    { "Light_Buffer", KEY_IGNORED, NULL },
    { "Vista_Buffer", KEY_IGNORED, NULL },
    { "Remove_Bounds", KEY_IGNORED, NULL },
    { "Split_Unions", KEY_IGNORED, NULL },
    { "All_Console", KEY_BOOL, "GA" },
    { "Debug_Console", KEY_BOOL, "GD" },
    { "Fatal_Console", KEY_IGNORED, NULL }, /* errors are always shown */
    { "Render_Console", KEY_BOOL, "GR" },
    { "Statistic_Console", KEY_BOOL, "GS" },
    { "Warning_Console", KEY_BOOL, "GW" },
    { "Warning_Level", KEY_IGNORED, NULL },
    { "Initial_Frame", KEY_SWITCH, "+KFI" },
    { "Final_Frame", KEY_SWITCH, "+KFF" },
    { "Initial_Clock", KEY_SWITCH, "+KI" },
    { "Final_Clock", KEY_SWITCH, "+KF" },
    { "Subset_Start_Frame", KEY_SWITCH, "+SF" },
    { "Subset_End_Frame", KEY_SWITCH, "+EF" },
    { "Cyclic_Animation", KEY_BOOL, "KC" },
    { "Field_Render", KEY_UNSUPPORTED, "field rendering" },
    { "Odd_Field", KEY_UNSUPPORTED, "field rendering" },
    { "Clock", KEY_SWITCH, "+K" },
    { "Frame_Step", KEY_UNSUPPORTED, "frame steps (POV-Ray 3.8)" },
    { "Start_Row", KEY_SWITCH, "+SR" },
    { "End_Row", KEY_SWITCH, "+ER" },
    { "Start_Column", KEY_SWITCH, "+SC" },
    { "End_Column", KEY_SWITCH, "+EC" },
    { "Continue_Trace", KEY_UNSUPPORTED, "continuing a render" },
    { "Create_Continue_Trace_Log", KEY_UNSUPPORTED, "continuing a render" },
    { "Output_Alpha", KEY_BOOL, "UA" },
    { "Compression", KEY_COMPRESSION, NULL },
    { "Create_Ini", KEY_UNSUPPORTED, "writing INI files" },
    { "Histogram_Type", KEY_UNSUPPORTED, "histograms" },
    { "Histogram_Name", KEY_UNSUPPORTED, "histograms" },
    { "Histogram_Grid_Size", KEY_UNSUPPORTED, "histograms" },
    { "Dither", KEY_UNSUPPORTED, "dithering" },
    { "Dither_Method", KEY_UNSUPPORTED, "dithering" },
    { "File_Gamma", KEY_UNSUPPORTED, "output gamma" },
    { "Radiosity_From_File", KEY_UNSUPPORTED, "radiosity files" },
    { "Radiosity_To_File", KEY_UNSUPPORTED, "radiosity files" },
    { "Radiosity_File_Name", KEY_UNSUPPORTED, "radiosity files" },
    { "Radiosity_Vain_Pretrace", KEY_UNSUPPORTED, "radiosity" },
    { "High_Reproducibility", KEY_UNSUPPORTED, "radiosity" },
    { "Pre_Scene_Command", KEY_UNSUPPORTED, "shell-out commands" },
    { "Pre_Frame_Command", KEY_UNSUPPORTED, "shell-out commands" },
    { "Post_Scene_Command", KEY_UNSUPPORTED, "shell-out commands" },
    { "Post_Frame_Command", KEY_UNSUPPORTED, "shell-out commands" },
    { "User_Abort_Command", KEY_UNSUPPORTED, "shell-out commands" },
    { "Fatal_Error_Command", KEY_UNSUPPORTED, "shell-out commands" },
    { "Include_Header", KEY_UNSUPPORTED, "an include file for every scene" },
    { "All_File", KEY_UNSUPPORTED, "console files" },
    { "Debug_File", KEY_UNSUPPORTED, "console files" },
    { "Fatal_File", KEY_UNSUPPORTED, "console files" },
    { "Render_File", KEY_UNSUPPORTED, "console files" },
    { "Statistic_File", KEY_UNSUPPORTED, "console files" },
    { "Warning_File", KEY_UNSUPPORTED, "console files" },
    { "Video_Mode", KEY_UNSUPPORTED, "the display" },
    { "Palette", KEY_UNSUPPORTED, "the display" },
    { "Buffer_Output", KEY_IGNORED, NULL },
    { "Buffer_Size", KEY_IGNORED, NULL },
};

static int read_ini(Options *opt, const char *spec, int depth, char *err, int errlen);

/* An INI file named at where (Include_Ini=, or a word naming one) could
 * not be read: its message ("cannot open INI file ...") gets where's
 * FILE:LINE:COLUMN in front, as every mistake of an INI file has. A
 * message that has one already (a mistake inside the file) is kept. */
static void position_error(Options *opt, const char *where, char *err, int errlen)
{
    if (!where || opt->error_has_position)
        return;
    char msg[1024];
    snprintf(msg, sizeof msg, "%s", err);
    snprintf(err, (size_t)errlen, "%s: %s", where, msg);
    opt->error_has_position = 1;
}

/* One KEY=VALUE, from an INI file (where: "FILE:LINE:COLUMN") or the
 * command line (where: NULL). */
static int apply_key(Options *opt, const char *key, const char *value, const char *where, int depth, char *err,
                     int errlen)
{
    const IniKey *k = NULL;
    for (size_t i = 0; i < sizeof ini_keys / sizeof ini_keys[0] && !k; i++)
        if (strcasecmp(ini_keys[i].name, key) == 0)
            k = &ini_keys[i];
    char msg[768];
    int status = 0, b;
    msg[0] = '\0';
    if (!k) {
        snprintf(msg, sizeof msg, "unknown INI key '%s'", key);
        status = -1;
    } else {
        switch (k->kind) {
        case KEY_SWITCH: {
            char sw[600];
            snprintf(sw, sizeof sw, "%s%s", k->prefix, value);
            char *own = own_string(opt, sw, strlen(sw));
            status = own ? parse_pov_switch(own, opt, msg, (int)sizeof msg) : -1;
            break;
        }
        case KEY_BOOL:
            if (parse_bool(value, &b)) {
                snprintf(msg, sizeof msg, "%s=%s: expected on or off", k->name, value);
                status = -1;
            } else if (k->prefix[0] == 'K') {
                opt->cyclic = b; /* Cyclic_Animation */
            } else if (k->prefix[0] == 'U') {
                opt->output_alpha = b; /* Output_Alpha */
            } else if (k->prefix[0] == 'D') {
                opt->display_asked = b; /* Display */
            } else if (k->prefix[0] == 'P') {
                opt->pause_asked = b; /* Pause_When_Done */
            } else if (k->prefix[0] == 'G') {
                /* All_Console, Debug_Console, ...: the stream's letter */
                if (k->prefix[1] == 'A' || k->prefix[1] == 'D')
                    opt->debug_console = b;
                if (k->prefix[1] == 'A' || k->prefix[1] == 'W')
                    opt->warning_console = b;
                if (k->prefix[1] == 'A' || k->prefix[1] == 'R')
                    opt->render_console = b;
                if (k->prefix[1] == 'A' || k->prefix[1] == 'S')
                    opt->statistics_console = b;
            } else if (k->prefix[0] == 'J') {
                opt->jitter_on = b; /* Jitter */
            } else if (k->prefix[0] == 'A') {
                opt->antialias_on = b;
                if (b) {
                    snprintf(opt->antialias_by, sizeof opt->antialias_by, "%s%s%s=%s", where ? where : "",
                             where ? ": " : "", k->name, value);
                    opt->antialias_positioned = where != NULL;
                }
            } else {
                opt->no_output = !b; /* Output_To_File */
            }
            break;
        case KEY_SCENE:
            opt->scene = value;
            break;
        case KEY_OUTPUT:
            opt->output = value;
            break;
        case KEY_LIBRARY:
            status = add_include(opt, value, msg, (int)sizeof msg);
            break;
        case KEY_DECLARE:
            status = add_declare(opt, value, msg, (int)sizeof msg);
            break;
        case KEY_BITS:
            if (parse_int(value, 1, 16, &b)) {
                snprintf(msg, sizeof msg, "Bits_Per_Color=%s: expected 1 to 16", value);
                status = -1;
            } else {
                opt->png16 = b > 8;
            }
            break;
        case KEY_COMPRESSION:
            /* POV-Ray keeps 0..255; JPEG's quality is it, up to 100 */
            if (parse_int(value, 0, 255, &b)) {
                snprintf(msg, sizeof msg, "Compression=%s: expected 0 to 255", value);
                status = -1;
            } else {
                opt->jpeg_quality = b;
            }
            break;
        case KEY_INCLUDE_INI:
            if (depth >= 16) {
                snprintf(msg, sizeof msg, "Include_Ini=%s: INI files included more than 16 deep", value);
                status = -1;
            } else if (read_ini(opt, value, depth + 1, err, errlen)) {
                position_error(opt, where, err, errlen);
                return -1;
            }
            break;
        case KEY_AA: {
            double v;
            int bad = parse_double(value, &v) || v < 0.0;
            if (!bad && strcmp(k->prefix, "threshold") == 0)
                opt->aa_threshold = v;
            else if (!bad && strcmp(k->prefix, "gamma") == 0)
                opt->aa_gamma = v;
            else if (!bad && strcmp(k->prefix, "amount") == 0)
                opt->jitter_amount = v;
            else if (!bad && strcmp(k->prefix, "depth") == 0)
                bad = parse_int(value, 1, 9, &opt->aa_depth);
            else if (!bad)
                bad = parse_int(value, 1, 2, &opt->aa_method);
            if (bad) {
                snprintf(msg, sizeof msg, "%s=%s: expected %s", k->name, value,
                         strcmp(k->prefix, "depth") == 0    ? "1 to 9"
                         : strcmp(k->prefix, "method") == 0 ? "1 or 2"
                                                            : "a number from 0");
                status = -1;
            }
            break;
        }
        case KEY_IGNORED:
            break;
        case KEY_UNSUPPORTED:
            snprintf(msg, sizeof msg, "%s: %s is not supported by hstrace yet", k->name, k->prefix);
            status = -1;
            break;
        }
    }
    if (status) {
        if (where) {
            snprintf(err, (size_t)errlen, "%s: %s", where, msg);
            opt->error_has_position = 1;
        } else {
            snprintf(err, (size_t)errlen, "%s", msg);
        }
    }
    return status;
}

static int read_ini(Options *opt, const char *spec, int depth, char *err, int errlen)
{
    IniFile *grown = realloc(opt->inis, sizeof *grown * (size_t)(opt->ninis + 1));
    if (!grown) {
        snprintf(err, (size_t)errlen, "out of memory");
        return -1;
    }
    opt->inis = grown;
    IniFile *f = &opt->inis[opt->ninis++];
    if (ini_file_read(f, spec, err, errlen)) {
        /* Unreadable: an input/output error; else a mistake at its place. */
        opt->error_is_io = strncmp(err, "cannot ", 7) == 0 || strstr(err, "too big for an INI file") != NULL;
        opt->error_has_position = !opt->error_is_io && strncmp(err, "out of memory", 13) != 0;
        return -1;
    }
    /* f may move as included files are added: keep what is needed. */
    int n = f->n;
    IniEntry *entries = f->entries;
    const char *path = f->path;
    for (int i = 0; i < n; i++) {
        const IniEntry *e = &entries[i];
        char where[600];
        snprintf(where, sizeof where, "%s:%d:%d", path, e->line, e->column);
        if (e->kind == INI_OPTION) {
            if (apply_key(opt, e->key, e->value, where, depth, err, errlen))
                return -1;
        } else if (e->kind == INI_SWITCH) {
            char msg[600];
            if (parse_pov_switch(e->key, opt, msg, (int)sizeof msg)) {
                snprintf(err, (size_t)errlen, "%s: %s", where, msg);
                opt->error_has_position = 1;
                return -1;
            }
            if (toupper((unsigned char)e->key[1]) == 'A' && opt->antialias_on) {
                snprintf(opt->antialias_by, sizeof opt->antialias_by, "%s: '%s'", where, e->key);
                opt->antialias_positioned = 1;
            }
        } else if (ini_spec_is_ini(e->key)) {
            if (depth >= 16) {
                snprintf(err, (size_t)errlen, "%s: INI files included more than 16 deep", where);
                opt->error_has_position = 1;
                return -1;
            }
            if (read_ini(opt, e->key, depth + 1, err, errlen)) {
                position_error(opt, where, err, errlen);
                return -1;
            }
        } else if (opt->scene && strcmp(opt->scene, e->key) != 0) {
            snprintf(err, (size_t)errlen, "%s: more than one scene given ('%s' and '%s')", where, opt->scene, e->key);
            opt->error_has_position = 1;
            return -1;
        } else {
            opt->scene = e->key;
        }
    }
    return 0;
}

/* KEY=VALUE on the command line (Declare=X=1, Width=640), as POV-Ray takes it. */
static int is_key_value(const char *a)
{
    if (!(isalpha((unsigned char)a[0]) || a[0] == '_'))
        return 0;
    const char *p = a;
    while (isalnum((unsigned char)*p) || *p == '_')
        p++;
    return *p == '=';
}

/* The pixels a partial render covers, as POV-Ray 3.7 works them out from
 * +SR +ER +SC +EC (measured with 3.7.0.10): a start of 1 or more is a row
 * counted from 1, below 1 a fraction of the height; an end above 1 is a
 * row counted from 1, up to 1 a fraction (+ER1 is the last row); fractions
 * are cut down to whole rows. An end beyond the image is an error, as in
 * POV-Ray; an empty area too (POV-Ray renders nothing). */
static int area_side(int have_start, double start, int have_end, double end, int size, int *lo, int *hi,
                     const char *what, char *err, int errlen)
{
    double first = !have_start ? 0.0 : start >= 1.0 ? start - 1.0 : start * size;
    double last = !have_end ? size - 1.0 : end > 1.0 ? end - 1.0 : end * size - 1.0;
    if (last >= size) {
        snprintf(err, (size_t)errlen, "the render area's end %s (%g) is beyond the image's %d", what, end, size);
        return -1;
    }
    *lo = (int)first;
    *hi = (int)last + 1;
    if (last < 0.0 || *lo >= *hi) {
        snprintf(err, (size_t)errlen, "the render area is empty: %ss %g to %g of %d", what, have_start ? start : 1.0,
                 have_end ? end : (double)size, size);
        return -1;
    }
    return 0;
}

static int render_area(Options *opt, char *err, int errlen)
{
    return area_side(opt->have_start_row, opt->start_row, opt->have_end_row, opt->end_row, opt->height,
                     &opt->area_y0, &opt->area_y1, "row", err, errlen) ||
                   area_side(opt->have_start_col, opt->start_col, opt->have_end_col, opt->end_col, opt->width,
                             &opt->area_x0, &opt->area_x1, "column", err, errlen)
               ? -1
               : 0;
}

/* A scene named without an extension is NAME.pov when NAME itself is not a
 * file and NAME.pov is, as POV-Ray takes "povray +Idesk". */
static int find_scene(Options *opt, char *err, int errlen)
{
    const char *base = strrchr(opt->scene, '/');
    base = base ? base + 1 : opt->scene;
    if (strchr(base, '.') || access(opt->scene, F_OK) == 0)
        return 0;
    size_t n = strlen(opt->scene);
    char *pov = malloc(n + 5);
    if (!pov) {
        snprintf(err, (size_t)errlen, "out of memory");
        return -1;
    }
    memcpy(pov, opt->scene, n);
    memcpy(pov + n, ".pov", 5);
    if (access(pov, F_OK) == 0)
        opt->scene = own_string(opt, pov, n + 4);
    free(pov);
    if (!opt->scene) {
        snprintf(err, (size_t)errlen, "out of memory");
        return -1;
    }
    return 0;
}

void options_free(Options *opt)
{
    for (int i = 0; i < opt->ninis; i++)
        ini_file_free(&opt->inis[i]);
    free(opt->inis);
    for (int i = 0; i < opt->nstrings; i++)
        free(opt->strings[i]);
    free(opt->strings);
    free(opt->declares);
    opt->inis = NULL;
    opt->strings = NULL;
    opt->declares = NULL;
    opt->ninis = opt->nstrings = opt->ndeclares = 0;
}

const char *options_output_extension(const Options *opt)
{
    switch (opt->output_type) {
    case 'E': return ".exr";
    case 'P': return ".ppm";
    case 'T': case 'C': return ".tga";
    case 'B': return ".bmp";
    case 'J': return ".jpg";
    case 'H': return ".hdr";
    default: return ".png";
    }
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
    opt->initial_frame = opt->final_frame = 1;
    opt->debug_console = opt->warning_console = opt->render_console = opt->statistics_console = 1;
    opt->aa_threshold = 0.3;
    opt->aa_method = 1;
    opt->aa_depth = 3;
    opt->aa_gamma = 2.5;
    opt->jitter_on = 1;
    opt->jitter_amount = 1.0;
    opt->final_clock = 1.0;
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
        } else if (is_key_value(a)) {
            /* before the INI file names: Include_Ini=more.ini is the key,
             * as POV-Ray takes it, not a file of that name */
            char key[128];
            size_t n = (size_t)(strchr(a, '=') - a);
            snprintf(key, sizeof key, "%.*s", (int)(n < sizeof key - 1 ? n : sizeof key - 1), a);
            if (apply_key(opt, key, a + n + 1, NULL, 0, err, errlen))
                return -1;
        } else if (ini_spec_is_ini(a)) {
            if (read_ini(opt, a, 0, err, errlen))
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
    if (render_area(opt, err, errlen))
        return -1;
    if (opt->scene && find_scene(opt, err, errlen))
        return -1;
    if (opt->antialias_on && opt->aov) {
        snprintf(err, (size_t)errlen, "--aov with anti-aliasing is not supported yet");
        return -1;
    }
    if (opt->output_type && opt->output) {
        /* +Oname without an extension gets the type's, as in POV-Ray; one
         * with another type's extension is a contradiction. */
        const char *base = strrchr(opt->output, '/'), *dot;
        base = base ? base + 1 : opt->output;
        dot = strrchr(base, '.');
        const char *ext = options_output_extension(opt);
        if (!dot) {
            size_t n = strlen(opt->output);
            char *named = malloc(n + 5);
            if (named) {
                memcpy(named, opt->output, n);
                memcpy(named + n, ext, 5);
                opt->output = own_string(opt, named, n + 4);
                free(named);
            }
            if (!named || !opt->output) {
                snprintf(err, (size_t)errlen, "out of memory");
                return -1;
            }
        } else if (strcasecmp(dot, ext) != 0 && !(opt->output_type == 'J' && strcasecmp(dot, ".jpeg") == 0)) {
            snprintf(err, (size_t)errlen, "+F%c asks for %s, but the output '%s' is named for another type",
                     opt->output_type, ext + 1, opt->output);
            return -1;
        }
    }
    if ((double)opt->width * opt->height > (double)(1 << 28)) {
        snprintf(err, (size_t)errlen, "image of %dx%d pixels is too large (at most 268435456 pixels)", opt->width,
                 opt->height);
        return -1;
    }
    return 0;
}
