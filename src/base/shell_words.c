/* Command lines quoted for a POSIX shell (shell_words.h). */
#include "shell_words.h"

#include <stdlib.h>
#include <string.h>

char *shell_quote_words(int argc, char *const *argv)
{
    /* At worst every character a quote (4 bytes), two quotes and a space
     * around each word. */
    size_t len = 1;
    for (int i = 0; i < argc; i++)
        len += 4 * strlen(argv[i]) + 3;
    char *out = malloc(len), *o = out;
    if (!out)
        return NULL;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (i > 0)
            *o++ = ' ';
        int plain = *a != '\0';
        for (const char *c = a; *c; c++)
            if (!strchr("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_+-=,./:@%^", *c))
                plain = 0;
        if (!plain)
            *o++ = '\'';
        for (const char *c = a; *c; c++) {
            if (*c == '\'') {
                memcpy(o, "'\\''", 4);
                o += 4;
            } else {
                *o++ = *c;
            }
        }
        if (!plain)
            *o++ = '\'';
    }
    *o = '\0';
    return out;
}
