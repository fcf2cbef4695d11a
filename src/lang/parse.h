/*
 * parse.h - turns one source file into a syntax tree (flex + bison, both
 * reentrant: all state lives in parse_ctx and the scanner handle).
 */
#ifndef REFRAY_PARSE_H
#define REFRAY_PARSE_H

#include <setjmp.h>
#include "base/arena.h"
#include "lang/ast.h"
#include "base/diag.h"
#include "base/source.h"

enum { PARSE_MAX_BRACKETS = 256 };

/* What one bracket level holds, as far as the scanner must know to tell a
 * property word used as a property from one used as a name
 * ([LANG-LEX-WORD-3]): a property may start only in a block body, where
 * the previous property has all its values and no operator waits for an
 * operand. */
typedef enum parse_level_kind {
    LEVEL_STATEMENTS,         /* the file, or a loop body */
    LEVEL_BLOCK,              /* the properties of a block, or of an inline material */
    LEVEL_EXPR                /* inside [ ] or ( ) */
} parse_level_kind;

typedef struct parse_level {
    parse_level_kind kind;
    int arity;                /* values the current property takes */
    int values;               /* values of it begun so far */
    int mid;                  /* an operator or sign waits for its operand */
    int ended;                /* the last token ended an operand */
} parse_level;

/* Shared by the scanner and the parser of one file. */
typedef struct parse_ctx {
    arena *arena;
    diag *diag;
    const source_set *sources;
    int file;                 /* index of the file being read */
    size_t offset;            /* scanner position, bytes */
    ast *root;                /* statement list being built */
    int out_of_memory;
    int cancelled;            /* the load's cancel poll said stop (diag.cancel) */
    int too_deep;             /* the parse stopped at the nesting limit (reported) */
    const char *scan_message; /* what was wrong with the last BAD_* token */
    int bracket_depth;        /* open '{' '[' '(' not yet closed */
    char pending_close;       /* a closer scanned but not yet applied, or 0 */
    src_span brackets[PARSE_MAX_BRACKETS]; /* where the innermost ones opened */
    void *stacks[3];          /* the parser's stacks once grown past yyparse's own */
    size_t stack_bytes[3];
    union parse_block *blocks; /* the scanner's live allocations */
    jmp_buf fatal;            /* where a scanner failure returns to (parse_fatal) */
    parse_level level;        /* the innermost bracket level */
    parse_level outer[PARSE_MAX_BRACKETS]; /* the level around each open bracket */
    int last_token, token_before; /* the two tokens scanned last (0: none) */
} parse_ctx;

/*
 * Parses sources->files[file].  Syntax errors are reported through d (with
 * recovery, so one run reports several); the returned statement list holds
 * whatever parsed (nothing, when the nesting limit stopped the parse).
 * Returns NULL only when memory ran out, or when d->cancel said stop
 * (cancel_stopped(d->cancel) then holds).  Everything the scanner and the
 * parser allocate comes from the arena's allocator (a->mem).
 */
ast *parse_file(arena *a, diag *d, const source_set *sources, int file);

/* Reports a syntax error at span (the parser's one way to speak). */
void parse_report_syntax(parse_ctx *ctx, src_span span, const char *message);

/*
 * The scanner's memory (flex's yyalloc, yyrealloc, yyfree): blocks from the
 * arena's allocator, each with a header that keeps its size (flex frees
 * without one) and links it into ctx->blocks, so that parse_file can free
 * whatever a failed scanner left.  resize with p NULL allocates; free of
 * NULL does nothing.
 */
void *parse_block_alloc(parse_ctx *ctx, size_t size);
void *parse_block_resize(parse_ctx *ctx, void *p, size_t size);
void parse_block_free(parse_ctx *ctx, void *p);

/* flex's fatal error (YY_FATAL_ERROR): for a scanner of a buffer in memory
 * only an allocation can fail, so it counts as out of memory; control
 * returns to parse_file (longjmp), which frees the scanner's blocks.  flex's
 * own handler would print and exit. */
void parse_fatal(parse_ctx *ctx);

#endif
