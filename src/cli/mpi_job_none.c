/* mpi_job.h without Open MPI: one process, always rank 0 of 1. */
#include "mpi_job.h"

#include <stdio.h>
#include <stdlib.h>

int mpi_job_init(int *argc, char ***argv, char *err, int errlen)
{
    (void)argc;
    (void)argv;
    /* Started by mpirun but built without MPI: every rank would render the
     * whole image and write the same file. */
    if (getenv("OMPI_COMM_WORLD_SIZE") && atoi(getenv("OMPI_COMM_WORLD_SIZE")) > 1) {
        snprintf(err, (size_t)errlen, "started by mpirun, but built without Open MPI (configure --with-mpi)");
        return -1;
    }
    return 0;
}

void mpi_job_finalize(void) {}
void mpi_job_abort(int status) { (void)status; }
int mpi_job_rank(void) { return 0; }
int mpi_job_size(void) { return 1; }
int mpi_job_built(void) { return 0; }
int mpi_job_local_size(void) { return 1; }
void mpi_job_broadcast(void *data, size_t n)
{
    (void)data;
    (void)n;
}
int mpi_job_max(int value) { return value; }

int mpi_tiles_begin(MpiTiles *t, const TileGrid *grid, int threads)
{
    (void)threads;
    (void)t;
    (void)grid;
    return -1; /* never asked for: one process renders all its tiles */
}

int mpi_tiles_end(MpiTiles *t, const TileGrid *grid, int status, Image *img, AovImage *aov, RenderStats *total,
                  RenderStats *per_rank, MpiTileWaits *waits, double *tile_seconds)
{
    (void)waits;
    (void)tile_seconds;
    (void)t;
    (void)grid;
    (void)img;
    (void)aov;
    (void)total;
    (void)per_rank;
    return status;
}
