/*
 * fileio.h - reading a whole input file with a size limit, and the one
 * place that maps the reasons a read fails to exit codes and messages.
 */
#ifndef REFRAY_FILEIO_H
#define REFRAY_FILEIO_H

#include <stddef.h>
#include <stdio.h>

/*
 * Reads path into a malloc'd, NUL-terminated buffer.  Returns 0 on success;
 * otherwise REFRAY_EXIT_NOINPUT (missing, unreadable, a directory, not a
 * regular file), REFRAY_EXIT_DATAERR (larger than max_bytes) or
 * REFRAY_EXIT_IOERR (a read failed), with a one-line reason in why.
 */
int file_read_all(const char *path, long max_bytes, char **text, size_t *len, char *why, size_t why_size);

/* The directory part of path ("." when it has none), malloc'd. */
char *file_dirname(const char *path);

/* dir + "/" + rel unless rel is absolute or dir is "."; malloc'd. */
char *file_join(const char *dir, const char *rel);

/*
 * Writes path atomically: fill(fp, ctx) writes a temporary
 * "<path>.tmp.XXXXXX" in the same directory, which is flushed, synced and
 * renamed onto path; on any failure it is removed and path is left as it
 * was.  fill returns 0 or an exit code (base/status.h), which is returned.
 * Returns 0, or REFRAY_EXIT_IOERR (path not a regular file, a write or the
 * rename failed) or REFRAY_EXIT_SOFTWARE with a one-line reason in why.
 */
int file_write_atomic(const char *path, int (*fill)(FILE *fp, void *ctx), void *ctx, char *why, size_t why_size);

#endif
