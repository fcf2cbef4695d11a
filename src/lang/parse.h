/*
 * parse.h - turns one source file into a syntax tree (flex + bison, both
 * reentrant: all state lives in parse_ctx and the scanner handle).
 */
#ifndef REFRAY_PARSE_H
#define REFRAY_PARSE_H

#include "base/arena.h"
#include "lang/ast.h"
#include "base/diag.h"
#include "base/source.h"

enum { PARSE_MAX_BRACKETS = 256 };

/* Shared by the scanner and the parser of one file. */
typedef struct parse_ctx {
    arena *arena;
    diag *diag;
    const source_set *sources;
    int file;                 /* index of the file being read */
    size_t offset;            /* scanner position, bytes */
    ast *root;                /* statement list being built */
    int out_of_memory;
    int too_deep;             /* the parse stopped at the nesting limit (reported) */
    const char *scan_message; /* what was wrong with the last BAD_* token */
    int bracket_depth;        /* open '{' '[' '(' not yet closed */
    char pending_close;       /* a closer scanned but not yet applied, or 0 */
    src_span brackets[PARSE_MAX_BRACKETS]; /* where the innermost ones opened */
} parse_ctx;

/*
 * Parses sources->files[file].  Syntax errors are reported through d (with
 * recovery, so one run reports several); the returned statement list holds
 * whatever parsed (nothing, when the nesting limit stopped the parse).
 * Returns NULL only when memory ran out.
 */
ast *parse_file(arena *a, diag *d, const source_set *sources, int file);

/* Reports a syntax error at span (the parser's one way to speak). */
void parse_report_syntax(parse_ctx *ctx, src_span span, const char *message);

#endif
