/* A render over Open MPI's ranks (mpi_job.h). Rank 0 runs a scheduler
 * thread beside its render threads: it answers each remote thread's request
 * with the next run of tiles (one shared counter for every rank, so a slow
 * rank simply asks less often) and notes who took them; at the end each
 * remote rank sends the pixels of its own tiles only, packed, and rank 0
 * puts them in place. Runs are guided: a share of what is left over twice the
 * threads of the whole job, so there are few requests while much is left
 * and single tiles at the end, where the balance is made. Every thread may
 * call MPI (MPI_THREAD_MULTIPLE); replies go to a tag of their own per
 * thread, so that two threads of one rank never take each other's tiles.
 * Waiting polls with short sleeps: Open MPI's blocking calls spin, and a
 * spinning scheduler would take a core from the render. */
#include "mpi_job.h"

#include <mpi.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { TAG_REQUEST = 1, TAG_FINISHED, TAG_PIXELS, TAG_STATS, TAG_TILE = 1000 };

/* Set once by mpi_job_init, before any thread starts; read-only after. */
static int job_rank = 0, job_size = 1, job_running = 0;

#define MAX_WORKERS 1024 /* threads of one rank (render_default_threads' bound) */

struct MpiTilesState {
    atomic_int next;   /* the next tile to hand out: rank 0's, shared by its threads and the scheduler */
    int *owner;        /* rank 0: who took each tile (-1: nobody) */
    unsigned char *mine; /* a remote rank: the tiles it was given (each marked by the thread given it) */
    int workers;       /* the threads of every rank together */
    pthread_t scheduler;
    int have_scheduler;
    /* A remote rank: each thread's run of tiles, [at, end), and what its
     * asking cost (each thread its own, summed at the end). */
    int at[MAX_WORKERS], end[MAX_WORKERS];
    long requests[MAX_WORKERS];
    double wait[MAX_WORKERS];
};

/* Waits for req without spinning on a core. */
static void wait_for(MPI_Request *req, MPI_Status *st)
{
    const struct timespec pause = { 0, 50000 }; /* 50 us */
    for (;;) {
        int done = 0;
        MPI_Test(req, &done, st);
        if (done)
            return;
        nanosleep(&pause, NULL);
    }
}

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

/* A tile for one of rank 0's threads, from the shared counter; -1 when
 * all are taken. */
static int next_on_root(TileSource *src, int worker)
{
    (void)worker;
    MpiTiles *t = (MpiTiles *)src;
    int tile = atomic_fetch_add(&t->state->next, 1);
    if (tile >= t->ntiles)
        return -1;
    t->state->owner[tile] = 0;
    return tile;
}

/* Rank 0, for a remote rank: a guided run of tiles, out[0] the first and
 * out[1] how many (0: none left). */
static void take_run(MpiTiles *t, int rank, int out[2])
{
    int first = atomic_load(&t->state->next), count;
    do {
        if (first >= t->ntiles) {
            out[0] = t->ntiles;
            out[1] = 0;
            return;
        }
        count = (t->ntiles - first) / (2 * t->state->workers);
        count = count < 1 ? 1 : count;
    } while (!atomic_compare_exchange_weak(&t->state->next, &first, first + count));
    for (int i = first; i < first + count; i++)
        t->state->owner[i] = rank;
    out[0] = first;
    out[1] = count;
}

static int next_remote(TileSource *src, int worker)
{
    MpiTiles *t = (MpiTiles *)src;
    struct MpiTilesState *st = t->state;
    if (worker < 0 || worker >= MAX_WORKERS)
        return -1;
    if (st->at[worker] >= st->end[worker]) {
        int run[2] = { 0, 0 };
        MPI_Request req;
        double t0 = MPI_Wtime();
        MPI_Send(&worker, 1, MPI_INT, 0, TAG_REQUEST, MPI_COMM_WORLD);
        MPI_Irecv(run, 2, MPI_INT, 0, TAG_TILE + worker, MPI_COMM_WORLD, &req);
        wait_for(&req, MPI_STATUS_IGNORE);
        st->requests[worker]++;
        st->wait[worker] += MPI_Wtime() - t0;
        st->at[worker] = run[0];
        st->end[worker] = run[0] + run[1];
        if (run[1] <= 0)
            return -1;
        memset(st->mine + run[0], 1, (size_t)run[1]);
    }
    return st->at[worker]++;
}

/* Rank 0: answers requests until every other rank has said it finished. */
static void *scheduler_main(void *arg)
{
    MpiTiles *t = arg;
    for (int finished = 0; finished < job_size - 1;) {
        int worker = 0;
        MPI_Status st;
        MPI_Request req;
        MPI_Irecv(&worker, 1, MPI_INT, MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &req);
        wait_for(&req, &st);
        if (st.MPI_TAG == TAG_FINISHED) {
            finished++;
            continue;
        }
        int run[2];
        take_run(t, st.MPI_SOURCE, run);
        MPI_Send(run, 2, MPI_INT, st.MPI_SOURCE, TAG_TILE + worker, MPI_COMM_WORLD);
    }
    return NULL;
}

int mpi_tiles_begin(MpiTiles *t, const TileGrid *grid, int threads)
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
    } else if (ok) {
        t->state->mine = calloc((size_t)(grid->ntiles > 0 ? grid->ntiles : 1), 1);
        ok = t->state->mine != NULL;
    }
    /* Every rank must be able to go on before any tile is handed out. */
    if (mpi_job_max(!ok) != 0) {
        if (t->state) {
            free(t->state->owner);
            free(t->state->mine);
        }
        free(t->state);
        t->state = NULL;
        return -1;
    }
    atomic_init(&t->state->next, 0);
    MPI_Allreduce(&threads, &t->state->workers, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    if (t->state->workers < 1)
        t->state->workers = 1;
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

/* Is tile `tile` rank r's? (rank 0 asks its table, a remote rank its marks) */
static int rank_has(const MpiTiles *t, int r, int tile)
{
    return job_rank == 0 ? t->state->owner[tile] == r : t->state->mine[tile] != 0;
}

/* The bytes of rank r's tiles in a plane of width-wide rows of samples of
 * `bytes` bytes: their rectangles, tile after tile, row after row. */
static size_t tiles_bytes(const MpiTiles *t, const TileGrid *grid, int r, size_t bytes)
{
    size_t n = 0;
    for (int tile = 0; tile < t->ntiles; tile++)
        if (rank_has(t, r, tile)) {
            int x0, y0, x1, y1;
            render_tile_area(grid, tile, &x0, &y0, &x1, &y1);
            n += (size_t)(x1 - x0) * (size_t)(y1 - y0) * bytes;
        }
    return n;
}

/* Copies rank r's tiles between a plane and a packed buffer: pack 1 plane
 * to buffer, 0 back. Only the tiles travel, so the job moves one image's
 * pixels whatever the number of ranks. */
static void pack_tiles(const MpiTiles *t, const TileGrid *grid, int r, int width, size_t bytes, void *plane,
                       unsigned char *packed, int pack)
{
    for (int tile = 0; tile < t->ntiles; tile++) {
        if (!rank_has(t, r, tile))
            continue;
        int x0, y0, x1, y1;
        render_tile_area(grid, tile, &x0, &y0, &x1, &y1);
        size_t row = (size_t)(x1 - x0) * bytes;
        for (int y = y0; y < y1; y++, packed += row) {
            char *at = (char *)plane + ((size_t)y * (size_t)width + (size_t)x0) * bytes;
            if (pack)
                memcpy(packed, at, row);
            else
                memcpy(at, packed, row);
        }
    }
}

/* MPI counts are ints: a large buffer goes in pieces of at most 1 GiB. */
#define PIECE ((size_t)1 << 30)
static void send_bytes(const unsigned char *p, size_t n, int to)
{
    for (size_t at = 0; at < n; at += PIECE)
        MPI_Send(p + at, (int)(n - at < PIECE ? n - at : PIECE), MPI_BYTE, to, TAG_PIXELS, MPI_COMM_WORLD);
}
static void recv_bytes(unsigned char *p, size_t n, int from)
{
    for (size_t at = 0; at < n; at += PIECE)
        MPI_Recv(p + at, (int)(n - at < PIECE ? n - at : PIECE), MPI_BYTE, from, TAG_PIXELS, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
}

/* The colour and analysis planes of rank r's tiles, to rank 0 (from r) or
 * from r (on rank 0). Returns -1 when out of memory. */
static int move_tiles(const MpiTiles *t, const TileGrid *grid, int r, Image *img, AovImage *aov)
{
    const int w = img->width;
    const size_t pixels = (size_t)w * (size_t)img->height;
    size_t colour = tiles_bytes(t, grid, r, 4 * sizeof(float)), plane = tiles_bytes(t, grid, r, 4);
    unsigned char *buf = malloc(colour > 0 ? colour : 1);
    if (!buf)
        return -1;
    const int sending = job_rank != 0;
    if (sending) {
        pack_tiles(t, grid, r, w, 4 * sizeof(float), img->rgba, buf, 1);
        send_bytes(buf, colour, 0);
    } else {
        recv_bytes(buf, colour, r);
        pack_tiles(t, grid, r, w, 4 * sizeof(float), img->rgba, buf, 0);
    }
    for (int c = 0; aov && c < aov->nchannels; c++) {
        char *p = (char *)aov->planes + (size_t)c * pixels * 4;
        if (sending) {
            pack_tiles(t, grid, r, w, 4, p, buf, 1);
            send_bytes(buf, plane, 0);
        } else {
            recv_bytes(buf, plane, r);
            pack_tiles(t, grid, r, w, 4, p, buf, 0);
        }
    }
    free(buf);
    return 0;
}

int mpi_tiles_end(MpiTiles *t, const TileGrid *grid, int status, Image *img, AovImage *aov, RenderStats *total,
                  RenderStats *per_rank, MpiTileWaits *waits, double *tile_seconds)
{
    MpiTileWaits mine = { 0, 0.0 };
    for (int i = 0; job_rank != 0 && i < MAX_WORKERS; i++) {
        mine.requests += t->state->requests[i];
        mine.wait_seconds += t->state->wait[i];
    }
    if (job_rank != 0)
        MPI_Send(&job_rank, 1, MPI_INT, 0, TAG_FINISHED, MPI_COMM_WORLD);
    else if (t->state->have_scheduler)
        pthread_join(t->state->scheduler, NULL);
    int failed = mpi_job_max(status != 0);
    if (!failed && job_rank == 0) {
        for (int tile = 0; tile < t->ntiles; tile++)
            failed |= t->state->owner[tile] < 0;
        if (per_rank)
            per_rank[0] = *total;
        if (waits)
            waits[0] = mine;
        for (int r = 1; r < job_size; r++) {
            if (move_tiles(t, grid, r, img, aov)) {
                fprintf(stderr, "hstrace: rank 0: out of memory for rank %d's pixels\n", r);
                mpi_job_abort(3);
            }
            RenderStats part;
            MPI_Recv(&part, (int)sizeof part, MPI_BYTE, r, TAG_STATS, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            if (per_rank)
                per_rank[r] = part;
            stats_add(total, &part);
            MpiTileWaits asked;
            MPI_Recv(&asked, (int)sizeof asked, MPI_BYTE, r, TAG_STATS, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            if (waits)
                waits[r] = asked;
        }
    } else if (!failed) {
        if (move_tiles(t, grid, job_rank, img, aov)) {
            fprintf(stderr, "hstrace: rank %d: out of memory for its pixels\n", job_rank);
            mpi_job_abort(3);
        }
        MPI_Send(total, (int)sizeof *total, MPI_BYTE, 0, TAG_STATS, MPI_COMM_WORLD);
        MPI_Send(&mine, (int)sizeof mine, MPI_BYTE, 0, TAG_STATS, MPI_COMM_WORLD);
    }
    /* Every tile was one rank's: the others hold 0 for it. */
    if (!failed && tile_seconds)
        MPI_Reduce(job_rank == 0 ? MPI_IN_PLACE : tile_seconds, tile_seconds, t->ntiles, MPI_DOUBLE, MPI_SUM, 0,
                   MPI_COMM_WORLD);
    if (t->state) {
        free(t->state->owner);
        free(t->state->mine);
    }
    free(t->state);
    t->state = NULL;
    return mpi_job_max(failed) ? -1 : 0;
}
