/* A bump allocator (arena.h). */
#include "arena.h"
#include "big_memory.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef struct Block {
    struct Block *next;
    size_t used, size;
    max_align_t data[];
} Block;

struct Arena {
    Block *head;
    ArenaBudget *budget;
    size_t taken; /* bytes of all its blocks, counted in the budget */
};

void arena_set_budget(Arena *a, ArenaBudget *budget)
{
    if (a->budget)
        a->budget->used -= a->taken;
    a->budget = budget;
    if (budget)
        budget->used += a->taken;
}

Arena *arena_new(void)
{
    return calloc(1, sizeof(Arena));
}

void *arena_alloc(Arena *a, size_t size)
{
    void *p = arena_alloc_uninit(a, size);
    if (p)
        memset(p, 0, size);
    return p;
}

void *arena_alloc_uninit(Arena *a, size_t size)
{
    const size_t align = sizeof(max_align_t);
    if (size > SIZE_MAX - align)
        return NULL;
    size = (size + align - 1) / align * align;
    if (size == 0)
        size = align;
    Block *b = a->head;
    if (!b || b->size - b->used < size) {
        size_t cap = size > 65536 ? size : 65536;
        size_t whole = sizeof(Block) + cap;
        if (whole < cap)
            return NULL; /* a size near SIZE_MAX */
        if (a->budget && (whole > a->budget->limit || a->budget->used > a->budget->limit - whole)) {
            a->budget->exceeded = 1;
            return NULL;
        }
        b = big_malloc(whole);
        if (!b)
            return NULL;
        a->taken += whole;
        if (a->budget)
            a->budget->used += whole;
        b->size = cap;
        b->used = 0;
        b->next = a->head;
        a->head = b;
    }
    void *p = (char *)b->data + b->used;
    b->used += size;
    return p;
}

int arena_release(Arena *a, void *p)
{
    /* A block made for one allocation bigger than the usual block holds it
     * alone (it is made full): only such a block can go. */
    for (Block **at = a ? &a->head : NULL; at && *at; at = &(*at)->next) {
        Block *b = *at;
        if ((void *)b->data != p)
            continue;
        if (b->size <= 65536 || b->used != b->size)
            return 0;
        *at = b->next;
        size_t whole = sizeof(Block) + b->size;
        a->taken -= whole;
        if (a->budget)
            a->budget->used -= whole;
        free(b);
        return 1;
    }
    return 0;
}

char *arena_strdup(Arena *a, const char *s)
{
    size_t n = strlen(s) + 1;
    char *p = arena_alloc(a, n);
    if (p)
        memcpy(p, s, n);
    return p;
}

void arena_free(Arena *a)
{
    if (!a)
        return;
    arena_set_budget(a, NULL);
    for (Block *b = a->head, *next; b; b = next) {
        next = b->next;
        free(b);
    }
    free(a);
}
