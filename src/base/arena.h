/* A bump allocator: zeroed memory in blocks, all of it freed in one call.
 * The scene's many small pieces live in one (scene.h), which also keeps the
 * parser's error paths (it unwinds with longjmp) free of leaks. */
#ifndef HST_ARENA_H
#define HST_ARENA_H

#include <stddef.h>

typedef struct Arena Arena;

/* An empty arena, or NULL when out of memory. */
Arena *arena_new(void);
/* A bound on what arenas may take from the system, shared by the arenas
 * given it (the parser's two): once `used` would pass `limit`, an
 * allocation returns NULL and sets `exceeded`, before any memory is asked
 * for. A budget is the caller's, and one thread's: NULL detaches it. */
typedef struct {
    size_t used, limit;
    int exceeded;
} ArenaBudget;
void arena_set_budget(Arena *a, ArenaBudget *budget);
void *arena_alloc(Arena *a, size_t size);
/* As arena_alloc, without zeroing (for memory about to be overwritten). */
void *arena_alloc_uninit(Arena *a, size_t size);
char *arena_strdup(Arena *a, const char *s);
/* Gives p's memory back before the arena goes, when p is an allocation
 * bigger than the arena's blocks (which then has a block to itself);
 * returns 1, or 0 and keeps it otherwise. */
int arena_release(Arena *a, void *p);
void arena_free(Arena *a);

#endif
