/* The parse's memory: the scene's arena (what outlives the parse), the
 * temporary arena (everything else), and growable arrays in them, each
 * checked against the parse's memory budget. */
#include <stdlib.h>
#include <string.h>

#include "tokens.h"

/* ---- memory ------------------------------------------------------------ */

static _Noreturn void out_of_memory(Parser *p)
{
    tok_fail_memory(p, p->last_pos);
}

void *tok_scene_alloc(Parser *p, size_t size)
{
    void *m = arena_alloc(p->arena, size);
    if (!m)
        out_of_memory(p);
    return m;
}

void *tok_temp_alloc(Parser *p, size_t size)
{
    void *m = arena_alloc(p->temp, size);
    if (!m)
        out_of_memory(p);
    return m;
}

char *tok_temp_strndup(Parser *p, const char *s, size_t n)
{
    char *r = tok_temp_alloc(p, n + 1);
    memcpy(r, s, n);
    r[n] = '\0';
    return r;
}

void tok_tvec_init(TempVec *v, size_t elem)
{
    memset(v, 0, sizeof *v);
    v->elem = elem;
}

/* The list's elements moved to room for cap of them in arena a. */
static void move_to(Parser *p, TempVec *v, int cap, Arena *a)
{
    void *d = arena_alloc_uninit(a, v->elem * (size_t)cap); /* each slot is zeroed when pushed */
    if (!d)
        out_of_memory(p);
    if (v->n)
        memcpy(d, v->data, v->elem * (size_t)v->n);
    v->data = d;
    v->cap = cap;
    v->in_scene = a == p->arena;
}

void *tok_tvec_push(Parser *p, TempVec *v)
{
    if (v->n == v->cap) {
        if (v->cap > (1 << 28))
            out_of_memory(p);
        move_to(p, v, v->cap ? v->cap * 2 : 16, p->temp);
    }
    void *slot = (char *)v->data + v->elem * (size_t)v->n++;
    memset(slot, 0, v->elem);
    return slot;
}

static void reserve_in(Parser *p, TempVec *v, int n, Arena *a)
{
    if (n <= v->cap)
        return;
    if (n > (1 << 28))
        n = 1 << 28; /* tok_tvec_push's own limit */
    move_to(p, v, n, a);
}

void tok_tvec_reserve(Parser *p, TempVec *v, int n) { reserve_in(p, v, n, p->temp); }

void tok_tvec_reserve_kept(Parser *p, TempVec *v, int n) { reserve_in(p, v, n, p->arena); }

void *tok_tvec_kept(Parser *p, const TempVec *v)
{
    if (v->in_scene && v->n > 0)
        return v->data;
    return tok_tvec_keep(p, v);
}

void *tok_tvec_keep(Parser *p, const TempVec *v)
{
    void *kept = tok_scene_alloc(p, v->elem * (size_t)(v->n ? v->n : 1));
    if (v->n)
        memcpy(kept, v->data, v->elem * (size_t)v->n);
    return kept;
}

