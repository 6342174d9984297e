/* Running a few jobs side by side: job 0 on the calling thread, the others
 * on threads of their own, all joined before it returns. The builds that
 * split their input into runs (the grid's registrations, the hierarchy's
 * set-up) use it; each job writes only its own record, and the caller
 * merges the records in job order, so results never depend on how many
 * jobs ran. */
#ifndef HST_PARALLEL_H
#define HST_PARALLEL_H

#include <stddef.h>

/* The most jobs parallel_jobs asks for: a caller's array of records. */
#define PARALLEL_MAX_JOBS 64

/* Runs fn on jobs[0], jobs[1], ... jobs[n - 1] (records of `size` bytes).
 * A job whose thread cannot be started runs on the calling thread. */
void parallel_run(int n, void *(*fn)(void *), void *jobs, size_t size);

/* How many jobs of at least `per_job` items each `items` makes, up to
 * `threads` (at least 1). */
int parallel_jobs(long items, long per_job, int threads);

#endif
