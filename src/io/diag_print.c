/*
 * diag_print.c - the GCC form of a diagnostic record (diag_print.h).
 *
 * Columns count bytes from 1.  The caret line copies the tabs of the source
 * line so the caret sits under the span in any tab width.  Very long lines
 * are shown as a window around the span, so a 1 MB line prints one screen.
 */
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

/* Control bytes (NUL among them) would garble the terminal: show them as '?'. */
static int shown_byte(unsigned char c)
{
    return (c < 0x20 && c != '\t') || c == 0x7f ? '?' : c;
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
        fputc(shown_byte((unsigned char)text[i]), out);
    fprintf(out, "%s\n      | %s", to < len ? "..." : "", from > 0 ? "   " : "");
    for (size_t i = from; i < caret && i < len; i++)
        fputc(text[i] == '\t' ? '\t' : ' ', out);
    fputc('^', out);
    for (size_t i = 1; i < width && caret + i < to; i++)
        fputc('~', out);
    fputc('\n', out);
}

void diag_print(void *stream, const diag_record *r)
{
    FILE *out = stream;
    if (r->path && r->line > 0)
        fprintf(out, "%s:%d:%d: %s: %s\n", r->path, r->line, r->column, level_name(r->level), r->message);
    else if (r->path)
        fprintf(out, "%s: %s: %s\n", r->path, level_name(r->level), r->message);
    else
        fprintf(out, "refray: %s: %s\n", level_name(r->level), r->message);
    if (r->path && r->source_line)
        print_excerpt(out, r);
}
