/*
 * filewrite.h - making and removing directory trees (what `refray kit` and
 * `refray conform` write); files themselves are written by io/atomic.h.
 */
#ifndef REFRAY_FILEWRITE_H
#define REFRAY_FILEWRITE_H

#include <stddef.h>
#include "io/atomic.h"

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
