/*
 * jsonloc.c - see jsonloc.h.
 *
 * Invariant of the cursor: pos <= len always; every read checks pos < len,
 * so a text that is not valid JSON ends a walk early instead of running
 * past the end.  Nesting is skipped with a counter, not recursion, so a
 * deeply nested text cannot exhaust the stack.
 */
#include <string.h>
#include "base/jsonloc.h"

typedef struct cursor {
    const char *s;
    size_t len, pos;
} cursor;

static void skip_space(cursor *c)
{
    while (c->pos < c->len && (c->s[c->pos] == ' ' || c->s[c->pos] == '\t' || c->s[c->pos] == '\n' ||
                               c->s[c->pos] == '\r'))
        c->pos++;
}

static int peek(const cursor *c)
{
    return c->pos < c->len ? (unsigned char)c->s[c->pos] : -1;
}

/* At a '"': past the closing quote. */
static void skip_string(cursor *c)
{
    c->pos++;
    while (c->pos < c->len && c->s[c->pos] != '"')
        c->pos += c->s[c->pos] == '\\' && c->pos + 1 < c->len ? 2 : 1;
    if (c->pos < c->len)
        c->pos++;
}

/* At the first byte of a value: past its last byte. */
static void skip_value(cursor *c)
{
    int ch = peek(c);
    if (ch == '"') {
        skip_string(c);
        return;
    }
    if (ch != '{' && ch != '[') {
        while (c->pos < c->len && !strchr(",}] \t\r\n", c->s[c->pos]))
            c->pos++;
        return;
    }
    size_t depth = 0;
    do {
        ch = peek(c);
        if (ch == '"') {
            skip_string(c);
            continue;
        }
        if (ch == '{' || ch == '[')
            depth++;
        else if (ch == '}' || ch == ']')
            depth--;
        c->pos++;
    } while (depth > 0 && c->pos < c->len);
}

static unsigned hex4(const char *s)
{
    unsigned v = 0;
    for (int i = 0; i < 4; i++) {
        int ch = (unsigned char)s[i];
        v = v * 16 + (unsigned)(ch <= '9' ? ch - '0' : (ch | 0x20) - 'a' + 10);
    }
    return v;
}

static size_t put_utf8(unsigned cp, char *out)
{
    if (cp < 0x80) {
        out[0] = (char)cp;
        return 1;
    }
    if (cp < 0x800) {
        out[0] = (char)(0xc0 | cp >> 6);
        out[1] = (char)(0x80 | (cp & 0x3f));
        return 2;
    }
    if (cp < 0x10000) {
        out[0] = (char)(0xe0 | cp >> 12);
        out[1] = (char)(0x80 | (cp >> 6 & 0x3f));
        out[2] = (char)(0x80 | (cp & 0x3f));
        return 3;
    }
    out[0] = (char)(0xf0 | cp >> 18);
    out[1] = (char)(0x80 | (cp >> 12 & 0x3f));
    out[2] = (char)(0x80 | (cp >> 6 & 0x3f));
    out[3] = (char)(0x80 | (cp & 0x3f));
    return 4;
}

/* One character of a string body at s[*i] (before end), decoded into
 * out; returns its byte count. */
static size_t decode_char(const char *s, size_t end, size_t *i, char out[4])
{
    static const char plain[] = "\"\\/bfnrt", meant[] = "\"\\/\b\f\n\r\t";
    if (s[*i] != '\\' || *i + 1 >= end) {
        out[0] = s[(*i)++];
        return 1;
    }
    char e = s[*i + 1];
    const char *k = strchr(plain, e);
    if (e != 'u' || *i + 6 > end) {
        out[0] = k && e ? meant[k - plain] : e;
        *i += 2;
        return 1;
    }
    unsigned cp = hex4(s + *i + 2);
    *i += 6;
    if (cp >= 0xd800 && cp < 0xdc00 && *i + 6 <= end && s[*i] == '\\' && s[*i + 1] == 'u') {
        unsigned lo = hex4(s + *i + 2);
        if (lo >= 0xdc00 && lo < 0xe000) {
            cp = 0x10000 + ((cp - 0xd800) << 10) + (lo - 0xdc00);
            *i += 6;
        }
    }
    return put_utf8(cp, out);
}

/* Whether the quoted string at span [b, e) decodes to name. */
static int string_is(const char *s, size_t b, size_t e, const char *name)
{
    size_t i = b + 1, end = e > b + 1 ? e - 1 : b + 1, at = 0, want = strlen(name);
    char ch[4];
    while (i < end) {
        size_t n = decode_char(s, end, &i, ch);
        if (at + n > want || memcmp(name + at, ch, n) != 0)
            return 0;
        at += n;
    }
    return at == want;
}

/* Appends text[0..n) to buf with the pointer escapes; *used counts the
 * full length. */
static void put_escaped(char *buf, size_t size, size_t *used, const char *text, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        const char *piece = text[i] == '~' ? "~0" : text[i] == '/' ? "~1" : NULL;
        size_t k = piece ? 2 : 1;
        for (size_t j = 0; j < k; j++, (*used)++)
            if (*used + 1 < size)
                buf[*used] = piece ? piece[j] : text[i];
    }
    if (size)
        buf[*used < size ? *used : size - 1] = '\0';
}

/* Appends the step separator '/'. */
static void put_slash(char *buf, size_t size, size_t *used)
{
    if (*used + 1 < size)
        buf[*used] = '/';
    (*used)++;
    if (size)
        buf[*used < size ? *used : size - 1] = '\0';
}

static void put_index(char *buf, size_t size, size_t *used, size_t index)
{
    char digits[24];
    int n = 0;
    do {
        digits[sizeof digits - 1 - n++] = (char)('0' + index % 10);
        index /= 10;
    } while (index);
    put_slash(buf, size, used);
    put_escaped(buf, size, used, digits + sizeof digits - n, (size_t)n);
}

static void put_key(char *buf, size_t size, size_t *used, const char *s, size_t b, size_t e)
{
    size_t i = b + 1, end = e > b + 1 ? e - 1 : b + 1;
    char ch[4];
    put_slash(buf, size, used);
    while (i < end) {
        size_t n = decode_char(s, end, &i, ch);
        put_escaped(buf, size, used, ch, n);
    }
    if (size)
        buf[*used < size ? *used : size - 1] = '\0';
}

/* At a value that is an object or array: steps to its member `key` (or
 * element `index` when key is NULL).  Returns 1 with the cursor on the
 * member's value and its name's span in *name; 0 when it is not there. */
static int enter(cursor *c, const jsonloc_step *step, jsonloc_span *name)
{
    int object = peek(c) == '{';
    if (!object && peek(c) != '[')
        return 0;
    if (object != (step->key != NULL))
        return 0;
    c->pos++;
    for (size_t i = 0;; i++) {
        skip_space(c);
        if (peek(c) == '}' || peek(c) == ']' || peek(c) < 0)
            return 0;
        name->begin = name->end = c->pos;
        if (object) {
            skip_string(c);
            name->end = c->pos;
            skip_space(c);
            if (peek(c) == ':')
                c->pos++;
            skip_space(c);
        }
        if (object ? string_is(c->s, name->begin, name->end, step->key) : i == step->index) {
            if (!object)
                name->end = c->pos;
            return 1;
        }
        skip_value(c);
        skip_space(c);
        if (peek(c) == ',')
            c->pos++;
    }
}

int jsonloc_find(const char *text, size_t len, const jsonloc_step *path, int depth, jsonloc_span *key,
                 jsonloc_span *value)
{
    cursor c = {text, len, 0};
    jsonloc_span name;
    skip_space(&c);
    name.begin = name.end = c.pos;
    for (int i = 0; i < depth; i++)
        if (!enter(&c, &path[i], &name))
            return 0;
    if (c.pos >= len)
        return 0;
    value->begin = c.pos;
    skip_value(&c);
    value->end = c.pos;
    if (key)
        *key = depth > 0 && path[depth - 1].key ? name : *value;
    return 1;
}

size_t jsonloc_elements(const char *text, size_t len, const jsonloc_step *path, int depth, size_t *begins,
                        size_t count)
{
    jsonloc_span value;
    if (!jsonloc_find(text, len, path, depth, NULL, &value) || text[value.begin] != '[')
        return 0;
    cursor c = {text, len, value.begin + 1};
    size_t found = 0;
    while (found < count) {
        skip_space(&c);
        if (peek(&c) == ']' || peek(&c) < 0)
            break;
        begins[found++] = c.pos;
        skip_value(&c);
        skip_space(&c);
        if (peek(&c) == ',')
            c.pos++;
    }
    return found;
}

/* Descends from the value at the cursor into the member or element that
 * holds offset, appending its step to buf; 0 when none holds it. */
static int descend(cursor *c, size_t offset, char *buf, size_t size, size_t *used, int *on_name)
{
    int object = peek(c) == '{';
    if (!object && peek(c) != '[')
        return 0;
    c->pos++;
    for (size_t i = 0;; i++) {
        skip_space(c);
        if (peek(c) == '}' || peek(c) == ']' || peek(c) < 0 || c->pos > offset)
            return 0;
        size_t kb = c->pos, ke = c->pos;
        if (object) {
            skip_string(c);
            ke = c->pos;
            skip_space(c);
            if (peek(c) == ':')
                c->pos++;
            skip_space(c);
        }
        size_t vb = c->pos;
        skip_value(c);
        if ((offset >= kb && offset < ke) || (offset >= vb && offset < c->pos)) {
            if (object)
                put_key(buf, size, used, c->s, kb, ke);
            else
                put_index(buf, size, used, i);
            *on_name = offset < ke;
            c->pos = vb;
            return 1;
        }
        skip_space(c);
        if (peek(c) == ',')
            c->pos++;
    }
}

size_t jsonloc_pointer_at(const char *text, size_t len, size_t offset, char *buf, size_t size)
{
    cursor c = {text, len, 0};
    size_t used = 0;
    int on_name = 0;
    if (size)
        buf[0] = '\0';
    skip_space(&c);
    while (!on_name && descend(&c, offset, buf, size, &used, &on_name))
        ;
    return used;
}

size_t jsonloc_pointer(const jsonloc_step *path, int depth, char *buf, size_t size)
{
    size_t used = 0;
    if (size)
        buf[0] = '\0';
    for (int i = 0; i < depth; i++) {
        if (!path[i].key) {
            put_index(buf, size, &used, path[i].index);
            continue;
        }
        put_slash(buf, size, &used);
        put_escaped(buf, size, &used, path[i].key, strlen(path[i].key));
    }
    return used;
}
