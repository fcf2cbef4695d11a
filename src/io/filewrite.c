/*
 * filewrite.c - see filewrite.h.
 */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "io/filewrite.h"
#include "base/status.h"

/* ---- Directory trees ---- */

int file_make_dirs(const char *path, char *why, size_t why_size)
{
    char *p = malloc(strlen(path) + 1);
    if (!p) {
        snprintf(why, why_size, "out of memory");
        return STATUS_NO_MEMORY;
    }
    strcpy(p, path);
    int rc = 0;
    /* Each prefix ending before a '/', then the whole path. */
    for (char *s = p + 1; rc == 0; s++) {
        if (*s != '/' && *s != '\0')
            continue;
        char keep = *s;
        *s = '\0';
        struct stat sb;
        if (mkdir(p, 0777) != 0 && !(errno == EEXIST && stat(p, &sb) == 0 && S_ISDIR(sb.st_mode))) {
            snprintf(why, why_size, "cannot create the directory '%s': %s", p, strerror(errno));
            rc = STATUS_IO;
        }
        *s = keep;
        if (!keep)
            break;
    }
    free(p);
    return rc;
}

/* Empties the directory open as fd (closed here) and everything under it;
 * the first failure is kept in why. */
static int empty_dir(int fd, const char *path, char *why, size_t why_size)
{
    DIR *d = fdopendir(fd);
    if (!d) {
        snprintf(why, why_size, "cannot read the directory '%s': %s", path, strerror(errno));
        close(fd);
        return STATUS_IO;
    }
    int rc = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        const char *name = e->d_name;
        if (strcmp(name, ".") == 0 || strcmp(name, "..") == 0)
            continue;
        struct stat sb;
        if (fstatat(dirfd(d), name, &sb, AT_SYMLINK_NOFOLLOW) == 0 && S_ISDIR(sb.st_mode)) {
            int sub = openat(dirfd(d), name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
            int r = sub < 0 ? STATUS_IO : empty_dir(sub, name, why, why_size);
            if (r == 0 && unlinkat(dirfd(d), name, AT_REMOVEDIR) != 0)
                r = STATUS_IO;
            if (r != 0 && rc == 0) {
                snprintf(why, why_size, "cannot remove the directory '%s' in '%s'", name, path);
                rc = r;
            }
        } else if (unlinkat(dirfd(d), name, 0) != 0 && rc == 0) {
            snprintf(why, why_size, "cannot remove '%s' in '%s': %s", name, path, strerror(errno));
            rc = STATUS_IO;
        }
    }
    closedir(d);
    return rc;
}

int file_remove_tree(const char *path, char *why, size_t why_size)
{
    struct stat sb;
    if (lstat(path, &sb) != 0 && errno == ENOENT)
        return 0;
    if (lstat(path, &sb) != 0 || (!S_ISDIR(sb.st_mode) && unlink(path) != 0)) {
        snprintf(why, why_size, "cannot remove '%s': %s", path, strerror(errno));
        return STATUS_IO;
    }
    if (!S_ISDIR(sb.st_mode))
        return 0;
    int fd = open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    int rc = fd < 0 ? STATUS_IO : empty_dir(fd, path, why, why_size);
    if (fd < 0)
        snprintf(why, why_size, "cannot open the directory '%s': %s", path, strerror(errno));
    if (rc == 0 && rmdir(path) != 0) {
        snprintf(why, why_size, "cannot remove the directory '%s': %s", path, strerror(errno));
        rc = STATUS_IO;
    }
    return rc;
}
