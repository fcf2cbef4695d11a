/*
 * eval.h - values and constant expressions of the scene language.
 *
 * Expressions are evaluated while the scene is lowered: there are no
 * run-time variables, only constants (`let`, loop variables, `pi`).  Every
 * number that comes out of here is finite: an overflow, a division by zero
 * or a function outside its domain is an error at the operator's span.
 */
#ifndef REFRAY_EVAL_H
#define REFRAY_EVAL_H

#include "lang/ast.h"
#include "base/diag.h"
#include "base/mem.h"
#include "base/names.h"
#include "base/vec.h"

typedef enum value_kind {
    VAL_NUMBER,
    VAL_VECTOR,
    VAL_STRING
} value_kind;

typedef struct value {
    value_kind kind;
    double number;
    vec3 vector;
    const char *text;
    src_span span;     /* the expression it came from */
} value;

typedef struct binding {
    const char *name;
    value value;
    src_span where;    /* the name in its `let` or `for` */
} binding;

/* Constants in scope, innermost last.  A scope is a mark into the array.
 * Names are found through a hash index (base/names.h): O(1) expected
 * comparisons per lookup, whatever the number of constants. */
typedef struct env {
    binding *items;
    int count;
    int cap;
    mem mem;
    name_index index;  /* over items; its comparisons count every lookup's work */
} env;

/* An empty scope whose bindings live in memory from m (NULL: the C
 * library).  e must not move while it is in use (its index points to it). */
void env_init(env *e, const mem *m);
void env_free(env *e);
/* Adds a binding; 0 when out of memory. */
int env_bind(env *e, const char *name, value v, src_span where);
const binding *env_find(const env *e, const char *name);
/* Drops every binding made after mark (a scope is the count at its start). */
void env_restore(env *e, int mark);

/* Evaluates node; reports errors to d and returns 0 on failure. */
int eval_expr(const env *e, diag *d, const ast *node, value *out);

/* "number", "vector", "string": for messages. */
const char *value_kind_name(value_kind kind);

/* A "did you mean" among the names in scope, or NULL. */
const char *env_suggest(const env *e, const char *name);

#endif
