/* Finding hstrace's data folders and POV-Ray's include folder. */
#include "datadir.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "config.h"

#ifndef HST_DATADIR
#define HST_DATADIR "/usr/local/share/hstrace"
#endif

static int is_dir(const char *p)
{
    struct stat st;
    return stat(p, &st) == 0 && S_ISDIR(st.st_mode);
}

/* dir (its first dirlen characters) + "/" + sub into buf, when a folder. */
static int try_dir(const char *dir, size_t dirlen, const char *sub, char *buf, int buflen)
{
    int n = snprintf(buf, (size_t)buflen, "%.*s/%s", (int)dirlen, dir, sub);
    return n > 0 && n < buflen && is_dir(buf);
}

const char *data_folder(const char *sub, char *buf, int buflen)
{
    const char *env = getenv("HSTRACE_DATADIR");
    if (env != NULL && env[0] != '\0' && try_dir(env, strlen(env), sub, buf, buflen))
        return buf;
    if (try_dir(HST_DATADIR, strlen(HST_DATADIR), sub, buf, buflen))
        return buf;
    char exe[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0)
        return NULL;
    exe[n] = '\0';
    char *slash = strrchr(exe, '/');
    if (slash == NULL)
        return NULL;
    size_t len = (size_t)(slash - exe);
    char data[PATH_MAX];
    if (snprintf(data, sizeof data, "%.*s/data", (int)len, exe) < (int)sizeof data &&
        try_dir(data, strlen(data), sub, buf, buflen))
        return buf;
    return NULL;
}

const char *povray_include_folder(void)
{
    const char *env = getenv("HSTRACE_POVRAY_INCLUDE");
    const char *dir = env != NULL ? env : POVRAY_INCLUDE_DIR;
    return dir[0] != '\0' && is_dir(dir) ? dir : NULL;
}
