/* What a scene may use while it is parsed: nesting and the C stack.
 *
 * The parser is recursive descent, and its recursion runs through next():
 * a directive can stand anywhere, so nearly every production can reach
 * every other through it (one strongly connected call graph of about a
 * hundred functions). Rather than a counter in each production, which a new
 * production could forget, the one guard sits where every level of every
 * recursion passes: the lexer, which checks at each token how much of the
 * calling thread's stack is left (limits_check_stack, inlined in
 * lex_token). A scene nested too deeply for the stack gets
 * "nested too deeply" at the token where the stack ran short.
 *
 * Recursions that read no tokens are bounded where they are built: a union
 * records how deep it nests (SceneObject.depth) and an array value how deep
 * its element arrays go, both capped at MAX_NESTING; expressions and
 * objects keep their 200-level count (nesting_enter), which makes those
 * errors land at the same place whatever the build. */
#define _GNU_SOURCE /* pthread_getattr_np: the real bounds of this thread's stack */
#include "config.h"

#include <pthread.h>
#include <stdint.h>
#include <sys/resource.h>

#include "parser_internal.h"

/* Stack kept back below the deepest token: what a production may use
 * between two tokens (number conversion, messages, the error path itself,
 * all of it larger under AddressSanitizer) must fit in it. */
static size_t stack_reserve(size_t stack_size)
{
    size_t r = stack_size / 8;
    return r < 128 * 1024 ? 128 * 1024 : r;
}

void limits_init_stack(Parser *p)
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

void limits_stack_exhausted(Parser *p, SourcePos pos)
{
    parse_fail(p, pos, "nested too deeply (the parser's stack is used up)");
}

int nesting_enter(Parser *p, const Token *t)
{
    if (++p->nesting > MAX_NESTING)
        parse_fail(p, t->pos, "nested too deeply (more than %d levels)", MAX_NESTING);
    return p->nesting;
}

void nesting_leave(Parser *p)
{
    p->nesting--;
}
