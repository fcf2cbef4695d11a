/*
 * parse_hints.h - syntax errors where people are known to stumble, said in
 * their own terms instead of as "unexpected X, expecting Y"
 * (spec/language.md, [LANG-DIAG-STUMBLE-1]):
 *   - a block whose '}' is missing, seen when the next statement starts
 *     inside it: reported at that block's '{';
 *   - a file name written without quotes (`file a.obj`, `include lamps`);
 *   - a property word where a statement must start.
 * Each function returns 1 when it wrote the message into buf (and may move
 * *at to the span the message is about), 0 when the error is not its case.
 */
#ifndef REFRAY_PARSE_HINTS_H
#define REFRAY_PARSE_HINTS_H

#include "lang/parse_error.h"

int parse_hint_unclosed(const parse_ctx *ctx, src_span *at, token_desc found, char *buf, size_t size);

/* found: the token; only_string: the parser would take nothing but a string. */
int parse_hint_file_name(const parse_ctx *ctx, src_span *at, token_desc found, int only_string, char *buf,
                         size_t size);

int parse_hint_property_statement(const parse_ctx *ctx, src_span at, token_desc found, char *buf, size_t size);

#endif
