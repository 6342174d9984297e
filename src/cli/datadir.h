/* hstrace's installed data (data/ in the source tree, $(pkgdatadir) once
 * installed): where a folder of it is. */
#ifndef HST_DATADIR_H
#define HST_DATADIR_H

/* The folder `sub` (e.g. "include") of hstrace's data: under
 * $HSTRACE_DATADIR, else the installed data folder, else beside the
 * program or in data/ beside it (an uninstalled build; Linux only). Fills
 * buf and returns it, or NULL when none exists. */
const char *data_folder(const char *sub, char *buf, int buflen);

/* POV-Ray's include folder: $HSTRACE_POVRAY_INCLUDE when set (empty: none,
 * as if POV-Ray were not installed), else the one configure found; NULL
 * when it does not exist. */
const char *povray_include_folder(void);

#endif
