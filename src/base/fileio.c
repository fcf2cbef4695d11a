/*
 * fileio.c - see fileio.h.  Only regular files are read: a directory, a FIFO
 * or a device could block forever or never end, which an input must not.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "base/fileio.h"
#include "base/status.h"

static int open_error(const char *path, char *why, size_t why_size)
{
    snprintf(why, why_size, "cannot open '%s': %s", path, strerror(errno));
    return REFRAY_EXIT_NOINPUT;
}

static int read_stream(FILE *f, const char *path, size_t size, char **text, size_t *len, char *why,
                       size_t why_size)
{
    char *buf = malloc(size + 1);
    if (!buf) {
        snprintf(why, why_size, "out of memory reading '%s'", path);
        return REFRAY_EXIT_SOFTWARE;
    }
    size_t got = fread(buf, 1, size, f);
    /* A file that grew since fstat is read only up to its checked size. */
    if (got != size || ferror(f)) {
        snprintf(why, why_size, "error reading '%s': %s", path, ferror(f) ? strerror(errno) : "file shrank");
        free(buf);
        return REFRAY_EXIT_IOERR;
    }
    buf[size] = '\0';
    *text = buf;
    *len = size;
    return 0;
}

int file_read_all(const char *path, long max_bytes, char **text, size_t *len, char *why, size_t why_size)
{
    struct stat st;
    if (stat(path, &st) != 0)
        return open_error(path, why, why_size);
    if (S_ISDIR(st.st_mode)) {
        snprintf(why, why_size, "'%s' is a directory, not a file", path);
        return REFRAY_EXIT_NOINPUT;
    }
    if (!S_ISREG(st.st_mode)) {
        snprintf(why, why_size, "'%s' is not a regular file", path);
        return REFRAY_EXIT_NOINPUT;
    }
    if (max_bytes >= 0 && st.st_size > max_bytes) {
        snprintf(why, why_size, "'%s' is %lld bytes, over the limit of %ld (--max-file-size)", path,
                 (long long)st.st_size, max_bytes);
        return REFRAY_EXIT_DATAERR;
    }
    FILE *f = fopen(path, "rb");
    if (!f)
        return open_error(path, why, why_size);
    int status = read_stream(f, path, (size_t)st.st_size, text, len, why, why_size);
    fclose(f);
    return status;
}

char *file_dirname(const char *path)
{
    const char *slash = strrchr(path, '/');
    size_t n = slash ? (size_t)(slash - path) : 0;
    if (slash && n == 0)
        n = 1; /* "/x": the root */
    char *dir = malloc(slash ? n + 1 : 2);
    if (!dir)
        return NULL;
    if (slash) {
        memcpy(dir, path, n);
        dir[n] = '\0';
    } else {
        strcpy(dir, ".");
    }
    return dir;
}

char *file_join(const char *dir, const char *rel)
{
    int keep = rel[0] == '/' || strcmp(dir, ".") == 0;
    size_t n = keep ? strlen(rel) : strlen(dir) + 1 + strlen(rel);
    char *out = malloc(n + 1);
    if (!out)
        return NULL;
    if (keep)
        strcpy(out, rel);
    else
        sprintf(out, "%s%s%s", dir, dir[strlen(dir) - 1] == '/' ? "" : "/", rel);
    return out;
}

/* mkstemp makes 0600; give the file the mode a plain fopen would have:
 * an existing file's, else 0666 less the umask (read from /proc, since
 * asking umask(2) means changing it for the whole process). */
static void set_mode(int fd, const char *path)
{
    struct stat sb;
    unsigned mask = 022;
    char line[128];
    if (stat(path, &sb) == 0 && S_ISREG(sb.st_mode)) {
        fchmod(fd, sb.st_mode & 07777);
        return;
    }
    FILE *f = fopen("/proc/self/status", "r");
    while (f && fgets(line, sizeof line, f))
        if (sscanf(line, "Umask: %o", &mask) == 1)
            break;
    if (f)
        fclose(f);
    fchmod(fd, (mode_t)(0666 & ~mask));
}

/* Fills the open temporary fd through fill and closes it; 0 or the exit code. */
static int fill_temp(int fd, const char *path, int (*fill)(FILE *fp, void *ctx), void *ctx)
{
    set_mode(fd, path);
    FILE *fp = fdopen(fd, "w");
    if (!fp) {
        close(fd);
        return REFRAY_EXIT_IOERR;
    }
    int rc = fill(fp, ctx);
    if (rc == 0 && (fflush(fp) != 0 || fsync(fileno(fp)) != 0))
        rc = REFRAY_EXIT_IOERR;
    if (fclose(fp) != 0 && rc == 0)
        rc = REFRAY_EXIT_IOERR;
    return rc;
}

int file_write_atomic(const char *path, int (*fill)(FILE *fp, void *ctx), void *ctx, char *why, size_t why_size)
{
    static const char suffix[] = ".tmp.XXXXXX";
    struct stat sb;
    if (stat(path, &sb) == 0 && !S_ISREG(sb.st_mode)) {
        snprintf(why, why_size, "cannot write '%s': it exists and is not a regular file", path);
        return REFRAY_EXIT_IOERR;
    }
    size_t n = strlen(path) + sizeof suffix;
    char *tmp = malloc(n);
    if (!tmp) {
        snprintf(why, why_size, "out of memory");
        return REFRAY_EXIT_SOFTWARE;
    }
    snprintf(tmp, n, "%s%s", path, suffix);
    int fd = mkstemp(tmp), rc = REFRAY_EXIT_IOERR;
    if (fd < 0)
        snprintf(why, why_size, "cannot write '%s': cannot create a temporary file: %s", path, strerror(errno));
    else if ((rc = fill_temp(fd, path, fill, ctx)) == REFRAY_EXIT_IOERR)
        snprintf(why, why_size, "cannot write '%s': write error: %s", path, strerror(errno));
    else if (rc == 0 && rename(tmp, path) != 0) {
        snprintf(why, why_size, "cannot write '%s': cannot rename the temporary file into place: %s", path,
                 strerror(errno));
        rc = REFRAY_EXIT_IOERR;
    }
    if (fd >= 0 && rc != 0)
        unlink(tmp);
    free(tmp);
    return rc;
}
