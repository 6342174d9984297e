/* #macro: definition, invocation and return, by POV-Ray 3.7's rules.
 *
 * A definition records where its body starts in the defining file's buffer
 * and skips to its #end. A call (the macro's name, anywhere a token can be)
 * reads the arguments, opens a new symbol level holding the parameters, and
 * pushes a source frame that replays the body from the buffer; the body's
 * #end pops both, and reading goes on after the call. The body's tokens thus
 * stand where the call was: a macro can expand to an object, a value, or any
 * part of one.
 *
 * An argument that is just an identifier of the caller is passed by
 * reference: `#declare Param = ...` (or #local) in the body changes the
 * caller's identifier. Any other argument is evaluated and passed by value.
 * (POV-Ray 3.7 has no optional parameters.) */
#include <stdio.h>
#include <string.h>

#include "tokens.h"

static Token read_name(Parser *p, const char *what)
{
    Token t = *tok_next_name(p);
    if (t.type != TK_WORD || t.elem) {
        char buf[96];
        snprintf(buf, sizeof buf, "an identifier after %s", what);
        tok_fail_expected(p, &t, buf);
    }
    if (t.kw >= 0)
        tok_fail(p, t.pos, "'%s' is a reserved word and cannot be %s", tok_keyword_name(t.kw),
                   strcmp(what, "#macro") == 0 ? "a macro name" : "a macro parameter");
    return t;
}

void tok_macro_define(Parser *p, const Token *hash)
{
    Token name = read_name(p, "#macro");
    Macro *m = tok_temp_alloc(p, sizeof *m);
    m->name = tok_temp_strndup(p, name.text, (size_t)name.len);
    m->declared_at = name.pos;
    tok_expect_punct(p, '(', "the macro name");
    TempVec params;
    tok_tvec_init(&params, sizeof(char *));
    Token *t = tok_next_name(p);
    if (!tok_is_punct(t, ')')) {
        tok_unget(p);
        for (;;) {
            if (params.n > 0 && tok_is_punct(tok_peek(p), ')')) { /* a trailing ',', as shapes3.inc has */
                (void)tok_next(p);
                break;
            }
            Token param = read_name(p, "'(' or ','");
            for (int i = 0; i < params.n; i++)
                if (strlen(((char **)params.data)[i]) == (size_t)param.len &&
                    strncmp(((char **)params.data)[i], param.text, (size_t)param.len) == 0)
                    tok_fail(p, param.pos, "macro '%s' has two parameters named '%.*s'", m->name, param.len,
                               param.text);
            *(char **)tok_tvec_push(p, &params) = tok_temp_strndup(p, param.text, (size_t)param.len);
            t = tok_next_name(p);
            if (tok_is_punct(t, ')'))
                break;
            if (!tok_is_punct(t, ',')) {
                if (t->type != TK_WORD)
                    tok_fail_expected(p, t, "',' or ')' in the macro's parameter list");
                tok_unget(p); /* POV-Ray lets a ',' be missing (shapes3.inc does) */
            }
        }
    }
    m->nparams = params.n;
    m->params = params.data;
    /* The body starts right after ')': tok_next() has read nothing beyond it. */
    const SourceFile *f = &p->files[p->depth - 1];
    m->file = f->name;
    m->dir = f->dir;
    m->buf = f->buf;
    m->size = f->size;
    m->body_offset = f->offset;
    m->body_line = f->line;
    m->body_col = f->col;
    tok_macro_skip_body(p, hash->pos);
    Value v;
    memset(&v, 0, sizeof v);
    v.kind = VAL_MACRO;
    v.macro = m;
    v.declared_at = name.pos;
    /* Macros are always global in POV-Ray, wherever they are defined. */
    tok_symbol_define_global(p, name.text, name.len, &v);
}

/* The argument is a lone identifier of the caller: pass it by reference.
 * Looks at the raw text so that nothing is carried out early. */
static Symbol *reference_argument(Parser *p, const Macro *m, int index)
{
    if (p->ungot)
        return NULL;
    LexMark mark = tok_mark(p);
    Token a, b;
    tok_raw(p, &a);
    if (tok_is_punct(&a, ')') || tok_is_punct(&a, ','))
        tok_fail(p, a.pos, "macro '%s' takes %d parameter%s but %d %s given", m->name, m->nparams,
                   m->nparams == 1 ? "" : "s", index, index == 1 ? "was" : "were");
    int lone = a.type == TK_WORD && a.kw < 0;
    if (lone) {
        tok_raw(p, &b);
        lone = tok_is_punct(&b, ',') || tok_is_punct(&b, ')');
    }
    tok_seek(p, mark);
    if (!lone)
        return NULL;
    Symbol *s = tok_symbol_find(p, a.text, a.len);
    if (!s)
        tok_fail(p, a.pos, "undeclared identifier '%.*s' passed as parameter '%s' of macro '%s'", a.len, a.text,
                   m->params[index], m->name);
    if (s->value.kind == VAL_MACRO)
        return NULL; /* a call without arguments: let it fail as such */
    (void)tok_next_name(p);
    return s;
}

void tok_macro_invoke(Parser *p, const Token *call, const Macro *m)
{
    Token open = *tok_next(p);
    if (!tok_is_punct(&open, '(')) {
        char what[160];
        snprintf(what, sizeof what, "'(' after macro '%s' (declared at %s:%d)", m->name, m->declared_at.file,
                 m->declared_at.line);
        tok_fail_expected(p, &open, what);
    }
    /* The arguments go on a stack that calls inside them use above this
     * call's slots (indices: the stack may move as it grows), and that is
     * back at `base` once they are bound, so that calls in a loop reuse
     * the same memory. */
    int base = p->arg_values.n;
    for (int i = 0; i < m->nparams; i++) {
        (void)tok_tvec_push(p, &p->arg_values);
        (void)tok_tvec_push(p, &p->arg_refs);
    }
#define ARG(i) (((Value *)p->arg_values.data)[base + (i)])
#define REF(i) (((Symbol **)p->arg_refs.data)[base + (i)])
    /* All arguments are read before the macro's level opens, so that they
     * mean what they mean at the call (recursion depends on it). */
    for (int i = 0; i < m->nparams; i++) {
        if (i > 0) {
            Token *t = tok_next(p);
            if (tok_is_punct(t, ')'))
                tok_fail(p, t->pos, "macro '%s' takes %d parameter%s but %d %s given", m->name, m->nparams,
                           m->nparams == 1 ? "" : "s", i, i == 1 ? "was" : "were");
            if (!tok_is_punct(t, ','))
                tok_unget(p); /* POV-Ray lets a ',' be missing */
        }
        Symbol *ref = reference_argument(p, m, i);
        REF(i) = ref;
        if (!ref) {
            Value v = p->hooks->value(p);
            ARG(i) = v;
        }
    }
    Token *close = tok_next(p);
    if (!tok_is_punct(close, ')')) {
        if (tok_is_punct(close, ','))
            tok_fail(p, close->pos, "macro '%s' takes %d parameter%s but more were given", m->name, m->nparams,
                       m->nparams == 1 ? "" : "s");
        tok_fail_expected(p, close, "')' after the macro arguments");
    }
    tok_limits_count_call(p, call->pos, m->name);
    tok_open_macro(p, m, call->pos);
    tok_push_scope(p);
    for (int i = 0; i < m->nparams; i++) {
        int len = (int)strlen(m->params[i]);
        if (REF(i)) {
            Symbol *s = tok_symbol_add_local(p, m->params[i], len, NULL);
            s->alias = REF(i);
            s->alias_serial = REF(i)->serial;
        } else {
            tok_symbol_add_local(p, m->params[i], len, &ARG(i));
        }
    }
    p->arg_values.n = p->arg_refs.n = base;
#undef ARG
#undef REF
}

/* The body's #end: back to the text after the call. */
void tok_macro_return(Parser *p)
{
    p->depth--;
    p->macro_depth--;
    tok_pop_scope(p);
}
