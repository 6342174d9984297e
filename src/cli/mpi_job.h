/* One render spread over the processes of an Open MPI job (`mpirun -n N
 * hstrace SCENE.pov ...`). Every rank parses and preprocesses the scene (the
 * same on each), rank 0's measured choices (the volume plan's lights, the
 * cost model, N_th) are handed to the others so that every rank decides
 * alike, rank 0 hands out tiles one at a time to whichever thread of
 * whichever rank asks (a slow rank takes fewer), and the pixels, analysis
 * channels and counters come back to rank 0, which writes the image. An
 * animation with at least as many frames as ranks is spread by frames
 * instead. Without Open MPI (configure --without-mpi, or not installed)
 * and outside mpirun, every function here is that of a single process. */
#ifndef HST_MPI_JOB_H
#define HST_MPI_JOB_H

#include <stddef.h>

#include "aov.h"
#include "image_buffer.h"
#include "render.h"
#include "stats.h"

/* Starts MPI when the program runs under mpirun (Open MPI's environment
 * says so), asking for threads that all call MPI. Returns 0, or -1 with a
 * message when MPI cannot start or lacks that thread support. Call it
 * before any thread starts; rank and size are set once here and only read
 * afterwards. */
int mpi_job_init(int *argc, char ***argv, char *err, int errlen);
void mpi_job_finalize(void);
/* Ends every rank of the job (a rank that cannot go on). */
void mpi_job_abort(int status);

int mpi_job_rank(void);
int mpi_job_size(void);   /* 1 outside mpirun */
int mpi_job_built(void);  /* 1 when built with Open MPI */
/* The ranks on this machine (Open MPI's local size), for the thread share. */
int mpi_job_local_size(void);

/* Rank 0's n bytes, copied to every rank (all ranks call it). */
void mpi_job_broadcast(void *data, size_t n);
/* The largest of every rank's value (all ranks call it): a status that is
 * not 0 on one rank ends them all alike. */
int mpi_job_max(int value);

/* What a rank spent asking for tiles. */
typedef struct {
    long requests;       /* runs of tiles asked of rank 0 */
    double wait_seconds; /* waiting for the answers, all threads together */
} MpiTileWaits;

/* The tiles of one frame, handed out by rank 0. */
typedef struct MpiTiles {
    TileSource source;   /* for RenderOptions.tiles */
    int ntiles;
    struct MpiTilesState *state;
} MpiTiles;

/* All ranks call it before render_image, with the frame's tile grid and
 * this rank's render threads.
 * Returns 0, or -1 when out of memory. */
int mpi_tiles_begin(MpiTiles *t, const TileGrid *grid, int threads);
/* All ranks call it after render_image, with its status (0 or -1): the
 * pixels of each tile (and of the analysis channels) land in rank 0's img
 * and aov, every rank's counters in per_rank[rank] (rank 0: an array of
 * mpi_job_size(), or NULL) and their sum in *total on rank 0, what each
 * asking cost in waits[rank] (likewise), and, when
 * tile_seconds is not NULL (on every rank or none), each tile's time from
 * the rank that rendered it in rank 0's tile_seconds. Returns 0,
 * or -1 when a rank failed (out of memory) or the image is incomplete. */
int mpi_tiles_end(MpiTiles *t, const TileGrid *grid, int status, Image *img, AovImage *aov, RenderStats *total,
                  RenderStats *per_rank, MpiTileWaits *waits, double *tile_seconds);

#endif
