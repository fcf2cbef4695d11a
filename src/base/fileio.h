/*
 * fileio.h - reading a whole input file with a size limit, and the one
 * place that maps the reasons a read fails to exit codes and messages.
 */
#ifndef REFRAY_FILEIO_H
#define REFRAY_FILEIO_H

#include <stddef.h>

/*
 * Reads path into a malloc'd, NUL-terminated buffer.  Returns 0 on success;
 * otherwise STATUS_NO_INPUT (missing, unreadable, a directory, not a
 * regular file), STATUS_DATA (larger than max_bytes) or
 * STATUS_IO (a read failed), with a one-line reason in why.
 */
int file_read_all(const char *path, long max_bytes, char **text, size_t *len, char *why, size_t why_size);

/* The directory part of path ("." when it has none), malloc'd. */
char *file_dirname(const char *path);

/* dir + "/" + rel unless rel is absolute or dir is "."; malloc'd. */
char *file_join(const char *dir, const char *rel);

#endif
