/* A command line written back as one line a POSIX shell reads as the same
 * words: for the EXR header's record of how a file was made. */
#ifndef HST_SHELL_WORDS_H
#define HST_SHELL_WORDS_H

/* argv[0..argc-1] joined by spaces, each word that holds anything but
 * letters, digits and _+-=,./:@%^ in single quotes (a quote inside as
 * '\''). Returns a malloc'd string, or NULL when out of memory. */
char *shell_quote_words(int argc, char *const *argv);

#endif
