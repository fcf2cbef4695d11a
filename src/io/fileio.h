/*
 * fileio.h - reading a whole input file with a size limit, and the one
 * place that maps the reasons a read fails to statuses and messages; file
 * names joined and made absolute.  (Writing: io/filewrite.h.)
 */
#ifndef REFRAY_FILEIO_H
#define REFRAY_FILEIO_H

#include <stddef.h>
#include "base/mem.h"

/*
 * Reads path into a NUL-terminated buffer from m (free it with *len + 1
 * bytes).  Returns STATUS_OK; otherwise STATUS_NO_INPUT (missing,
 * unreadable, a directory, not a regular file), STATUS_DATA (larger than
 * max_bytes; max_bytes < 0: no limit), STATUS_IO (a read failed) or
 * STATUS_NO_MEMORY, with a one-line reason in why.
 */
int file_read_all(const char *path, long max_bytes, const mem *m, char **text, size_t *len, char *why,
                  size_t why_size);

/* The directory part of path ("." when it has none), a string from m
 * (mem_free_string); NULL when out of memory. */
char *file_dirname(const mem *m, const char *path);

/* dir + "/" + rel unless rel is absolute or dir is ".", a string from m. */
char *file_join(const mem *m, const char *dir, const char *rel);

/* path made absolute against the working directory (not resolved:
 * "." and ".." parts and links stay), a string from m; NULL when out of
 * memory or the working directory is unknown. */
char *file_absolute(const mem *m, const char *path);

#endif
