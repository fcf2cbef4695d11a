/*
 * export_json_print.c - the layout of an exported document: objects one
 * member per line, but an object or array of plain values on one line
 * when that line stays short, and each element of a long array of short
 * arrays (vertices, triangles, matrix rows) on a line of its own.  The
 * values themselves are jansson's encoding: reals with 17 significant
 * digits (JSON_REAL_PRECISION(17), %.17g), which read back as the same
 * double, strings escaped.  JSON=1 builds only.
 */
#include <stdlib.h>
#include <string.h>
#include "export/export_json_impl.h"

enum { ONE_LINE_MAX = 120 };

#define SCALAR_FLAGS (JSON_ENCODE_ANY | JSON_REAL_PRECISION(17))

static int is_plain(const json_t *v)
{
    return !json_is_object(v) && !json_is_array(v);
}

/* Writes one plain value; 0 on failure. */
static int put_plain(FILE *fp, const json_t *v)
{
    char buf[64];
    size_t n = json_dumpb(v, buf, sizeof buf, SCALAR_FLAGS);
    if (n == 0)
        return 0;
    if (n <= sizeof buf)
        return fwrite(buf, 1, n, fp) == n;
    char *text = json_dumps(v, SCALAR_FLAGS);
    int ok = text && fputs(text, fp) >= 0;
    free(text);
    return ok;
}

/* A member name as a JSON string: as it is when it needs no escape. */
static int put_key(FILE *fp, const char *key)
{
    for (const unsigned char *c = (const unsigned char *)key; *c; c++) {
        if (*c < 0x20 || *c >= 0x7f || *c == '"' || *c == '\\') {
            json_t *s = json_string(key);
            int ok = s && put_plain(fp, s);
            json_decref(s);
            return ok;
        }
    }
    return fprintf(fp, "\"%s\"", key) > 0;
}

/* The length of v on one line, or ONE_LINE_MAX + 1 when that is longer or
 * v holds an object or array below its own members. */
static size_t one_line_length(const json_t *v)
{
    size_t n = 2, count = 0;
    const char *key;
    json_t *item;
    size_t i;
    if (is_plain(v))
        return json_dumpb(v, NULL, 0, SCALAR_FLAGS);
    if (json_is_array(v)) {
        json_array_foreach(v, i, item) {
            if (!is_plain(item))
                return ONE_LINE_MAX + 1;
            n += json_dumpb(item, NULL, 0, SCALAR_FLAGS) + (count++ ? 2 : 0);
        }
        return n;
    }
    json_object_foreach((json_t *)v, key, item) {
        if (json_is_object(item) || (json_is_array(item) && json_array_size(item) > 0 &&
                                     !is_plain(json_array_get(item, 0))))
            return ONE_LINE_MAX + 1;
        n += strlen(key) + 4 + one_line_length(item) + (count++ ? 2 : 0);
        if (n > ONE_LINE_MAX)
            return n;
    }
    return n;
}

static int put_value(FILE *fp, const json_t *v, int indent);

static int put_one_line(FILE *fp, const json_t *v)
{
    const char *key;
    json_t *item;
    size_t i;
    int ok = 1, first = 1;
    if (is_plain(v))
        return put_plain(fp, v);
    ok = fputc(json_is_array(v) ? '[' : '{', fp) != EOF;
    if (json_is_array(v)) {
        json_array_foreach(v, i, item) {
            ok = ok && (first || fputs(", ", fp) >= 0) && put_plain(fp, item);
            first = 0;
        }
    } else {
        json_object_foreach((json_t *)v, key, item) {
            ok = ok && (first || fputs(", ", fp) >= 0) && put_key(fp, key) && fputs(": ", fp) >= 0 &&
                 put_one_line(fp, item);
            first = 0;
        }
    }
    return ok && fputc(json_is_array(v) ? ']' : '}', fp) != EOF;
}

static int put_indent(FILE *fp, int indent)
{
    return fprintf(fp, "\n%*s", indent, "") > 0;
}

static int put_array(FILE *fp, const json_t *v, int indent)
{
    json_t *item;
    size_t i;
    int ok = fputc('[', fp) != EOF;
    json_array_foreach(v, i, item) {
        ok = ok && (i == 0 || fputc(',', fp) != EOF) && put_indent(fp, indent + 2) && put_value(fp, item, indent + 2);
    }
    return ok && put_indent(fp, indent) && fputc(']', fp) != EOF;
}

static int put_object(FILE *fp, const json_t *v, int indent)
{
    const char *key;
    json_t *item;
    int ok = fputc('{', fp) != EOF, first = 1;
    json_object_foreach((json_t *)v, key, item) {
        ok = ok && (first || fputc(',', fp) != EOF) && put_indent(fp, indent + 2) && put_key(fp, key) &&
             fputs(": ", fp) >= 0 && put_value(fp, item, indent + 2);
        first = 0;
    }
    return ok && put_indent(fp, indent) && fputc('}', fp) != EOF;
}

static int put_value(FILE *fp, const json_t *v, int indent)
{
    int empty = json_is_array(v) ? json_array_size(v) == 0 : json_is_object(v) ? json_object_size(v) == 0 : 0;
    if (is_plain(v) || empty || one_line_length(v) <= ONE_LINE_MAX)
        return put_one_line(fp, v);
    return json_is_array(v) ? put_array(fp, v, indent) : put_object(fp, v, indent);
}

int export_json_print(FILE *fp, const json_t *doc)
{
    int ok = put_value(fp, doc, 0) && fputc('\n', fp) != EOF;
    return ok && !ferror(fp) ? STATUS_OK : STATUS_IO;
}
