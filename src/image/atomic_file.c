/* Atomic file replacement through a temporary file and rename(). */
#include "atomic_file.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
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

/* ---- the temporary removed on SIGINT, SIGTERM and SIGHUP ------------------
 * An interrupted write would leave ".NAME.XXXXXX" beside the output. While
 * a temporary exists, its path is in a slot the handler can read without
 * locks or allocation (a fixed array, marked in use by a sig_atomic_t after
 * the path is written); the handler unlinks every one in use, puts back the
 * signal's former action and raises the signal again, so the process ends
 * as the signal would have ended it (or the former handler runs). Only
 * unlink, sigaction and raise are called there, all async-signal-safe.
 * Handlers are installed while a temporary exists and put back after; a
 * signal its process ignores stays ignored. Opened and committed from one
 * thread at a time (hstrace writes its files from the main thread). */
#define TMP_SLOTS 4

static char tmp_slot_path[TMP_SLOTS][PATH_MAX];
static volatile sig_atomic_t tmp_slot_used[TMP_SLOTS];
static const int cleanup_signals[] = { SIGINT, SIGTERM, SIGHUP };
#define NSIGNALS ((int)(sizeof cleanup_signals / sizeof cleanup_signals[0]))
static struct sigaction former[NSIGNALS];
static volatile sig_atomic_t installed[NSIGNALS];
static int slots_in_use;

static void on_signal(int sig)
{
    int e = errno;
    for (int i = 0; i < TMP_SLOTS; i++)
        if (tmp_slot_used[i])
            (void)unlink(tmp_slot_path[i]);
    for (int k = 0; k < NSIGNALS; k++)
        if (cleanup_signals[k] == sig && installed[k]) {
            (void)sigaction(sig, &former[k], NULL);
            installed[k] = 0;
        }
    errno = e;
    /* blocked while this handler runs: delivered, with the former action, once it returns */
    (void)raise(sig);
}

static void install_handlers(void)
{
    for (int k = 0; k < NSIGNALS; k++) {
        struct sigaction now, act;
        if (sigaction(cleanup_signals[k], NULL, &now) != 0 || now.sa_handler == SIG_IGN)
            continue; /* ignored (nohup): it ends nothing, so nothing to clean */
        memset(&act, 0, sizeof act);
        act.sa_handler = on_signal;
        sigemptyset(&act.sa_mask);
        for (int j = 0; j < NSIGNALS; j++) /* one handler at a time */
            sigaddset(&act.sa_mask, cleanup_signals[j]);
        former[k] = now;
        if (sigaction(cleanup_signals[k], &act, NULL) == 0)
            installed[k] = 1;
    }
}

static void remove_handlers(void)
{
    for (int k = 0; k < NSIGNALS; k++)
        if (installed[k]) {
            installed[k] = 0;
            (void)sigaction(cleanup_signals[k], &former[k], NULL);
        }
}

/* The slot now guarding path, or -1 when none is free (or the path too
 * long): that temporary is then left to atomic_file_abort alone. */
static int guard(const char *path)
{
    size_t n = strlen(path);
    if (n >= PATH_MAX)
        return -1;
    for (int i = 0; i < TMP_SLOTS; i++)
        if (!tmp_slot_used[i]) {
            memcpy(tmp_slot_path[i], path, n + 1);
            atomic_signal_fence(memory_order_seq_cst); /* the path before the mark */
            tmp_slot_used[i] = 1;
            if (slots_in_use++ == 0)
                install_handlers();
            return i;
        }
    return -1;
}

static void unguard(AtomicFile *af)
{
    if (af->slot < 0)
        return;
    tmp_slot_used[af->slot] = 0;
    atomic_signal_fence(memory_order_seq_cst);
    af->slot = -1;
    if (--slots_in_use == 0)
        remove_handlers();
}

static void release(AtomicFile *af)
{
    unguard(af);
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
    af->slot = -1;
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
    /* A read-only file is not replaced, though its folder would let a
     * rename do it: POV-Ray, which opens the file itself, is refused, and
     * so is a user who asked for it to be kept. No write bit at all counts
     * too, for root, whom access() lets write anything. */
    if (have_mode && (access(target, W_OK) != 0 || (st.st_mode & 0222) == 0)) {
        release(af);
        errno = EACCES;
        return -1;
    }

    for (unsigned attempt = 0; attempt < 100; attempt++) {
        char suffix[7];
        random_suffix(suffix, attempt);
        snprintf(af->tmp, len, "%.*s.%.*s.%s", (int)dirlen, target, (int)baselen, base, suffix);
        /* Guarded before it exists: a signal between its creation and its
         * guard would leave it (seen under load, with the signal sent as
         * soon as the file showed). A name that turns out to be another's
         * (EEXIST) is unguarded at once. */
        af->slot = guard(af->tmp);
        af->fd = open(af->tmp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (af->fd >= 0)
            break;
        unguard(af);
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
    /* A signal from here on unlinks a name that is gone or renamed away:
     * harmless. */
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
