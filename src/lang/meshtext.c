/*
 * meshtext.c - quoting a token of a mesh file in a message (meshtext.h).
 */
#include <string.h>
#include "lang/meshtext.h"

meshtext_shown meshtext_show(const char *text, src_span tok)
{
    meshtext_shown out;
    size_t n = tok.end - tok.begin, k = 0;
    for (; k < n && k < MESHTEXT_SHOWN_MAX; k++) {
        unsigned char c = (unsigned char)text[tok.begin + k];
        out.s[k] = c < 0x20 || c == 0x7f ? '?' : (char)c;
    }
    if (k < n) {
        memcpy(out.s + k, "...", 3);
        k += 3;
    }
    out.s[k] = '\0';
    return out;
}
