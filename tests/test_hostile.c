/* Hostile input to the parser: every recursive production nested deep
 * enough to have overflowed the stack is "nested too deeply" at a position
 * inside the nesting (on the main thread and on a thread with a small
 * stack), and the same productions nested 90 deep still parse. Numbers
 * that become integers (counts, levels, indices, characters) are refused
 * with their position when NaN, infinite or out of range, or clamped where
 * POV-Ray clamps; infinite and NaN geometry, cameras and colours are
 * refused at the value. Memory stays within the budget and flat across a
 * loop's passes and a macro's calls; endless loops and recursions stop at
 * the budgets of work and time, naming the position, the loop or macro
 * and the calls that led there. Bytes of the scene that are not printable
 * UTF-8 reach messages escaped. */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "parser.h"
#include "tap.h"

static ParseOptions opts = { .image_width = 32, .image_height = 24 };

/* A text built as head, `level` n times, core, `tail` n times, end. */
typedef struct {
    const char *name;
    const char *head, *level, *core, *tail, *end;
    /* 1: the 200-level count of expressions and objects stops it, at the
     * start of a level; 0: the stack guard does, at a token inside. */
    int counted;
} Production;

static const Production productions[] = {
    { "parentheses", "#declare X = ", "(", "1", ")", ";\n", 1 },
    { "unary minus", "#declare X = ", "-", "1", "", ";\n", 1 },
    { "function arguments", "#declare X = ", "abs(", "1", ")", ";\n", 1 },
    { "conditional", "#declare X = (", "1 ? ", "1", " : 0", ");\n", 1 },
    { "vector components", "#declare X = ", "<1, ", "1", ">.x", ";\n", 1 },
    { "#if in an #if condition", "#declare X = ", "#if (", "1", ") #end 1", ";\n", 0 },
    { "array indices", "#declare A = array[1] { 0 }\n#declare X = ", "A[", "0", "]", ";\n", 0 },
    { "union", "", "union { ", "triangle { 0, x, y }", " }", "\n", 1 },
    { "object", "", "object { ", "triangle { 0, x, y }", " }", "\n", 1 },
    { "concat", "#declare S = ", "concat(", "\"a\"", ")", ";\n", 0 },
    { "strupr", "#declare S = ", "strupr(", "\"a\"", ")", ";\n", 0 },
    { "strlwr", "#declare S = ", "strlwr(", "\"a\"", ")", ";\n", 0 },
    { "substr", "#declare S = ", "substr(", "\"abc\"", ", 1, 1)", ";\n", 0 },
    { "vstr", "#declare S = ", "vstr(2, <1, 2>, ", "\",\"", ", 0, 0)", ";\n", 0 },
    { "macro call as a macro argument", "#macro M(A) A #end\n#declare X = ", "M(", "1", ")", ";\n", 0 },
    { "transform", "#declare T = ", "transform { ", "scale 2", " }", "\n", 0 },
    { "checker pigments", "#declare P = pigment { ", "checker pigment { ", "rgb 1", " }", " }\n", 0 },
    { "pigment_map", "#declare P = pigment { ", "gradient x pigment_map { [0 ", "rgb 1", "] }", " }\n", 0 },
    { "color_map in pigment_map", "#declare P = pigment { ",
      "gradient x pigment_map { [0 gradient y color_map { [0 rgb 1] } ", "rgb 1", "] }", " }\n", 0 },
    { "#declare in #declare", "#declare B = ", "#declare A = ", "1", "; 1", ";\n", 0 },
    { "array initialisers", "#declare A = ", "array[1] { ", "1", " }", "\n", 0 },
};
#define NPRODUCTIONS ((int)(sizeof productions / sizeof productions[0]))

static char *build(const Production *pr, int n, size_t *nest_from, size_t *nest_to)
{
    size_t lh = strlen(pr->head), ll = strlen(pr->level), lc = strlen(pr->core), lt = strlen(pr->tail);
    size_t size = lh + (ll + lt) * (size_t)n + lc + strlen(pr->end) + 1;
    char *s = malloc(size), *o = s;
    if (!s)
        return NULL;
    memcpy(o, pr->head, lh), o += lh;
    *nest_from = (size_t)(o - s);
    for (int i = 0; i < n; i++)
        memcpy(o, pr->level, ll), o += ll;
    *nest_to = (size_t)(o - s);
    memcpy(o, pr->core, lc), o += lc;
    for (int i = 0; i < n; i++)
        memcpy(o, pr->tail, lt), o += lt;
    strcpy(o, pr->end);
    return s;
}

/* The column of offset `at` on its line, and the line. */
static void position_of(const char *s, size_t at, int *line, int *col)
{
    *line = 1;
    size_t start = 0;
    for (size_t i = 0; i < at; i++)
        if (s[i] == '\n') {
            (*line)++;
            start = i + 1;
        }
    *col = (int)(at - start) + 1;
}

typedef struct {
    const Production *pr;
    int depth;
    int small_stack;
    int ok;
    char what[1200];
} Job;

/* Deep: must fail with "nested too deeply" inside the nesting. */
static void run_deep(Job *j)
{
    size_t from, to;
    char *text = build(j->pr, j->depth, &from, &to);
    ParseError err;
    Scene *s = text ? parse_scene_string("deep.pov", text, &opts, &err) : NULL;
    int line_from, col_from, line_to, col_to;
    if (text) {
        position_of(text, from, &line_from, &col_from);
        position_of(text, to, &line_to, &col_to);
    }
    if (!text) {
        snprintf(j->what, sizeof j->what, "out of memory building the text");
    } else if (s) {
        snprintf(j->what, sizeof j->what, "parsed at depth %d", j->depth);
    } else if (!strstr(err.message, "nested too deeply")) {
        snprintf(j->what, sizeof j->what, "%s:%d:%d: %s", err.file, err.line, err.column, err.message);
    } else {
        int inside = line_from == line_to && err.line == line_from && err.column >= col_from && err.column <= col_to;
        j->ok = inside;
        if (j->pr->counted && !j->small_stack) /* the count comes before the stack runs short */
            j->ok = inside && strcmp(err.message, "nested too deeply (more than 200 levels)") == 0;
        snprintf(j->what, sizeof j->what, "%d:%d: %s (nesting from %d:%d to %d:%d)", err.line, err.column,
                 err.message, line_from, col_from, line_to, col_to);
    }
    scene_free(s);
    free(text);
}

static void *run_deep_thread(void *arg)
{
    run_deep(arg);
    return NULL;
}

static void test_deep(void)
{
    for (int i = 0; i < NPRODUCTIONS; i++) {
        Job j = { &productions[i], 100000, 0, 0, "" };
        run_deep(&j);
        tap_ok(j.ok, "%s nested %d deep: %s", j.pr->name, j.depth, j.what);
    }
}

/* The guard measures the stack of the thread it runs on: a parse on a
 * thread with 256 KiB of stack stops as cleanly. */
static void test_small_stack(void)
{
    for (int i = 0; i < NPRODUCTIONS; i++) {
        Job j = { &productions[i], 100000, 1, 0, "" };
        pthread_attr_t attr;
        pthread_t tid;
        pthread_attr_init(&attr);
        pthread_attr_setstacksize(&attr, 256 * 1024);
        if (pthread_create(&tid, &attr, run_deep_thread, &j) == 0)
            pthread_join(tid, NULL);
        else
            snprintf(j.what, sizeof j.what, "cannot start a thread");
        pthread_attr_destroy(&attr);
        tap_ok(j.ok, "%s nested %d deep on a 256 KiB stack: %s", j.pr->name, j.depth, j.what);
    }
}

static void test_shallow(void)
{
    for (int i = 0; i < NPRODUCTIONS; i++) {
        const Production *pr = &productions[i];
        size_t from, to;
        int depth = 90; /* parentheses count two levels each: 180 of 200 */
        char *text = build(pr, depth, &from, &to);
        ParseError err;
        Scene *s = text ? parse_scene_string("shallow.pov", text, &opts, &err) : NULL;
        tap_ok(s != NULL, "%s nested %d deep parses", pr->name, depth);
        if (!s)
            tap_diag("%s:%d:%d: %s", err.file, err.line, err.column, err.message);
        scene_free(s);
        free(text);
    }
}

/* Parses text expecting failure at line:col with msg in the message. */
static void expect_error(const char *text, int line, int col, const char *msg, const char *what)
{
    ParseError err;
    Scene *s = parse_scene_string("t.pov", text, &opts, &err);
    int ok = !s && err.line == line && err.column == col && strstr(err.message, msg) != NULL;
    tap_ok(ok, "%s", what);
    if (!ok)
        tap_diag("got %s -> %s:%d:%d: %s", s ? "a scene" : "error", err.file, err.line, err.column, err.message);
    scene_free(s);
}

/* Nesting that grows without nesting in the text: copies of a union put in
 * a new union, an array stored in its own element, in a loop. */
static void test_nesting_by_copies(void)
{
    expect_error("#declare U = union { triangle { 0, x, y } }\n"
                 "#declare I = 0;\n"
                 "#while (I < 100000)\n"
                 "  #declare U = union { object { U } }\n"
                 "  #declare I = I + 1;\n"
                 "#end\n",
                 4, 16, "nested too deeply (unions inside unions more than 200 levels)",
                 "a union holding a copy of itself, 100000 times: nested too deeply at the 200th");
    expect_error("#declare A = array[1];\n"
                 "#declare A[0] = 1;\n"
                 "#declare I = 0;\n"
                 "#while (I < 100000)\n"
                 "  #declare A[0] = A;\n"
                 "  #declare I = I + 1;\n"
                 "#end\n",
                 5, 19, "nested too deeply (arrays in arrays more than 200 levels)",
                 "an array stored in its own element, 100000 times: nested too deeply at the 200th");
}

static Scene *parse_ok(const char *text, const char *what)
{
    ParseError err;
    Scene *s = parse_scene_string("t.pov", text, &opts, &err);
    tap_ok(s != NULL, "%s", what);
    if (!s)
        tap_diag("%s:%d:%d: %s", err.file, err.line, err.column, err.message);
    return s;
}

/* NaN below is 0 * 1e309 (1e309 reads as infinity, as in POV-Ray). */
static void test_conversions(void)
{
    Scene *s = parse_ok("global_settings { max_trace_level 1e10 }", "max_trace_level 1e10 parses");
    tap_ok(s && s->globals.max_trace_level == 256, "max_trace_level 1e10 is POV-Ray's limit, 256 (got %d)",
           s ? s->globals.max_trace_level : -1);
    scene_free(s);
    s = parse_ok("global_settings { max_trace_level -1e10 }", "max_trace_level -1e10 parses");
    tap_ok(s && s->globals.max_trace_level == 1, "max_trace_level -1e10 is 1, as POV-Ray's max(1, ...)");
    scene_free(s);
    expect_error("#declare N = 0 * 1e309;\nglobal_settings { max_trace_level N }", 2, 35,
                 "expected a finite number, found nan", "max_trace_level NaN: refused at the value");
    expect_error("#declare S = chr(1e10);", 1, 18, "chr(1e+10): a character code is from 0 to 65535", "chr(1e10)");
    expect_error("#declare S = chr(0 * 1e309);", 1, 18, "a character code is from 0 to 65535", "chr(NaN)");
    expect_error("#declare S = chr(-1);", 1, 18, "a character code is from 0 to 65535", "chr(-1)");
    expect_error("triangle { 0, x, y finish { reflection { 0.5 fresnel 1e10 } } }", 1, 46,
                 "fresnel must be true or false", "fresnel 1e10");
    expect_error("#declare N = 0 * 1e309;\ntriangle { 0, x, y finish { reflection { 0.5 fresnel N } } }", 2, 54,
                 "expected a finite number, found nan", "fresnel NaN");
    s = parse_ok("triangle { 0, x, y pigment { bozo octaves 1e10 } }\n"
                 "triangle { 0, x, y pigment { bozo octaves -1e10 } }",
                 "octaves 1e10 and -1e10 parse");
    tap_ok(s && s->objects[0]->texture->pigment.turbulence[0].octaves == 10 &&
               s->objects[1]->texture->pigment.turbulence[0].octaves == 1,
           "octaves are held to POV-Ray's 1 to 10");
    scene_free(s);
    expect_error("global_settings { noise_generator 1e10 }", 1, 35, "must be 1, 2, or 3", "noise_generator 1e10");
    expect_error("triangle { 0, x, y pigment { bozo noise_generator -1e10 } }", 1, 51, "must be 0, 1, 2, or 3",
                 "a pigment's noise_generator -1e10");
    expect_error("polygon { 1e10, <0, 0>, <1, 0>, <0, 1> }", 1, 11, "polygon: 1e+10 is not a usable count",
                 "polygon count 1e10");
    expect_error("#declare N = 0 * 1e309;\n#declare A = array[N];", 2, 20, "invalid array size nan",
                 "array size NaN");
    expect_error("#declare A = array[3];\n#declare B = A[1e10];", 2, 16, "index 1e+10 is out of range",
                 "array index 1e10");
    expect_error("#declare N = 0 * 1e309;\n#declare A = array[3];\n#declare B = A[N];", 3, 16, "index nan is out of range",
                 "array index NaN");
    s = parse_ok("#declare A = array[3][4];\n#declare D = dimension_size(A, 1e10);\nbox { 0, D + 1 }",
                 "dimension_size(A, 1e10) parses");
    tap_ok(s && s->objects[0]->u.box.corner2.x == 1.0, "dimension_size of a dimension A lacks is 0, as POV-Ray's");
    scene_free(s);
    expect_error("#declare S = substr(\"abc\", 0 * 1e309, 1);", 1, 14, "'substr' range outside the string",
                 "substr start NaN");
    expect_error("#declare S = substr(\"abc\", 1, 1e10);", 1, 14, "'substr' range outside the string",
                 "substr length 1e10");
    expect_error("mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0, 1, 1e10> } }", 1, 57,
                 "mesh2 face index out of range (3 vertices)", "mesh2 face index 1e10");
    expect_error("mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0, 1, 0 * 1e309> } }", 1, 57,
                 "expected a finite vector, found <0, 1, nan>", "mesh2 face index NaN");
    s = parse_ok("fog { distance 1 fog_type 1e10 rgb 1 }", "fog_type 1e10: POV-Ray's warning, and on");
    scene_free(s);
    s = parse_ok("triangle { 0, x, y pigment { spiral1 1e10 } }", "spiral1 1e10 parses");
    tap_ok(s && s->objects[0]->texture->pigment.arms == 0, "spiral1 1e10 has POV-Ray's (short)(int) arms, 0 (got %d)",
           s ? s->objects[0]->texture->pigment.arms : -1);
    scene_free(s);
    /* POV-Ray's domain errors, in its words */
    expect_error("#declare X = sqrt(-1);", 1, 14, "sqrt of negative number -1.000000", "sqrt(-1)");
    expect_error("#declare X = ln(0);", 1, 14, "ln of negative number 0.000000", "ln(0)");
    expect_error("#declare X = log(-2);", 1, 14, "log of negative number -2.000000", "log(-2)");
}

static void test_infinite_values(void)
{
    expect_error("triangle { 0, x, <0, 1/0, 0> }", 1, 18, "expected a finite vector, found <0, inf, 0>",
                 "a triangle vertex 1/0");
    expect_error("triangle { 0, x, <0, 1e309, 0> }", 1, 18, "expected a finite vector, found <0, inf, 0>",
                 "a triangle vertex 1e309 (the fast path for plain numbers too)");
    expect_error("#declare N = val(\"nan\");\ncamera { location <N, 0, -5> look_at 0 }", 2, 19,
                 "expected a finite vector, found <nan, 0, -5>", "a camera location val(\"nan\")");
    expect_error("camera { angle 1e309 }", 1, 16, "expected a finite number, found inf", "a camera angle 1e309");
    expect_error("plane { y, -1e309 }", 1, 12, "expected a finite number, found -inf", "a plane distance -1e309");
    expect_error("light_source { 0, rgb <1, 1e309, 1> }", 1, 19, "expected a finite colour, found <1, inf, 1>",
                 "a light's colour 1e309");
    expect_error("triangle { 0, x, y pigment { rgb 1 - 1e309 } }", 1, 30, "expected a finite colour, found <-inf, -inf, -inf, 0, 0>",
                 "a pigment colour -inf");
    /* inside expressions and declarations, any value */
    Scene *s = parse_ok("#declare Big = 1e309;\n#declare V = <1, 1/0, 3>;\n#if (Big > 1) box { 0, V.x } #end",
                        "infinities inside expressions and declarations are values");
    scene_free(s);
    s = parse_ok("camera { location <1e308, 0, -5> look_at 0 }\ntriangle { 0, x, y }",
                 "a camera 1e308 away is finite: POV-Ray renders it, so does hstrace");
    scene_free(s);
}

/* Parses with a budget; returns the scene, or NULL with err filled. */
static Scene *parse_with(const char *text, const ParseOptions *o, ParseError *err)
{
    return parse_scene_string("t.pov", text, o, err);
}

static void test_memory(void)
{
    ParseOptions o = opts;
    ParseError err;
    o.max_memory = 16u << 20;
    Scene *s = parse_with("#declare A = array[1e8];", &o, &err);
    tap_ok(!s && err.line == 1 && err.column == 20 &&
               strcmp(err.message, "the scene needs more than 16 MiB of memory while it is parsed (--max-memory sets the budget)") == 0,
           "array[1e8] with a 16 MiB budget: refused at the size (%d:%d: %s)", err.line, err.column, err.message);
    scene_free(s);
    /* Memory flat across iterations: each of these took a few hundred
     * bytes (calls) or a kilobyte (literals, arrays) per pass, 50 to 800
     * MiB here. */
    static char loop[2600];
    char lit[1001];
    memset(lit, 'x', 1000);
    lit[1000] = '\0';
    struct {
        const char *what;
        const char *text;
    } flat[] = {
        { "200000 calls of a one-argument macro", "#macro M(A) #local B = A; #end\n"
                                                  "#for (I, 1, 200000) M(I) #end\n" },
        { "200000 calls with two string arguments", "#macro M(A, B) #end\n"
                                                     "#for (I, 1, 200000) M(\"one\", concat(\"t\", \"wo\")) #end\n" },
        { "200000 calls of a macro with a #local array[16]", "#macro M(A) #local V = array[16]; #local V[3] = A; #end\n"
                                                              "#for (I, 1, 200000) M(I) #end\n" },
        { "200000 passes declaring an array of arrays anew", "#for (I, 1, 200000)\n"
                                                              "#declare G = array[2] { array[8], array[3] { I, 1, 2 } };\n"
                                                              "#declare H = G; #end\n" },
        { "200000 passes over a 1000-character literal under a false #if", loop },
        { "200000 passes over a 1000-character literal", loop + 1300 },
    };
    snprintf(loop, 1300, "#for (I, 1, 200000) #if (0) #declare S = \"%s\"; #end #end\n", lit);
    snprintf(loop + 1300, 1300, "#for (I, 1, 200000) #declare S = \"%s\"; #end\n", lit);
    o.max_memory = 8u << 20;
    for (size_t i = 0; i < sizeof flat / sizeof flat[0]; i++) {
        s = parse_with(flat[i].text, &o, &err);
        tap_ok(s != NULL, "%s: within 8 MiB", flat[i].what);
        if (!s)
            tap_diag("%s:%d:%d: %s", err.file, err.line, err.column, err.message);
        scene_free(s);
    }
    /* what does grow is bounded: a new string per pass */
    s = parse_with("#for (I, 1, 10000000) #declare S = concat(\"a\", str(I, 0, 0)); #end\n", &o, &err);
    tap_ok(!s && err.line == 1 && strstr(err.message, "more than 8 MiB of memory"),
           "strings made anew in a loop stop at the budget (%d:%d: %s)", err.line, err.column, err.message);
    scene_free(s);
}

/* Only the first line of the notes: the innermost call. */
static int first_note_is(const ParseError *err, const char *want)
{
    return strncmp(err->notes, want, strlen(want)) == 0;
}

static void test_time(void)
{
    ParseOptions o = opts;
    ParseError err;
    Scene *s = parse_with("#macro M(N)\n  #if (N > 0) M(N - 1) M(N - 1) #end\n#end\nM(60)\n", &o, &err);
    tap_ok(!s && strstr(err.message, "more than 20000000 tokens read again by loops and macro calls") &&
               strstr(err.message, "is the recursion of macro 'M' endless?") && err.line >= 2 && err.line <= 3 &&
               first_note_is(&err, "t.pov:2:") && strstr(err.notes, "and ") != NULL,
           "exponential recursion M(60): the budget of repeated text, in M, with the calls (%d:%d: %s)", err.line,
           err.column, err.message);
    scene_free(s);
    s = parse_with("#declare I = 0;\n#while (1)\n  #declare I = sin(I) * cos(I) + sqrt(abs(I)) + I * I / (I + 1);\n#end\n",
                   &o, &err);
    tap_ok(!s && strstr(err.message, "is the #while at t.pov:2 endless?") && err.line == 3,
           "an endless #while with a heavy body: the budget, naming the loop (%d:%d: %s)", err.line, err.column,
           err.message);
    scene_free(s);
    s = parse_with("mesh2 { vertex_vectors { 50000000,\n#declare I = 0;\n#while (I < 10)\n<I, 0, 0>,\n#declare I = I;\n#end\n} }",
                   &o, &err);
    tap_ok(!s && strstr(err.message, "is the #while at t.pov:3 endless?"),
           "an endless loop inside mesh2 (a mutated #declare): the budget (%d:%d: %s)", err.line, err.column,
           err.message);
    scene_free(s);
    /* a long comment, or a long literal skipped by a false #if, is one
     * token or none: the budget counts its bytes */
    static char longtext[2][120100];
    memset(longtext, 0, sizeof longtext);
    strcpy(longtext[0], "#while (1)\n/* ");
    memset(longtext[0] + strlen(longtext[0]), 'x', 120000);
    strcat(longtext[0], " */\n#end\n");
    strcpy(longtext[1], "#while (1)\n#if (0) \"");
    memset(longtext[1] + strlen(longtext[1]), 'x', 120000);
    strcat(longtext[1], "\" #end\n#end\n");
    for (int i = 0; i < 2; i++) {
        s = parse_with(longtext[i], &o, &err);
        tap_ok(!s && strstr(err.message, "is the #while at t.pov:1 endless?"),
               "an endless #while over a 120000-byte %s: the budget counts its bytes (%d:%d: %s)",
               i ? "literal under a false #if" : "comment", err.line, err.column, err.message);
        scene_free(s);
    }
    o.max_macro_calls = 1000;
    s = parse_with("#macro M(N)\n  #if (N > 0) M(N - 1) M(N - 1) #end\n#end\nM(60)\n", &o, &err);
    tap_ok(!s && strcmp(err.message, "more than 1000 macro calls (--max-macro-calls): is the recursion of macro 'M' endless?") == 0 &&
               err.line == 2 && first_note_is(&err, "t.pov:2:"),
           "1000 macro calls at most: at the 1001st call (%d:%d: %s)", err.line, err.column, err.message);
    scene_free(s);
    o = opts;
    o.max_parse_seconds = 0.2;
    s = parse_with("#while (1) #end\n", &o, &err);
    tap_ok(!s && strstr(err.message, "the parse ran for more than 0.2 s (--max-parse-seconds): is the #while at t.pov:1 endless?"),
           "--max-parse-seconds 0.2 stops an endless loop (%d:%d: %s)", err.line, err.column, err.message);
    scene_free(s);
    /* what real scenes do stays well inside: 100000 iterations, 100000 calls */
    o = opts;
    s = parse_with("#macro Add(A, B) (A + B) #end\n#declare S = 0;\n#for (I, 1, 100000) #declare S = Add(S, I); #end\n",
                   &o, &err);
    tap_ok(s != NULL, "100000 iterations calling a macro parse within the default budgets");
    scene_free(s);
}

static void test_escaped_bytes(void)
{
    expect_error("#error \"bad \x1b[31mred\xff\xfe caf\xc3\xa9\"\n", 1, 1,
                 "#error: bad \\x1b[31mred\\xff\\xfe caf\xc3\xa9", "#error: control and malformed bytes escaped, UTF-8 kept");
    expect_error("#include \"\x1b]0;title\x07\"\n", 1, 10, "cannot open include file '\\x1b]0;title\\x07'",
                 "an include name with terminal controls, escaped");
    expect_error("box { 0, \"\xc0\xaf\xed\xa0\x80\xc2\x85\" }", 1, 10,
                 "expected a numeric expression, found string \"\\xc0\\xaf\\xed\\xa0\\x80\\xc2\\x85\"",
                 "overlong, surrogate and C1 sequences escaped");
    char dir[] = "hst_hostile_XXXXXX"; /* in the build folder, where the test runs */
    if (!mkdtemp(dir)) {
        tap_ok(0, "temporary folder");
        return;
    }
    char path[256], text[600];
    snprintf(path, sizeof path, "%s/a\x1b[1mb.inc", dir);
    FILE *f = fopen(path, "w");
    if (f) {
        fputs("#declare X = ;\n", f);
        fclose(f);
    }
    snprintf(text, sizeof text, "#include \"%s\"\n", path);
    ParseError err;
    Scene *s = parse_scene_string("t.pov", text, &opts, &err);
    char want[300];
    snprintf(want, sizeof want, "%s/a\\x1b[1mb.inc", dir);
    tap_ok(!s && strcmp(err.file, want) == 0 && err.line == 1 && err.column == 14,
           "an error inside a file whose name has controls: the name escaped (%s:%d:%d)", err.file, err.line, err.column);
    scene_free(s);
    remove(path);
    rmdir(dir);
}

int main(void)
{
    test_escaped_bytes();
    test_memory();
    test_time();
    test_conversions();
    test_infinite_values();
    test_nesting_by_copies();
    test_deep();
    test_small_stack();
    test_shallow();
    return tap_done();
}
