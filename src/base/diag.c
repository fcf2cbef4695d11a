/*
 * diag.c - prints diagnostics in the form compilers use:
 *
 *   scene.scene:3:17: error: radius must be > 0, got -1
 *       3 | sphere { radius -1 }
 *         |                 ^~
 *
 * Columns count bytes from 1.  The caret line copies the tabs of the source
 * line so the caret sits under the span in any tab width.  Very long lines
 * are shown as a window around the span, so a 1 MB line prints one screen.
 */
#include <stdarg.h>
#include <string.h>
#include "base/diag.h"

enum { WINDOW_BEFORE = 60, WINDOW_AFTER = 100 };

void diag_init(diag *d, const source_set *sources, FILE *out)
{
    d->sources = sources;
    d->out = out;
    d->errors = 0;
    d->warnings = 0;
    d->max_errors = 20;
    d->warnings_enabled = 1;
}

int diag_too_many(const diag *d)
{
    return d->max_errors > 0 && d->errors >= d->max_errors;
}

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

static void print_excerpt(FILE *out, const source_file *f, src_span span, int line, int col)
{
    size_t len;
    const char *text = source_line_text(f, span.begin, &len);
    size_t caret = (size_t)(col - 1);
    size_t from = caret > WINDOW_BEFORE ? caret - WINDOW_BEFORE : 0;
    size_t to = len - from > (size_t)(WINDOW_BEFORE + WINDOW_AFTER) ? from + WINDOW_BEFORE + WINDOW_AFTER : len;
    size_t width = span.end > span.begin ? span.end - span.begin : 1;
    if (caret + width > len)
        width = caret < len ? len - caret : 1;
    const char *lead = from > 0 ? "..." : "";
    fprintf(out, "%5d | %s", line, lead);
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

static void print_include_chain(FILE *out, const source_set *set, const source_file *f)
{
    src_span from = f->included_from;
    while (from.file >= 0 && from.file < set->count) {
        const source_file *parent = set->files[from.file];
        int line, col;
        source_line_col(parent, from.begin, &line, &col);
        fprintf(out, "%s:%d:%d: note: included from here\n", parent->path, line, col);
        from = parent->included_from;
    }
}

void diag_report(diag *d, diag_level level, src_span span, const char *fmt, ...)
{
    if (level == DIAG_ERROR)
        d->errors++;
    else if (level == DIAG_WARNING)
        d->warnings++;
    int over = level == DIAG_ERROR ? d->max_errors > 0 && d->errors > d->max_errors
                                   : level == DIAG_WARNING && !d->warnings_enabled;
    if (over || !d->out)
        return;
    const source_file *f = NULL;
    if (d->sources && span.file >= 0 && span.file < d->sources->count)
        f = d->sources->files[span.file];
    int line = 0, col = 0;
    if (f && !f->text) {
        fprintf(d->out, "%s: %s: ", f->path, level_name(level));
        f = NULL;
    } else if (f) {
        source_line_col(f, span.begin, &line, &col);
        fprintf(d->out, "%s:%d:%d: %s: ", f->path, line, col, level_name(level));
    } else {
        fprintf(d->out, "refray: %s: ", level_name(level));
    }
    va_list ap;
    va_start(ap, fmt);
    vfprintf(d->out, fmt, ap);
    va_end(ap);
    fputc('\n', d->out);
    if (f) {
        print_excerpt(d->out, f, span, line, col);
        print_include_chain(d->out, d->sources, f);
    }
    if (level == DIAG_ERROR && d->max_errors > 0 && d->errors == d->max_errors)
        fprintf(d->out, "refray: note: too many errors (%d), stopping\n", d->max_errors);
}
