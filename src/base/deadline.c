/* The current thread's deadline (deadline.h): one per thread, as each
 * render thread sets its own, and no thread waits on another to read it. */
#include "deadline.h"

#include "clock.h"

static _Thread_local double thread_deadline;
static _Thread_local unsigned steps;  /* deadline_step's count */
static _Thread_local int steps_past;  /* deadline_step saw the deadline pass */

void deadline_set(double when)
{
    thread_deadline = when;
    steps = 0;
    steps_past = 0;
}

int deadline_step(void)
{
    if (!steps_past && thread_deadline > 0.0 && (++steps & 0xFFFFu) == 0)
        steps_past = deadline_passed();
    return steps_past;
}

int deadline_passed(void)
{
    return thread_deadline > 0.0 && clock_wall() > thread_deadline;
}
