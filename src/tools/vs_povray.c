/* `hstrace vs-povray`: find POV-Ray, render with both programs in a private
 * folder, compare, report, clean up. */
#include "vs_povray.h"

#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/utsname.h>
#include <time.h>
#include <unistd.h>

#include "config.h"
#include "atomic_file.h"
#include "compare_options.h"
#include "image.h"
#include "image_compare.h"
#include "mask_compare.h"
#include "process.h"
#include "render.h"
#include "vs_povray_options.h"
#include "vs_povray_report.h"

#ifndef HST_DATADIR
#define HST_DATADIR "/usr/local/share/hstrace"
#endif

#define PROGRAM "hstrace vs-povray"
#define TAIL_LINES 20        /* lines of a failed program's output shown */
#define TAIL_BYTES 65536     /* ... taken from at most this much of its end */
#define MAX_DECLARED 32      /* POV-Ray options a scene may declare */
#define FILE_NAME 80         /* longest name of a file in the private folder or the report */
#define TMP_MAX_LEN 1024     /* longest TMPDIR */

typedef struct {
    double wall[VS_MAX_RUNS], cpu[VS_MAX_RUNS], shadow[VS_MAX_RUNS];
    double verified, disagreements; /* from the --verify-shadows render; NAN: none */
} Timings;

typedef struct {
    const VsPovrayOptions *opt;
    ProcessGuard guard;
    int guarded;
    char tmp[TMP_MAX_LEN + 32];   /* the private folder; "" until made */
    const char *self;             /* the file hstrace re-executes */
    char povray[PATH_MAX];        /* POV-Ray's program file */
    char scene[PATH_MAX];         /* the scene, absolute, for POV-Ray */
    char scene_arg[PATH_MAX];     /* the scene as given, for hstrace (which runs in the same folder) */
    const char *argv0;            /* as the user typed it, for the command line */
    /* POV-Ray's include folders, "+L/absolute/path" (malloc'd): the
     * scene's, the --include-path ones, the project's. */
    char *libraries[MAX_INCLUDE_PATHS + 2];
    int nlibraries;
    char declared_line[1024];     /* the scene's "// povray-reference-options:" */
    char *declared[MAX_DECLARED]; /* ... split into options (pointers into a copy) */
    char declared_copy[1024];
    int ndeclared;
    int width, height, threads;
    int progress;                 /* stderr is a terminal: show what runs */
    int interrupted;              /* the termination signal that stopped a child, or 0 */
    char povray_version[96];
} VsRun;

/* ---- small helpers --------------------------------------------------------- */

static int is_executable_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode) && access(path, X_OK) == 0;
}

static int is_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

static void tmp_path(const VsRun *v, const char *name, char *out, size_t n)
{
    snprintf(out, n, "%s/%s", v->tmp, name);
}

static void progress(const VsRun *v, const char *what, const char *detail, int run)
{
    if (!v->progress)
        return;
    fprintf(stderr, "\r\033[K" PROGRAM ": %s %s", what, detail);
    if (run > 0)
        fprintf(stderr, " (run %d of %d)", run, v->opt->runs);
    fflush(stderr);
}

static void progress_done(const VsRun *v)
{
    if (v->progress) {
        fprintf(stderr, "\r\033[K");
        fflush(stderr);
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double median(const double *v, int n)
{
    double s[VS_MAX_RUNS];
    memcpy(s, v, (size_t)n * sizeof *s);
    qsort(s, (size_t)n, sizeof *s, cmp_double);
    return n % 2 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
}

/* path made absolute (not resolved: POV-Ray runs in another folder, and
 * "scene folder/.." must keep meaning what it meant here). Returns 0, or -1
 * with errno set. */
static int absolute(const char *path, char *out, size_t n)
{
    if (path[0] == '/') {
        if (strlen(path) >= n) {
            errno = ENAMETOOLONG;
            return -1;
        }
        snprintf(out, n, "%s", path);
        return 0;
    }
    char cwd[PATH_MAX];
    if (!getcwd(cwd, sizeof cwd))
        return -1;
    size_t nc = strcmp(cwd, "/") == 0 ? 0 : strlen(cwd), np = strlen(path);
    if (nc + 1 + np >= n) {
        errno = ENAMETOOLONG;
        return -1;
    }
    memcpy(out, cwd, nc);
    out[nc] = '/';
    memcpy(out + nc + 1, path, np + 1);
    return 0;
}

/* ---- finding the programs ------------------------------------------------- */

/* POV-Ray: HSTRACE_POVRAY (a path, or a name looked up in PATH), else
 * "povray" in PATH. Returns 0, or VS_EXIT_NO_POVRAY after the message. */
static int find_povray(VsRun *v)
{
    const char *env = getenv("HSTRACE_POVRAY");
    const char *name = env && *env ? env : "povray";
    if (strchr(name, '/')) {
        /* POV-Ray runs in the private folder: a relative name is made absolute. */
        if (is_executable_file(name) && absolute(name, v->povray, sizeof v->povray) == 0)
            return 0;
    } else {
        const char *path = getenv("PATH");
        if (!path)
            path = "/usr/bin:/bin";
        for (const char *p = path;;) {
            const char *end = strchr(p, ':');
            size_t len = end ? (size_t)(end - p) : strlen(p);
            char cand[PATH_MAX];
            if (len == 0)
                snprintf(cand, sizeof cand, "./%s", name);
            else
                snprintf(cand, sizeof cand, "%.*s/%s", (int)len, p, name);
            if (is_executable_file(cand)) {
                snprintf(v->povray, sizeof v->povray, "%s", cand);
                return 0;
            }
            if (!end)
                break;
            p = end + 1;
        }
    }
    if (env && *env)
        fprintf(stderr, PROGRAM ": povray not found; install the Debian package povray (HSTRACE_POVRAY='%s' is "
                        "not an executable program)\n", env);
    else
        fprintf(stderr, PROGRAM ": povray not found; install the Debian package povray\n");
    return VS_EXIT_NO_POVRAY;
}

/* The scene's "// povray-reference-options: OPTIONS" line (the first one,
 * at the start of a line): options its POV-Ray renders need, split at
 * white space, as reference/make-references.sh reads them. */
static void read_declared_options(VsRun *v)
{
    static const char key[] = "// povray-reference-options:";
    FILE *f = fopen(v->scene, "r");
    if (!f)
        return;
    char line[1024];
    while (fgets(line, sizeof line, f)) {
        if (strncmp(line, key, sizeof key - 1) != 0)
            continue;
        const char *s = line + sizeof key - 1;
        s += strspn(s, " \t");
        size_t n = strcspn(s, "\r\n");
        snprintf(v->declared_line, sizeof v->declared_line, "%.*s", (int)n, s);
        break;
    }
    fclose(f);
    snprintf(v->declared_copy, sizeof v->declared_copy, "%s", v->declared_line);
    char *save = NULL;
    for (char *t = strtok_r(v->declared_copy, " \t", &save); t && v->ndeclared < MAX_DECLARED;
         t = strtok_r(NULL, " \t", &save))
        v->declared[v->ndeclared++] = t;
}

/* "+L" and the first len characters of dir, for POV-Ray's command line. */
static int add_library(VsRun *v, const char *dir, int len)
{
    char *s = malloc((size_t)len + 3);
    if (!s) {
        fprintf(stderr, PROGRAM ": out of memory\n");
        return -1;
    }
    snprintf(s, (size_t)len + 3, "+L%.*s", len, dir);
    v->libraries[v->nlibraries++] = s;
    return 0;
}

/* --report DIR: an existing folder we may write in, or a name a folder can
 * be made with (made once the renders are done: a failed run leaves
 * nothing). Returns 0, or -1 after the message. */
static int check_report_folder(const char *dir)
{
    struct stat st;
    if (stat(dir, &st) == 0) {
        if (!S_ISDIR(st.st_mode)) {
            fprintf(stderr, PROGRAM ": --report '%s': not a folder\n", dir);
            return -1;
        }
        if (access(dir, W_OK | X_OK) != 0) {
            fprintf(stderr, PROGRAM ": --report '%s': %s\n", dir, strerror(errno));
            return -1;
        }
        return 0;
    }
    if (errno != ENOENT) {
        fprintf(stderr, PROGRAM ": --report '%s': %s\n", dir, strerror(errno));
        return -1;
    }
    char parent[PATH_MAX];
    snprintf(parent, sizeof parent, "%s", dir);
    size_t n = strlen(parent);
    while (n > 1 && parent[n - 1] == '/')
        parent[--n] = '\0';
    char *slash = strrchr(parent, '/');
    if (!slash)
        snprintf(parent, sizeof parent, ".");
    else if (slash == parent)
        slash[1] = '\0';
    else
        *slash = '\0';
    if (!is_dir(parent) || access(parent, W_OK | X_OK) != 0) {
        fprintf(stderr, PROGRAM ": --report '%s': %s\n", dir,
                is_dir(parent) ? strerror(errno) : "its parent folder does not exist");
        return -1;
    }
    return 0;
}

/* Everything checked before the first render: the scene, POV-Ray, the
 * report's folder. Returns 0 or an exit status (after the message). */
static int prepare(VsRun *v)
{
    const VsPovrayOptions *opt = v->opt;
    if (access(opt->scene, R_OK) != 0 || absolute(opt->scene, v->scene, sizeof v->scene)) {
        fprintf(stderr, PROGRAM ": %s: %s\n", opt->scene, strerror(errno));
        return VS_EXIT_IO;
    }
    /* A scene named like a subcommand is a file to hstrace as ./NAME. */
    int subcommand = strcmp(opt->scene, "compare") == 0 || strcmp(opt->scene, "vs-povray") == 0;
    snprintf(v->scene_arg, sizeof v->scene_arg, "%s%s", subcommand ? "./" : "", opt->scene);
    read_declared_options(v);
    /* POV-Ray searches its include folders, not the scene's: give it the
     * folders hstrace searches, in hstrace's order (the scene's first). */
    const char *slash = strrchr(v->scene, '/');
    int dirlen = slash == v->scene ? 1 : (int)(slash - v->scene);
    if (add_library(v, v->scene, dirlen))
        return VS_EXIT_IO;
    char dir[PATH_MAX];
    for (int i = 0; i < opt->render.ninclude_paths; i++)
        if (is_dir(opt->render.include_paths[i]) && absolute(opt->render.include_paths[i], dir, sizeof dir) == 0 &&
            add_library(v, dir, (int)strlen(dir)))
            return VS_EXIT_IO;
    if (is_dir(HST_DATADIR "/include") && add_library(v, HST_DATADIR "/include", (int)strlen(HST_DATADIR "/include")))
        return VS_EXIT_IO;
    int status = find_povray(v);
    if (status)
        return status;
    if (opt->report && check_report_folder(opt->report))
        return VS_EXIT_IO;
    v->self = access("/proc/self/exe", X_OK) == 0 ? "/proc/self/exe" : NULL;
    v->width = opt->render.width;
    v->height = opt->render.height;
    v->threads = opt->render.threads > 0 ? opt->render.threads : render_default_threads();
    v->progress = isatty(STDERR_FILENO);
    return 0;
}

/* ---- running the programs -------------------------------------------------- */

/* Prints the end of a failed program's output: for POV-Ray only what
 * follows its banner (from its first "==== [" section line on). */
static void print_tail(const char *log, int is_povray)
{
    FILE *f = fopen(log, "rb");
    if (!f)
        return;
    static const size_t cap = TAIL_BYTES;
    char *buf = malloc(cap + 1);
    if (!buf) {
        fclose(f);
        return;
    }
    if (fseek(f, 0, SEEK_END) == 0) {
        long size = ftell(f);
        if (size > (long)cap)
            fseek(f, size - (long)cap, SEEK_SET);
        else
            fseek(f, 0, SEEK_SET);
    }
    size_t n = fread(buf, 1, cap, f);
    fclose(f);
    buf[n] = '\0';
    for (size_t i = 0; i < n; i++)
        if (buf[i] == '\r' || buf[i] == '\0')
            buf[i] = '\n';
    char *start = buf;
    if (is_povray) {
        char *section = strstr(buf, "==== [");
        if (section)
            start = section;
    }
    /* The last TAIL_LINES non-empty lines, POV-Ray's section lines left out. */
    char *lines[TAIL_LINES];
    int count = 0;
    for (char *save = NULL, *l = strtok_r(start, "\n", &save); l; l = strtok_r(NULL, "\n", &save)) {
        if (is_povray && strncmp(l, "==== [", 6) == 0)
            continue;
        if (count == TAIL_LINES)
            memmove(lines, lines + 1, (TAIL_LINES - 1) * sizeof *lines);
        lines[count < TAIL_LINES ? count++ : TAIL_LINES - 1] = l;
    }
    for (int i = 0; i < count; i++)
        fprintf(stderr, "%s\n", lines[i]);
    free(buf);
}

/* After a child: 0 when it succeeded; -1 when a termination signal stopped
 * it (v->interrupted says which); otherwise prints why it failed and
 * returns the exit status. */
static int check_child(VsRun *v, int is_povray, const char *what, const ProcessResult *r, const char *log)
{
    const char *name = is_povray ? "POV-Ray" : "hstrace";
    progress_done(v);
    if (r->interrupted) {
        v->interrupted = r->interrupted;
        return -1;
    }
    if (!r->started) {
        if (is_povray) {
            fprintf(stderr, PROGRAM ": povray not found; install the Debian package povray (cannot run '%s': %s)\n",
                    v->povray, strerror(r->start_errno));
            return r->start_errno == ENOENT || r->start_errno == EACCES ? VS_EXIT_NO_POVRAY : VS_EXIT_POVRAY_FAILED;
        }
        fprintf(stderr, PROGRAM ": cannot run hstrace again: %s\n", strerror(r->start_errno));
        return VS_EXIT_IO;
    }
    if (r->exited && r->status == 0)
        return 0;
    if (r->exited)
        fprintf(stderr, PROGRAM ": %s failed on %s (%s, exit status %d):\n", name, v->opt->scene, what, r->status);
    else
        fprintf(stderr, PROGRAM ": %s failed on %s (%s, killed by signal %d):\n", name, v->opt->scene, what,
                r->status);
    print_tail(log, is_povray);
    if (is_povray)
        return VS_EXIT_POVRAY_FAILED;
    if (r->exited && (r->status == VS_EXIT_USAGE || r->status == VS_EXIT_SCENE || r->status == VS_EXIT_IO))
        return r->status;
    return VS_EXIT_IO;
}

static int spawn_failed(VsRun *v, const char *name)
{
    progress_done(v);
    fprintf(stderr, PROGRAM ": cannot run %s: %s\n", name, strerror(errno));
    return VS_EXIT_IO;
}

/* hstrace SCENE [render options] --shadows M +Qq -o OUT [--stats-json JSON]
 * --width W --height H --threads T, in the current folder (the render
 * options may name files relative to it). */
static int run_hstrace(VsRun *v, const char *method, int quality, const char *out, const char *json,
                       int with_shadow_channels, int verify, ProcessResult *r)
{
    const VsPovrayOptions *opt = v->opt;
    char **argv = calloc((size_t)opt->nrender_args + 26, sizeof *argv);
    if (!argv)
        return spawn_failed(v, "hstrace");
    char prog[] = "hstrace", shadows[] = "--shadows", o[] = "-o", sj[] = "--stats-json", w[] = "--width",
         h[] = "--height", t[] = "--threads", aov[] = "--aov", aov_groups[] = "shadow", vs[] = "--verify-shadows";
    char q[16], ws[16], hs[16], ts[16], outp[PATH_MAX], jsonp[PATH_MAX], meth[32];
    snprintf(q, sizeof q, "+Q%d", quality);
    snprintf(ws, sizeof ws, "%d", v->width);
    snprintf(hs, sizeof hs, "%d", v->height);
    snprintf(ts, sizeof ts, "%d", v->threads);
    snprintf(meth, sizeof meth, "%s", method);
    tmp_path(v, out, outp, sizeof outp);
    int n = 0;
    argv[n++] = prog;
    argv[n++] = v->scene_arg;
    for (int i = 0; i < opt->nrender_args; i++)
        argv[n++] = opt->render_args[i];
    argv[n++] = shadows;
    argv[n++] = meth;
    argv[n++] = q;
    argv[n++] = o;
    argv[n++] = outp;
    if (json) {
        tmp_path(v, json, jsonp, sizeof jsonp);
        argv[n++] = sj;
        argv[n++] = jsonp;
    }
    if (with_shadow_channels) {
        argv[n++] = aov;
        argv[n++] = aov_groups;
    }
    if (verify)
        argv[n++] = vs;
    argv[n++] = w;
    argv[n++] = ws;
    argv[n++] = h;
    argv[n++] = hs;
    argv[n++] = t;
    argv[n++] = ts;
    argv[n] = NULL;
    char log[PATH_MAX];
    tmp_path(v, "hstrace.log", log, sizeof log);
    int rc = process_run(&v->guard, v->self, argv, NULL, log, r);
    free(argv);
    if (rc)
        return spawn_failed(v, "hstrace");
    char what[64];
    snprintf(what, sizeof what, "--shadows %s +Q%d%s", method, quality, verify ? " --verify-shadows" : "");
    return check_child(v, 0, what, r, log);
}

/* povray +ISCENE +OOUT +FE -A -D (quiet but for warnings and errors) +Ww +Hh
 * +WTt +Qq +LDIR... DECLARED..., in the private folder: POV-Ray writes only
 * where its configuration permits, and the current folder is permitted. */
/* Does the text file at path hold `text` on one of its lines? */
static int file_contains(const char *path, const char *text)
{
    FILE *f = fopen(path, "r");
    char line[1024];
    int found = 0;
    while (f && !found && fgets(line, sizeof line, f))
        found = strstr(line, text) != NULL;
    if (f)
        fclose(f);
    return found;
}

static int run_povray(VsRun *v, int quality, const char *out, ProcessResult *r)
{
    char *argv[16 + MAX_INCLUDE_PATHS + 2 + MAX_DECLARED];
    char prog[] = "povray", fe[] = "+FE", na[] = "-A", nd[] = "-D", gs[] = "-GS", gr[] = "-GR", gd[] = "-GD",
         nv[] = "-V";
    char in[PATH_MAX + 3], o[FILE_NAME + 3], w[16], h[16], wt[16], q[16];
    snprintf(in, sizeof in, "+I%s", v->scene);
    snprintf(o, sizeof o, "+O%s", out);
    snprintf(w, sizeof w, "+W%d", v->width);
    snprintf(h, sizeof h, "+H%d", v->height);
    snprintf(wt, sizeof wt, "+WT%d", v->threads);
    snprintf(q, sizeof q, "+Q%d", quality);
    int n = 0;
    char *fixed[] = {prog, in, o, fe, na, nd, gs, gr, gd, nv, w, h, wt, q};
    for (size_t i = 0; i < sizeof fixed / sizeof fixed[0]; i++)
        argv[n++] = fixed[i];
    for (int i = 0; i < v->nlibraries; i++)
        argv[n++] = v->libraries[i];
    for (int i = 0; i < v->ndeclared; i++)
        argv[n++] = v->declared[i];
    argv[n] = NULL;
    char log[PATH_MAX];
    tmp_path(v, "povray.log", log, sizeof log);
    /* On a loaded machine POV-Ray 3.7 can give up before its render threads
     * start ("Timed out waiting for worker thread startup"): that, and only
     * that, is tried again, up to twice. */
    for (int attempt = 1;; attempt++) {
        if (process_run(&v->guard, v->povray, argv, v->tmp, log, r))
            return spawn_failed(v, "povray");
        if (attempt == 3 || r->interrupted || (r->exited && r->status == 0) ||
            !file_contains(log, "Timed out waiting for worker thread startup"))
            break;
    }
    char what[16];
    snprintf(what, sizeof what, "+Q%d", quality);
    int status = check_child(v, 1, what, r, log);
    if (status == 0 && !v->povray_version[0]) {
        /* "Persistence of Vision(tm) Ray Tracer Version 3.7.0.10.unofficial (g++ @" */
        FILE *f = fopen(log, "r");
        char line[512];
        while (f && fgets(line, sizeof line, f)) {
            const char *s = strstr(line, "Ray Tracer Version ");
            if (s) {
                s += strlen("Ray Tracer Version ");
                snprintf(v->povray_version, sizeof v->povray_version, "%.*s", (int)strcspn(s, " \r\n"), s);
                break;
            }
        }
        if (f)
            fclose(f);
    }
    return status;
}

/* The number after the first "KEY": in a --stats-json file; NAN when absent. */
static double read_json_number(const char *path, const char *key)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return NAN;
    char buf[16384];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    char quoted[64];
    snprintf(quoted, sizeof quoted, "\"%s\":", key);
    const char *s = strstr(buf, quoted);
    if (!s)
        return NAN;
    char *end;
    double t = strtod(s + strlen(quoted), &end);
    return end == s + strlen(quoted) ? NAN : t;
}

/* All renders: POV-Ray's +Q3/+Q4 pair and each method's +Q4 render with
 * its shadow channels (--aov shadow: the render and its shadow losses stand
 * for hstrace's own pair), then the timed full renders, run after run,
 * POV-Ray first in each. Returns 0, -1 when interrupted, or an exit status. */
static int render_all(VsRun *v, Timings *pov, Timings *methods)
{
    const VsPovrayOptions *opt = v->opt;
    ProcessResult r;
    char name[FILE_NAME], json[FILE_NAME];
    int status;
    /* hstrace first: its message names the line of a scene error. */
    for (int m = 0; m < opt->nmethods; m++) {
        const char *method = opt->methods[m]->name;
        snprintf(name, sizeof name, "%s.q4.exr", method);
        progress(v, method, "+Q4", 0);
        if ((status = run_hstrace(v, method, 4, name, NULL, 1, 0, &r)))
            return status;
    }
    /* A method that is not exact: its disagreements with the shadow ray, in
     * a full render of its own (the timed ones must not pay for the check). */
    for (int m = 0; m < opt->nmethods; m++) {
        methods[m].verified = methods[m].disagreements = NAN;
        if (!opt->methods[m]->inexact)
            continue;
        const char *method = opt->methods[m]->name;
        char path[PATH_MAX];
        snprintf(name, sizeof name, "%s.verify.exr", method);
        snprintf(json, sizeof json, "%s.verify.json", method);
        progress(v, method, "--verify-shadows", 0);
        if ((status = run_hstrace(v, method, 9, name, json, 0, 1, &r)))
            return status;
        tmp_path(v, json, path, sizeof path);
        methods[m].verified = read_json_number(path, "verified");
        methods[m].disagreements = read_json_number(path, "disagreements");
    }
    progress(v, "POV-Ray", "+Q3", 0);
    if ((status = run_povray(v, 3, "povray.q3.exr", &r)))
        return status;
    progress(v, "POV-Ray", "+Q4", 0);
    if ((status = run_povray(v, 4, "povray.q4.exr", &r)))
        return status;
    for (int run = 0; run < opt->runs; run++) {
        progress(v, "POV-Ray", "+Q9", run + 1);
        if ((status = run_povray(v, 9, "povray.exr", &r)))
            return status;
        pov->wall[run] = r.wall_seconds;
        pov->cpu[run] = r.cpu_seconds;
        pov->shadow[run] = NAN;
        for (int m = 0; m < opt->nmethods; m++) {
            const char *method = opt->methods[m]->name;
            snprintf(name, sizeof name, "%s.exr", method);
            snprintf(json, sizeof json, "%s.json", method);
            progress(v, method, "+Q9", run + 1);
            if ((status = run_hstrace(v, method, 9, name, json, 0, 0, &r)))
                return status;
            char path[PATH_MAX];
            tmp_path(v, json, path, sizeof path);
            methods[m].wall[run] = r.wall_seconds;
            methods[m].cpu[run] = r.cpu_seconds;
            methods[m].shadow[run] = read_json_number(path, "shadow_testing");
        }
    }
    progress_done(v);
    return 0;
}

/* ---- comparing and reporting ---------------------------------------------- */

/* Reads a render from the private folder, checking its size. */
static int read_render(const VsRun *v, const char *name, const char *who, Image *img)
{
    char path[PATH_MAX], err[1024];
    tmp_path(v, name, path, sizeof path);
    if (image_read(path, img, 0.0, err, sizeof err)) {
        fprintf(stderr, PROGRAM ": %s's render %s: %s\n", who, name, err);
        return VS_EXIT_IO;
    }
    if (img->width != v->width || img->height != v->height) {
        fprintf(stderr, PROGRAM ": %s's render %s is %dx%d pixels, not %dx%d\n", who, name, img->width,
                img->height, v->width, v->height);
        image_free(img);
        return VS_EXIT_IO;
    }
    return 0;
}

/* The +Q3/+Q4 pair a method's +Q4 render stands for: the render (*q4,
 * replaced) and the render plus its shadow.loss channels (*q3). */
static int pair_from_channels(const VsRun *v, const char *name, Image *q3, Image *q4)
{
    static const char *const names[3] = {"shadow.loss.R", "shadow.loss.G", "shadow.loss.B"};
    char path[PATH_MAX], err[1024];
    float *loss[3];
    int w, h;
    tmp_path(v, name, path, sizeof path);
    if (image_read_exr_channels(path, names, 3, loss, &w, &h, err, sizeof err)) {
        fprintf(stderr, PROGRAM ": hstrace's render %s: %s\n", name, err);
        return VS_EXIT_IO;
    }
    Image render = *q4;
    int status = 0;
    if (w != render.width || h != render.height) {
        fprintf(stderr, PROGRAM ": hstrace's render %s: shadow channels of another size\n", name);
        render.rgba = NULL; /* still *q4's */
        status = VS_EXIT_IO;
    } else if (mask_pair_from_loss(&render, (const float *const *)loss, q3, q4)) {
        fprintf(stderr, PROGRAM ": out of memory\n");
        *q4 = render; /* still the caller's to free */
        render.rgba = NULL;
        status = VS_EXIT_IO;
    }
    image_free(&render);
    for (int k = 0; k < 3; k++)
        free(loss[k]);
    return status;
}

/* One PNG of the report (8-bit sRGB, written to a temporary and renamed). */
static int write_png(const VsRun *v, const char *name, const Image *img)
{
    char path[PATH_MAX], err[1024];
    ImageWriteOptions wo;
    memset(&wo, 0, sizeof wo);
    snprintf(path, sizeof path, "%s/%s", v->opt->report, name);
    if (image_write(path, img, &wo, err, sizeof err) == 0)
        return 0;
    fprintf(stderr, PROGRAM ": %s\n", err);
    return VS_EXIT_IO;
}

/* A text file of the report, through a temporary renamed into place. */
static int write_text(const VsRun *v, const char *name, void (*print)(FILE *, const VsResult *), const VsResult *res)
{
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/%s", v->opt->report, name);
    AtomicFile af;
    if (atomic_file_open(&af, path) == 0) {
        FILE *f = fdopen(af.fd, "w");
        if (f) {
            af.fd = -1;
            print(f, res);
            int bad = ferror(f);
            if (fclose(f) == 0 && !bad && atomic_file_commit(&af) == 0)
                return 0;
            if (bad)
                errno = EIO;
        }
        atomic_file_abort(&af);
    }
    fprintf(stderr, PROGRAM ": cannot write '%s': %s\n", path, strerror(errno));
    return VS_EXIT_IO;
}

/* Fills the result's rows from the renders; with --report writes the PNGs.
 * Returns 0 or an exit status (a report file that could not be written
 * leaves the figures complete). */
static int compare_all(VsRun *v, const Timings *pov, const Timings *methods, VsResult *res)
{
    const VsPovrayOptions *opt = v->opt;
    Image ref, ref3, ref4, hst3, img, q4, map;
    memset(&ref, 0, sizeof ref);
    memset(&ref3, 0, sizeof ref3);
    memset(&ref4, 0, sizeof ref4);
    memset(&hst3, 0, sizeof hst3);
    memset(&img, 0, sizeof img);
    memset(&q4, 0, sizeof q4);
    memset(&map, 0, sizeof map);
    int status = 0, report_status = 0;
    if ((status = read_render(v, "povray.exr", "POV-Ray", &ref)) ||
        (status = read_render(v, "povray.q3.exr", "POV-Ray", &ref3)) ||
        (status = read_render(v, "povray.q4.exr", "POV-Ray", &ref4)))
        goto done;
    res->povray.name = "povray";
    res->povray.wall = median(pov->wall, opt->runs);
    res->povray.cpu = median(pov->cpu, opt->runs);
    res->povray.shadow = NAN;
    res->povray.speedup = 1.0;
    res->povray.verified = res->povray.disagreements = -1;
    if (opt->report) {
        if (mkdir(opt->report, 0777) != 0 && errno != EEXIST) {
            fprintf(stderr, PROGRAM ": --report '%s': %s\n", opt->report, strerror(errno));
            report_status = VS_EXIT_IO;
        } else {
            snprintf(res->povray.render_png, sizeof res->povray.render_png, "povray.png");
            report_status = write_png(v, res->povray.render_png, &ref);
        }
    }
    MaskCompareOptions mo = {.loss_tolerance = res->threshold, .allow_a_leaks = 0};
    for (int m = 0; m < opt->nmethods; m++) {
        VsRow *row = &res->rows[m];
        const char *method = opt->methods[m]->name;
        char name[FILE_NAME];
        row->name = method;
        row->wall = median(methods[m].wall, opt->runs);
        row->cpu = median(methods[m].cpu, opt->runs);
        row->shadow = median(methods[m].shadow, opt->runs);
        row->speedup = res->povray.wall / row->wall;
        row->verified = isfinite(methods[m].verified) ? (long long)methods[m].verified : -1;
        row->disagreements = isfinite(methods[m].disagreements) ? (long long)methods[m].disagreements : -1;
        snprintf(name, sizeof name, "%s.exr", method);
        if ((status = read_render(v, name, "hstrace", &img)))
            goto done;
        snprintf(name, sizeof name, "%s.q4.exr", method);
        if ((status = read_render(v, name, "hstrace", &q4)) || (status = pair_from_channels(v, name, &hst3, &q4)))
            goto done;
        int want_maps = opt->report && !report_status;
        if (image_compare(&ref, &img, res->threshold, &row->image) ||
            mask_compare(&ref3, &ref4, &hst3, &q4, &mo, &row->mask, want_maps ? &map : NULL)) {
            fprintf(stderr, PROGRAM ": out of memory\n");
            status = VS_EXIT_IO;
            goto done;
        }
        res->nrows = m + 1;
        if (want_maps) {
            snprintf(row->render_png, sizeof row->render_png, "%s.png", method);
            snprintf(row->mask_png, sizeof row->mask_png, "%s-mask.png", method);
            snprintf(row->diff_png, sizeof row->diff_png, "%s-diff.png", method);
            if ((report_status = write_png(v, row->render_png, &img)) == 0)
                report_status = write_png(v, row->mask_png, &map);
            image_free(&map);
            if (report_status == 0) {
                if (image_compare_heat_map(&ref, &img, res->threshold, &map)) {
                    fprintf(stderr, PROGRAM ": out of memory\n");
                    report_status = VS_EXIT_IO;
                } else {
                    report_status = write_png(v, row->diff_png, &map);
                }
                image_free(&map);
            }
        }
        image_free(&img);
        image_free(&q4);
        image_free(&hst3);
    }
    status = report_status;
done:
    image_free(&ref);
    image_free(&ref3);
    image_free(&ref4);
    image_free(&hst3);
    image_free(&img);
    image_free(&q4);
    image_free(&map);
    return status;
}

/* The command line, each word quoted for a POSIX shell where needed. */
static char *quote_command(const char *self, int argc, char **argv)
{
    size_t len = 1;
    for (int i = -1; i < argc; i++)
        len += 4 * strlen(i < 0 ? self : argv[i]) + 3;
    char *out = malloc(len), *o = out;
    if (!out)
        return NULL;
    for (int i = -1; i < argc; i++) {
        const char *a = i < 0 ? self : argv[i];
        if (i >= 0)
            *o++ = ' ';
        int plain = *a != '\0';
        for (const char *c = a; *c; c++)
            if (!strchr("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_+-=,./:@%^", *c))
                plain = 0;
        if (plain) {
            o += sprintf(o, "%s", a);
            continue;
        }
        *o++ = '\'';
        for (const char *c = a; *c; c++) {
            if (*c == '\'')
                o += sprintf(o, "'\\''");
            else
                *o++ = *c;
        }
        *o++ = '\'';
    }
    *o = '\0';
    return out;
}

/* "Linux x86_64, 2 cores, Intel(R) ..." */
static void describe_machine(char *out, size_t n)
{
    struct utsname u;
    int cores = render_default_threads();
    if (uname(&u) == 0)
        snprintf(out, n, "%s %s, %d core%s", u.sysname, u.machine, cores, cores == 1 ? "" : "s");
    else
        snprintf(out, n, "%d core%s", cores, cores == 1 ? "" : "s");
    FILE *f = fopen("/proc/cpuinfo", "r");
    char line[256];
    while (f && fgets(line, sizeof line, f)) {
        if (strncmp(line, "model name", 10) != 0)
            continue;
        const char *s = strchr(line, ':');
        if (s) {
            s += 1 + strspn(s + 1, " \t");
            size_t used = strlen(out);
            snprintf(out + used, n - used, ", %.*s", (int)strcspn(s, "\n"), s);
        }
        break;
    }
    if (f)
        fclose(f);
}

/* Removes the private folder and what the renders left in it. */
static void remove_private_folder(VsRun *v)
{
    if (!v->tmp[0])
        return;
    DIR *d = opendir(v->tmp);
    if (d) {
        struct dirent *e;
        char path[PATH_MAX];
        while ((e = readdir(d)) != NULL) {
            if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
                continue;
            snprintf(path, sizeof path, "%s/%s", v->tmp, e->d_name);
            unlink(path);
        }
        closedir(d);
    }
    if (rmdir(v->tmp) != 0)
        fprintf(stderr, PROGRAM ": cannot remove the temporary folder '%s': %s\n", v->tmp, strerror(errno));
    v->tmp[0] = '\0';
}

static int make_private_folder(VsRun *v)
{
    const char *dir = getenv("TMPDIR");
    if (!dir || !*dir)
        dir = "/tmp";
    if (strlen(dir) > TMP_MAX_LEN) {
        fprintf(stderr, PROGRAM ": TMPDIR is longer than %d characters\n", TMP_MAX_LEN);
        return VS_EXIT_IO;
    }
    snprintf(v->tmp, sizeof v->tmp, "%s/hstrace-vs-povray.XXXXXX", dir);
    if (mkdtemp(v->tmp))
        return 0;
    fprintf(stderr, PROGRAM ": cannot make a temporary folder in '%s': %s\n", dir, strerror(errno));
    v->tmp[0] = '\0';
    return VS_EXIT_IO;
}

static int measure_and_report(VsRun *v, int argc, char **argv)
{
    const VsPovrayOptions *opt = v->opt;
    Timings *t = calloc((size_t)opt->nmethods + 1, sizeof *t);
    VsResult *res = calloc(1, sizeof *res);
    char *command = quote_command(v->argv0, argc, argv);
    int status = VS_EXIT_IO;
    if (!t || !res || !command) {
        fprintf(stderr, PROGRAM ": out of memory\n");
        goto done;
    }
    if ((status = render_all(v, &t[0], &t[1])))
        goto done;
    res->scene = opt->scene;
    res->width = v->width;
    res->height = v->height;
    res->threads = v->threads;
    res->runs = opt->runs;
    res->threshold = COMPARE_DEFAULT_THRESHOLD;
    res->command = command;
    res->hstrace_version = PACKAGE_VERSION;
    snprintf(res->povray_version, sizeof res->povray_version, "%s", v->povray_version[0] ? v->povray_version : "unknown");
    res->povray_path = v->povray;
    res->povray_options = v->declared_line;
    time_t now = time(NULL);
    struct tm tm;
    if (gmtime_r(&now, &tm))
        strftime(res->date, sizeof res->date, "%Y-%m-%dT%H:%M:%SZ", &tm);
    describe_machine(res->machine, sizeof res->machine);
    status = compare_all(v, &t[0], &t[1], res);
    if (res->nrows == opt->nmethods) {
        if (opt->json)
            vs_report_json(stdout, res);
        else
            vs_report_text(stdout, res);
        if (fflush(stdout) != 0 && status == 0) {
            fprintf(stderr, PROGRAM ": cannot write the table: %s\n", strerror(errno));
            status = VS_EXIT_IO;
        }
    }
    /* The page last: it never names a file not yet written. */
    if (status == 0 && opt->report && (status = write_text(v, "vs-povray.json", vs_report_json, res)) == 0)
        status = write_text(v, "index.html", vs_report_html, res);
done:
    free(command);
    free(res);
    free(t);
    return status;
}

int vs_povray_main(int argc, char **argv, const char *self)
{
    VsPovrayOptions opt;
    char err[1024];
    if (vs_povray_options_parse(argc, argv, &opt, err, sizeof err)) {
        fprintf(stderr, PROGRAM ": %s\n", err);
        return VS_EXIT_USAGE;
    }
    if (opt.help) {
        vs_povray_options_usage(stdout);
        return VS_EXIT_OK;
    }
    VsRun *v = calloc(1, sizeof *v);
    if (!v) {
        fprintf(stderr, PROGRAM ": out of memory\n");
        vs_povray_options_free(&opt);
        return VS_EXIT_IO;
    }
    v->opt = &opt;
    v->argv0 = self;
    int status = prepare(v);
    if (status == 0 && !v->self)
        v->self = self;
    if (status == 0) {
        if (process_guard_begin(&v->guard)) {
            fprintf(stderr, PROGRAM ": cannot block signals: %s\n", strerror(errno));
            status = VS_EXIT_IO;
        } else {
            v->guarded = 1;
        }
    }
    if (status == 0)
        status = make_private_folder(v);
    if (status == 0)
        status = measure_and_report(v, argc, argv);
    remove_private_folder(v);
    for (int i = 0; i < v->nlibraries; i++)
        free(v->libraries[i]);
    vs_povray_options_free(&opt);
    ProcessGuard guard = v->guard;
    int guarded = v->guarded, sig = v->interrupted;
    free(v);
    if (guarded) {
        if (sig)
            process_die(&guard, sig);
        process_guard_end(&guard); /* a signal that came between two renders is delivered now */
    }
    return status < 0 ? VS_EXIT_IO : status;
}
