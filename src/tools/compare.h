/* `hstrace compare A B [options]`: how far apart two images are, and two
 * renderers' shadow masks, held to limits that decide the exit status. The
 * command line is in compare_options.h, the output in compare_report.h, the
 * figures in image_compare.h and mask_compare.h. */
#ifndef HST_COMPARE_H
#define HST_COMPARE_H

/* Exit statuses, documented in the man page (as cmp(1) and diff(1) use them). */
enum {
    COMPARE_EXIT_WITHIN = 0,  /* within every limit given */
    COMPARE_EXIT_OUTSIDE = 1, /* a limit not met */
    COMPARE_EXIT_TROUBLE = 2, /* bad usage; an image unreadable, of another size or unwritable */
};

/* Runs the command; argv[0] is "compare". Returns the exit status. */
int compare_main(int argc, char **argv);

#endif
