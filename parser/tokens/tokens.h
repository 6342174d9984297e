/* The token stream, the lowest of the parser's three parts (as Lua's llex
 * under lparser and lcode): the lexer, #directives, macros, symbols and
 * their values, arrays, #fopen's files, the files read, the limits of a
 * parse, and the Parser itself with its errors and memory. The expression
 * evaluator (parser/expressions) and the scene grammar (parser/grammar)
 * are above it; it reaches them through TokHooks only.
 *
 * Error handling: every error calls tok_fail(), which fills the ParseError
 * and longjmps back to the public entry point. Nothing the parser allocates
 * is owned by the C stack: scene data lives in the scene's arena, everything
 * temporary (file buffers, symbols, growing arrays) in `p->temp`, so an error
 * anywhere leaks nothing. */
#ifndef HST_TOKENS_H
#define HST_TOKENS_H

#include <setjmp.h>
#include <stdio.h>
#include <stddef.h>

#include "convert.h"
#include "keywords.h"
#include "parser.h"
#include "scene.h"

/* ---- tokens ------------------------------------------------------------ */

typedef enum {
    TK_EOF,
    TK_NUMBER,
    TK_STRING,
    TK_WORD,  /* a keyword (kw >= 0) or an identifier (kw == -1) */
    TK_PUNCT, /* punct holds the character, or one of the P_* below */
} TokenType;

enum { P_LE = 256, P_GE, P_NE };

typedef struct {
    TokenType type;
    int punct;
    int kw;
    double number;
    const char *text; /* spelling, pointing into the file buffer */
    int len;
    char *string;     /* TK_STRING: contents with escapes resolved */
    SourcePos pos;
    /* An array element `A[i][j]` (tok_next() reads the indices): the element,
     * which may still hold no value. text/len span the whole `A[i][j]`. */
    struct Symbol *elem;
    unsigned elem_serial; /* elem's serial then: it changes if the array is recycled */
} Token;

/* ---- the include stack --------------------------------------------------- */

#define MAX_INCLUDE_DEPTH 64
/* Macro invocations active at once (recursion included). Expanding a macro
 * pushes a source frame, not a C stack frame, so the limit is generous; it
 * turns endless recursion into an error. */
#define MAX_MACRO_DEPTH 1000
#define MAX_SOURCE_FRAMES (MAX_INCLUDE_DEPTH + MAX_MACRO_DEPTH + 1)

struct Macro;

/* One frame of the source stack: an open file, or the body of an invoked
 * macro being replayed from the buffer of the file that defined it (file
 * buffers live until the parse ends, so a macro defined in an include file
 * that has been closed can still be called). */
typedef struct {
    const char *name; /* as shown in messages (scene arena) */
    const char *dir;  /* folder searched first for its #includes */
    const char *buf;
    size_t size, offset;
    int line, col;
    int controls_at_entry; /* control stack height when the file started */
    /* Text before this offset has been read before: a loop went back over
     * it, or (SIZE_MAX) the frame replays a macro body. Its tokens count
     * in the budget of repeated text. */
    size_t repeated_to;
    const struct Macro *macro; /* a macro body: the macro, else NULL */
    SourcePos called_at;       /* a macro body: the call's position */
} SourceFile;

/* A point in the input to come back to (#while, #for). */
typedef struct {
    int depth;
    size_t offset;
    int line, col;
} LexMark;

/* ---- values and symbols ---------------------------------------------------- */

typedef enum {
    VAL_NONE,
    VAL_NUMERIC, /* float, 2-5 component vector or colour: see terms */
    VAL_STRING,
    VAL_OBJECT,
    VAL_LIGHT,
    VAL_TEXTURE,
    VAL_PIGMENT,
    VAL_FINISH,
    VAL_INTERIOR,
    VAL_MATERIAL,    /* material_texture and material_interior (either may be NULL) */
    VAL_CAMERA,
    VAL_SKY_SPHERE,
    VAL_TRANSFORM,
    VAL_NORMAL,      /* parsed and forgotten: normals are not modelled */
    /* Declared blend maps (POV-Ray's COLOUR_MAP_ID ... NORMAL_MAP_ID): a
     * colour_map or pigment_map in `pigment` (its map, nmap and notes), a
     * texture_map in `texture` (map, nmap, map_depth), a normal_map or
     * slope_map in `normal` (map / slope). */
    VAL_COLOUR_MAP,
    VAL_PIGMENT_MAP,
    VAL_TEXTURE_MAP,
    VAL_NORMAL_MAP,
    VAL_SLOPE_MAP,
    VAL_UNSUPPORTED, /* a declaration of something hstrace cannot render */
    VAL_MACRO,
    VAL_ARRAY,
    VAL_FILE, /* a #fopen file identifier */
} ValueKind;

struct Symbol;
struct UserFile;

/* #macro Name(P1, P2, ...): where its body starts in its file's buffer. */
typedef struct Macro {
    const char *name;
    const char *file, *dir; /* the defining file, as in SourceFile */
    const char *buf;
    size_t size, body_offset;
    int body_line, body_col;
    int nparams;
    char **params;
    SourcePos declared_at;
} Macro;

/* array[N][M]...: elements are symbols so that a token can refer to one;
 * an element not yet given a value has kind VAL_NONE. */
#define MAX_ARRAY_DIMS 5
#define ARRAY_SIZE_CLASSES 32
typedef struct ArrayValue {
    int ndims;
    int size[MAX_ARRAY_DIMS];
    long count;
    long capacity; /* elements allocated (a recycled block may hold more than count) */
    struct Symbol *elems;
    SourcePos declared_at;
    struct ArrayValue *next_free; /* on the parser's list of recycled arrays */
} ArrayValue;

typedef struct {
    ValueKind kind;
    int terms;      /* VAL_NUMERIC: 1 float, 2-4 vector, 5 colour */
    double v[5];
    char *string;
    SceneObject *object;
    SceneLight *light;
    SceneTexture *texture;
    Pigment *pigment;
    const SceneNormal *normal;
    Finish *finish;
    Interior *interior;
    const SceneTexture *material_texture;
    const Interior *material_interior;
    SceneCamera *camera;
    SkySphere *sky;
    Transform *transform;
    Macro *macro;
    ArrayValue *array;
    struct UserFile *file;
    /* VAL_UNSUPPORTED: what it is ("'sphere'", "macro 'Foo'") and where the
     * unsupported thing was first written. */
    const char *what;
    SourcePos declared_at;
    int strict_only; /* approximated, and unsupported only because of --strict */
} Value;

typedef struct Symbol {
    struct Symbol *next;       /* in its hash bucket */
    struct Symbol *scope_next; /* the symbols of the same level */
    const char *name; /* interned (tok_intern_name) */
    int level; /* 0: global; each include file and macro call opens one more */
    unsigned serial; /* changes when the symbol is freed, so aliases notice */
    /* A macro parameter passed by reference: the caller's symbol, which
     * reads and #declare go to. */
    struct Symbol *alias;
    unsigned alias_serial;
    Value value;
} Symbol;

#define SYMBOL_BUCKETS 2048
#define MAX_SCOPE_LEVELS MAX_SOURCE_FRAMES

typedef struct {
    Symbol *buckets[SYMBOL_BUCKETS];
    Symbol *scopes[MAX_SCOPE_LEVELS]; /* per level, its symbols */
    int level;
    Symbol *free_list;
} SymbolTable;

/* ---- #if / #while / #for ---------------------------------------------------- */

typedef enum { CTL_IF, CTL_ELSE, CTL_WHILE, CTL_FOR, CTL_SWITCH } ControlKind;

typedef struct {
    ControlKind kind;
    int file_depth;
    SourcePos pos;  /* of the directive, for "missing #end" */
    LexMark loop;   /* #while: start of the condition; #for: start of the body */
    const char *for_var;
    double for_end, for_step;
    double switch_value; /* CTL_SWITCH: a #case matched, text is being read */
} Control;

/* A growable array in the temporary arena. */
typedef struct {
    void *data;
    int n, cap;
    size_t elem;
    int in_scene;   /* data is in the scene's arena (tok_tvec_reserve_kept), until it grows */
} TempVec;

/* An entry of the parser's open-addressing tables (literals, names). */
struct Interned {
    const char *key;
    char *value;
};

/* ---- the parser ----------------------------------------------------------- */

/* Limits that turn runaway input into an error instead of a hang or a
 * stack overflow (limits.c). POV-Ray has none; scenes that need more than
 * these (ParseOptions raises each) are far more likely endless loops or
 * recursions. The budgets of repeated text and of macro calls are what
 * stops an endless parse within seconds, whatever its loop's body holds. */
#define MAX_LOOP_ITERATIONS 10000000L
#define MAX_MACRO_CALLS 2000000L
#define MAX_REPEATED_TOKENS 20000000L
#define MAX_NESTING 200

/* What the token stream needs from the parts above it, whose headers it
 * does not include (parser/expressions, parser/grammar): #if's condition,
 * #for's bounds, #switch's value, an array's indices, a macro's arguments,
 * #declare, #default, #version's gamma mode, #read and #write's values.
 * The grammar fills them in when a parse starts (parse_scene.c), so that
 * the dependencies of the parser's parts go one way: grammar, expressions,
 * tokens, each using only the ones after it. */
struct Parser;
typedef struct {
    void (*expression)(struct Parser *p, double e[5], int *terms);
    double (*number)(struct Parser *p);      /* a float */
    double (*number_full)(struct Parser *p); /* a float, comparisons allowed */
    char *(*string)(struct Parser *p);
    int (*starts_float)(struct Parser *p, const Token *t);
    int (*starts_expression)(struct Parser *p, const Token *t);
    int (*starts_string)(struct Parser *p, const Token *t);
    /* Any value: unsupported things become VAL_UNSUPPORTED. */
    Value (*value)(struct Parser *p);
    void (*declare)(struct Parser *p, const Token *hash, int local);
    void (*default_directive)(struct Parser *p);
    void (*version_seen)(struct Parser *p);
} TokHooks;

typedef struct Parser {
    Scene *scene;
    Arena *arena; /* the scene's */
    Arena *temp;  /* freed when parsing ends */
    const ParseOptions *opts;
    ParseError *err;
    jmp_buf fail;
    const TokHooks *hooks; /* the parts above (TokHooks) */

    SourceFile *files; /* grown on demand up to MAX_SOURCE_FRAMES */
    int depth;         /* number of open frames (files and macro bodies) */
    int files_cap;
    int include_depth, macro_depth;
    int no_macro_calls; /* >0: identifiers are names (#declare X, #ifdef (X)) */

    Token tok;      /* the last token tok_next() returned */
    int ungot;      /* tok_next() returns tok again */
    int brace_depth;
    SourcePos last_pos;

    SymbolTable symbols;
    TempVec controls; /* of Control */
    /* limits.c: the work done so far, and its budgets */
    long loop_iterations, macro_calls, repeated_tokens;
    long max_loop_iterations, max_macro_calls, max_repeated_tokens;
    unsigned tokens_read;  /* the clock is read every 4096 tokens */
    double deadline;       /* clock_wall() seconds, or 0: none */

    double version;
    int version_given;
    int debug_line_open; /* #debug text on stderr does not end in a newline */
    int gamma_set;
    double assumed_gamma; /* 0 with gamma_set: srgb */

    /* limits.c: the lowest stack address a token may be read at, and the
     * levels of expressions and objects open (MAX_NESTING at most). */
    const char *stack_floor;
    int nesting;
    /* What the scene's arenas may take from the system (ParseOptions
     * .max_memory), and every file read so far (readfile.c). */
    ArenaBudget budget;
    TempVec read_files;
    /* Memory that stays flat when text is read again (a loop's next pass, a
     * macro's next call): string literals by where they stand in their
     * file's buffer (lexer.c), identifier names by their spelling
     * (symbols.c), and the arguments of the macro calls being read, a
     * stack whose slots the next call reuses (macros.c). */
    struct Interned *literals, *names;
    size_t nliterals, cap_literals, nnames, cap_names;
    TempVec arg_values, arg_refs;
    /* Arrays whose symbol was given another value or went away, by the
     * size class of their capacity (class k: 2^k to 2^(k+1) - 1
     * elements), for the next arrays to reuse (arrays.c). */
    struct ArrayValue *free_arrays[ARRAY_SIZE_CLASSES];

    /* Inside a #declare: unsupported things become VAL_UNSUPPORTED instead of
     * errors. `poison_jmp` leads back to the innermost declaration. */
    int declaring;
    jmp_buf *poison_jmp;
    const char *poison_what;
    SourcePos poison_at;
    /* Where the token that poisoned the value stands (an unsupported
     * keyword, an identifier holding an unsupported value, a texture layer
     * --strict refuses): when it is the last token read, the arguments of
     * what it starts may still follow. */
    SourcePos poison_by;
    /* An unsupported identifier or function inside a declared expression:
     * the expression is read to its end (its value is then unsupported). */
    const char *deferred_what;
    SourcePos deferred_at;

    TempVec rand_streams; /* of unsigned: seed() makes one, rand() draws */
    TempVec user_files;   /* of struct UserFile *: every #fopen, closed or not */
    struct UserFile *free_user_files; /* closed, forgotten: for the next #fopen */
    int poison_strict;

    /* The grammar's own state, which the token stream and the evaluator
     * never read (GramState in parser/grammar/grammar.h). */
    struct GramState *gram;
} Parser;

/* errors (errors.c) */
#if defined(__GNUC__)
#define HST_PRINTF(a, b) __attribute__((format(printf, a, b)))
#else
#define HST_PRINTF(a, b)
#endif
_Noreturn void tok_fail(Parser *p, SourcePos pos, const char *fmt, ...) HST_PRINTF(3, 4);
/* in copied to out (size bytes with the NUL) with every byte that is not
 * part of printable UTF-8 (controls, DEL, C1, malformed sequences) shown
 * as \xNN, except the characters in `keep` (NULL: none); cut short at a
 * whole character. Messages, warnings and #debug text go through it, so
 * that no byte of a scene reaches the terminal raw. Returns the length. */
size_t tok_text_escape(char *out, size_t size, const char *in, const char *keep);
/* A file's name as messages show it (escaped; the scene arena). */
const char *tok_display_name(Parser *p, const char *path);
/* Ends the line of #debug text on stderr, if the scene left one open, so
 * that the next message (a warning, the error) starts a line of its own. */
void tok_debug_end_line(Parser *p);
/* FILE:LINE:COLUMN: warning: MSG on stderr, on a line of its own. */
void tok_warning(Parser *p, SourcePos pos, const char *msg);
_Noreturn void tok_fail_io(Parser *p, SourcePos pos, const char *fmt, ...) HST_PRINTF(3, 4);
/* "expected X after Y, found Z" at the found token. */
_Noreturn void tok_fail_expected(Parser *p, const Token *found, const char *what);
/* An unsupported keyword at `t`: an error, or VAL_UNSUPPORTED in a #declare. */
_Noreturn void tok_unsupported(Parser *p, const Token *t);
/* The same for what no one token names (`what`, e.g. "'box' as a part of
 * 'merge'"), at pos. */
_Noreturn void tok_unsupported_at(Parser *p, SourcePos pos, const char *what);
/* A feature at `t` that hstrace approximates (an ApproxKind): a note added
 * to *notes; with --strict an error (in a #declare: a poisoned value). */
void tok_approximate(Parser *p, const Token *t, ApproxKind kind, const ApproxNote **notes);
/* The note alone, not refused by --strict here: for what approximates only
 * depending on the rest of the scene, which the collection decides
 * (gram_collect_approximations: photons). */
void tok_note_approximation(Parser *p, const Token *t, ApproxKind kind, const ApproxNote **notes);
/* Use of an identifier holding an unsupported declaration. */
_Noreturn void tok_use_unsupported(Parser *p, const Token *t, const Value *v);
/* In a declaration: remember the first unsupported thing of an expression
 * and skip its `(arguments)`; returns 0 outside declarations. */
int tok_defer_unsupported(Parser *p, const char *what, SourcePos at);
/* How messages name a token: its spelling or its string, cut short, or
 * "the end of the file" (the temporary arena). */
const char *tok_describe(Parser *p, const Token *t);

/* memory (memory.c) */
void *tok_scene_alloc(Parser *p, size_t size);       /* scene arena, checked */
void *tok_temp_alloc(Parser *p, size_t size);    /* temporary arena, checked */
char *tok_temp_strndup(Parser *p, const char *s, size_t n);
void tok_tvec_init(TempVec *v, size_t elem);
void *tok_tvec_push(Parser *p, TempVec *v); /* returns the new zeroed slot */
/* Room for n elements in all, made at once: a list whose count is written
 * first (mesh2's) then grows in one step, not by doubling (each doubling
 * copies the list and leaves the old copy in the arena). */
void tok_tvec_reserve(Parser *p, TempVec *v, int n);
/* tok_tvec_reserve in the scene's arena: a list that is kept as it is read
 * (mesh2's) is then not copied at its end (tok_tvec_kept). */
void tok_tvec_reserve_kept(Parser *p, TempVec *v, int n);
/* The elements in the scene's arena: the list's own (no copy) where
 * tok_tvec_reserve_kept made its room and it did not grow beyond, else a copy. */
void *tok_tvec_kept(Parser *p, const TempVec *v);
/* The elements as a copy in the scene's arena (they outlive the parse). */
void *tok_tvec_keep(Parser *p, const TempVec *v);

/* limits.c: the guards on what a scene may use while it is parsed. */
/* Notes how far down this thread's stack may go (the parse's entry). */
void tok_limits_init_stack(Parser *p);
_Noreturn void tok_limits_stack_exhausted(Parser *p, SourcePos pos);
/* Every token is read after this check (tok_lex), so every level of
 * every recursion of the parser meets it: true when the stack left below
 * the caller is down to the reserve, and the parse must stop with
 * tok_limits_stack_exhausted. (Stacks grow down on every machine hstrace
 * builds for.) */
static inline int tok_limits_stack_low(const Parser *p)
{
#if defined(__GNUC__)
    const char *here = __builtin_frame_address(0);
#else
    char probe;
    const char *here = &probe;
#endif
    return here < p->stack_floor;
}
/* The budgets of time and work (limits.c). tok_lex counts every token
 * read from text read before (a long one as several) and looks at the
 * clock now and then; loops count their iterations, macro calls
 * themselves. */
void tok_limits_init_work(Parser *p);
_Noreturn void tok_limits_work_exhausted(Parser *p, SourcePos pos, const char *what);
void tok_limits_check_time(Parser *p, SourcePos pos);
void tok_limits_count_iteration(Parser *p, SourcePos loop);
void tok_limits_count_call(Parser *p, SourcePos call, const char *macro);
/* A token was read from offset `from` to f->offset (blanks and comments
 * before it included). Read again, it counts one, and one more for every 16
 * bytes it spans, so that long strings and comments in a loop count what
 * they cost. */
static inline void tok_limits_count_token(Parser *p, const SourceFile *f, size_t from, SourcePos pos)
{
    if (from < f->repeated_to) {
        p->repeated_tokens += 1 + (long)((f->offset - from) >> 4);
        if (p->repeated_tokens > p->max_repeated_tokens)
            tok_limits_work_exhausted(p, pos, "tokens");
    }
    if ((++p->tokens_read & 4095u) == 0 && p->deadline > 0.0)
        tok_limits_check_time(p, pos);
}
/* One more level of an expression or an object (MAX_NESTING at most). */
int tok_nesting_enter(Parser *p, const Token *t);
void tok_nesting_leave(Parser *p);

/* The budget of ParseOptions.max_memory for the parse's arenas. */
void tok_limits_init_memory(Parser *p);
/* The memory the parse may still take from its budget. */
size_t tok_limits_memory_left(const Parser *p);
/* "out of memory", or, when the budget ran out, the budget's message. */
_Noreturn void tok_fail_memory(Parser *p, SourcePos pos);
/* The budget's message for what would need more than tok_limits_memory_left,
 * found before it is asked for. */
_Noreturn void tok_limits_over_budget(Parser *p, SourcePos pos);

/* readfile.c: a file's text, read whole (see there). */
typedef struct {
    const char *text; /* NUL-terminated, in the temporary arena */
    size_t size;
    const char *name; /* the path it was read by (scene arena) */
    const char *dir;  /* its folder, searched first by its #includes */
    int again;        /* read before: its text counts as repeated text */
} SourceText;
void tok_source_files_init(Parser *p);
/* Reads path whole: 1 and *out; 0 when it cannot be opened (errno says
 * why, the caller words the message). What is no regular file, a read
 * error, a zero byte in the text or a file beyond the memory budget are
 * errors at `at`. */
int tok_source_read(Parser *p, const char *path, SourcePos at, SourceText *out);
/* The same for dir/name ("." : name as it is). */
int tok_source_read_in(Parser *p, const char *dir, const char *name, SourcePos at, SourceText *out);

/* lexer.c */
void tok_open_buffer(Parser *p, const char *name, const char *buf, size_t size, SourcePos at);
/* A file read by tok_source_read, on top of the include stack. */
void tok_open_source(Parser *p, const SourceText *s, SourcePos at);
void tok_open_macro(Parser *p, const Macro *m, SourcePos called_at);
int tok_peek_char(Parser *p); /* the next character after blanks, or -1 */
size_t tok_offset(Parser *p);
/* The folders a relative #include (and #fopen ... read) name is looked
 * for in, in order: the current file's, then each include folder. */
int tok_search_dirs(Parser *p, const char **dirs, int cap);
void tok_raw(Parser *p, Token *t); /* TK_EOF at the end of the current file */
/* The next token of f, which need not be on the include stack (#read's
 * data is written in the scene language's tokens). */
void tok_lex(Parser *p, SourceFile *f, Token *t);
LexMark tok_mark(Parser *p);
void tok_seek(Parser *p, LexMark m);
/* A vector of three plain numbers, `<1, -2.5, 3e2>`, read straight from
 * the text (the '<' already read when had_angle): the tokens tok_raw would
 * read, counted as it counts them, and the same numbers, without making
 * them tokens. Returns 1 positioned after the '>' (what follows is not
 * looked at), or 0 positioned where it started (the text is something
 * else: the caller reads it by the general path). */
int tok_plain_vector(Parser *p, int had_angle, double c[3]);
/* The bytes of the current file (or macro) after the lexer's position. */
size_t tok_bytes_left(Parser *p);
/* The number whose text starts at b[start] (a digit, or '.' and a digit),
 * as the lexer reads it: its end in *end, its value in *value. Returns 0
 * when the text is too long to convert (an error at the number). */
int tok_number_text(const char *b, size_t start, size_t size, size_t *end, double *value);
/* plain_lists.c: the n items of a long list of plain vectors, `<1, -2.5,
 * 3e2>` with optional commas between, read on ParseOptions.threads threads
 * into out (vertex_vectors) or, with faces, as faces' vertex indices below
 * nvertices: 1 positioned after the n-th vector's '>', as the item by item
 * reading would leave it (the tokens counted); 0, positioned where it
 * started, when the text is anything else (a comment, an identifier, an
 * index out of range, more or fewer than n vectors ...): the caller reads
 * it item by item, which reports what is wrong. */
int tok_plain_vector_list(Parser *p, int n, Vec3 *out, MeshFace *faces, int nvertices);
int tok_skip_semicolon(Parser *p); /* consume a ';' if it comes next */
/* Whether the next token is keyword kw, looking at the raw text so that no
 * directive is carried out early (the current #declare is not stored yet). */
int tok_next_is_keyword(Parser *p, int kw);
int tok_next_is_punct(Parser *p, int c); /* the same for punctuation */
/* Whether the raw text goes on with '{' and a word (keyword or identifier),
 * which is then in `word`; nothing is consumed. */
int tok_next_is_brace_and_word(Parser *p, Token *word);
const char *tok_dir_of(Parser *p, const char *path);

/* directives.c: the token stream after #directives */
Token *tok_next(Parser *p);
void tok_unget(Parser *p);
Token *tok_peek(Parser *p);
int tok_is_punct(const Token *t, int c);
int tok_is_kw(const Token *t, int kw);
void tok_expect_punct(Parser *p, int c, const char *after);
void tok_begin_block(Parser *p, const char *after); /* '{' after `after` */
void tok_skip_block_body(Parser *p);                /* after '{': to its '}' */
void tok_skip_balanced_group(Parser *p, const Token *open);
/* A name, not expanded as a macro call: #declare X, #ifdef (X), ... */
Token *tok_next_name(Parser *p);

/* symbols.c */
void tok_symbols_init(Parser *p);
/* The one copy of a name (temporary arena): the same spelling, the same
 * pointer, so that symbols made again and again cost their name once. */
const char *tok_intern_name(Parser *p, const char *name, int len);
/* The innermost visible symbol (an alias resolved to its target). */
Symbol *tok_symbol_find(Parser *p, const char *name, int len);
/* The symbol a token names: an array element, else tok_symbol_find(); fails on
 * an element that has no value yet. NULL when the name is undeclared. */
Symbol *tok_symbol_of(Parser *p, const Token *t);
/* #declare (local 0) / #local (1) as POV-Ray does it: an existing visible
 * identifier (#local: of the current level) is overwritten in place, through
 * a by-reference macro parameter to the caller's; else a new one is made at
 * the global (#declare) or current (#local) level. */
void tok_symbol_set(Parser *p, const char *name, int len, int local, const Value *v);
/* A new symbol at the current level, hiding outer ones (macro parameters). */
Symbol *tok_symbol_add_local(Parser *p, const char *name, int len, const Value *v);
void tok_symbol_define_global(Parser *p, const char *name, int len, const Value *v);
void tok_symbol_undef(Parser *p, const char *name, int len);
void tok_push_scope(Parser *p);
void tok_pop_scope(Parser *p);

/* macros.c */
void tok_macro_define(Parser *p, const Token *hash); /* after '#macro' */
void tok_macro_invoke(Parser *p, const Token *call, const Macro *m); /* after the name */
void tok_macro_return(Parser *p);
void tok_macro_skip_body(Parser *p, SourcePos from); /* directives.c: to the #end */

/* arrays.c */
Value tok_array_value(Parser *p, const Token *kw); /* after 'array' */
/* tok_next() read the name of array s and '[' follows: read the indices and
 * make p->tok that element. */
void tok_array_element(Parser *p, Symbol *s);
double tok_array_function(Parser *p, const Token *t); /* dimensions, dimension_size */
/* The value a symbol or an array element held is given up (it gets
 * another value, or the symbol goes away): an array in it, and the arrays
 * in its elements, are kept for reuse. Every array belongs to one symbol
 * or element, since reading an array's name copies it (gram_copy_value); an
 * element's serial changes, so tokens and by-reference parameters that
 * still point into it notice. Anything else in the value stays where it
 * is (the arenas). */
void tok_value_give_up(Parser *p, Value *v);
/* An array of `count` elements, all without a value: a recycled one when
 * one fits, else new (temporary arena). */
ArrayValue *tok_array_new(Parser *p, long count);
/* A token's array element, or NULL when its array no longer exists: the
 * right side of `#declare A[i] = ...` may have declared A anew. POV-Ray
 * renders such a scene; the value then goes into the array that was
 * replaced, which nothing can read any more: it is given up. */
Symbol *tok_element_of(const Token *t);
/* fileio.c: #fopen, #fclose, #read, #write (after the keyword) */
void tok_fopen(Parser *p, const Token *hash);
void tok_fclose(Parser *p);
void tok_read(Parser *p);
void tok_write(Parser *p);
/* Closes every file still open. With `report`, a failed close (a write
 * error, e.g. a full disk) is an I/O error; without, errors are ignored
 * (the parse is already failing). */
void tok_user_files_close_all(Parser *p, int report);

const char *tok_value_kind_name(ValueKind k);

#endif
