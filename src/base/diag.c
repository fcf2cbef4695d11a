/*
 * diag.c - counts diagnostics and turns them into records (diag.h).
 *
 * The message is formatted here, into a buffer on the stack; one longer
 * than that gets a buffer from the source set's allocator, and is cut to
 * the stack buffer when even that fails, so reporting never fails.  What
 * a record carries for display, its message and its file name, is then
 * escaped and cut (text_escape): a sink receives printable ASCII only, at
 * most SHOWN_BYTES of it, whatever the input held ([REL-ESCAPE-1]).
 */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "base/diag.h"
#include "base/text.h"

enum { MESSAGE_BYTES = 512, SHOWN_BYTES = 1024 };

void diag_init(diag *d, const source_set *sources, diag_sink sink, void *sink_user)
{
    d->sources = sources;
    d->sink = sink;
    d->sink_user = sink_user;
    d->errors = 0;
    d->warnings = 0;
    d->max_errors = 20;
    d->warnings_enabled = 1;
    d->cancel = NULL;
    d->subject = NULL;
    d->subject_ctx = NULL;
}

int diag_too_many(const diag *d)
{
    return d->max_errors > 0 && d->errors >= d->max_errors;
}

int diag_stop(const diag *d)
{
    return cancel_step(d->cancel) || diag_too_many(d);
}

static void emit(const diag *d, diag_level level, const source_file *f, size_t offset, const char *message,
                 size_t span_length, int excerpt)
{
    diag_record r;
    char path[SHOWN_BYTES];
    memset(&r, 0, sizeof r);
    r.level = level;
    r.message = message;
    if (f) {
        text_escape(f->path, strlen(f->path), path, sizeof path);
        r.path = path;
    }
    /* A mesh file's text is released once its mesh is built: a later
     * message names the file without a line. */
    if (f && f->text) {
        source_line_col(f, offset, &r.line, &r.column);
        if (excerpt)
            r.source_line = source_line_text(f, offset, &r.source_line_length);
        r.span_length = span_length;
    }
    d->sink(d->sink_user, &r);
}

/* One note per file that read the next: an OBJ file is read by a mesh,
 * a scene file by an include. */
static void emit_include_chain(const diag *d, const source_file *f)
{
    const source_set *set = d->sources;
    /* A chain longer than the files there are would be a loop: defensive. */
    for (int steps = 0; steps < set->count && f->included_from.file >= 0 && f->included_from.file < set->count;
         steps++) {
        const source_file *parent = set->files[f->included_from.file];
        emit(d, DIAG_NOTE, parent, f->included_from.begin,
             f->is_mesh ? "in the mesh read here" : "included from here", 0, 0);
        f = parent;
    }
}

static void deliver(const diag *d, diag_level level, src_span span, const char *message)
{
    const source_file *f = NULL;
    if (d->sources && span.file >= 0 && span.file < d->sources->count)
        f = d->sources->files[span.file];
    emit(d, level, f, span.begin, message, span.end > span.begin ? span.end - span.begin : 0, 1);
    if (f)
        emit_include_chain(d, f);
}

/* "SUBJECT: " into buf when the subject hook names the span's value;
 * returns its length (0: none). */
static size_t subject_prefix(const diag *d, src_span span, char *buf, size_t size)
{
    char name[256];
    if (!d->subject || !d->sources || span.file < 0 || span.file >= d->sources->count ||
        d->subject(d->subject_ctx, span, name, sizeof name) == 0)
        return 0;
    int n = snprintf(buf, size, "%s: ", name);
    return n > 0 && (size_t)n < size ? (size_t)n : 0;
}

void diag_report(diag *d, diag_level level, src_span span, const char *fmt, ...)
{
    if (level == DIAG_ERROR)
        d->errors++;
    else if (level == DIAG_WARNING)
        d->warnings++;
    int over = level == DIAG_ERROR ? d->max_errors > 0 && d->errors > d->max_errors
                                   : level == DIAG_WARNING && !d->warnings_enabled;
    if (over || !d->sink)
        return;
    char local[MESSAGE_BYTES], *message = local;
    size_t lead = subject_prefix(d, span, local, sizeof local);
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(local + lead, sizeof local - lead, fmt, ap) + (int)lead;
    va_end(ap);
    const mem *m = d->sources ? &d->sources->mem : NULL;
    char *big = n >= (int)sizeof local ? mem_alloc(m, (size_t)n + 1) : NULL;
    if (big) {
        memcpy(big, local, lead);
        va_start(ap, fmt);
        vsnprintf(big + lead, (size_t)n + 1 - lead, fmt, ap);
        va_end(ap);
        message = big;
    }
    char shown[SHOWN_BYTES];
    text_escape(message, strlen(message), shown, sizeof shown);
    if (big)
        mem_free(m, big, (size_t)n + 1);
    deliver(d, level, span, shown);
    if (level == DIAG_ERROR && d->max_errors > 0 && d->errors == d->max_errors) {
        snprintf(local, sizeof local, "too many errors (%d), stopping", d->max_errors);
        deliver(d, DIAG_NOTE, src_span_none(), local);
    }
}
