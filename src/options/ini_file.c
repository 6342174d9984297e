/* Reading POV-Ray INI files (ini_file.h). */
#include "ini_file.h"

#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

/* An INI file is a few lines of settings; anything bigger is a mistake
 * (a scene or an image named by accident), refused before it is read. */
#define INI_MAX_BYTES (1 << 20)

int ini_spec_is_ini(const char *word)
{
    size_t n = strlen(word);
    const char *open = n > 0 && word[n - 1] == ']' ? strrchr(word, '[') : NULL;
    size_t end = open ? (size_t)(open - word) : n;
    return end >= 4 && strncasecmp(word + end - 4, ".ini", 4) == 0;
}

void ini_file_free(IniFile *f)
{
    for (int i = 0; i < f->n; i++) {
        free(f->entries[i].key);
        free(f->entries[i].value);
    }
    free(f->entries);
    free(f->path);
    free(f->section);
    memset(f, 0, sizeof *f);
}

typedef struct {
    const char *s, *end;
    int line;
    const char *line_start;
    const char *entry; /* where the entry being read began */
    IniFile *f;
    char *err;
    int errlen;
} Reader;

static int fail(Reader *r, const char *fmt, const char *what)
{
    char msg[256];
    snprintf(msg, sizeof msg, fmt, what);
    snprintf(r->err, (size_t)r->errlen, "%s:%d:%d: %s", r->f->path, r->line, (int)(r->entry - r->line_start) + 1, msg);
    return -1;
}

static int add(Reader *r, IniKind kind, const char *key, size_t keylen, const char *value, size_t valuelen)
{
    IniFile *f = r->f;
    if (f->n == f->cap) {
        int cap = f->cap ? f->cap * 2 : 16;
        IniEntry *e = realloc(f->entries, sizeof *e * (size_t)cap);
        if (!e)
            return fail(r, "%s", "out of memory");
        f->entries = e;
        f->cap = cap;
    }
    IniEntry *e = &f->entries[f->n];
    e->kind = kind;
    e->line = r->line;
    e->column = (int)(r->entry - r->line_start) + 1;
    e->key = strndup(key, keylen);
    e->value = value ? strndup(value, valuelen) : NULL;
    if (!e->key || (value && !e->value)) {
        free(e->key);
        free(e->value);
        return fail(r, "%s", "out of memory");
    }
    f->n++;
    return 0;
}

static int at_end(const Reader *r)
{
    return r->s >= r->end;
}

static void skip_blanks(Reader *r)
{
    while (!at_end(r) && (*r->s == ' ' || *r->s == '\t'))
        r->s++;
}

/* To the end of the line, its newline (\n, \r or \r\n) included. */
static void skip_line(Reader *r)
{
    while (!at_end(r) && *r->s != '\n' && *r->s != '\r')
        r->s++;
    if (!at_end(r)) {
        if (*r->s == '\r' && r->s + 1 < r->end && r->s[1] == '\n')
            r->s++;
        r->s++;
        r->line++;
        r->line_start = r->entry = r->s;
    }
}

/* A word's characters: not a space, nor one of the characters that end
 * one in POV-Ray's reader. */
static int word_char(char c)
{
    return !isspace((unsigned char)c) && c != ',' && c != ';' && c != '#' && c != '"' && c != '\'' && c != '[' &&
           c != ']' && c != '=';
}

/* A value's characters: POV-Ray ends an unquoted value at a space, a
 * comma, a comment or a quote; '=', '[' and ']' belong to it (Declare=X=1). */
static int value_char(char c)
{
    return !isspace((unsigned char)c) && c != ',' && c != ';' && c != '#' && c != '"' && c != '\'';
}

/* A quoted string from its opening quote, on one line. */
static int quoted(Reader *r, const char **start, size_t *len)
{
    char q = *r->s++;
    *start = r->s;
    while (!at_end(r) && *r->s != q && *r->s != '\n' && *r->s != '\r')
        r->s++;
    if (at_end(r) || *r->s != q)
        return fail(r, "a string opened with %s is not closed on its line", q == '"' ? "\"" : "'");
    *len = (size_t)(r->s - *start);
    r->s++;
    return 0;
}

/* KEY=VALUE[, VALUE ...] from the key's first character. */
static int option(Reader *r)
{
    const char *key = r->s;
    while (!at_end(r) && word_char(*r->s))
        r->s++;
    size_t keylen = (size_t)(r->s - key);
    if (keylen == 0)
        return fail(r, "%s", "expected KEY=VALUE, a +/- switch, a [section] or a comment");
    skip_blanks(r);
    if (at_end(r) || *r->s != '=') {
        /* Not an option: a word, the scene file. */
        return add(r, INI_WORD, key, keylen, NULL, 0);
    }
    r->s++;
    for (;;) {
        skip_blanks(r);
        const char *value = r->s;
        size_t len;
        int was_quoted = !at_end(r) && (*r->s == '"' || *r->s == '\'');
        if (was_quoted) {
            if (quoted(r, &value, &len))
                return -1;
        } else {
            while (!at_end(r) && value_char(*r->s))
                r->s++;
            len = (size_t)(r->s - value);
        }
        if (len == 0 && !was_quoted) {
            char k[80];
            snprintf(k, sizeof k, "%.*s", (int)(keylen < 64 ? keylen : 64), key);
            return fail(r, "%s= has no value", k);
        }
        if (add(r, INI_OPTION, key, keylen, value, len))
            return -1;
        skip_blanks(r);
        if (at_end(r) || *r->s != ',')
            break;
        r->s++;
    }
    /* One option a line: POV-Ray ignores the rest of it. */
    skip_line(r);
    return 0;
}

/* A +/- switch, its value quoted or not ("+L\"my dir\"" is +Lmy dir). */
static int switch_entry(Reader *r)
{
    const char *start = r->s++;
    while (!at_end(r) && word_char(*r->s))
        r->s++;
    size_t len = (size_t)(r->s - start);
    if (len == 1)
        return fail(r, "%s", "a switch sign without a switch");
    if (!at_end(r) && (*r->s == '"' || *r->s == '\'')) {
        const char *value;
        size_t vlen;
        if (quoted(r, &value, &vlen))
            return -1;
        char *joined = malloc(len + vlen + 1);
        if (!joined)
            return fail(r, "%s", "out of memory");
        memcpy(joined, start, len);
        memcpy(joined + len, value, vlen);
        joined[len + vlen] = '\0';
        int status = add(r, INI_SWITCH, joined, len + vlen, NULL, 0);
        free(joined);
        return status;
    }
    return add(r, INI_SWITCH, start, len, NULL, 0);
}

static int parse(Reader *r)
{
    int applies = 1; /* lines before any [section] */
    for (;;) {
        /* Blank space and newlines. */
        while (!at_end(r) && isspace((unsigned char)*r->s)) {
            if (*r->s == '\n' || *r->s == '\r') {
                skip_line(r);
                continue;
            }
            r->s++;
        }
        if (at_end(r))
            return 0;
        r->entry = r->s;
        char c = *r->s;
        if (c == '[') {
            const char *name = ++r->s;
            while (!at_end(r) && *r->s != ']' && *r->s != '\n' && *r->s != '\r')
                r->s++;
            if (at_end(r) || *r->s != ']')
                return fail(r, "%s", "a [section] header without its ']'");
            size_t len = (size_t)(r->s - name);
            r->s++;
            applies = r->f->section && strlen(r->f->section) == len && strncasecmp(name, r->f->section, len) == 0;
            continue;
        }
        if (!applies || c == ';' || c == '#') {
            skip_line(r);
            continue;
        }
        if (c == '\0')
            return fail(r, "%s", "a NUL byte: not a text file");
        int status = c == '+' || c == '-' ? switch_entry(r) : option(r);
        if (status)
            return -1;
    }
}

int ini_file_read(IniFile *f, const char *spec, char *err, int errlen)
{
    memset(f, 0, sizeof *f);
    size_t n = strlen(spec);
    const char *bracket = n > 0 && spec[n - 1] == ']' ? strrchr(spec, '[') : NULL;
    f->path = strndup(spec, bracket ? (size_t)(bracket - spec) : n);
    if (bracket)
        f->section = strndup(bracket + 1, n - (size_t)(bracket - spec) - 2);
    if (!f->path || (bracket && !f->section)) {
        snprintf(err, (size_t)errlen, "out of memory");
        return -1;
    }
    /* Opened without waiting (a FIFO with no writer would block the open
     * for ever), then refused unless it is a regular file. */
    int fd = open(f->path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        snprintf(err, (size_t)errlen, "cannot open INI file '%s': %s", f->path, strerror(errno));
        return -1;
    }
    struct stat st;
    int stat_failed = fstat(fd, &st) != 0;
    if (stat_failed || !S_ISREG(st.st_mode)) {
        snprintf(err, (size_t)errlen, "cannot read INI file '%s': %s", f->path,
                 stat_failed           ? strerror(errno)
                 : S_ISDIR(st.st_mode) ? "it is a folder"
                                       : "not a regular file");
        close(fd);
        return -1;
    }
    FILE *fp = fdopen(fd, "rb");
    if (!fp) {
        snprintf(err, (size_t)errlen, "cannot open INI file '%s': %s", f->path, strerror(errno));
        close(fd);
        return -1;
    }
    char *text = malloc(INI_MAX_BYTES + 1);
    size_t got = text ? fread(text, 1, INI_MAX_BYTES + 1, fp) : 0;
    int bad = ferror(fp);
    fclose(fp);
    if (!text || bad || got > INI_MAX_BYTES) {
        snprintf(err, (size_t)errlen, !text ? "out of memory" : bad ? "cannot read INI file '%s'"
                                                                   : "'%s' is too big for an INI file (over 1 MiB)",
                 f->path);
        free(text);
        return -1;
    }
    f->bytes = got;
    Reader r = { text, text + got, 1, text, text, f, err, errlen };
    int status = parse(&r);
    free(text);
    return status;
}
