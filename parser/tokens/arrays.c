/* POV-Ray 3.7 arrays: `array[N][M]...` with an optional initialiser
 * `{ {a, b}, {c, d} }`, elements read as `A[i][j]` (tok_next() reads the
 * indices, so an element can stand wherever an identifier can) and set by
 * `#declare A[i] = ...`; dimensions(A) and dimension_size(A, D). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "tokens.h"

/* Elements at most: a bound that keeps a typo such as array[1e9] from
 * exhausting memory (POV-Ray would try). */
#define MAX_ARRAY_ELEMENTS 100000000L

static void parse_initialiser(Parser *p, ArrayValue *a, int dim, long base)
{
    long stride = 1;
    for (int d = dim + 1; d < a->ndims; d++)
        stride *= a->size[d];
    tok_begin_block(p, "the array size or ','");
    for (int i = 0; i < a->size[dim]; i++) {
        if (i > 0) {
            Token *t = tok_next(p);
            if (tok_is_punct(t, '}'))
                tok_fail(p, t->pos, "this array initialiser has %d element%s where %d are needed", i,
                           i == 1 ? "" : "s", a->size[dim]);
            if (!tok_is_punct(t, ','))
                tok_unget(p); /* POV-Ray accepts a missing ',' */
        }
        if (dim + 1 < a->ndims) {
            parse_initialiser(p, a, dim + 1, base + i * stride);
        } else {
            Token *t = tok_peek(p);
            if (tok_is_punct(t, '}'))
                tok_fail(p, t->pos, "this array initialiser has %d element%s where %d are needed", i,
                           i == 1 ? "" : "s", a->size[dim]);
            a->elems[base + i].value = p->hooks->value(p);
        }
    }
    Token *t = tok_next(p);
    if (tok_is_punct(t, ','))
        t = tok_next(p); /* a trailing ',' */
    if (!tok_is_punct(t, '}')) {
        char what[96];
        snprintf(what, sizeof what, "'}' after the %d elements of the array initialiser", a->size[dim]);
        tok_fail_expected(p, t, what);
    }
}

static int size_class(long n)
{
    int k = 0;
    while (k + 1 < ARRAY_SIZE_CLASSES && (n >> (k + 1)) > 0)
        k++;
    return k;
}

ArrayValue *tok_array_new(Parser *p, long count)
{
    /* The first of a few in count's class that is big enough, or any of
     * the next class (all are). Loops and macro calls make arrays of the
     * same sizes again and again: the first one usually fits. */
    int k = size_class(count);
    ArrayValue **link = &p->free_arrays[k];
    for (int tries = 0; *link && tries < 8; tries++, link = &(*link)->next_free)
        if ((*link)->capacity >= count)
            break;
    if ((!*link || (*link)->capacity < count) && k + 1 < ARRAY_SIZE_CLASSES && p->free_arrays[k + 1])
        link = &p->free_arrays[k + 1];
    ArrayValue *a = *link;
    if (a && a->capacity >= count) {
        *link = a->next_free;
        for (long i = 0; i < count; i++) {
            unsigned serial = a->elems[i].serial;
            memset(&a->elems[i], 0, sizeof a->elems[i]);
            a->elems[i].serial = serial;
        }
        long capacity = a->capacity;
        Symbol *elems = a->elems;
        memset(a, 0, sizeof *a);
        a->capacity = capacity;
        a->elems = elems;
        a->count = count;
        return a;
    }
    a = tok_temp_alloc(p, sizeof *a);
    a->elems = tok_temp_alloc(p, sizeof *a->elems * (size_t)count);
    a->capacity = count;
    a->count = count;
    return a;
}

void tok_value_give_up(Parser *p, Value *v)
{
    if (v->kind != VAL_ARRAY || !v->array)
        return;
    /* Nested arrays are given up one after the other through a list of
     * our own, not by recursion: `#declare A[0] = A` in a loop nests them
     * as deep as the loop runs. */
    ArrayValue *todo = v->array;
    todo->next_free = NULL;
    v->array = NULL;
    v->kind = VAL_NONE;
    while (todo) {
        ArrayValue *a = todo;
        todo = a->next_free;
        for (long i = 0; i < a->count; i++) {
            Symbol *e = &a->elems[i];
            e->serial++;
            if (e->value.kind == VAL_ARRAY && e->value.array) {
                e->value.array->next_free = todo;
                todo = e->value.array;
            }
            e->value.kind = VAL_NONE;
            e->value.array = NULL;
        }
        int k = size_class(a->capacity);
        a->next_free = p->free_arrays[k];
        p->free_arrays[k] = a;
    }
}

Symbol *tok_element_of(const Token *t)
{
    return t->elem->serial == t->elem_serial ? t->elem : NULL;
}

Value tok_array_value(Parser *p, const Token *kw)
{
    ArrayValue shape, *a = &shape; /* the sizes first, then the elements */
    memset(&shape, 0, sizeof shape);
    a->declared_at = kw->pos;
    a->count = 1;
    for (;;) {
        /* After the first size, look at the raw text: `#local A = array[N]`
         * with no ';' may be followed by a directive that uses A, which
         * must not be carried out before A is stored. */
        if (a->ndims > 0 && !tok_next_is_punct(p, '['))
            break;
        Token *t = tok_next(p);
        if (!tok_is_punct(t, '['))
            tok_fail_expected(p, t, "'[' and the array size after 'array'");
        if (a->ndims == MAX_ARRAY_DIMS)
            tok_fail(p, t->pos, "arrays have at most %d dimensions", MAX_ARRAY_DIMS);
        Token at = *tok_peek(p);
        double n = p->hooks->number_full(p);
        tok_expect_punct(p, ']', "the array size");
        int size;
        if (!int_from_double(n + 1e-10, 1, (int)MAX_ARRAY_ELEMENTS, &size))
            tok_fail(p, at.pos, "invalid array size %g (1 to %ld)", n, MAX_ARRAY_ELEMENTS);
        a->size[a->ndims++] = size;
        a->count *= size;
        if (a->count > MAX_ARRAY_ELEMENTS)
            tok_fail(p, at.pos, "array of more than %ld elements", MAX_ARRAY_ELEMENTS);
        if ((size_t)a->count > tok_limits_memory_left(p) / sizeof *a->elems) /* named at the size that crosses it */
            tok_limits_over_budget(p, at.pos);
    }
    a = tok_array_new(p, shape.count);
    a->ndims = shape.ndims;
    memcpy(a->size, shape.size, sizeof a->size);
    a->declared_at = shape.declared_at;
    if (tok_next_is_punct(p, '{'))
        parse_initialiser(p, a, 0, 0);
    Value v;
    memset(&v, 0, sizeof v);
    v.kind = VAL_ARRAY;
    v.array = a;
    return v;
}

void tok_array_element(Parser *p, Symbol *s)
{
    Token t = p->tok;
    const ArrayValue *a = s->value.array;
    int depth = p->depth;
    const char *buf = p->files[depth - 1].buf;
    int saved = p->no_macro_calls;
    p->no_macro_calls = 0; /* the indices are ordinary expressions */
    long index = 0;
    for (int d = 0; d < a->ndims; d++) {
        Token *open = tok_next(p);
        if (!tok_is_punct(open, '[')) {
            char what[120];
            snprintf(what, sizeof what, "'[': '%.*s' has %d dimensions", t.len > 60 ? 60 : t.len, t.text, a->ndims);
            tok_fail_expected(p, open, what);
        }
        Token at = *tok_peek(p);
        double v = p->hooks->number_full(p);
        tok_expect_punct(p, ']', "the array index");
        int i;
        if (!int_from_double(v, 0, a->size[d] - 1, &i)) {
            if (a->ndims == 1)
                tok_fail(p, at.pos, "index %g is out of range for '%.*s' (array[%d]: 0 to %d)", v, t.len, t.text,
                           a->size[0], a->size[0] - 1);
            tok_fail(p, at.pos, "index %g is out of range for dimension %d of '%.*s' (0 to %d)", v, d + 1, t.len,
                       t.text, a->size[d] - 1);
        }
        index = index * a->size[d] + i;
    }
    p->no_macro_calls = saved;
    /* Let messages show `A[i][j]` when it was written on one stretch. */
    const SourceFile *f = &p->files[p->depth - 1];
    if (p->depth == depth && f->buf == buf && !p->ungot) {
        size_t start = (size_t)(t.text - buf);
        if (f->offset > start && f->offset - start <= 80 && memchr(t.text, '\n', f->offset - start) == NULL)
            t.len = (int)(f->offset - start);
    }
    t.elem = &a->elems[index];
    t.elem_serial = t.elem->serial;
    p->tok = t;
}

static const ArrayValue *array_argument(Parser *p, const char *function)
{
    Token t = *tok_next(p);
    if (t.type == TK_WORD && t.kw < 0 && !t.elem) {
        Symbol *s = tok_symbol_find(p, t.text, t.len);
        if (!s)
            tok_fail(p, t.pos, "undeclared identifier '%.*s'", t.len, t.text);
        if (s->value.kind == VAL_ARRAY)
            return s->value.array;
        tok_fail(p, t.pos, "'%s' needs an array, but '%.*s' is %s", function, t.len, t.text,
                   tok_value_kind_name(s->value.kind));
    }
    char what[64];
    snprintf(what, sizeof what, "an array identifier in '%s'", function);
    tok_fail_expected(p, &t, what);
}

double tok_array_function(Parser *p, const Token *t)
{
    const char *name = tok_keyword_name(t->kw);
    char after[64];
    snprintf(after, sizeof after, "'%s'", name);
    tok_expect_punct(p, '(', after);
    const ArrayValue *a = array_argument(p, name);
    double v;
    if (t->kw == KW_dimensions) {
        v = a->ndims;
    } else {
        tok_expect_punct(p, ',', "the array");
        int d;
        /* POV-Ray warns and answers 0 for a dimension the array lacks */
        v = int_from_double(p->hooks->number_full(p), 1, a->ndims, &d) ? a->size[d - 1] : 0.0;
    }
    tok_expect_punct(p, ')', "the arguments");
    return v;
}
