/*
 * eval.c - constant folding of the scene language's expressions.
 */
#include <math.h>
#include <string.h>
#include "lang/eval.h"
#include "lang/keywords.h"
#include "base/suggest.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* Nested operators, calls and vectors an expression may hold.  Evaluation
 * recurses once per level, so the bound keeps a generated `1+1+...+1` of a
 * million terms from overflowing the C stack; no hand-written expression
 * comes near it. */
enum { SUGGEST_MAX = 64, EVAL_MAX_DEPTH = 1000 };

static int eval_at(const env *e, diag *d, const ast *node, value *out, int depth);

static const char *binding_name(const void *ctx, int i)
{
    return ((const env *)ctx)->items[i].name;
}

void env_init(env *e, const mem *m)
{
    e->items = NULL;
    e->count = 0;
    e->cap = 0;
    e->mem = mem_pick(m);
    name_index_init(&e->index, binding_name, e, &e->mem);
}

void env_free(env *e)
{
    mem m = e->mem;
    name_index_free(&e->index);
    mem_free(&m, e->items, (size_t)e->cap * sizeof *e->items);
    env_init(e, &m);
}

int env_bind(env *e, const char *name, value v, src_span where)
{
    if (e->count == e->cap) {
        int cap = e->cap ? 2 * e->cap : 16;
        binding *items = mem_resize_array(&e->mem, e->items, (size_t)e->cap, (size_t)cap, sizeof *items);
        if (!items)
            return 0;
        e->items = items;
        e->cap = cap;
    }
    binding *b = &e->items[e->count];
    b->name = name;
    b->value = v;
    b->where = where;
    if (!name_index_add(&e->index, e->count))
        return 0;
    e->count++;
    return 1;
}

const binding *env_find(const env *e, const char *name)
{
    /* A lookup only counts its comparisons into the index: the scope
     * itself does not change, hence the const interface. */
    int i = name_index_find((name_index *)&e->index, name);
    return i >= 0 ? &e->items[i] : NULL;
}

void env_restore(env *e, int mark)
{
    while (e->count > mark)
        name_index_remove(&e->index, --e->count);
}

const char *env_suggest(const env *e, const char *name)
{
    const char *names[SUGGEST_MAX + 1];
    int count = 0;
    names[count++] = "pi";
    for (int i = e->count - 1; i >= 0 && count < SUGGEST_MAX; i--)
        names[count++] = e->items[i].name;
    return suggest_nearest(name, strlen(name), names, count);
}

const char *value_kind_name(value_kind kind)
{
    return kind == VAL_NUMBER ? "number" : kind == VAL_VECTOR ? "vector" : "string";
}

static value number_value(double x, src_span span)
{
    value v = {VAL_NUMBER, x, {0, 0, 0}, NULL, span};
    return v;
}

static value vector_value(vec3 x, src_span span)
{
    value v = {VAL_VECTOR, 0, x, NULL, span};
    return v;
}

/* The finiteness check every result passes: literals (1e400) included. */
static int finite_or_report(diag *d, const value *v, src_span at, const char *what)
{
    int ok = v->kind == VAL_NUMBER ? isfinite(v->number) : v->kind == VAL_VECTOR ? vec_is_finite(v->vector) : 1;
    if (!ok)
        diag_report(d, DIAG_ERROR, at, "%s is not a finite number", what);
    return ok;
}

static int eval_name(const env *e, diag *d, const ast *node, value *out)
{
    const binding *b = env_find(e, node->text);
    if (b) {
        *out = b->value;
        out->span = node->span;
        return 1;
    }
    if (strcmp(node->text, "pi") == 0) {
        *out = number_value(M_PI, node->span);
        return 1;
    }
    const char *hint = env_suggest(e, node->text);
    if (hint)
        diag_report(d, DIAG_ERROR, node->span, "unknown constant '%s'; did you mean '%s'?", node->text, hint);
    else
        diag_report(d, DIAG_ERROR, node->span, "unknown constant '%s'", node->text);
    return 0;
}

static int eval_vector(const env *e, diag *d, const ast *node, value *out, int depth)
{
    if (node->count != 3) {
        diag_report(d, DIAG_ERROR, node->span, "a vector has 3 components, this one has %d", node->count);
        return 0;
    }
    double c[3];
    int i = 0;
    for (const ast *k = node->first; k; k = k->next, i++) {
        value v;
        if (!eval_at(e, d, k, &v, depth + 1))
            return 0;
        if (v.kind != VAL_NUMBER) {
            diag_report(d, DIAG_ERROR, k->span, "a vector component must be a number, not a %s",
                        value_kind_name(v.kind));
            return 0;
        }
        c[i] = v.number;
    }
    *out = vector_value(vec_make(c[0], c[1], c[2]), node->span);
    return 1;
}

static int eval_negate(const env *e, diag *d, const ast *node, value *out, int depth)
{
    if (!eval_at(e, d, node->first, out, depth + 1))
        return 0;
    if (out->kind == VAL_STRING) {
        diag_report(d, DIAG_ERROR, node->head, "cannot negate a string");
        return 0;
    }
    out->number = -out->number;
    out->vector = vec_neg(out->vector);
    out->span = node->span;
    return 1;
}

static int binary_numbers(diag *d, const ast *node, double a, double b, double *r)
{
    switch (node->op) {
    case '+': *r = a + b; break;
    case '-': *r = a - b; break;
    case '*': *r = a * b; break;
    case '/':
        if (b == 0) {
            diag_report(d, DIAG_ERROR, node->head, "division by zero");
            return 0;
        }
        *r = a / b;
        break;
    default:
        *r = pow(a, b);
        if (isnan(*r)) {
            diag_report(d, DIAG_ERROR, node->head, "%g ^ %g is not a real number", a, b);
            return 0;
        }
    }
    return 1;
}

/* vector +- vector, number * vector, vector * number, vector / number. */
static int binary_vectors(diag *d, const ast *node, const value *a, const value *b, value *r)
{
    int op = node->op;
    if (a->kind == VAL_VECTOR && b->kind == VAL_VECTOR && (op == '+' || op == '-')) {
        *r = vector_value(op == '+' ? vec_add(a->vector, b->vector) : vec_sub(a->vector, b->vector), node->span);
        return 1;
    }
    if (op == '*' && (a->kind == VAL_NUMBER) != (b->kind == VAL_NUMBER)) {
        const value *s = a->kind == VAL_NUMBER ? a : b, *v = a->kind == VAL_NUMBER ? b : a;
        *r = vector_value(vec_scale(v->vector, s->number), node->span);
        return 1;
    }
    if (op == '/' && a->kind == VAL_VECTOR && b->kind == VAL_NUMBER) {
        if (b->number == 0) {
            diag_report(d, DIAG_ERROR, node->head, "division by zero");
            return 0;
        }
        *r = vector_value(vec_make(a->vector.x / b->number, a->vector.y / b->number, a->vector.z / b->number),
                          node->span);
        return 1;
    }
    const char *hint = op == '*' && a->kind == VAL_VECTOR && b->kind == VAL_VECTOR
                           ? " (use dot() or cross() to multiply vectors)" : "";
    diag_report(d, DIAG_ERROR, node->head, "cannot apply '%c' to a %s and a %s%s", op,
                value_kind_name(a->kind), value_kind_name(b->kind), hint);
    return 0;
}

static int eval_binary(const env *e, diag *d, const ast *node, value *out, int depth)
{
    value a, b;
    if (!eval_at(e, d, node->first, &a, depth + 1) || !eval_at(e, d, node->first->next, &b, depth + 1))
        return 0;
    if (a.kind == VAL_STRING || b.kind == VAL_STRING) {
        diag_report(d, DIAG_ERROR, node->head, "cannot apply '%c' to a string", node->op);
        return 0;
    }
    if (a.kind == VAL_NUMBER && b.kind == VAL_NUMBER) {
        double r;
        if (!binary_numbers(d, node, a.number, b.number, &r))
            return 0;
        *out = number_value(r, node->span);
    } else if (!binary_vectors(d, node, &a, &b, out)) {
        return 0;
    }
    return finite_or_report(d, out, node->head, "the result");
}

/* Functions of one number; 0 with *why set when x is outside the domain. */
static int math1(int fn, double x, double *r, const char **why)
{
    *why = NULL;
    switch (fn) {
    case KW_SQRT: *r = sqrt(x); *why = x < 0 ? "sqrt of a negative number" : NULL; break;
    case KW_SIN: *r = sin(x); break;
    case KW_COS: *r = cos(x); break;
    case KW_TAN: *r = tan(x); break;
    case KW_ASIN: *r = asin(x); *why = fabs(x) > 1 ? "asin outside [-1, 1]" : NULL; break;
    case KW_ACOS: *r = acos(x); *why = fabs(x) > 1 ? "acos outside [-1, 1]" : NULL; break;
    case KW_ABS: *r = fabs(x); break;
    case KW_EXP: *r = exp(x); break;
    case KW_LOG: *r = log(x); *why = x <= 0 ? "log of a number <= 0" : NULL; break;
    case KW_FLOOR: *r = floor(x); break;
    case KW_RADIANS: *r = x * (M_PI / 180.0); break;
    default: *r = x * (180.0 / M_PI); break;
    }
    return *why == NULL;
}

static int math2(int fn, double x, double y, double *r)
{
    switch (fn) {
    case KW_ATAN2: *r = atan2(x, y); break;
    case KW_POW: *r = pow(x, y); break;
    case KW_MIN: *r = fmin(x, y); break;
    default: *r = fmax(x, y); break;
    }
    return !isnan(*r);
}

static int expect_kind(diag *d, const value *v, value_kind kind, const char *fn)
{
    if (v->kind == kind)
        return 1;
    diag_report(d, DIAG_ERROR, v->span, "%s expects a %s here, not a %s", fn, value_kind_name(kind),
                value_kind_name(v->kind));
    return 0;
}

static int call_vector_fn(diag *d, int fn, const value *args, value *out, src_span span)
{
    const char *name = keyword_name((keyword_id)fn);
    for (int i = 0; i < keyword_get((keyword_id)fn)->arity; i++)
        if (!expect_kind(d, &args[i], VAL_VECTOR, name))
            return 0;
    switch (fn) {
    case KW_DOT: *out = number_value(vec_dot(args[0].vector, args[1].vector), span); break;
    case KW_CROSS: *out = vector_value(vec_cross(args[0].vector, args[1].vector), span); break;
    case KW_LENGTH: *out = number_value(vec_length(args[0].vector), span); break;
    default:
        if (vec_length(args[0].vector) == 0) {
            diag_report(d, DIAG_ERROR, args[0].span, "cannot normalize a zero-length vector");
            return 0;
        }
        *out = vector_value(vec_normalize(args[0].vector), span);
    }
    return 1;
}

static int call_number_fn(diag *d, int fn, const value *args, value *out, src_span span)
{
    const char *name = keyword_name((keyword_id)fn);
    int arity = keyword_get((keyword_id)fn)->arity;
    for (int i = 0; i < arity; i++)
        if (!expect_kind(d, &args[i], VAL_NUMBER, name))
            return 0;
    double r;
    const char *why = NULL;
    int ok = arity == 1 ? math1(fn, args[0].number, &r, &why) : math2(fn, args[0].number, args[1].number, &r);
    if (!ok) {
        if (why)
            diag_report(d, DIAG_ERROR, span, "%s (argument %g)", why, args[0].number);
        else
            diag_report(d, DIAG_ERROR, span, "%s(%g, %g) is not a real number", name, args[0].number,
                        args[1].number);
        return 0;
    }
    *out = number_value(r, span);
    return 1;
}

static int eval_call(const env *e, diag *d, const ast *node, value *out, int depth)
{
    if (node->keyword < 0) {
        const char *names[KEYWORD_COUNT];
        int count = 0;
        for (int i = 0; i < KEYWORD_COUNT; i++)
            if (keyword_get((keyword_id)i)->cls == KWC_FUNCTION)
                names[count++] = keyword_name((keyword_id)i);
        const char *hint = suggest_nearest(node->text, strlen(node->text), names, count);
        diag_report(d, DIAG_ERROR, node->head, "unknown function '%s'%s%s%s", node->text,
                    hint ? "; did you mean '" : "", hint ? hint : "", hint ? "'?" : "");
        return 0;
    }
    int fn = node->keyword, arity = keyword_get((keyword_id)fn)->arity;
    if (node->count != arity) {
        diag_report(d, DIAG_ERROR, node->span, "%s takes %d argument%s, got %d", keyword_name((keyword_id)fn),
                    arity, arity == 1 ? "" : "s", node->count);
        return 0;
    }
    value args[2];
    int i = 0;
    for (const ast *k = node->first; k; k = k->next)
        if (!eval_at(e, d, k, &args[i++], depth + 1))
            return 0;
    int vector_fn = fn == KW_DOT || fn == KW_CROSS || fn == KW_NORMALIZE || fn == KW_LENGTH;
    if (!(vector_fn ? call_vector_fn : call_number_fn)(d, fn, args, out, node->span))
        return 0;
    return finite_or_report(d, out, node->span, "the result");
}

static int eval_at(const env *e, diag *d, const ast *node, value *out, int depth)
{
    if (depth > EVAL_MAX_DEPTH) {
        diag_report(d, DIAG_ERROR, node->span, "expression nested too deep (more than %d operators, calls or "
                    "vectors inside each other)", EVAL_MAX_DEPTH);
        return 0;
    }
    switch (node->kind) {
    case AST_NUMBER:
        *out = number_value(node->number, node->span);
        if (!isfinite(node->number)) {
            diag_report(d, DIAG_ERROR, node->span, "number out of range (the largest is about 1.8e308)");
            return 0;
        }
        return 1;
    case AST_STRING:
        *out = number_value(0, node->span);
        out->kind = VAL_STRING;
        out->text = node->text;
        return 1;
    case AST_NAME:
        return eval_name(e, d, node, out);
    case AST_VECTOR:
        return eval_vector(e, d, node, out, depth);
    case AST_NEGATE:
        return eval_negate(e, d, node, out, depth);
    case AST_BINARY:
        return eval_binary(e, d, node, out, depth);
    case AST_CALL:
        return eval_call(e, d, node, out, depth);
    default:
        diag_report(d, DIAG_ERROR, node->span, "expected a value here");
        return 0;
    }
}

int eval_expr(const env *e, diag *d, const ast *node, value *out)
{
    return eval_at(e, d, node, out, 0);
}
