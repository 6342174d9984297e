/* Arrays of megabytes on transparent huge pages.
 *
 * Linux backs fresh memory page by page: the first write to each 4 KiB page
 * is a page fault. On a virtual machine a fault costs microseconds (here:
 * 104,000 faults were 0.7 s of a 2.2 s render of 10^6 triangles, most of them
 * in the world's polygons, the parser's mesh lists and the hierarchy's
 * arrays). Where the system hands out 2 MiB pages only to memory that asks
 * for them (transparent_hugepage "madvise", Debian's default), an array that
 * asks faults up to 512 times less often. The advice changes no byte the
 * program computes, only how the kernel backs it; where the system has no
 * such pages (or no madvise), these are plain malloc and realloc.
 *
 * Only arrays of at least BIG_MEMORY_MIN bytes ask: below it no whole 2 MiB
 * page fits reliably, and a huge page a small array only half uses would
 * cost memory. Free them with free(). */
#ifndef HST_BIG_MEMORY_H
#define HST_BIG_MEMORY_H

#include <stddef.h>

#define BIG_MEMORY_MIN ((size_t)4 << 20)

/* Asks for huge pages for the whole 4 KiB pages inside [p, p + bytes) when
 * bytes >= BIG_MEMORY_MIN; call it before the memory is first written. */
void big_memory_advise(void *p, size_t bytes);

/* malloc, calloc and realloc, then big_memory_advise on the result (a big
 * calloc comes from fresh pages that nothing has written yet). */
void *big_malloc(size_t bytes);
void *big_calloc(size_t count, size_t size);
void *big_realloc(void *p, size_t bytes);

#endif
