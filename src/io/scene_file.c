/*
 * scene_file.c - the file resolver and the file loaders (scene_file.h).
 */
/* realpath is an XSI function: it needs more than _POSIX_C_SOURCE. */
#define _XOPEN_SOURCE 700
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "base/text.h"
#include "io/diag_print.h"
#include "io/fileio.h"
#include "io/scene_file.h"

static const char *delivered_name(const void *reader, int i)
{
    return ((const scene_file_reader *)reader)->delivered[i];
}

void scene_file_reader_init(scene_file_reader *f, long max_bytes, const mem *m)
{
    memset(f, 0, sizeof *f);
    f->max_bytes = max_bytes;
    f->mem = mem_pick(m);
    name_index_init(&f->index, delivered_name, f, &f->mem);
}

void scene_file_reader_free(scene_file_reader *f)
{
    for (int i = 0; i < f->root_count; i++)
        mem_free_string(&f->mem, f->roots[i]);
    mem_free(&f->mem, f->roots, (size_t)f->root_cap * sizeof *f->roots);
    f->roots = NULL;
    f->root_count = f->root_cap = 0;
    name_index_free(&f->index);
    for (int i = 0; i < f->delivered_count; i++)
        mem_free_string(&f->mem, f->delivered[i]);
    mem_free(&f->mem, f->delivered, (size_t)f->delivered_cap * sizeof *f->delivered);
    f->delivered = NULL;
    f->delivered_count = f->delivered_cap = 0;
}

/* Records identity as delivered; 0 when out of memory. */
static int remember(scene_file_reader *f, const char *identity)
{
    if (f->delivered_count == f->delivered_cap) {
        int cap = f->delivered_cap ? 2 * f->delivered_cap : 8;
        char **grown = mem_resize_array(&f->mem, f->delivered, (size_t)f->delivered_cap, (size_t)cap,
                                        sizeof *grown);
        if (!grown)
            return 0;
        f->delivered = grown;
        f->delivered_cap = cap;
    }
    char *copy = mem_strdup(&f->mem, identity);
    if (!copy)
        return 0;
    f->delivered[f->delivered_count] = copy;
    if (!name_index_add(&f->index, f->delivered_count)) {
        mem_free_string(&f->mem, copy);
        return 0;
    }
    f->delivered_count++;
    return 1;
}

static void release(void *user, scene_source *src)
{
    scene_file_reader *f = user;
    mem_free_string(&f->mem, (char *)src->path);
    mem_free_string(&f->mem, (char *)src->identity);
    if (src->text)
        mem_free(&f->mem, (char *)src->text, src->len + 1);
    memset(src, 0, sizeof *src);
}

/* A copy of path's real path, or of path itself when it has none. */
static char *identity_of(const mem *m, const char *path)
{
    char resolved[PATH_MAX];
    return mem_strdup(m, realpath(path, resolved) ? resolved : path);
}

/* The real path of path, or, when it does not exist, its directory's real
 * path joined with its last name; NULL when neither resolves (or out of
 * memory: *oom set).  When path exists but realpath fails (a resolution
 * longer than PATH_MAX, a link to a pipe or a deleted file through /proc)
 * the open could still reach a file anywhere: NULL with *unresolved set. */
static char *real_or_parent(const mem *m, const char *path, int *oom, int *unresolved)
{
    char resolved[PATH_MAX];
    struct stat st;
    if (realpath(path, resolved))
        return mem_strdup(m, resolved);
    if (errno != ENOENT || lstat(path, &st) == 0 || errno != ENOENT) {
        *unresolved = errno ? errno : ENOENT;
        return NULL;
    }
    char *dir = file_dirname(m, path), *joined = NULL;
    if (!dir) {
        *oom = 1;
        return NULL;
    }
    const char *slash = strrchr(path, '/');
    if (realpath(dir, resolved) && !(joined = file_join(m, resolved, slash ? slash + 1 : path)))
        *oom = 1;
    mem_free_string(m, dir);
    return joined;
}

void scene_file_reader_anywhere(scene_file_reader *f)
{
    f->anywhere = 1;
}

int scene_file_reader_confine(scene_file_reader *f, const char *scene_path, const char *const *dirs)
{
    int n = 1, oom = 0;
    for (int i = 0; dirs && dirs[i]; i++)
        n++;
    f->roots = mem_calloc(&f->mem, (size_t)n + 1, sizeof *f->roots);
    if (!f->roots)
        return STATUS_NO_MEMORY;
    f->root_cap = n + 1;
    char resolved[PATH_MAX], *dir = file_dirname(&f->mem, scene_path);
    if (!dir)
        return STATUS_NO_MEMORY;
    for (int i = 0; i < n && !oom; i++) {
        const char *d = i == 0 ? dir : dirs[i - 1];
        if (realpath(d, resolved) && !(f->roots[f->root_count++] = mem_strdup(&f->mem, resolved)))
            oom = 1;
    }
    mem_free_string(&f->mem, dir);
    return oom ? STATUS_NO_MEMORY : STATUS_OK;
}

/* Whether resolved_path lies in root's tree (root itself included). */
static int within(const char *resolved_path, const char *root)
{
    size_t n = strlen(root);
    if (n == 1 && root[0] == '/')
        return resolved_path[0] == '/';
    return strncmp(resolved_path, root, n) == 0 && (resolved_path[n] == '/' || resolved_path[n] == '\0');
}

/* [REL-READ-1] STATUS_OK when path may be read under f's confinement,
 * else STATUS_DATA with the reason (or STATUS_NO_MEMORY). */
static int may_read(scene_file_reader *f, const char *name, const char *path, char *why, size_t why_size)
{
    int oom = 0, unresolved = 0;
    if (f->anywhere)
        return STATUS_OK;
    if (!f->roots) {
        /* Nobody chose where this reader may read: it reads nothing. */
        snprintf(why, why_size, "cannot read '%s': this load may read no files (no directory was given to it)",
                 name);
        return STATUS_DATA;
    }
    char *resolved_path = real_or_parent(&f->mem, path, &oom, &unresolved);
    if (unresolved) {
        snprintf(why, why_size, "cannot read '%s': its real path cannot be found (%s), so it cannot be judged "
                 "inside the directories this load may read", name, strerror(unresolved));
        return STATUS_DATA;
    }
    if (oom || !resolved_path) {
        /* Neither it nor its directory exists: reading it fails anyway. */
        mem_free_string(&f->mem, resolved_path);
        return oom ? STATUS_NO_MEMORY : STATUS_OK;
    }
    int ok = 0;
    for (int i = 0; i < f->root_count && !ok; i++)
        ok = within(resolved_path, f->roots[i]);
    if (!ok)
        snprintf(why, why_size, "cannot read '%s': its real path '%s' is outside the directories this load may "
                 "read (the scene's own, '%s', and %d given with --allow-read); allow another with --allow-read DIR",
                 name, resolved_path, f->root_count > 0 ? f->roots[0] : "?", f->root_count > 0 ? f->root_count - 1 : 0);
    mem_free_string(&f->mem, resolved_path);
    return ok ? STATUS_OK : STATUS_DATA;
}

static int fetch(void *user, const char *from, const char *name, scene_source *out, char *why, size_t why_size)
{
    scene_file_reader *f = user;
    int accept_known = out->known;
    out->known = 0;
    char *dir = file_dirname(&f->mem, from);
    char *path = dir ? file_join(&f->mem, dir, name) : NULL, *text = NULL;
    mem_free_string(&f->mem, dir);
    if (!path)
        return STATUS_NO_MEMORY;
    out->path = path;
    if (!(out->identity = identity_of(&f->mem, path))) {
        release(f, out);
        return STATUS_NO_MEMORY;
    }
    if (accept_known && name_index_find(&f->index, out->identity) >= 0) {
        out->known = 1;
        return STATUS_OK;
    }
    size_t len = 0;
    int status = may_read(f, name, path, why, why_size);
    if (status != STATUS_OK) {
        release(f, out);
        return status;
    }
    status = file_read_all(path, f->max_bytes, &f->mem, &text, &len, why, why_size);
    out->text = text;
    out->len = len;
    if (status == STATUS_OK && accept_known && !remember(f, out->identity))
        status = STATUS_NO_MEMORY;
    if (status != STATUS_OK)
        release(f, out);
    return status;
}

scene_resolver scene_file_resolver(scene_file_reader *files)
{
    scene_resolver r = {fetch, release, files};
    return r;
}

/* A message without location through the load's sink, escaped as every
 * record is ([REL-ESCAPE-1]). */
static void report(const scene_load_opts *o, const char *message)
{
    diag_record r;
    char shown[1024];
    text_escape(message, strlen(message), shown, sizeof shown);
    memset(&r, 0, sizeof r);
    r.level = DIAG_ERROR;
    r.message = shown;
    if (o->sink)
        o->sink(o->sink_user, &r);
}

int scene_file_is_json(const char *path)
{
    static const char ext[] = ".json";
    size_t n = strlen(path), k = sizeof ext - 1;
    if (n < k)
        return 0;
    for (size_t i = 0; i < k; i++)
        if (tolower((unsigned char)path[n - k + i]) != ext[i])
            return 0;
    return 1;
}

scene_model *scene_file_load_source(const scene_source *root, const scene_load_opts *o, int *status)
{
    if (scene_file_is_json(root->path))
        return scene_load_json_source(root, o, status);
    return scene_load_source(root, o, status);
}

/* Loads the root text under path (its identity: its real path). */
static scene_model *load_root(const char *path, const char *text, size_t len, const scene_load_opts *o,
                              const mem *m, int *status)
{
    scene_source root = {path, identity_of(m, path), text, len, 0};
    scene_model *s = NULL;
    if (root.identity)
        s = scene_file_load_source(&root, o, status);
    else
        *status = STATUS_NO_MEMORY;
    mem_free_string(m, (char *)root.identity);
    return s;
}

static scene_model *load_file(const char *path, const scene_load_opts *o, int anywhere,
                              const char *const *read_dirs, int *status);

scene_model *scene_file_load_with(const char *path, const scene_load_opts *o, int *status)
{
    return load_file(path, o, 0, NULL, status);
}

scene_model *scene_file_load_confined(const char *path, const scene_load_opts *o, const char *const *read_dirs,
                                      int *status)
{
    return load_file(path, o, 0, read_dirs, status);
}

scene_model *scene_file_load_anywhere(const char *path, const scene_load_opts *o, int *status)
{
    return load_file(path, o, 1, NULL, status);
}

/* The body of the file loads: f confined to path's tree and read_dirs',
 * or reading anywhere. */
static scene_model *load_file(const char *path, const scene_load_opts *o, int anywhere,
                              const char *const *read_dirs, int *status)
{
    scene_load_opts opts;
    if (o)
        opts = *o;
    else
        scene_load_opts_init(&opts);
    scene_file_reader files;
    mem m = mem_pick(&opts.mem);
    scene_file_reader_init(&files, opts.limits.max_file_bytes, &m);
    if (!opts.resolver.fetch)
        opts.resolver = scene_file_resolver(&files);
    char why[512], *text = NULL;
    size_t len = 0;
    scene_model *s = NULL;
    *status = STATUS_OK;
    if (anywhere)
        scene_file_reader_anywhere(&files);
    else
        *status = scene_file_reader_confine(&files, path, read_dirs);
    if (*status == STATUS_OK)
        *status = file_read_all(path, opts.limits.max_file_bytes, &m, &text, &len, why, sizeof why);
    else
        snprintf(why, sizeof why, "out of memory");
    if (*status != STATUS_OK)
        report(&opts, why);
    else {
        /* The root is delivered too: an include of it is known (a cycle). */
        char *identity = identity_of(&m, path);
        if (!identity || !remember(&files, identity))
            *status = STATUS_NO_MEMORY;
        mem_free_string(&m, identity);
        if (*status == STATUS_OK)
            s = load_root(path, text, len, &opts, &m, status);
        mem_free(&m, text, len + 1);
    }
    scene_file_reader_free(&files);
    return s;
}

static void short_opts(scene_load_opts *o, const scene_limits *limits, FILE *diag_out, int warnings)
{
    scene_load_opts_init(o);
    if (limits)
        o->limits = *limits;
    o->warnings = warnings;
    o->sink = diag_out ? diag_print : NULL;
    o->sink_user = diag_out;
}

scene_model *scene_file_load(const char *path, const scene_limits *limits, FILE *diag_out, int warnings,
                             int *status)
{
    scene_load_opts o;
    short_opts(&o, limits, diag_out, warnings);
    return scene_file_load_with(path, &o, status);
}

scene_model *scene_file_load_text(const char *path, const char *text, size_t len, const scene_limits *limits,
                                  FILE *diag_out, int warnings, int *status)
{
    return scene_file_load_text_confined(path, text, len, limits, diag_out, warnings, NULL, status);
}

scene_model *scene_file_load_text_confined(const char *path, const char *text, size_t len,
                                           const scene_limits *limits, FILE *diag_out, int warnings,
                                           const char *const *read_dirs, int *status)
{
    scene_load_opts o;
    short_opts(&o, limits, diag_out, warnings);
    scene_file_reader files;
    scene_file_reader_init(&files, o.limits.max_file_bytes, &o.mem);
    o.resolver = scene_file_resolver(&files);
    scene_model *s = NULL;
    *status = scene_file_reader_confine(&files, path, read_dirs);
    if (*status == STATUS_OK)
        s = load_root(path, text, len, &o, &files.mem, status);
    scene_file_reader_free(&files);
    return s;
}
