/* Characters to tokens, and the stack of open files (#include).
 *
 * Every file is read whole into the temporary arena, so a token's spelling can
 * point into its buffer and #while can jump back by offset. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#include <sys/stat.h>

#include "tokens.h"

const char *tok_dir_of(Parser *p, const char *path)
{
    const char *slash = strrchr(path, '/');
    if (!slash)
        return ".";
    if (slash == path)
        return "/";
    return tok_temp_strndup(p, path, (size_t)(slash - path));
}

/* Room for one more frame. Frame pointers are not kept across an open, so
 * the array may move. */
static void reserve_frame(Parser *p)
{
    if (p->depth < p->files_cap)
        return;
    int cap = p->files_cap ? p->files_cap * 2 : 16;
    if (cap > MAX_SOURCE_FRAMES)
        cap = MAX_SOURCE_FRAMES;
    SourceFile *bigger = tok_temp_alloc(p, sizeof *bigger * (size_t)cap);
    if (p->depth)
        memcpy(bigger, p->files, sizeof *bigger * (size_t)p->depth);
    p->files = bigger;
    p->files_cap = cap;
}

/* A frame for a file's text; name and dir are the caller's, kept. */
static void open_text(Parser *p, const char *name, const char *dir, const char *buf, size_t size, SourcePos at)
{
    if (p->include_depth >= MAX_INCLUDE_DEPTH || p->depth >= MAX_SOURCE_FRAMES) {
        /* Name the cycle when there is one: that is the usual cause. */
        for (int i = 0; i < p->depth; i++)
            if (!p->files[i].macro && strcmp(p->files[i].name, name) == 0)
                tok_fail(p, at, "#include nested more than %d deep: '%s' includes itself", MAX_INCLUDE_DEPTH,
                           name);
        tok_fail(p, at, "#include nested more than %d deep", MAX_INCLUDE_DEPTH);
    }
    reserve_frame(p);
    SourceFile *f = &p->files[p->depth++];
    p->include_depth++;
    memset(f, 0, sizeof *f);
    f->name = name;
    f->dir = dir;
    f->buf = buf;
    f->size = size;
    f->line = 1;
    f->col = 1;
    f->controls_at_entry = p->controls.n;
}

void tok_open_buffer(Parser *p, const char *name, const char *buf, size_t size, SourcePos at)
{
    open_text(p, tok_display_name(p, name), tok_dir_of(p, name), buf, size, at);
}

void tok_open_source(Parser *p, const SourceText *s, SourcePos at)
{
    open_text(p, s->name, s->dir, s->text, s->size, at);
    if (s->again) /* an #include in a loop: its text is read again */
        p->files[p->depth - 1].repeated_to = SIZE_MAX;
}

void tok_open_macro(Parser *p, const Macro *m, SourcePos called_at)
{
    if (p->macro_depth >= MAX_MACRO_DEPTH || p->depth >= MAX_SOURCE_FRAMES)
        tok_fail(p, called_at, "macro '%s' called more than %d levels deep: is its recursion endless?", m->name,
                   MAX_MACRO_DEPTH);
    reserve_frame(p);
    SourceFile *f = &p->files[p->depth++];
    p->macro_depth++;
    memset(f, 0, sizeof *f);
    f->name = m->file;
    f->dir = m->dir;
    f->buf = m->buf;
    f->size = m->size;
    f->offset = m->body_offset;
    f->line = m->body_line;
    f->col = m->body_col;
    f->controls_at_entry = p->controls.n;
    f->macro = m;
    f->called_at = called_at;
    f->repeated_to = SIZE_MAX; /* a body is read again at every call */
}

/* Adds dir unless the list has it already: the current folder and the
 * including file's are often the same ("." twice in a message), and a
 * folder searched twice finds nothing new. */
static int add_search_dir(const char **dirs, int nd, int cap, const char *dir)
{
    if (!dir || nd >= cap)
        return nd;
    for (int i = 0; i < nd; i++)
        if (strcmp(dirs[i], dir) == 0)
            return nd;
    dirs[nd] = dir;
    return nd + 1;
}

int tok_search_dirs(Parser *p, const char **dirs, int cap)
{
    int nd = add_search_dir(dirs, 0, cap, p->opts->first_dir);
    nd = add_search_dir(dirs, nd, cap, p->files[p->depth - 1].dir);
    for (int i = 0; i < p->opts->ninclude_dirs; i++)
        nd = add_search_dir(dirs, nd, cap, p->opts->include_dirs[i]);
    return nd;
}

LexMark tok_mark(Parser *p)
{
    SourceFile *f = &p->files[p->depth - 1];
    LexMark m = { p->depth, f->offset, f->line, f->col };
    return m;
}

void tok_seek(Parser *p, LexMark m)
{
    SourceFile *f = &p->files[m.depth - 1];
    f->offset = m.offset;
    f->line = m.line;
    f->col = m.col;
}

static int peek_char(const SourceFile *f, size_t ahead)
{
    return f->offset + ahead < f->size ? (unsigned char)f->buf[f->offset + ahead] : -1;
}

static void advance(SourceFile *f)
{
    if (f->offset >= f->size)
        return;
    if (f->buf[f->offset] == '\n') {
        f->line++;
        f->col = 1;
    } else {
        f->col++;
    }
    f->offset++;
}

static SourcePos here(const SourceFile *f)
{
    SourcePos s = { f->name, f->line, f->col };
    return s;
}

/* Whitespace and comments. POV-Ray nests block comments. */
static void skip_space(Parser *p, SourceFile *f)
{
    for (;;) {
        /* blanks, the common case, with a local index */
        size_t i = f->offset, size = f->size;
        const char *b = f->buf;
        int line = f->line, col = f->col;
        while (i < size) {
            char c = b[i];
            if (c == '\n') {
                line++;
                col = 1;
            } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
                col++;
            } else {
                break;
            }
            i++;
        }
        f->offset = i;
        f->line = line;
        f->col = col;
        int c = peek_char(f, 0);
        if (c == '/' && peek_char(f, 1) == '/') {
            while (f->offset < f->size && f->buf[f->offset] != '\n')
                advance(f);
        } else if (c == '/' && peek_char(f, 1) == '*') {
            SourcePos start = here(f);
            int level = 0;
            do {
                if (f->offset >= f->size)
                    tok_fail(p, start, "comment starting here has no closing '*/'");
                if (peek_char(f, 0) == '/' && peek_char(f, 1) == '*') {
                    level++;
                    advance(f);
                } else if (peek_char(f, 0) == '*' && peek_char(f, 1) == '/') {
                    level--;
                    advance(f);
                }
                advance(f);
            } while (level > 0);
        } else {
            return;
        }
    }
}

int tok_peek_char(Parser *p)
{
    SourceFile *f = &p->files[p->depth - 1];
    skip_space(p, f);
    return peek_char(f, 0);
}

size_t tok_bytes_left(Parser *p)
{
    const SourceFile *f = &p->files[p->depth - 1];
    return f->size - f->offset;
}

size_t tok_offset(Parser *p)
{
    return p->files[p->depth - 1].offset;
}

int tok_skip_semicolon(Parser *p)
{
    SourceFile *f = &p->files[p->depth - 1];
    skip_space(p, f);
    if (peek_char(f, 0) == ';') {
        advance(f);
        return 1;
    }
    return 0;
}

static int is_ident_start(int c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
static int is_digit(int c) { return c >= '0' && c <= '9'; }

/* Most numbers in big scenes (mesh2 lists) have few digits: with at most
 * 15 significant digits m and a power of ten 10^k, k <= 22, both are exact
 * doubles, so m / 10^k (or m * 10^k) is one correctly rounded operation:
 * the same double strtod() gives, at a fraction of its cost. Anything else
 * goes to strtod(). */
static int decimal_fast(const char *s, size_t len, double *out)
{
    static const double pow10[] = { 1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22 };
    unsigned long long m = 0;
    int digits = 0, frac = 0, seen_point = 0;
    size_t i = 0;
    for (; i < len; i++) {
        char c = s[i];
        if (c >= '0' && c <= '9') {
            if (m == 0 && c == '0') {
                if (seen_point)
                    frac++;
                continue; /* leading zeros do not count as digits */
            }
            if (++digits > 15)
                return 0;
            m = m * 10 + (unsigned long long)(c - '0');
            if (seen_point)
                frac++;
        } else if (c == '.' && !seen_point) {
            seen_point = 1;
        } else {
            break;
        }
    }
    int exp10 = 0;
    if (i < len) { /* an exponent */
        i++;
        int neg = 0;
        if (i < len && (s[i] == '+' || s[i] == '-'))
            neg = s[i++] == '-';
        if (i >= len || len - i > 3)
            return 0;
        for (; i < len; i++)
            exp10 = exp10 * 10 + (s[i] - '0');
        if (neg)
            exp10 = -exp10;
    }
    int scale = exp10 - frac;
    if (scale < -22 || scale > 22)
        return 0;
    *out = scale < 0 ? (double)m / pow10[-scale] : (double)m * pow10[scale];
    return 1;
}

int tok_number_text(const char *b, size_t start, size_t size, size_t *end, double *value)
{
    /* The digits of the common number (no exponent) are gathered as they
     * are scanned, as decimal_fast gathers them, so that it is converted
     * in the same pass. */
    static const double pow10[] = { 1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22 };
    size_t i = start;
    unsigned long long m = 0;
    int digits = 0, frac = 0;
    for (; i < size && is_digit((unsigned char)b[i]); i++)
        if (m != 0 || b[i] != '0') { /* leading zeros do not count as digits */
            digits++;
            m = m * 10 + (unsigned long long)(b[i] - '0');
        }
    if (i < size && b[i] == '.') {
        i++;
        for (; i < size && is_digit((unsigned char)b[i]); i++) {
            frac++;
            if (m != 0 || b[i] != '0') {
                digits++;
                m = m * 10 + (unsigned long long)(b[i] - '0');
            }
        }
    }
    int exponent = 0;
    if (i < size && (b[i] == 'e' || b[i] == 'E')) {
        size_t k = i + 1;
        if (k < size && (b[k] == '+' || b[k] == '-'))
            k++;
        if (k < size && is_digit((unsigned char)b[k])) {
            exponent = 1;
            i = k;
            while (i < size && is_digit((unsigned char)b[i]))
                i++;
        }
    }
    *end = i;
    size_t len = i - start;
    /* decimal_fast's rule: at most 15 digits (m is exact, and so is m /
     * 10^frac, one rounding); with an exponent, decimal_fast itself. */
    if (!exponent && digits <= 15 && frac <= 22) {
        *value = (double)m / pow10[frac];
        return 1;
    }
    if (decimal_fast(b + start, len, value))
        return 1;
    char tmp[128];
    if (len >= sizeof tmp)
        return 0;
    memcpy(tmp, b + start, len);
    tmp[len] = '\0';
    *value = strtod(tmp, NULL);
    return 1;
}

static void lex_number(Parser *p, SourceFile *f, Token *t)
{
    /* A number holds no newline: the column moves once. */
    size_t start = f->offset, end;
    int ok = tok_number_text(f->buf, start, f->size, &end, &t->number);
    f->col += (int)(end - start);
    f->offset = end;
    t->type = TK_NUMBER;
    t->len = (int)(end - start);
    if (!ok)
        tok_fail(p, t->pos, "number too long");
}

/* One punctuation character c (',' '<' '>') as the token scan_token would
 * make of it: '<' and '>' before '=' are another token (<=, >=). */
static int plain_punct(Parser *p, SourceFile *f, int c)
{
    size_t from = f->offset; /* tok_lex's count includes the blanks before */
    skip_space(p, f);
    if (peek_char(f, 0) != c || ((c == '<' || c == '>') && peek_char(f, 1) == '='))
        return 0;
    SourcePos pos = here(f);
    advance(f);
    tok_limits_count_token(p, f, from, pos);
    return 1;
}

int tok_plain_vector(Parser *p, int had_angle, double c[3])
{
    SourceFile *f = &p->files[p->depth - 1];
    LexMark m = tok_mark(p);
    if (!had_angle && !plain_punct(p, f, '<'))
        goto unexpected;
    for (int i = 0; i < 3; i++) {
        size_t from = f->offset;
        skip_space(p, f);
        SourcePos pos = here(f);
        int ch = peek_char(f, 0);
        double sign = 1.0;
        if (ch == '-' || ch == '+') { /* a sign is a token of its own */
            sign = ch == '-' ? -1.0 : 1.0;
            advance(f);
            tok_limits_count_token(p, f, from, pos);
            from = f->offset;
            skip_space(p, f);
            pos = here(f);
            ch = peek_char(f, 0);
        }
        if (!(is_digit(ch) || (ch == '.' && is_digit(peek_char(f, 1)))))
            goto unexpected;
        Token t;
        t.pos = pos;
        lex_number(p, f, &t);
        tok_limits_count_token(p, f, from, pos);
        c[i] = sign * t.number;
        if (!isfinite(c[i]))
            goto no; /* 1e309: the general path reports it */
        if (!plain_punct(p, f, i < 2 ? ',' : '>'))
            goto unexpected;
    }
    return 1;
unexpected: {
    /* The token that is not the plain vector's, read as tok_raw reads it
     * (counted, and failing where it would), so that what the budgets see
     * and report does not depend on which path reads the text. */
    Token t;
    tok_lex(p, f, &t);
}
no:
    tok_seek(p, m);
    return 0;
}

/* The value of the string literal whose quote stands at `at` in its
 * file's buffer, if it was read before (the buffers live as long as the
 * parse, and string values are never changed in place). */
static char **literal_slot(Parser *p, const char *at)
{
    if ((p->nliterals + 1) * 2 > p->cap_literals) {
        size_t cap = p->cap_literals ? p->cap_literals * 2 : 256;
        struct Interned *t = tok_temp_alloc(p, sizeof *t * cap);
        for (size_t i = 0; i < p->cap_literals; i++) {
            if (!p->literals[i].key)
                continue;
            size_t j = ((uintptr_t)p->literals[i].key * 11400714819323198485ull >> 20) & (cap - 1);
            while (t[j].key)
                j = (j + 1) & (cap - 1);
            t[j] = p->literals[i];
        }
        p->literals = t;
        p->cap_literals = cap;
    }
    size_t j = ((uintptr_t)at * 11400714819323198485ull >> 20) & (p->cap_literals - 1);
    while (p->literals[j].key && p->literals[j].key != at)
        j = (j + 1) & (p->cap_literals - 1);
    if (!p->literals[j].key) {
        p->literals[j].key = at;
        p->nliterals++;
    }
    return &p->literals[j].value;
}

static void lex_string(Parser *p, SourceFile *f, Token *t)
{
    char **cached = literal_slot(p, f->buf + f->offset);
    advance(f); /* the opening quote */
    size_t start = f->offset;
    size_t n = 0;
    while (f->offset < f->size && f->buf[f->offset] != '"') {
        if (f->buf[f->offset] == '\\' && f->offset + 1 < f->size)
            advance(f);
        advance(f);
        n++;
    }
    if (f->offset >= f->size)
        tok_fail(p, t->pos, "string starting here has no closing '\"'");
    size_t end = f->offset;
    advance(f);
    t->type = TK_STRING;
    t->len = (int)(f->offset - start + 1);
    if (*cached) { /* read again: a loop's next pass, a macro's next call */
        t->string = *cached;
        return;
    }
    char *s = tok_temp_alloc(p, n + 1), *o = s;
    for (size_t i = start; i < end; i++) {
        char c = f->buf[i];
        if (c == '\\' && i + 1 < end) {
            c = f->buf[++i];
            switch (c) {
            case 'n': c = '\n'; break;
            case 't': c = '\t'; break;
            case 'r': c = '\r'; break;
            case 'a': c = '\a'; break;
            case 'b': c = '\b'; break;
            case 'f': c = '\f'; break;
            case 'v': c = '\v'; break;
            default: break; /* \\ \" \' stand for themselves */
            }
        }
        *o++ = c;
    }
    *o = '\0';
    t->string = s;
    *cached = s;
}

void tok_raw(Parser *p, Token *t)
{
    tok_lex(p, &p->files[p->depth - 1], t);
}

static void scan_token(Parser *p, SourceFile *f, Token *t);

void tok_lex(Parser *p, SourceFile *f, Token *t)
{
    if (tok_limits_stack_low(p))
        tok_limits_stack_exhausted(p, here(f));
    size_t from = f->offset;
    scan_token(p, f, t);
    tok_limits_count_token(p, f, from, t->pos);
}

/* The blanks and comments, then the token: t. */
static void scan_token(Parser *p, SourceFile *f, Token *t)
{
    skip_space(p, f);
    memset(t, 0, sizeof *t);
    t->kw = -1;
    t->pos = here(f);
    t->text = f->buf + f->offset;
    int c = peek_char(f, 0);
    if (c < 0) {
        t->type = TK_EOF;
        t->text = "";
        return;
    }
    if (is_digit(c) || (c == '.' && is_digit(peek_char(f, 1)))) {
        lex_number(p, f, t);
        return;
    }
    if (is_ident_start(c)) {
        size_t start = f->offset;
        while (is_ident_start(peek_char(f, 0)) || is_digit(peek_char(f, 0)))
            advance(f);
        size_t len = f->offset - start;
        if (len > 200)
            tok_fail(p, t->pos, "identifier too long (more than 200 characters)");
        t->type = TK_WORD;
        t->len = (int)len;
        t->kw = tok_keyword_lookup(t->text, t->len);
        return;
    }
    if (c == '"') {
        lex_string(p, f, t);
        return;
    }
    t->type = TK_PUNCT;
    t->punct = c;
    t->len = 1;
    int c2 = peek_char(f, 1);
    if (c == '<' && c2 == '=')
        t->punct = P_LE;
    else if (c == '>' && c2 == '=')
        t->punct = P_GE;
    else if (c == '!' && c2 == '=')
        t->punct = P_NE;
    if (t->punct >= 256) {
        t->len = 2;
        advance(f);
    }
    /* the characters POV-Ray's language uses as punctuation */
    static const unsigned char is_punctuation[256] = {
        ['{'] = 1, ['}'] = 1, ['('] = 1, [')'] = 1, ['['] = 1, [']'] = 1, ['<'] = 1, ['>'] = 1,
        [','] = 1, [';'] = 1, ['='] = 1, ['+'] = 1, ['-'] = 1, ['*'] = 1, ['/'] = 1, ['.'] = 1,
        ['?'] = 1, [':'] = 1, ['!'] = 1, ['&'] = 1, ['|'] = 1, ['#'] = 1,
    };
    if (!is_punctuation[(unsigned char)c]) {
        if (c >= 32 && c < 127)
            tok_fail(p, t->pos, "unexpected character '%c'", c);
        tok_fail(p, t->pos, "unexpected byte 0x%02x", (unsigned)c);
    }
    advance(f);
}

int tok_next_is_punct(Parser *p, int c)
{
    if (p->ungot)
        return tok_is_punct(&p->tok, c);
    LexMark m = tok_mark(p);
    Token t;
    tok_raw(p, &t);
    tok_seek(p, m);
    return tok_is_punct(&t, c);
}

int tok_next_is_brace_and_word(Parser *p, Token *word)
{
    if (p->ungot)
        return 0;
    LexMark m = tok_mark(p);
    Token brace;
    tok_raw(p, &brace);
    int found = tok_is_punct(&brace, '{');
    if (found) {
        tok_raw(p, word);
        found = word->type == TK_WORD;
    }
    tok_seek(p, m);
    return found;
}

int tok_next_is_keyword(Parser *p, int kw)
{
    if (p->ungot)
        return p->tok.type == TK_WORD && p->tok.kw == kw;
    LexMark m = tok_mark(p);
    Token t;
    tok_raw(p, &t);
    tok_seek(p, m);
    return t.type == TK_WORD && t.kw == kw;
}
