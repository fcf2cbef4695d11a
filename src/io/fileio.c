/*
 * fileio.c - see fileio.h.  Only regular files are read: a directory, a FIFO
 * or a device could block forever or never end, which an input must not
 * ([REL-FILE-1]).
 */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "io/fileio.h"
#include "base/status.h"

static int open_error(const char *path, char *why, size_t why_size)
{
    snprintf(why, why_size, "cannot open '%s': %s", path, strerror(errno));
    return STATUS_NO_INPUT;
}

int file_open_read(const char *path, int *fd, struct stat *st, char *why, size_t why_size)
{
    /* O_NONBLOCK: opening a FIFO without a writer returns at once instead
     * of waiting; the descriptor's own fstat then says what was opened,
     * so nothing can be swapped in between a check and the open. */
    *fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (*fd < 0)
        return open_error(path, why, why_size);
    int status = STATUS_OK;
    if (fstat(*fd, st) != 0)
        status = open_error(path, why, why_size);
    else if (S_ISDIR(st->st_mode)) {
        snprintf(why, why_size, "'%s' is a directory, not a file", path);
        status = STATUS_NO_INPUT;
    } else if (!S_ISREG(st->st_mode)) {
        snprintf(why, why_size, "'%s' is not a regular file", path);
        status = STATUS_NO_INPUT;
    } else if (fcntl(*fd, F_SETFL, fcntl(*fd, F_GETFL) & ~O_NONBLOCK) != 0)
        status = open_error(path, why, why_size);
    if (status != STATUS_OK) {
        close(*fd);
        *fd = -1;
    }
    return status;
}

FILE *file_fopen_read(const char *path, int *status, char *why, size_t why_size)
{
    int fd;
    struct stat st;
    *status = file_open_read(path, &fd, &st, why, why_size);
    if (*status != STATUS_OK)
        return NULL;
    FILE *f = fdopen(fd, "rb");
    if (!f) {
        *status = open_error(path, why, why_size);
        close(fd);
    }
    return f;
}

/* size < 0: the file's size is unknown, only that it passed the limit. */
static int too_big(const char *path, long long size, long max_bytes, char *why, size_t why_size)
{
    if (size >= 0)
        snprintf(why, why_size, "'%s' is %lld bytes, over the limit of %ld (--max-file-size)", path, size,
                 max_bytes);
    else
        snprintf(why, why_size, "'%s' is over the limit of %ld bytes (--max-file-size)", path, max_bytes);
    return STATUS_DATA;
}

/* Reads fd to its end, never trusting the size fstat gave (a /proc file
 * says 0, a growing file more than it had): at most max_bytes (< 0: no
 * limit); one byte more is an error. */
static int read_fd(int fd, const char *path, size_t hint, long max_bytes, const mem *m, char **text,
                   size_t *len, char *why, size_t why_size)
{
    size_t cap = hint + 1 > 4096 ? hint + 1 : 4096, n = 0;
    char *buf = mem_alloc(m, cap + 1);
    for (;;) {
        if (!buf) {
            snprintf(why, why_size, "out of memory reading '%s'", path);
            return STATUS_NO_MEMORY;
        }
        if (max_bytes >= 0 && n > (size_t)max_bytes) {
            mem_free(m, buf, cap + 1);
            return too_big(path, -1, max_bytes, why, why_size);
        }
        if (n == cap) {
            size_t next = cap * 2;
            char *grown = mem_resize(m, buf, cap + 1, next + 1);
            if (!grown)
                mem_free(m, buf, cap + 1);
            buf = grown;
            cap = next;
            continue;
        }
        ssize_t got = read(fd, buf + n, cap - n);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0) {
            snprintf(why, why_size, "error reading '%s': %s", path, strerror(errno));
            mem_free(m, buf, cap + 1);
            return STATUS_IO;
        }
        if (got == 0)
            break;
        n += (size_t)got;
    }
    /* The text is kept at its length: one resize, no slack held. */
    char *fit = mem_resize(m, buf, cap + 1, n + 1);
    if (fit)
        buf = fit;
    else if (cap != n) {
        /* Shrinking failed: keep the bigger block, but its size must be
         * what it is freed with, so copy into one of the right size. */
        fit = mem_alloc(m, n + 1);
        if (fit)
            memcpy(fit, buf, n);
        mem_free(m, buf, cap + 1);
        if (!fit) {
            snprintf(why, why_size, "out of memory reading '%s'", path);
            return STATUS_NO_MEMORY;
        }
        buf = fit;
    }
    buf[n] = '\0';
    *text = buf;
    *len = n;
    return STATUS_OK;
}

int file_read_all(const char *path, long max_bytes, const mem *m, char **text, size_t *len, char *why,
                  size_t why_size)
{
    int fd;
    struct stat st;
    int status = file_open_read(path, &fd, &st, why, why_size);
    if (status != STATUS_OK)
        return status;
    if (max_bytes >= 0 && st.st_size > max_bytes)
        status = too_big(path, (long long)st.st_size, max_bytes, why, why_size);
    else
        status = read_fd(fd, path, (size_t)st.st_size, max_bytes, m, text, len, why, why_size);
    close(fd);
    return status;
}

char *file_dirname(const mem *m, const char *path)
{
    const char *slash = strrchr(path, '/');
    size_t n = slash ? (size_t)(slash - path) : 0;
    if (slash && n == 0)
        n = 1; /* "/x": the root */
    return slash ? mem_strndup(m, path, n) : mem_strdup(m, ".");
}

char *file_join(const mem *m, const char *dir, const char *rel)
{
    if (rel[0] == '/' || strcmp(dir, ".") == 0)
        return mem_strdup(m, rel);
    const char *sep = dir[strlen(dir) - 1] == '/' ? "" : "/";
    size_t n = strlen(dir) + strlen(sep) + strlen(rel);
    char *out = mem_alloc(m, n + 1);
    if (out)
        snprintf(out, n + 1, "%s%s%s", dir, sep, rel);
    return out;
}

char *file_absolute(const mem *m, const char *path)
{
    if (path[0] == '/')
        return file_join(m, "/", path);
    char cwd[4096];
    return getcwd(cwd, sizeof cwd) ? file_join(m, cwd, path) : NULL;
}
