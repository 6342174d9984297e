/* Arrays of megabytes on transparent huge pages (see big_memory.h). */
#define _DEFAULT_SOURCE /* madvise and MADV_HUGEPAGE are not POSIX */
#include "big_memory.h"

#include <stdint.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <unistd.h>

void big_memory_advise(void *p, size_t bytes)
{
#if defined(MADV_HUGEPAGE)
    if (!p || bytes < BIG_MEMORY_MIN)
        return;
    long page = sysconf(_SC_PAGESIZE);
    if (page <= 0)
        return;
    uintptr_t lo = ((uintptr_t)p + (uintptr_t)page - 1) / (uintptr_t)page * (uintptr_t)page;
    uintptr_t hi = ((uintptr_t)p + bytes) / (uintptr_t)page * (uintptr_t)page;
    /* Only advice: a kernel without transparent huge pages says EINVAL, and
     * the memory is as good as before. */
    if (hi > lo)
        (void)madvise((void *)lo, hi - lo, MADV_HUGEPAGE);
#else
    (void)p;
    (void)bytes;
#endif
}

void *big_malloc(size_t bytes)
{
    void *p = malloc(bytes);
    big_memory_advise(p, bytes);
    return p;
}

void *big_calloc(size_t count, size_t size)
{
    void *p = calloc(count, size);
    if (p)
        big_memory_advise(p, count * size); /* calloc checked the product */
    return p;
}

void *big_realloc(void *p, size_t bytes)
{
    void *q = realloc(p, bytes);
    big_memory_advise(q, bytes);
    return q;
}
