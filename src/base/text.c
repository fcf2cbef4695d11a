/*
 * text.c - see text.h.
 */
#include <string.h>
#include "base/text.h"

/* The length of the well-formed UTF-8 sequence at p (n bytes left) when it
 * is 2 to 4 bytes long, else 0 (RFC 3629: no overlong forms, no
 * surrogates, nothing above U+10FFFF). */
static size_t utf8_sequence(const unsigned char *p, size_t n)
{
    size_t need;
    unsigned lo = 0x80, hi = 0xBF;
    if (p[0] >= 0xC2 && p[0] <= 0xDF)
        need = 2;
    else if (p[0] >= 0xE0 && p[0] <= 0xEF) {
        need = 3;
        lo = p[0] == 0xE0 ? 0xA0 : 0x80;
        hi = p[0] == 0xED ? 0x9F : 0xBF;
    } else if (p[0] >= 0xF0 && p[0] <= 0xF4) {
        need = 4;
        lo = p[0] == 0xF0 ? 0x90 : 0x80;
        hi = p[0] == 0xF4 ? 0x8F : 0xBF;
    } else
        return 0;
    if (n < need || p[1] < lo || p[1] > hi)
        return 0;
    for (size_t i = 2; i < need; i++)
        if (p[i] < 0x80 || p[i] > 0xBF)
            return 0;
    return need;
}

size_t text_clean(const char *in, size_t len, char *out, size_t out_size)
{
    const unsigned char *p = (const unsigned char *)in;
    size_t o = 0;
    if (out_size == 0)
        return 0;
    for (size_t i = 0; i < len;) {
        if (p[i] == '\r' && i + 1 < len && p[i + 1] == '\n') {
            i++;
            continue;
        }
        size_t seq = p[i] >= 0x80 ? utf8_sequence(p + i, len - i) : 0;
        size_t take = seq ? seq : 1;
        if (o + take >= out_size)
            break;
        if (seq)
            memcpy(out + o, p + i, seq);
        else
            out[o] = (p[i] >= 0x20 && p[i] < 0x7f) || p[i] == '\n' || p[i] == '\t' ? (char)p[i]
                     : p[i] == '\r' ? '\n' : '?';
        o += take;
        i += take;
    }
    out[o] = '\0';
    return o;
}

size_t text_tail(const char *text, size_t len, int max_lines, size_t max_bytes)
{
    size_t end = len;
    while (end > 0 && text[end - 1] == '\n')
        end--;
    size_t start = end;
    int lines = 1;
    while (start > 0 && end - start < max_bytes) {
        if (text[start - 1] == '\n' && ++lines > max_lines)
            break;
        start--;
    }
    /* Cut by bytes in the middle of a line: begin at its next line. */
    if (start > 0 && text[start - 1] != '\n') {
        const char *nl = memchr(text + start, '\n', end - start);
        if (nl)
            start = (size_t)(nl - text) + 1;
    }
    return start;
}
