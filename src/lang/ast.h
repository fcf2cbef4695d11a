/*
 * ast.h - the syntax tree the grammar builds.  Grammar actions only build
 * these nodes; names, types and ranges are checked by the lowering pass,
 * which keeps every node's span for its diagnostics.  Nodes live in the
 * parse's arena and are never freed one by one.
 */
#ifndef REFRAY_AST_H
#define REFRAY_AST_H

#include "base/arena.h"
#include "base/source.h"

typedef enum ast_kind {
    AST_NUMBER,      /* number */
    AST_STRING,      /* text */
    AST_NAME,        /* text: a constant, material or enum name */
    AST_VECTOR,      /* children: the components as written ([a, b] keeps 2) */
    AST_NEGATE,      /* child: operand */
    AST_BINARY,      /* op: + - * / ^; children: left, right */
    AST_CALL,        /* keyword: function id, or -1 with text for an unknown one */
    AST_PROPERTY,    /* keyword: its id; children: the values (a block for inline material) */
    AST_BLOCK,       /* keyword: block id; text: name of `material NAME {}`; children: properties */
    AST_LET,         /* text: name (keyword >= 0 when a reserved word was used); child: value */
    AST_FOR,         /* text: variable; children: from, to, then the body statements */
    AST_INCLUDE,     /* text: the path as written */
    AST_ORACLE       /* text: the oracle's name */
} ast_kind;

typedef struct ast ast;
struct ast {
    ast_kind kind;
    src_span span;      /* the whole construct */
    src_span head;      /* the word that introduces it (keyword, name, operator) */
    int keyword;        /* keyword_id, or -1 */
    int op;             /* operator character for AST_BINARY */
    double number;
    const char *text;
    ast *first;         /* first child */
    ast *last;          /* last child, for appending in order */
    ast *next;          /* next sibling */
    int count;          /* number of children */
};

ast *ast_new(arena *a, ast_kind kind, src_span span);
/* Appends child (may be NULL: then nothing happens) and widens parent's span. */
ast *ast_append(ast *parent, ast *child);

#endif
