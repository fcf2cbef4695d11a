/*
 * diag.h - GCC-style diagnostics: "FILE:LINE:COL: error: MESSAGE", then the
 * source line and a caret under the span.  Every message of the front end
 * and of scene validation goes through diag_report, so they all look alike
 * and are all counted.
 */
#ifndef REFRAY_DIAG_H
#define REFRAY_DIAG_H

#include <stdio.h>
#include "base/source.h"

typedef enum diag_level {
    DIAG_ERROR,
    DIAG_WARNING,
    DIAG_NOTE
} diag_level;

typedef struct diag {
    const source_set *sources; /* where spans point; may be NULL for span-less messages */
    FILE *out;                 /* stream messages go to (stderr in the CLI) */
    int errors;                /* errors reported so far, including suppressed ones */
    int warnings;
    int max_errors;            /* after this many errors further ones are counted, not printed */
    int warnings_enabled;      /* 0: warnings are counted but not printed */
    /* Optional: what a span points at, printed before the message as
     * "SUBJECT: " (a JSON scene names the value by its JSON pointer, since
     * a line and column alone do not say which field of a generated file
     * is meant).  Writes at most size bytes into buf; returns 0 for none. */
    size_t (*subject)(const void *ctx, src_span span, char *buf, size_t size);
    const void *subject_ctx;
} diag;

void diag_init(diag *d, const source_set *sources, FILE *out);

/* Prints one diagnostic (unless over max_errors) and counts it.  A span with
 * file -1 prints "refray: error: ..." without location. */
void diag_report(diag *d, diag_level level, src_span span, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* True once the error limit is reached: callers use it to stop early. */
int diag_too_many(const diag *d);

#endif
