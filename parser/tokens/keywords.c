/* Reserved-word lookup: keywords.def is sorted, so a binary search does. */
#include "keywords.h"

#include <string.h>

static const char *const keyword_names[KW_COUNT] = {
#define KW(w) #w,
#include "keywords.def"
#undef KW
};

int tok_keyword_lookup(const char *s, int len)
{
    int lo = 0, hi = KW_COUNT - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        const char *k = keyword_names[mid];
        int c = strncmp(k, s, (size_t)len);
        if (c == 0 && k[len] != '\0')
            c = 1; /* k is longer than s, so it sorts after it */
        if (c == 0)
            return mid;
        if (c < 0)
            lo = mid + 1;
        else
            hi = mid - 1;
    }
    return -1;
}

const char *tok_keyword_name(int kw)
{
    return kw >= 0 && kw < KW_COUNT ? keyword_names[kw] : "?";
}
