/*
 * parse.c - drives the reentrant scanner and the pure parser over one file,
 * and gives them their memory (parse.h).
 */
#include <string.h>
#include "lang/parse.h"
#include "scene.tab.h"
#include "scene.lex.h"

/* A scanner block's header: its links and size, padded to the strictest
 * alignment so the payload after it stays aligned. */
typedef union parse_block {
    struct {
        union parse_block *prev, *next;
        size_t size;            /* of the whole block, header included */
    } link;
    long double ld;
    long long ll;
    double d;
    void *p;
} parse_block;

void parse_report_syntax(parse_ctx *ctx, src_span span, const char *message)
{
    diag_report(ctx->diag, DIAG_ERROR, span, "%s", message);
}

static void block_link(parse_ctx *ctx, parse_block *b)
{
    b->link.prev = NULL;
    b->link.next = ctx->blocks;
    if (ctx->blocks)
        ctx->blocks->link.prev = b;
    ctx->blocks = b;
}

static void block_unlink(parse_ctx *ctx, parse_block *b)
{
    if (b->link.prev)
        b->link.prev->link.next = b->link.next;
    else
        ctx->blocks = b->link.next;
    if (b->link.next)
        b->link.next->link.prev = b->link.prev;
}

void *parse_block_alloc(parse_ctx *ctx, size_t size)
{
    parse_block *b = size < (size_t)-1 - sizeof *b ? mem_alloc(&ctx->arena->mem, sizeof *b + size) : NULL;
    if (!b)
        return NULL;
    b->link.size = sizeof *b + size;
    block_link(ctx, b);
    return b + 1;
}

void *parse_block_resize(parse_ctx *ctx, void *p, size_t size)
{
    if (!p)
        return parse_block_alloc(ctx, size);
    parse_block *b = (parse_block *)p - 1;
    if (size >= (size_t)-1 - sizeof *b)
        return NULL;
    block_unlink(ctx, b);
    parse_block *moved = mem_resize(&ctx->arena->mem, b, b->link.size, sizeof *b + size);
    if (moved) {
        moved->link.size = sizeof *b + size;
        b = moved;
    }
    block_link(ctx, b);
    return moved ? b + 1 : NULL;
}

void parse_block_free(parse_ctx *ctx, void *p)
{
    if (!p)
        return;
    parse_block *b = (parse_block *)p - 1;
    block_unlink(ctx, b);
    mem_free(&ctx->arena->mem, b, b->link.size);
}

void parse_fatal(parse_ctx *ctx)
{
    ctx->out_of_memory = 1;
    longjmp(ctx->fatal, 1);
}

/* Scans and parses the file: bison's status, or -1 when the scanner failed
 * (out of memory). */
static int scan_and_parse(parse_ctx *ctx, yyscan_t scanner, const source_file *f)
{
    if (setjmp(ctx->fatal) != 0)
        return -1;
    YY_BUFFER_STATE buffer = scn__scan_bytes(f->text, (int)f->len, scanner);
    int status = scn_parse(scanner, ctx);
    scn__delete_buffer(buffer, scanner);
    return status;
}

ast *parse_file(arena *a, diag *d, const source_set *sources, int file)
{
    parse_ctx ctx;
    memset(&ctx, 0, sizeof ctx);
    ctx.arena = a;
    ctx.diag = d;
    ctx.sources = sources;
    ctx.file = file;
    yyscan_t scanner;
    if (scn_lex_init_extra(&ctx, &scanner) != 0)
        return NULL;
    int status = scan_and_parse(&ctx, scanner, sources->files[file]);
    /* After a fatal error the scanner may be half built: its blocks are
     * freed one by one rather than through scn_lex_destroy. */
    if (status < 0)
        while (ctx.blocks)
            parse_block_free(&ctx, ctx.blocks + 1);
    else
        scn_lex_destroy(scanner);
    for (int i = 0; i < 3; i++)
        mem_free(&a->mem, ctx.stacks[i], ctx.stack_bytes[i]);
    if ((status == 2 && !ctx.too_deep) || ctx.out_of_memory || ctx.cancelled)
        return NULL;
    if (!ctx.root || ctx.too_deep)
        ctx.root = ast_new(a, AST_BLOCK, src_span_none());
    return ctx.root;
}
