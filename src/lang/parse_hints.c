/*
 * parse_hints.c - see parse_hints.h.  Each hint reads the scanner's state
 * (parse_ctx: open brackets, the level inside each, the last tokens) and
 * the source text around the error; none changes anything.
 */
#include <stdio.h>
#include <string.h>
#include "lang/keywords.h"
#include "lang/parse_hints.h"

static const source_file *file_of(const parse_ctx *ctx)
{
    return ctx->sources->files[ctx->file];
}

static int is_word_byte(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

static int is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\f' || c == '\v';
}

/* The word ending just before offset end (blanks and line ends skipped):
 * its length, and its start in *begin. */
static size_t word_before(const char *text, size_t end, size_t *begin)
{
    while (end > 0 && (is_blank(text[end - 1]) || text[end - 1] == '\n' || text[end - 1] == '\r'))
        end--;
    size_t b = end;
    while (b > 0 && is_word_byte(text[b - 1]))
        b--;
    *begin = b;
    return end - b;
}

static keyword_class word_class(const char *word, size_t len)
{
    int id = keyword_lookup(word, len);
    return id < 0 ? KWC_FUNCTION : keyword_get((keyword_id)id)->cls;
}

/* "sphere {" or "material glass {" for the '{' at offset open: the words
 * that open that block, and in *start where the first begins; 0 when they
 * are not a block's. */
static int block_words(const char *text, size_t open, char *buf, size_t size, size_t *start)
{
    size_t b1, n1 = word_before(text, open, &b1), b0, n0;
    if (n1 == 0)
        return 0;
    keyword_class cls = word_class(text + b1, n1);
    *start = b1;
    if (cls == KWC_BLOCK || (cls == KWC_STATEMENT && keyword_lookup(text + b1, n1) == KW_MATERIAL)) {
        snprintf(buf, size, "%.*s {", (int)n1, text + b1);
        return 1;
    }
    n0 = word_before(text, b1, &b0);
    if (n0 == 0 || keyword_lookup(text + b0, n0) != KW_MATERIAL)
        return 0;
    *start = b0;
    snprintf(buf, size, "material %.*s {", (int)n1, text + b1);
    return 1;
}

static void line_col(const parse_ctx *ctx, size_t offset, int *line, int *col)
{
    source_line_col(file_of(ctx), offset, line, col);
}

/* Whether only blanks stand between the start of its line and offset. */
static int starts_line(const char *text, size_t offset)
{
    while (offset > 0 && is_blank(text[offset - 1]))
        offset--;
    return offset == 0 || text[offset - 1] == '\n' || text[offset - 1] == '\r';
}

/* The innermost open '{' whose level is a block body, skipping the newest
 * bracket when the error is on that bracket itself: its index, or -1. */
static int enclosing_body(const parse_ctx *ctx, int skip_newest)
{
    int depth = ctx->bracket_depth - skip_newest;
    if (depth <= 0 || ctx->bracket_depth > PARSE_MAX_BRACKETS)
        return -1;
    const parse_level *inside = skip_newest ? &ctx->outer[depth] : &ctx->level;
    if (inside->kind != LEVEL_BLOCK || file_of(ctx)->text[ctx->brackets[depth - 1].begin] != '{')
        return -1;
    return depth - 1;
}

/*
 * A statement cannot stand among a block's properties, so one found there
 * means the block before it was not closed: `sphere { radius 1` and on the
 * next line `sphere { radius 2 }`.  The parser only notices at the second
 * '{' (a block word may be a property, as `disk` is); the error is put at
 * the first block's '{', where the '}' belongs.  A `let`, `for`, `include`
 * or `oracle` counts when it starts a line below that '{' (on the same line
 * it is more likely a statement put inside a block on purpose).
 */
int parse_hint_unclosed(const parse_ctx *ctx, src_span *at, token_desc found, char *buf, size_t size)
{
    const char *text = file_of(ctx)->text;
    char inner[96], outer[96];
    int opened = found.cls == TC_PUNCT && found.ch == '{';
    int statement = found.cls == TC_LET || found.cls == TC_FOR || found.cls == TC_INCLUDE || found.cls == TC_ORACLE;
    int index = opened || statement ? enclosing_body(ctx, opened) : -1;
    size_t outer_start, inner_start = at->begin;
    if (index < 0 || !block_words(text, ctx->brackets[index].begin, outer, sizeof outer, &outer_start))
        return 0;
    src_span open = ctx->brackets[index];
    int line, col, open_line, open_col;
    line_col(ctx, open.begin, &open_line, &open_col);
    if (opened) {
        if (!block_words(text, at->begin, inner, sizeof inner, &inner_start))
            return 0;
    } else {
        size_t len = at->end - at->begin;
        if (!starts_line(text, at->begin))
            return 0;
        line_col(ctx, at->begin, &line, &col);
        if (line == open_line)
            return 0;
        snprintf(inner, sizeof inner, "%.*s", (int)(len < 40 ? len : 40), text + at->begin);
    }
    line_col(ctx, inner_start, &line, &col);
    snprintf(buf, size, "the '%s' at %d:%d is not closed: '}' is missing before the '%s' at %d:%d", outer,
             open_line, open_col, inner, line, col);
    *at = open;
    return 1;
}

static int is_path_byte(char c)
{
    return is_word_byte(c) || c == '.' || c == '/' || c == '-';
}

/* The run of file-name bytes around offset, on its line. */
static src_span path_run(const parse_ctx *ctx, size_t offset)
{
    const source_file *f = file_of(ctx);
    src_span run = {ctx->file, offset, offset};
    while (run.begin > 0 && is_path_byte(f->text[run.begin - 1]))
        run.begin--;
    while (run.end < f->len && is_path_byte(f->text[run.end]))
        run.end++;
    return run;
}

/*
 * `include lamps.scene` (a name where only a string may stand) and
 * `mesh { file a.obj }` (a name, then a '.' that no number holds, right
 * after `file` or `include`) are file names without their quotes.
 */
int parse_hint_file_name(const parse_ctx *ctx, src_span *at, token_desc found, int only_string, char *buf,
                         size_t size)
{
    const char *text = file_of(ctx)->text;
    int name = (found.cls == TC_NAME || found.cls == TC_CALLNAME || found.cls == TC_KEYWORD) && only_string;
    int dot = found.cls == TC_BAD_CHAR && text[at->begin] == '.' && at->begin > 0 &&
              is_word_byte(text[at->begin - 1]);
    if (!name && !dot)
        return 0;
    src_span run = path_run(ctx, at->begin);
    size_t b, n = word_before(text, run.begin, &b);
    int id = keyword_lookup(text + b, n);
    if (dot && id != KW_FILE && id != KW_INCLUDE)
        return 0;
    size_t len = run.end - run.begin;
    snprintf(buf, size, "file names are strings: write \"%.*s\"%s", (int)(len < 200 ? len : 200),
             text + run.begin, len < 200 ? "" : "...");
    *at = run;
    return 1;
}

/* A property word where a statement must start: the block around it is
 * missing, or it was meant inside the block before. */
int parse_hint_property_statement(const parse_ctx *ctx, src_span at, token_desc found, char *buf, size_t size)
{
    const char *word = file_of(ctx)->text + at.begin;
    size_t len = at.end - at.begin;
    if ((found.cls != TC_NAME && found.cls != TC_CALLNAME) || word_class(word, len) != KWC_PROPERTY)
        return 0;
    snprintf(buf, size, "'%.*s' is a property, not a statement", (int)len, word);
    return 1;
}
