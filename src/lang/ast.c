/*
 * ast.c - node construction for the grammar actions.
 */
#include "lang/ast.h"

ast *ast_new(arena *a, ast_kind kind, src_span span)
{
    ast *node = arena_alloc(a, sizeof *node);
    if (!node)
        return NULL;
    node->kind = kind;
    node->span = span;
    node->head = span;
    node->keyword = -1;
    return node;
}

ast *ast_append(ast *parent, ast *child)
{
    if (!parent || !child)
        return parent;
    if (parent->last)
        parent->last->next = child;
    else
        parent->first = child;
    parent->last = child;
    parent->count++;
    parent->span = src_span_join(parent->span, child->span);
    return parent;
}
