/* POV-Ray's user file directives: #fopen, #fclose, #read, #write.
 *
 * A file opened for reading is read whole into the temporary arena at #fopen
 * and tokenised from there, so no FILE* stays open for it. A file opened for
 * writing keeps its FILE* until #fclose or the end of the parse, where
 * tok_user_files_close_all() closes it whether the parse succeeded or not.
 *
 * As in POV-Ray: the file identifier is global; #read declares (globally)
 * or overwrites its variables; when a #read reaches the end of the data the
 * file is closed and its identifier undefined, so that
 * `#while (defined(F)) #read (F, V) ... #end` reads every value. Numbers are
 * written with C's "%g" (six significant digits), vectors as "<x,y,z> ". */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "tokens.h"

typedef struct UserFile {
    const char *name;  /* as written in #fopen, for messages (interned) */
    SourcePos opened_at;
    FILE *out;         /* write / append, until closed */
    int reading;
    SourceFile data; /* reading: the data, tokenised by the scene lexer */
    struct UserFile *next_free; /* closed and forgotten: the next #fopen's */
} UserFile;

/* ---- files --------------------------------------------------------------- */

/* A record for a new #fopen: one whose file was closed and whose
 * identifier is gone (so that #fopen ... #fclose in a loop costs one), or
 * a new one. */
static UserFile *new_user_file(Parser *p, const char *name, SourcePos at)
{
    UserFile *f = p->free_user_files;
    if (f) {
        p->free_user_files = f->next_free;
    } else {
        f = tok_temp_alloc(p, sizeof *f);
        *(UserFile **)tok_tvec_push(p, &p->user_files) = f;
    }
    memset(f, 0, sizeof *f);
    char shown[512];
    tok_text_escape(shown, sizeof shown, name, NULL);
    f->name = tok_intern_name(p, shown, (int)strlen(shown));
    f->opened_at = at;
    return f;
}

/* f is closed and its identifier undefined: nothing refers to it. */
static void forget_user_file(Parser *p, UserFile *f)
{
    f->next_free = p->free_user_files;
    p->free_user_files = f;
}

/* Closes f's output; a write error is reported at `at` when report is set. */
static void close_output(Parser *p, UserFile *f, SourcePos at, int report)
{
    FILE *out = f->out;
    if (!out)
        return;
    f->out = NULL; /* before any error: the error path closes the others */
    int failed = ferror(out);
    if (fclose(out) != 0)
        failed = 1;
    if (failed && report)
        tok_fail_io(p, at, "error writing '%s'", f->name);
}

void tok_user_files_close_all(Parser *p, int report)
{
    UserFile **files = p->user_files.data;
    for (int i = 0; i < p->user_files.n; i++)
        close_output(p, files[i], files[i]->opened_at, report);
}

/* POV-Ray looks for a file to read in the current folder, then in its
 * library paths; hstrace also looks in the scene's folder first among the
 * latter, as #include does. */
static int read_data(Parser *p, const char *name, SourcePos at, SourceText *out)
{
    if (tok_source_read(p, name, at, out))
        return 1;
    if (name[0] == '/')
        return 0;
    int e = errno;
    const char *dirs[130];
    int nd = tok_search_dirs(p, dirs, 128);
    for (int i = 0; i < nd; i++)
        if (tok_source_read_in(p, dirs[i], name, at, out))
            return 1;
    errno = e;
    return 0;
}

/* Written files are regular files too: opened without blocking (a FIFO
 * with no reader fails at once instead of waiting), then checked. */
static FILE *open_for_writing(Parser *p, const char *name, int append, SourcePos at)
{
    const char *doing = append ? "appending" : "writing";
    int fd = open(name, O_WRONLY | O_CREAT | O_NONBLOCK | O_CLOEXEC | (append ? O_APPEND : O_TRUNC), 0666);
    if (fd < 0)
        tok_fail_io(p, at, "cannot open '%s' for %s: %s", name, doing, strerror(errno));
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        tok_fail_io(p, at, "cannot open '%s' for %s: it is not a regular file", name, doing);
    }
    int flags = fcntl(fd, F_GETFL);
    if (flags >= 0)
        (void)fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    FILE *out = fdopen(fd, append ? "a" : "w");
    if (!out) {
        int e = errno;
        close(fd);
        tok_fail_io(p, at, "cannot open '%s' for %s: %s", name, doing, strerror(e));
    }
    return out;
}

/* The file a token names, checked to be open in the wanted mode. */
static UserFile *file_of(Parser *p, const char *directive, int reading)
{
    p->no_macro_calls++;
    Token t = *tok_next(p);
    p->no_macro_calls--;
    Symbol *s = t.type == TK_WORD && t.kw < 0 && !t.elem ? tok_symbol_find(p, t.text, t.len) : NULL;
    if (!s && t.type == TK_WORD && t.kw < 0 && !t.elem)
        tok_fail(p, t.pos,
                   "'%.*s' is not an open file: no #fopen declared it, or it was closed (by #fclose, or when "
                   "a #read reached the end of its data)",
                   t.len, t.text);
    if (!s || s->value.kind != VAL_FILE) {
        char what[80];
        snprintf(what, sizeof what, "a file identifier opened by #fopen after '%s ('", directive);
        tok_fail_expected(p, &t, what);
    }
    UserFile *f = s->value.file;
    if (reading && !f->reading)
        tok_fail(p, t.pos, "cannot read from '%.*s': file '%s' is open for writing", t.len, t.text, f->name);
    if (!reading && f->reading)
        tok_fail(p, t.pos, "cannot write to '%.*s': file '%s' is open for reading", t.len, t.text, f->name);
    return f;
}

/* ---- #fopen / #fclose -------------------------------------------------------- */

void tok_fopen(Parser *p, const Token *hash)
{
    (void)hash;
    p->no_macro_calls++;
    Token id = *tok_next(p);
    p->no_macro_calls--;
    if (id.type != TK_WORD || id.kw >= 0 || id.elem)
        tok_fail_expected(p, &id, "a new identifier after '#fopen'");
    Symbol *old = tok_symbol_find(p, id.text, id.len);
    if (old && old->value.kind != VAL_FILE)
        tok_fail(p, id.pos, "#fopen needs a new identifier: '%.*s' is already declared as %s", id.len, id.text,
                   tok_value_kind_name(old->value.kind));
    SourcePos name_at = tok_peek(p)->pos;
    char *name = p->hooks->string(p);
    Token mode = *tok_next(p);
    if (!tok_is_kw(&mode, KW_read) && !tok_is_kw(&mode, KW_write) && !tok_is_kw(&mode, KW_append))
        tok_fail_expected(p, &mode, "'read', 'write' or 'append' after the file name of '#fopen'");
    if (old) /* POV-Ray lets an open file's identifier be reused */
        close_output(p, old->value.file, id.pos, 1);
    UserFile *f = new_user_file(p, name, name_at);
    if (mode.kw == KW_read) {
        SourceText text;
        if (!read_data(p, name, name_at, &text))
            tok_fail_io(p, name_at, "cannot open '%s' for reading: %s", name, strerror(errno));
        f->reading = 1;
        f->data.name = f->name;
        f->data.buf = text.text;
        f->data.size = text.size;
        f->data.line = f->data.col = 1;
    } else {
        if (p->opts->forbid_writes)
            tok_fail_io(p, name_at, "writing files is not allowed here: '%s'", name);
        f->out = open_for_writing(p, name, mode.kw == KW_append, name_at);
    }
    Value v = { .kind = VAL_FILE, .file = f };
    tok_symbol_define_global(p, id.text, id.len, &v);
}

/* POV-Ray accepts #fclose of an identifier that is no longer (or never
 * was) an open file: a file closed at the end of its data may be closed
 * again by the scene. */
void tok_fclose(Parser *p)
{
    p->no_macro_calls++;
    Token id = *tok_next(p);
    p->no_macro_calls--;
    if (id.type != TK_WORD || id.kw >= 0)
        tok_fail_expected(p, &id, "a file identifier after '#fclose'");
    Symbol *s = id.elem ? NULL : tok_symbol_find(p, id.text, id.len);
    if (!s || s->value.kind != VAL_FILE)
        return;
    UserFile *f = s->value.file;
    close_output(p, f, id.pos, 1);
    tok_symbol_undef(p, id.text, id.len);
    if (!tok_symbol_find(p, id.text, id.len))
        forget_user_file(p, f);
}

/* ---- reading data ---------------------------------------------------------- */

/* The data is written in the scene language's own tokens (POV-Ray reads it
 * with its scene tokeniser: comments, escapes in strings), so the lexer
 * reads it too, from the file's own cursor. */
static void data_next(Parser *p, UserFile *f, Token *t)
{
    tok_lex(p, &f->data, t);
}

/* Puts t back; at the end of the data there is nothing to put back. */
static void data_unread(UserFile *f, const Token *t)
{
    if (t->type == TK_EOF)
        return;
    f->data.offset = (size_t)(t->text - f->data.buf);
    f->data.line = t->pos.line;
    f->data.col = t->pos.column;
}

/* A float, with an optional sign; 0 (nothing read) when none comes next. */
static int data_float(Parser *p, UserFile *f, double *val)
{
    Token t;
    data_next(p, f, &t);
    double sign = 1;
    if (t.type == TK_PUNCT && (t.punct == '-' || t.punct == '+')) {
        sign = t.punct == '-' ? -1 : 1;
        data_next(p, f, &t);
        if (t.type != TK_NUMBER)
            tok_fail(p, t.pos, "expected a number after the sign");
    }
    if (t.type != TK_NUMBER) {
        data_unread(f, &t);
        return 0;
    }
    *val = sign * t.number;
    return 1;
}

/* One value into *v; returns 1 when the data ended (before or just after
 * it): then v is set only if a value was read (*got). */
static int read_value(Parser *p, UserFile *f, Value *v, int *got)
{
    *got = 0;
    Token t;
    data_next(p, f, &t);
    if (t.type == TK_EOF)
        return 1;
    memset(v, 0, sizeof *v);
    if (t.type == TK_NUMBER || (t.type == TK_PUNCT && (t.punct == '-' || t.punct == '+'))) {
        data_unread(f, &t);
        v->kind = VAL_NUMERIC;
        v->terms = 1;
        (void)data_float(p, f, &v->v[0]);
    } else if (t.type == TK_PUNCT && t.punct == '<') {
        int n = 0;
        double x;
        while (data_float(p, f, &x)) {
            Token c;
            if (n == 5)
                tok_fail(p, t.pos, "more than 5 components in this vector");
            v->v[n++] = x;
            data_next(p, f, &c);
            if (c.type == TK_EOF)
                tok_fail(p, t.pos, "this vector has no closing '>'");
            if (!(c.type == TK_PUNCT && c.punct == ','))
                data_unread(f, &c);
        }
        Token close;
        data_next(p, f, &close);
        if (!(close.type == TK_PUNCT && close.punct == '>'))
            tok_fail(p, close.pos, "expected a vector component or '>'");
        if (n < 2)
            tok_fail(p, t.pos, "a vector needs at least 2 components");
        v->kind = VAL_NUMERIC;
        v->terms = n;
    } else if (t.type == TK_STRING) {
        v->kind = VAL_STRING;
        v->string = t.string;
    } else {
        tok_fail(p, t.pos, "expected a float, a vector or a string");
    }
    *got = 1;
    Token after;
    data_next(p, f, &after);
    if (after.type == TK_EOF)
        return 1;
    if (!(after.type == TK_PUNCT && after.punct == ','))
        data_unread(f, &after);
    return 0;
}

/* Where a value read goes: a new global, an existing variable (POV-Ray
 * overwrites a float, vector or string wherever it is visible), or an
 * array element. */
static void store(Parser *p, const Token *t, const Value *v)
{
    if (t->elem) {
        Symbol *e = tok_element_of(t);
        if (e) {
            tok_value_give_up(p, &e->value);
            e->value = *v;
        }
        return;
    }
    tok_symbol_set(p, t->text, t->len, 0, v);
}

void tok_read(Parser *p)
{
    tok_expect_punct(p, '(', "'#read'");
    Token file_tok = *tok_peek(p);
    UserFile *f = file_of(p, "#read", 1);
    int ended = 0;
    if (!tok_is_punct(tok_next(p), ','))
        tok_unget(p);
    for (;;) {
        Token *t;
        p->no_macro_calls++;
        t = tok_next(p);
        p->no_macro_calls--;
        if (tok_is_punct(t, ')'))
            break;
        if (t->type != TK_WORD || t->kw >= 0)
            tok_fail_expected(p, t, "a variable or ')' in '#read'");
        Token var = *t;
        if (!var.elem) {
            Symbol *old = tok_symbol_find(p, var.text, var.len);
            if (old && old->value.kind != VAL_NUMERIC && old->value.kind != VAL_STRING)
                tok_fail(p, var.pos, "'#read' cannot store into '%.*s', which is %s", var.len, var.text,
                           tok_value_kind_name(old->value.kind));
        }
        if (!ended) {
            Value v;
            int got;
            ended = read_value(p, f, &v, &got);
            if (got)
                store(p, &var, &v);
        }
        t = tok_next(p);
        if (!tok_is_punct(t, ','))
            tok_unget(p);
    }
    if (ended) { /* POV-Ray closes the file and forgets its identifier */
        tok_symbol_undef(p, file_tok.text, file_tok.len);
        if (!tok_symbol_find(p, file_tok.text, file_tok.len))
            forget_user_file(p, f);
    }
}

/* ---- writing ------------------------------------------------------------- */

/* uint8 ... sint32le: the following values as binary integers, rounded and
 * clamped to the type's range. */
static int binary_type(int kw, long *lo, long *hi, int *bytes, int *big_endian)
{
    *big_endian = 0;
    switch (kw) {
    case KW_uint8: *lo = 0; *hi = 255; *bytes = 1; return 1;
    case KW_sint8: *lo = -128; *hi = 127; *bytes = 1; return 1;
    case KW_uint16be: *big_endian = 1; /* fall through */
    case KW_uint16le: *lo = 0; *hi = 65535; *bytes = 2; return 1;
    case KW_sint16be: *big_endian = 1; /* fall through */
    case KW_sint16le: *lo = -32768; *hi = 32767; *bytes = 2; return 1;
    case KW_sint32be: *big_endian = 1; /* fall through */
    case KW_sint32le: *lo = -2147483647L - 1; *hi = 2147483647L; *bytes = 4; return 1;
    default: return 0;
    }
}

static void write_binary(Parser *p, UserFile *f, long lo, long hi, int bytes, int big_endian)
{
    for (;;) {
        Token *t = tok_peek(p);
        if (tok_is_punct(t, ',') || tok_is_punct(t, ')'))
            return;
        if (!p->hooks->starts_expression(p, t))
            tok_fail_expected(p, tok_next(p), "a number after the binary type in '#write'");
        Token at = *tok_peek(p);
        double e[5] = { 0 };
        int terms = 1;
        p->hooks->expression(p, e, &terms);
        for (int i = 0; i < terms; i++) {
            if (isnan(e[i]))
                tok_fail(p, at.pos, "#write cannot write nan as a binary integer");
            long val = int_clamped(floor(e[i] + 0.5), (int)lo, (int)hi);
            unsigned long u = (unsigned long)val;
            for (int j = 0; j < bytes; j++) {
                int shift = (big_endian ? bytes - 1 - j : j) * 8;
                fputc((int)((u >> shift) & 0xff), f->out);
            }
        }
    }
}

void tok_write(Parser *p)
{
    tok_expect_punct(p, '(', "'#write'");
    UserFile *f = file_of(p, "#write", 0);
    for (;;) {
        Token *t = tok_peek(p);
        if (tok_is_punct(t, ')')) {
            tok_next(p);
            break;
        }
        if (tok_is_punct(t, ',')) {
            tok_next(p);
            continue;
        }
        long lo, hi;
        int bytes, big_endian;
        if (t->type == TK_WORD && binary_type(t->kw, &lo, &hi, &bytes, &big_endian)) {
            tok_next(p);
            write_binary(p, f, lo, hi, bytes, big_endian);
        } else if (p->hooks->starts_string(p, t)) {
            fputs(p->hooks->string(p), f->out);
        } else if (p->hooks->starts_expression(p, t)) {
            double e[5] = { 0 };
            int terms = 1;
            p->hooks->expression(p, e, &terms);
            if (terms == 1) {
                fprintf(f->out, "%g", e[0]);
            } else {
                fputc('<', f->out);
                for (int i = 0; i < terms; i++)
                    fprintf(f->out, i ? ",%g" : "%g", e[i]);
                fputs("> ", f->out);
            }
        } else {
            tok_fail_expected(p, tok_next(p), "a string or an expression in '#write'");
        }
    }
}
