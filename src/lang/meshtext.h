/*
 * meshtext.h - what the OBJ and PLY readers share about text: blanks, line
 * ends (LF, CRLF or a lone CR) and tokens quoted in messages.
 */
#ifndef REFRAY_MESHTEXT_H
#define REFRAY_MESHTEXT_H

#include <stddef.h>
#include "base/source.h"

enum { MESHTEXT_SHOWN_MAX = 40 };   /* bytes of a token quoted in a message */

static inline int meshtext_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\v' || c == '\f';
}

static inline int meshtext_eol(char c)
{
    return c == '\n' || c == '\r';
}

/* Length of the line terminator at i of text[0..len): 2 for CRLF, 1 for LF
 * or a lone CR, else 0. */
static inline size_t meshtext_eol_length(const char *text, size_t len, size_t i)
{
    if (i >= len || !meshtext_eol(text[i]))
        return 0;
    return text[i] == '\r' && i + 1 < len && text[i + 1] == '\n' ? 2 : 1;
}

/* A token fit for quoting: at most MESHTEXT_SHOWN_MAX bytes, control bytes
 * as '?', "..." when cut.  Returned by value into a caller's variable (a
 * function result must not be read after the call in C99). */
typedef struct meshtext_shown {
    char s[MESHTEXT_SHOWN_MAX + 4];
} meshtext_shown;

meshtext_shown meshtext_show(const char *text, src_span tok);

#endif
