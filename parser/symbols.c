/* Identifiers and their values, with POV-Ray's scoping: each include file
 * opens a level for its #local identifiers; #declare writes the global level;
 * a name resolves to its innermost definition. */
#include <string.h>

#include "parser_internal.h"

static unsigned hash_name(const char *s, int len)
{
    unsigned h = 2166136261u;
    for (int i = 0; i < len; i++)
        h = (h ^ (unsigned char)s[i]) * 16777619u;
    return h % SYMBOL_BUCKETS;
}

static int same_name(const Symbol *s, const char *name, int len)
{
    return strncmp(s->name, name, (size_t)len) == 0 && s->name[len] == '\0';
}

void symbols_init(Parser *p)
{
    memset(&p->symbols, 0, sizeof p->symbols);
}

Symbol *symbol_find(Parser *p, const char *name, int len)
{
    Symbol *best = NULL;
    for (Symbol *s = p->symbols.buckets[hash_name(name, len)]; s; s = s->next)
        if (same_name(s, name, len) && (!best || s->level > best->level))
            best = s;
    return best;
}

void symbol_set(Parser *p, const char *name, int len, int local, const Value *v)
{
    int level = local ? p->symbols.level : 0;
    unsigned h = hash_name(name, len);
    for (Symbol *s = p->symbols.buckets[h]; s; s = s->next)
        if (s->level == level && same_name(s, name, len)) {
            s->value = *v;
            return;
        }
    Symbol *s = p->symbols.free_list;
    if (s)
        p->symbols.free_list = s->next;
    else
        s = tmp_alloc(p, sizeof *s);
    s->name = tmp_strndup(p, name, (size_t)len);
    s->level = level;
    s->value = *v;
    s->next = p->symbols.buckets[h];
    p->symbols.buckets[h] = s;
}

void symbol_undef(Parser *p, const char *name, int len)
{
    Symbol *target = symbol_find(p, name, len);
    if (!target)
        return;
    Symbol **link = &p->symbols.buckets[hash_name(name, len)];
    while (*link != target)
        link = &(*link)->next;
    *link = target->next;
    target->next = p->symbols.free_list;
    p->symbols.free_list = target;
}

void symbols_push_scope(Parser *p)
{
    p->symbols.level++;
}

void symbols_pop_scope(Parser *p)
{
    int level = p->symbols.level;
    for (int b = 0; b < SYMBOL_BUCKETS; b++) {
        Symbol **link = &p->symbols.buckets[b];
        while (*link) {
            Symbol *s = *link;
            if (s->level >= level) {
                *link = s->next;
                s->next = p->symbols.free_list;
                p->symbols.free_list = s;
            } else {
                link = &s->next;
            }
        }
    }
    if (level > 0)
        p->symbols.level--;
}
