/*
 * source.h - the text of every scene file read in one load, and spans into it.
 *
 * Locations are kept as byte offsets (cheap to carry through the scanner,
 * parser and lowering) and turned into line:column only when a diagnostic is
 * printed.  A span names its file by index into the load's source_set, so a
 * scene built from several include files still points at the right text.
 */
#ifndef REFRAY_SOURCE_H
#define REFRAY_SOURCE_H

#include <stddef.h>
#include "base/mem.h"

typedef struct src_span {
    int file;         /* index into source_set.files; -1: no location */
    size_t begin;     /* byte offset of the first byte */
    size_t end;       /* byte offset one past the last byte (end >= begin) */
} src_span;

typedef struct source_file {
    char *path;            /* as the user or the include wrote it, joined to the includer's dir */
    char *text;            /* contents, NUL-terminated (NUL bytes inside are kept, len counts them)
                              unless lent; NULL once released */
    size_t len;            /* bytes in text, not counting the terminator */
    size_t *line_start;    /* offset of each line's first byte; NULL for a lent file */
    size_t line_count;
    size_t line_cap;       /* entries allocated in line_start */
    src_span included_from;/* the include statement that read it; file -1 for the root */
    int is_mesh;           /* read by a mesh (an OBJ or PLY file), not by an include */
    int lent;              /* text is the caller's (source_set_lend), not freed here */
} source_file;

typedef struct source_set {
    source_file **files;
    int count;
    int cap;
    mem mem;               /* where the files and their texts live */
} source_set;

/* A span that points nowhere, for messages about the command line. */
src_span src_span_none(void);
src_span src_span_join(src_span a, src_span b);

/* An empty set whose memory comes from m (NULL: the C library). */
void source_set_init(source_set *set, const mem *m);
void source_set_free(source_set *set);

/* Adds a file whose text the caller already holds (copied).  Returns its
 * index, or -1 when out of memory. */
int source_set_add(source_set *set, const char *path, const char *text, size_t len,
                   src_span included_from);

/* The same without a copy, for big mesh files: text[0..len) (need not be
 * NUL-terminated) stays the caller's and must stay valid until
 * source_set_release(set, index), which the caller must call before it
 * frees the text.  No line index is built: a message finds its line by
 * scanning.  Returns the index, or -1 when out of memory. */
int source_set_lend(source_set *set, const char *path, const char *text, size_t len, src_span included_from);

/* Drops the text of a file no message will point into any more (a mesh
 * file once its mesh is built; freed unless lent); its path stays.  A span
 * into it is then reported without a line (diag.c). */
void source_set_release(source_set *set, int file);

/* 1-based line and column (in bytes) of a byte offset. */
void source_line_col(const source_file *file, size_t offset, int *line, int *col);

/* The text of the line that holds offset, without its line terminator. */
const char *source_line_text(const source_file *file, size_t offset, size_t *length);

#endif
