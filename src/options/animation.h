/* POV-Ray's animations: which frames a command line asks for, the clock of
 * each, and the file each frame is written to, as POV-Ray 3.7 computes
 * them (frontend/animationprocessing.cpp, and checked against 3.7.0.10):
 *
 *   initial_frame  = max(+KFI, 0)                 (default 1)
 *   final_frame    = max(+KFF, initial_frame)     (default 1), one more with +KC
 *   clock_delta    = (+KF - +KI) / (final_frame - initial_frame)
 *   clock(frame)   = clock_delta * (frame - initial_frame) + +KI, in float
 *
 * rendering frames +SF .. +EF (a value below 1 other than 0 is a fraction
 * of the frames; without +EF, the final frame, or the one before it with
 * +KC), every +STP-th of them from +SF's (Frame_Step; below 1 is 1). It animates when +KFF is above +KFI; else a still is rendered, with
 * clock +K (clock_on true when +K is given) and the other values 0. Frame n of "name.ext" is written to "nameNNN.ext", the number
 * padded with zeros to the digits of the final frame. */
#ifndef HST_ANIMATION_H
#define HST_ANIMATION_H

#include "options.h"

typedef struct {
    int animated;           /* 0: a still */
    int first, last;        /* the frames rendered, inclusive: first, first + step, ... up to last */
    int step;               /* Frame_Step, 1 or more */
    int initial_frame, final_frame;
    double initial_clock, final_clock, clock_delta;
    double still_clock;     /* +K, for a still */
    int still_clock_on;     /* +K given */
    int digits;             /* of the final frame, for the file names */
} Animation;

/* Returns 0, or -1 with a message (an empty range of frames). */
int animation_plan(const Options *opt, Animation *a, char *err, int errlen);

/* How many frames are rendered. */
int animation_frames(const Animation *a);

/* The clock of frame n, as the scene sees it (single precision, as POV-Ray
 * keeps it); a still's is +K's. */
double animation_clock(const Animation *a, int frame);

/* A value POV-Ray 3.7 hands the scene as a declared float (Declare=, and
 * clock_delta, initial_clock, final_clock, the frame numbers): kept in
 * single precision, then written with 6 significant digits and read back
 * (1.23456789 becomes 1.23457, 1/6 becomes 0.166667). */
double pov_declared_value(double v);

/* "name.ext" with frame n's number before the extension (malloc'd; NULL
 * when out of memory). */
char *animation_file_name(const char *output, int frame, int digits);

#endif
