/* Hostile input to the parser: every recursive production nested deep
 * enough to have overflowed the stack is "nested too deeply" at a position
 * inside the nesting (on the main thread and on a thread with a small
 * stack), and the same productions nested 90 deep still parse. */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

int main(void)
{
    test_nesting_by_copies();
    test_deep();
    test_small_stack();
    test_shallow();
    return tap_done();
}
