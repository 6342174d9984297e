/* The time the current thread's work must end by (--max-render-seconds),
 * for computations whose one step can run for seconds: a fractal pattern
 * of max_iteration 2^31, or a pigment of averages nested 40 deep, is one
 * colour of one ray, so the render's check between rays would come only
 * after hours. Such work asks now and then and gives up once it has
 * passed; the render is then discarded. */
#ifndef HST_DEADLINE_H
#define HST_DEADLINE_H

/* Sets this thread's deadline, a clock_wall() time (0: none). */
void deadline_set(double when);

/* Whether this thread's deadline has passed (a clock read: call it every
 * many thousand steps, not every step). */
int deadline_passed(void);

/* A step of work counted: every 2^16 steps the clock is read, and once
 * the deadline has passed every step says so at once, without the clock
 * (for work that branches: a pigment or normal of nested averages asks
 * for 2^40 values at one point, each of which must then end at once). Cleared by
 * deadline_set. */
int deadline_step(void);

#endif
