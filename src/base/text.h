/*
 * text.h - making untrusted bytes (another program's standard error, a
 * file name) safe to put into JSON, XML and terminal reports.
 */
#ifndef REFRAY_TEXT_H
#define REFRAY_TEXT_H

#include <stddef.h>

/*
 * Copies len bytes of in to out (out_size bytes, always NUL-terminated) as
 * valid UTF-8 that XML 1.0 accepts: well-formed sequences of 2 to 4 bytes
 * are kept, every other byte that is not printable ASCII, a tab or a line
 * feed becomes '?'.  "\r\n" becomes "\n" and a lone "\r" (a progress
 * line redrawn) a line feed.  A sequence that would not fit whole is
 * dropped.  Returns the length written.
 */
size_t text_clean(const char *in, size_t len, char *out, size_t out_size);

/*
 * Copies len bytes of in to out (out_size bytes, always NUL-terminated)
 * with every byte that is not printable ASCII (0x20 to 0x7e) written as
 * \xHH: control bytes, ESC and the C1 range 0x80 to 0x9f among them, so
 * the text cannot move a terminal's cursor or change its colours
 * ([REL-ESCAPE-1]).  When the escaped text does not fit, its middle is
 * cut: the first two thirds and the last third of the room are kept, with
 * "..." between.  Returns the length written.
 */
size_t text_escape(const char *in, size_t len, char *out, size_t out_size);

/* The last lines of text[0..len): at most max_lines lines and max_bytes
 * bytes, cut at a line start where possible.  Returns the offset in text
 * where that tail begins. */
size_t text_tail(const char *text, size_t len, int max_lines, size_t max_bytes);

#endif
