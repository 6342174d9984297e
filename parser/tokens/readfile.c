/* Scene, include and #fopen data files, read whole into the temporary
 * arena (so that tokens point into them and #while can jump back).
 *
 * Only regular files are read: a directory, a device (/dev/zero), a FIFO
 * or a socket is refused at once, before a byte is read -- opened without
 * blocking, so that a FIFO with no writer does not hang the parse. A file
 * is read in pieces and the reading stops at the first byte no scene holds
 * (a zero byte: a binary file), with its line and column; its size counts
 * in the parse's memory budget before it is read. A file read before by
 * the same path, unchanged since (device, inode, size, modification time),
 * is not read again: an #include inside a loop costs its text once in
 * memory, and its tokens count as text read again. */
#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "tokens.h"

typedef struct {
    const char *path; /* as opened (temporary arena) */
    dev_t dev;
    ino_t ino;
    off_t size;
    struct timespec mtime;
    SourceText text;
} ReadFile;

static const char *kind_of(mode_t mode)
{
    if (S_ISDIR(mode))
        return "a directory";
    if (S_ISCHR(mode) || S_ISBLK(mode))
        return "a device";
    if (S_ISFIFO(mode))
        return "a FIFO";
    if (S_ISSOCK(mode))
        return "a socket";
    return "not a regular file";
}

/* The line and column of offset `at` in text, for a message. */
static SourcePos position_in(const char *name, const char *text, size_t at)
{
    SourcePos pos = { name, 1, 1 };
    for (size_t i = 0; i < at; i++) {
        if (text[i] == '\n') {
            pos.line++;
            pos.column = 1;
        } else {
            pos.column++;
        }
    }
    return pos;
}

static const ReadFile *already_read(Parser *p, const char *path, const struct stat *st)
{
    const ReadFile *files = p->read_files.data;
    for (int i = 0; i < p->read_files.n; i++) {
        const ReadFile *r = &files[i];
        if (r->dev == st->st_dev && r->ino == st->st_ino && r->size == st->st_size &&
            r->mtime.tv_sec == st->st_mtim.tv_sec && r->mtime.tv_nsec == st->st_mtim.tv_nsec &&
            strcmp(r->path, path) == 0)
            return r;
    }
    return NULL;
}

/* Reads the open regular file fd whole (and closes it). */
static void read_whole(Parser *p, int fd, const struct stat *st, const char *path, SourcePos at, SourceText *out)
{
    /* The size is a hint (a /proc file says 0): the text grows as read. */
    size_t cap = st->st_size > 0 ? (size_t)st->st_size + 1 : 4096, n = 0;
    if ((uintmax_t)st->st_size >= (uintmax_t)SIZE_MAX / 2) {
        close(fd);
        tok_limits_over_budget(p, at);
    }
    char *buf = arena_alloc_uninit(p->temp, cap);
    for (;;) {
        if (!buf) {
            close(fd);
            tok_fail_memory(p, at);
        }
        char probe[4096];
        char *into = buf + n;
        size_t want = cap - 1 - n;
        if (want == 0) { /* as big as the size said: is there more? */
            into = probe;
            want = sizeof probe;
        }
        if (want > ((size_t)1 << 20))
            want = (size_t)1 << 20;
        ssize_t got = read(fd, into, want);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0) {
            int e = errno;
            close(fd);
            tok_fail_io(p, at, "cannot read '%s': %s", path, strerror(e));
        }
        if (got == 0)
            break;
        if (into == probe) { /* it grew (a /proc file): twice the room */
            size_t more = cap * 2 > n + (size_t)got + 1 ? cap * 2 : n + (size_t)got + 1;
            char *bigger = cap > SIZE_MAX / 4 ? NULL : arena_alloc_uninit(p->temp, more);
            if (!bigger) {
                close(fd);
                tok_fail_memory(p, at);
            }
            memcpy(bigger, buf, n);
            memcpy(bigger + n, probe, (size_t)got);
            buf = bigger;
            cap = more;
        }
        const char *zero = memchr(buf + n, '\0', (size_t)got);
        if (zero) {
            close(fd);
            tok_fail(p, position_in(path, buf, (size_t)(zero - buf)),
                       "a zero byte, which no scene text holds: '%s' is not a scene file", path);
        }
        n += (size_t)got;
    }
    close(fd);
    buf[n] = '\0';
    out->text = buf;
    out->size = n;
}

void tok_source_files_init(Parser *p)
{
    tok_tvec_init(&p->read_files, sizeof(ReadFile));
}

int tok_source_read(Parser *p, const char *path, SourcePos at, SourceText *out)
{
    /* O_NONBLOCK: opening a FIFO must not wait for a writer */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return 0;
    struct stat st;
    if (fstat(fd, &st) != 0) {
        int e = errno;
        close(fd);
        errno = e;
        return 0;
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        tok_fail_io(p, at, "'%s' is %s, not a file to read", path, kind_of(st.st_mode));
    }
    const ReadFile *seen = already_read(p, path, &st);
    if (seen) {
        close(fd);
        *out = seen->text;
        out->again = 1;
        return 1;
    }
    int flags = fcntl(fd, F_GETFL);
    if (flags >= 0)
        (void)fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    if ((uintmax_t)st.st_size >= (uintmax_t)tok_limits_memory_left(p)) {
        close(fd);
        tok_limits_over_budget(p, at);
    }
    SourceText text;
    memset(&text, 0, sizeof text);
    read_whole(p, fd, &st, path, at, &text);
    /* positions name it (escaped) as long as the scene lives */
    const char *real = tok_temp_strndup(p, path, strlen(path));
    text.name = tok_display_name(p, path);
    text.dir = tok_dir_of(p, real);
    ReadFile *r = tok_tvec_push(p, &p->read_files);
    r->path = real;
    r->dev = st.st_dev;
    r->ino = st.st_ino;
    r->size = st.st_size;
    r->mtime = st.st_mtim;
    r->text = text;
    *out = text;
    return 1;
}

int tok_source_read_in(Parser *p, const char *dir, const char *name, SourcePos at, SourceText *out)
{
    char joined[4096];
    int n;
    if (strcmp(dir, ".") == 0)
        n = snprintf(joined, sizeof joined, "%s", name);
    else
        n = snprintf(joined, sizeof joined, "%s%s%s", dir, dir[0] && dir[strlen(dir) - 1] == '/' ? "" : "/", name);
    if (n < 0 || (size_t)n >= sizeof joined) {
        errno = ENAMETOOLONG;
        return 0;
    }
    return tok_source_read(p, joined, at, out);
}
