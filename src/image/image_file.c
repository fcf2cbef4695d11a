/*
 * image_file.c - image files: dispatch by extension, the atomic write, and
 * reading.
 *
 * Invariant: a back end is only ever called with a valid image (width and
 * height >= 1, pixels present) and valid options; this file checks both,
 * and checks that the format is compiled in, before any file is created.
 */
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "image/image.h"
#include "image/codec.h"
#include "image/image_file.h"

#ifndef REFRAY_HAVE_PNG
#define REFRAY_HAVE_PNG 0
#endif
#ifndef REFRAY_HAVE_EXR
#define REFRAY_HAVE_EXR 0
#endif

/* Room for a back end's reason before the file name is put in front. */
#define REASON_MAX 512

/* ---- Formats ---- */

static const char supported_list[] =
#if REFRAY_HAVE_PNG
    ".png "
#endif
#if REFRAY_HAVE_EXR
    ".exr "
#endif
    ".pfm .ppm";

/* ASCII case-insensitive equality; locale-independent on purpose. */
static int same_ignoring_case(const char *a, const char *b)
{
    for (; *a && *b; a++, b++) {
        char x = (*a >= 'A' && *a <= 'Z') ? (char)(*a - 'A' + 'a') : *a;
        char y = (*b >= 'A' && *b <= 'Z') ? (char)(*b - 'A' + 'a') : *b;
        if (x != y)
            return 0;
    }
    return *a == *b;
}

/* The extension of path's last component including the dot, or NULL. */
static const char *extension_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash + 1 : path, '.');
    return dot;
}

img_format img_format_from_path(const char *path)
{
    static const struct { const char *ext; img_format fmt; } table[] = {
        {".png", IMG_FORMAT_PNG}, {".exr", IMG_FORMAT_EXR},
        {".pfm", IMG_FORMAT_PFM}, {".ppm", IMG_FORMAT_PPM},
    };
    const char *ext = path ? extension_of(path) : NULL;
    for (size_t i = 0; ext && i < sizeof table / sizeof table[0]; i++)
        if (same_ignoring_case(ext, table[i].ext))
            return table[i].fmt;
    return IMG_FORMAT_UNKNOWN;
}

int img_format_available(img_format fmt)
{
    switch (fmt) {
    case IMG_FORMAT_PNG: return REFRAY_HAVE_PNG;
    case IMG_FORMAT_EXR: return REFRAY_HAVE_EXR;
    case IMG_FORMAT_PFM:
    case IMG_FORMAT_PPM: return 1;
    default: return 0;
    }
}

/* Why fmt (from path) cannot be used by this build, or 0 if it can. */
static int check_format(const char *path, img_format fmt, int writing, char *why, size_t len)
{
    const char *ext = path ? extension_of(path) : NULL;
    if (fmt == IMG_FORMAT_UNKNOWN && path && !ext)
        return img_error(why, len, STATUS_USAGE,
                         "no file extension to choose the format by (supported: %s)",
                         supported_list);
    if (fmt == IMG_FORMAT_UNKNOWN && !ext)
        return img_error(why, len, STATUS_USAGE, "unknown image format (supported: %s)",
                         supported_list);
    if (fmt == IMG_FORMAT_UNKNOWN)
        return img_error(why, len, STATUS_USAGE, "unknown image format '%s' (supported: %s)", ext,
                         supported_list);
    if (img_format_available(fmt))
        return STATUS_OK;
    if (fmt == IMG_FORMAT_EXR)
        return img_error(why, len, STATUS_USAGE, "this refray was built without OpenEXR (EXR=0); %s",
                         writing ? "write .pfm instead" : "cannot read .exr files");
    return img_error(why, len, STATUS_USAGE, "this refray was built without libpng (PNG=0); %s",
                     writing ? "write .ppm instead" : "cannot read .png files");
}

static int check_image(const img_buf *img, char *why, size_t len)
{
    if (!img || !img->rgb || img->width < 1 || img->height < 1)
        return img_error(why, len, STATUS_INTERNAL, "invalid image (%dx%d%s)", img ? img->width : 0,
                         img ? img->height : 0, img && !img->rgb ? ", no pixels" : "");
    return STATUS_OK;
}

static int check_opts(const img_write_opts *o, char *why, size_t len)
{
    if (o->png_bits != 8 && o->png_bits != 16)
        return img_error(why, len, STATUS_USAGE, "PNG bit depth must be 8 or 16, not %d", o->png_bits);
    if (o->tone != IMG_TONE_CLAMP && o->tone != IMG_TONE_REINHARD)
        return img_error(why, len, STATUS_USAGE, "unknown tone mapping %d", o->tone);
    if (!isfinite(o->exposure_stops))
        return img_error(why, len, STATUS_USAGE, "exposure must be a finite number of stops");
    return STATUS_OK;
}

/* Every check that can fail before a byte is written. */
static int check_write(const char *path, img_format fmt, const img_buf *img,
                       const img_write_opts *o, char *why, size_t len)
{
    int rc = check_format(path, fmt, 1, why, len);
    if (rc == STATUS_OK)
        rc = check_image(img, why, len);
    if (rc == STATUS_OK)
        rc = check_opts(o, why, len);
    return rc;
}

static int encode(FILE *fp, img_format fmt, const img_buf *img, const img_write_opts *o,
                  img_write_stats *st, char *why, size_t len)
{
    switch (fmt) {
#if REFRAY_HAVE_PNG
    case IMG_FORMAT_PNG: return img_png_write(fp, img, o, st, why, len);
#endif
#if REFRAY_HAVE_EXR
    case IMG_FORMAT_EXR: return img_exr_write(fp, img, o, st, why, len);
#endif
    case IMG_FORMAT_PFM: return img_pfm_write(fp, img, o, st, why, len);
    case IMG_FORMAT_PPM: return img_ppm_write(fp, img, o, st, why, len);
    default: return img_error(why, len, STATUS_INTERNAL, "no encoder for this format");
    }
}

/* The stream checks are here, not only in the back ends, because stdio
 * buffers: a full disk usually shows only when the buffer is flushed. */
int img_write_stream(FILE *fp, img_format fmt, const img_buf *img, const img_write_opts *o,
                     char *err, size_t errlen)
{
    img_write_opts defaults = img_write_opts_default();
    img_write_stats st = {0, 0};
    if (!o)
        o = &defaults;
    int rc = check_write(NULL, fmt, img, o, err, errlen);
    if (rc != STATUS_OK)
        return rc;
    rc = encode(fp, fmt, img, o, &st, err, errlen);
    if (rc == STATUS_OK && fflush(fp) != 0)
        rc = img_error(err, errlen, STATUS_IO, "write error: %s", strerror(errno));
    else if (rc == STATUS_OK && ferror(fp))
        rc = img_error(err, errlen, STATUS_IO, "write error");
    if (o->stats)
        *o->stats = st;
    return rc;
}

/* ---- The atomic write ---- */

/* 0666 less the umask.  Read where Linux publishes it: asking umask(2)
 * means setting it, a process-wide change other threads could see.
 * Elsewhere the common umask 022 is assumed. */
static mode_t new_file_mode(void)
{
    unsigned mask = 022;
    FILE *f = fopen("/proc/self/status", "r");
    char line[128];
    while (f && fgets(line, sizeof line, f))
        if (sscanf(line, "Umask: %o", &mask) == 1)
            break;
    if (f)
        fclose(f);
    return (mode_t)(0666 & ~mask);
}

/* mkstemp creates 0600; give the file the mode it would have had if we
 * had written path directly (keeping an existing file's mode). */
static int set_final_mode(int fd, const char *path, char *why, size_t len)
{
    struct stat sb;
    mode_t mode = stat(path, &sb) == 0 && S_ISREG(sb.st_mode) ? (sb.st_mode & 07777)
                                                              : new_file_mode();
    if (fchmod(fd, mode) != 0)
        return img_error(why, len, STATUS_IO, "cannot set the file mode: %s", strerror(errno));
    return STATUS_OK;
}

/* Encodes into the open temporary file fd and closes it, checking the
 * flush, the fsync and the close. */
static int fill_temp(int fd, const char *path, img_format fmt, const img_buf *img,
                     const img_write_opts *o, char *why, size_t len)
{
    int rc = set_final_mode(fd, path, why, len);
    FILE *fp = rc == STATUS_OK ? fdopen(fd, "wb") : NULL;
    if (!fp) {
        if (rc == STATUS_OK)
            rc = img_error(why, len, STATUS_IO, "cannot open a stream: %s", strerror(errno));
        close(fd);
        return rc;
    }
    rc = img_write_stream(fp, fmt, img, o, why, len);
    if (rc == STATUS_OK && fsync(fileno(fp)) != 0)
        rc = img_error(why, len, STATUS_IO, "write error: %s", strerror(errno));
    if (fclose(fp) != 0 && rc == STATUS_OK)
        rc = img_error(why, len, STATUS_IO, "write error: %s", strerror(errno));
    return rc;
}

static int write_atomically(const char *path, img_format fmt, const img_buf *img,
                            const img_write_opts *o, char *why, size_t len)
{
    /* The rename would replace a device, a FIFO or a directory entry that
     * is not a plain file (as root even /dev/full): refuse instead. */
    struct stat sb;
    if (stat(path, &sb) == 0 && !S_ISREG(sb.st_mode))
        return img_error(why, len, STATUS_IO, "it exists and is not a regular file");
    static const char suffix[] = ".tmp.XXXXXX";
    size_t n = strlen(path) + sizeof suffix;
    char *tmp = malloc(n);
    if (!tmp)
        return img_error(why, len, STATUS_NO_MEMORY, "out of memory");
    snprintf(tmp, n, "%s%s", path, suffix);
    int fd = mkstemp(tmp);
    int rc = STATUS_OK;
    if (fd < 0)
        rc = img_error(why, len, STATUS_IO, "cannot create a temporary file: %s", strerror(errno));
    else
        rc = fill_temp(fd, path, fmt, img, o, why, len);
    if (fd >= 0 && rc == STATUS_OK && rename(tmp, path) != 0)
        rc = img_error(why, len, STATUS_IO, "cannot rename the temporary file into place: %s",
                       strerror(errno));
    if (fd >= 0 && rc != STATUS_OK)
        unlink(tmp);
    free(tmp);
    return rc;
}

int img_write(const char *path, const img_buf *img, const img_write_opts *o, char *err,
              size_t errlen)
{
    char why[REASON_MAX];
    img_write_opts defaults = img_write_opts_default();
    if (!o)
        o = &defaults;
    img_format fmt = img_format_from_path(path);
    int rc = check_write(path, fmt, img, o, why, sizeof why);
    if (rc == STATUS_OK)
        rc = write_atomically(path, fmt, img, o, why, sizeof why);
    if (rc != STATUS_OK)
        img_error(err, errlen, rc, "cannot write '%s': %s", path ? path : "(null)", why);
    return rc;
}

/* ---- Reading ---- */

static int decode(FILE *fp, img_format fmt, img_buf *out, char *why, size_t len)
{
    switch (fmt) {
#if REFRAY_HAVE_PNG
    case IMG_FORMAT_PNG: return img_png_read(fp, out, why, len);
#endif
#if REFRAY_HAVE_EXR
    case IMG_FORMAT_EXR: return img_exr_read(fp, out, why, len);
#endif
    case IMG_FORMAT_PFM: return img_pfm_read(fp, out, why, len);
    case IMG_FORMAT_PPM: return img_ppm_read(fp, out, why, len);
    default: return img_error(why, len, STATUS_INTERNAL, "no decoder for this format");
    }
}

int img_read(const char *path, img_buf *out, char *err, size_t errlen)
{
    char why[REASON_MAX];
    FILE *fp = NULL;
    memset(out, 0, sizeof *out);
    img_format fmt = img_format_from_path(path);
    int rc = check_format(path, fmt, 0, why, sizeof why);
    if (rc == STATUS_OK && !(fp = fopen(path, "rb")))
        rc = img_error(why, sizeof why, STATUS_NO_INPUT, "%s", strerror(errno));
    if (rc == STATUS_OK)
        rc = decode(fp, fmt, out, why, sizeof why);
    if (fp)
        fclose(fp);
    if (rc != STATUS_OK) {
        img_free(out);
        img_error(err, errlen, rc, "cannot read '%s': %s", path ? path : "(null)", why);
    }
    return rc;
}

/* ---- Tiles ---- */

int img_write_exr_tile(FILE *fp, const tile_info *t, const img_buf *img, const img_write_opts *o, char *err,
                       size_t errlen)
{
    img_write_opts defaults = img_write_opts_default();
    img_write_stats st = {0, 0};
    int rc;
    if (!o)
        o = &defaults;
    if ((rc = check_write(NULL, IMG_FORMAT_EXR, img, o, err, errlen)) != STATUS_OK)
        return rc;
#if REFRAY_HAVE_EXR
    rc = img_exr_write_tile(fp, t, img, o, &st, err, errlen);
    if (rc == STATUS_OK && fflush(fp) != 0)
        rc = img_error(err, errlen, STATUS_IO, "write error: %s", strerror(errno));
#else
    (void)fp;
    (void)t;
    rc = img_error(err, errlen, STATUS_INTERNAL, "no OpenEXR");
#endif
    if (o->stats)
        *o->stats = st;
    return rc;
}

int img_read_exr_tile(FILE *fp, tile_info *t, img_buf *img, char *err, size_t errlen)
{
    int rc = check_format(NULL, IMG_FORMAT_EXR, 0, err, errlen);
    if (img)
        memset(img, 0, sizeof *img);
#if REFRAY_HAVE_EXR
    if (rc == STATUS_OK)
        rc = img_exr_read_tile(fp, t, img, err, errlen);
#else
    (void)fp;
    (void)t;
#endif
    if (rc != STATUS_OK && img)
        img_free(img);
    return rc;
}
