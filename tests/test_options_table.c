/* The options' table (src/options/options_table.c) against what users
 * read: every row named once, --help printed from it, its switches in
 * --help's paragraphs and the man page's OPTIONS, the INI keys hstrace
 * takes in the man page and the keys the man page names in the table, the
 * defaults --help states those of the rows, and the defaults options_parse
 * gives. tests/option-coverage.sh holds --help and the man page against
 * each other and the tests.
 *
 * Environment: top_srcdir (default .), for man/hstrace.1. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "grid.h"
#include "options.h"
#include "options_table.h"
#include "tap.h"

static char *read_all(FILE *f)
{
    size_t n = 0, cap = 1 << 16;
    char *s = malloc(cap);
    size_t got;
    while (s && (got = fread(s + n, 1, cap - n - 1, f)) > 0) {
        n += got;
        if (n + 1 == cap) {
            char *grown = realloc(s, cap *= 2);
            if (!grown) {
                free(s);
                return NULL;
            }
            s = grown;
        }
    }
    if (s)
        s[n] = '\0';
    return s;
}

/* The man page's text from the line starting with from up to the next line
 * starting with one of the stops, its "\-" as "-". */
static char *man_part(const char *man, const char *from, const char *stop1, const char *stop2)
{
    const char *a = strstr(man, from);
    if (!a)
        return NULL;
    const char *e = a + strlen(from), *b1 = strstr(e, stop1), *b2 = stop2 ? strstr(e, stop2) : NULL;
    const char *end = b1 && (!b2 || b1 < b2) ? b1 : b2 ? b2 : a + strlen(a);
    char *out = malloc((size_t)(end - a) + 1), *o = out;
    for (const char *p = a; out && p < end; p++) {
        if (p[0] == '\\' && p[1] == '-')
            p++;
        *o++ = *p;
    }
    if (out)
        *o = '\0';
    return out;
}

/* Does text hold the switch +X (or -X) not followed by an upper-case letter
 * (+W is not +WT)? */
static int has_switch(const char *text, const char *sw)
{
    size_t n = strlen(sw + 1);
    for (const char *p = text; (p = strstr(p, sw + 1)) != NULL; p++)
        if (p > text && (p[-1] == '+' || p[-1] == '-') && !isupper((unsigned char)p[n]))
            return 1;
    return 0;
}

/* Does text hold word as a whole word (an INI key)? */
static int has_word(const char *text, const char *word)
{
    size_t n = strlen(word);
    for (const char *p = text; (p = strstr(p, word)) != NULL; p++)
        if ((p == text || !(isalnum((unsigned char)p[-1]) || p[-1] == '_')) &&
            !(isalnum((unsigned char)p[n]) || p[n] == '_'))
            return 1;
    return 0;
}

static int same(const char *a, const char *b)
{
    return a && b && strcasecmp(a, b) == 0;
}

int main(void)
{
    const char *srcdir = getenv("top_srcdir") ? getenv("top_srcdir") : ".";
    char path[4096];
    snprintf(path, sizeof path, "%s/man/hstrace.1", srcdir);
    FILE *mf = fopen(path, "r");
    char *man = mf ? read_all(mf) : NULL;
    if (mf)
        fclose(mf);
    if (!man) {
        printf("Bail out! cannot read %s\n", path);
        return 1;
    }
    char *help = NULL;
    size_t help_len = 0;
    FILE *hf = open_memstream(&help, &help_len);
    options_usage(hf);
    fclose(hf);
    const char *paragraphs = strstr(help, "\nPOV-Ray switches:");
    char *man_options = man_part(man, "\n.SH OPTIONS", "\n.SH ", NULL);
    char *man_ini = man_part(man, "\n.SS POV-Ray INI files", "\n.SH ", "\n.SS ");
    if (!paragraphs || !man_options || !man_ini) {
        printf("Bail out! --help has no POV-Ray switches paragraph or the man page no OPTIONS / INI files\n");
        return 1;
    }

    /* Every row named, and named once. */
    int unnamed = 0, twice = 0, nlong = 0, npov = 0, nini = 0;
    for (size_t i = 0; i < option_nrows; i++) {
        const OptionRow *r = &option_rows[i];
        nlong += r->name != NULL;
        npov += r->pov != NULL;
        nini += r->ini != NULL;
        if (!r->name && !r->short_name && !r->pov && !r->ini) {
            tap_diag("row %zu has no name", i);
            unnamed++;
        }
        for (size_t j = 0; j < i; j++) {
            const OptionRow *q = &option_rows[j];
            if (same(r->name, q->name) || same(r->short_name, q->short_name) || same(r->pov, q->pov) ||
                same(r->ini, q->ini)) {
                tap_diag("rows %zu and %zu share a name", j, i);
                twice++;
            }
        }
    }
    tap_ok(unnamed == 0 && twice == 0, "each of the %zu rows (%d long options, %d switches, %d INI keys) named, "
           "and no name in two rows", option_nrows, nlong, npov, nini);
    tap_ok(nlong >= 30 && npov >= 40 && nini >= 80, "the table holds the options (at least 30 long, 40 switches, "
           "80 INI keys)");

    /* --help: each long option's line, and no other option line. */
    int missing = 0, extra = 0;
    for (size_t i = 0; i < option_nrows; i++) {
        const OptionRow *r = &option_rows[i];
        if (!r->name)
            continue;
        char line[256];
        snprintf(line, sizeof line, "\n  %s%s%s%s%s", r->short_name ? r->short_name : "  ", r->short_name ? ", " : "  ",
                 r->name, r->value_name ? " " : "", r->value_name ? r->value_name : "");
        if (!strstr(help, line) || !r->help) {
            tap_diag("%s: no line in --help", r->name);
            missing++;
        }
    }
    for (const char *p = help; p < paragraphs && (p = strstr(p, "\n  ")) != NULL && p < paragraphs; p++) {
        const char *o = p + 1;
        while (*o == ' ')
            o++;
        if (o - p - 1 > 6 || *o != '-')
            continue; /* a description's further line */
        if (o[1] == '-' || strncmp(o, "-o, ", 4) == 0) {
            const char *name = o[1] == '-' ? o : o + 4;
            size_t n = strcspn(name, " \n");
            int found = 0;
            for (size_t i = 0; i < option_nrows && !found; i++)
                found = option_rows[i].name && strlen(option_rows[i].name) == n &&
                        strncmp(option_rows[i].name, name, n) == 0;
            if (!found) {
                tap_diag("--help's %.*s is no row", (int)n, name);
                extra++;
            }
        }
    }
    tap_ok(missing == 0 && extra == 0, "--help lists each long option of the table, and only those");

    /* Switches: in --help's paragraphs and the man page's OPTIONS. */
    int no_help = 0, no_man = 0;
    for (size_t i = 0; i < option_nrows; i++) {
        const char *sw = option_rows[i].pov;
        if (!sw)
            continue;
        if (!has_switch(paragraphs, sw)) {
            tap_diag("%s: not in --help's POV-Ray switches", sw);
            no_help++;
        }
        if (!has_switch(man_options, sw)) {
            tap_diag("%s: not in the man page's OPTIONS", sw);
            no_man++;
        }
    }
    tap_ok(no_help == 0, "each of the table's %d switches is in --help's paragraphs", npov);
    tap_ok(no_man == 0, "each of the table's %d switches is in the man page's OPTIONS", npov);

    /* INI keys: those hstrace takes in the man page; those the man page's
     * INI section names, rows that hstrace takes. */
    int taken = 0, undocumented = 0, unknown = 0, named = 0;
    for (size_t i = 0; i < option_nrows; i++) {
        const OptionRow *r = &option_rows[i];
        if (!r->ini || r->type == OPT_IGNORED || r->type == OPT_UNSUPPORTED)
            continue;
        taken++;
        if (!has_word(man, r->ini)) {
            tap_diag("%s: taken, not in the man page", r->ini);
            undocumented++;
        }
    }
    for (const char *p = man_ini; (p = strstr(p, "\n.B")) != NULL; p++) {
        const char *w = p + 3;
        while (*w && *w != ' ' && *w != '\n')
            w++;
        while (*w == ' ')
            w++;
        size_t n = strspn(w, "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_");
        if (n < 2 || !isupper((unsigned char)w[0]) || !memchr(w, '_', n))
            continue; /* a key has an underscore: Input_File_Name */
        named++;
        const OptionRow *r = NULL;
        for (size_t i = 0; i < option_nrows && !r; i++)
            if (option_rows[i].ini && strlen(option_rows[i].ini) == n && strncmp(option_rows[i].ini, w, n) == 0)
                r = &option_rows[i];
        if (!r || r->type == OPT_IGNORED || r->type == OPT_UNSUPPORTED) {
            tap_diag("the man page's INI key %.*s is not one the table takes", (int)n, w);
            unknown++;
        }
    }
    tap_ok(undocumented == 0, "each of the %d INI keys the table takes is in the man page", taken);
    tap_ok(unknown == 0 && named >= 10, "each of the %d INI keys the man page's INI section names is one the "
           "table takes", named);

    /* The defaults --help states are the rows'. */
    int wrong = 0, stated = 0;
    for (size_t i = 0; i < option_nrows; i++) {
        const OptionRow *r = &option_rows[i];
        const char *d = r->help && r->dflt ? strstr(r->help, "default ") : NULL;
        if (!d)
            continue;
        d += strlen("default ");
        size_t n = strcspn(d, " ),;\n");
        stated++;
        if (strlen(r->dflt) != n || strncmp(r->dflt, d, n) != 0) {
            tap_diag("%s: --help says default %.*s, the row %s", r->name, (int)n, d, r->dflt);
            wrong++;
        }
    }
    tap_ok(wrong == 0 && stated >= 6, "the %d defaults --help states are the rows'", stated);

    /* The defaults options_parse gives, as they were before the table. */
    Options o;
    char err[1024];
    char *argv[] = { "hstrace", "x.pov", "--no-povray-ini", NULL };
    int status = options_parse(3, argv, &o, err, (int)sizeof err);
    tap_ok(status == 0 && o.width == 320 && o.height == 240 && o.quality == 9 && strcmp(o.shadows, "hst") == 0 &&
               o.nth.mode == NTH_AUTO && o.max_tree_rays == 1L << 20 && o.pixel_coherence == 1 &&
               o.tolerance == GRID_TOLERANCE && o.plane_precision == 0 && o.volumes_always == 0 && o.threads == 0,
           "defaults: 320x240, +Q9, --shadows hst, --nth auto, --max-tree-rays 2^20, --pixel-coherence on, "
           "--tolerance GRID_TOLERANCE, planes in double, volumes auto, all cores");
    tap_ok(status == 0 && o.initial_frame == 1 && o.final_frame == 1 && o.initial_clock == 0.0 &&
               o.final_clock == 1.0 && o.debug_console && o.warning_console && o.render_console &&
               o.statistics_console && !o.antialias_on && o.aa_threshold == 0.3 && o.aa_method == 1 &&
               o.aa_depth == 3 && o.aa_gamma == 2.5 && o.jitter_on == 1 && o.jitter_amount == 1.0 &&
               o.display_gamma == 0.0 && !o.no_output && o.output_type == 0 && o.jpeg_quality == 0,
           "defaults: frames 1 to 1, clocks 0 to 1, every console on, anti-aliasing off (0.3, method 1, depth 3, "
           "gamma 2.5, jitter 1), sRGB, an image written");
    options_free(&o);

    free(help);
    free(man);
    free(man_options);
    free(man_ini);
    return tap_done();
}
