#include "parallel.h"

#include <pthread.h>

void parallel_run(int n, void *(*fn)(void *), void *jobs, size_t size)
{
    char *rec = jobs;
    if (n > PARALLEL_MAX_JOBS) { /* never asked for (parallel_jobs caps it); stay correct all the same */
        for (int i = 0; i < n; i++)
            fn(rec + size * (size_t)i);
        return;
    }
    pthread_t tids[PARALLEL_MAX_JOBS];
    int spawned[PARALLEL_MAX_JOBS] = { 0 };
    for (int i = 1; i < n; i++)
        spawned[i] = pthread_create(&tids[i], NULL, fn, rec + size * (size_t)i) == 0;
    if (n > 0)
        fn(rec);
    for (int i = 1; i < n; i++) {
        if (spawned[i])
            pthread_join(tids[i], NULL);
        else
            fn(rec + size * (size_t)i);
    }
}

int parallel_jobs(long items, long per_job, int threads)
{
    long n = per_job > 0 ? items / per_job : items;
    if (n > threads)
        n = threads;
    if (n > PARALLEL_MAX_JOBS)
        n = PARALLEL_MAX_JOBS;
    return n < 1 ? 1 : (int)n;
}
