/* Identifiers and their values, with POV-Ray's scoping: each include file
 * and each macro call opens a level for its #local identifiers (and a macro's
 * parameters); a name resolves to its innermost definition. Each level keeps
 * a list of its symbols so that closing it costs what it holds, not the
 * table's size (macros open and close levels very often). */
#include <string.h>

#include "tokens.h"

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

void tok_symbols_init(Parser *p)
{
    memset(&p->symbols, 0, sizeof p->symbols);
}

const char *tok_intern_name(Parser *p, const char *name, int len)
{
    if ((p->nnames + 1) * 2 > p->cap_names) {
        size_t cap = p->cap_names ? p->cap_names * 2 : 1024;
        struct Interned *t = tok_temp_alloc(p, sizeof *t * cap);
        for (size_t i = 0; i < p->cap_names; i++) {
            const char *k = p->names[i].key;
            if (!k)
                continue;
            size_t j = hash_name(k, (int)strlen(k)) * 2654435761u & (cap - 1);
            while (t[j].key)
                j = (j + 1) & (cap - 1);
            t[j] = p->names[i];
        }
        p->names = t;
        p->cap_names = cap;
    }
    size_t j = hash_name(name, len) * 2654435761u & (p->cap_names - 1);
    for (; p->names[j].key; j = (j + 1) & (p->cap_names - 1))
        if (strncmp(p->names[j].key, name, (size_t)len) == 0 && p->names[j].key[len] == '\0')
            return p->names[j].key;
    char *copy = tok_temp_strndup(p, name, (size_t)len);
    p->names[j].key = copy;
    p->names[j].value = copy;
    p->nnames++;
    return copy;
}

/* The innermost symbol of that name, aliases not followed. */
static Symbol *find_own(Parser *p, const char *name, int len)
{
    Symbol *best = NULL;
    for (Symbol *s = p->symbols.buckets[hash_name(name, len)]; s; s = s->next)
        if ((!best || s->level > best->level) && same_name(s, name, len))
            best = s;
    return best;
}

/* A by-reference parameter leads to the caller's symbol, if that still
 * exists (the macro may have #undef'd it). */
static Symbol *follow(Symbol *s)
{
    for (int hops = 0; s && s->alias && hops < MAX_SCOPE_LEVELS; hops++)
        s = s->alias->serial == s->alias_serial ? s->alias : NULL;
    return s;
}

Symbol *tok_symbol_find(Parser *p, const char *name, int len)
{
    return follow(find_own(p, name, len));
}

Symbol *tok_symbol_of(Parser *p, const Token *t)
{
    if (!t->elem)
        return tok_symbol_find(p, t->text, t->len);
    if (t->elem->value.kind == VAL_NONE)
        tok_fail(p, t->pos, "array element '%.*s' is used before it is given a value", t->len, t->text);
    return t->elem;
}

static Symbol *new_symbol(Parser *p, const char *name, int len, int level)
{
    Symbol *s = p->symbols.free_list;
    unsigned serial = 0;
    if (s) {
        p->symbols.free_list = s->next;
        serial = s->serial;
        memset(s, 0, sizeof *s);
        s->serial = serial;
    } else {
        s = tok_temp_alloc(p, sizeof *s);
    }
    s->name = (char *)tok_intern_name(p, name, len);
    s->level = level;
    unsigned h = hash_name(name, len);
    s->next = p->symbols.buckets[h];
    p->symbols.buckets[h] = s;
    s->scope_next = p->symbols.scopes[level];
    p->symbols.scopes[level] = s;
    return s;
}

void tok_symbol_set(Parser *p, const char *name, int len, int local, const Value *v)
{
    Symbol *s = find_own(p, name, len);
    if (s && (!local || s->level == p->symbols.level)) {
        Symbol *target = follow(s);
        if (target) {
            if (!(v->kind == VAL_ARRAY && v->array == target->value.array))
                tok_value_give_up(p, &target->value);
            target->value = *v;
            return;
        }
    }
    new_symbol(p, name, len, local ? p->symbols.level : 0)->value = *v;
}

Symbol *tok_symbol_add_local(Parser *p, const char *name, int len, const Value *v)
{
    Symbol *s = new_symbol(p, name, len, p->symbols.level);
    if (v)
        s->value = *v;
    return s;
}

void tok_symbol_define_global(Parser *p, const char *name, int len, const Value *v)
{
    for (Symbol *s = p->symbols.buckets[hash_name(name, len)]; s; s = s->next)
        if (s->level == 0 && same_name(s, name, len)) {
            if (!(v->kind == VAL_ARRAY && v->array == s->value.array))
                tok_value_give_up(p, &s->value);
            s->value = *v;
            s->alias = NULL;
            return;
        }
    new_symbol(p, name, len, 0)->value = *v;
}

static void unlink_from_bucket(Parser *p, Symbol *target)
{
    Symbol **link = &p->symbols.buckets[hash_name(target->name, (int)strlen(target->name))];
    while (*link && *link != target)
        link = &(*link)->next;
    if (*link)
        *link = target->next;
}

static void release(Parser *p, Symbol *s)
{
    tok_value_give_up(p, &s->value);
    s->serial++;
    s->next = p->symbols.free_list;
    p->symbols.free_list = s;
}

void tok_symbol_undef(Parser *p, const char *name, int len)
{
    Symbol *target = find_own(p, name, len);
    if (!target)
        return;
    unlink_from_bucket(p, target);
    Symbol **link = &p->symbols.scopes[target->level];
    while (*link && *link != target)
        link = &(*link)->scope_next;
    if (*link)
        *link = target->scope_next;
    release(p, target);
}

void tok_push_scope(Parser *p)
{
    if (p->symbols.level + 1 >= MAX_SCOPE_LEVELS)
        tok_fail(p, p->last_pos, "too many nested include files and macro calls");
    p->symbols.level++;
    p->symbols.scopes[p->symbols.level] = NULL;
}

void tok_pop_scope(Parser *p)
{
    int level = p->symbols.level;
    if (level == 0)
        return;
    Symbol *s = p->symbols.scopes[level];
    while (s) {
        Symbol *next_in_scope = s->scope_next;
        unlink_from_bucket(p, s);
        release(p, s);
        s = next_in_scope;
    }
    p->symbols.scopes[level] = NULL;
    p->symbols.level--;
}

/* What a value is, as messages name it. */
const char *tok_value_kind_name(ValueKind k)
{
    switch (k) {
    case VAL_NUMERIC: return "a number";
    case VAL_STRING: return "a string";
    case VAL_OBJECT: return "an object";
    case VAL_LIGHT: return "a light_source";
    case VAL_TEXTURE: return "a texture";
    case VAL_PIGMENT: return "a pigment";
    case VAL_FINISH: return "a finish";
    case VAL_INTERIOR: return "an interior";
    case VAL_MATERIAL: return "a material";
    case VAL_CAMERA: return "a camera";
    case VAL_SKY_SPHERE: return "a sky_sphere";
    case VAL_TRANSFORM: return "a transform";
    case VAL_NORMAL: return "a normal";
    case VAL_COLOUR_MAP: return "a color_map";
    case VAL_PIGMENT_MAP: return "a pigment_map";
    case VAL_TEXTURE_MAP: return "a texture_map";
    case VAL_NORMAL_MAP: return "a normal_map";
    case VAL_SLOPE_MAP: return "a slope_map";
    case VAL_MACRO: return "a macro";
    case VAL_ARRAY: return "an array";
    case VAL_FILE: return "a file identifier";
    default: return "something else";
    }
}
