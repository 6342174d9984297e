/* Reading a POV-Ray scene file into a Scene description (scene.h). */
#ifndef HST_PARSER_H
#define HST_PARSER_H

#include "scene.h"

/* A symbol declared before the scene is read (POV-Ray's Declare=NAME=VALUE):
 * a float, or a string when string is not NULL. */
typedef struct {
    const char *name;
    double number;
    const char *string;
} ParseDeclare;

/* POV-Ray's clock and frame values as the scene sees them (clock,
 * clock_on, clock_delta, initial_clock, final_clock, frame_number,
 * initial_frame, final_frame). */
typedef struct {
    double clock, clock_delta, initial_clock, final_clock;
    double frame_number, initial_frame, final_frame;
    int clock_on;
} ParseAnimation;

typedef struct {
    /* Folders searched for #include after the scene's own folder, in order:
     * --include-path/+L folders, then the project's installed include folder,
     * then POV-Ray's include folder when it exists. */
    const char *const *include_dirs;
    int ninclude_dirs;
    /* A folder searched before the including file's own (POV-Ray looks in
     * the current folder first: "."), or NULL. */
    const char *first_dir;
    /* image_width / image_height as the scene sees them. */
    int image_width, image_height;
    /* Global symbols declared before the first token, in order (a name given
     * twice keeps its first value, as POV-Ray 3.7 keeps it). A name that is
     * not an identifier, or is a reserved word, is an error at the scene's
     * start. */
    const ParseDeclare *declares;
    int ndeclares;
    /* The frame being rendered; NULL: a still, as POV-Ray renders one
     * without animation switches (clock 0, clock_delta 1, ...). */
    const ParseAnimation *animation;
    /* Threads a long list of plain vectors (mesh2's) may be read on
     * (0 or 1: the calling thread alone); the scene is the same for any. */
    int threads;
    /* Reads the file of an image_map, bump_map or material_map (found
     * through the folders above) into *out (scene.h's LoadedPicture; the
     * parser frees its rgba and index), its colours decoded to linear
     * light. decoding_gamma: IMAGE_GAMMA_FILE_DEFAULT the curve the file
     * names, else its type's (POV-Ray 3.7's readers), 0 sRGB, else a power
     * law, for every type (`gamma G`, 1: the values as stored).
     * untagged_gamma, with IMAGE_GAMMA_FILE_DEFAULT: the curve of a file
     * that names none (POV-Ray's defaultGamma), IMAGE_GAMMA_FILE_DEFAULT
     * for its type's own. premultiplied: -1 the format's own reading (EXR
     * premultiplied, the others straight), else `premultiplied`'s value.
     * max_bytes: the memory the parse's budget has left, which a picture
     * (and the parser's copy of it) must fit, checked from its header
     * before it is decoded. Returns 0, or -1 with the reason in err (the
     * parser names the file and the position). NULL: pictures are
     * refused. */
    int (*load_image)(void *user, const char *path, double decoding_gamma, double untagged_gamma, int premultiplied,
                      size_t max_bytes, LoadedPicture *out, char *err, int errlen);
    /* +MV3.7: the language version is set (3.7) before the first line, as
     * POV-Ray's kPOVAttrib_Version does: no #version needed, and the gamma
     * mode stays as it starts (image_gamma.c). */
    int language_version_given;
    void *load_image_user;
    /* POV-Ray's console streams turned off (-GD, -GW, -GA): #debug text
     * and warnings (#warning, the parser's own) are not printed. Errors
     * always are. */
    int quiet_debug, quiet_warnings;
    /* Budgets of the parse's work (0: the default), each an error naming the
     * position, the loop or macro, and the macro calls that led there:
     * #while/#for iterations in all (10 million), macro calls in all (2
     * million), tokens read again by loops and macro calls, a long one
     * counting one per 16 bytes (20 million: what bounds an endless loop
     * whatever its body, within seconds), and seconds of parsing (none). */
    long max_loop_iterations;
    long max_macro_calls;
    long max_repeated_tokens;
    double max_parse_seconds;
    /* Bytes the parse may allocate (the scene description and everything
     * temporary: arrays, strings, macro frames, file texts, meshes); 0
     * means the default, parse_default_max_memory(). */
    size_t max_memory;
    /* --strict: what hstrace would approximate (ApproxKind) is an error. */
    int strict;
    /* POV-Ray's quality below 6 (+Q0 to +Q5, its Q_QUICKC): a pigment
     * given a quick_color shows that colour instead of itself (its
     * pattern is not evaluated); others are evaluated as at +Q9. */
    int quick_colours;
    /* #fopen ... write/append is an error (for a fuzzer, which must not
     * write files its inputs name). */
    int forbid_writes;
} ParseOptions;

/* A parse error: "FILE:LINE:COLUMN: message". */
typedef struct {
    char file[512];
    int line, column;
    char message[512];
    int is_io; /* 1 when the error is an unreadable file rather than bad text */
    /* Where the error's macro was called from, innermost first: lines of
     * "FILE:LINE:COLUMN: note: in macro 'Name' called here\n"; empty when
     * the error is not inside a macro. */
    char notes[1024];
} ParseError;

/* A fair share of the machine for one parse: a quarter of its physical
 * memory, at least 256 MiB (4 GiB when the size is unknown). */
size_t parse_default_max_memory(void);

/* Returns NULL and fills err on failure; never exits, never crashes. */
Scene *parse_scene_file(const char *path, const ParseOptions *opts, ParseError *err);
/* The same from a string, `name` standing in for the file name in messages
 * and as the folder for #include ("." when it has none). */
Scene *parse_scene_string(const char *name, const char *text, const ParseOptions *opts, ParseError *err);

#endif
