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

/* One member on its own line, `indent"key": value`, followed by ",\n"
 * (or "\n" for the last member of an object, last != 0). */
void json_key_string(FILE *f, const char *indent, const char *key, const char *v, int last);
void json_key_number(FILE *f, const char *indent, const char *key, double v, int last);
void json_key_count(FILE *f, const char *indent, const char *key, long v, int last);

#endif
