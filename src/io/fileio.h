/*
 * fileio.h - reading a whole input file with a size limit, and the one
 * place that maps the reasons a read fails to statuses and messages; file
 * names joined and made absolute.  (Writing: io/filewrite.h.)
 */
#ifndef REFRAY_FILEIO_H
#define REFRAY_FILEIO_H

#include <stddef.h>
#include <stdio.h>
#include <sys/stat.h>
#include "base/mem.h"

/*
 * Opens path for reading, refusing what is not a regular file without
 * blocking on it: opened with O_NONBLOCK (a FIFO without a writer does not
 * wait), then fstat of the open descriptor decides (nothing can be
 * swapped in after a check).  Returns STATUS_OK with *fd open (blocking
 * again) and *st its status; or STATUS_NO_INPUT (missing, unreadable, a
 * directory, not a regular file) with a one-line reason in why.  Every
 * input file of the program is opened here ([REL-FILE-1]).
 */
int file_open_read(const char *path, int *fd, struct stat *st, char *why, size_t why_size);

/* The same as a stdio stream ("rb"); NULL with *status and why on failure. */
FILE *file_fopen_read(const char *path, int *status, char *why, size_t why_size);

/*
 * Reads path (file_open_read) to its end into a NUL-terminated buffer
 * from m (free it with *len + 1 bytes); the size the file system claims
 * is not trusted (a /proc file claims 0).  Returns STATUS_OK; otherwise
 * STATUS_NO_INPUT (as file_open_read), STATUS_DATA (larger than
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
