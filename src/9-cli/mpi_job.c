/* A render over Open MPI's ranks (mpi_job.h). Rank 0 runs a scheduler
 * thread beside its render threads: it answers each remote thread's request
 * with the next tile (one shared counter for every rank, so a slow rank
 * simply asks less often) and notes who took it; at the end each remote
 * rank sends its whole image, rank 0 keeps the tiles that rank rendered.
 * Every thread may call MPI (MPI_THREAD_MULTIPLE); replies go to a tag of
 * their own per thread, so that two threads of one rank never take each
 * other's tile. */
#include "mpi_job.h"

#include <mpi.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { TAG_REQUEST = 1, TAG_FINISHED, TAG_PIXELS, TAG_PLANE, TAG_STATS, TAG_TILE = 1000 };

/* Set once by mpi_job_init, before any thread starts; read-only after. */
static int job_rank = 0, job_size = 1, job_running = 0;

struct MpiTilesState {
    atomic_int next;   /* the next tile to hand out: rank 0's, shared by its threads and the scheduler */
    int *owner;        /* rank 0: who took each tile (-1: nobody) */
    pthread_t scheduler;
    int have_scheduler;
};

int mpi_job_init(int *argc, char ***argv, char *err, int errlen)
{
    /* Outside mpirun hstrace is one process and MPI is never started. */
    if (!getenv("OMPI_COMM_WORLD_SIZE") && !getenv("PMIX_RANK"))
        return 0;
    int provided = 0;
    if (MPI_Init_thread(argc, argv, MPI_THREAD_MULTIPLE, &provided) != MPI_SUCCESS) {
        snprintf(err, (size_t)errlen, "MPI could not start");
        return -1;
    }
    job_running = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &job_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &job_size);
    if (provided < MPI_THREAD_MULTIPLE && job_size > 1) {
        snprintf(err, (size_t)errlen, "this Open MPI gives no MPI_THREAD_MULTIPLE (level %d): tiles cannot be "
                 "handed to threads", provided);
        return -1;
    }
    return 0;
}

void mpi_job_finalize(void)
{
    if (job_running)
        MPI_Finalize();
    job_running = 0;
}

void mpi_job_abort(int status)
{
    if (job_running && job_size > 1)
        MPI_Abort(MPI_COMM_WORLD, status);
}

int mpi_job_rank(void) { return job_rank; }
int mpi_job_size(void) { return job_size; }
int mpi_job_built(void) { return 1; }

int mpi_job_local_size(void)
{
    const char *s = getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
    int n = s ? atoi(s) : 1;
    return n >= 1 ? n : 1;
}

void mpi_job_broadcast(void *data, size_t n)
{
    if (job_size > 1)
        MPI_Bcast(data, (int)n, MPI_BYTE, 0, MPI_COMM_WORLD);
}

int mpi_job_max(int value)
{
    int out = value;
    if (job_size > 1)
        MPI_Allreduce(&value, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return out;
}

/* A tile for `rank`, from the shared counter; -1 when all are taken. */
static int take(MpiTiles *t, int rank)
{
    int tile = atomic_fetch_add(&t->state->next, 1);
    if (tile >= t->ntiles)
        return -1;
    t->state->owner[tile] = rank;
    return tile;
}

static int next_on_root(TileSource *src, int worker)
{
    (void)worker;
    return take((MpiTiles *)src, 0);
}

static int next_remote(TileSource *src, int worker)
{
    (void)src;
    int tile = -1;
    MPI_Send(&worker, 1, MPI_INT, 0, TAG_REQUEST, MPI_COMM_WORLD);
    MPI_Recv(&tile, 1, MPI_INT, 0, TAG_TILE + worker, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return tile;
}

/* Rank 0: answers requests until every other rank has said it finished. */
static void *scheduler_main(void *arg)
{
    MpiTiles *t = arg;
    for (int finished = 0; finished < job_size - 1;) {
        int worker = 0;
        MPI_Status st;
        MPI_Recv(&worker, 1, MPI_INT, MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &st);
        if (st.MPI_TAG == TAG_FINISHED) {
            finished++;
            continue;
        }
        int tile = take(t, st.MPI_SOURCE);
        MPI_Send(&tile, 1, MPI_INT, st.MPI_SOURCE, TAG_TILE + worker, MPI_COMM_WORLD);
    }
    return NULL;
}

int mpi_tiles_begin(MpiTiles *t, const TileGrid *grid)
{
    memset(t, 0, sizeof *t);
    t->ntiles = grid->ntiles;
    t->state = calloc(1, sizeof *t->state);
    int ok = t->state != NULL;
    if (ok && job_rank == 0) {
        t->state->owner = malloc(sizeof *t->state->owner * (size_t)(grid->ntiles > 0 ? grid->ntiles : 1));
        ok = t->state->owner != NULL;
        for (int i = 0; ok && i < grid->ntiles; i++)
            t->state->owner[i] = -1;
    }
    /* Every rank must be able to go on before any tile is handed out. */
    if (mpi_job_max(!ok) != 0) {
        if (t->state)
            free(t->state->owner);
        free(t->state);
        t->state = NULL;
        return -1;
    }
    atomic_init(&t->state->next, 0);
    t->source.next = job_rank == 0 ? next_on_root : next_remote;
    if (job_rank == 0) {
        if (pthread_create(&t->state->scheduler, NULL, scheduler_main, t) != 0) {
            fprintf(stderr, "hstrace: rank 0 cannot start the tile scheduler's thread\n");
            mpi_job_abort(3);
        }
        t->state->have_scheduler = 1;
    }
    return 0;
}

/* Rank 0 copies into dst the rectangles of the tiles rank `r` rendered,
 * from src (both width*height samples of `bytes` bytes each). */
static void keep_tiles(const MpiTiles *t, const TileGrid *grid, int r, int width, size_t bytes, void *dst,
                       const void *src)
{
    for (int tile = 0; tile < t->ntiles; tile++) {
        if (t->state->owner[tile] != r)
            continue;
        int x0, y0, x1, y1;
        render_tile_area(grid, tile, &x0, &y0, &x1, &y1);
        for (int y = y0; y < y1; y++) {
            size_t at = ((size_t)y * (size_t)width + (size_t)x0) * bytes;
            memcpy((char *)dst + at, (const char *)src + at, (size_t)(x1 - x0) * bytes);
        }
    }
}

int mpi_tiles_end(MpiTiles *t, const TileGrid *grid, int status, Image *img, AovImage *aov, RenderStats *total,
                  RenderStats *per_rank)
{
    if (job_rank != 0)
        MPI_Send(&job_rank, 1, MPI_INT, 0, TAG_FINISHED, MPI_COMM_WORLD);
    else if (t->state->have_scheduler)
        pthread_join(t->state->scheduler, NULL);
    int failed = mpi_job_max(status != 0);
    const int w = img->width, h = img->height;
    const size_t pixels = (size_t)w * (size_t)h;
    if (!failed && job_rank == 0) {
        for (int tile = 0; tile < t->ntiles; tile++)
            failed |= t->state->owner[tile] < 0;
        if (per_rank)
            per_rank[0] = *total;
        float *buf = malloc(pixels * 4 * sizeof *buf);
        if (!buf) {
            fprintf(stderr, "hstrace: rank 0: out of memory for the other ranks' pixels\n");
            mpi_job_abort(3);
        }
        for (int r = 1; r < job_size; r++) {
            MPI_Recv(buf, (int)(pixels * 4), MPI_FLOAT, r, TAG_PIXELS, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            keep_tiles(t, grid, r, w, 4 * sizeof(float), img->rgba, buf);
            for (int c = 0; aov && c < aov->nchannels; c++) {
                char *plane = (char *)aov->planes + (size_t)c * pixels * 4;
                MPI_Recv(buf, (int)(pixels * 4), MPI_BYTE, r, TAG_PLANE, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                keep_tiles(t, grid, r, w, 4, plane, buf);
            }
            RenderStats part;
            MPI_Recv(&part, (int)sizeof part, MPI_BYTE, r, TAG_STATS, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            if (per_rank)
                per_rank[r] = part;
            stats_add(total, &part);
        }
        free(buf);
    } else if (!failed) {
        MPI_Send(img->rgba, (int)(pixels * 4), MPI_FLOAT, 0, TAG_PIXELS, MPI_COMM_WORLD);
        for (int c = 0; aov && c < aov->nchannels; c++)
            MPI_Send((char *)aov->planes + (size_t)c * pixels * 4, (int)(pixels * 4), MPI_BYTE, 0, TAG_PLANE,
                     MPI_COMM_WORLD);
        MPI_Send(total, (int)sizeof *total, MPI_BYTE, 0, TAG_STATS, MPI_COMM_WORLD);
    }
    if (t->state)
        free(t->state->owner);
    free(t->state);
    t->state = NULL;
    return mpi_job_max(failed) ? -1 : 0;
}
