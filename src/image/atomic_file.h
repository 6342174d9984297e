/* Atomic file replacement: write everything to a fresh temporary file in the
 * target's folder (".NAME.XXXXXX"), then rename() it over the target. Readers
 * of the target see either the old complete file or the new complete file,
 * never a truncated one; a failed or interrupted write leaves the target as it
 * was. */
#ifndef HST_ATOMIC_FILE_H
#define HST_ATOMIC_FILE_H

typedef struct {
    int fd;       /* open for writing, or -1 once closed */
    char *tmp;    /* path of the temporary file (malloc'd), NULL when none */
    char *target; /* copy of the final path (malloc'd) */
    int slot;     /* the signal handlers' record of tmp (atomic_file.c), or -1 */
} AtomicFile;

/* Creates the temporary file beside `target` (mode 0666 filtered by the
 * umask, or the existing target's permission bits). Until it is committed
 * or aborted, SIGINT, SIGTERM and SIGHUP remove it before they end the
 * process. A target that exists read-only is refused (EACCES). Returns 0,
 * or -1 with errno set and nothing left on disk. */
int atomic_file_open(AtomicFile *af, const char *target);

/* Closes the descriptor if it is still open (a writer that wrapped it in a
 * FILE and fclose'd it must set af->fd = -1 first) and renames the temporary
 * over the target. Returns 0, or -1 with errno set after removing the
 * temporary. Either way the AtomicFile is released. */
int atomic_file_commit(AtomicFile *af);

/* Closes and removes the temporary, keeping errno; the target is untouched.
 * Safe to call on a released AtomicFile. */
void atomic_file_abort(AtomicFile *af);

#endif
