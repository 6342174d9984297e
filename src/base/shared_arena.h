/* A bump allocator several threads take from at once: memory in big
 * chunks, handed out by an atomic offset into the current one (a new chunk
 * under a lock when it runs out), all of it freed in one call. For data
 * built concurrently and kept to the end, like the light buffer's cells:
 * one allocation costs an atomic add instead of malloc's bookkeeping, and
 * the chunks (at least BIG_MEMORY_MIN) ask for transparent huge pages
 * (big_memory.h), so that filling them costs a page fault per 2 MiB rather
 * than per 4 KiB (on this project's virtual machines some 1.7 us each: a
 * quarter of the light buffer's build time on stars before). Nothing is
 * given back before the arena goes. */
#ifndef HST_SHARED_ARENA_H
#define HST_SHARED_ARENA_H

#include <pthread.h>
#include <stdatomic.h>
#include <stddef.h>

typedef struct SharedChunk SharedChunk;

typedef struct {
    _Atomic(SharedChunk *) current; /* the chunk allocations come from, or NULL */
    SharedChunk *all;               /* every chunk, for freeing (under lock) */
    pthread_mutex_t lock;
    size_t chunk_bytes;
    atomic_size_t reserved;         /* bytes of the chunks taken from the system */
} SharedArena;

/* An empty arena whose chunks hold chunk_bytes (more for a bigger request).
 * Returns 0, or -1 when the lock cannot be made. */
int shared_arena_init(SharedArena *a, size_t chunk_bytes);
/* `bytes` aligned to 16, or NULL when out of memory. Safe from any thread. */
void *shared_arena_alloc(SharedArena *a, size_t bytes);
void shared_arena_free(SharedArena *a);

#endif
