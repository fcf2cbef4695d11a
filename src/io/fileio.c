/*
 * fileio.c - see fileio.h.  Only regular files are read: a directory, a FIFO
 * or a device could block forever or never end, which an input must not.
 */
#include <errno.h>
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

static int read_stream(FILE *f, const char *path, size_t size, const mem *m, char **text, size_t *len,
                       char *why, size_t why_size)
{
    char *buf = mem_alloc(m, size + 1);
    if (!buf) {
        snprintf(why, why_size, "out of memory reading '%s'", path);
        return STATUS_NO_MEMORY;
    }
    size_t got = fread(buf, 1, size, f);
    /* A file that grew since fstat is read only up to its checked size. */
    if (got != size || ferror(f)) {
        snprintf(why, why_size, "error reading '%s': %s", path, ferror(f) ? strerror(errno) : "file shrank");
        mem_free(m, buf, size + 1);
        return STATUS_IO;
    }
    buf[size] = '\0';
    *text = buf;
    *len = size;
    return 0;
}

int file_read_all(const char *path, long max_bytes, const mem *m, char **text, size_t *len, char *why,
                  size_t why_size)
{
    struct stat st;
    if (stat(path, &st) != 0)
        return open_error(path, why, why_size);
    if (S_ISDIR(st.st_mode)) {
        snprintf(why, why_size, "'%s' is a directory, not a file", path);
        return STATUS_NO_INPUT;
    }
    if (!S_ISREG(st.st_mode)) {
        snprintf(why, why_size, "'%s' is not a regular file", path);
        return STATUS_NO_INPUT;
    }
    if (max_bytes >= 0 && st.st_size > max_bytes) {
        snprintf(why, why_size, "'%s' is %lld bytes, over the limit of %ld (--max-file-size)", path,
                 (long long)st.st_size, max_bytes);
        return STATUS_DATA;
    }
    FILE *f = fopen(path, "rb");
    if (!f)
        return open_error(path, why, why_size);
    int status = read_stream(f, path, (size_t)st.st_size, m, text, len, why, why_size);
    fclose(f);
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
