/* Replays inputs through a fuzz entry point without libFuzzer, for make
 * check: every file named on the command line is read and handed to
 * LLVMFuzzerTestOneInput, as the fuzzer hands it its inputs. Linked with
 * fuzz_scene.c or fuzz_image.c, it keeps the entry points building with
 * the rest of the tree, and runs the seed corpus and every finding kept in
 * tests/fuzz/findings under the build's sanitizers (tests/fuzz-replay.sh).
 *
 * usage: replay FILE...   Prints a TAP line per file; an input that crashes
 * or trips a sanitizer ends the program there (the sanitizer build does not
 * recover), which the TAP driver reports as a failure. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The whole file, or NULL (its reason on stderr). */
static uint8_t *read_all(const char *path, size_t *size)
{
    FILE *fp = fopen(path, "rb");
    if (!fp) {
        perror(path);
        return NULL;
    }
    size_t cap = 4096, n = 0;
    uint8_t *buf = malloc(cap);
    while (buf) {
        n += fread(buf + n, 1, cap - n, fp);
        if (n < cap)
            break;
        uint8_t *bigger = realloc(buf, cap * 2);
        if (!bigger) {
            free(buf);
            buf = NULL;
            break;
        }
        buf = bigger;
        cap *= 2;
    }
    if (buf && ferror(fp)) {
        perror(path);
        free(buf);
        buf = NULL;
    }
    fclose(fp);
    *size = n;
    return buf;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fputs("usage: replay FILE...\n", stderr);
        return 2;
    }
    printf("1..%d\n", argc - 1);
    int failed = 0;
    for (int i = 1; i < argc; i++) {
        size_t size = 0;
        uint8_t *data = read_all(argv[i], &size);
        if (!data) {
            printf("not ok %d - %s could not be read\n", i, argv[i]);
            failed++;
            continue;
        }
        fflush(stdout); /* the TAP so far, should the input bring the program down */
        (void)LLVMFuzzerTestOneInput(data, size);
        free(data);
        printf("ok %d - %s (%zu bytes) replayed\n", i, argv[i], size);
    }
    return failed ? 1 : 0;
}
