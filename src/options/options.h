/* The command line: GNU-style options and POV-Ray's own +/- switches where
 * they mean the same thing. The names are fixed: tools outside call them. */
#ifndef HST_OPTIONS_H
#define HST_OPTIONS_H

#include <stdio.h>

#include "shadow.h"

/* Exit statuses, documented in the man page. */
enum {
    EXIT_OK = 0,
    EXIT_USAGE = 1,       /* bad command line, impossible sizes */
    EXIT_SCENE = 2,       /* the scene has an error or uses something unsupported */
    EXIT_IO = 3,          /* a file could not be read or written, or the colour config is missing or broken */
};

#define MAX_INCLUDE_PATHS 32

/* Declare=NAME=VALUE: a float, or a string when string is not NULL. */
typedef struct {
    const char *name;
    double number;
    const char *string;
} OptionDeclare;

typedef struct {
    const char *scene;
    const char *output;           /* NULL: scene name with .png, in the current folder */
    int width, height;
    int threads;                  /* 0: all cores */
    int quality;                  /* POV-Ray's +Q: 0..11, default 9 */
    const char *shadows;          /* method name */
    double tolerance;             /* relative margin of the shadow tests (--tolerance) */
    int plane_precision;          /* PlanePrecision of the shadow-polygon planes (--plane-precision) */
    NthSetting nth;               /* hst's N_th (--nth: a number, auto or per-point) */
    int verify_shadows;        /* 1 --verify-shadows, 2 --verify-reference */
    int pixel_coherence;          /* hst: counts from the neighbouring pixel (--pixel-coherence) */
    int instancing;               /* meshes placed many times kept once (--instancing auto: 1; off: 0) */
    int volumes_always;           /* hst: build every light's volumes (--volumes always); 0: auto */
    int grid[3];                  /* 0: choose from the polygon count */
    const char *include_paths[MAX_INCLUDE_PATHS];
    int ninclude_paths;
    int stats;
    int strict;       /* --strict: approximations are errors */
    /* What the parse may use (0: the parser's defaults): --max-memory,
     * --max-parse-seconds, --max-loop-iterations, --max-macro-calls,
     * --max-repeated-tokens. */
    size_t max_memory;
    double max_parse_seconds;
    long max_loop_iterations, max_macro_calls, max_repeated_tokens;
    /* --max-render-seconds: the render's own time (0: no limit). */
    double max_render_seconds;
    /* --max-tree-rays: the rays one camera ray's tree of reflected,
     * refracted and transmitted rays may hold (0: no limit). */
    long max_tree_rays;
    const char *stats_json;
    int exr_float;
    int png16;
    unsigned aov;                 /* --aov: AovGroup bits (aov.h); 0 none */
    /* OpenColorIO (see colour.h); NULL when not given. */
    const char *ocio_config, *display, *view, *colorspace;
    int help, version;
    int povray_options;           /* --povray-options: list POV-Ray's keys and switches */
    /* POV-Ray's povray.ini (povray_ini.h), read before everything else
     * unless --no-povray-ini: the file read (NULL: none), why that one, and
     * a warning to show (a $POVINI that cannot be opened), or "". */
    int no_povray_ini;
    const char *povray_ini;
    const char *povray_ini_why;
    char povray_ini_warning[320];
    /* Declare=NAME=VALUE from the command line and INI files, in order. */
    OptionDeclare *declares;
    int ndeclares;
    int antialias_on;             /* +A or Antialias=on, last */
    double aa_threshold;          /* +An, Antialias_Threshold (0.3) */
    int aa_method;                /* +AMn, Sampling_Method (1) */
    int aa_depth;                 /* +Rn, Antialias_Depth (3) */
    double aa_gamma;              /* Antialias_Gamma (2.5) */
    /* Display_Gamma: 0 sRGB (POV-Ray's default), else a power law. POV-Ray
     * uses it as the working and the file gamma of a scene that turns gamma
     * correction off (no assumed_gamma, below 3.7): what an EXR holds and
     * what a PNG's gAMA chunk says. */
    double display_gamma;
    /* File_Gamma: 0 sRGB (POV-Ray's default), else a power law (1: none).
     * POV-Ray 3.7 encodes its PNG, PPM, Targa, BMP and JPEG files with it
     * (PNG's gAMA chunk says it, an sRGB chunk too for sRGB); EXR and HDR
     * stay linear; a scene that turns gamma correction off gets
     * Display_Gamma instead (frontend/renderfrontend.h, imageprocessing.cpp). */
    double file_gamma;
    /* +MV3.7: the scene's language version is 3.7 from its first line, as
     * if it had a #version (which changes how its pictures are read). */
    int language_version_given;
    int jitter_on;                /* +J / -J, Jitter (on) */
    double jitter_amount;         /* +Jn, Jitter_Amount (1) */
    int render_block_size;        /* +BSn, Render_Block_Size (32): anti-aliasing's blocks */
    char antialias_by[720];       /* what turned it on, for the message */
    int antialias_positioned;     /* ... which begins with FILE:LINE:COLUMN */
    /* Animation, as POV-Ray's +KFIn +KFFn +KIf +KFf +KC +SFx +EFx and the
     * INI keys of the same (animation.h); +Kf: a still's clock. */
    int initial_frame, final_frame;
    double initial_clock, final_clock;
    int cyclic;
    int frame_step;               /* +STPn, Frame_Step (1; below 1 is 1) */
    int have_subset_start, have_subset_end;
    double subset_start, subset_end;
    double clock;
    int have_clock;
    /* Partial renders, as POV-Ray's +SRn +ERn +SCn +ECn (a value of 1 or
     * more a row or column counted from 1, below 1 a fraction) and the
     * INI keys Start_Row ...; area_*: the pixels rendered, [x0, x1) x
     * [y0, y1), worked out at the end of options_parse. */
    double start_row, end_row, start_col, end_col;
    int have_start_row, have_end_row, have_start_col, have_end_col;
    int area_x0, area_y0, area_x1, area_y1;               /* +K or Clock= given: clock_on in a still */
    int output_type;              /* POV-Ray's +F: 0 none given, 'N' PNG, 'E' EXR, 'P' PPM,
                                   * 'T' Targa, 'C' RLE Targa, 'B' BMP, 'J' JPEG, 'H' HDR */
    int output_type_given;        /* +F or Output_File_Type after povray.ini (whose type yields to -o's name) */
    int jpeg_quality;             /* the INI key Compression: 0 (POV-Ray's default, 85) to 255 */
    int output_alpha;             /* +UA / Output_Alpha: an alpha channel, the background transparent */
    int no_output;                /* -F: render, write no image */
    int display_asked;            /* +D or Display=on: there is no display window, said once */
    int pause_asked;              /* +P or Pause_When_Done=on: nothing to pause on, said once */
    /* POV-Ray's console streams (+G.. / -G.., All_Console ...): 1 shown
     * (the default), 0 turned off. Errors are always shown. */
    int debug_console, warning_console, render_console, statistics_console;
    int error_has_position;       /* the message options_parse gave begins with FILE:LINE:COLUMN */
    int error_is_io;              /* ... is about a file that could not be read (exit status 3) */
    /* What options_free releases: the INI files read (their strings are
     * values of the options above) and strings made here. */
    struct IniFile *inis;
    int ninis;
    size_t ini_bytes; /* read from INI files in all, bounded with ninis */
    char **strings;
    int nstrings;
} Options;

/* Fills opt from argv: options, POV-Ray switches, KEY=VALUE INI options and
 * INI files (FILE.ini, FILE.ini[section]), later settings winning. Returns
 * 0, or -1 with a message in err. options_free either way. */
int options_parse(int argc, char **argv, Options *opt, char *err, int errlen);
void options_free(Options *opt);
/* The output file's extension for POV-Ray's +F type (".png" without one). */
const char *options_output_extension(const Options *opt);
void options_usage(FILE *f);
/* --povray-options: POV-Ray 3.7's INI keys and switches and what hstrace
 * does with each (options_list.c). 0, or -1 when out of memory. */
int options_povray_list(FILE *f);

/* For subcommands' parsers: is arg the long option name, alone or as
 * "name=value"? And its value ("--name=value" or "--name value", advancing
 * *i), or NULL with a message in err. */
int options_is_long(const char *arg, const char *name);
const char *options_value(int argc, char **argv, int *i, const char *name, char *err, int errlen);
/* A size in bytes as --max-memory takes it ("512M", "8G", "1.5GiB"):
 * 0, or -1 when it is none. */
int options_parse_size(const char *s, size_t *out);

#endif
