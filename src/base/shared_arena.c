/* A bump allocator several threads take from at once (shared_arena.h). */
#include "shared_arena.h"

#include <stdint.h>
#include <stdlib.h>

#include "big_memory.h"

#define ALIGN 16

struct SharedChunk {
    SharedChunk *next;
    size_t size;          /* bytes of data */
    atomic_size_t used;   /* bytes handed out, or asked for past the end */
    _Alignas(ALIGN) char data[];
};

int shared_arena_init(SharedArena *a, size_t chunk_bytes)
{
    atomic_init(&a->current, NULL);
    a->all = NULL;
    a->chunk_bytes = chunk_bytes;
    atomic_init(&a->reserved, 0);
    return pthread_mutex_init(&a->lock, NULL) == 0 ? 0 : -1;
}

/* A chunk of `size` bytes of data, listed in a (the lock held). */
static SharedChunk *chunk_new(SharedArena *a, size_t size)
{
    size_t total = sizeof(SharedChunk) + size;
    SharedChunk *c = aligned_alloc(ALIGN, (total + ALIGN - 1) / ALIGN * ALIGN);
    if (!c)
        return NULL;
    big_memory_advise(c, total);
    c->size = size;
    atomic_init(&c->used, 0);
    c->next = a->all;
    a->all = c;
    atomic_fetch_add(&a->reserved, total);
    return c;
}

void *shared_arena_alloc(SharedArena *a, size_t bytes)
{
    size_t need = (bytes + ALIGN - 1) / ALIGN * ALIGN;
    if (need < bytes)
        return NULL; /* overflow */
    /* A request of more than a quarter chunk gets a chunk of its own (not
     * made current: the current one keeps its room). */
    if (need > a->chunk_bytes / 4) {
        pthread_mutex_lock(&a->lock);
        SharedChunk *own = chunk_new(a, need);
        pthread_mutex_unlock(&a->lock);
        if (!own)
            return NULL;
        atomic_store(&own->used, need);
        return own->data;
    }
    for (;;) {
        SharedChunk *c = atomic_load_explicit(&a->current, memory_order_acquire);
        if (c) {
            size_t at = atomic_fetch_add_explicit(&c->used, need, memory_order_relaxed);
            if (at <= c->size && need <= c->size - at)
                return c->data + at;
        }
        /* out of room (or none yet): one thread makes the next chunk, the
         * others find it current when they get the lock */
        pthread_mutex_lock(&a->lock);
        int failed = 0;
        if (atomic_load_explicit(&a->current, memory_order_relaxed) == c) {
            SharedChunk *next = chunk_new(a, a->chunk_bytes);
            if (next)
                atomic_store_explicit(&a->current, next, memory_order_release);
            else
                failed = 1;
        }
        pthread_mutex_unlock(&a->lock);
        if (failed)
            return NULL;
    }
}

void shared_arena_free(SharedArena *a)
{
    for (SharedChunk *c = a->all, *next; c; c = next) {
        next = c->next;
        free(c);
    }
    a->all = NULL;
    atomic_store(&a->current, NULL);
    pthread_mutex_destroy(&a->lock);
}
