/* JSON output shared by the subcommands' --json (compare_report.c,
 * vs_povray_report.c): strings escaped, numbers with no infinities. */
#ifndef HST_JSON_WRITE_H
#define HST_JSON_WRITE_H

#include <stdio.h>

/* s as a quoted JSON string: '"' and '\' escaped, control characters as
 * \u00XX; other bytes (UTF-8) as they are. */
void json_write_string(FILE *f, const char *s);

/* v with 9 significant digits; JSON has no infinity or NaN, so those are
 * null (the PSNR of equal images, a time not measured). */
void json_write_number(FILE *f, double v);

#endif
