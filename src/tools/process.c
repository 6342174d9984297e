/* Child processes: fork, exec, wait with sigwaitinfo, time. */
#include "process.h"

#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include "clock.h"

static const int termination_signals[] = {SIGINT, SIGTERM, SIGHUP};
#define NTERMINATION ((int)(sizeof termination_signals / sizeof termination_signals[0]))

int process_guard_begin(ProcessGuard *g)
{
    sigemptyset(&g->terminate);
    for (int k = 0; k < NTERMINATION; k++) {
        struct sigaction sa;
        /* A signal ignored when we started (a shell's background job ignores
         * SIGINT) stays ignored: the user asked for that. */
        if (sigaction(termination_signals[k], NULL, &sa) == 0 && sa.sa_handler != SIG_IGN)
            sigaddset(&g->terminate, termination_signals[k]);
    }
    g->waited = g->terminate;
    sigaddset(&g->waited, SIGCHLD);
    struct sigaction dfl;
    memset(&dfl, 0, sizeof dfl);
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    if (sigaction(SIGCHLD, &dfl, &g->old_chld) != 0)
        return -1;
    if (sigprocmask(SIG_BLOCK, &g->waited, &g->old_mask) != 0) {
        int e = errno;
        sigaction(SIGCHLD, &g->old_chld, NULL);
        errno = e;
        return -1;
    }
    return 0;
}

void process_guard_end(ProcessGuard *g)
{
    sigaction(SIGCHLD, &g->old_chld, NULL);
    sigprocmask(SIG_SETMASK, &g->old_mask, NULL);
}

int process_pending_signal(const ProcessGuard *g)
{
    sigset_t pending;
    if (sigpending(&pending) != 0)
        return 0;
    for (int k = 0; k < NTERMINATION; k++)
        if (sigismember(&g->terminate, termination_signals[k]) && sigismember(&pending, termination_signals[k]))
            return termination_signals[k];
    return 0;
}

void process_die(ProcessGuard *g, int sig)
{
    struct sigaction dfl;
    memset(&dfl, 0, sizeof dfl);
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    sigaction(sig, &dfl, NULL);
    sigaction(SIGCHLD, &g->old_chld, NULL);
    sigset_t mask = g->old_mask;
    sigdelset(&mask, sig);
    sigprocmask(SIG_SETMASK, &mask, NULL); /* delivers sig if it is still pending */
    raise(sig);
    _exit(128 + sig); /* only if sig could not end the process */
}

static double cpu_of_children(void)
{
    struct rusage ru;
    if (getrusage(RUSAGE_CHILDREN, &ru) != 0)
        return 0.0;
    return (double)ru.ru_utime.tv_sec + ru.ru_utime.tv_usec * 1e-6 + (double)ru.ru_stime.tv_sec +
           ru.ru_stime.tv_usec * 1e-6;
}

static int set_cloexec(int fd)
{
    int flags = fcntl(fd, F_GETFD);
    return flags < 0 ? -1 : fcntl(fd, F_SETFD, flags | FD_CLOEXEC);
}

/* In the child after fork(): only async-signal-safe calls until exec. */
static void child(const ProcessGuard *g, const char *path, char *const argv[], const char *dir, int null_fd,
                  int log_fd, int report_fd)
{
    int e;
    sigaction(SIGCHLD, &g->old_chld, NULL);
    sigprocmask(SIG_SETMASK, &g->old_mask, NULL);
    if ((dir && chdir(dir) != 0) || dup2(null_fd, STDIN_FILENO) < 0 || dup2(log_fd, STDOUT_FILENO) < 0 ||
        dup2(log_fd, STDERR_FILENO) < 0) {
        e = errno;
    } else {
        if (strchr(path, '/'))
            execv(path, argv);
        else
            execvp(path, argv);
        e = errno;
    }
    ssize_t unused = write(report_fd, &e, sizeof e);
    (void)unused;
    _exit(127);
}

int process_run(const ProcessGuard *g, const char *path, char *const argv[], const char *dir, const char *log,
                ProcessResult *r)
{
    memset(r, 0, sizeof *r);
    if ((r->interrupted = process_pending_signal(g)) != 0)
        return 0;
    int null_fd = open("/dev/null", O_RDONLY | O_CLOEXEC);
    if (null_fd < 0)
        return -1;
    int log_fd = open(log, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (log_fd < 0) {
        int e = errno;
        close(null_fd);
        errno = e;
        return -1;
    }
    /* exec's failure comes back through a pipe that exec itself closes. */
    int report[2];
    if (pipe(report) != 0 || set_cloexec(report[0]) != 0 || set_cloexec(report[1]) != 0) {
        int e = errno;
        close(null_fd);
        close(log_fd);
        errno = e;
        return -1;
    }
    double cpu0 = cpu_of_children();
    double t0 = clock_wall();
    pid_t pid = fork();
    if (pid == 0)
        child(g, path, argv, dir, null_fd, log_fd, report[1]);
    int fork_errno = errno;
    close(null_fd);
    close(log_fd);
    close(report[1]);
    if (pid < 0) {
        close(report[0]);
        errno = fork_errno;
        return -1;
    }
    int start_errno = 0;
    ssize_t got;
    do
        got = read(report[0], &start_errno, sizeof start_errno);
    while (got < 0 && errno == EINTR);
    close(report[0]);
    r->started = got != (ssize_t)sizeof start_errno;
    r->start_errno = r->started ? 0 : start_errno;

    int wstatus = 0;
    for (;;) {
        pid_t w = waitpid(pid, &wstatus, WNOHANG);
        if (w == pid)
            break;
        if (w < 0 && errno != EINTR)
            return -1;
        siginfo_t info;
        int sig = sigwaitinfo(&g->waited, &info);
        if (sig < 0 || sig == SIGCHLD)
            continue; /* EINTR, or a child's exit: reap it above */
        /* A termination signal: stop the child (it may have had the signal
         * too, from the terminal) and reap it. */
        r->interrupted = sig;
        kill(pid, SIGTERM);
        while (waitpid(pid, &wstatus, 0) < 0 && errno == EINTR)
            ;
        break;
    }
    r->wall_seconds = clock_wall() - t0;
    r->cpu_seconds = cpu_of_children() - cpu0;
    if (!r->interrupted)
        r->interrupted = process_pending_signal(g);
    if (WIFEXITED(wstatus)) {
        r->exited = 1;
        r->status = WEXITSTATUS(wstatus);
    } else {
        r->exited = 0;
        r->status = WIFSIGNALED(wstatus) ? WTERMSIG(wstatus) : 0;
    }
    return 0;
}
