/*
 * fileio.h - reading a whole input file with a size limit, and the one
 * place that maps the reasons a read fails to exit codes and messages;
 * writing a file atomically, making and removing directory trees.
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

/* path made absolute against the working directory (not resolved:
 * "." and ".." parts and links stay); malloc'd, NULL when out of memory or
 * the working directory is unknown. */
char *file_absolute(const char *path);

/* 0666 less the process's umask: the mode open(2) gives a new file. */
unsigned file_new_mode(void);

/* Writes the contents of a file into fp; returns 0, or non-zero to abandon
 * the file (the writer's own reason stays with its caller). */
typedef int (*file_fill_fn)(FILE *fp, void *ctx);

/*
 * Writes path atomically: fill writes into a temporary "<path>.tmp.XXXXXX"
 * in the same directory, which is flushed, synced, closed and renamed onto
 * path, with the mode a new file would get (file_new_mode).  On any failure,
 * fill's included, the temporary is removed and path is left as it was.
 * Returns 0; REFRAY_EXIT_IOERR (path is not a regular file, or a write,
 * sync or rename failed), REFRAY_EXIT_SOFTWARE (out of memory), or fill's
 * non-zero result; with a one-line reason naming path in why.
 */
int file_write_atomic(const char *path, file_fill_fn fill, void *ctx, char *why, size_t why_size);

/* file_write_atomic of len bytes of data. */
int file_write_bytes(const char *path, const void *data, size_t len, char *why, size_t why_size);

/* Creates directory path and its missing parents.  Returns 0, or
 * REFRAY_EXIT_IOERR with the reason in why. */
int file_make_dirs(const char *path, char *why, size_t why_size);

/*
 * Removes path and, for a directory, everything under it.  Symbolic links
 * are removed, never followed, so nothing outside path is touched.  Returns
 * 0 (also when path does not exist), or REFRAY_EXIT_IOERR with the first
 * reason in why (what could be removed is removed).
 */
int file_remove_tree(const char *path, char *why, size_t why_size);

#endif
