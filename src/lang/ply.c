/*
 * ply.c - the PLY reader (see ply.h for the accepted language).
 *
 * The input may be hostile: any bytes, any length.  Invariants:
 * - Every read is at an offset < len, checked right there; NUL bytes are
 *   data in a binary body and an error in a text part.
 * - Nothing is allocated for a count the header declares: positions and
 *   triangles grow as they are read (polymesh.c), so a header that claims
 *   2^31 vertices costs nothing until they are there; a binary list count
 *   is checked against the bytes left before its items are read.
 * - Header tokens are spans into the text, so header messages point at the
 *   exact bytes; ASCII data numbers too.  Binary data have no lines: their
 *   messages point at the header line declaring the element and give the
 *   byte offset.
 * - After the first error in the body reading stops (the rest of a binary
 *   file cannot be framed), so one bad file gives one message there.
 */
#include <limits.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "lang/meshtext.h"
#include "lang/ply.h"

enum {
    ELEMENTS_MAX = 256,   /* elements one header may declare */
    PROPERTIES_MAX = 1024,/* properties of one element */
    WORDS_MAX = 6,        /* tokens of one header line read (property list T T NAME is 5) */
    NUMBER_MAX = 255      /* longest number token accepted */
};

typedef enum scalar {
    S_NONE, S_INT8, S_UINT8, S_INT16, S_UINT16, S_INT32, S_UINT32, S_FLOAT32, S_FLOAT64
} scalar;

static const struct {
    const char *name;
    scalar type;
} type_names[] = {
    {"char", S_INT8},     {"uchar", S_UINT8},     {"short", S_INT16},   {"ushort", S_UINT16},
    {"int", S_INT32},     {"uint", S_UINT32},     {"float", S_FLOAT32}, {"double", S_FLOAT64},
    {"int8", S_INT8},     {"uint8", S_UINT8},     {"int16", S_INT16},   {"uint16", S_UINT16},
    {"int32", S_INT32},   {"uint32", S_UINT32},   {"float32", S_FLOAT32}, {"float64", S_FLOAT64},
};

static const int type_size[] = {0, 1, 1, 2, 2, 4, 4, 4, 8};

/* What a property means to the mesh. */
typedef enum role { R_SKIP, R_X, R_Y, R_Z, R_NX, R_NY, R_NZ, R_INDICES } role;

static const char *const role_names[] = {"", "x", "y", "z", "nx", "ny", "nz"};

typedef struct property {
    src_span name;
    scalar type;          /* the value type, or a list's item type */
    scalar count_type;    /* a list's count type; S_NONE for a scalar */
    role use;
} property;

typedef enum element_kind { E_OTHER, E_VERTEX, E_FACE } element_kind;

typedef struct element {
    src_span name;
    src_span decl;        /* the whole `element` line */
    long long count;
    property *props;
    int prop_count, prop_cap;
    element_kind kind;
} element;

typedef enum format { F_NONE, F_ASCII, F_LITTLE, F_BIG } format;

typedef struct reader {
    const char *text;
    size_t len;
    size_t pos;                /* next byte to read */
    int file;
    diag *d;
    polymesh *mesh;
    format fmt;
    element *elements;
    int element_count;
    int vertex_element, face_element; /* indices, -1 when absent */
    int has_normals;
    int *corners;              /* the face being read */
    int corner_cap;
    int failed;                /* an error in the data: stop reading */
    int out_of_memory;
} reader;

/* One value read from the data: integers exactly in i (and f), floats in f;
 * at is where it starts. */
typedef struct value {
    long long i;
    double f;
    int integral;
    size_t at;
} value;

/* ---- header: lines and tokens ------------------------------------------ */

static src_span span_of(const reader *r, size_t begin, size_t end)
{
    src_span s;
    s.file = r->file;
    s.begin = begin;
    s.end = end;
    return s;
}

static int token_is(const reader *r, src_span tok, const char *word)
{
    size_t n = strlen(word);
    return tok.end - tok.begin == n && memcmp(r->text + tok.begin, word, n) == 0;
}

/* Reads the words of one header line into w[0..WORDS_MAX-1] and moves past
 * its terminator.  Returns the number of words (more than WORDS_MAX are
 * counted, not kept); *line is the span of the whole line.  A NUL byte
 * ends the header with an error (-1). */
static int header_line(reader *r, src_span w[WORDS_MAX], src_span *line)
{
    int n = 0;
    *line = span_of(r, r->pos, r->pos);
    while (r->pos < r->len && !meshtext_eol(r->text[r->pos])) {
        if (r->text[r->pos] == '\0') {
            diag_report(r->d, DIAG_ERROR, span_of(r, r->pos, r->pos + 1), "NUL byte in the PLY header");
            return -1;
        }
        if (meshtext_blank(r->text[r->pos])) {
            r->pos++;
            continue;
        }
        size_t begin = r->pos;
        while (r->pos < r->len && !meshtext_eol(r->text[r->pos]) && !meshtext_blank(r->text[r->pos]) && r->text[r->pos])
            r->pos++;
        if (n < WORDS_MAX)
            w[n] = span_of(r, begin, r->pos);
        n += n < INT_MAX;
    }
    line->end = r->pos;
    r->pos += meshtext_eol_length(r->text, r->len, r->pos);
    return n;
}

/* ---- header: statements ------------------------------------------------ */

/* A decimal count 0 .. INT_MAX; reports and returns -1 otherwise. */
static long long read_count(reader *r, src_span tok)
{
    long long k = 0;
    int ok = tok.end > tok.begin;
    for (size_t i = tok.begin; i < tok.end && ok; i++) {
        char c = r->text[i];
        ok = c >= '0' && c <= '9';
        if (ok && k <= INT_MAX)
            k = k * 10 + (c - '0');
    }
    if (ok && k <= INT_MAX)
        return k;
    meshtext_shown q = meshtext_show(r->text, tok);
    diag_report(r->d, DIAG_ERROR, tok, "element count '%s' is not a whole number from 0 to %d", q.s, INT_MAX);
    return -1;
}

static scalar type_of(const reader *r, src_span tok)
{
    for (size_t i = 0; i < sizeof type_names / sizeof type_names[0]; i++)
        if (token_is(r, tok, type_names[i].name))
            return type_names[i].type;
    return S_NONE;
}

static int is_integer_type(scalar t)
{
    return t != S_NONE && t != S_FLOAT32 && t != S_FLOAT64;
}

/* Reads a type word; reports and returns S_NONE when it is none. */
static scalar read_type(reader *r, src_span tok)
{
    scalar t = type_of(r, tok);
    if (t == S_NONE) {
        meshtext_shown q = meshtext_show(r->text, tok);
        diag_report(r->d, DIAG_ERROR, tok,
                    "unknown PLY type '%s' (expected char, uchar, short, ushort, int, uint, float or double)",
                    q.s);
    }
    return t;
}

/* format ascii|binary_little_endian|binary_big_endian 1.0 */
static int header_format(reader *r, const src_span *w, int n, src_span line)
{
    static const char *const names[] = {"ascii", "binary_little_endian", "binary_big_endian"};
    if (r->fmt != F_NONE) {
        diag_report(r->d, DIAG_ERROR, line, "a second 'format' line");
        return 0;
    }
    for (int k = 0; n == 3 && k < 3; k++)
        if (token_is(r, w[1], names[k])) {
            r->fmt = (format)(F_ASCII + k);
            if (token_is(r, w[2], "1.0"))
                return 1;
            meshtext_shown q = meshtext_show(r->text, w[2]);
            diag_report(r->d, DIAG_ERROR, w[2], "unsupported PLY version '%s' (only 1.0 is known)", q.s);
            return 0;
        }
    diag_report(r->d, DIAG_ERROR, n >= 2 ? w[1] : line,
                "expected 'format ascii 1.0', 'format binary_little_endian 1.0' or 'format binary_big_endian 1.0'");
    return 0;
}

/* element NAME COUNT */
static int header_element(reader *r, const src_span *w, int n, src_span line)
{
    if (n != 3) {
        diag_report(r->d, DIAG_ERROR, line, "expected 'element NAME COUNT'");
        return 0;
    }
    if (r->element_count == ELEMENTS_MAX) {
        diag_report(r->d, DIAG_ERROR, line, "more than %d elements", ELEMENTS_MAX);
        return 0;
    }
    long long count = read_count(r, w[2]);
    if (count < 0)
        return 0;
    element *e = &r->elements[r->element_count];
    memset(e, 0, sizeof *e);
    e->name = w[1];
    e->decl = line;
    e->count = count;
    e->kind = token_is(r, w[1], "vertex") ? E_VERTEX : token_is(r, w[1], "face") ? E_FACE : E_OTHER;
    int *seen = e->kind == E_VERTEX ? &r->vertex_element : e->kind == E_FACE ? &r->face_element : NULL;
    if (seen && *seen >= 0) {
        meshtext_shown q = meshtext_show(r->text, w[1]);
        diag_report(r->d, DIAG_ERROR, w[1], "a second element '%s'", q.s);
        return 0;
    }
    if (seen)
        *seen = r->element_count;
    r->element_count++;
    return 1;
}

/* The role of a property of the vertex or face element, by its name. */
static role role_of(const reader *r, const element *e, src_span name, int list)
{
    if (e->kind == E_FACE && list && (token_is(r, name, "vertex_indices") || token_is(r, name, "vertex_index")))
        return R_INDICES;
    if (e->kind != E_VERTEX || list)
        return R_SKIP;
    for (int k = R_X; k <= R_NZ; k++)
        if (token_is(r, name, role_names[k]))
            return (role)k;
    return R_SKIP;
}

static int add_property(reader *r, element *e, const property *p, src_span line)
{
    if (e->prop_count == PROPERTIES_MAX) {
        diag_report(r->d, DIAG_ERROR, line, "more than %d properties in one element", PROPERTIES_MAX);
        return 0;
    }
    for (int k = 0; k < e->prop_count && p->use != R_SKIP; k++)
        if (e->props[k].use == p->use) {
            meshtext_shown q = meshtext_show(r->text, p->name);
            diag_report(r->d, DIAG_ERROR, p->name, "a second property '%s'", q.s);
            return 0;
        }
    property *grown = polymesh_grow(&r->mesh->mem, e->props, &e->prop_cap, (long)e->prop_count + 1, sizeof *grown,
                                    PROPERTIES_MAX);
    if (!grown) {
        diag_report(r->d, DIAG_ERROR, line, "out of memory reading PLY file");
        r->out_of_memory = 1;
        return 0;
    }
    e->props = grown;
    e->props[e->prop_count++] = *p;
    return 1;
}

/* property TYPE NAME | property list COUNT_TYPE TYPE NAME */
static int header_property(reader *r, const src_span *w, int n, src_span line)
{
    property p;
    if (r->element_count == 0) {
        diag_report(r->d, DIAG_ERROR, line, "'property' before any 'element'");
        return 0;
    }
    element *e = &r->elements[r->element_count - 1];
    int list = n >= 2 && token_is(r, w[1], "list");
    if (n != (list ? 5 : 3)) {
        diag_report(r->d, DIAG_ERROR, line, "expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
        return 0;
    }
    p.count_type = list ? read_type(r, w[2]) : S_NONE;
    p.type = read_type(r, w[list ? 3 : 1]);
    p.name = w[list ? 4 : 2];
    if (p.type == S_NONE || (list && p.count_type == S_NONE))
        return 0;
    if (list && !is_integer_type(p.count_type)) {
        diag_report(r->d, DIAG_ERROR, w[2], "a list's count must have an integer type");
        return 0;
    }
    p.use = role_of(r, e, p.name, list);
    if (p.use == R_INDICES && !is_integer_type(p.type)) {
        diag_report(r->d, DIAG_ERROR, w[3], "vertex indices must have an integer type");
        return 0;
    }
    return add_property(r, e, &p, line);
}

/* One header line after `ply`; returns 1 to go on, 0 on error, 2 at
 * end_header. */
static int header_statement(reader *r)
{
    src_span w[WORDS_MAX], line;
    int n = header_line(r, w, &line);
    if (n < 0)
        return 0;
    if (n == 0 || token_is(r, w[0], "comment") || token_is(r, w[0], "obj_info"))
        return 1;
    if (token_is(r, w[0], "end_header"))
        return 2;
    if (token_is(r, w[0], "format"))
        return header_format(r, w, n, line);
    if (r->fmt == F_NONE) {
        diag_report(r->d, DIAG_ERROR, w[0], "expected the 'format' line after 'ply'");
        return 0;
    }
    if (token_is(r, w[0], "element"))
        return header_element(r, w, n, line);
    if (token_is(r, w[0], "property"))
        return header_property(r, w, n, line);
    meshtext_shown q = meshtext_show(r->text, w[0]);
    diag_report(r->d, DIAG_ERROR, w[0], "unknown PLY header keyword '%s'", q.s);
    return 0;
}

/* The roles the mesh needs: x y z (and nx ny nz, all or none) in vertex,
 * a list of indices in face. */
static int check_elements(reader *r)
{
    int have[R_INDICES + 1] = {0};
    if (r->vertex_element < 0) {
        diag_report(r->d, DIAG_ERROR, span_of(r, 0, 3), "the PLY header has no element 'vertex'");
        return 0;
    }
    if (r->face_element < 0) {
        diag_report(r->d, DIAG_ERROR, span_of(r, 0, 3), "mesh has no faces (the PLY header has no element 'face')");
        return 0;
    }
    for (int k = 0; k < 2; k++) {
        const element *e = &r->elements[k ? r->face_element : r->vertex_element];
        for (int i = 0; i < e->prop_count; i++)
            have[e->props[i].use] = 1;
    }
    const element *v = &r->elements[r->vertex_element];
    for (int k = R_X; k <= R_Z; k++)
        if (!have[k]) {
            diag_report(r->d, DIAG_ERROR, v->decl, "element 'vertex' has no property '%s'", role_names[k]);
            return 0;
        }
    int normals = have[R_NX] + have[R_NY] + have[R_NZ];
    if (normals == 1 || normals == 2) {
        diag_report(r->d, DIAG_ERROR, v->decl, "element 'vertex' has some of nx, ny, nz but not all three");
        return 0;
    }
    r->has_normals = normals == 3;
    if (!have[R_INDICES]) {
        diag_report(r->d, DIAG_ERROR, r->elements[r->face_element].decl,
                    "element 'face' has no list property 'vertex_indices' (or 'vertex_index')");
        return 0;
    }
    return 1;
}

static int parse_header(reader *r)
{
    src_span w[WORDS_MAX], line;
    int n = header_line(r, w, &line);
    if (n != 1 || !token_is(r, w[0], "ply")) {
        diag_report(r->d, DIAG_ERROR, n > 0 ? w[0] : line, "not a PLY file: the first line must be 'ply'");
        return 0;
    }
    for (;;) {
        if (r->pos >= r->len) {
            diag_report(r->d, DIAG_ERROR, span_of(r, r->len, r->len), "the PLY header has no 'end_header' line");
            return 0;
        }
        int status = header_statement(r);
        if (status == 0)
            return 0;
        if (status == 2)
            break;
    }
    if (r->fmt == F_NONE) {
        diag_report(r->d, DIAG_ERROR, span_of(r, 0, 3), "the PLY header has no 'format' line");
        return 0;
    }
    return check_elements(r);
}

/* ---- data ---------------------------------------------------------------- */

/* Reports an error in the data of element e, instance index: at tok for
 * ASCII, at the element's header line with the byte offset for binary. */
static void data_error(reader *r, const element *e, long long index, src_span tok, const char *fmt, ...)
{
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    meshtext_shown name = meshtext_show(r->text, e->name);
    if (r->fmt == F_ASCII)
        diag_report(r->d, DIAG_ERROR, tok, "element '%s' %lld: %s", name.s, index, msg);
    else
        diag_report(r->d, DIAG_ERROR, e->decl, "element '%s' %lld, at byte %zu: %s", name.s, index, tok.begin, msg);
    r->failed = 1;
}

/* The next whitespace-separated token of ASCII data; 0 at the end. */
static int data_token(reader *r, src_span *tok)
{
    while (r->pos < r->len && (meshtext_blank(r->text[r->pos]) || meshtext_eol(r->text[r->pos])))
        r->pos++;
    if (r->pos >= r->len)
        return 0;
    size_t begin = r->pos;
    while (r->pos < r->len && !meshtext_blank(r->text[r->pos]) && !meshtext_eol(r->text[r->pos]))
        r->pos++;
    *tok = span_of(r, begin, r->pos);
    return 1;
}

static const long long type_min[] = {0, -128, 0, -32768, 0, INT32_MIN, 0};
static const long long type_max[] = {0, 127, 255, 32767, 65535, INT32_MAX, UINT32_MAX};

/* An ASCII integer of type t: '-'? digits, in t's range. */
static int ascii_integer(reader *r, src_span tok, scalar t, long long *out)
{
    size_t i = tok.begin;
    int negative = i < tok.end && (r->text[i] == '-' || r->text[i] == '+') ? r->text[i++] == '-' : 0;
    long long k = 0;
    int ok = i < tok.end;
    for (; i < tok.end && ok; i++) {
        char c = r->text[i];
        ok = c >= '0' && c <= '9';
        if (ok && k <= UINT32_MAX)
            k = k * 10 + (c - '0');
    }
    k = negative ? -k : k;
    *out = k;
    return ok && k >= type_min[t] && k <= type_max[t];
}

/* An ASCII float: only digits, signs, '.' and exponent letters (no inf,
 * nan or hex), all of it consumed by strtod, finite. */
static int ascii_float(reader *r, src_span tok, double *out)
{
    size_t n = tok.end - tok.begin;
    const char *s = r->text + tok.begin;
    char buf[NUMBER_MAX + 1], *end = buf;
    if (n > NUMBER_MAX)
        return 0;
    for (size_t i = 0; i < n; i++)
        if (!((s[i] >= '0' && s[i] <= '9') || s[i] == '+' || s[i] == '-' || s[i] == '.' || s[i] == 'e' ||
              s[i] == 'E'))
            return 0;
    memcpy(buf, s, n);
    buf[n] = '\0';
    *out = strtod(buf, &end);
    return end == buf + n && n > 0 && isfinite(*out);
}

static const char *const type_words[] = {"", "char", "uchar", "short", "ushort", "int", "uint", "float", "double"};

/* What is being read, for messages only (so nothing is formatted unless
 * something goes wrong): element e's instance index, property p, its list
 * count when count is set. */
typedef struct place {
    const element *e;
    long long index;
    const property *p;
    int count;
} place;

/* "property 'x'" or "property 'x' (its count)". */
static void describe(const reader *r, const place *at, char *out, size_t size)
{
    meshtext_shown q = meshtext_show(r->text, at->p->name);
    snprintf(out, size, "property '%s'%s", q.s, at->count ? " (its count)" : "");
}

static int read_ascii(reader *r, const place *at, scalar t, value *v)
{
    char what[80];
    src_span tok;
    int found = data_token(r, &tok);
    v->at = found ? tok.begin : r->len;
    v->integral = is_integer_type(t);
    if (found && (v->integral ? ascii_integer(r, tok, t, &v->i) : ascii_float(r, tok, &v->f))) {
        if (v->integral)
            v->f = (double)v->i;
        return 1;
    }
    describe(r, at, what, sizeof what);
    if (!found) {
        data_error(r, at->e, at->index, span_of(r, r->len, r->len), "the file ends before %s", what);
        return 0;
    }
    meshtext_shown q = meshtext_show(r->text, tok);
    if (v->integral)
        data_error(r, at->e, at->index, tok, "%s: '%s' is not a whole number in the range of %s", what, q.s,
                   type_words[t]);
    else
        data_error(r, at->e, at->index, tok, "%s: '%s' is not a finite number", what, q.s);
    return 0;
}

/* The n bytes at p as an unsigned integer in the file's byte order. */
static uint64_t binary_bits(const reader *r, const unsigned char *p, int n)
{
    uint64_t u = 0;
    for (int k = 0; k < n; k++)
        u = u << 8 | p[r->fmt == F_LITTLE ? n - 1 - k : k];
    return u;
}

/* The value of type t from its bits: integers sign-extended, floats by
 * their IEEE 754 encoding (C99 Annex F). */
static void decode(scalar t, uint64_t u, value *v)
{
    v->integral = is_integer_type(t);
    if (t == S_FLOAT32) {
        uint32_t w = (uint32_t)u;
        float f;
        memcpy(&f, &w, sizeof f);
        v->f = f;
    } else if (t == S_FLOAT64) {
        memcpy(&v->f, &u, sizeof v->f);
    } else {
        int bits = 8 * type_size[t];
        int is_signed = t == S_INT8 || t == S_INT16 || t == S_INT32;
        long long k = (long long)u;
        if (is_signed && (u >> (bits - 1)) & 1)
            k -= (long long)1 << bits;
        v->i = k;
        v->f = (double)k;
    }
}

static int read_binary(reader *r, const place *at, scalar t, value *v)
{
    char what[80];
    int n = type_size[t];
    v->at = r->pos;
    if (r->len - r->pos < (size_t)n) {
        describe(r, at, what, sizeof what);
        data_error(r, at->e, at->index, span_of(r, r->pos, r->pos), "the file ends in the middle of %s", what);
        return 0;
    }
    decode(t, binary_bits(r, (const unsigned char *)r->text + r->pos, n), v);
    r->pos += (size_t)n;
    if (v->integral || isfinite(v->f))
        return 1;
    describe(r, at, what, sizeof what);
    data_error(r, at->e, at->index, span_of(r, v->at, v->at), "%s is not finite", what);
    return 0;
}

static int read_value(reader *r, const place *at, scalar t, value *v)
{
    return r->fmt == F_ASCII ? read_ascii(r, at, t, v) : read_binary(r, at, t, v);
}

/* A list's count: an integer from 0 to INT_MAX, whose items can fit in the
 * bytes left. */
static int read_list_count(reader *r, const element *e, long long index, const property *p, long long *count)
{
    char what[80];
    place at = {e, index, p, 1};
    value v;
    if (!read_value(r, &at, p->count_type, &v))
        return 0;
    /* A binary item takes its type's size, an ASCII one a digit and a blank
     * (the last one may lack its blank). */
    size_t room = r->fmt != F_ASCII ? (r->len - r->pos) / (size_t)type_size[p->type] : (r->len - r->pos + 1) / 2;
    if (v.i >= 0 && v.i <= INT_MAX && (unsigned long long)v.i <= room) {
        *count = v.i;
        return 1;
    }
    describe(r, &at, what, sizeof what);
    if (v.i < 0 || v.i > INT_MAX)
        data_error(r, e, index, span_of(r, v.at, r->pos), "%s is %lld", what, v.i);
    else
        data_error(r, e, index, span_of(r, v.at, v.at), "%s is %lld, more items than the file holds", what, v.i);
    return 0;
}

static int skip_property(reader *r, const element *e, long long index, const property *p)
{
    place at = {e, index, p, 0};
    value v;
    long long count = 1;
    if (p->count_type != S_NONE && !read_list_count(r, e, index, p, &count))
        return 0;
    for (long long k = 0; k < count; k++)
        if (!read_value(r, &at, p->type, &v))
            return 0;
    return 1;
}

static int read_vertex(reader *r, const element *e, long long index)
{
    double c[R_NZ + 1] = {0};
    for (int i = 0; i < e->prop_count; i++) {
        const property *p = &e->props[i];
        place at = {e, index, p, 0};
        value v;
        if (p->use == R_SKIP) {
            if (!skip_property(r, e, index, p))
                return 0;
            continue;
        }
        if (!read_value(r, &at, p->type, &v))
            return 0;
        c[p->use] = v.f;
    }
    int ok = polymesh_add_position(r->mesh, vec_make(c[R_X], c[R_Y], c[R_Z]));
    if (ok == 1 && r->has_normals)
        ok = polymesh_add_normal(r->mesh, vec_make(c[R_NX], c[R_NY], c[R_NZ]));
    if (ok != 1)
        data_error(r, e, index, span_of(r, r->pos, r->pos), ok == 0 ? "out of memory" : "too many vertices");
    r->out_of_memory |= ok == POLYMESH_NO_MEMORY;
    return ok == 1;
}

static int reserve_corners(reader *r, long long n)
{
    int *grown = polymesh_grow(&r->mesh->mem, r->corners, &r->corner_cap, n, sizeof *grown, INT_MAX);
    if (!grown)
        return 0;
    r->corners = grown;
    return 1;
}

/* The face's corner list: each index checked against the vertex count. */
static int read_indices(reader *r, const element *e, long long index, const property *p, long long *n)
{
    place at = {e, index, p, 0};
    if (!read_list_count(r, e, index, p, n))
        return 0;
    if (!reserve_corners(r, *n)) {
        data_error(r, e, index, span_of(r, r->pos, r->pos), "out of memory");
        r->out_of_memory = 1;
        return 0;
    }
    for (long long k = 0; k < *n; k++) {
        value v;
        if (!read_value(r, &at, p->type, &v))
            return 0;
        if (v.i < 0 || v.i >= r->mesh->position_count) {
            data_error(r, e, index, span_of(r, v.at, r->pos), "vertex index %lld is out of range (%d vertices)", v.i,
                       r->mesh->position_count);
            return 0;
        }
        r->corners[k] = (int)v.i;
    }
    return 1;
}

static int read_face(reader *r, const element *e, long long index)
{
    long long n = 0;
    size_t at = r->pos;
    if (r->fmt == F_ASCII) {
        src_span tok;
        size_t keep = r->pos;
        at = data_token(r, &tok) ? tok.begin : r->pos;
        r->pos = keep;
    }
    for (int i = 0; i < e->prop_count; i++) {
        const property *p = &e->props[i];
        if (!(p->use == R_INDICES ? read_indices(r, e, index, p, &n) : skip_property(r, e, index, p)))
            return 0;
    }
    int ok = polymesh_add_face(r->mesh, r->corners, r->has_normals ? r->corners : NULL, (int)n, at);
    if (ok == 1)
        return 1;
    if (ok == POLYMESH_TOO_MANY)
        data_error(r, e, index, span_of(r, at, at), "mesh exceeds the limit of %ld triangles", r->mesh->max_triangles);
    else
        data_error(r, e, index, span_of(r, at, at), "out of memory");
    r->out_of_memory |= ok == POLYMESH_NO_MEMORY;
    return 0;
}

/* Reads past instance index of e, every value checked as it is framed. */
static int skip_instance(reader *r, const element *e, long long index)
{
    for (int i = 0; i < e->prop_count; i++)
        if (!skip_property(r, e, index, &e->props[i]))
            return 0;
    return 1;
}

/* The instances of e from r->pos: read into the mesh, or (skip) framed
 * and read past. */
static void read_element(reader *r, const element *e, int skip)
{
    for (long long i = 0; i < e->count && !r->failed && !diag_too_many(r->d); i++) {
        if (skip || e->kind == E_OTHER)
            skip_instance(r, e, i);
        else if (e->kind == E_VERTEX)
            read_vertex(r, e, i);
        else
            read_face(r, e, i);
    }
}

static void parse_body(reader *r)
{
    /* PLY puts no order on elements ([MESH-PLY-2]).  Faces whose vertices
     * come later are framed where they stand (binary data can be found
     * only so) and read once the vertices are in, each index then checked
     * against all of them. */
    int later = r->face_element < r->vertex_element;
    size_t faces_at = 0;
    for (int k = 0; k < r->element_count && !r->failed; k++) {
        if (k == r->face_element)
            faces_at = r->pos;
        read_element(r, &r->elements[k], later && k == r->face_element);
    }
    if (later && !r->failed) {
        size_t end = r->pos;
        r->pos = faces_at;
        read_element(r, &r->elements[r->face_element], 0);
        r->pos = end;
    }
    if (r->failed || r->fmt != F_ASCII)
        return;
    src_span tok;
    if (data_token(r, &tok)) {
        meshtext_shown q = meshtext_show(r->text, tok);
        diag_report(r->d, DIAG_WARNING, tok, "data after the last element ignored ('%s')", q.s);
    }
}

int ply_is_ply(const char *text, size_t len)
{
    return len >= 4 && memcmp(text, "ply", 3) == 0 && meshtext_eol(text[3]);
}

int ply_parse(const source_set *sources, int file, diag *d, long max_triangles, polymesh *out)
{
    const source_file *f = sources->files[file];
    int errors_before = d->errors;
    element elements[ELEMENTS_MAX];
    reader r;
    memset(&r, 0, sizeof r);
    polymesh_init(out, max_triangles, &sources->mem);
    r.text = f->text;
    r.len = f->len;
    r.file = file;
    r.d = d;
    r.mesh = out;
    r.elements = elements;
    r.vertex_element = r.face_element = -1;
    if (parse_header(&r))
        parse_body(&r);
    for (int k = 0; k < r.element_count; k++)
        mem_free(&out->mem, elements[k].props, (size_t)elements[k].prop_cap * sizeof *elements[k].props);
    mem_free(&out->mem, r.corners, (size_t)r.corner_cap * sizeof *r.corners);
    const src_span *faces = r.face_element >= 0 ? &elements[r.face_element].decl : NULL;
    return polymesh_finish(out, d, errors_before, faces, 0, r.out_of_memory);
}
