/*
 * image_file.c - image streams: formats by extension, encoding to and
 * decoding from an open stream (files themselves: io/image_io.c).
 *
 * Invariant: a back end is only ever called with a valid image (width and
 * height >= 1, pixels present) and valid options; this file checks both,
 * and checks that the format is compiled in, before any file is created.
 */
#include <errno.h>
#include <math.h>
#include <string.h>
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

int img_check_write(img_format fmt, const img_buf *img, const img_write_opts *o, char *err, size_t errlen)
{
    img_write_opts defaults = img_write_opts_default();
    return check_write(NULL, fmt, img, o ? o : &defaults, err, errlen);
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

/* ---- Reading ---- */

static int decode(FILE *fp, img_format fmt, const img_read_opts *o, img_buf *out, char *why, size_t len)
{
    switch (fmt) {
#if REFRAY_HAVE_PNG
    case IMG_FORMAT_PNG: return img_png_read(fp, o, out, why, len);
#endif
#if REFRAY_HAVE_EXR
    case IMG_FORMAT_EXR: return img_exr_read(fp, o, out, why, len);
#endif
    case IMG_FORMAT_PFM: return img_pfm_read(fp, o, out, why, len);
    case IMG_FORMAT_PPM: return img_ppm_read(fp, o, out, why, len);
    default: return img_error(why, len, STATUS_INTERNAL, "no decoder for this format");
    }
}

int img_read_stream(FILE *fp, img_format fmt, const img_read_opts *o, img_buf *out, char *err, size_t errlen)
{
    img_read_opts defaults = img_read_opts_default();
    memset(out, 0, sizeof *out);
    int rc = check_format(NULL, fmt, 0, err, errlen);
    if (rc == STATUS_OK)
        rc = decode(fp, fmt, o ? o : &defaults, out, err, errlen);
    if (rc != STATUS_OK)
        img_free(out);
    return rc;
}

int img_check_format(const char *path, int writing, char *err, size_t errlen)
{
    return check_format(path, img_format_from_path(path), writing, err, errlen);
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

int img_read_exr_tile(FILE *fp, const img_read_opts *o, tile_info *t, img_buf *img, char *err, size_t errlen)
{
    int rc = check_format(NULL, IMG_FORMAT_EXR, 0, err, errlen);
    if (img)
        memset(img, 0, sizeof *img);
#if REFRAY_HAVE_EXR
    if (rc == STATUS_OK)
        rc = img_exr_read_tile(fp, o, t, img, err, errlen);
#else
    (void)fp;
    (void)o;
    (void)t;
#endif
    if (rc != STATUS_OK && img)
        img_free(img);
    return rc;
}
