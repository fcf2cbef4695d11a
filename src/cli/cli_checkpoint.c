/*
 * cli_checkpoint.c - the checkpoint directory of refray render
 * --checkpoint DIR (spec/scaling.md, [SCALE-RESUME-1..3]): a manifest,
 * DIR/refray-checkpoint, five text lines
 *     refray-checkpoint 1
 *     image W H
 *     region X0 Y0 X1 Y1
 *     key 16-HEX-DIGITS
 *     bands N
 * and one PFM tile per finished band, DIR/tile-NNNNN.pfm with its sidecar
 * (io/tile_file.h), written atomically when the band is done.  A tile is
 * there whole or not at all, so whatever stopped the render, the tiles in
 * DIR are finished ones; they are ordinary tiles that refray merge reads.
 */
#include <dirent.h>
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "base/status.h"
#include "cli/cli_args.h"
#include "cli/cli_checkpoint.h"
#include "io/atomic.h"
#include "io/fileio.h"
#include "io/filewrite.h"
#include "io/tile_file.h"

static const char manifest_name[] = "refray-checkpoint";

typedef struct ck_manifest {
    tile_info info;
    int bands;
} ck_manifest;

/* DIR/name into buf. */
static const char *in_dir(const cli_tiles *t, const char *name, char *buf, size_t size)
{
    snprintf(buf, size, "%s/%s", t->checkpoint, name);
    return buf;
}

static const char *tile_path(const cli_tiles *t, int b, char *buf, size_t size)
{
    char name[32];
    snprintf(name, sizeof name, "tile-%05d.pfm", b);
    return in_dir(t, name, buf, size);
}

/* 1 when name is one the checkpoint writes, by exact name: the manifest,
 * or the tile of a band below `bands` or its sidecar ([SCALE-RESUME-4]).
 * Nothing else in DIR is touched, whatever its name. */
static int own_name(const char *name, int bands)
{
    char want[48];
    if (strcmp(name, manifest_name) == 0)
        return 1;
    if (strncmp(name, "tile-", 5) != 0 || !isdigit((unsigned char)name[5]))
        return 0;
    long b = strtol(name + 5, NULL, 10);
    if (b < 0 || b >= bands)
        return 0;
    snprintf(want, sizeof want, "tile-%05ld.pfm", b);
    size_t n = strlen(want);
    return strncmp(name, want, n) == 0 && (name[n] == '\0' || strcmp(name + n, ".tile") == 0);
}

/* 1 when path names the same directory as t->checkpoint. */
static int in_checkpoint_dir(const cli_tiles *t, const char *path)
{
    struct stat a, b;
    const char *slash = strrchr(path, '/');
    char dir[4096];
    if (!slash)
        snprintf(dir, sizeof dir, ".");
    else
        snprintf(dir, sizeof dir, "%.*s", slash == path ? 1 : (int)(slash - path), path);
    return stat(dir, &a) == 0 && stat(t->checkpoint, &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

/* The output must not be a file the checkpoint writes and removes
 * ([SCALE-RESUME-4]): refused before anything is rendered. */
static int check_output(const cli_tiles *t)
{
    if (!t->output || strcmp(t->output, "-") == 0 || !in_checkpoint_dir(t, t->output))
        return STATUS_OK;
    const char *slash = strrchr(t->output, '/'), *name = slash ? slash + 1 : t->output;
    if (!own_name(name, INT_MAX) && file_temp_owner(name) < 0)
        return STATUS_OK;
    cli_error("the output '%s' is a name the checkpoint '%s' writes and removes (its manifest, its tiles "
              "tile-NNNNN.pfm and their sidecars): name the output otherwise or give another directory",
              t->output, t->checkpoint);
    return STATUS_USAGE;
}

/* A new checkpoint (no manifest yet) in a directory that already holds a
 * file named as one of its tiles: that file is someone else's, and the
 * checkpoint would read it and, at the end, remove it. */
static int check_fresh(const cli_tiles *t)
{
    char path[4096];
    for (int b = 0; b < t->bands; b++) {
        for (int side = 0; side < 2; side++) {
            char name[40];
            snprintf(name, sizeof name, "tile-%05d.pfm%s", b, side ? ".tile" : "");
            in_dir(t, name, path, sizeof path);
            if (access(path, F_OK) == 0) {
                cli_error("the directory '%s' holds '%s', a name the checkpoint writes, but no checkpoint "
                          "manifest (spec/scaling.md): give another directory to --checkpoint",
                          t->checkpoint, path);
                return STATUS_DATA;
            }
        }
    }
    return STATUS_OK;
}

static int write_manifest(const cli_tiles *t, const char *path)
{
    char text[256], key[17], why[600];
    const tile_rect *r = &t->target.region;
    tile_key_text(t->target.key, key);
    int n = snprintf(text, sizeof text, "refray-checkpoint 1\nimage %d %d\nregion %d %d %d %d\nkey %s\nbands %d\n",
                     t->target.width, t->target.height, r->x0, r->y0, r->x1, r->y1, key, t->bands);
    int rc = file_write_bytes(path, text, (size_t)n, why, sizeof why);
    if (rc != STATUS_OK)
        cli_error("checkpoint: %s", why);
    return rc;
}

/* 1 when text is exactly a manifest, into *m. */
static int parse_manifest(const char *text, ck_manifest *m)
{
    char key[17];
    int n = -1;
    tile_rect *r = &m->info.region;
    if (sscanf(text, "refray-checkpoint 1 image %d %d region %d %d %d %d key %16[0-9a-f] bands %d%n",
               &m->info.width, &m->info.height, &r->x0, &r->y0, &r->x1, &r->y1, key, &m->bands, &n) != 8 ||
        n < 0 || strspn(text + n, "\n") != strlen(text + n))
        return 0;
    return tile_key_parse(key, &m->info.key);
}

static void describe(const tile_info *t, char *buf, size_t size)
{
    char key[17], where[64];
    tile_key_text(t->key, key);
    snprintf(buf, size, "a %dx%d image, %s, key %s", t->width, t->height,
             tile_rect_text(&t->region, where, sizeof where), key);
}

/* Reads the manifest at path into t->bands, checking it is t's render. */
static int check_manifest(cli_tiles *t, const char *path, const char *text)
{
    ck_manifest m;
    char theirs[160], ours[160];
    int rows = t->target.region.y1 - t->target.region.y0;
    if (!parse_manifest(text, &m) || m.bands < 1 || m.bands > rows) {
        cli_error("'%s' is not a refray checkpoint manifest (spec/scaling.md); give "
                "another directory to --checkpoint", path);
        return STATUS_DATA;
    }
    if (!tile_info_equal(&m.info, &t->target)) {
        describe(&m.info, theirs, sizeof theirs);
        describe(&t->target, ours, sizeof ours);
        cli_error("the checkpoint '%s' belongs to another render (%s), not this one (%s): "
                "another scene, size, region or setting; remove it or give another directory",
                t->checkpoint, theirs, ours);
        return STATUS_DATA;
    }
    t->bands = m.bands;
    return STATUS_OK;
}

/* Loads band b's tile when the checkpoint has it. */
static int load_tile(cli_tiles *t, int b, unsigned char *done)
{
    char path[4096], why[600];
    tile_info info;
    img_buf px;
    int rc = tile_file_read(tile_path(t, b, path, sizeof path), &t->read, &info, &px, why, sizeof why);
    if (rc == STATUS_NO_INPUT)
        return STATUS_OK;
    if (rc != STATUS_OK) {
        cli_note("", "warning: checkpoint: %s; rendering that tile again", why);
        return STATUS_OK;
    }
    tile_info want = t->target;
    want.region = cli_tiles_band(t, b);
    if (!tile_info_equal(&info, &want)) {
        cli_error("the checkpoint tile '%s' is not band %d of this render; remove the "
                "checkpoint '%s' or give another directory", path, b, t->checkpoint);
        img_free(&px);
        return STATUS_DATA;
    }
    size_t w = 3 * (size_t)(t->target.region.x1 - t->target.region.x0);
    memcpy(t->pixels + (size_t)(want.region.y0 - t->target.region.y0) * w, px.rgb,
           w * (size_t)px.height * sizeof(double));
    img_free(&px);
    done[b] = 1;
    return STATUS_OK;
}

int cli_checkpoint_open(cli_tiles *t, unsigned char *done)
{
    char path[4096], why[600], *text = NULL;
    size_t len = 0;
    int rc = check_output(t);
    if (rc != STATUS_OK)
        return rc;
    if ((rc = file_make_dirs(t->checkpoint, why, sizeof why)) != STATUS_OK) {
        cli_error("checkpoint: %s", why);
        return rc;
    }
    in_dir(t, manifest_name, path, sizeof path);
    rc = file_read_all(path, 4096, NULL, &text, &len, why, sizeof why);
    if (rc == STATUS_NO_INPUT && access(path, F_OK) != 0)
        return (rc = check_fresh(t)) != STATUS_OK ? rc : write_manifest(t, path);
    if (rc == STATUS_OK)
        rc = check_manifest(t, path, text);
    else if (rc == STATUS_DATA)
        rc = check_manifest(t, path, "");
    else
        cli_error("checkpoint: %s", why);
    mem_free(NULL, text, len + 1);
    for (int b = 0; rc == STATUS_OK && b < t->bands; b++)
        rc = load_tile(t, b, done);
    return rc;
}

int cli_checkpoint_save(const cli_tiles *t, int b, char *why, size_t why_size)
{
    char path[4096], reason[600];
    tile_info info = t->target;
    info.region = cli_tiles_band(t, b);
    size_t w = 3 * (size_t)(info.region.x1 - info.region.x0);
    img_buf view;
    memset(&view, 0, sizeof view);
    view.width = info.region.x1 - info.region.x0;
    view.height = info.region.y1 - info.region.y0;
    view.rgb = t->pixels + (size_t)(info.region.y0 - t->target.region.y0) * w;
    int rc = tile_file_write(tile_path(t, b, path, sizeof path), &info, &view, NULL, reason, sizeof reason);
    if (rc != STATUS_OK)
        snprintf(why, why_size, "cannot save a tile into the checkpoint: %s", reason);
    return rc;
}

/* The manifest, a tile of one of the t's bands or its sidecar, by exact
 * name, or the temporary of a write cut short (io/atomic.h's name, which
 * no other program writes): a worker killed while it wrote a tile, whose
 * process is gone. */
static int ours(const cli_tiles *t, const char *name)
{
    long pid = file_temp_owner(name);
    if (pid > 0)
        return pid == (long)getpid() || (kill((pid_t)pid, 0) != 0 && errno == ESRCH);
    return own_name(name, t->bands);
}

void cli_tiles_checkpoint_clear(const cli_tiles *t)
{
    char path[4096];
    DIR *d = opendir(t->checkpoint);
    for (struct dirent *e; d && (e = readdir(d)) != NULL;)
        if (ours(t, e->d_name))
            unlink(in_dir(t, e->d_name, path, sizeof path));
    if (d)
        closedir(d);
    rmdir(t->checkpoint);
}
