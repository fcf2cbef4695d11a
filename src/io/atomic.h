/*
 * atomic.h - the one way refray writes an output file: into a temporary
 * in the same directory, renamed onto the path only when every byte is
 * written, flushed and synced, so that the path holds the old file or the
 * whole new one, never a part (spec/reliability.md, "Output files").
 *
 * The policy, checked before anything is created ([REL-OUT-*]):
 *   - the directory must exist and be writable, and the file's name fit
 *     the file system (NAME_MAX);
 *   - a path that is a symbolic link is refused (nothing is written
 *     through or over a link), as is anything but a regular file;
 *   - an existing regular file is replaced only when this process could
 *     write it (a read-only file is refused, as a shell's `>` refuses
 *     it) and it belongs to this user (root: to anyone, and the new file
 *     gets its owner and group back);
 *   - the new file's mode: the old file's permission bits (setuid, setgid
 *     and sticky are never copied), or 0666 less the umask for a new one.
 * The temporary is ".refray-tmp-PID-XXXXXX" (mkstemp) beside the output:
 * hidden, short (an output name of NAME_MAX bytes still works), and
 * marked with the writer's process id.  A process killed while writing
 * (SIGKILL) leaves it behind; the next writer into that directory removes
 * every such file of this user whose process is gone and that was last
 * written more than a minute ago.
 */
#ifndef REFRAY_ATOMIC_H
#define REFRAY_ATOMIC_H

#include <stddef.h>
#include <stdio.h>
#include <sys/types.h>
#include "base/cancel.h"

/* 0666 less the process's umask: the mode open(2) gives a new file. */
unsigned file_new_mode(void);

/* What an output path will be written with, once checked. */
typedef struct file_target {
    unsigned mode;       /* permission bits of the new file (<= 0777) */
    int replaces;        /* 1: a regular file is there now */
    uid_t uid;           /* the replaced file's owner and group */
    gid_t gid;
} file_target;

/*
 * Checks that path could be written by the policy above, before any work
 * whose result would go there.  Returns STATUS_OK with *t filled (t may be
 * NULL), or STATUS_IO with a one-line reason naming path in why.
 */
int file_write_check(const char *path, file_target *t, char *why, size_t why_size);

/* An output file being written. */
typedef struct file_out {
    FILE *fp;            /* where the contents go */
    char *path;          /* copies (malloc) */
    char *tmp;
    cancel_poll *cancel; /* asked before the rename; NULL: never */
} file_out;

/*
 * Checks path (file_write_check), removes stale temporaries in its
 * directory and creates this write's temporary, with the final mode,
 * owner and group already set.  Returns STATUS_OK with o->fp open, or
 * STATUS_IO / STATUS_NO_MEMORY with the reason in why (nothing created).
 */
int file_out_open(file_out *o, const char *path, cancel_poll *cancel, char *why, size_t why_size);

/*
 * Flushes, syncs and closes the temporary, checks that path has not turned
 * into a link or a non-file meanwhile and renames the temporary onto it.
 * Returns STATUS_OK; STATUS_CANCELLED (o->cancel said stop), STATUS_IO;
 * on failure the temporary is removed and path is left as it was.
 */
int file_out_commit(file_out *o, char *why, size_t why_size);

/* Closes and removes the temporary: path is left as it was. */
void file_out_abort(file_out *o);

/* Writes the contents of a file into fp; returns STATUS_OK, or another
 * status to abandon the file (the writer's own reason stays with its
 * caller). */
typedef int (*file_fill_fn)(FILE *fp, void *ctx);

/*
 * The whole write: file_out_open, fill, file_out_commit (or abort when
 * fill fails).  Returns STATUS_OK, fill's status, or the writer's
 * (STATUS_IO, STATUS_NO_MEMORY, STATUS_CANCELLED) with a reason naming
 * path in why (after a failure of fill, a generic one).
 */
int file_write_polled(const char *path, file_fill_fn fill, void *ctx, cancel_poll *cancel, char *why,
                      size_t why_size);

/* file_write_polled without a cancel poll. */
int file_write_atomic(const char *path, file_fill_fn fill, void *ctx, char *why, size_t why_size);

/* file_write_atomic of len bytes of data. */
int file_write_bytes(const char *path, const void *data, size_t len, char *why, size_t why_size);

/* Removes the stale temporaries of dir (see the top); the number removed. */
int file_remove_stale(const char *dir);

/* The process id in a temporary's name ".refray-tmp-PID-XXXXXX", or -1
 * when name is not one (for a directory refray owns, such as a
 * checkpoint, that may remove them sooner than file_remove_stale). */
long file_temp_owner(const char *name);

#endif
