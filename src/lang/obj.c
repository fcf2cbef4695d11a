/*
 * obj.c - the Wavefront OBJ reader (see obj.h for the accepted language).
 *
 * The input may be hostile: any bytes, any length.  Invariants:
 * - Every read of text is at an offset < len, checked right there; the
 *   NUL-terminator is never relied on, and NUL bytes inside are refused
 *   before anything else, so no byte of a token can be NUL.
 * - Tokens are spans into the text, so every message points at the exact
 *   bytes; numbers are parsed from a bounded copy of their token.
 * - Arrays grow by doubling (here and in polymesh.c) with their limit and
 *   size_t overflow checked first; triangles never get room beyond
 *   max_triangles.
 * - One error per statement: after it the rest of the logical line is
 *   skipped and parsing goes on with the next, so one run reports many
 *   independent mistakes (up to the diag's limit).
 */
#include <assert.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "lang/meshtext.h"
#include "lang/obj.h"

enum {
    NUMBER_MAX = 255,  /* longest number token accepted */
    VERTEX_VALUES_MAX = 7, /* v x y z w, or v x y z r g b */
    WARNED_MAX = 8     /* distinct unknown statements warned about */
};

/* Indices saturate here while being read: far beyond any count (<= INT_MAX),
 * so a saturated index is out of range whatever the count. */
#define INDEX_SATURATED (1LL << 40)

typedef struct parser {
    const char *text;
    size_t len;
    size_t pos;                  /* next byte to read */
    int file;                    /* for spans */
    diag *d;
    polymesh *mesh;
    int texcoord_count;          /* vt statements seen: t indices are checked against it */
    int *corner_v, *corner_vn;   /* the face being read: position and normal indices */
    int corner_v_cap, corner_vn_cap;
    src_span warned[WARNED_MAX]; /* keywords of the unknown statements warned about */
    int warned_count;
    int stop;                    /* a limit was hit or memory ran out: give up */
    int out_of_memory;
} parser;

/* A continuation is a backslash followed by nothing but blanks up to a line
 * terminator (or the end of the text).  Returns the offset just past it, or 0
 * when i holds no continuation (0 cannot be past anything). */
static size_t continuation_end(const parser *p, size_t i)
{
    if (i >= p->len || p->text[i] != '\\')
        return 0;
    size_t j = i + 1;
    while (j < p->len && meshtext_blank(p->text[j]))
        j++;
    if (j == p->len)
        return j;
    size_t n = meshtext_eol_length(p->text, p->len, j);
    return n ? j + n : 0;
}

/* Skips blanks and continuations, which together separate tokens. */
static void skip_blank(parser *p)
{
    for (;;) {
        size_t next;
        if (p->pos < p->len && meshtext_blank(p->text[p->pos]))
            p->pos++;
        else if ((next = continuation_end(p, p->pos)) != 0)
            p->pos = next;
        else
            return;
    }
}

/* The end of a logical line: end of text, a line terminator, or a comment. */
static int at_line_end(const parser *p)
{
    return p->pos >= p->len || meshtext_eol(p->text[p->pos]) || p->text[p->pos] == '#';
}

static int is_token_byte(const parser *p, size_t i)
{
    char c = p->text[i];
    return !meshtext_blank(c) && !meshtext_eol(c) && c != '#' && !continuation_end(p, i);
}

/* Reads the next token of the logical line into *tok; returns 0 at its end. */
static int next_token(parser *p, src_span *tok)
{
    skip_blank(p);
    if (at_line_end(p))
        return 0;
    tok->file = p->file;
    tok->begin = p->pos;
    while (p->pos < p->len && is_token_byte(p, p->pos))
        p->pos++;
    tok->end = p->pos;
    return 1;
}

/* Moves past the rest of the logical line: tokens, a comment, the terminator. */
static void skip_line(parser *p)
{
    src_span tok;
    while (next_token(p, &tok))
        continue;
    while (p->pos < p->len && !meshtext_eol(p->text[p->pos]))
        p->pos++;
    p->pos += meshtext_eol_length(p->text, p->len, p->pos);
}

static int token_is(const parser *p, src_span tok, const char *word)
{
    size_t n = strlen(word);
    return tok.end - tok.begin == n && memcmp(p->text + tok.begin, word, n) == 0;
}

static src_span span_at(const parser *p, size_t offset)
{
    src_span s;
    s.file = p->file;
    s.begin = s.end = offset;
    return s;
}

static int is_number_byte(char c)
{
    return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.' || c == 'e' || c == 'E';
}

/* Parses tok as a finite decimal number into *out; reports and returns 0 if
 * it is not one.  Only digits, signs, '.' and exponent letters pass the first
 * check, which keeps strtod's "inf", "nan" and hexadecimal forms (no OBJ
 * writer emits them) out; strtod must then consume the whole token. */
static int read_number(parser *p, src_span tok, double *out)
{
    size_t n = tok.end - tok.begin;
    const char *s = p->text + tok.begin;
    if (n > NUMBER_MAX) {
        meshtext_shown q = meshtext_show(p->text, tok);
        diag_report(p->d, DIAG_ERROR, tok, "number '%s' is too long (more than %d characters)",
                    q.s, NUMBER_MAX);
        return 0;
    }
    char buf[NUMBER_MAX + 1], *end = buf;
    size_t i = 0;
    while (i < n && is_number_byte(s[i]))
        i++;
    memcpy(buf, s, n);
    buf[n] = '\0';
    double v = i == n ? strtod(buf, &end) : 0.0;
    if (i < n || end != buf + n) {
        meshtext_shown q = meshtext_show(p->text, tok);
        diag_report(p->d, DIAG_ERROR, tok, "malformed number '%s'", q.s);
        return 0;
    }
    if (!isfinite(v)) {
        meshtext_shown q = meshtext_show(p->text, tok);
        diag_report(p->d, DIAG_ERROR, tok, "number '%s' is not finite", q.s);
        return 0;
    }
    *out = v;
    return 1;
}

/* index: '-'? digit+.  Saturates at INDEX_SATURATED instead of overflowing. */
static int read_index(parser *p, src_span tok, long long *out)
{
    size_t i = tok.begin;
    int negative = i < tok.end && p->text[i] == '-';
    long long k = 0;
    i += (size_t)negative;
    if (i == tok.end)
        k = -1;
    for (; i < tok.end && k >= 0; i++) {
        char c = p->text[i];
        if (c < '0' || c > '9')
            k = -1;
        else if (k < INDEX_SATURATED)
            k = k * 10 + (c - '0');
    }
    if (k < 0) {
        meshtext_shown q = meshtext_show(p->text, tok);
        diag_report(p->d, DIAG_ERROR, tok, "malformed index '%s'", q.s);
        return 0;
    }
    *out = negative ? -k : k;
    return 1;
}

/* Resolves the OBJ index in tok against the `count` items (named `what`)
 * defined so far: k >= 1 is the k-th, -k the k-th counted back from the
 * last.  Stores the 0-based index; reports and returns 0 when the index is 0
 * or names an item that does not exist yet (forward references, which the
 * format allows in theory but no writer uses, are refused). */
static int resolve_index(parser *p, src_span tok, int count, const char *what, int *out)
{
    long long k;
    if (!read_index(p, tok, &k))
        return 0;
    if (k >= -(long long)count && k <= count && k != 0) {
        *out = k > 0 ? (int)(k - 1) : (int)(count + k);
        return 1;
    }
    meshtext_shown q = meshtext_show(p->text, tok);
    if (k == 0) {
        diag_report(p->d, DIAG_ERROR, tok,
                    "index 0 is invalid: OBJ indices start at 1 (or count back from -1)");
        return 0;
    }
    if (k > count)
        diag_report(p->d, DIAG_ERROR, tok, "index %s refers to a %s not yet defined (%d so far)",
                    q.s, what, count);
    else
        diag_report(p->d, DIAG_ERROR, tok, "index %s reaches before the first %s (%d so far)",
                    q.s, what, count);
    return 0;
}

static void out_of_memory(parser *p, src_span where)
{
    diag_report(p->d, DIAG_ERROR, where, "out of memory reading OBJ file");
    p->stop = 1;
    p->out_of_memory = 1;
}

/* Reports what a polymesh_add_* call refused; returns whether it succeeded. */
static int added(parser *p, int status, src_span where, const char *what)
{
    if (status == 1)
        return 1;
    if (status == POLYMESH_NO_MEMORY)
        out_of_memory(p, where);
    else if (what)
        diag_report(p->d, DIAG_ERROR, where, "too many %s in OBJ file (limit %d)", what, INT_MAX);
    else
        diag_report(p->d, DIAG_ERROR, where, "mesh exceeds the limit of %ld triangles (--max-mesh-triangles)",
                    p->mesh->max_triangles);
    p->stop = 1;
    return 0;
}

/* Reads x y z into *v.  When tokens run out, reports at the end of the last
 * one read ("'v' needs 3 coordinates, got 2"). */
static int read_coords(parser *p, src_span kw, vec3 *v)
{
    double c[3];
    src_span tok = kw;
    for (int i = 0; i < 3; i++) {
        size_t last_end = tok.end;
        if (!next_token(p, &tok)) {
            meshtext_shown q = meshtext_show(p->text, kw);
            diag_report(p->d, DIAG_ERROR, span_at(p, last_end), "'%s' needs 3 coordinates, got %d",
                        q.s, i);
            return 0;
        }
        if (!read_number(p, tok, &c[i]))
            return 0;
    }
    *v = vec_make(c[0], c[1], c[2]);
    return 1;
}

/* v x y z [w]: w, and the r g b colours some writers append, are dropped
 * once known to be numbers; more than VERTEX_VALUES_MAX numbers is no
 * vertex any writer makes (a 30-million-value line must not pass). */
static void parse_vertex(parser *p, src_span kw)
{
    vec3 v;
    src_span tok;
    double ignored;
    if (!read_coords(p, kw, &v))
        return;
    for (int n = 3; next_token(p, &tok); n++) {
        if (n == VERTEX_VALUES_MAX) {
            diag_report(p->d, DIAG_ERROR, tok, "'v' takes at most %d numbers (x y z, then w or r g b)",
                        VERTEX_VALUES_MAX);
            return;
        }
        if (!read_number(p, tok, &ignored))
            return;
    }
    added(p, polymesh_add_position(p->mesh, v), kw, "vertices");
}

/* vn x y z */
static void parse_normal(parser *p, src_span kw)
{
    vec3 n;
    src_span tok;
    if (!read_coords(p, kw, &n))
        return;
    if (next_token(p, &tok)) {
        meshtext_shown q = meshtext_show(p->text, tok);
        diag_report(p->d, DIAG_ERROR, tok, "unexpected '%s' after the 3 coordinates of 'vn'", q.s);
        return;
    }
    /* Checked here, so the error points at the normal, not at a face using
     * it; the normal is still kept, so the faces' indices stay right. */
    if (n.x == 0 && n.y == 0 && n.z == 0)
        diag_report(p->d, DIAG_ERROR, kw, "vertex normal of zero length");
    added(p, polymesh_add_normal(p->mesh, n), kw, "normals");
}

/* Splits tok at '/' into field[0..2]; returns the number of fields, or 4
 * when there are more than three. */
static int split_fields(const parser *p, src_span tok, src_span field[3])
{
    int n = 0;
    field[0] = tok;
    for (size_t i = tok.begin; i < tok.end; i++) {
        if (p->text[i] != '/')
            continue;
        if (n == 2)
            return 4;
        field[n].end = i;
        field[++n] = tok;
        field[n].begin = i + 1;
    }
    return n + 1;
}

static int is_empty(src_span s)
{
    return s.begin == s.end;
}

/* corner: i | i/t | i//n | i/t/n.  Resolves the position and normal indices
 * into *v and *vn (-1: none) and range-checks the texture one. */
static int parse_corner(parser *p, src_span tok, int *v, int *vn, int *has_normal)
{
    src_span field[3];
    int n = split_fields(p, tok, field), ignored;
    int well_formed = n <= 3 && !is_empty(field[0]) && (n != 2 || !is_empty(field[1]))
                      && (n != 3 || !is_empty(field[2]));
    if (!well_formed) {
        meshtext_shown q = meshtext_show(p->text, tok);
        diag_report(p->d, DIAG_ERROR, tok,
                    "malformed face vertex '%s' (expected i, i/t, i//n or i/t/n)", q.s);
        return 0;
    }
    if (!resolve_index(p, field[0], p->mesh->position_count, "vertex", v))
        return 0;
    if (n >= 2 && !is_empty(field[1])
        && !resolve_index(p, field[1], p->texcoord_count, "texture coordinate", &ignored))
        return 0;
    *vn = -1;
    *has_normal = n == 3;
    return n < 3 || resolve_index(p, field[2], p->mesh->normal_count, "normal", vn);
}

/* Reads one corner token as the face's n-th; 0 after reporting a problem. */
static int add_corner(parser *p, src_span tok, int n, int *first_has_normal)
{
    int v, vn, has_normal;
    if (!parse_corner(p, tok, &v, &vn, &has_normal))
        return 0;
    if (n == 0)
        *first_has_normal = has_normal;
    if (has_normal != *first_has_normal) {
        meshtext_shown q = meshtext_show(p->text, tok);
        diag_report(p->d, DIAG_ERROR, tok,
                    "face vertex '%s' %s a normal index but the face's first vertex %s", q.s,
                    has_normal ? "has" : "lacks", has_normal ? "has none" : "has one");
        return 0;
    }
    const mem *m = &p->mesh->mem;
    int *cv = polymesh_grow(m, p->corner_v, &p->corner_v_cap, (long)n + 1, sizeof *cv, INT_MAX);
    if (cv)
        p->corner_v = cv;
    int *cn = cv ? polymesh_grow(m, p->corner_vn, &p->corner_vn_cap, (long)n + 1, sizeof *cn, INT_MAX) : NULL;
    if (cn)
        p->corner_vn = cn;
    if (!cv || !cn) {
        out_of_memory(p, tok);
        return 0;
    }
    p->corner_v[n] = v;
    p->corner_vn[n] = vn;
    return 1;
}

/* f corner corner corner ... */
static void parse_face(parser *p, src_span kw)
{
    src_span tok, where = kw;
    int n = 0, first_has_normal = 0;
    while (next_token(p, &tok)) {
        if (n == INT_MAX || !add_corner(p, tok, n, &first_has_normal))
            return;
        n++;
        where.end = tok.end;
    }
    if (n < 3) {
        diag_report(p->d, DIAG_ERROR, where, "face has %d vertices, needs at least 3", n);
        return;
    }
    added(p, polymesh_add_face(p->mesh, p->corner_v, first_has_normal ? p->corner_vn : NULL, n, kw.begin),
          where, NULL);
}

/* Warns once per kind of unknown statement, for the first WARNED_MAX kinds;
 * the last of those says that later ones go unreported, so a garbage file
 * cannot flood the output with warnings. */
static void warn_unknown(parser *p, src_span kw)
{
    size_t n = kw.end - kw.begin;
    for (int i = 0; i < p->warned_count; i++) {
        src_span w = p->warned[i];
        if (w.end - w.begin == n && memcmp(p->text + w.begin, p->text + kw.begin, n) == 0)
            return;
    }
    if (p->warned_count == WARNED_MAX)
        return;
    p->warned[p->warned_count++] = kw;
    meshtext_shown q = meshtext_show(p->text, kw);
    diag_report(p->d, DIAG_WARNING, kw, "unknown OBJ statement '%s' ignored%s", q.s,
                p->warned_count == WARNED_MAX ? " (further unknown statements are not reported)"
                                              : "");
}

/* Statements common in OBJ files that carry nothing a mesh of positions and
 * normals needs: ignored without a word. */
static const char *const quiet_keywords[] = {"o", "g", "s", "usemtl", "mtllib"};

static void parse_statement(parser *p, src_span kw)
{
    if (token_is(p, kw, "v"))
        parse_vertex(p, kw);
    else if (token_is(p, kw, "vn"))
        parse_normal(p, kw);
    else if (token_is(p, kw, "f"))
        parse_face(p, kw);
    else if (token_is(p, kw, "vt"))
        p->texcoord_count += p->texcoord_count < INT_MAX;
    else {
        for (size_t i = 0; i < sizeof quiet_keywords / sizeof quiet_keywords[0]; i++)
            if (token_is(p, kw, quiet_keywords[i]))
                return;
        warn_unknown(p, kw);
    }
}

/* Refuses a NUL byte anywhere: it has no place in a text format and would
 * cut C strings short. */
static int check_no_nul(parser *p)
{
    const char *nul = memchr(p->text, '\0', p->len);
    if (!nul)
        return 1;
    src_span s = span_at(p, (size_t)(nul - p->text));
    s.end++;
    diag_report(p->d, DIAG_ERROR, s, "NUL byte in OBJ file");
    return 0;
}

static void parse_file(parser *p)
{
    if (p->len >= 3 && memcmp(p->text, "\xEF\xBB\xBF", 3) == 0)
        p->pos = 3;
    while (p->pos < p->len && !p->stop && !diag_stop(p->d)) {
        src_span kw;
        if (next_token(p, &kw))
            parse_statement(p, kw);
        skip_line(p);
    }
}

int obj_parse(const source_set *sources, int file, diag *d, long max_triangles, polymesh *out)
{
    assert(sources && file >= 0 && file < sources->count);
    const source_file *f = sources->files[file];
    int errors_before = d->errors;
    parser p;
    memset(&p, 0, sizeof p);
    polymesh_init(out, max_triangles, &sources->mem);
    p.text = f->text;
    p.len = f->len;
    p.file = file;
    p.d = d;
    p.mesh = out;
    if (check_no_nul(&p))
        parse_file(&p);
    mem_free(&out->mem, p.corner_v, (size_t)p.corner_v_cap * sizeof *p.corner_v);
    mem_free(&out->mem, p.corner_vn, (size_t)p.corner_vn_cap * sizeof *p.corner_vn);
    src_span start = span_at(&p, 0);
    return polymesh_finish(out, d, errors_before, &start, cancel_stopped(d->cancel), p.out_of_memory);
}
