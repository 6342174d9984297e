/* Child processes run to completion, one at a time, for `hstrace vs-povray`:
 * a program started in a folder with its output captured in a file, timed by
 * the parent (wall clock from fork to reaping, and the child's CPU time),
 * and interruptible.
 *
 * While a ProcessGuard is held, SIGCHLD and the termination signals SIGINT,
 * SIGTERM and SIGHUP (those not ignored when the guard began) are blocked
 * and waited for with sigwaitinfo(): a child's exit wakes the parent at once,
 * so the timing is exact, and a termination signal is seen as soon as it
 * arrives, so the caller can stop the child and remove its files before
 * dying by that signal (process_die). No signal handler, no global state. */
#ifndef HST_PROCESS_H
#define HST_PROCESS_H

#include <signal.h>

typedef struct {
    sigset_t terminate;      /* the termination signals watched */
    sigset_t waited;         /* terminate + SIGCHLD */
    sigset_t old_mask;
    struct sigaction old_chld;
} ProcessGuard;

typedef struct {
    int started;        /* 0: the program could not be executed (start_errno says why) */
    int start_errno;
    int exited;         /* 1: exited with `status`; 0: killed by signal `status` */
    int status;
    int interrupted;    /* a termination signal the parent received while waiting (the
                         * child was then terminated and reaped); 0 when none */
    double wall_seconds; /* from just before fork() to the child reaped */
    double cpu_seconds;  /* the child's user + system CPU time */
} ProcessResult;

/* Blocks the signals described above and makes sure SIGCHLD is not ignored
 * (an ignored SIGCHLD would reap children before waitpid). Returns 0, or -1
 * with errno set. */
int process_guard_begin(ProcessGuard *g);
/* Restores the signal mask and SIGCHLD's action. A termination signal that
 * arrived outside process_run is still pending and is delivered now. */
void process_guard_end(ProcessGuard *g);

/* A termination signal pending (arrived while no child ran), or 0. */
int process_pending_signal(const ProcessGuard *g);

/* Runs argv (argv[0] the name the program is given, `path` the file
 * executed: with a '/' as it is, otherwise searched in PATH) in folder `dir`
 * (NULL: the current one), stdin from /dev/null, stdout and stderr into the
 * file `log` (created or truncated), and waits for it. Returns 0 with *r
 * filled (look at r->started, r->exited, r->status, r->interrupted), or -1
 * with errno set when no child could be made. */
int process_run(const ProcessGuard *g, const char *path, char *const argv[], const char *dir, const char *log,
                ProcessResult *r);

/* Ends the process by signal sig, as if it had not been blocked: restores
 * the guard and sig's default action, then raises it. Does not return. */
void process_die(ProcessGuard *g, int sig);

#endif
