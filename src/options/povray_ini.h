/* Which povray.ini POV-Ray 3.7 reads before its command line on Unix, so
 * that hstrace's defaults (size, library paths, output type ...) are those
 * POV-Ray has on the same machine. As vfe/unix/unixoptions.cpp does it
 * (UnixOptionsProcessor::Process_povray_ini, 3.7.0.10; the paths are those
 * of Debian's build), the first of these that can be opened is the one read,
 * and no other:
 *
 *   $POVINI                           when set (one that cannot be opened is
 *                                     warned about, and the search goes on)
 *   ./povray.ini                      the current folder's
 *   $HOME/.povray/3.7/povray.ini      the user's
 *   SYSCONF/povray/3.7/povray.ini     the system's (/etc/povray/3.7/povray.ini)
 *   $HOME/.povrayrc                   the user's, of POV-Ray 3.6 and before
 *   SYSCONF/povray.ini                the system's, of POV-Ray 3.6 and before
 *
 * ($HOME's only when it is set and not empty.) SYSCONF is
 * $HSTRACE_POVRAY_SYSCONFDIR when set, else the folder configure was given
 * (--with-povray-sysconfdir, /etc by default). The file is read as any INI
 * file, before the command line's settings, which override it. */
#ifndef HST_POVRAY_INI_H
#define HST_POVRAY_INI_H

#include <limits.h>

typedef struct {
    char path[PATH_MAX];  /* the file found, or "" */
    const char *why;      /* which of the six it is ("the system's povray.ini") */
    char warning[320];    /* "$POVINI: cannot open ..." when it could not be, or "" */
} PovrayIni;

/* Looks for it (nothing is read but the environment and whether files can
 * be opened). Returns 1 with ini->path set, or 0 when none of them can be
 * opened (POV-Ray then adds its own include folder, as hstrace always
 * searches it: see the man page's FILES). */
int povray_ini_find(PovrayIni *ini);

#endif
