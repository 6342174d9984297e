/* `hstrace vs-povray SCENE.pov [options]`: the scene rendered by POV-Ray and
 * by hstrace under each shadow method, at the same size and thread count,
 * in a private temporary folder (removed whatever happens, a termination
 * signal included); then one table: wall, CPU and shadow-testing time,
 * speed-up against POV-Ray, RMSE and shadow-mask disagreements against
 * POV-Ray's renders (image_compare.h, mask_compare.h). --report DIR adds an
 * HTML page with the images. The command line is in vs_povray_options.h,
 * the outputs in vs_povray_report.h, the child processes in process.h.
 *
 * Every program runs as a child process: POV-Ray as HSTRACE_POVRAY names it
 * or as found in PATH, hstrace by re-executing this program
 * (/proc/self/exe, else argv[0]). Each full render (+Q9) is timed by this
 * process from fork to exit; the shadow masks come from extra +Q3 and +Q4
 * renders of both programs (untimed). */
#ifndef HST_VS_POVRAY_H
#define HST_VS_POVRAY_H

/* Exit statuses, documented in the man page; 0 to 3 mean what they mean
 * when rendering. */
enum {
    VS_EXIT_OK = 0,
    VS_EXIT_USAGE = 1,          /* bad command line */
    VS_EXIT_SCENE = 2,          /* hstrace rejected the scene (its FILE:LINE:COLUMN message is shown) */
    VS_EXIT_IO = 3,             /* a file could not be read or written; hstrace failed otherwise */
    VS_EXIT_NO_POVRAY = 4,      /* POV-Ray is not installed (or HSTRACE_POVRAY names no program) */
    VS_EXIT_POVRAY_FAILED = 5,  /* POV-Ray failed on the scene (the end of its output is shown) */
};

/* Runs the command; argv[0] is "vs-povray", self is the program's own
 * argv[0]. Returns the exit status. */
int vs_povray_main(int argc, char **argv, const char *self);

#endif
