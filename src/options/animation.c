/* POV-Ray's frames, clocks and frame file names (animation.h). */
#include "animation.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* +SF/+EF: a frame number, or a fraction of the frames when below 1 (and
 * not 0), as POV-Ray reads them. */
static int subset_frame(double v, const Animation *a)
{
    if (v == 0.0 || v >= 1.0)
        return (int)v;
    return (int)((a->final_frame - a->initial_frame + 1) * v);
}

/* The largest frame number +SF/+EF may name: that of +KFF (frame numbers
 * are ints; a larger double has no frame, and (int) of it is undefined). */
#define SUBSET_FRAME_MAX 1000000000.0

static int subset_in_range(double v, const char *what, char *err, int errlen)
{
    if (v >= 0.0 && v <= SUBSET_FRAME_MAX)
        return 0;
    snprintf(err, (size_t)errlen, "the subset's %s frame (%g) is not a frame number from 0 to %.0f", what, v,
             SUBSET_FRAME_MAX);
    return -1;
}

int animation_plan(const Options *opt, Animation *a, char *err, int errlen)
{
    memset(a, 0, sizeof *a);
    a->step = opt->frame_step > 1 ? opt->frame_step : 1;
    a->still_clock = (float)opt->clock;
    a->still_clock_on = opt->have_clock;
    a->initial_frame = opt->initial_frame > 0 ? opt->initial_frame : 0;
    a->final_frame = opt->final_frame > a->initial_frame ? opt->final_frame : a->initial_frame;
    a->initial_clock = opt->initial_clock;
    a->final_clock = opt->final_clock;
    a->animated = opt->final_frame > opt->initial_frame;
    if (!a->animated) {
        a->first = a->last = a->initial_frame;
        return 0;
    }
    if (opt->cyclic)
        a->final_frame++;
    a->first = a->initial_frame;
    if ((opt->have_subset_start && subset_in_range(opt->subset_start, "start", err, errlen)) ||
        (opt->have_subset_end && subset_in_range(opt->subset_end, "end", err, errlen)))
        return -1;
    if (opt->have_subset_start) {
        a->first = subset_frame(opt->subset_start, a);
        if (a->first < a->initial_frame)
            a->first = a->initial_frame;
    }
    if (opt->have_subset_end) {
        a->last = subset_frame(opt->subset_end, a);
        if (a->last < a->first)
            a->last = a->first;
    } else {
        a->last = a->final_frame - (opt->cyclic ? 1 : 0);
    }
    if (a->first > a->last || a->first > a->final_frame) {
        snprintf(err, (size_t)errlen, "no frame to render: frames %d to %d of %d to %d", a->first, a->last,
                 a->initial_frame, a->final_frame);
        return -1;
    }
    a->clock_delta = (a->final_clock - a->initial_clock) / (double)(a->final_frame - a->initial_frame);
    a->digits = 1;
    for (int i = a->final_frame; i >= 10; i /= 10)
        a->digits++;
    return 0;
}

int animation_frames(const Animation *a)
{
    return (a->last - a->first) / a->step + 1;
}

double animation_clock(const Animation *a, int frame)
{
    if (!a->animated)
        return a->still_clock;
    return (float)(a->clock_delta * (double)(frame - a->initial_frame) + a->initial_clock);
}

double pov_declared_value(double v)
{
    char buf[40];
    snprintf(buf, sizeof buf, "%g", (double)(float)v);
    return strtod(buf, NULL);
}

char *animation_file_name(const char *output, int frame, int digits)
{
    const char *base = strrchr(output, '/');
    base = base ? base + 1 : output;
    const char *dot = strrchr(base, '.');
    size_t stem = dot && dot != base ? (size_t)(dot - output) : strlen(output);
    size_t n = strlen(output) + 16 + (size_t)digits;
    char *name = malloc(n);
    if (name)
        snprintf(name, n, "%.*s%0*d%s", (int)stem, output, digits, frame, output + stem);
    return name;
}
