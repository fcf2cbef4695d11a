/*
 * atomic.c - see atomic.h.
 */
/* fchown, kill, and the d_type-free readdir walk need more than
 * _POSIX_C_SOURCE's base set on some systems; 700 is POSIX 2008 + XSI. */
#define _XOPEN_SOURCE 700
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#include "base/status.h"
#include "io/atomic.h"
#include "io/fileio.h"

#define TEMP_PREFIX ".refray-tmp-"
enum { STALE_SECONDS = 60 };

/* Read where Linux publishes it: asking umask(2) means setting it, a
 * process-wide change.  Elsewhere the common umask 022 is assumed. */
unsigned file_new_mode(void)
{
    unsigned mask = 022;
    char line[128];
    FILE *f = fopen("/proc/self/status", "r");
    while (f && fgets(line, sizeof line, f))
        if (sscanf(line, "Umask: %o", &mask) == 1)
            break;
    if (f)
        fclose(f);
    return 0666u & ~mask;
}

static int refuse(char *why, size_t why_size, const char *path, const char *reason)
{
    snprintf(why, why_size, "cannot write '%s': %s", path, reason);
    return STATUS_IO;
}

/* The directory part of path must be a directory this process may add
 * files to. */
static int check_dir(const char *path, const char *dir, char *why, size_t why_size)
{
    struct stat ds;
    const char *reason = NULL;
    if (stat(dir, &ds) != 0)
        reason = strerror(errno);
    else if (!S_ISDIR(ds.st_mode))
        reason = "not a directory";
    else if (access(dir, W_OK | X_OK) != 0)
        reason = strerror(errno);
    if (!reason)
        return STATUS_OK;
    snprintf(why, why_size, "cannot write '%s': cannot write into '%s': %s", path, dir, reason);
    return STATUS_IO;
}

/* What is at path now, against the policy of atomic.h. */
static int check_existing(const char *path, file_target *t, char *why, size_t why_size)
{
    struct stat sb;
    if (lstat(path, &sb) != 0)
        return errno == ENOENT ? STATUS_OK : refuse(why, why_size, path, strerror(errno));
    if (S_ISLNK(sb.st_mode))
        return refuse(why, why_size, path, "it is a symbolic link (refray writes neither through nor over one)");
    if (!S_ISREG(sb.st_mode))
        return refuse(why, why_size, path, "it exists and is not a regular file");
    if (sb.st_uid != geteuid() && geteuid() != 0) {
        char reason[96];
        snprintf(reason, sizeof reason, "it belongs to another user (uid %ld)", (long)sb.st_uid);
        return refuse(why, why_size, path, reason);
    }
    if (faccessat(AT_FDCWD, path, W_OK, AT_EACCESS) != 0)
        return refuse(why, why_size, path, "it is read-only");
    t->replaces = 1;
    t->mode = (unsigned)(sb.st_mode & 0777);
    t->uid = sb.st_uid;
    t->gid = sb.st_gid;
    return STATUS_OK;
}

int file_write_check(const char *path, file_target *t, char *why, size_t why_size)
{
    file_target local;
    if (!t)
        t = &local;
    memset(t, 0, sizeof *t);
    t->mode = file_new_mode();
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    if (!*base || strcmp(base, ".") == 0 || strcmp(base, "..") == 0)
        return refuse(why, why_size, path, "it names no file");
    char *dir = file_dirname(NULL, path);
    if (!dir) {
        snprintf(why, why_size, "cannot write '%s': out of memory", path);
        return STATUS_NO_MEMORY;
    }
    int rc = check_dir(path, dir, why, why_size);
    long name_max = rc == STATUS_OK ? pathconf(dir, _PC_NAME_MAX) : 0;
    if (name_max <= 0)
        name_max = NAME_MAX;
    if (rc == STATUS_OK && strlen(base) > (size_t)name_max) {
        char reason[96];
        snprintf(reason, sizeof reason, "its name is %zu bytes, over the %ld of this file system", strlen(base),
                 name_max);
        rc = refuse(why, why_size, path, reason);
    }
    mem_free_string(NULL, dir);
    return rc == STATUS_OK ? check_existing(path, t, why, why_size) : rc;
}

long file_temp_owner(const char *name)
{
    size_t n = sizeof TEMP_PREFIX - 1;
    if (strncmp(name, TEMP_PREFIX, n) != 0)
        return -1;
    char *end;
    errno = 0;
    long pid = strtol(name + n, &end, 10);
    if (errno || end == name + n || pid <= 0 || *end != '-' || strlen(end + 1) != 6)
        return -1;
    return pid;
}

int file_remove_stale(const char *dir)
{
    DIR *d = opendir(dir);
    int removed = 0;
    if (!d)
        return 0;
    time_t now = time(NULL);
    for (struct dirent *e; (e = readdir(d)) != NULL;) {
        long pid = file_temp_owner(e->d_name);
        struct stat sb;
        if (pid < 0 || fstatat(dirfd(d), e->d_name, &sb, AT_SYMLINK_NOFOLLOW) != 0 || !S_ISREG(sb.st_mode) ||
            sb.st_uid != geteuid() || now - sb.st_mtime < STALE_SECONDS)
            continue;
        /* kill(pid, 0) fails with ESRCH only when no such process exists. */
        if (kill((pid_t)pid, 0) != 0 && errno == ESRCH && unlinkat(dirfd(d), e->d_name, 0) == 0)
            removed++;
    }
    closedir(d);
    return removed;
}

static void free_out(file_out *o)
{
    free(o->path);
    free(o->tmp);
    o->path = o->tmp = NULL;
    o->fp = NULL;
}

/* The temporary for path in dir, with the target's mode and owner. */
static int make_temp(file_out *o, const char *dir, const file_target *t, char *why, size_t why_size)
{
    size_t n = strlen(dir) + sizeof "/" TEMP_PREFIX "-XXXXXX" + 24;
    o->tmp = malloc(n);
    if (!o->tmp) {
        refuse(why, why_size, o->path, "out of memory");
        return STATUS_NO_MEMORY;
    }
    snprintf(o->tmp, n, "%s/" TEMP_PREFIX "%ld-XXXXXX", dir, (long)getpid());
    int fd = mkstemp(o->tmp);
    if (fd < 0) {
        char reason[160];
        snprintf(reason, sizeof reason, "cannot create a temporary file: %s", strerror(errno));
        return refuse(why, why_size, o->path, reason);
    }
    const char *failed = NULL;
    if (t->replaces && (t->uid != geteuid() || t->gid != getegid()) && fchown(fd, t->uid, t->gid) != 0)
        failed = "cannot give it the owner and group of the file it replaces";
    else if (fchmod(fd, (mode_t)t->mode) != 0)
        failed = "cannot set its mode";
    else if (!(o->fp = fdopen(fd, "wb")))
        failed = "cannot open a stream";
    if (!failed)
        return STATUS_OK;
    char reason[200];
    snprintf(reason, sizeof reason, "%s: %s", failed, strerror(errno));
    close(fd);
    unlink(o->tmp);
    return refuse(why, why_size, o->path, reason);
}

int file_out_open(file_out *o, const char *path, cancel_poll *cancel, char *why, size_t why_size)
{
    file_target t;
    memset(o, 0, sizeof *o);
    o->cancel = cancel;
    int rc = file_write_check(path, &t, why, why_size);
    if (rc != STATUS_OK)
        return rc;
    char *dir = file_dirname(NULL, path);
    size_t len = strlen(path) + 1;
    o->path = malloc(len);
    if (!dir || !o->path) {
        mem_free_string(NULL, dir);
        free_out(o);
        snprintf(why, why_size, "cannot write '%s': out of memory", path);
        return STATUS_NO_MEMORY;
    }
    memcpy(o->path, path, len);
    file_remove_stale(dir);
    rc = make_temp(o, dir, &t, why, why_size);
    mem_free_string(NULL, dir);
    if (rc != STATUS_OK)
        free_out(o);
    return rc;
}

void file_out_abort(file_out *o)
{
    if (o->fp)
        fclose(o->fp);
    if (o->tmp)
        unlink(o->tmp);
    free_out(o);
}

int file_out_commit(file_out *o, char *why, size_t why_size)
{
    char reason[160] = "";
    FILE *fp = o->fp;
    errno = 0;
    if (fflush(fp) != 0 || ferror(fp) || fsync(fileno(fp)) != 0)
        snprintf(reason, sizeof reason, "write error: %s", errno ? strerror(errno) : "unknown");
    if (fclose(fp) != 0 && !reason[0])
        snprintf(reason, sizeof reason, "write error: %s", strerror(errno));
    o->fp = NULL;
    int rc = reason[0] ? STATUS_IO : STATUS_OK;
    file_target now;
    if (rc == STATUS_OK && cancel_now(o->cancel)) {
        snprintf(why, why_size, "cannot write '%s': interrupted", o->path);
        rc = STATUS_CANCELLED;
    } else if (rc == STATUS_OK && (rc = check_existing(o->path, &now, why, why_size)) != STATUS_OK) {
        /* Something else appeared at the path meanwhile: leave it. */
    } else if (rc == STATUS_OK && rename(o->tmp, o->path) != 0) {
        snprintf(reason, sizeof reason, "cannot rename the temporary file into place: %s", strerror(errno));
        rc = STATUS_IO;
    }
    if (reason[0])
        refuse(why, why_size, o->path, reason);
    if (rc != STATUS_OK)
        unlink(o->tmp);
    free_out(o);
    return rc;
}

int file_write_polled(const char *path, file_fill_fn fill, void *ctx, cancel_poll *cancel, char *why,
                      size_t why_size)
{
    file_out o;
    int rc = file_out_open(&o, path, cancel, why, why_size);
    if (rc != STATUS_OK)
        return rc;
    errno = 0;
    rc = fill(o.fp, ctx);
    if (rc != STATUS_OK) {
        snprintf(why, why_size, "cannot write '%s': %s", path, errno ? strerror(errno) : "write error");
        file_out_abort(&o);
        return rc;
    }
    return file_out_commit(&o, why, why_size);
}

int file_write_atomic(const char *path, file_fill_fn fill, void *ctx, char *why, size_t why_size)
{
    return file_write_polled(path, fill, ctx, NULL, why, why_size);
}

typedef struct byte_span {
    const void *data;
    size_t len;
} byte_span;

static int fill_bytes(FILE *fp, void *ctx)
{
    const byte_span *b = ctx;
    return b->len == 0 || fwrite(b->data, 1, b->len, fp) == b->len ? 0 : STATUS_IO;
}

int file_write_bytes(const char *path, const void *data, size_t len, char *why, size_t why_size)
{
    byte_span b;
    b.data = data;
    b.len = len;
    return file_write_atomic(path, fill_bytes, &b, why, why_size);
}
