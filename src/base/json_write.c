/* JSON strings and numbers. */
#include "json_write.h"

#include <math.h>

void json_write_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (const unsigned char *c = (const unsigned char *)s; *c; c++) {
        if (*c == '"' || *c == '\\')
            fprintf(f, "\\%c", *c);
        else if (*c < 0x20)
            fprintf(f, "\\u%04x", *c);
        else
            fputc(*c, f);
    }
    fputc('"', f);
}

void json_write_number(FILE *f, double v)
{
    if (isfinite(v))
        fprintf(f, "%.9g", v);
    else
        fprintf(f, "null");
}

void json_key_string(FILE *f, const char *indent, const char *key, const char *v, int last)
{
    fprintf(f, "%s\"%s\": ", indent, key);
    json_write_string(f, v);
    fputs(last ? "\n" : ",\n", f);
}

void json_key_number(FILE *f, const char *indent, const char *key, double v, int last)
{
    fprintf(f, "%s\"%s\": ", indent, key);
    json_write_number(f, v);
    fputs(last ? "\n" : ",\n", f);
}

void json_key_count(FILE *f, const char *indent, const char *key, long v, int last)
{
    fprintf(f, "%s\"%s\": %ld%s", indent, key, v, last ? "\n" : ",\n");
}
