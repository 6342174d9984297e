/* The povray.ini POV-Ray 3.7 reads (povray_ini.h). */
#include "povray_ini.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "config.h"

#ifndef POVRAY_SYSCONFDIR
#define POVRAY_SYSCONFDIR "/etc"
#endif

/* Whether POV-Ray would take the file: it asks fopen(name, "r"), so a file
 * that can be opened for reading. Opened without waiting, since a FIFO
 * with no writer would block an open for ever; whether it is an INI file
 * is the reading's business, as it is POV-Ray's. errno says why not. */
static int can_open(const char *path)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return 0;
    close(fd);
    return 1;
}

/* dir + tail into ini->path when it can be opened. */
static int try_file(PovrayIni *ini, const char *dir, const char *tail, const char *why)
{
    int n = snprintf(ini->path, sizeof ini->path, "%s%s", dir, tail);
    if (n <= 0 || (size_t)n >= sizeof ini->path || !can_open(ini->path)) {
        ini->path[0] = '\0';
        return 0;
    }
    ini->why = why;
    return 1;
}

int povray_ini_find(PovrayIni *ini)
{
    memset(ini, 0, sizeof *ini);
    const char *povini = getenv("POVINI");
    if (povini) {
        errno = 0;
        if (try_file(ini, povini, "", "$POVINI"))
            return 1;
        int why = errno ? errno : ENAMETOOLONG;
        /* as POV-Ray: said, and the search goes on */
        snprintf(ini->warning, sizeof ini->warning, "$POVINI: cannot open '%.200s': %s", povini, strerror(why));
    }
    const char *home = getenv("HOME");
    if (home && !home[0])
        home = NULL;
    const char *env = getenv("HSTRACE_POVRAY_SYSCONFDIR");
    const char *sys = env ? env : POVRAY_SYSCONFDIR;
    return try_file(ini, "", "./povray.ini", "the current folder's povray.ini") ||
           (home && try_file(ini, home, "/.povray/3.7/povray.ini", "the user's povray.ini")) ||
           try_file(ini, sys, "/povray/3.7/povray.ini", "the system's povray.ini") ||
           (home && try_file(ini, home, "/.povrayrc", "the user's .povrayrc (POV-Ray 3.6's)")) ||
           try_file(ini, sys, "/povray.ini", "the system's povray.ini of POV-Ray 3.6");
}
