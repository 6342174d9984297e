/* --povray-options: every POV-Ray 3.7 INI key and switch the options' table
 * has a row for, and what hstrace does with it, one a line, by key:
 *
 *   KEY  SWITCH  honoured | ignored: WHY | refused: WHAT | refused when on: WHAT
 *
 * ("-" for a key or a switch the setting has not). The man page's POV-RAY
 * OPTIONS lists the same, and tests/option-coverage.sh holds the two
 * together. */
#include <stdio.h>
#include <stdlib.h>
#include <strings.h>

#include "options.h"
#include "options_table.h"

static const char *sort_name(const OptionRow *r)
{
    return r->ini ? r->ini : r->pov + 1;
}

static int by_name(const void *a, const void *b)
{
    const OptionRow *x = *(const OptionRow *const *)a, *y = *(const OptionRow *const *)b;
    return strcasecmp(sort_name(x), sort_name(y));
}

int options_povray_list(FILE *f)
{
    const OptionRow **rows = malloc(option_nrows * sizeof *rows);
    if (!rows)
        return -1;
    size_t n = 0;
    for (size_t i = 0; i < option_nrows; i++)
        if (option_rows[i].ini || option_rows[i].pov)
            rows[n++] = &option_rows[i];
    qsort(rows, n, sizeof *rows, by_name);
    for (size_t i = 0; i < n; i++) {
        const OptionRow *r = rows[i];
        fprintf(f, "%-24s %-5s ", r->ini ? r->ini : "-", r->pov ? r->pov : "-");
        if (r->type == OPT_UNSUPPORTED)
            fprintf(f, "refused%s: %s\n", r->ini_as == INI_AS_ON_OFF ? " when on" : "", r->reason);
        else if (r->reason)
            fprintf(f, "ignored: %s\n", r->reason);
        else
            fprintf(f, "honoured\n");
    }
    free(rows);
    return 0;
}
