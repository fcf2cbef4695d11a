/*
 * jsonloc.h - where a value sits in a JSON text.
 *
 * A JSON library hands back values without their positions; a diagnostic
 * needs the line and column.  These functions walk a text that a JSON
 * parser has already accepted (they are not a parser: on text that is not
 * valid JSON they give some answer or none, never read out of bounds) and
 * find the byte span of the value at a path, or the path of the value at a
 * byte offset.  Paths are printed as JSON pointers (RFC 6901): "/a/0/b",
 * with '~' written "~0" and '/' written "~1"; the root is "".
 */
#ifndef REFRAY_JSONLOC_H
#define REFRAY_JSONLOC_H

#include <stddef.h>

/* One step of a path: a member name, or an array index when key is NULL. */
typedef struct jsonloc_step {
    const char *key;
    size_t index;
} jsonloc_step;

typedef struct jsonloc_span {
    size_t begin, end;  /* byte offsets, end one past the last byte */
} jsonloc_span;

/*
 * Finds the value at path (depth steps) in text[0..len).  Returns 1 with
 * the span of the value in *value and, in *key, the span of the quoted
 * member name that leads to it (for an array element or the root: the
 * value's span again); 0 when the path is not in the text.  key may be NULL.
 */
int jsonloc_find(const char *text, size_t len, const jsonloc_step *path, int depth, jsonloc_span *key,
                 jsonloc_span *value);

/*
 * The begin offsets of the first count elements of the array at path, in
 * order, into begins.  Returns the number found (fewer when the array is
 * shorter or the path is not there).  One walk of the text, however many
 * elements.
 */
size_t jsonloc_elements(const char *text, size_t len, const jsonloc_step *path, int depth, size_t *begins,
                        size_t count);

/*
 * The JSON pointer of the innermost value, or member name, that holds byte
 * offset: written NUL-terminated into buf (cut short when it does not fit
 * in size bytes).  Returns the pointer's full length; 0 for the root (or
 * an offset outside every value).
 */
size_t jsonloc_pointer_at(const char *text, size_t len, size_t offset, char *buf, size_t size);

/* A path printed as a JSON pointer into buf; returns its full length. */
size_t jsonloc_pointer(const jsonloc_step *path, int depth, char *buf, size_t size);

#endif
