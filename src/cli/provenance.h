/* What is needed to reproduce and judge an image, written into its EXR
 * header: the scene and a hash of its text, the command line and the
 * options in force, the version, the shadow method, N_th and the calibrated
 * costs, the timings, and (with --aov) how to read the analysis channels.
 * Attribute names and types are listed in the man page (EXR HEADER). */
#ifndef HST_PROVENANCE_H
#define HST_PROVENANCE_H

#include <pthread.h>
#include <stdint.h>

#include "image.h"
#include "options.h"
#include "parser.h"
#include "stats.h"

#define PROVENANCE_MAX_ATTRIBUTES 32

typedef struct {
    ImageAttribute attr[PROVENANCE_MAX_ATTRIBUTES];
    int n;
    char *command_line, *options, *volumes;
    char scene_hash[32];
} Provenance;

/* FNV-1a, 64 bits, of a file's bytes. Returns 0, or -1 when unreadable. */
int provenance_hash_file(const char *path, uint64_t *hash);

/* The scene file's hash, made while the scene is parsed: on a thread of
 * its own where a core is to spare (the parse uses one; on 10^6 triangles,
 * 43 MB, the hash is 60 ms the render then does not wait for), else when
 * it is asked for. The same hash either way. */
typedef struct {
    const char *path;
    uint64_t hash;
    int status;            /* provenance_hash_file's */
    int state;             /* 0: not asked for, 1: on its thread, 2: made */
    pthread_t thread;
} SceneHash;

void scene_hash_start(SceneHash *h, const char *path, int background);
/* The hash (waiting for its thread, or making it now): 0, or -1 when the
 * file was unreadable. Safe to call again, and on a hash never started
 * (then -1). */
int scene_hash_finish(SceneHash *h, uint64_t *hash);

/* Fills p from the command line, the options, the frame's clock (anim:
 * as the scene saw it; NULL: none) and the report (timings so far; writing
 * the image comes after). Returns 0, or -1 when out of memory. */
int provenance_build(Provenance *p, int argc, char **argv, const Options *opt, const ParseAnimation *anim,
                     const StatsReport *r, SceneHash *scene_hash);
void provenance_free(Provenance *p);

#endif
