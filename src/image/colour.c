/* Colour management, the part that needs no OpenColorIO: whether OCIO is
 * asked for, which config file, where the shipped one is. */
#include "colour.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#ifndef HST_DATADIR
#define HST_DATADIR "/usr/local/share/hstrace"
#endif

#define SHIPPED_CONFIG "ocio/config.ocio"

const float colour_rec709_chromaticities[8] = {
    0.6400f, 0.3300f, /* red */
    0.3000f, 0.6000f, /* green */
    0.1500f, 0.0600f, /* blue */
    0.3127f, 0.3290f, /* white: D65 */
};

static const char *ocio_env(void)
{
    const char *e = getenv("OCIO");
    return e != NULL && e[0] != '\0' ? e : NULL;
}

int colour_requested(const ColourRequest *req)
{
    return req->config != NULL || req->display != NULL || req->view != NULL || req->colorspace != NULL ||
           ocio_env() != NULL;
}

static int is_file(const char *p)
{
    struct stat st;
    return stat(p, &st) == 0 && S_ISREG(st.st_mode);
}

/* dir + "/" + SHIPPED_CONFIG into buf when that file exists. */
static int try_dir(const char *dir, size_t dirlen, char *buf, int buflen)
{
    int n = snprintf(buf, (size_t)buflen, "%.*s/%s", (int)dirlen, dir, SHIPPED_CONFIG);
    return n > 0 && n < buflen && is_file(buf);
}

const char *colour_shipped_config(char *buf, int buflen)
{
    const char *env = getenv("HSTRACE_DATADIR");
    char exe[PATH_MAX];
    ssize_t n;

    if (env != NULL && env[0] != '\0' && try_dir(env, strlen(env), buf, buflen))
        return buf;
    if (try_dir(HST_DATADIR, strlen(HST_DATADIR), buf, buflen))
        return buf;
    /* An uninstalled build: data/ beside the executable (Linux only; other
     * systems set HSTRACE_DATADIR or install). */
    n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n > 0) {
        char *slash;
        exe[n] = '\0';
        slash = strrchr(exe, '/');
        if (slash != NULL) {
            size_t len = (size_t)(slash - exe);
            char data[PATH_MAX];
            if (try_dir(exe, len, buf, buflen))
                return buf;
            if (snprintf(data, sizeof data, "%.*s/data", (int)len, exe) < (int)sizeof data &&
                try_dir(data, strlen(data), buf, buflen))
                return buf;
        }
    }
    return NULL;
}

const char *colour_config_path(const ColourRequest *req, const char **origin, char *buf, int buflen, char *err,
                               int errlen)
{
    const char *env = ocio_env();

    if (req->config != NULL) {
        *origin = "--ocio-config";
        return req->config;
    }
    if (env != NULL) {
        *origin = "$OCIO";
        return env;
    }
    *origin = "the shipped config";
    if (colour_shipped_config(buf, buflen) == NULL) {
        snprintf(err, (size_t)errlen,
                 "cannot find hstrace's colour configuration %s (looked in $HSTRACE_DATADIR, %s and beside the "
                 "program); give one with --ocio-config FILE or $OCIO",
                 SHIPPED_CONFIG, HST_DATADIR);
        return NULL;
    }
    return buf;
}
