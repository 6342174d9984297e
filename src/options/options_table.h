/* The options' table: one row per setting, naming every way to give it (a
 * GNU-style long option, a POV-Ray switch, an INI key), its type, where it
 * is kept in Options, its default and its --help text. options.c reads it
 * for --help, the long options, the switches and the INI keys;
 * tests/test_options_table.c holds it against --help and the man page.
 *
 * A static array of rows rather than an X-macro .def file: the rows are
 * not alike (a range, a list of words, a handler, a reason for refusing),
 * and designated initializers name what each row has and leave the rest
 * zero, where a .def line would spell out every column on every row; and
 * there is only one C view to generate, the array itself. */
#ifndef HST_OPTIONS_TABLE_H
#define HST_OPTIONS_TABLE_H

#include <stddef.h>
#include <stdio.h>

#include "options.h"

typedef enum {
    OPT_FLAG,        /* a long option without a value: raises an int to lo (the stronger of two wins) */
    OPT_INT,         /* a whole number from lo to hi */
    OPT_REAL,        /* a number from lo to hi (above lo with lo_open) */
    OPT_COUNT,       /* a whole number from 1 to 10^15 into a long; "0" too when lo is 0 */
    OPT_SIZE,        /* bytes, as options_parse_size reads them */
    OPT_WORDS,       /* one of words, stored as its value */
    OPT_STRING,      /* any text (a switch's must not be empty) */
    OPT_NAME,        /* a text that must not be empty */
    OPT_LIST,        /* repeatable: each one added (the include paths) */
    OPT_PARSED,      /* read by parse; a value it refuses gets the row's message */
    OPT_CUSTOM,      /* handler reads it and writes its own messages */
    OPT_SIGN,        /* a switch without value: +X 1, -X 0 */
    OPT_BOOL,        /* an INI key's on/off (inverted: off sets 1) */
    OPT_INCLUDE_INI, /* Include_Ini: reads another INI file in its place */
    OPT_IGNORED,     /* a key or switch that cannot change the image or the files: accepted, reason says why */
    OPT_UNSUPPORTED  /* a key or switch for what hstrace does not do: refused with reason (with ini_as
                      * INI_AS_ON_OFF, only when on: off is POV-Ray's default and changes nothing) */
} OptionType;

/* How an INI key's value is taken. */
typedef enum {
    INI_AS_VALUE,  /* the row's type reads it: "KEY=VALUE: expected ..." */
    INI_AS_SWITCH, /* as the switch followed by the value (Width=640 is +W640) */
    INI_AS_ON_OFF  /* on/off, as the switch +X / -X */
} IniAs;

typedef struct {
    const char *word;
    int value;
} OptionWord;

typedef struct OptionRow OptionRow;

/* OPT_CUSTOM: arg is what names the setting in a message (the long option,
 * the whole switch "+A0.5", the INI key), value what follows it. Writes its
 * message in err and returns -1, or returns 0. */
typedef int (*OptionHandler)(const OptionRow *row, const char *arg, const char *value, Options *opt, char *err,
                             int errlen);
/* OPT_PARSED: 0, or -1 for a value it refuses. */
typedef int (*OptionParser)(const char *value, void *slot);

/* A field of Options, counted from 1 so that 0 is "none". */
#define OPTION_FIELD(f) (offsetof(Options, f) + 1)

struct OptionRow {
    const char *name;       /* "--width", or NULL */
    const char *short_name; /* "-o", "-h", or NULL */
    const char *pov;        /* POV-Ray switch with its sign, "+W", or NULL */
    const char *ini;        /* INI key as POV-Ray 3.7 spells it, or NULL */
    OptionType type;
    IniAs ini_as;
    size_t field;           /* OPTION_FIELD(...) or 0 */
    size_t given;           /* OPTION_FIELD of an int set to 1 when the switch is given, or 0 */
    double lo, hi;
    int lo_open;            /* OPT_REAL: above lo */
    int inverted;           /* OPT_BOOL */
    int ignore_rest;        /* OPT_SIGN: what follows the switch is ignored, not refused */
    const OptionWord *words;
    OptionParser parse;
    OptionHandler handler;
    const char *dflt;       /* the default, as the row's own value would be written */
    const char *value_name; /* --help: the value's name ("N", "auto|always") */
    const char *help;       /* --help: the description, lines separated by '\n' */
    void (*help_tail)(FILE *f, const char *indent); /* --help: lines that depend on the build */
    const char *expect;     /* long option's message: "--NAME 'VALUE': EXPECT" */
    const char *pov_expect; /* switch's message: "'SWITCH': POV_EXPECT" */
    const char *ini_expect; /* INI key's message: "KEY=VALUE: expected INI_EXPECT" */
    /* OPT_UNSUPPORTED: what it is about ("field rendering"); a row that is
     * accepted and changes nothing (OPT_IGNORED, and the few that also set
     * a field for a note): why. --povray-options lists a row with a reason
     * as refused or ignored, one without as honoured. */
    const char *reason;
};

extern const OptionRow option_rows[];
extern const size_t option_nrows;

/* The column where --help's descriptions begin. */
#define OPTION_HELP_COLUMN 25

/* Shared with the rows' handlers (options.c). */
int option_parse_int(const char *s, int lo, int hi, int *out);
int option_parse_double(const char *s, double *out);
int option_add_include(Options *opt, const char *dir, char *err, int errlen);
char *option_own_string(Options *opt, const char *s, size_t n);

#endif
