/*
 * diag.h - diagnostics as records: where (file, line, column), how bad,
 * what, and the source line to show under it.  Every message of the front
 * end and of scene validation goes through diag_report, so they all look
 * alike and are all counted; a sink chosen by the caller receives them (the
 * core prints nothing: io/diag_print.h prints them as compilers do).
 */
#ifndef REFRAY_DIAG_H
#define REFRAY_DIAG_H

#include <stddef.h>
#include "base/cancel.h"
#include "base/source.h"

typedef enum diag_level {
    DIAG_ERROR,
    DIAG_WARNING,
    DIAG_NOTE
} diag_level;

/* One message.  Pointers are valid during the sink's call only.  path and
 * message are printable ASCII (other bytes escaped as \xHH) of at most
 * 1023 bytes; source_line is the input's own bytes, any of them, so that
 * columns count as in the file: a sink that shows it escapes it
 * (io/diag_print.c does; spec/reliability.md, [REL-ESCAPE-1]). */
typedef struct diag_record {
    diag_level level;
    const char *path;          /* the file; NULL: no location (a whole-load message) */
    int line, column;          /* 1-based, column in bytes; 0 without a location, or
                                  with path alone (a mesh file whose text is gone) */
    const char *message;       /* without location or level */
    const char *source_line;   /* the line holding the span, without its terminator, raw;
                                  NULL: nothing to show (an "included from here" note) */
    size_t source_line_length;
    size_t span_length;        /* bytes of the span from the column on (may pass the line end) */
} diag_record;

typedef void (*diag_sink)(void *user, const diag_record *record);

typedef struct diag {
    const source_set *sources; /* where spans point; may be NULL for span-less messages */
    diag_sink sink;            /* NULL: messages are counted, not delivered */
    void *sink_user;
    int errors;                /* errors reported so far, including suppressed ones */
    int warnings;
    int max_errors;            /* after this many errors further ones are counted, not delivered */
    int warnings_enabled;      /* 0: warnings are counted but not delivered */
    cancel_poll *cancel;       /* the load's: every reader asks it through diag_stop; NULL: never */
    /* Optional: what a span points at, put before the message as
     * "SUBJECT: " (a JSON scene names the value by its JSON pointer, since
     * a line and column alone do not say which field of a generated file
     * is meant).  Writes at most size bytes into buf, NUL-terminated;
     * returns 0 for none. */
    size_t (*subject)(const void *ctx, src_span span, char *buf, size_t size);
    const void *subject_ctx;
} diag;

void diag_init(diag *d, const source_set *sources, diag_sink sink, void *sink_user);

/*
 * Counts one diagnostic and, unless it is over max_errors or a switched-off
 * warning, delivers it: the record itself, then for a file that was
 * included one note per file that read the next, outermost last ("included
 * from here"; "in the mesh read here" for an OBJ file read by a mesh), and
 * once the error limit is reached, a "too many errors (N), stopping" note
 * without location.  A span with file -1 gives a record without location.
 */
void diag_report(diag *d, diag_level level, src_span span, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* True once the error limit is reached: callers use it to stop early. */
int diag_too_many(const diag *d);

/* diag_too_many, or the load was cancelled: counts one step of d->cancel
 * (base/cancel.h).  Every loop of the front end over input (statements,
 * OBJ lines, tokens) asks it, so a load stops within [REL-CANCEL-1]. */
int diag_stop(const diag *d);

#endif
