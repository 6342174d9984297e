/* Command-line parsing: the long options, POV-Ray's switches and INI keys
 * as the options' table (options_table.c) describes them, INI files, and
 * what is worked out from the settings at the end. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "options.h"

#include "ini_file.h"
#include "options_table.h"
#include "povray_ini.h"
#include "shadow.h"

int option_parse_int(const char *s, int lo, int hi, int *out)
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
int options_parse_size(const char *s, size_t *out)
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


static const char usage_head[] =
    "usage: hstrace SCENE.pov [options]\n"
    "       hstrace FILE.ini[SECTION] [more INI files, switches, KEY=VALUE] [options]\n"
    "       hstrace compare A B [options]   (see hstrace compare --help)\n"
    "       hstrace vs-povray SCENE.pov [options]   (see hstrace vs-povray --help)\n"
    "       hstrace stitch PART.exr... -o FULL.exr   (see hstrace stitch --help)\n"
    "\n"
    "Renders a POV-Ray scene made of polygons, with hybrid shadow testing; compares\n"
    "two images and two renderers' shadow masks; measures every shadow method\n"
    "against POV-Ray on a scene; or joins the parts of a partial render.\n"
    "\n";

/* What POV-Ray's switches and INI keys do, after the table of long options. */
static const char usage_tail[] =
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
    "+Rn (depth, 3), +J[amount] / -J (POV-Ray's own jitter, on by default), +AGn\n"
    "(Antialias_Gamma, 2.5), +BSn (Render_Block_Size: the blocks it decides in, 32).\n"
    "+UA: an alpha channel (PNG, Targa, BMP; EXR always has one), the background\n"
    "transparent, as POV-Ray 3.7's; -UA (the default) composites it.\n"
    "+C (continue: hstrace leaves no partial image, so it renders all), +MV3.7,\n"
    "+SPn +EPn (mosaic preview: no display) are accepted; +P (pause) with a note, -P.\n"
    "Console streams: +GA -GA (all), +GD -GD (#debug), +GW -GW (warnings), +GR -GR\n"
    "(progress line), +GS -GS (--stats), +GF -GF +GP accepted; errors are always\n"
    "shown; a stream to a file (+GW name) and +GI name (an INI file) are refused.\n"
    "On a terminal a progress line shows the pixels done and the time left.\n"
    "Animation: +KFIn +KFFn (first and last frame), +KIf +KFf (their clocks), +KC\n"
    "(cyclic), +SFn +EFn (the frames rendered), +STPn (every n-th of them), +Kf (a\n"
    "still's clock); each frame is parsed and rendered anew and written to\n"
    "NAMEnn.EXT, as POV-Ray numbers them.\n"
    "Partial renders: +SRn +ERn +SCn +ECn (rows and columns from 1, or fractions below\n"
    "1), the rest of the image black, as POV-Ray writes them.\n"
    "Accepted and ignored, since they cannot change the image or the files: +B +BMn\n"
    "+MBn +SU +UR +UL +UV (POV-Ray's bounding and buffers), +UD, +X, +WLn, +MIn, +RSn\n"
    "+RPn (the blocks' order), +UO, +RFname, +RVP, +HR. Refused, with why: +UF (field\n"
    "rendering), +TH (dithering), +RFI +RFO (radiosity files), +RTR +KLA (real-time\n"
    "ray tracing), +HI (an include header); their - forms (off) are accepted.\n"
    "--povray-options lists every POV-Ray INI key and switch and what hstrace does.\n"
    "POV-Ray INI files (FILE.ini, FILE.ini[SECTION]) and INI options given as KEY=VALUE\n"
    "(Input_File_Name, Output_File_Name, Width, Height, Quality, Work_Threads,\n"
    "Library_Path, Output_File_Type, Bits_Per_Color, File_Gamma, Version,\n"
    "Declare=NAME=VALUE, Initial_Frame, ...: see the man page); settings apply in\n"
    "order, later ones winning, after the povray.ini POV-Ray reads ($POVINI, else\n"
    "./povray.ini, ~/.povray/3.7/povray.ini, /etc/povray/3.7/povray.ini: the first\n"
    "found; --no-povray-ini reads none) and before $POVINC's include folder.\n"
    "\n"
    "Exit status: 0 success, 1 bad usage (also a mistake in an INI file, a display,\n"
    "view or colour space the config lacks), 2 scene error, 3 input/output error (also\n"
    "an unreadable INI file, a missing or broken colour config).\n";

/* The table's rows with a long option and a description, each as
 * "  -o, --output FILE" then its description from OPTION_HELP_COLUMN (two
 * spaces after a longer head), a description's further lines indented. */
void options_usage(FILE *f)
{
    char indent[OPTION_HELP_COLUMN + 1];
    memset(indent, ' ', OPTION_HELP_COLUMN);
    indent[OPTION_HELP_COLUMN] = '\0';
    fputs(usage_head, f);
    for (size_t i = 0; i < option_nrows; i++) {
        const OptionRow *r = &option_rows[i];
        if (!r->name || !r->help)
            continue;
        int n = fprintf(f, "  %s%s%s%s%s", r->short_name ? r->short_name : "  ", r->short_name ? ", " : "  ",
                        r->name, r->value_name ? " " : "", r->value_name ? r->value_name : "");
        fprintf(f, "%*s", n < OPTION_HELP_COLUMN ? OPTION_HELP_COLUMN - n : 2, "");
        for (const char *line = r->help; *line;) {
            size_t len = strcspn(line, "\n");
            fprintf(f, "%s%.*s\n", line == r->help ? "" : indent, (int)len, line);
            line += len + (line[len] == '\n');
        }
        if (r->help_tail)
            r->help_tail(f, indent);
    }
    fputs(usage_tail, f);
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

int option_add_include(Options *opt, const char *dir, char *err, int errlen)
{
    /* A folder named again is searched where it was first named, as POV-Ray
     * drops the repeats of its library paths (vfe/vfecontrol.cpp): povray.ini
     * and a command line often name the same ones. */
    for (int i = 0; i < opt->ninclude_paths; i++)
        if (strcmp(opt->include_paths[i], dir) == 0)
            return 0;
    if (opt->ninclude_paths >= MAX_INCLUDE_PATHS) {
        snprintf(err, (size_t)errlen, "too many include paths (at most %d)", MAX_INCLUDE_PATHS);
        return -1;
    }
    opt->include_paths[opt->ninclude_paths++] = dir;
    return 0;
}
int option_parse_double(const char *s, double *out)
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

/* ---- the table's rows as long options, switches and INI keys ------------- */

static void *field_of(Options *opt, size_t field)
{
    return (char *)opt + field - 1;
}

#define INT_FIELD(opt, r) ((int *)field_of(opt, (r)->field))
#define DOUBLE_FIELD(opt, r) ((double *)field_of(opt, (r)->field))
#define STRING_FIELD(opt, r) ((const char **)field_of(opt, (r)->field))

static int in_range(const OptionRow *r, double x)
{
    return (r->lo_open ? x > r->lo : x >= r->lo) && x <= r->hi;
}

/* The row of a long option ("--width", "--width=N", "-o"); a flag only
 * alone ("--stats=1" is no option). */
static const OptionRow *long_row(const char *a)
{
    for (size_t i = 0; i < option_nrows; i++) {
        const OptionRow *r = &option_rows[i];
        if ((r->short_name && strcmp(a, r->short_name) == 0) ||
            (r->name && (r->type == OPT_FLAG ? strcmp(a, r->name) == 0 : is_long(a, r->name))))
            return r;
    }
    return NULL;
}

/* A long option's value (also a row's default). Numbers are read as strtod
 * reads them (1e-400 is 0), as the options always have been. */
static int long_value(const OptionRow *r, const char *v, Options *opt, char *err, int errlen)
{
    int bad = 0;
    switch (r->type) {
    case OPT_INT:
        bad = option_parse_int(v, (int)r->lo, (int)r->hi, INT_FIELD(opt, r));
        break;
    case OPT_REAL: {
        char *end;
        double x = strtod(v, &end);
        bad = end == v || *end != '\0' || !in_range(r, x);
        if (!bad)
            *DOUBLE_FIELD(opt, r) = x;
        break;
    }
    case OPT_COUNT:
        if (r->lo == 0 && strcmp(v, "0") == 0)
            *(long *)field_of(opt, r->field) = 0;
        else
            bad = parse_count(v, field_of(opt, r->field));
        break;
    case OPT_SIZE:
        bad = options_parse_size(v, field_of(opt, r->field));
        break;
    case OPT_WORDS: {
        const OptionWord *w = r->words;
        while (w->word && strcmp(w->word, v) != 0)
            w++;
        bad = !w->word;
        if (!bad)
            *INT_FIELD(opt, r) = w->value;
        break;
    }
    case OPT_PARSED:
        bad = r->parse(v, field_of(opt, r->field));
        break;
    case OPT_NAME:
        if (v[0] == '\0') {
            snprintf(err, (size_t)errlen, "%s: the name is empty", r->name);
            return -1;
        }
        *STRING_FIELD(opt, r) = v;
        break;
    case OPT_STRING:
        *STRING_FIELD(opt, r) = v;
        break;
    case OPT_LIST:
        return option_add_include(opt, v, err, errlen);
    case OPT_CUSTOM:
        return r->handler(r, r->name, v, opt, err, errlen);
    default:
        bad = 1;
        break;
    }
    if (bad) {
        snprintf(err, (size_t)errlen, "%s '%s': %s", r->name, v, r->expect);
        return -1;
    }
    return 0;
}

/* argv[*i] is r's long option: its value, if it takes one, from "=value"
 * or the next word. */
static int long_option(const OptionRow *r, int argc, char **argv, int *i, Options *opt, char *err, int errlen)
{
    const char *a = argv[*i];
    if (r->type == OPT_UNSUPPORTED) {
        snprintf(err, (size_t)errlen, "'%s': %s is not supported by hstrace (make bench runs hstrace's own)", a,
                 r->reason);
        return -1;
    }
    if (r->type == OPT_FLAG) {
        int *level = INT_FIELD(opt, r);
        if (*level < (int)r->lo)
            *level = (int)r->lo;
        return 0;
    }
    const char *v = option_value(argc, argv, i, r->short_name && strcmp(a, r->short_name) == 0 ? r->short_name : r->name,
                                 err, errlen);
    return v ? long_value(r, v, opt, err, errlen) : -1;
}

/* The row of a switch ("+WT4" is +WT's, "+W640" +W's): the longest of the
 * table's switches that begins it, case ignored. */
static const OptionRow *switch_row(const char *arg)
{
    const OptionRow *best = NULL;
    size_t longest = 0;
    for (size_t i = 0; i < option_nrows; i++) {
        const OptionRow *r = &option_rows[i];
        size_t n = r->pov ? strlen(r->pov + 1) : 0;
        if (n > longest && strncasecmp(arg + 1, r->pov + 1, n) == 0) {
            best = r;
            longest = n;
        }
    }
    return best;
}

/* POV-Ray switches: +X or -X followed by a value where it has one. */
static int parse_pov_switch(const char *arg, Options *opt, char *err, int errlen)
{
    const OptionRow *r = switch_row(arg);
    if (!r) {
        snprintf(err, (size_t)errlen, "unknown POV-Ray switch '%s'", arg);
        return -1;
    }
    const char *v = arg + strlen(r->pov);
    int on = arg[0] == '+', bad = 0;
    if (r->given)
        *(int *)field_of(opt, r->given) = 1;
    switch (r->type) {
    case OPT_INT: {
        int unused;
        bad = option_parse_int(v, (int)r->lo, (int)r->hi, r->field ? INT_FIELD(opt, r) : &unused);
        break;
    }
    case OPT_REAL: {
        double x;
        bad = option_parse_double(v, &x) || !in_range(r, x);
        if (!bad)
            *DOUBLE_FIELD(opt, r) = x;
        break;
    }
    case OPT_STRING:
        if (!*v)
            break;
        *STRING_FIELD(opt, r) = v;
        return 0;
    case OPT_LIST:
        if (!*v)
            break;
        return option_add_include(opt, v, err, errlen);
    case OPT_SIGN:
        if (*v && !r->ignore_rest)
            break;
        if (r->field)
            *INT_FIELD(opt, r) = on;
        return 0;
    case OPT_CUSTOM:
        return r->handler(r, arg, v, opt, err, errlen);
    case OPT_IGNORED:
        if (*v && !r->ignore_rest)
            break; /* no switch of POV-Ray's: +B5 */
        return 0; /* it cannot change the image or the files */
    case OPT_UNSUPPORTED:
        if (!on && r->ini_as == INI_AS_ON_OFF)
            return 0; /* off: POV-Ray's default, nothing asked for */
        snprintf(err, (size_t)errlen, "'%s': %s is not supported by hstrace yet", arg, r->reason);
        return -1;
    default:
        break;
    }
    if (bad) {
        snprintf(err, (size_t)errlen, "'%s': %s", arg, r->pov_expect);
        return -1;
    }
    if (r->type == OPT_INT || r->type == OPT_REAL)
        return 0;
    snprintf(err, (size_t)errlen, "unknown POV-Ray switch '%s'", arg);
    return -1;
}

/* ---- INI options and files (ini_file.h) ---------------------------------- */

/* A string the options own (freed by options_free). */
char *option_own_string(Options *opt, const char *s, size_t n)
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

static int read_ini(Options *opt, const char *spec, const char *where, int depth, char *err, int errlen);

/* The row of an INI key (POV-Ray 3.7's names, case ignored). */
static const OptionRow *ini_row(const char *key)
{
    for (size_t i = 0; i < option_nrows; i++)
        if (option_rows[i].ini && strcasecmp(option_rows[i].ini, key) == 0)
            return &option_rows[i];
    return NULL;
}

/* An INI key's value, as its row takes it; msg: the message without the
 * position. */
static int ini_value(const OptionRow *r, const char *value, const char *where, Options *opt, char *msg, int msglen)
{
    int b, bad = 0;
    double x;
    if (r->type == OPT_IGNORED)
        return 0;
    if (r->type == OPT_UNSUPPORTED) {
        /* a key refused only when on takes off, POV-Ray's default */
        if (r->ini_as == INI_AS_ON_OFF && parse_bool(value, &b)) {
            snprintf(msg, (size_t)msglen, "%s=%s: expected on or off", r->ini, value);
            return -1;
        }
        if (r->ini_as == INI_AS_ON_OFF && !b)
            return 0;
        snprintf(msg, (size_t)msglen, "%s: %s is not supported by hstrace yet", r->ini, r->reason);
        return -1;
    }
    if (r->ini_as == INI_AS_SWITCH) {
        char sw[600];
        snprintf(sw, sizeof sw, "%s%s", r->pov, value);
        char *own = option_own_string(opt, sw, strlen(sw));
        return own ? parse_pov_switch(own, opt, msg, msglen) : -1;
    }
    if (r->ini_as == INI_AS_ON_OFF || r->type == OPT_BOOL) {
        if (parse_bool(value, &b)) {
            snprintf(msg, (size_t)msglen, "%s=%s: expected on or off", r->ini, value);
            return -1;
        }
        if (r->type == OPT_BOOL) {
            *INT_FIELD(opt, r) = r->inverted ? !b : b;
            return 0;
        }
        /* as the switch +X or -X */
        char sw[8];
        snprintf(sw, sizeof sw, "%c%s", b ? '+' : '-', r->pov + 1);
        if (parse_pov_switch(sw, opt, msg, msglen))
            return -1;
        if (b && strcmp(r->pov, "+A") == 0) {
            /* Antialias=on: the message that names what turned it on says where */
            snprintf(opt->antialias_by, sizeof opt->antialias_by, "%s%s%s=%s", where ? where : "", where ? ": " : "",
                     r->ini, value);
            opt->antialias_positioned = where != NULL;
        }
        return 0;
    }
    switch (r->type) {
    case OPT_INT:
        bad = option_parse_int(value, (int)r->lo, (int)r->hi, INT_FIELD(opt, r));
        break;
    case OPT_REAL:
        bad = option_parse_double(value, &x) || !in_range(r, x);
        if (!bad)
            *DOUBLE_FIELD(opt, r) = x;
        break;
    case OPT_PARSED:
        bad = r->parse(value, field_of(opt, r->field));
        break;
    case OPT_STRING:
        *STRING_FIELD(opt, r) = value;
        break;
    case OPT_LIST:
        return option_add_include(opt, value, msg, msglen);
    case OPT_CUSTOM:
        return r->handler(r, r->ini, value, opt, msg, msglen);
    default:
        break;
    }
    if (bad) {
        snprintf(msg, (size_t)msglen, "%s=%s: expected %s", r->ini, value, r->ini_expect);
        return -1;
    }
    return 0;
}

/* One KEY=VALUE, from an INI file (where: "FILE:LINE:COLUMN") or the
 * command line (where: NULL). */
static int apply_key(Options *opt, const char *key, const char *value, const char *where, int depth, char *err,
                     int errlen)
{
    const OptionRow *k = ini_row(key);
    char msg[768];
    int status = 0;
    msg[0] = '\0';
    if (!k) {
        snprintf(msg, sizeof msg, "unknown INI key '%s'", key);
        status = -1;
    } else if (k->type == OPT_INCLUDE_INI) {
        if (depth >= 16) {
            snprintf(msg, sizeof msg, "Include_Ini=%s: INI files included more than 16 deep", value);
            status = -1;
        } else if (read_ini(opt, value, where, depth + 1, err, errlen)) {
            return -1; /* err already says where */
        }
    } else {
        status = ini_value(k, value, where, opt, msg, (int)sizeof msg);
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

/* A row's default, given as the row's own value would be: through its long
 * option, else its INI key when that is its on/off or its only name, else
 * its switch. The table's defaults are its own: one refused is a bug. */
static void apply_default(const OptionRow *r, Options *opt)
{
    char msg[768];
    int status;
    if (r->name) {
        status = long_value(r, r->dflt, opt, msg, (int)sizeof msg);
    } else if (r->ini && (r->ini_as == INI_AS_ON_OFF || !r->pov)) {
        status = ini_value(r, r->dflt, NULL, opt, msg, (int)sizeof msg);
    } else {
        char sw[64];
        snprintf(sw, sizeof sw, "%s%s", r->pov, r->dflt);
        status = parse_pov_switch(sw, opt, msg, (int)sizeof msg);
    }
    if (status) {
        fprintf(stderr, "hstrace: the options' table has a default its row refuses: %s\n", msg);
        abort();
    }
}

/* Only depth bounds nothing: a file that includes the next one ten times,
 * fifteen deep, is 10^15 reads. So the INI files read for one command are
 * bounded in number and in bytes, whatever includes them. */
#define INI_MAX_FILES 1000
#define INI_MAX_TOTAL_BYTES (16u << 20)

/* Where POV-Ray 3.7 finds an INI file it is given by name
 * (frontend/processrenderoptions.cpp, OpenINIFileStream): in the current
 * folder, then in each library path given so far (so Debian's povray.ini
 * finds quickres.ini and res120.ini in /usr/share/povray-3.7/ini), each
 * place trying the name as given when it has an extension of up to three
 * letters, then the name with .ini and with .INI. The spec's section stays
 * on. The first found, as a spec the options own; spec itself when none is
 * (its reading then says it cannot be opened), or NULL when out of memory. */
static const char *find_ini(Options *opt, const char *spec)
{
    size_t n = strlen(spec);
    const char *open = n > 0 && spec[n - 1] == ']' ? strrchr(spec, '[') : NULL;
    size_t name_len = open ? (size_t)(open - spec) : n;
    const char *section = spec + name_len;
    const char *dot = NULL;
    for (const char *c = spec; c < spec + name_len; c++)
        dot = *c == '.' ? c : *c == '/' ? NULL : dot;
    int has_extension = dot && (size_t)(spec + name_len - dot) <= 4;
    static const char *const tails[] = { "", ".ini", ".INI" };
    for (int d = -1; d < opt->ninclude_paths; d++) {
        if (d >= 0 && spec[0] == '/')
            break; /* a full path is where it says */
        const char *dir = d < 0 ? "" : opt->include_paths[d];
        for (int t = has_extension ? 0 : 1; t < 3; t++) {
            char path[PATH_MAX];
            int len = snprintf(path, sizeof path, "%s%s%.*s%s", dir, d < 0 ? "" : "/", (int)name_len, spec, tails[t]);
            struct stat st;
            if (len <= 0 || (size_t)len >= sizeof path || stat(path, &st) != 0)
                continue;
            if (d < 0 && t == 0)
                return spec;
            char full[PATH_MAX + 256];
            len = snprintf(full, sizeof full, "%s%s", path, section);
            return len > 0 && (size_t)len < sizeof full ? option_own_string(opt, full, (size_t)len) : spec;
        }
    }
    return spec;
}

/* Reads the INI file spec (with its section) and applies its entries;
 * where is the position of the line that included it ("FILE:LINE:COLUMN"),
 * NULL for the command line. */
static int read_ini(Options *opt, const char *spec, const char *where, int depth, char *err, int errlen)
{
    char msg[700];
    spec = find_ini(opt, spec);
    if (!spec) {
        snprintf(err, (size_t)errlen, "out of memory");
        return -1;
    }
    if (opt->ninis >= INI_MAX_FILES || opt->ini_bytes > INI_MAX_TOTAL_BYTES) {
        snprintf(msg, sizeof msg, "'%s': INI files read %d times, %zu bytes in all: more than the %d files or %u MiB "
                 "one command may read (do INI files include each other again and again?)",
                 spec, opt->ninis, opt->ini_bytes, INI_MAX_FILES, INI_MAX_TOTAL_BYTES >> 20);
        opt->error_has_position = where != NULL;
        snprintf(err, (size_t)errlen, "%s%s%s", where ? where : "", where ? ": " : "", msg);
        return -1;
    }
    IniFile *grown = realloc(opt->inis, sizeof *grown * (size_t)(opt->ninis + 1));
    if (!grown) {
        snprintf(err, (size_t)errlen, "out of memory");
        return -1;
    }
    opt->inis = grown;
    IniFile *f = &opt->inis[opt->ninis++];
    if (ini_file_read(f, spec, msg, (int)sizeof msg)) {
        /* Unreadable: an input/output error, at the line that named the
         * file if any; else a mistake at its own place in the file. */
        opt->error_is_io = strncmp(msg, "cannot ", 7) == 0 || strstr(msg, "too big for an INI file") != NULL;
        int positioned = !opt->error_is_io && strncmp(msg, "out of memory", 13) != 0;
        if (!positioned && where)
            snprintf(err, (size_t)errlen, "%s: %s", where, msg);
        else
            snprintf(err, (size_t)errlen, "%s", msg);
        opt->error_has_position = positioned || where;
        return -1;
    }
    opt->ini_bytes += f->bytes;
    /* f may move as included files are added: keep what is needed. */
    int n = f->n;
    IniEntry *entries = f->entries;
    const char *path = f->path;
    for (int i = 0; i < n; i++) {
        const IniEntry *e = &entries[i];
        char here[600];
        snprintf(here, sizeof here, "%s:%d:%d", path, e->line, e->column);
        if (e->kind == INI_OPTION) {
            if (apply_key(opt, e->key, e->value, here, depth, err, errlen))
                return -1;
        } else if (e->kind == INI_SWITCH) {
            if (parse_pov_switch(e->key, opt, msg, (int)sizeof msg)) {
                snprintf(err, (size_t)errlen, "%s: %s", here, msg);
                opt->error_has_position = 1;
                return -1;
            }
            if (toupper((unsigned char)e->key[1]) == 'A' && opt->antialias_on) {
                snprintf(opt->antialias_by, sizeof opt->antialias_by, "%s: '%s'", here, e->key);
                opt->antialias_positioned = 1;
            }
        } else if (ini_spec_is_ini(e->key)) {
            if (depth >= 16) {
                snprintf(err, (size_t)errlen, "%s: INI files included more than 16 deep", here);
                opt->error_has_position = 1;
                return -1;
            }
            if (read_ini(opt, e->key, here, depth + 1, err, errlen))
                return -1;
        } else if (opt->scene && strcmp(opt->scene, e->key) != 0) {
            snprintf(err, (size_t)errlen, "%s: more than one scene given ('%s' and '%s')", here, opt->scene, e->key);
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
    /* Checked in doubles before any conversion: a start or end of 1e300,
     * NaN or below 0 has no row, and (int) of it is undefined. */
    if (have_start && !(start >= 0.0 && start <= (double)size)) {
        snprintf(err, (size_t)errlen, "the render area's start %s (%g) is not within the image's %d", what, start,
                 size);
        return -1;
    }
    if (have_end && !(end >= 0.0 && end <= (double)size)) {
        snprintf(err, (size_t)errlen, "the render area's end %s (%g) is beyond the image's %d", what, end, size);
        return -1;
    }
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
        opt->scene = option_own_string(opt, pov, n + 4);
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

/* Is povray.ini to be read? Not with --no-povray-ini, and not for what
 * only prints (--help, --version, --povray-options and their POV-Ray
 * spellings): looked for before anything else is read. */
static int wants_povray_ini(int argc, char **argv)
{
    static const char *const words[] = { "--no-povray-ini", "--help", "-h", "-help", "-?", "--version", "-version",
                                         "--V", "--povray-options" };
    for (int i = 1; i < argc; i++)
        for (size_t k = 0; k < sizeof words / sizeof words[0]; k++)
            if (strcmp(argv[i], words[k]) == 0)
                return 0;
    return 1;
}

/* POV-Ray's povray.ini (povray_ini.h), read as the first of the settings
 * so that everything after it overrides it. What it says is the machine's
 * default for POV-Ray: its scene is one when the command line names none;
 * its output type yields to an output named with another type's extension
 * (-o out.exr); its Display=on and Pause_When_Done=on bring no note. */
static int read_povray_ini(Options *opt, const char **scene, char *err, int errlen)
{
    PovrayIni ini;
    int found = povray_ini_find(&ini);
    snprintf(opt->povray_ini_warning, sizeof opt->povray_ini_warning, "%s", ini.warning);
    if (!found)
        return 0;
    opt->povray_ini = option_own_string(opt, ini.path, strlen(ini.path));
    opt->povray_ini_why = ini.why;
    if (!opt->povray_ini) {
        snprintf(err, (size_t)errlen, "out of memory");
        return -1;
    }
    if (read_ini(opt, opt->povray_ini, NULL, 0, err, errlen)) {
        size_t n = strlen(err);
        if (n + 1 < (size_t)errlen)
            snprintf(err + n, (size_t)errlen - n, " (read as %s, before the command line; --no-povray-ini reads none)",
                     ini.why);
        return -1;
    }
    *scene = opt->scene;
    opt->scene = NULL;
    opt->output_type_given = 0;
    opt->display_asked = 0;
    opt->pause_asked = 0;
    return 0;
}

/* $POVINC: one more include folder, after all others, as POV-Ray's Unix
 * front end adds it (vfe/unix/unixconsole.cpp). */
static int add_povinc(Options *opt, char *err, int errlen)
{
    const char *dir = getenv("POVINC");
    if (!dir || !dir[0])
        return 0;
    char *own = option_own_string(opt, dir, strlen(dir));
    if (!own) {
        snprintf(err, (size_t)errlen, "out of memory");
        return -1;
    }
    return option_add_include(opt, own, err, errlen);
}

/* An output named with an image type's extension: a type that povray.ini
 * alone gave yields to it. */
static void output_type_from_name(Options *opt)
{
    if (!opt->output_type || opt->output_type_given || !opt->output)
        return;
    const char *base = strrchr(opt->output, '/'), *dot;
    base = base ? base + 1 : opt->output;
    dot = strrchr(base, '.');
    static const struct { const char *ext; int type; } types[] = {
        { ".png", 'N' }, { ".exr", 'E' }, { ".ppm", 'P' }, { ".tga", 'T' }, { ".bmp", 'B' },
        { ".jpg", 'J' }, { ".jpeg", 'J' }, { ".hdr", 'H' },
    };
    for (size_t i = 0; dot && i < sizeof types / sizeof types[0]; i++)
        if (strcasecmp(dot, types[i].ext) == 0 && !(types[i].type == 'T' && opt->output_type == 'C')) {
            opt->output_type = types[i].type;
            return;
        }
}

int options_parse(int argc, char **argv, Options *opt, char *err, int errlen)
{
    memset(opt, 0, sizeof *opt);
    for (size_t i = 0; i < option_nrows; i++)
        if (option_rows[i].dflt)
            apply_default(&option_rows[i], opt);
    /* povray.ini is a render's: not read for what only prints */
    const char *ini_scene = NULL;
    if (wants_povray_ini(argc, argv) && read_povray_ini(opt, &ini_scene, err, errlen))
        return -1;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const OptionRow *r = long_row(a);
        if (r) {
            if (long_option(r, argc, argv, &i, opt, err, errlen))
                return -1;
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
            if (read_ini(opt, a, NULL, 0, err, errlen))
                return -1;
        } else if (!opt->scene) {
            opt->scene = a;
        } else {
            snprintf(err, (size_t)errlen, "more than one scene given ('%s' and '%s')", opt->scene, a);
            return -1;
        }
    }
    if (!opt->scene)
        opt->scene = ini_scene;
    if (add_povinc(opt, err, errlen))
        return -1;
    output_type_from_name(opt);
    if (!opt->help && !opt->version && !opt->povray_options && !opt->scene) {
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
                opt->output = option_own_string(opt, named, n + 4);
                free(named);
            }
            if (!named || !opt->output) {
                snprintf(err, (size_t)errlen, "out of memory");
                return -1;
            }
        } else if (strcasecmp(dot, ext) != 0 && !(opt->output_type == 'J' && strcasecmp(dot, ".jpeg") == 0)) {
            if (opt->output_type_given)
                snprintf(err, (size_t)errlen, "+F%c asks for %s, but the output '%s' is named for another type",
                         opt->output_type, ext + 1, opt->output);
            else
                snprintf(err, (size_t)errlen, "%s's Output_File_Type=%c asks for %s, but the output '%s' is named "
                         "for no image type", opt->povray_ini ? opt->povray_ini : "povray.ini", opt->output_type,
                         ext + 1, opt->output);
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
