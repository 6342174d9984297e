/* The time the current thread's work must end by (--max-render-seconds),
 * for computations whose one step can run for seconds: a fractal pattern
 * of max_iteration 2^31 is one colour of one ray, so the render's check
 * between rays would come only after hours. Such loops ask now and then
 * and give up once it has passed; the render is then discarded. */
#ifndef HST_DEADLINE_H
#define HST_DEADLINE_H

/* Sets this thread's deadline, a clock_wall() time (0: none). */
void deadline_set(double when);

/* Whether this thread's deadline has passed (a clock read: call it every
 * many thousand steps, not every step). */
int deadline_passed(void);

#endif
