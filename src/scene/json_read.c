/*
 * json_read.c - see json_read.h.  Built only with JSON=1.
 */
#include <assert.h>
#include <math.h>
#include <string.h>
#include "base/suggest.h"
#include "scene/json_read.h"

/* The byte offset where jansson's error lies.  jansson reports the offset
 * just past what it read, and names the token it stopped at ("near
 * 'tru'"): the token is taken back to its first byte when the text there
 * is that token; without a token, the caret is walked back to the first
 * character of a number that ends there. */
static src_span syntax_span(int file, const source_file *f, const json_error_t *e)
{
    size_t pos = e->position > 0 ? (size_t)e->position : 0, begin;
    const char *near = strstr(e->text, "near '");
    src_span s = {file, 0, 1};
    if (pos > f->len)
        pos = f->len;
    begin = pos;
    if (near && strchr(near + 6, '\'')) {
        size_t n = (size_t)(strrchr(near + 6, '\'') - (near + 6));
        if (n > 0 && n <= pos && memcmp(f->text + pos - n, near + 6, n) == 0)
            begin = pos - n;
    } else {
        while (begin > 0 && strchr("0123456789+-.eE", f->text[begin - 1]))
            begin--;
    }
    if (begin == pos && begin == f->len && begin > 0)
        begin--;
    s.begin = begin;
    s.end = pos > begin ? pos : begin + 1;
    return s;
}

/* What one walk of the text counts: enough to bound jansson's tree. */
typedef struct jread_census {
    double numbers, strings, string_bytes, longest, literals, arrays, objects, members;
} jread_census;

/* Counts the values of text without parsing it: a string is skipped to
 * its closing quote (escapes included), a number or a literal to its last
 * character; a member is a ':' outside strings.  Malformed text gives some
 * counts, and jansson refuses it afterwards. */
static void census(const char *t, size_t len, jread_census *c)
{
    memset(c, 0, sizeof *c);
    for (size_t i = 0; i < len; i++) {
        char ch = t[i];
        if (ch == '"') {
            size_t j = i + 1;
            while (j < len && t[j] != '"')
                j += t[j] == '\\' ? 2 : 1;
            double n = (double)((j < len ? j : len) - i - 1);
            c->strings++;
            c->string_bytes += n;
            c->longest = n > c->longest ? n : c->longest;
            i = j;
        } else if (ch == '[' || ch == '{' || ch == ':') {
            *(ch == '[' ? &c->arrays : ch == '{' ? &c->objects : &c->members) += 1;
        } else if (ch == '-' || (ch >= '0' && ch <= '9')) {
            size_t start = i;
            c->numbers++;
            while (i + 1 < len && t[i + 1] != '\0' && strchr("0123456789+-.eE", t[i + 1]))
                i++;
            /* jansson's lexer buffers a number's text as it does a string's. */
            c->longest = (double)(i + 1 - start) > c->longest ? (double)(i + 1 - start) : c->longest;
        } else if (ch >= 'a' && ch <= 'z') {
            size_t start = i;
            c->literals++;
            while (i + 1 < len && t[i + 1] >= 'a' && t[i + 1] <= 'z')
                i++;
            c->longest = (double)(i + 1 - start) > c->longest ? (double)(i + 1 - start) : c->longest;
        }
    }
}

/* An upper bound of the bytes jansson 2.14 holds at once while it parses a
 * document of census c, glibc's 8-byte chunk headers and 16-byte rounding
 * included (spec/reliability.md [REL-MEMORY-2] measures each term): a
 * number 32; a string value 72 + its bytes; an array 128 (its first table
 * of 8 slots) and 24 per element (a table of up to twice the elements,
 * and the old one beside the new while it grows); an object 224 (its
 * first 8 buckets) and 120 + the key's bytes per member (the pair, buckets
 * of up to twice the members, old and new while they grow); true, false
 * and null are shared, 0; the token buffer 3 times the longest token
 * (string, number or word: the lexer buffers each); 64
 * KiB of the parser's own.  Every value but the root is an element or a
 * member's value. */
double jread_tree_bound(const char *text, size_t len)
{
    jread_census c;
    census(text, len, &c);
    double value_strings = c.strings > c.members ? c.strings - c.members : 0;
    double values = c.numbers + value_strings + c.literals + c.arrays + c.objects;
    double elements = values - c.members - 1 > 0 ? values - c.members - 1 : 0;
    return 32 * c.numbers + 72 * value_strings + c.string_bytes + 128 * c.arrays + 24 * elements + 224 * c.objects +
           120 * c.members + 3 * c.longest + 65536;
}

/* [REL-MEMORY-2] jansson has no streaming parser and its allocator is the
 * process's (json_set_alloc_funcs is global), so the load's allocator and
 * its --max-memory cannot see the tree: the bound is judged before jansson
 * starts.  1 when it fits beside what the load holds, else 0 after the
 * error at 1:1. */
static int tree_fits(loader *L, int file, const source_file *f)
{
    double need = jread_tree_bound(f->text, f->len), budget = (double)L->limits->max_memory_mb * 1048576.0;
    if (need + loader_memory_extra(L) <= budget)
        return 1;
    src_span s = {file, 0, f->len > 0 ? 1 : 0};
    diag_report(&L->diag, DIAG_ERROR, s,
                "parsing this JSON document would take up to %.0f MiB (jansson holds the whole document as a tree, "
                "about 32 to 230 bytes a value), over --max-memory %ld MiB; write big meshes as OBJ or PLY files "
                "(refray export --to json --mesh-files DIR) or raise --max-memory",
                need / 1048576.0, L->limits->max_memory_mb);
    return 0;
}

json_t *jread_parse(loader *L, int file)
{
    const source_file *f = L->scene->sources.files[file];
    json_error_t e;
    /* jansson skips a NUL byte between tokens as if it were a space, and the
     * text walker (base/jsonloc.c) does not, so a diagnostic after it would
     * lose its place; no JSON text holds one (RFC 8259), and a .scene that
     * does is refused the same way. */
    const char *nul = memchr(f->text, '\0', f->len);
    if (nul) {
        src_span s = {file, (size_t)(nul - f->text), (size_t)(nul - f->text) + 1};
        diag_report(&L->diag, DIAG_ERROR, s, "malformed JSON: NUL byte in the text");
        return NULL;
    }
    if (!tree_fits(L, file, f))
        return NULL;
    /* Every number as a double (strtod of its text): JSON has one number
     * type, and an integer too large for jansson's 64-bit integers is still
     * a number. */
    json_t *root = json_loadb(f->text, f->len, JSON_REJECT_DUPLICATES | JSON_DECODE_INT_AS_REAL, &e);
    if (root)
        return root;
    if (json_error_code(&e) == json_error_out_of_memory)
        loader_oom(L);
    else
        diag_report(&L->diag, DIAG_ERROR, syntax_span(file, f, &e), "malformed JSON: %s", e.text);
    return NULL;
}

void jread_push_key(jreader *r, const char *key)
{
    assert(r->depth < JREAD_MAX_DEPTH);
    r->path[r->depth].key = key;
    r->path[r->depth++].index = 0;
}

void jread_push_index(jreader *r, size_t index)
{
    assert(r->depth < JREAD_MAX_DEPTH);
    r->path[r->depth].key = NULL;
    r->path[r->depth++].index = index;
}

void jread_pop(jreader *r)
{
    assert(r->depth > 0);
    r->depth--;
}

/* The span of the current path extended by key (when not NULL); *name
 * gets the span of the member's name.  0 when not in the text. */
static int locate(const jreader *r, const char *key, jsonloc_span *name, jsonloc_span *val)
{
    const source_file *f = r->L->scene->sources.files[r->file];
    jsonloc_step path[JREAD_MAX_DEPTH + 1];
    memcpy(path, r->path, (size_t)r->depth * sizeof path[0]);
    path[r->depth].key = key;
    path[r->depth].index = 0;
    return jsonloc_find(f->text, f->len, path, r->depth + (key != NULL), name, val);
}

static src_span to_span(const jreader *r, jsonloc_span v)
{
    const source_file *f = r->L->scene->sources.files[r->file];
    src_span s = {r->file, v.begin, v.end};
    if (v.begin < f->len && f->text[v.begin] == '{')
        s.end = v.begin + 1;
    return s;
}

src_span jread_span(const jreader *r, const char *key)
{
    jsonloc_span name, val;
    if ((key && locate(r, key, &name, &val)) || locate(r, NULL, &name, &val))
        return to_span(r, val);
    src_span s = {r->file, 0, 1};
    return s;
}

static src_span key_span(const jreader *r, const char *key)
{
    jsonloc_span name, val;
    if (locate(r, key, &name, &val))
        return to_span(r, name);
    return jread_span(r, NULL);
}

static src_span field_span(const void *ctx, int field)
{
    const jreader *r = ctx;
    switch (field) {
    case CHECK_BLOCK: return jread_span(r, NULL);
    case CHECK_TRANSFORM: return jread_span(r, "transform");
    case CHECK_RECT_EDGES: return src_span_join(jread_span(r, "edge_u"), jread_span(r, "edge_v"));
    case CHECK_RECT_EXTENT: return src_span_join(jread_span(r, "corner"), jread_span(r, "edge_v"));
    case CHECK_CONE_RADIUS0:
    case CHECK_CONE_RADIUS1: {
        jreader at = *r;
        jread_push_key(&at, "radii");
        jread_push_index(&at, (size_t)(field - CHECK_CONE_RADIUS0));
        return jread_span(&at, NULL);
    }
    default: return jread_span(r, keyword_name((keyword_id)field));
    }
}

check_at jread_at(const jreader *r)
{
    check_at at;
    at.span = field_span;
    at.ctx = r;
    return at;
}

static const char *kind_name(const json_t *v)
{
    switch (json_typeof(v)) {
    case JSON_OBJECT: return "an object";
    case JSON_ARRAY: return "an array";
    case JSON_STRING: return "a string";
    case JSON_INTEGER:
    case JSON_REAL: return "a number";
    case JSON_TRUE:
    case JSON_FALSE: return "a boolean";
    default: return "null";
    }
}

static int wrong_type(jreader *r, const char *key, const char *want, const json_t *got)
{
    diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, key), "expected %s, got %s", want, kind_name(got));
    return 0;
}

int jread_known(jreader *r, json_t *obj, const char *const *allowed)
{
    const char *key;
    json_t *val;
    int ok = 1, count = 0;
    while (allowed[count])
        count++;
    json_object_foreach(obj, key, val) {
        int known = 0;
        for (int i = 0; i < count && !known; i++)
            known = strcmp(key, allowed[i]) == 0;
        if (known)
            continue;
        const char *hint = suggest_nearest(key, strlen(key), allowed, count);
        if (hint)
            diag_report(&r->L->diag, DIAG_ERROR, key_span(r, key), "unknown field '%s'; did you mean '%s'?", key, hint);
        else
            diag_report(&r->L->diag, DIAG_ERROR, key_span(r, key), "unknown field '%s'", key);
        ok = 0;
    }
    return ok;
}

json_t *jread_member(jreader *r, json_t *obj, const char *key)
{
    json_t *v = json_object_get(obj, key);
    if (!v)
        diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, NULL), "missing field '%s'", key);
    return v;
}

int jread_number(jreader *r, json_t *obj, const char *key, double *out)
{
    json_t *v = jread_member(r, obj, key);
    if (!v)
        return 0;
    if (!json_is_number(v))
        return wrong_type(r, key, "a number", v);
    *out = json_number_value(v);
    return 1;
}

int jread_value_vec3(jreader *r, json_t *val, vec3 *out)
{
    double c[3];
    if (!json_is_array(val) || json_array_size(val) != 3) {
        if (json_is_array(val))
            diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, NULL), "expected an array of 3 numbers, got %zu value%s",
                        json_array_size(val), json_array_size(val) == 1 ? "" : "s");
        else
            wrong_type(r, NULL, "an array of 3 numbers", val);
        return 0;
    }
    for (size_t i = 0; i < 3; i++) {
        json_t *e = json_array_get(val, i);
        if (!json_is_number(e)) {
            jread_push_index(r, i);
            wrong_type(r, NULL, "a number", e);
            jread_pop(r);
            return 0;
        }
        c[i] = json_number_value(e);
    }
    *out = vec_make(c[0], c[1], c[2]);
    return 1;
}

int jread_vec3(jreader *r, json_t *obj, const char *key, vec3 *out)
{
    json_t *v = jread_member(r, obj, key);
    if (!v)
        return 0;
    jread_push_key(r, key);
    int ok = jread_value_vec3(r, v, out);
    jread_pop(r);
    return ok;
}

int jread_bool(jreader *r, json_t *obj, const char *key, int *out)
{
    json_t *v = jread_member(r, obj, key);
    if (!v)
        return 0;
    if (!json_is_boolean(v))
        return wrong_type(r, key, "true or false", v);
    *out = json_is_true(v);
    return 1;
}

int jread_string(jreader *r, json_t *obj, const char *key, int nullable, const char **out)
{
    json_t *v = jread_member(r, obj, key);
    *out = NULL;
    if (!v)
        return 0;
    if (nullable && json_is_null(v))
        return 1;
    if (!json_is_string(v))
        return wrong_type(r, key, nullable ? "a string or null" : "a string", v);
    *out = json_string_value(v);
    return 1;
}

int jread_enum(jreader *r, json_t *obj, const char *key, const char *const *names, int count, int *out)
{
    const char *name;
    char list[256];
    size_t used = 0;
    if (!jread_string(r, obj, key, 0, &name))
        return 0;
    for (int i = 0; i < count; i++) {
        if (strcmp(name, names[i]) == 0) {
            *out = i;
            return 1;
        }
        used += (size_t)snprintf(list + used, used < sizeof list ? sizeof list - used : 0, "%s'%s'",
                                 i == 0 ? "" : i == count - 1 ? " or " : ", ", names[i]);
    }
    const char *hint = suggest_nearest(name, strlen(name), names, count);
    if (hint)
        diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, key), "unknown %s '%s'; did you mean '%s'?", key, name,
                    hint);
    else
        diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, key), "unknown %s '%s'; it is %s", key, name, list);
    return 0;
}

int jread_value_index(jreader *r, json_t *val, int count, const char *what, int *out)
{
    if (!json_is_number(val))
        return wrong_type(r, NULL, "a whole number", val);
    double x = json_number_value(val);
    if (x != floor(x)) {
        diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, NULL), "expected a whole number, got %.17g", x);
        return 0;
    }
    if (x < 0 || x >= count) {
        diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, NULL),
                    "%s %.17g does not exist (there %s %d, numbered from 0)", what, x, count == 1 ? "is" : "are", count);
        return 0;
    }
    *out = (int)x;
    return 1;
}

int jread_index(jreader *r, json_t *obj, const char *key, int count, const char *what, int *out)
{
    json_t *v = jread_member(r, obj, key);
    if (!v)
        return 0;
    jread_push_key(r, key);
    int ok = jread_value_index(r, v, count, what, out);
    jread_pop(r);
    return ok;
}

int jread_array(jreader *r, json_t *obj, const char *key, json_t **out)
{
    json_t *v = jread_member(r, obj, key);
    if (!v)
        return 0;
    if (!json_is_array(v))
        return wrong_type(r, key, "an array", v);
    *out = v;
    return 1;
}

int jread_is_object(jreader *r, json_t *val)
{
    return json_is_object(val) || wrong_type(r, NULL, "an object", val);
}
