/*
 * diag_print.c - the GCC form of a diagnostic record (diag_print.h).
 *
 * Columns count bytes from 1.  The caret line copies the tabs of the source
 * line so the caret sits under the span in any tab width.  Very long lines
 * are shown as a window around the span, so a 1 MB line prints one screen.
 * A byte of the source line that is not printable ASCII (nor a tab) is
 * shown as \xHH, and the caret line makes room for it, so no input byte
 * reaches the terminal as itself ([REL-ESCAPE-1]; the record's message and
 * path come escaped already).
 */
#include <string.h>
#include "base/text.h"
#include "io/diag_print.h"

enum { WINDOW_BEFORE = 60, WINDOW_AFTER = 100 };

static const char *level_name(diag_level level)
{
    switch (level) {
    case DIAG_ERROR:
        return "error";
    case DIAG_WARNING:
        return "warning";
    default:
        return "note";
    }
}

static int plain(unsigned char c)
{
    return (c >= 0x20 && c < 0x7f) || c == '\t';
}

/* One byte of the excerpt: itself, or \xHH for any other. */
static void put_byte(FILE *out, unsigned char c)
{
    if (plain(c))
        fputc(c, out);
    else
        fprintf(out, "\\x%02x", c);
}

static void print_excerpt(FILE *out, const diag_record *r)
{
    const char *text = r->source_line;
    size_t len = r->source_line_length;
    size_t caret = (size_t)(r->column - 1);
    size_t from = caret > WINDOW_BEFORE ? caret - WINDOW_BEFORE : 0;
    size_t to = len - from > (size_t)(WINDOW_BEFORE + WINDOW_AFTER) ? from + WINDOW_BEFORE + WINDOW_AFTER : len;
    size_t width = r->span_length ? r->span_length : 1;
    if (caret + width > len)
        width = caret < len ? len - caret : 1;
    const char *lead = from > 0 ? "..." : "";
    fprintf(out, "%5d | %s", r->line, lead);
    for (size_t i = from; i < to; i++)
        put_byte(out, (unsigned char)text[i]);
    fprintf(out, "%s\n      | %s", to < len ? "..." : "", from > 0 ? "   " : "");
    for (size_t i = from; i < caret && i < len; i++)
        fputs(text[i] == '\t' ? "\t" : plain((unsigned char)text[i]) ? " " : "    ", out);
    fputc('^', out);
    for (size_t i = 1; i < width && caret + i < to; i++)
        fputs(plain((unsigned char)text[caret + i]) ? "~" : "~~~~", out);
    fputc('\n', out);
}

void diag_print(void *stream, const diag_record *r)
{
    FILE *out = stream;
    /* The library's records come escaped; a host's own (rf_diagnostic_print)
     * may not: escaping printable ASCII again changes nothing. */
    char path[1024], message[1024];
    text_escape(r->message ? r->message : "", r->message ? strlen(r->message) : 0, message, sizeof message);
    if (r->path)
        text_escape(r->path, strlen(r->path), path, sizeof path);
    if (r->path && r->line > 0)
        fprintf(out, "%s:%d:%d: %s: %s\n", path, r->line, r->column, level_name(r->level), message);
    else if (r->path)
        fprintf(out, "%s: %s: %s\n", path, level_name(r->level), message);
    else
        fprintf(out, "refray: %s: %s\n", level_name(r->level), message);
    if (r->path && r->source_line)
        print_excerpt(out, r);
}
