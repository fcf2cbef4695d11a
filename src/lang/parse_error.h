/*
 * parse_error.h - wording of syntax errors.  The grammar hands over what it
 * found and what it expected as token classes; this module turns them into
 * "unexpected X, expecting Y", adds "did you mean" for misspelt words and
 * "(to close '{' at line 3)" for brackets left open.
 */
#ifndef REFRAY_PARSE_ERROR_H
#define REFRAY_PARSE_ERROR_H

#include "lang/parse.h"

typedef enum token_class {
    TC_END, TC_NUMBER, TC_STRING, TC_NAME, TC_CALLNAME, TC_KEYWORD, TC_FUNC,
    TC_LET, TC_FOR, TC_IN, TC_INCLUDE, TC_ORACLE, TC_MATERIAL, TC_DOTDOT,
    TC_BAD_CHAR, TC_BAD_STRING, TC_BAD_NUMBER,
    TC_PUNCT,        /* a one-character token; the character is in ch */
    TC_OTHER         /* error and invalid tokens of the parser itself */
} token_class;

typedef struct token_desc {
    token_class cls;
    int ch;
} token_desc;

/* Reports one syntax error: found at span `at`, count expected tokens. */
void parse_error_report(parse_ctx *ctx, src_span at, token_desc found,
                        const token_desc *expected, int count);

#endif
