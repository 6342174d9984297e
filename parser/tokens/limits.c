/* What a scene may use while it is parsed: the C stack, nesting, memory,
 * time and work.
 *
 * The parser is recursive descent, and its recursion runs through tok_next():
 * a directive can stand anywhere, so nearly every production can reach
 * every other through it (one strongly connected call graph of about a
 * hundred functions). Rather than a counter in each production, which a new
 * production could forget, the one guard sits where every level of every
 * recursion passes: the lexer, which checks at each token how much of the
 * calling thread's stack is left (limits_check_stack, inlined in
 * tok_lex). A scene nested too deeply for the stack gets
 * "nested too deeply" at the token where the stack ran short.
 *
 * Recursions that read no tokens are bounded where they are built: a union
 * records how deep it nests (SceneObject.depth) and an array value how deep
 * its element arrays go, both capped at MAX_NESTING; expressions and
 * objects keep their 200-level count (tok_nesting_enter), which makes those
 * errors land at the same place whatever the build. */
#define _GNU_SOURCE /* pthread_getattr_np: the real bounds of this thread's stack */
#include "config.h"

#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include "memory_budget.h"
#include "tokens.h"

/* Stack kept back below the deepest token: what a production may use
 * between two tokens (number conversion, messages, the error path itself,
 * all of it larger under AddressSanitizer) must fit in it. */
static size_t stack_reserve(size_t stack_size)
{
    size_t r = stack_size / 8;
    return r < 128 * 1024 ? 128 * 1024 : r;
}

void tok_limits_init_stack(Parser *p)
{
    char *here = __builtin_frame_address(0);
    size_t size = 0;
    char *lowest = NULL;
#if defined(HAVE_PTHREAD_GETATTR_NP)
    pthread_attr_t attr;
    if (pthread_getattr_np(pthread_self(), &attr) == 0) {
        void *addr;
        size_t sz;
        if (pthread_attr_getstack(&attr, &addr, &sz) == 0 && (char *)addr < here &&
            here <= (char *)addr + sz) {
            lowest = addr;
            size = sz;
        }
        pthread_attr_destroy(&attr);
    }
#endif
    if (!lowest) {
        /* Without the thread's own bounds: the process's stack limit,
         * counted from here (the parse starts near the top of the stack). */
        struct rlimit rl;
        size = 8u << 20;
        if (getrlimit(RLIMIT_STACK, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY && rl.rlim_cur < size)
            size = (size_t)rl.rlim_cur;
        lowest = here - size;
    }
    size_t reserve = stack_reserve(size);
    size_t left = (size_t)(here - lowest);
    p->stack_floor = left > reserve ? lowest + reserve : here;
}

void tok_limits_stack_exhausted(Parser *p, SourcePos pos)
{
    tok_fail(p, pos, "nested too deeply (the parser's stack is used up)");
}

/* ---- memory ------------------------------------------------------------- */

size_t parse_default_max_memory(void)
{
    return memory_budget_default();
}

void tok_limits_init_memory(Parser *p)
{
    p->budget.limit = p->opts->max_memory ? p->opts->max_memory : parse_default_max_memory();
    arena_set_budget(p->arena, &p->budget);
    arena_set_budget(p->temp, &p->budget);
}

size_t tok_limits_memory_left(const Parser *p)
{
    return p->budget.used < p->budget.limit ? p->budget.limit - p->budget.used : 0;
}

void tok_limits_over_budget(Parser *p, SourcePos pos)
{
    p->budget.exceeded = 1;
    tok_fail_memory(p, pos);
}

void tok_fail_memory(Parser *p, SourcePos pos)
{
    if (!p->budget.exceeded)
        tok_fail(p, pos, "out of memory");
    char limit[32];
    memory_size_text(limit, sizeof limit, p->budget.limit);
    tok_fail(p, pos, "the scene needs more than %s of memory while it is parsed (--max-memory sets the budget)",
               limit);
}

/* ---- time and work --------------------------------------------------------- */

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

void tok_limits_init_work(Parser *p)
{
    const ParseOptions *o = p->opts;
    p->max_loop_iterations = o->max_loop_iterations > 0 ? o->max_loop_iterations : MAX_LOOP_ITERATIONS;
    p->max_macro_calls = o->max_macro_calls > 0 ? o->max_macro_calls : MAX_MACRO_CALLS;
    p->max_repeated_tokens = o->max_repeated_tokens > 0 ? o->max_repeated_tokens : MAX_REPEATED_TOKENS;
    p->deadline = o->max_parse_seconds > 0.0 ? now() + o->max_parse_seconds : 0.0;
}

/* What was running out of budget: the innermost loop running (in this
 * file, an includer, a macro's body or its caller), else the innermost
 * macro: with no loop, a recursion. */
static void what_runs(Parser *p, char *buf, size_t n)
{
    const Control *c = p->controls.data;
    for (int i = p->controls.n - 1; i >= 0; i--)
        if (c[i].kind == CTL_WHILE || c[i].kind == CTL_FOR) {
            snprintf(buf, n, "is the %s at %s:%d endless?", c[i].kind == CTL_WHILE ? "#while" : "#for", c[i].pos.file,
                     c[i].pos.line);
            return;
        }
    for (int d = p->depth - 1; d >= 0; d--)
        if (p->files[d].macro) {
            snprintf(buf, n, "is the recursion of macro '%s' endless?", p->files[d].macro->name);
            return;
        }
    snprintf(buf, n, "is a loop or a recursion endless?");
}

void tok_limits_work_exhausted(Parser *p, SourcePos pos, const char *what)
{
    char runs[600];
    what_runs(p, runs, sizeof runs);
    if (strcmp(what, "tokens") == 0)
        tok_fail(p, pos, "more than %ld tokens read again by loops and macro calls (--max-repeated-tokens): %s",
                   p->max_repeated_tokens, runs);
    tok_fail(p, pos, "the parse ran for more than %g s (--max-parse-seconds): %s", p->opts->max_parse_seconds, runs);
}

void tok_limits_check_time(Parser *p, SourcePos pos)
{
    if (now() > p->deadline)
        tok_limits_work_exhausted(p, pos, "seconds");
}

void tok_limits_count_iteration(Parser *p, SourcePos loop)
{
    if (++p->loop_iterations > p->max_loop_iterations)
        tok_fail(p, loop, "more than %ld loop iterations (--max-loop-iterations): is this loop endless?",
                   p->max_loop_iterations);
}

void tok_limits_count_call(Parser *p, SourcePos call, const char *macro)
{
    if (++p->macro_calls > p->max_macro_calls)
        tok_fail(p, call, "more than %ld macro calls (--max-macro-calls): is the recursion of macro '%s' endless?",
                   p->max_macro_calls, macro);
}

/* ---- nesting ------------------------------------------------------------ */

int tok_nesting_enter(Parser *p, const Token *t)
{
    if (++p->nesting > MAX_NESTING)
        tok_fail(p, t->pos, "nested too deeply (more than %d levels)", MAX_NESTING);
    return p->nesting;
}

void tok_nesting_leave(Parser *p)
{
    p->nesting--;
}
