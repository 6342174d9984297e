/* `hstrace stitch PART... -o FULL`: partial renders (+SR +ER +SC +EC, one
 * per job of a Slurm job array or GNU parallel) joined into the image one
 * render makes, bit for bit in every channel. Each part's area and options
 * come from its EXR header (stitch_plan.h reads them); the parts must agree
 * on the scene, the version and the options and fill the image exactly
 * once, else nothing is written. The command line is stitch_options.h's. */
#ifndef HST_STITCH_H
#define HST_STITCH_H

/* Exit statuses, documented in the man page; 1 and 3 mean what they mean
 * when rendering. */
enum {
    STITCH_EXIT_OK = 0,
    STITCH_EXIT_USAGE = 1, /* bad command line; parts that do not make one image (overlap, gap, another
                              scene, version, size, channel set or options) */
    STITCH_EXIT_IO = 3,    /* a part missing, unreadable, or not an EXR hstrace wrote; FULL unwritable */
};

/* Runs the command; argv[0] is "stitch", self is the program's own argv[0]
 * (for the command line recorded in FULL's header). Returns the exit
 * status. */
int stitch_main(int argc, char **argv, const char *self);

#endif
