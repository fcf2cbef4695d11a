/*
 * parse.c - drives the reentrant scanner and the pure parser over one file.
 */
#include "lang/parse.h"
#include "scene.tab.h"
#include "scene.lex.h"

void parse_report_syntax(parse_ctx *ctx, src_span span, const char *message)
{
    diag_report(ctx->diag, DIAG_ERROR, span, "%s", message);
}

ast *parse_file(arena *a, diag *d, const source_set *sources, int file)
{
    parse_ctx ctx = {0};
    ctx.arena = a;
    ctx.diag = d;
    ctx.sources = sources;
    ctx.file = file;
    yyscan_t scanner;
    if (scn_lex_init_extra(&ctx, &scanner) != 0)
        return NULL;
    const source_file *f = sources->files[file];
    YY_BUFFER_STATE buffer = scn__scan_bytes(f->text, (int)f->len, scanner);
    int status = buffer ? scn_parse(scanner, &ctx) : 2;
    if (buffer)
        scn__delete_buffer(buffer, scanner);
    scn_lex_destroy(scanner);
    if ((status == 2 && !ctx.too_deep) || ctx.out_of_memory)
        return NULL;
    if (!ctx.root || ctx.too_deep)
        ctx.root = ast_new(a, AST_BLOCK, src_span_none());
    return ctx.root;
}
