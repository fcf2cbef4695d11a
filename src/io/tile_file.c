/*
 * tile_file.c - see tile_file.h.
 */
#include <errno.h>
#include <float.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "base/hash.h"
#include "image/image_file.h"
#include "io/fileio.h"
#include "io/image_io.h"
#include "io/filewrite.h"
#include "io/tile_file.h"

static const char sidecar_suffix[] = ".tile";

int tile_file_format_ok(const char *path, char *why, size_t why_size)
{
    img_format f = img_format_from_path(path);
    if (f == IMG_FORMAT_EXR && !img_format_available(f)) {
        snprintf(why, why_size, "this refray was built without OpenEXR (EXR=0): write .pfm tiles");
        return 0;
    }
    if (f == IMG_FORMAT_EXR || f == IMG_FORMAT_PFM)
        return 1;
    /* A glob such as tiles/tile-* lists each tile's sidecar beside it: name
     * it as what it is, not as a picture format it is not. */
    size_t n = strlen(path), k = sizeof sidecar_suffix - 1;
    if (n > k && strcmp(path + n - k, sidecar_suffix) == 0) {
        snprintf(why, why_size, "'%.4096s' is the sidecar of the tile named without its '.tile': give the tile, "
                 "whose sidecar is read beside it", path);
        return 0;
    }
    if (f == IMG_FORMAT_PNG || f == IMG_FORMAT_PPM)
        snprintf(why, why_size, "a tile is .exr or .pfm, not '%s': PNG and PPM hold display codes, not the "
                 "linear values a merge needs", path);
    else
        snprintf(why, why_size, "a tile is .exr or .pfm, not '%s'", path);
    return 0;
}

/* path + ".tile" in a buffer of ours, or NULL when out of memory. */
static char *sidecar_of(const char *path)
{
    size_t n = strlen(path) + sizeof sidecar_suffix;
    char *s = malloc(n);
    if (s)
        snprintf(s, n, "%s%s", path, sidecar_suffix);
    return s;
}

/* ---- Writing ---- */

typedef struct tile_fill {
    const tile_info *t;
    const img_buf *px;
    const img_write_opts *o;
    char why[400];
} tile_fill;

static int fill_exr(FILE *fp, void *ctx)
{
    tile_fill *f = ctx;
    return img_write_exr_tile(fp, f->t, f->px, f->o, f->why, sizeof f->why);
}

static void put_le64(unsigned char *p, uint64_t v)
{
    for (int i = 0; i < 8; i++)
        p[i] = (unsigned char)(v >> (8 * i));
}

/* The FNV-1a hash of the n values as the sidecar holds them (little-endian
 * doubles): one changed byte always changes it, since each step of FNV-1a
 * is a bijection of the state. */
static uint64_t pixels_check(const double *v, size_t n)
{
    uint64_t h = HASH_FNV_START, bits;
    for (size_t i = 0; i < n; i++) {
        memcpy(&bits, &v[i], sizeof bits);
        h = hash_u64(h, bits);
    }
    return h;
}

static int fill_sidecar(FILE *fp, void *ctx)
{
    tile_fill *f = ctx;
    const tile_rect *r = &f->t->region;
    char key[17], check[17];
    size_t n = 3 * (size_t)f->px->width * (size_t)f->px->height;
    tile_key_text(f->t->key, key);
    tile_key_text(pixels_check(f->px->rgb, n), check);
    if (fprintf(fp, "refray-tile 2\nimage %d %d\nregion %d %d %d %d\nkey %s\npixels f64le fnv1a64 %s\n",
                f->t->width, f->t->height, r->x0, r->y0, r->x1, r->y1, key, check) < 0)
        return STATUS_IO;
    unsigned char b[8];
    for (size_t i = 0; i < n; i++) {
        uint64_t bits;
        memcpy(&bits, &f->px->rgb[i], sizeof bits);
        put_le64(b, bits);
        if (fwrite(b, 1, sizeof b, fp) != sizeof b)
            return STATUS_IO;
    }
    return STATUS_OK;
}

int tile_file_write(const char *path, const tile_info *t, const img_buf *px, const img_write_opts *o, char *why,
                    size_t why_size)
{
    tile_fill f = {t, px, o, ""};
    char reason[400];
    int rc;
    if (!tile_file_format_ok(path, reason, sizeof reason)) {
        snprintf(why, why_size, "%s", reason);
        return STATUS_USAGE;
    }
    if (img_format_from_path(path) == IMG_FORMAT_EXR) {
        rc = file_write_atomic(path, fill_exr, &f, why, why_size);
        if (rc != STATUS_OK && f.why[0])
            snprintf(why, why_size, "cannot write '%s': %s", path, f.why);
        return rc;
    }
    if ((rc = img_write(path, px, o, why, why_size)) != STATUS_OK)
        return rc;
    char *side = sidecar_of(path);
    if (!side) {
        snprintf(why, why_size, "out of memory");
        return STATUS_NO_MEMORY;
    }
    rc = file_write_atomic(side, fill_sidecar, &f, why, why_size);
    free(side);
    return rc;
}

/* ---- Reading ---- */

static int read_error(char *why, size_t why_size, int code, const char *path, const char *what)
{
    snprintf(why, why_size, "cannot read '%s': %s", path, what);
    return code;
}

/* The five header lines into *t and the pixels' checksum into *check: 1
 * when they are exactly the format's, -1 for the first layout (no
 * checksum), 0 for anything else. */
static int parse_header(FILE *fp, tile_info *t, uint64_t *check)
{
    char line[5][128], key[17];
    int n = -1;
    tile_rect *r = &t->region;
    for (int i = 0; i < 5; i++)
        if (!fgets(line[i], sizeof line[i], fp))
            return i > 0 && strcmp(line[0], "refray-tile 1\n") == 0 ? -1 : 0;
    if (strcmp(line[0], "refray-tile 1\n") == 0)
        return -1;
    if (strcmp(line[0], "refray-tile 2\n") != 0 ||
        sscanf(line[4], "pixels f64le fnv1a64 %16[0-9a-f]%n", key, &n) != 1 || strcmp(line[4] + n, "\n") != 0 ||
        !tile_key_parse(key, check))
        return 0;
    n = -1;
    if (sscanf(line[1], "image %d %d%n", &t->width, &t->height, &n) != 2 || strcmp(line[1] + n, "\n") != 0)
        return 0;
    n = -1;
    if (sscanf(line[2], "region %d %d %d %d%n", &r->x0, &r->y0, &r->x1, &r->y1, &n) != 4 ||
        strcmp(line[2] + n, "\n") != 0)
        return 0;
    n = -1;
    if (sscanf(line[3], "key %16[0-9a-f]%n", key, &n) != 1 || strcmp(line[3] + n, "\n") != 0)
        return 0;
    return tile_key_parse(key, &t->key);
}

static uint64_t get_le64(const unsigned char *p)
{
    uint64_t v = 0;
    for (int i = 7; i >= 0; i--)
        v = v << 8 | p[i];
    return v;
}

/* The region's doubles after the header, into a new *px. */
static int read_doubles(FILE *fp, const char *path, const tile_info *t, uint64_t check, img_buf *px, char *why,
                        size_t why_size)
{
    uint64_t h = HASH_FNV_START;
    const tile_rect *r = &t->region;
    int rc = img_create(px, r->x1 - r->x0, r->y1 - r->y0);
    if (rc != STATUS_OK)
        return read_error(why, why_size, rc, path, "out of memory");
    size_t row = 3 * (size_t)px->width;
    unsigned char *buf = malloc(8 * row);
    if (!buf)
        rc = read_error(why, why_size, STATUS_NO_MEMORY, path, "out of memory");
    for (int y = 0; rc == STATUS_OK && y < px->height; y++) {
        if (fread(buf, 8, row, fp) != row) {
            rc = read_error(why, why_size, ferror(fp) ? STATUS_IO : STATUS_DATA, path,
                            ferror(fp) ? strerror(errno) : "the tile's pixels end early");
            break;
        }
        h = hash_bytes(h, buf, 8 * row);
        for (size_t i = 0; rc == STATUS_OK && i < row; i++) {
            uint64_t bits = get_le64(buf + 8 * i);
            double *v = img_pixel(px, 0, y) + i;
            memcpy(v, &bits, sizeof bits);
            /* A render writes finite, non-negative values only (a non-finite
             * radiance is counted and written as 0): anything else is a
             * damaged file, which must not reach a merged image. */
            if (!(*v >= 0 && *v <= DBL_MAX)) {
                char what[160];
                snprintf(what, sizeof what, "pixel (%d, %d) of the tile holds %.17g, a value no render writes "
                         "(damaged)", r->x0 + (int)(i / 3), r->y0 + y, *v);
                rc = read_error(why, why_size, STATUS_DATA, path, what);
            }
        }
    }
    /* After the value checks, which name a pixel: a changed byte that
     * still reads as a value a render writes is caught here. */
    if (rc == STATUS_OK && h != check)
        rc = read_error(why, why_size, STATUS_DATA, path, "its pixels do not match their checksum (a byte was "
                        "changed: damaged)");
    free(buf);
    if (rc != STATUS_OK)
        img_free(px);
    return rc;
}

/* The sidecar's header, its length checked against the file's. */
static int read_sidecar(FILE *fp, const char *path, const img_read_opts *o, tile_info *t, img_buf *px, char *why,
                        size_t why_size)
{
    char reason[200];
    struct stat sb;
    uint64_t check = 0;
    int layout = parse_header(fp, t, &check);
    if (layout < 0)
        return read_error(why, why_size, STATUS_DATA, path, "a sidecar of the first layout (refray-tile 1), "
                          "without the checksum of its pixels this refray checks: render the tile again");
    if (layout == 0)
        return read_error(why, why_size, STATUS_DATA, path, "not a refray tile sidecar (its header is not "
                          "the five lines of spec/scaling.md)");
    if (img_check_header(t->width, t->height, o, reason, sizeof reason) != STATUS_OK ||
        !tile_info_valid(t, img_max_pixels(o), reason, sizeof reason))
        return read_error(why, why_size, STATUS_DATA, path, reason);
    long header = ftell(fp);
    double want = (double)header + 24.0 * (double)tile_area(&t->region);
    if (header < 0 || fstat(fileno(fp), &sb) != 0 || (double)sb.st_size != want)
        return read_error(why, why_size, STATUS_DATA, path, "its length does not match its region (damaged or "
                          "cut short)");
    return px ? read_doubles(fp, path, t, check, px, why, why_size) : STATUS_OK;
}

int tile_file_read(const char *path, const img_read_opts *o, tile_info *t, img_buf *px, char *why, size_t why_size)
{
    char reason[400];
    int rc;
    if (px)
        memset(px, 0, sizeof *px);
    if (!tile_file_format_ok(path, reason, sizeof reason)) {
        snprintf(why, why_size, "%s", reason);
        return STATUS_USAGE;
    }
    int exr = img_format_from_path(path) == IMG_FORMAT_EXR;
    char *name = exr ? NULL : sidecar_of(path);
    const char *open_path = exr ? path : name;
    if (!open_path)
        return read_error(why, why_size, STATUS_NO_MEMORY, path, "out of memory");
    /* A PFM tile's pixels are in its sidecar, but a missing PFM itself is
     * what to say first. */
    int e = 0, pfm_there = exr || access(path, F_OK) == 0, open_status = STATUS_OK;
    FILE *fp = NULL;
    /* file_fopen_read: a FIFO or a directory is refused, not waited on
     * ([REL-FILE-1]); errno stays 0 when the open itself succeeded. */
    if (!pfm_there)
        e = errno;
    else if ((errno = 0) == 0 && !(fp = file_fopen_read(open_path, &open_status, reason, sizeof reason)))
        e = errno;
    if (!fp) {
        int missing = !pfm_there || e == ENOENT || e == EACCES || (e == 0 && open_status == STATUS_NO_INPUT);
        if (pfm_there && !exr && e == ENOENT)
            snprintf(reason, sizeof reason, "its sidecar '%s' is missing (a PFM tile needs it)", open_path);
        else if (!pfm_there || e != 0)
            snprintf(reason, sizeof reason, "%s", strerror(e));
        rc = read_error(why, why_size, missing ? STATUS_NO_INPUT : STATUS_IO, path, reason);
    } else if (exr) {
        rc = img_read_exr_tile(fp, o, t, px, reason, sizeof reason);
        if (rc != STATUS_OK)
            read_error(why, why_size, rc, path, reason);
    } else {
        rc = read_sidecar(fp, open_path, o, t, px, why, why_size);
    }
    if (fp)
        fclose(fp);
    free(name);
    return rc;
}

int tile_file_remove(const char *path)
{
    char *side = sidecar_of(path);
    int bad = unlink(path) != 0 && errno != ENOENT;
    if (side)
        bad |= unlink(side) != 0 && errno != ENOENT;
    free(side);
    return bad || !side ? -1 : 0;
}
