/* The shared arena (src/base/shared_arena.h) taken from by several threads
 * at once: every allocation aligned to 16, none overlapping another, each
 * keeping what its thread wrote, requests past a quarter chunk included. */
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "shared_arena.h"
#include "tap.h"

#define THREADS 4
#define PER_THREAD 20000

typedef struct {
    SharedArena *arena;
    int id;
    unsigned char *block[PER_THREAD];
    size_t size[PER_THREAD];
    int failed;
} Job;

static void *take(void *arg)
{
    Job *j = arg;
    unsigned seed = 12345u + (unsigned)j->id;
    for (int i = 0; i < PER_THREAD; i++) {
        seed = seed * 1103515245u + 12345u;
        /* mostly cells' sizes, now and then one past a quarter chunk */
        size_t size = (i % 997 == 0) ? (size_t)300000 + (seed % 1000) : (size_t)1 + (seed >> 8) % 3000;
        unsigned char *p = shared_arena_alloc(j->arena, size);
        j->block[i] = p;
        j->size[i] = size;
        if (!p) {
            j->failed++;
            continue;
        }
        memset(p, (j->id * 31 + i) & 0xff, size);
    }
    return NULL;
}

typedef struct {
    uintptr_t lo, hi;
} Span;

static int by_lo(const void *a, const void *b)
{
    const Span *x = a, *y = b;
    return x->lo < y->lo ? -1 : x->lo > y->lo;
}

int main(void)
{
    SharedArena arena;
    tap_ok(shared_arena_init(&arena, (size_t)1 << 20) == 0, "an arena of 1 MiB chunks");
    static Job jobs[THREADS];
    pthread_t tid[THREADS];
    for (int t = 0; t < THREADS; t++) {
        jobs[t].arena = &arena;
        jobs[t].id = t;
        pthread_create(&tid[t], NULL, take, &jobs[t]);
    }
    for (int t = 0; t < THREADS; t++)
        pthread_join(tid[t], NULL);
    long failed = 0, misaligned = 0, changed = 0;
    static Span spans[THREADS * PER_THREAD];
    int n = 0;
    for (int t = 0; t < THREADS; t++) {
        failed += jobs[t].failed;
        for (int i = 0; i < PER_THREAD; i++) {
            unsigned char *p = jobs[t].block[i];
            if (!p)
                continue;
            misaligned += ((uintptr_t)p % 16) != 0;
            for (size_t k = 0; k < jobs[t].size[i]; k++)
                if (p[k] != ((t * 31 + i) & 0xff)) {
                    changed++;
                    break;
                }
            spans[n++] = (Span){ (uintptr_t)p, (uintptr_t)p + jobs[t].size[i] };
        }
    }
    qsort(spans, (size_t)n, sizeof *spans, by_lo);
    long overlaps = 0;
    for (int i = 1; i < n; i++)
        overlaps += spans[i].lo < spans[i - 1].hi;
    tap_ok(failed == 0, "every allocation made (%ld failed)", failed);
    tap_ok(misaligned == 0, "every allocation aligned to 16 (%ld not)", misaligned);
    tap_ok(overlaps == 0 && n == THREADS * PER_THREAD, "no two of %d allocations overlap (%ld do)", n, overlaps);
    tap_ok(changed == 0, "each keeps what its thread wrote (%ld changed)", changed);
    size_t reserved = atomic_load(&arena.reserved);
    tap_ok(reserved >= (size_t)n, "the chunks taken from the system are counted (%zu bytes)", reserved);
    shared_arena_free(&arena);
    return tap_done();
}
