/* The token stream the grammar sees: raw tokens with every #directive already
 * carried out (#include, #declare, #if, #while, #for, #macro skipping, ...).
 *
 * #while and #for are replayed the way POV-Ray does it: the loop remembers
 * where its condition (or body) starts in the file buffer and the lexer jumps
 * back there at #end. Skipped text (a false #if branch, a finished loop, a
 * macro body) is tokenised but not interpreted, counting nested directives to
 * find the matching #else/#end. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "tokens.h"

int tok_is_punct(const Token *t, int c) { return t->type == TK_PUNCT && t->punct == c; }
int tok_is_kw(const Token *t, int kw) { return t->type == TK_WORD && t->kw == kw; }

static void handle_directive(Parser *p, const Token *hash);

static void count_braces(Parser *p, const Token *t, int dir)
{
    if (tok_is_punct(t, '{'))
        p->brace_depth += dir;
    else if (tok_is_punct(t, '}'))
        p->brace_depth -= dir;
}

/* End of the current file: check its #if/#while are closed, go back to the
 * includer. Returns 0 at the end of the scene itself. */
static int close_file(Parser *p, const Token *eof)
{
    SourceFile *f = &p->files[p->depth - 1];
    if (f->macro) /* its #end was taken by a directive of the body: unbalanced */
        tok_fail(p, eof->pos, "the body of macro '%s' (declared at %s:%d) ends without its #end", f->macro->name,
                   f->macro->declared_at.file, f->macro->declared_at.line);
    if (p->controls.n > f->controls_at_entry) {
        Control *c = (Control *)p->controls.data + p->controls.n - 1;
        tok_fail(p, c->pos, "this directive has no matching #end before the end of '%s'", f->name);
    }
    if (p->depth == 1)
        return 0;
    p->depth--;
    p->include_depth--;
    tok_pop_scope(p);
    return 1;
}

/* An identifier just read into p->tok: a macro call is carried out (1), an
 * array element gets its indices read. */
static int expand_identifier(Parser *p)
{
    Symbol *s = tok_symbol_find(p, p->tok.text, p->tok.len);
    if (!s)
        return 0;
    if (s->value.kind == VAL_MACRO && !p->no_macro_calls) {
        Token call = p->tok;
        tok_macro_invoke(p, &call, s->value.macro);
        return 1;
    }
    if (s->value.kind == VAL_ARRAY && tok_peek_char(p) == '[')
        tok_array_element(p, s);
    return 0;
}

Token *tok_next(Parser *p)
{
    if (p->ungot) {
        p->ungot = 0;
        count_braces(p, &p->tok, +1);
        return &p->tok;
    }
    for (;;) {
        tok_raw(p, &p->tok);
        if (p->tok.type == TK_EOF) {
            if (close_file(p, &p->tok))
                continue;
            break;
        }
        if (tok_is_punct(&p->tok, '#')) {
            Token hash = p->tok;
            handle_directive(p, &hash);
            if (p->ungot) {
                /* the directive read one token too far (an expression's
                 * lookahead): that token is the next one */
                p->ungot = 0;
                break;
            }
            continue;
        }
        if (p->tok.type == TK_WORD && p->tok.kw < 0 && expand_identifier(p))
            continue;
        break;
    }
    p->last_pos = p->tok.pos;
    count_braces(p, &p->tok, +1);
    return &p->tok;
}

Token *tok_next_name(Parser *p)
{
    p->no_macro_calls++;
    Token *t = tok_next(p);
    p->no_macro_calls--;
    return t;
}

void tok_unget(Parser *p)
{
    p->ungot = 1;
    count_braces(p, &p->tok, -1);
}

Token *tok_peek(Parser *p)
{
    Token *t = tok_next(p);
    tok_unget(p);
    return t;
}

void tok_expect_punct(Parser *p, int c, const char *after)
{
    Token *t = tok_next(p);
    if (!tok_is_punct(t, c)) {
        char what[64];
        snprintf(what, sizeof what, "'%c' after %s", c, after);
        tok_fail_expected(p, t, what);
    }
}

void tok_begin_block(Parser *p, const char *after)
{
    Token *t = tok_next(p);
    if (!tok_is_punct(t, '{')) {
        char what[80];
        snprintf(what, sizeof what, "'{' after '%s'", after);
        tok_fail_expected(p, t, what);
    }
}

/* After a '{' was read: everything up to its '}', directives still obeyed. */
void tok_skip_block_body(Parser *p)
{
    int target = p->brace_depth - 1;
    for (;;) {
        Token *t = tok_next(p);
        if (t->type == TK_EOF)
            tok_fail(p, t->pos, "expected '}' before the end of the file");
        if (tok_is_punct(t, '}') && p->brace_depth == target)
            return;
    }
}

/* `open` ('(' '[' or '{') was read: skip to its partner. */
void tok_skip_balanced_group(Parser *p, const Token *open)
{
    if (tok_is_punct(open, '{')) {
        tok_skip_block_body(p);
        return;
    }
    int close = open->punct == '(' ? ')' : ']';
    int level = 1;
    SourcePos start = open->pos;
    while (level > 0) {
        Token *t = tok_next(p);
        if (t->type == TK_EOF)
            tok_fail(p, start, "no matching '%c' for this '%c' before the end of the file", close, open->punct);
        if (tok_is_punct(t, open->punct))
            level++;
        else if (tok_is_punct(t, close))
            level--;
    }
}

/* ---- skipping text ------------------------------------------------------ */

typedef enum { SKIP_TO_END, SKIP_TO_ELSE, SKIP_TO_CASE } SkipMode;
typedef enum { STOP_END, STOP_ELSE, STOP_ELSEIF, STOP_CASE, STOP_RANGE } SkipStop;

static int opens_block(int kw)
{
    return kw == KW_if || kw == KW_ifdef || kw == KW_ifndef || kw == KW_while || kw == KW_for ||
           kw == KW_switch || kw == KW_macro;
}

/* Raw tokens up to the matching #end (or, in SKIP_TO_ELSE, an #else/#elseif
 * of the same level), which is consumed. `from` is for the message. */
static SkipStop skip_text(Parser *p, SkipMode mode, SourcePos from, const char *what)
{
    int level = 0;
    Token t;
    for (;;) {
        tok_raw(p, &t);
        if (t.type == TK_EOF)
            tok_fail(p, from, "%s has no matching #end", what);
        if (!tok_is_punct(&t, '#'))
            continue;
        tok_raw(p, &t);
        if (t.type != TK_WORD)
            continue;
        if (opens_block(t.kw)) {
            level++;
        } else if (t.kw == KW_end) {
            if (level == 0)
                return STOP_END;
            level--;
        } else if (level == 0 && mode == SKIP_TO_ELSE) {
            if (t.kw == KW_else)
                return STOP_ELSE;
            if (t.kw == KW_elseif)
                return STOP_ELSEIF;
        } else if (level == 0 && mode == SKIP_TO_CASE) {
            if (t.kw == KW_else)
                return STOP_ELSE;
            if (t.kw == KW_case)
                return STOP_CASE;
            if (t.kw == KW_range)
                return STOP_RANGE;
        }
    }
}

void tok_macro_skip_body(Parser *p, SourcePos from)
{
    skip_text(p, SKIP_TO_END, from, "#macro");
}

/* ---- the control stack ---------------------------------------------------- */

static Control *push_control(Parser *p, ControlKind kind, SourcePos pos)
{
    if (p->controls.n >= 100000)
        tok_fail(p, pos, "directives nested too deeply");
    Control *c = tok_tvec_push(p, &p->controls);
    c->kind = kind;
    c->file_depth = p->depth;
    c->pos = pos;
    return c;
}

static Control *top_control(Parser *p)
{
    SourceFile *f = &p->files[p->depth - 1];
    if (p->controls.n <= f->controls_at_entry)
        return NULL;
    return (Control *)p->controls.data + p->controls.n - 1;
}

/* The loop goes back to m: the text from there to here is read again. */
static void loop_back(Parser *p, LexMark m)
{
    SourceFile *f = &p->files[m.depth - 1];
    if (f->offset > f->repeated_to)
        f->repeated_to = f->offset;
    tok_seek(p, m);
}

/* `( expr )`, as POV-Ray requires after #if/#while: the closing parenthesis
 * ends it, so no token beyond is read (it may be another directive). */
static double parse_condition(Parser *p, const char *after)
{
    tok_expect_punct(p, '(', after);
    double e[5] = { 0 };
    int terms = 1;
    p->hooks->expression(p, e, &terms);
    tok_expect_punct(p, ')', "the condition");
    return e[0];
}

/* A condition is true when it is not (nearly) zero, as POV-Ray's ftrue(),
 * whose EPSILON is 1e-10. */
static int truthy(double v) { return fabs(v) > 1e-10; }

static void run_if(Parser *p, const Token *hash, int cond)
{
    while (!cond) {
        SkipStop s = skip_text(p, SKIP_TO_ELSE, hash->pos, "#if");
        if (s == STOP_END)
            return;
        if (s == STOP_ELSE) {
            push_control(p, CTL_ELSE, hash->pos);
            return;
        }
        cond = truthy(parse_condition(p, "#elseif"));
    }
    push_control(p, CTL_IF, hash->pos);
}

static Token read_identifier(Parser *p, const char *after)
{
    Token *t = tok_next(p);
    if (t->type != TK_WORD) {
        char what[80];
        snprintf(what, sizeof what, "an identifier after %s", after);
        tok_fail_expected(p, t, what);
    }
    return *t;
}

static void directive_end(Parser *p, const Token *hash)
{
    Control *c = top_control(p);
    if (!c) {
        if (p->files[p->depth - 1].macro) {
            tok_macro_return(p);
            return;
        }
        tok_fail(p, hash->pos, "#end without a matching #if, #while, #for, #switch or #macro");
    }
    if (c->kind == CTL_IF || c->kind == CTL_ELSE || c->kind == CTL_SWITCH) {
        p->controls.n--;
        return;
    }
    tok_limits_count_iteration(p, c->pos);
    if (c->kind == CTL_WHILE) {
        LexMark m = c->loop;
        SourcePos at = c->pos;
        loop_back(p, m);
        if (!truthy(parse_condition(p, "#while"))) {
            p->controls.n--;
            skip_text(p, SKIP_TO_END, at, "#while");
        }
        return;
    }
    /* CTL_FOR */
    Symbol *s = tok_symbol_find(p, c->for_var, (int)strlen(c->for_var));
    if (!s || s->value.kind != VAL_NUMERIC || s->value.terms != 1)
        tok_fail(p, hash->pos, "the #for variable '%s' is no longer a float", c->for_var);
    double v = s->value.v[0] + c->for_step;
    s->value.v[0] = v;
    if (c->for_step > 0 ? v <= c->for_end : v >= c->for_end)
        loop_back(p, c->loop);
    else
        p->controls.n--;
}

static void directive_for(Parser *p, const Token *hash)
{
    tok_expect_punct(p, '(', "#for");
    p->no_macro_calls++;
    Token var = read_identifier(p, "#for (");
    p->no_macro_calls--;
    if (var.kw >= 0)
        tok_fail(p, var.pos, "'%s' is a reserved word and cannot be a #for variable", tok_keyword_name(var.kw));
    tok_expect_punct(p, ',', "the #for variable");
    double start = p->hooks->number(p);
    tok_expect_punct(p, ',', "the #for start value");
    double end = p->hooks->number(p);
    double step = 1.0;
    Token *t = tok_next(p);
    if (tok_is_punct(t, ',')) {
        step = p->hooks->number(p);
        t = tok_next(p);
    }
    if (!tok_is_punct(t, ')'))
        tok_fail_expected(p, t, "')' to close #for");
    if (step == 0.0)
        tok_fail(p, hash->pos, "#for step must not be zero");
    Value v = { .kind = VAL_NUMERIC, .terms = 1 };
    v.v[0] = start;
    tok_symbol_set(p, var.text, var.len, 1, &v);
    if (step > 0 ? start > end : start < end) {
        skip_text(p, SKIP_TO_END, hash->pos, "#for");
        return;
    }
    Control *c = push_control(p, CTL_FOR, hash->pos);
    c->loop = tok_mark(p);
    c->for_var = tok_intern_name(p, var.text, var.len);
    c->for_end = end;
    c->for_step = step;
}

/* ---- #switch ------------------------------------------------------------ */

/* POV-Ray compares a #case value with the #switch value to within 1e-10. */
static int case_matches(Parser *p, double value, int is_range)
{
    if (!is_range)
        return fabs(parse_condition(p, "#case") - value) < 1e-10;
    tok_expect_punct(p, '(', "#range");
    double lo = p->hooks->number_full(p);
    tok_expect_punct(p, ',', "the lower end of the range");
    double hi = p->hooks->number_full(p);
    tok_expect_punct(p, ')', "the upper end of the range");
    return value >= lo && value <= hi;
}

/* From the #switch line (or a #case that did not match): skip to the next
 * #case or #range that matches, or #else, and read the text after it; or
 * to #end, which closes the #switch. */
static void find_matching_case(Parser *p, SourcePos switch_pos, double value)
{
    for (;;) {
        SkipStop s = skip_text(p, SKIP_TO_CASE, switch_pos, "#switch");
        if (s == STOP_END)
            return;
        if (s == STOP_ELSE || case_matches(p, value, s == STOP_RANGE))
            break;
    }
    Control *c = push_control(p, CTL_SWITCH, switch_pos);
    c->switch_value = value;
}

static void directive_switch(Parser *p, const Token *hash)
{
    double value = parse_condition(p, "#switch");
    /* Only blanks and comments may come before the first #case: POV-Ray
     * reports anything else. */
    LexMark m = tok_mark(p);
    Token t;
    tok_raw(p, &t);
    if (tok_is_punct(&t, '#'))
        tok_raw(p, &t);
    if (!tok_is_kw(&t, KW_case) && !tok_is_kw(&t, KW_range) && !tok_is_kw(&t, KW_else) && !tok_is_kw(&t, KW_end))
        tok_fail(p, t.pos, "#switch must be followed by #case, #range, #else or #end");
    tok_seek(p, m);
    find_matching_case(p, hash->pos, value);
}

/* #case, #range or #else reached while reading a matching case: POV-Ray
 * falls through (the condition is read and ignored) until #break. */
static int switch_fall_through(Parser *p, const Token *t)
{
    Control *c = top_control(p);
    if (!c || c->kind != CTL_SWITCH)
        return 0;
    if (t->kw != KW_else)
        (void)case_matches(p, c->switch_value, t->kw == KW_range);
    return 1;
}

/* #break: leave the innermost #switch, #while or #for (skipping to its
 * #end, any #if inside closed on the way), or return from the macro. */
static void directive_break(Parser *p, const Token *hash)
{
    for (;;) {
        Control *c = top_control(p);
        if (!c) {
            if (p->files[p->depth - 1].macro) {
                tok_macro_return(p);
                return;
            }
            tok_fail(p, hash->pos, "#break outside #switch, #while, #for and #macro");
        }
        ControlKind kind = c->kind;
        SourcePos at = c->pos;
        p->controls.n--;
        skip_text(p, SKIP_TO_END, at, kind == CTL_SWITCH ? "#switch" : kind == CTL_WHILE ? "#while" : kind == CTL_FOR ? "#for" : "#if");
        if (kind == CTL_SWITCH || kind == CTL_WHILE || kind == CTL_FOR)
            return;
    }
}

static void directive_include(Parser *p, const Token *hash)
{
    Token *t = tok_peek(p);
    SourcePos at = t->pos;
    char *name = p->hooks->string(p);
    SourceText text;
    if (name[0] == '/') {
        if (!tok_source_read(p, name, at, &text))
            tok_fail_io(p, at, "cannot open include file '%s': %s", name, strerror(errno));
        tok_open_source(p, &text, at);
    } else {
        const char *dirs[130];
        int nd = tok_search_dirs(p, dirs, 128);
        for (int i = 0; i < nd; i++) {
            if (tok_source_read_in(p, dirs[i], name, at, &text)) {
                tok_open_source(p, &text, at);
                tok_push_scope(p);
                return;
            }
        }
        char searched[400];
        size_t used = 0;
        searched[0] = '\0';
        for (int i = 0; i < nd && used + 4 < sizeof searched; i++) {
            int w = snprintf(searched + used, sizeof searched - used, "%s%s", i ? ", " : "", dirs[i]);
            used += w > 0 ? (size_t)w : 0;
        }
        if (used >= sizeof searched)
            memcpy(searched + sizeof searched - 4, "...", 4);
        tok_fail_io(p, at, "cannot open include file '%s' (searched: %s)", name, searched);
    }
    (void)hash;
    tok_push_scope(p);
}

/* '#' before something that is not a directive: POV-Ray 3.7 drops the '#'
 * without a word and reads on from the token after it (image_size.pov's
 * `look_at <0,2,0>#`, then '}'), except before a float identifier or a float
 * function, where it stops with "Expected 'object or directive.'" (its
 * Parse_Directive; checked with povray). */
static void stray_hash(Parser *p, const Token *t, LexMark before)
{
    if (t->type == TK_WORD && p->hooks->starts_float(p, t))
        tok_fail_expected(p, t, "a directive after '#'");
    tok_seek(p, before);
}

static void handle_directive(Parser *p, const Token *hash)
{
    Token t;
    LexMark before = tok_mark(p);
    tok_raw(p, &t);
    if (t.type != TK_WORD || t.kw < 0) {
        Symbol *s = t.type == TK_WORD ? tok_symbol_find(p, t.text, t.len) : NULL;
        if (s && s->value.kind == VAL_MACRO) { /* `#Name(...)`, as older scenes write it */
            tok_macro_invoke(p, &t, s->value.macro);
            return;
        }
        stray_hash(p, &t, before);
        return;
    }
    switch (t.kw) {
    case KW_include:
        directive_include(p, hash);
        return;
    case KW_declare:
    case KW_local:
        p->hooks->declare(p, hash, t.kw == KW_local);
        return;
    case KW_undef: {
        p->no_macro_calls++;
        Token id = read_identifier(p, "#undef");
        p->no_macro_calls--;
        if (id.elem)
            tok_fail(p, id.pos, "#undef cannot remove an array element");
        tok_symbol_undef(p, id.text, id.len);
        return;
    }
    case KW_if:
        run_if(p, hash, truthy(parse_condition(p, "#if")));
        return;
    case KW_ifdef:
    case KW_ifndef: {
        tok_expect_punct(p, '(', t.kw == KW_ifdef ? "#ifdef" : "#ifndef");
        p->no_macro_calls++;
        Token id = read_identifier(p, "'('");
        p->no_macro_calls--;
        tok_expect_punct(p, ')', "the identifier");
        int defined = id.elem ? id.elem->value.kind != VAL_NONE : id.kw < 0 && tok_symbol_find(p, id.text, id.len) != NULL;
        run_if(p, hash, t.kw == KW_ifdef ? defined : !defined);
        return;
    }
    case KW_else:
        if (switch_fall_through(p, &t))
            return;
        /* fall through */
    case KW_elseif: {
        Control *c = top_control(p);
        if (!c || c->kind != CTL_IF)
            tok_fail(p, t.pos, "#%s without a matching #if", tok_keyword_name(t.kw));
        /* The branch before it ran: skip the rest, #elseif conditions unread. */
        p->controls.n--;
        skip_text(p, SKIP_TO_END, c->pos, "#if");
        return;
    }
    case KW_end:
        directive_end(p, hash);
        return;
    case KW_while: {
        LexMark m = tok_mark(p);
        if (truthy(parse_condition(p, "#while"))) {
            tok_limits_count_iteration(p, hash->pos);
            Control *c = push_control(p, CTL_WHILE, hash->pos);
            c->loop = m;
        } else {
            skip_text(p, SKIP_TO_END, hash->pos, "#while");
        }
        return;
    }
    case KW_for:
        directive_for(p, hash);
        return;
    case KW_macro:
        tok_macro_define(p, hash);
        return;
    case KW_version: {
        double v = p->hooks->number(p);
        if (!tok_is_punct(tok_next(p), ';'))
            tok_unget(p); /* POV-Ray wants the ';'; hstrace does not insist */
        p->version = v;
        p->version_given = 1;
        p->hooks->version_seen(p);
        return;
    }
    case KW_debug: {
        /* POV-Ray's debug stream: the text as it is, newlines from "\n"
         * (and tabs), the other controls escaped as in messages */
        char *msg = p->hooks->string(p);
        size_t n = strlen(msg) * 4 + 1;
        char *shown = tok_temp_alloc(p, n);
        tok_text_escape(shown, n, msg, "\n\t");
        if (p->opts->quiet_debug)
            return;
        fputs(shown, stderr);
        fflush(stderr);
        if (*msg)
            p->debug_line_open = msg[strlen(msg) - 1] != '\n';
        return;
    }
    case KW_warning: {
        tok_warning(p, hash->pos, p->hooks->string(p));
        return;
    }
    case KW_error: {
        char *msg = p->hooks->string(p);
        tok_fail(p, hash->pos, "#error: %s", msg);
    }
    case KW_default:
        p->hooks->default_directive(p);
        return;
    case KW_switch:
        directive_switch(p, hash);
        return;
    case KW_case:
    case KW_range:
        if (switch_fall_through(p, &t))
            return;
        tok_fail(p, t.pos, "#%s without a matching #switch", tok_keyword_name(t.kw));
    case KW_break:
        directive_break(p, hash);
        return;
    case KW_fopen:
        tok_fopen(p, hash);
        return;
    case KW_fclose:
        tok_fclose(p);
        return;
    case KW_read:
        tok_read(p);
        return;
    case KW_write:
        tok_write(p);
        return;
    default:
        stray_hash(p, &t, before);
    }
}
