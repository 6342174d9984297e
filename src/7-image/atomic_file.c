/* Atomic file replacement through a temporary file and rename(). */
#include "atomic_file.h"

#include <errno.h>
#include <fcntl.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

/* Longest base name copied into the temporary's name, so that ".NAME.XXXXXX"
 * stays within NAME_MAX (255 on the usual file systems) for long targets. */
#define TMP_BASE_MAX 200

static atomic_uint tmp_counter;

/* Six characters from a 64-bit mix of time, process id and a counter. The
 * name only needs to be unlikely to collide; O_EXCL makes it safe. */
static void random_suffix(char out[7], unsigned attempt)
{
    static const char alphabet[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
    struct timespec ts;
    uint64_t x;

    clock_gettime(CLOCK_REALTIME, &ts);
    x = (uint64_t)ts.tv_nsec ^ ((uint64_t)ts.tv_sec << 30) ^
        ((uint64_t)getpid() << 17) ^
        ((uint64_t)atomic_fetch_add(&tmp_counter, 1u) * 0x9E3779B97F4A7C15ull) ^ attempt;
    for (int i = 0; i < 6; i++) {
        /* splitmix64 step per character */
        x += 0x9E3779B97F4A7C15ull;
        uint64_t z = x;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        z ^= z >> 31;
        out[i] = alphabet[z % (sizeof alphabet - 1)];
    }
    out[6] = '\0';
}

static void release(AtomicFile *af)
{
    free(af->tmp);
    free(af->target);
    af->tmp = NULL;
    af->target = NULL;
    af->fd = -1;
}

int atomic_file_open(AtomicFile *af, const char *target)
{
    const char *slash, *base;
    size_t dirlen, baselen, len;
    struct stat st;
    int have_mode;

    af->fd = -1;
    af->tmp = NULL;
    af->target = NULL;
    if (target == NULL || target[0] == '\0') {
        errno = ENOENT;
        return -1;
    }
    slash = strrchr(target, '/');
    base = slash ? slash + 1 : target;
    dirlen = (size_t)(base - target);
    baselen = strlen(base);
    if (baselen == 0) { /* "dir/" names a folder, not a file */
        errno = EISDIR;
        return -1;
    }
    if (baselen > TMP_BASE_MAX)
        baselen = TMP_BASE_MAX;

    af->target = strdup(target);
    len = dirlen + 1 + baselen + 1 + 6 + 1;
    af->tmp = malloc(len);
    if (af->target == NULL || af->tmp == NULL) {
        release(af);
        errno = ENOMEM;
        return -1;
    }

    /* Keep an existing target's permission bits; otherwise open() applies
     * the umask to 0666 as for any newly created file. */
    have_mode = stat(target, &st) == 0 && S_ISREG(st.st_mode);

    for (unsigned attempt = 0; attempt < 100; attempt++) {
        char suffix[7];
        random_suffix(suffix, attempt);
        snprintf(af->tmp, len, "%.*s.%.*s.%s", (int)dirlen, target, (int)baselen, base, suffix);
        af->fd = open(af->tmp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (af->fd >= 0)
            break;
        if (errno != EEXIST) {
            int e = errno;
            release(af);
            errno = e;
            return -1;
        }
    }
    if (af->fd < 0) {
        release(af);
        errno = EEXIST;
        return -1;
    }
    if (have_mode)
        (void)fchmod(af->fd, st.st_mode & 07777);
    return 0;
}

int atomic_file_commit(AtomicFile *af)
{
    int e;

    if (af->tmp == NULL) {
        errno = EINVAL;
        return -1;
    }
    if (af->fd >= 0) {
        int rc = close(af->fd);
        af->fd = -1;
        if (rc != 0) {
            atomic_file_abort(af);
            return -1;
        }
    }
    if (rename(af->tmp, af->target) != 0) {
        e = errno;
        atomic_file_abort(af);
        errno = e;
        return -1;
    }
    release(af);
    return 0;
}

void atomic_file_abort(AtomicFile *af)
{
    int e = errno;

    if (af->fd >= 0)
        close(af->fd);
    if (af->tmp != NULL)
        unlink(af->tmp);
    release(af);
    errno = e;
}
