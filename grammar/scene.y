/*
 * scene.y - the grammar of the refray scene language (spec/language.md).
 *
 * A pure parser with locations: every piece of state is in parse_ctx and the
 * scanner handle, so two scenes can be parsed at once.  Actions only build
 * syntax nodes (ast.h); meaning is given by the lowering pass.
 *
 * Properties take their values by juxtaposition (`rectangle [0,4,0] [1,0,0]
 * [0,0,1]`).  To keep that unambiguous for an LALR(1) parser with no
 * conflicts, a property word comes as KEYWORD only where a property may
 * start and as NAME everywhere else (the scanner decides, scene.l:
 * `let width = 4`, `radius width / 2`), and a value after the first may not
 * begin with a sign: `a -b` is always the subtraction a - b.  The second
 * rule is why the expression grammar exists twice: expr, and expr_ns ("no
 * sign") that cannot start with unary + or -.
 */

%code requires {
#include "lang/ast.h"
#include "lang/parse.h"
#include "base/source.h"
#ifndef YY_TYPEDEF_YY_SCANNER_T
#define YY_TYPEDEF_YY_SCANNER_T
typedef void *yyscan_t;
#endif
/* A span covering the whole right-hand side, or an empty one after the
 * previous symbol for an empty rule. */
#define YYLLOC_DEFAULT(cur, rhs, n)                                         \
    do {                                                                    \
        if (n) {                                                            \
            (cur).file = YYRHSLOC(rhs, 1).file;                             \
            (cur).begin = YYRHSLOC(rhs, 1).begin;                           \
            (cur).end = YYRHSLOC(rhs, n).end;                               \
        } else {                                                            \
            (cur).file = YYRHSLOC(rhs, 0).file;                             \
            (cur).begin = (cur).end = YYRHSLOC(rhs, 0).end;                 \
        }                                                                   \
    } while (0)
}

%code provides {
#define YYSTYPE SCN_STYPE
#define YYLTYPE SCN_LTYPE
int scn_lex(SCN_STYPE *value, SCN_LTYPE *location, yyscan_t scanner);
}

%code {
#include <stdio.h>
#include <string.h>
#include "lang/keywords.h"
#include "lang/parse_error.h"

static void scn_error(const SCN_LTYPE *location, yyscan_t scanner, parse_ctx *ctx, const char *message);

/* A node, or a note that memory ran out (the parse then stops). */
#define NODE(kind, span) ast_checked(ctx, ast_new(ctx->arena, (kind), (span)))

static ast *ast_checked(parse_ctx *ctx, ast *node)
{
    if (!node)
        ctx->out_of_memory = 1;
    return node;
}

static ast *binary(parse_ctx *ctx, int op, ast *left, ast *right, src_span op_span)
{
    ast *node = NODE(AST_BINARY, op_span);
    if (node) {
        node->op = op;
        ast_append(ast_append(node, left), right);
        node->head = op_span;
    }
    return node;
}

static ast *named(parse_ctx *ctx, ast_kind kind, const char *text, src_span span)
{
    ast *node = NODE(kind, span);
    if (node)
        node->text = text;
    return node;
}

#define CHECK_MEMORY() do { if (ctx->out_of_memory) YYNOMEM; } while (0)

/*
 * The parse stacks start in yyparse's frame (YYINITDEPTH deep) and grow
 * through the load's allocator, never malloc: yyoverflow is bison's hook
 * for that, expanded inside yyparse (so ctx, scanner and yylloc are in
 * scope).  Each stack is moved as soon as its copy exists, so a failure
 * half way leaves every pointer valid; the size grows only when all three
 * moved.  parse_file frees the blocks after the parse.  Past YYMAXDEPTH,
 * or when memory runs out, the parse stops as bison itself would.
 */
#define yyoverflow(message, ss, ss_bytes, vs, vs_bytes, ls, ls_bytes, size)                                \
    do {                                                                                                  \
        YYPTRDIFF_T grown_ = *(size) >= YYMAXDEPTH ? 0 : *(size) > YYMAXDEPTH / 2 ? YYMAXDEPTH : 2 * *(size); \
        void *moved_;                                                                                     \
        if (grown_ && (moved_ = stack_move(ctx, 0, *(ss), (ss_bytes), (size_t)grown_ * sizeof **(ss))))    \
            *(ss) = moved_;                                                                               \
        else                                                                                              \
            grown_ = 0;                                                                                   \
        if (grown_ && (moved_ = stack_move(ctx, 1, *(vs), (vs_bytes), (size_t)grown_ * sizeof **(vs))))    \
            *(vs) = moved_;                                                                               \
        else                                                                                              \
            grown_ = 0;                                                                                   \
        if (grown_ && (moved_ = stack_move(ctx, 2, *(ls), (ls_bytes), (size_t)grown_ * sizeof **(ls))))    \
            *(ls) = moved_;                                                                               \
        else                                                                                              \
            grown_ = 0;                                                                                   \
        if (grown_)                                                                                       \
            *(size) = grown_;                                                                             \
        else if (!ctx->out_of_memory)                                                                     \
            scn_error(&yylloc, scanner, ctx, (message));                                                  \
    } while (0)

/* Lookahead correction keeps a scratch stack of its own: 20 states in
 * yyparse's frame, which this grammar never outgrows (only its three empty
 * rules push onto it, and none follows another).  Were it ever to, the parse
 * would end as "nesting too deep" instead of calling malloc. */
#define YYSTACK_ALLOC(size) ((void)(size), (void *)0)

/* A copy of the used bytes of stack `slot` in a block of `bytes`; the
 * previous block is freed unless it is yyparse's own array.  NULL when out
 * of memory (ctx->out_of_memory set). */
static void *stack_move(parse_ctx *ctx, int slot, const void *old, size_t used, size_t bytes)
{
    void *block = mem_alloc(&ctx->arena->mem, bytes);
    if (!block) {
        ctx->out_of_memory = 1;
        return NULL;
    }
    memcpy(block, old, used);
    mem_free(&ctx->arena->mem, ctx->stacks[slot], ctx->stack_bytes[slot]);
    ctx->stacks[slot] = block;
    ctx->stack_bytes[slot] = bytes;
    return block;
}
}

%define api.pure full
%define api.prefix {scn_}
%define api.location.type {src_span}
%define parse.error custom
/* Lookahead correction: the expected tokens of an error message are those
 * of the state where the error really is, not of one reached by a default
 * reduction. */
%define parse.lac full
%locations
%param {yyscan_t scanner}
%parse-param {parse_ctx *ctx}
%expect 0

%union {
    double number;
    const char *text;
    int id;
    ast *node;
}

%token <number> NUMBER "number"
%token <text> STRING "string" NAME "name" CALLNAME "unknown function"
%token <id> KEYWORD "keyword" FUNC "function"
%token LET "let" FOR "for" IN "in" INCLUDE "include" ORACLE "oracle" MATERIAL "material"
%token DOTDOT ".."
%token BAD_CHAR "invalid character" BAD_STRING "unterminated string" BAD_NUMBER "malformed number"

%type <node> statements statement block_body property arguments argument_list
%type <node> expr sum term unary power primary expression_list expr_ns sum_ns term_ns

%%

program
    : statements                       { ctx->root = $1; }
    ;

statements
    : %empty                           { $$ = NODE(AST_BLOCK, @$); CHECK_MEMORY(); }
    | statements statement             { $$ = ast_append($1, $2); CHECK_MEMORY(); }
    | statements error                 { $$ = $1; }
    ;

statement
    : LET NAME '=' expr                { $$ = named(ctx, AST_LET, $2, @$); ast_append($$, $4); if ($$) $$->head = @2; }
    | LET KEYWORD '=' expr             { $$ = named(ctx, AST_LET, keyword_name($2), @$);
                                         ast_append($$, $4); if ($$) { $$->head = @2; $$->keyword = $2; } }
    | FOR NAME IN expr DOTDOT expr '{' statements '}'
                                       { $$ = named(ctx, AST_FOR, $2, @$);
                                         ast_append(ast_append(ast_append($$, $4), $6), $8);
                                         if ($$) $$->head = @2; }
    | INCLUDE STRING                   { $$ = named(ctx, AST_INCLUDE, $2, @$); if ($$) $$->head = @2; }
    | ORACLE NAME                      { $$ = named(ctx, AST_ORACLE, $2, @$); if ($$) $$->head = @2; }
    | MATERIAL NAME '{' block_body '}' { $$ = $4; $$->keyword = KW_MATERIAL; $$->text = $2;
                                         $$->span = @$; $$->head = @2; }
    | KEYWORD '{' block_body '}'       { $$ = $3; $$->keyword = $1; $$->span = @$; $$->head = @1; }
    ;

block_body
    : %empty                           { $$ = NODE(AST_BLOCK, @$); CHECK_MEMORY(); }
    | block_body property              { $$ = ast_append($1, $2); }
    | block_body error                 { $$ = $1; }
    ;

property
    : KEYWORD arguments                { $$ = $2; $$->keyword = $1; $$->head = @1; $$->span = @$; }
    | MATERIAL arguments               { $$ = $2; $$->keyword = KW_MATERIAL; $$->head = @1; $$->span = @$; }
    | MATERIAL '{' block_body '}'      { $$ = NODE(AST_PROPERTY, @$); CHECK_MEMORY();
                                         $$->keyword = KW_MATERIAL; $$->head = @1;
                                         $3->keyword = KW_MATERIAL; $3->span = @$; $3->head = @1;
                                         ast_append($$, $3); }
    ;

arguments
    : %empty                           { $$ = NODE(AST_PROPERTY, @$); CHECK_MEMORY(); }
    | argument_list
    ;

argument_list
    : expr                             { $$ = ast_append(NODE(AST_PROPERTY, @1), $1); CHECK_MEMORY(); }
    | argument_list expr_ns            { $$ = ast_append($1, $2); }
    ;

expr
    : sum
    ;

sum
    : sum '+' term                     { $$ = binary(ctx, '+', $1, $3, @2); CHECK_MEMORY(); }
    | sum '-' term                     { $$ = binary(ctx, '-', $1, $3, @2); CHECK_MEMORY(); }
    | term
    ;

term
    : term '*' unary                   { $$ = binary(ctx, '*', $1, $3, @2); CHECK_MEMORY(); }
    | term '/' unary                   { $$ = binary(ctx, '/', $1, $3, @2); CHECK_MEMORY(); }
    | unary
    ;

unary
    : '-' unary                        { $$ = ast_append(NODE(AST_NEGATE, @$), $2); CHECK_MEMORY();
                                         $$->span = @$; $$->head = @1; }
    | '+' unary                        { $$ = $2; }
    | power
    ;

/* Right associative and tighter than unary minus: -2^2 = -4, 2^-1 = 0.5. */
power
    : primary '^' unary                { $$ = binary(ctx, '^', $1, $3, @2); CHECK_MEMORY(); }
    | primary
    ;

primary
    : NUMBER                           { $$ = NODE(AST_NUMBER, @1); CHECK_MEMORY(); $$->number = $1; }
    | STRING                           { $$ = named(ctx, AST_STRING, $1, @1); CHECK_MEMORY(); }
    | NAME                             { $$ = named(ctx, AST_NAME, $1, @1); CHECK_MEMORY(); }
    | '[' expression_list ']'          { $$ = $2; $$->kind = AST_VECTOR; $$->span = @$; $$->head = @1; }
    | '[' ']'                          { $$ = NODE(AST_VECTOR, @$); CHECK_MEMORY(); }
    | '(' expr ')'                     { $$ = $2; }
    | FUNC '(' expression_list ')'     { $$ = $3; $$->kind = AST_CALL; $$->keyword = $1;
                                         $$->span = @$; $$->head = @1; }
    | FUNC '(' ')'                     { $$ = NODE(AST_CALL, @$); CHECK_MEMORY(); $$->keyword = $1; $$->head = @1; }
    | CALLNAME '(' expression_list ')' { $$ = $3; $$->kind = AST_CALL; $$->text = $1;
                                         $$->span = @$; $$->head = @1; }
    | CALLNAME '(' ')'                 { $$ = named(ctx, AST_CALL, $1, @$); CHECK_MEMORY(); $$->head = @1; }
    ;

expression_list
    : expr                             { $$ = ast_append(NODE(AST_CALL, @1), $1); CHECK_MEMORY(); }
    | expression_list ',' expr         { $$ = ast_append($1, $3); }
    ;

expr_ns
    : sum_ns
    ;

sum_ns
    : sum_ns '+' term                  { $$ = binary(ctx, '+', $1, $3, @2); CHECK_MEMORY(); }
    | sum_ns '-' term                  { $$ = binary(ctx, '-', $1, $3, @2); CHECK_MEMORY(); }
    | term_ns
    ;

term_ns
    : term_ns '*' unary                { $$ = binary(ctx, '*', $1, $3, @2); CHECK_MEMORY(); }
    | term_ns '/' unary                { $$ = binary(ctx, '/', $1, $3, @2); CHECK_MEMORY(); }
    | power
    ;

%%

static void scn_error(const SCN_LTYPE *location, yyscan_t scanner, parse_ctx *ctx, const char *message)
{
    (void)scanner;
    /* Bison calls this only for its own failures.  "memory exhausted" after
     * an action ran out of memory is reported by the loader; otherwise it
     * means the parse stack would pass YYMAXDEPTH: deep nesting, not a typo. */
    if (ctx->out_of_memory)
        return;
    if (strstr(message, "exhausted")) {
        message = "nesting too deep (more than 10000 open brackets or operators)";
        ctx->too_deep = 1;
    }
    parse_report_syntax(ctx, *location, message);
}

/* The parse_error module's view of a grammar symbol. */
static token_desc describe(yysymbol_kind_t kind)
{
    token_desc d = {TC_OTHER, 0};
    switch (kind) {
    case YYSYMBOL_YYEOF: d.cls = TC_END; break;
    case YYSYMBOL_NUMBER: d.cls = TC_NUMBER; break;
    case YYSYMBOL_STRING: d.cls = TC_STRING; break;
    case YYSYMBOL_NAME: d.cls = TC_NAME; break;
    case YYSYMBOL_CALLNAME: d.cls = TC_CALLNAME; break;
    case YYSYMBOL_KEYWORD: d.cls = TC_KEYWORD; break;
    case YYSYMBOL_FUNC: d.cls = TC_FUNC; break;
    case YYSYMBOL_LET: d.cls = TC_LET; break;
    case YYSYMBOL_FOR: d.cls = TC_FOR; break;
    case YYSYMBOL_IN: d.cls = TC_IN; break;
    case YYSYMBOL_INCLUDE: d.cls = TC_INCLUDE; break;
    case YYSYMBOL_ORACLE: d.cls = TC_ORACLE; break;
    case YYSYMBOL_MATERIAL: d.cls = TC_MATERIAL; break;
    case YYSYMBOL_DOTDOT: d.cls = TC_DOTDOT; break;
    case YYSYMBOL_BAD_CHAR: d.cls = TC_BAD_CHAR; break;
    case YYSYMBOL_BAD_STRING: d.cls = TC_BAD_STRING; break;
    case YYSYMBOL_BAD_NUMBER: d.cls = TC_BAD_NUMBER; break;
    default: {
        /* One-character tokens are named "'c'" by bison. */
        const char *name = yysymbol_name(kind);
        if (name[0] == '\'' && name[1] && name[2] == '\'') {
            d.cls = TC_PUNCT;
            d.ch = name[1];
        }
    }
    }
    return d;
}

static int yyreport_syntax_error(const yypcontext_t *context, yyscan_t scanner, parse_ctx *ctx)
{
    (void)scanner;
    enum { MAX_EXPECTED = 64 };
    yysymbol_kind_t expected[MAX_EXPECTED];
    token_desc wanted[MAX_EXPECTED];
    int count = yypcontext_expected_tokens(context, expected, MAX_EXPECTED);
    if (count < 0)
        count = 0;
    for (int i = 0; i < count; i++)
        wanted[i] = describe(expected[i]);
    parse_error_report(ctx, *yypcontext_location(context), describe(yypcontext_token(context)),
                       wanted, count);
    return 0;
}
