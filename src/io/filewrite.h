/*
 * filewrite.h - writing a file atomically, making and removing directory
 * trees (what `refray kit` and `refray conform` write).
 */
#ifndef REFRAY_FILEWRITE_H
#define REFRAY_FILEWRITE_H

#include <stddef.h>
#include <stdio.h>

/* 0666 less the process's umask: the mode open(2) gives a new file. */
unsigned file_new_mode(void);

/* Writes the contents of a file into fp; returns STATUS_OK, or another
 * status to abandon the file (the writer's own reason stays with its
 * caller). */
typedef int (*file_fill_fn)(FILE *fp, void *ctx);

/*
 * Writes path atomically: fill writes into a temporary "<path>.tmp.XXXXXX"
 * in the same directory, which is flushed, synced, closed and renamed onto
 * path, with the mode a new file would get (file_new_mode).  On any failure,
 * fill's included, the temporary is removed and path is left as it was.
 * Returns STATUS_OK; STATUS_IO (path is not a regular file, or a write,
 * sync or rename failed), STATUS_NO_MEMORY, or fill's status; with a
 * one-line reason naming path in why.
 */
int file_write_atomic(const char *path, file_fill_fn fill, void *ctx, char *why, size_t why_size);

/* file_write_atomic of len bytes of data. */
int file_write_bytes(const char *path, const void *data, size_t len, char *why, size_t why_size);

/* Creates directory path and its missing parents.  Returns STATUS_OK, or
 * STATUS_IO (STATUS_NO_MEMORY) with the reason in why. */
int file_make_dirs(const char *path, char *why, size_t why_size);

/*
 * Removes path and, for a directory, everything under it.  Symbolic links
 * are removed, never followed, so nothing outside path is touched.  Returns
 * STATUS_OK (also when path does not exist), or STATUS_IO with the first
 * reason in why (what could be removed is removed).
 */
int file_remove_tree(const char *path, char *why, size_t why_size);

#endif
