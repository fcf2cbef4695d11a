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

static int printable(unsigned char c)
{
    return c >= 0x20 && c < 0x7f;
}

/* Escapes in[from..to) into out at *o, up to room bytes in all. */
static void escape_range(const unsigned char *in, size_t from, size_t to, char *out, size_t *o)
{
    static const char hex[] = "0123456789abcdef";
    for (size_t i = from; i < to; i++) {
        if (printable(in[i])) {
            out[(*o)++] = (char)in[i];
            continue;
        }
        out[(*o)++] = '\\';
        out[(*o)++] = 'x';
        out[(*o)++] = hex[in[i] >> 4];
        out[(*o)++] = hex[in[i] & 15];
    }
}

size_t text_escape(const char *in, size_t len, char *out, size_t out_size)
{
    const unsigned char *p = (const unsigned char *)in;
    size_t o = 0, need = 0;
    if (out_size == 0)
        return 0;
    for (size_t i = 0; i < len; i++)
        need += printable(p[i]) ? 1 : 4;
    if (need < out_size) {
        escape_range(p, 0, len, out, &o);
        out[o] = '\0';
        return o;
    }
    /* Too long: a head and a tail of whole escapes, "..." between. */
    size_t room = out_size > 4 ? out_size - 4 : 0, head_room = room * 2 / 3, head = 0, tail = len, used = 0;
    while (head < len && used + (printable(p[head]) ? 1 : 4) <= head_room)
        used += printable(p[head++]) ? 1 : 4;
    while (tail > head && used + (printable(p[tail - 1]) ? 1 : 4) <= room)
        used += printable(p[--tail]) ? 1 : 4;
    escape_range(p, 0, head, out, &o);
    if (out_size > 4) {
        memcpy(out + o, "...", 3);
        o += 3;
    }
    escape_range(p, tail, len, out, &o);
    out[o] = '\0';
    return o;
}
