/* The two clocks hstrace measures with: wall time for what users wait for,
 * a thread's CPU time for work on a shared, busy machine. */
#ifndef HST_CLOCK_H
#define HST_CLOCK_H

/* Monotonic wall clock and this thread's CPU clock, in seconds. */
double clock_wall(void);
double clock_thread_cpu(void);

#endif
