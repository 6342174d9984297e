/* The current thread's deadline (deadline.h): one per thread, as each
 * render thread sets its own, and no thread waits on another to read it. */
#include "deadline.h"

#include "clock.h"

static _Thread_local double thread_deadline;

void deadline_set(double when)
{
    thread_deadline = when;
}

int deadline_passed(void)
{
    return thread_deadline > 0.0 && clock_wall() > thread_deadline;
}
