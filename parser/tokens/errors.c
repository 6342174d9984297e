/* The parse's errors, warnings and notes: every message of the parser is
 * made here, with its position, its text escaped (tok_text_escape), and the
 * longjmp back to the entry point; what hstrace does not support or only
 * approximates, which a #declare turns into a poisoned value. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tokens.h"

/* ---- errors ------------------------------------------------------------ */

/* The length of the printable UTF-8 character at s (n bytes left), or 0:
 * a control character (C0, DEL, C1), a malformed, overlong or surrogate
 * sequence, or a code point beyond U+10FFFF. */
static size_t printable_char(const unsigned char *s, size_t n)
{
    unsigned c = s[0];
    if (c < 0x80)
        return c >= 0x20 && c != 0x7f;
    size_t len = c >= 0xc2 && c <= 0xdf ? 2 : c >= 0xe0 && c <= 0xef ? 3 : c >= 0xf0 && c <= 0xf4 ? 4 : 0;
    if (len == 0 || len > n)
        return 0;
    for (size_t i = 1; i < len; i++)
        if ((s[i] & 0xc0) != 0x80)
            return 0;
    if ((c == 0xe0 && s[1] < 0xa0) || (c == 0xed && s[1] >= 0xa0) || (c == 0xf0 && s[1] < 0x90) ||
        (c == 0xf4 && s[1] >= 0x90))
        return 0; /* overlong, a surrogate, beyond U+10FFFF */
    if (c == 0xc2 && s[1] < 0xa0)
        return 0; /* U+0080 to U+009F: C1 controls */
    return len;
}

size_t tok_text_escape(char *out, size_t size, const char *in, const char *keep)
{
    const unsigned char *s = (const unsigned char *)in;
    size_t n = strlen(in), o = 0;
    for (size_t i = 0; i < n;) {
        size_t len = printable_char(s + i, n - i);
        if (len == 0 && keep && s[i] && strchr(keep, s[i]))
            len = 1;
        if (len) {
            if (o + len >= size)
                break;
            memcpy(out + o, s + i, len);
            o += len;
            i += len;
        } else {
            if (o + 4 >= size)
                break;
            snprintf(out + o, 5, "\\x%02x", s[i]);
            o += 4;
            i++;
        }
    }
    if (size)
        out[o] = '\0';
    return o;
}

const char *tok_display_name(Parser *p, const char *path)
{
    size_t n = strlen(path) * 4 + 1;
    char *shown = tok_scene_alloc(p, n);
    tok_text_escape(shown, n, path, NULL);
    return shown;
}

void tok_debug_end_line(Parser *p)
{
    if (p->debug_line_open)
        fputc('\n', stderr);
    p->debug_line_open = 0;
}

void tok_warning(Parser *p, SourcePos pos, const char *msg)
{
    if (p->opts->quiet_warnings)
        return;
    tok_debug_end_line(p);
    char shown[1024];
    tok_text_escape(shown, sizeof shown, msg, NULL);
    fprintf(stderr, "%s:%d:%d: warning: %s\n", pos.file, pos.line, pos.column, shown);
}

static _Noreturn void vfail(Parser *p, SourcePos pos, int is_io, const char *fmt, va_list ap)
{
    ParseError *e = p->err;
    snprintf(e->file, sizeof e->file, "%s", pos.file ? pos.file : "");
    e->line = pos.line;
    e->column = pos.column;
    e->is_io = is_io;
    /* The message may quote the scene (a string, a file name): what is not
     * printable UTF-8 is shown as \xNN, never copied to the terminal. */
    char raw[sizeof e->message];
    vsnprintf(raw, sizeof raw, fmt, ap);
    tok_text_escape(e->message, sizeof e->message, raw, NULL);
    /* "%g" shows a NaN's sign bit, which means nothing: "nan" either way */
    for (char *m = e->message; (m = strstr(m, "-nan")) != NULL;)
        memmove(m, m + 1, strlen(m + 1) + 1);
    /* Inside macros: where each was called, innermost first, so that an
     * error in a macro's body can be traced to the line that caused it. */
    e->notes[0] = '\0';
    size_t used = 0;
    int shown = 0, hidden = 0;
    for (int i = p->depth - 1; i >= 0; i--) {
        const SourceFile *f = &p->files[i];
        if (!f->macro)
            continue;
        if (shown == 8) {
            hidden++;
            continue;
        }
        int n = snprintf(e->notes + used, sizeof e->notes - used, "%s:%d:%d: note: in macro '%s' called here\n",
                         f->called_at.file, f->called_at.line, f->called_at.column, f->macro->name);
        if (n < 0 || (size_t)n >= sizeof e->notes - used) {
            e->notes[used] = '\0';
            hidden++;
            continue;
        }
        used += (size_t)n;
        shown++;
    }
    if (hidden)
        snprintf(e->notes + used, sizeof e->notes - used, "note: and %d more macro calls\n", hidden);
    longjmp(p->fail, 1);
}

void tok_fail(Parser *p, SourcePos pos, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfail(p, pos, 0, fmt, ap);
}

void tok_fail_io(Parser *p, SourcePos pos, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfail(p, pos, 1, fmt, ap);
}

const char *tok_describe(Parser *p, const Token *t)
{
    char buf[80];
    switch (t->type) {
    case TK_EOF:
        return "the end of the file";
    case TK_STRING:
        snprintf(buf, sizeof buf, "string \"%.40s%s\"", t->string, strlen(t->string) > 40 ? "..." : "");
        break;
    default:
        snprintf(buf, sizeof buf, "'%.*s'", t->len > 60 ? 60 : t->len, t->text);
        break;
    }
    return tok_temp_strndup(p, buf, strlen(buf));
}

void tok_fail_expected(Parser *p, const Token *found, const char *what)
{
    tok_fail(p, found->pos, "expected %s, found %s", what, tok_describe(p, found));
}

/* Inside a #declare an unsupported thing only poisons the declaration: the
 * error comes when (if ever) the scene uses it. */
static _Noreturn void poison(Parser *p, const char *what, SourcePos at, const Token *by, int strict_only)
{
    p->poison_what = what;
    p->poison_at = at;
    p->poison_by = by->pos;
    p->poison_strict = strict_only;
    longjmp(*p->poison_jmp, 1);
}

void tok_approximate(Parser *p, const Token *t, ApproxKind kind, const ApproxNote **notes)
{
    char what[96];
    snprintf(what, sizeof what, "'%.*s'", t->len > 60 ? 60 : t->len, t->text);
    if (p->opts->strict) {
        if (p->declaring)
            poison(p, tok_temp_strndup(p, what, strlen(what)), t->pos, t, 1);
        tok_fail(p, t->pos, "%s is only approximated by hstrace (%s); --strict makes it an error", what,
                   approx_kind_effect(kind));
    }
    tok_note_approximation(p, t, kind, notes);
}

void tok_note_approximation(Parser *p, const Token *t, ApproxKind kind, const ApproxNote **notes)
{
    char what[96];
    snprintf(what, sizeof what, "'%.*s'", t->len > 60 ? 60 : t->len, t->text);
    ApproxNote *n = tok_scene_alloc(p, sizeof *n);
    n->kind = kind;
    n->pos = t->pos;
    char *w = tok_scene_alloc(p, strlen(what) + 1);
    memcpy(w, what, strlen(what) + 1);
    n->what = w;
    n->next = *notes;
    *notes = n;
}

void tok_unsupported(Parser *p, const Token *t)
{
    if (t->kw == KW_sqr) /* a function-only keyword: POV-Ray 3.7 rejects it here too */
        tok_fail(p, t->pos, "'sqr' is only allowed inside function { }; use pow(X, 2)");
    char buf[96];
    snprintf(buf, sizeof buf, "'%.*s'", t->len > 60 ? 60 : t->len, t->text);
    if (p->declaring)
        poison(p, tok_temp_strndup(p, buf, strlen(buf)), t->pos, t, 0);
    tok_fail(p, t->pos, "%s is not supported by hstrace", buf);
}

void tok_unsupported_at(Parser *p, SourcePos pos, const char *what)
{
    if (p->declaring) {
        Token by;
        memset(&by, 0, sizeof by);
        by.pos = pos;
        poison(p, tok_temp_strndup(p, what, strlen(what)), pos, &by, 0);
    }
    tok_fail(p, pos, "%s is not supported by hstrace", what);
}

void tok_use_unsupported(Parser *p, const Token *t, const Value *v)
{
    if (p->declaring)
        poison(p, v->what, v->declared_at, t, v->strict_only);
    if (v->strict_only)
        tok_fail(p, t->pos, "%s is only approximated by hstrace; --strict makes it an error (declared at %s:%d)",
                   v->what, v->declared_at.file, v->declared_at.line);
    tok_fail(p, t->pos, "%s is not supported by hstrace (declared at %s:%d)", v->what, v->declared_at.file,
               v->declared_at.line);
}

int tok_defer_unsupported(Parser *p, const char *what, SourcePos at)
{
    if (!p->declaring)
        return 0;
    if (!p->deferred_what) {
        p->deferred_what = what;
        p->deferred_at = at;
    }
    Token *t = tok_next(p);
    if (tok_is_punct(t, '(')) {
        Token open = *t;
        tok_skip_balanced_group(p, &open);
    } else {
        tok_unget(p);
    }
    return 1;
}

