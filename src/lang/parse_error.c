/*
 * parse_error.c - turns a bison syntax error into one helpful sentence.
 *
 * The expected-token set of an LALR parser is long and mechanical ("number,
 * string, name, '[', '(', function, '-', '+', ..."), so it is grouped into
 * what a person thinks in: a value, an operator, a statement, a property.
 */
#include <stdio.h>
#include <string.h>
#include "base/diag.h"
#include "lang/keywords.h"
#include "lang/parse_error.h"
#include "lang/parse_hints.h"
#include "lang/schema.h"
#include "base/suggest.h"

enum { MESSAGE_MAX = 512, SHOWN_TEXT_MAX = 40 };

typedef struct expect_set {
    const token_desc *tokens;
    int count;
} expect_set;

static int expects(const expect_set *set, token_class cls, int ch)
{
    for (int i = 0; i < set->count; i++)
        if (set->tokens[i].cls == cls && (cls != TC_PUNCT || set->tokens[i].ch == ch))
            return 1;
    return 0;
}

static const source_file *file_of(const parse_ctx *ctx)
{
    return ctx->sources->files[ctx->file];
}

/* The token's own text, shortened for the message. */
static void token_text(const parse_ctx *ctx, src_span at, char *buf, size_t size)
{
    size_t len = at.end - at.begin;
    if (len > SHOWN_TEXT_MAX)
        len = SHOWN_TEXT_MAX;
    snprintf(buf, size, "%.*s%s", (int)len, file_of(ctx)->text + at.begin,
             at.end - at.begin > SHOWN_TEXT_MAX ? "..." : "");
}

static void describe_found(const parse_ctx *ctx, src_span at, token_desc found, char *buf, size_t size)
{
    char text[SHOWN_TEXT_MAX + 8];
    token_text(ctx, at, text, sizeof text);
    switch (found.cls) {
    case TC_END: snprintf(buf, size, "end of file"); break;
    case TC_NUMBER: snprintf(buf, size, "number %s", text); break;
    case TC_STRING: snprintf(buf, size, "string %s", text); break;
    case TC_NAME:
    case TC_CALLNAME: snprintf(buf, size, "name '%s'", text); break;
    case TC_KEYWORD: snprintf(buf, size, "keyword '%s'", text); break;
    case TC_FUNC: snprintf(buf, size, "function '%s'", text); break;
    default: snprintf(buf, size, "'%s'", text); break;
    }
}

static void add_item(char *buf, size_t size, int *items, const char *item)
{
    size_t used = strlen(buf);
    snprintf(buf + used, size - used, "%s%s", *items ? ", " : "", item);
    (*items)++;
}

/* "a value, an operator or '}'": the groups first, then single tokens. */
static void describe_expected(const expect_set *set, char *buf, size_t size)
{
    int items = 0;
    int value = expects(set, TC_NUMBER, 0);
    int operator = expects(set, TC_PUNCT, '*');
    buf[0] = '\0';
    if (value)
        add_item(buf, size, &items, "a value");
    if (operator)
        add_item(buf, size, &items, "an operator");
    if (expects(set, TC_LET, 0))
        add_item(buf, size, &items, "a statement");
    else if (expects(set, TC_KEYWORD, 0) && (value || !expects(set, TC_NAME, 0)))
        add_item(buf, size, &items, "a property");
    if (!value && expects(set, TC_NAME, 0))
        add_item(buf, size, &items, "a name");
    if (!value && expects(set, TC_STRING, 0))
        add_item(buf, size, &items, "a string");
    if (expects(set, TC_IN, 0))
        add_item(buf, size, &items, "'in'");
    if (expects(set, TC_DOTDOT, 0))
        add_item(buf, size, &items, "'..'");
    static const char singles[] = "=({,])}";
    for (const char *c = singles; *c; c++) {
        if ((*c == '(' && value) || !expects(set, TC_PUNCT, *c))
            continue;
        char item[4] = {'\'', *c, '\'', '\0'};
        add_item(buf, size, &items, item);
    }
    if (expects(set, TC_END, 0))
        add_item(buf, size, &items, "end of file");
    /* Turn the last ", " into " or ". */
    char *last = NULL;
    for (char *p = strstr(buf, ", "); p; p = strstr(p + 1, ", "))
        last = p;
    if (last && items > 1) {
        memmove(last + 4, last + 2, strlen(last + 2) + 1);
        memcpy(last, " or ", 4);
    }
}

static int is_word_byte(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

/* The word that ends just before offset `end`, skipping blanks. */
static size_t word_before(const char *text, size_t end, size_t *begin)
{
    while (end > 0 && (text[end - 1] == ' ' || text[end - 1] == '\t' || text[end - 1] == '\n' ||
                       text[end - 1] == '\r'))
        end--;
    size_t b = end;
    while (b > 0 && is_word_byte(text[b - 1]))
        b--;
    *begin = b;
    return end - b;
}

/* The block whose '{' is innermost open: `sphere {`, `material glass {`, `material {`. */
static int enclosing_block(const parse_ctx *ctx)
{
    const char *text = file_of(ctx)->text;
    int depth = ctx->bracket_depth < PARSE_MAX_BRACKETS ? ctx->bracket_depth : PARSE_MAX_BRACKETS;
    for (int i = depth - 1; i >= 0; i--) {
        size_t at = ctx->brackets[i].begin;
        if (text[at] != '{')
            continue;
        size_t begin, len = word_before(text, at, &begin);
        int id = keyword_lookup(text + begin, len);
        if (id < 0 && len > 0) {
            len = word_before(text, begin, &begin);
            id = keyword_lookup(text + begin, len);
            return id == KW_MATERIAL ? KW_MATERIAL : -1;
        }
        return id >= 0 && schema_of((keyword_id)id) ? id : -1;
    }
    return -1;
}

static int unknown_property(const parse_ctx *ctx, const char *word, size_t len, char *buf, size_t size)
{
    int block = enclosing_block(ctx);
    const block_schema *schema = block >= 0 ? schema_of((keyword_id)block) : NULL;
    if (!schema)
        return 0;
    const char *names[SCHEMA_MAX_PROPS];
    for (int i = 0; i < schema->prop_count; i++)
        names[i] = keyword_name(schema->props[i]);
    const char *hint = suggest_nearest(word, len, names, schema->prop_count);
    if (hint) {
        snprintf(buf, size, "unknown property '%.*s' in %s; did you mean '%s'?", (int)len, word,
                 keyword_name((keyword_id)block), hint);
    } else {
        char list[256];
        schema_list(schema, list, sizeof list);
        snprintf(buf, size, "unknown property '%.*s' in %s (it takes %s)", (int)len, word,
                 keyword_name((keyword_id)block), list);
    }
    return 1;
}

static int unknown_statement(const char *word, size_t len, char *buf, size_t size)
{
    const char *names[KEYWORD_COUNT];
    int count = 0;
    for (int i = 0; i < KEYWORD_COUNT; i++) {
        const keyword_info *info = keyword_get((keyword_id)i);
        if ((info->cls == KWC_STATEMENT && i != KW_IN) || schema_of((keyword_id)i))
            names[count++] = info->name;
    }
    const char *hint = suggest_nearest(word, len, names, count);
    if (!hint)
        return 0;
    snprintf(buf, size, "unknown statement '%.*s'; did you mean '%s'?", (int)len, word, hint);
    return 1;
}

/* A misspelt word where a property or statement must start. */
static int misspelt_word(const parse_ctx *ctx, src_span at, token_desc found, const expect_set *set,
                         char *buf, size_t size)
{
    if ((found.cls != TC_NAME && found.cls != TC_CALLNAME) || !expects(set, TC_KEYWORD, 0))
        return 0;
    const char *word = file_of(ctx)->text + at.begin;
    size_t len = at.end - at.begin;
    if (expects(set, TC_LET, 0))
        return unknown_statement(word, len, buf, size);
    return unknown_property(ctx, word, len, buf, size);
}

static char closer_of(char open)
{
    return open == '{' ? '}' : open == '[' ? ']' : ')';
}

/* " (to close '{' at line 3)" when the innermost open bracket's closer
 * would do; an opener that is itself the unexpected token does not count. */
static void bracket_note(const parse_ctx *ctx, src_span at, const expect_set *set, char *buf, size_t size)
{
    int depth = ctx->bracket_depth;
    if (depth > 0 && depth <= PARSE_MAX_BRACKETS && ctx->brackets[depth - 1].begin == at.begin)
        depth--;
    if (depth <= 0 || depth > PARSE_MAX_BRACKETS)
        return;
    src_span open = ctx->brackets[depth - 1];
    char c = file_of(ctx)->text[open.begin];
    if (!expects(set, TC_PUNCT, closer_of(c)))
        return;
    int line, col;
    source_line_col(file_of(ctx), open.begin, &line, &col);
    size_t used = strlen(buf);
    snprintf(buf + used, size - used, " (to close '%c' at line %d)", c, line);
}

/* The scanner's word on a BAD_* token, with the offending text or byte:
 * a control byte is shown in hex, never written raw into the message. */
static void bad_token(const parse_ctx *ctx, src_span at, token_desc found, char *buf, size_t size)
{
    char text[SHOWN_TEXT_MAX + 8];
    token_text(ctx, at, text, sizeof text);
    const char *why = ctx->scan_message;
    unsigned char byte = (unsigned char)file_of(ctx)->text[at.begin];
    int printable = byte >= 0x20 && byte < 0x7f;
    if (found.cls == TC_BAD_NUMBER)
        snprintf(buf, size, "malformed number '%s'%s%s", text, why ? ": " : "", why ? why : "");
    else if (found.cls == TC_BAD_CHAR && why && strcmp(why, "invalid character") == 0)
        snprintf(buf, size, printable ? "invalid character '%c'" : "invalid character 0x%02X", byte);
    else if (found.cls == TC_BAD_CHAR && byte >= 0x80)
        snprintf(buf, size, "%s: 0x%02X", why, byte);
    else
        snprintf(buf, size, "%s", why ? why : "invalid token");
}

void parse_error_report(parse_ctx *ctx, src_span at, token_desc found,
                        const token_desc *expected, int count)
{
    char message[MESSAGE_MAX];
    expect_set set = {expected, count};
    int only_string = count == 1 && expected[0].cls == TC_STRING;
    if (parse_hint_file_name(ctx, &at, found, only_string, message, sizeof message) ||
        parse_hint_unclosed(ctx, &at, found, message, sizeof message) ||
        (expects(&set, TC_LET, 0) && parse_hint_property_statement(ctx, at, found, message, sizeof message))) {
        /* a known stumble, said in its own terms */
    } else if (found.cls == TC_BAD_CHAR || found.cls == TC_BAD_STRING || found.cls == TC_BAD_NUMBER) {
        bad_token(ctx, at, found, message, sizeof message);
    } else if (!misspelt_word(ctx, at, found, &set, message, sizeof message)) {
        char what[SHOWN_TEXT_MAX + 32], wanted[256];
        describe_found(ctx, at, found, what, sizeof what);
        describe_expected(&set, wanted, sizeof wanted);
        if (wanted[0])
            snprintf(message, sizeof message, "unexpected %s, expecting %s", what, wanted);
        else
            snprintf(message, sizeof message, "unexpected %s", what);
        bracket_note(ctx, at, &set, message, sizeof message);
    }
    parse_report_syntax(ctx, at, message);
}
