/* libFuzzer entry point: POV-Ray INI files and KEY=VALUE command-line
 * words, through the INI reader (ini_file.c) and the option parser
 * (options.c), then checked as the command checks them before it renders
 * (animation_plan, the output's name, the frames' file names). Nothing is
 * rendered or written.
 *
 * The input is up to three parts, divided at lines that are exactly "%%":
 *
 *   the INI file fuzz.ini
 *   %%
 *   the command line, one word a line (without it: "fuzz.ini")
 *   %%
 *   a second INI file, inc.ini, for Include_Ini=inc.ini and "inc.ini[Sec]"
 *
 * Both files are written to a private temporary folder, made on the first
 * input, and the parse runs with that folder as the current one (the
 * previous one restored after each input), so that the names the input
 * gives (INI files, Include_Ini, Input_File_Name) are looked for there
 * only: every '/' of the input is read as '_', so that no name reaches
 * outside it. Built and run by tests/fuzz/run.sh (`make fuzz`); replayed
 * by tests/fuzz-replay.sh. */
#include <ctype.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "animation.h"
#include "options.h"

#define MAX_WORDS 64

static char folder[4096];

static void remove_folder(void)
{
    static const char *const names[] = { "fuzz.ini", "inc.ini" };
    char path[4200];
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        snprintf(path, sizeof path, "%s/%s", folder, names[i]);
        (void)unlink(path);
    }
    (void)rmdir(folder);
}

/* The private folder, made once. 0, or -1 when it cannot be made. */
static int make_folder(void)
{
    if (folder[0])
        return 0;
    const char *tmp = getenv("TMPDIR");
    snprintf(folder, sizeof folder, "%s/hstfuzzini.XXXXXX", tmp && tmp[0] ? tmp : "/tmp");
    if (!mkdtemp(folder)) {
        perror("fuzz_ini: mkdtemp");
        folder[0] = '\0';
        return -1;
    }
    atexit(remove_folder);
    return 0;
}

static int write_file(const char *name, const char *text, size_t n)
{
    FILE *fp = fopen(name, "wb");
    if (!fp)
        return -1;
    int bad = n && fwrite(text, 1, n, fp) != n;
    return fclose(fp) || bad ? -1 : 0;
}

/* The next part of text from *at: up to a line "%%" (which is skipped) or
 * the end. Sets *n; returns NULL when there is no part left. */
static char *next_part(char *text, size_t size, size_t *at, size_t *n)
{
    if (*at > size)
        return NULL;
    char *start = text + *at;
    for (size_t i = *at; i < size; i++) {
        int line_start = i == 0 || text[i - 1] == '\n';
        if (line_start && i + 2 <= size && text[i] == '%' && text[i + 1] == '%' &&
            (i + 2 == size || text[i + 2] == '\n')) {
            *n = i - *at;
            *at = i + 3;
            return start;
        }
    }
    *n = size - *at;
    *at = size + 1;
    return start;
}

/* Does err hold FILE:LINE:COLUMN: somewhere (the file's name may itself
 * hold colons)? */
static int positioned(const char *err)
{
    for (const char *p = strchr(err, ':'); p; p = strchr(p + 1, ':')) {
        const char *q = p + 1;
        if (!isdigit((unsigned char)*q))
            continue;
        while (isdigit((unsigned char)*q))
            q++;
        if (*q++ != ':' || !isdigit((unsigned char)*q))
            continue;
        while (isdigit((unsigned char)*q))
            q++;
        if (q[0] == ':' && q[1] == ' ')
            return 1;
    }
    return 0;
}

/* The checks main.c makes before it parses the scene: the frames, their
 * clocks and file names (the first and the last only: bounded work). */
static void validate(const Options *opt)
{
    Animation anim;
    char err[1024];
    if (animation_plan(opt, &anim, err, (int)sizeof err)) {
        if (!err[0])
            abort();
        return;
    }
    if (anim.first > anim.last)
        abort();
    const char *output = opt->output ? opt->output : "fuzz";
    const char *ext = options_output_extension(opt);
    if (!ext || ext[0] != '.')
        abort();
    const int frames[2] = { anim.first, anim.last };
    for (int k = 0; k < 2; k++) {
        volatile double clock = animation_clock(&anim, frames[k]);
        (void)clock;
        if (anim.animated) {
            char *name = animation_file_name(output, frames[k], anim.digits);
            free(name);
        }
    }
    volatile double declared = pov_declared_value(anim.clock_delta) + pov_declared_value(anim.initial_clock);
    (void)declared;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (make_folder())
        return 0;
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    for (size_t i = 0; i < size; i++)
        if (text[i] == '/')
            text[i] = '_'; /* no name reaches outside the folder */
    size_t at = 0, n_ini = 0, n_words = 0, n_inc = 0;
    char *ini = next_part(text, size, &at, &n_ini);
    char *words = next_part(text, size, &at, &n_words);
    char *inc = next_part(text, size, &at, &n_inc);
    int here = open(".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (here < 0 || chdir(folder)) {
        if (here >= 0)
            close(here);
        free(text);
        return 0;
    }
    if (!inc)
        (void)unlink("inc.ini"); /* the last input's */
    if (write_file("fuzz.ini", ini, n_ini) == 0 && (!inc || write_file("inc.ini", inc, n_inc) == 0)) {
        char *argv[MAX_WORDS + 3];
        int argc = 0;
        argv[argc++] = "hstrace";
        argv[argc++] = "--no-povray-ini"; /* the input's settings only, not the machine's */
        if (words) {
            /* one word a line: the part's newlines become the ends of words */
            words[n_words] = '\0';
            for (char *w = words; w && argc < MAX_WORDS + 2;) {
                char *nl = strchr(w, '\n');
                if (nl)
                    *nl = '\0';
                argv[argc++] = w;
                w = nl ? nl + 1 : NULL;
            }
        } else {
            argv[argc++] = "fuzz.ini";
        }
        argv[argc] = NULL;
        Options opt;
        char err[1024];
        err[0] = '\0';
        if (options_parse(argc, argv, &opt, err, (int)sizeof err)) {
            /* every refusal says what, an INI file's mistake where too */
            if (!err[0] || (opt.error_has_position && !positioned(err)))
                abort();
        } else if (!opt.help && !opt.version) {
            if (!opt.scene || opt.width < 1 || opt.height < 1 || opt.area_x0 < 0 || opt.area_x1 > opt.width ||
                opt.area_x0 >= opt.area_x1 || opt.area_y0 < 0 || opt.area_y1 > opt.height || opt.area_y0 >= opt.area_y1)
                abort(); /* options_parse let through what the render cannot take */
            validate(&opt);
        }
        options_free(&opt);
    }
    if (fchdir(here))
        abort(); /* the replay reads its next input from there */
    close(here);
    free(text);
    return 0;
}
