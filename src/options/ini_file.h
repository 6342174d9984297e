/* POV-Ray's INI files, read the way POV-Ray 3.7 reads them
 * (base/processoptions.cpp): a file name with an optional section,
 * "render.ini[Big]"; lines of KEY=VALUE (one option a line, the rest of
 * the line ignored; a value quoted with " or ' may hold spaces; VALUE,
 * VALUE lists), +/- switches (several a line), comments from ';' or '#',
 * and [Section] headers. Lines before the first header always apply; a
 * section's lines apply only when the name asked for it (case ignored),
 * and no named section applies when none was asked for. A word that is
 * none of these is the scene file, as on POV-Ray's command line. What the
 * keys mean is the options' business (options.c); this only reads them. */
#ifndef HST_INI_FILE_H
#define HST_INI_FILE_H

#include <stddef.h>

typedef enum { INI_OPTION, INI_SWITCH, INI_WORD } IniKind;

typedef struct {
    IniKind kind;
    char *key;   /* INI_OPTION: the key as written; INI_SWITCH: "+W640" (sign included); INI_WORD: the word */
    char *value; /* INI_OPTION: the value, its quotes removed; NULL otherwise */
    int line, column;
} IniEntry;

typedef struct IniFile {
    char *path;        /* the file, without the section */
    char *section;     /* the section asked for, or NULL */
    IniEntry *entries; /* in the file's order */
    int n, cap;
    size_t bytes; /* the file's size */
} IniFile;

/* Does this command-line word name an INI file ("x.ini", "x.INI[sec]")? */
int ini_spec_is_ini(const char *word);

/* Reads spec. Returns 0, or -1 with "FILE:LINE: message" (or "FILE:
 * message") in err; f is to be freed either way. Only a regular file is
 * read: a FIFO, a device or a folder is refused at once ("cannot read"). */
int ini_file_read(IniFile *f, const char *spec, char *err, int errlen);
void ini_file_free(IniFile *f);

#endif
