/* POV-Ray's reserved words as an enum, so the parser compares integers and
 * can tell "a keyword hstrace does not support" from "an unknown name". */
#ifndef HST_KEYWORDS_H
#define HST_KEYWORDS_H

enum {
#define KW(w) KW_##w,
#include "keywords.def"
#undef KW
    KW_COUNT
};

/* The keyword id of `len` bytes at `s`, or -1 when it is not reserved. */
int tok_keyword_lookup(const char *s, int len);
const char *tok_keyword_name(int kw);

#endif
