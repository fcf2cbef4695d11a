/*
 * image.c - the frame buffer, dispatch by extension, the atomic write, and
 * the number conversions every writer shares (half, float, display value).
 *
 * Invariant: a back end is only ever called with a valid image (width and
 * height >= 1, pixels present) and valid options; image.c checks both,
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
#include "image/tonemap.h"

#ifndef REFRAY_HAVE_PNG
#define REFRAY_HAVE_PNG 0
#endif
#ifndef REFRAY_HAVE_EXR
#define REFRAY_HAVE_EXR 0
#endif

/* Room for a back end's reason before the file name is put in front. */
#define REASON_MAX 512

int img_error(char *err, size_t errlen, int code, const char *fmt, ...)
{
    if (err && errlen > 0) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err, errlen, fmt, ap);
        va_end(ap);
    }
    return code;
}

int img_create(rf_image *img, int width, int height)
{
    img->width = img->height = 0;
    img->rgb = NULL;
    if (width < 1 || height < 1 || (size_t)width > SIZE_MAX / 3 / sizeof(double) / (size_t)height)
        return IMG_ESOFTWARE;
    img->rgb = calloc((size_t)width * (size_t)height * 3, sizeof(double));
    if (!img->rgb)
        return IMG_EOSERR;
    img->width = width;
    img->height = height;
    return IMG_OK;
}

void img_free(rf_image *img)
{
    if (!img)
        return;
    free(img->rgb);
    img->rgb = NULL;
    img->width = img->height = 0;
}

img_write_opts img_write_opts_default(void)
{
    img_write_opts o;
    o.exposure_stops = 0.0;
    o.tone = IMG_TONE_CLAMP;
    o.linear_png = 0;
    o.png_bits = 8;
    o.exr_float = 0;
    o.stats = NULL;
    return o;
}

/* ---- Number conversions ---- */

double img_sanitize(double v, img_write_stats *st)
{
    if (isfinite(v))
        return v;
    st->nonfinite++;
    return 0.0;
}

/* x rounded to the nearest integer, ties to the even one, for 0 <= x <
 * 2^52 (so floor(x) and the comparisons are exact); independent of the
 * floating-point rounding mode. */
static double round_half_even(double x)
{
    double f = floor(x);
    double r = x - f;
    if (r > 0.5 || (r == 0.5 && fmod(f, 2.0) != 0.0))
        return f + 1.0;
    return f;
}

/* binary16: 1 sign bit, 5 exponent bits (bias 15), 10 fraction bits.
 *   subnormal  |v| = m * 2^-24,                 m in [0, 1023], exponent field 0
 *   normal     |v| = (1024 + m) * 2^(E - 10),   E in [-14, 15], field E + 15
 * In both ranges the code is (field << 10) + m, and a rounded m of 1024
 * carries into the exponent field, which is exactly the next binade.  The
 * largest finite half is 65504 = 2047 * 2^5; the halfway point to the next
 * step, 65520, ties to the even neighbour 65536 = infinity, so every
 * |v| >= 65520 would overflow. */
uint16_t img_half_from_double(double v, int *clamped)
{
    if (clamped)
        *clamped = 0;
    if (isnan(v))
        return 0;
    uint16_t sign = signbit(v) ? 0x8000u : 0u;
    double a = fabs(v);
    if (a >= 65520.0) {
        if (clamped)
            *clamped = 1;
        return (uint16_t)(sign | 0x7BFFu);
    }
    if (a < 0x1p-14)
        return (uint16_t)(sign | (uint16_t)round_half_even(a * 0x1p24));
    int e;
    frexp(a, &e); /* a = f * 2^e, f in [0.5, 1): E = e - 1 */
    double m = round_half_even(ldexp(a, 11 - e) - 1024.0);
    return (uint16_t)(sign | (((unsigned)(e - 1 + 15) << 10) + (unsigned)m));
}

/* FLT_MAX = (2 - 2^-23) * 2^127; half an ulp above it, (2 - 2^-24) * 2^127,
 * is the tie that rounds to even, i.e. to 2^128 = infinity. */
#define FLOAT_OVERFLOW_EDGE ((2.0 - 0x1p-24) * 0x1p127)

float img_float_from_double(double v, int *clamped)
{
    if (clamped)
        *clamped = 0;
    if (isnan(v))
        return 0.0f;
    if (fabs(v) >= FLOAT_OVERFLOW_EDGE) {
        if (clamped)
            *clamped = 1;
        return signbit(v) ? -FLT_MAX : FLT_MAX;
    }
    return (float)v;
}

double img_display_value(double v, const img_write_opts *o)
{
    v = tonemap_exposure(v, o->exposure_stops);
    v = o->tone == IMG_TONE_REINHARD ? tonemap_reinhard(v) : tonemap_clamp(v);
    v = tonemap_clamp(v);
    return o->linear_png ? v : tonemap_srgb_encode(v);
}

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
        return img_error(why, len, IMG_EUSAGE,
                         "no file extension to choose the format by (supported: %s)",
                         supported_list);
    if (fmt == IMG_FORMAT_UNKNOWN && !ext)
        return img_error(why, len, IMG_EUSAGE, "unknown image format (supported: %s)",
                         supported_list);
    if (fmt == IMG_FORMAT_UNKNOWN)
        return img_error(why, len, IMG_EUSAGE, "unknown image format '%s' (supported: %s)", ext,
                         supported_list);
    if (img_format_available(fmt))
        return IMG_OK;
    if (fmt == IMG_FORMAT_EXR)
        return img_error(why, len, IMG_EUSAGE, "this refray was built without OpenEXR (EXR=0); %s",
                         writing ? "write .pfm instead" : "cannot read .exr files");
    return img_error(why, len, IMG_EUSAGE, "this refray was built without libpng (PNG=0); %s",
                     writing ? "write .ppm instead" : "cannot read .png files");
}

static int check_image(const rf_image *img, char *why, size_t len)
{
    if (!img || !img->rgb || img->width < 1 || img->height < 1)
        return img_error(why, len, IMG_ESOFTWARE, "invalid image (%dx%d%s)", img ? img->width : 0,
                         img ? img->height : 0, img && !img->rgb ? ", no pixels" : "");
    return IMG_OK;
}

static int check_opts(const img_write_opts *o, char *why, size_t len)
{
    if (o->png_bits != 8 && o->png_bits != 16)
        return img_error(why, len, IMG_EUSAGE, "PNG bit depth must be 8 or 16, not %d", o->png_bits);
    if (o->tone != IMG_TONE_CLAMP && o->tone != IMG_TONE_REINHARD)
        return img_error(why, len, IMG_EUSAGE, "unknown tone mapping %d", o->tone);
    if (!isfinite(o->exposure_stops))
        return img_error(why, len, IMG_EUSAGE, "exposure must be a finite number of stops");
    return IMG_OK;
}

/* Every check that can fail before a byte is written. */
static int check_write(const char *path, img_format fmt, const rf_image *img,
                       const img_write_opts *o, char *why, size_t len)
{
    int rc = check_format(path, fmt, 1, why, len);
    if (rc == IMG_OK)
        rc = check_image(img, why, len);
    if (rc == IMG_OK)
        rc = check_opts(o, why, len);
    return rc;
}

static int encode(FILE *fp, img_format fmt, const rf_image *img, const img_write_opts *o,
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
    default: return img_error(why, len, IMG_ESOFTWARE, "no encoder for this format");
    }
}

/* The stream checks are here, not only in the back ends, because stdio
 * buffers: a full disk usually shows only when the buffer is flushed. */
int img_write_stream(FILE *fp, img_format fmt, const rf_image *img, const img_write_opts *o,
                     char *err, size_t errlen)
{
    img_write_opts defaults = img_write_opts_default();
    img_write_stats st = {0, 0};
    if (!o)
        o = &defaults;
    int rc = check_write(NULL, fmt, img, o, err, errlen);
    if (rc != IMG_OK)
        return rc;
    rc = encode(fp, fmt, img, o, &st, err, errlen);
    if (rc == IMG_OK && fflush(fp) != 0)
        rc = img_error(err, errlen, IMG_EIO, "write error: %s", strerror(errno));
    else if (rc == IMG_OK && ferror(fp))
        rc = img_error(err, errlen, IMG_EIO, "write error");
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
        return img_error(why, len, IMG_EIO, "cannot set the file mode: %s", strerror(errno));
    return IMG_OK;
}

/* Encodes into the open temporary file fd and closes it, checking the
 * flush, the fsync and the close. */
static int fill_temp(int fd, const char *path, img_format fmt, const rf_image *img,
                     const img_write_opts *o, char *why, size_t len)
{
    int rc = set_final_mode(fd, path, why, len);
    FILE *fp = rc == IMG_OK ? fdopen(fd, "wb") : NULL;
    if (!fp) {
        if (rc == IMG_OK)
            rc = img_error(why, len, IMG_EIO, "cannot open a stream: %s", strerror(errno));
        close(fd);
        return rc;
    }
    rc = img_write_stream(fp, fmt, img, o, why, len);
    if (rc == IMG_OK && fsync(fileno(fp)) != 0)
        rc = img_error(why, len, IMG_EIO, "write error: %s", strerror(errno));
    if (fclose(fp) != 0 && rc == IMG_OK)
        rc = img_error(why, len, IMG_EIO, "write error: %s", strerror(errno));
    return rc;
}

static int write_atomically(const char *path, img_format fmt, const rf_image *img,
                            const img_write_opts *o, char *why, size_t len)
{
    /* The rename would replace a device, a FIFO or a directory entry that
     * is not a plain file (as root even /dev/full): refuse instead. */
    struct stat sb;
    if (stat(path, &sb) == 0 && !S_ISREG(sb.st_mode))
        return img_error(why, len, IMG_EIO, "it exists and is not a regular file");
    static const char suffix[] = ".tmp.XXXXXX";
    size_t n = strlen(path) + sizeof suffix;
    char *tmp = malloc(n);
    if (!tmp)
        return img_error(why, len, IMG_EOSERR, "out of memory");
    snprintf(tmp, n, "%s%s", path, suffix);
    int fd = mkstemp(tmp);
    int rc = IMG_OK;
    if (fd < 0)
        rc = img_error(why, len, IMG_EIO, "cannot create a temporary file: %s", strerror(errno));
    else
        rc = fill_temp(fd, path, fmt, img, o, why, len);
    if (fd >= 0 && rc == IMG_OK && rename(tmp, path) != 0)
        rc = img_error(why, len, IMG_EIO, "cannot rename the temporary file into place: %s",
                       strerror(errno));
    if (fd >= 0 && rc != IMG_OK)
        unlink(tmp);
    free(tmp);
    return rc;
}

int img_write(const char *path, const rf_image *img, const img_write_opts *o, char *err,
              size_t errlen)
{
    char why[REASON_MAX];
    img_write_opts defaults = img_write_opts_default();
    if (!o)
        o = &defaults;
    img_format fmt = img_format_from_path(path);
    int rc = check_write(path, fmt, img, o, why, sizeof why);
    if (rc == IMG_OK)
        rc = write_atomically(path, fmt, img, o, why, sizeof why);
    if (rc != IMG_OK)
        img_error(err, errlen, rc, "cannot write '%s': %s", path ? path : "(null)", why);
    return rc;
}

/* ---- Reading ---- */

static int decode(FILE *fp, img_format fmt, rf_image *out, char *why, size_t len)
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
    default: return img_error(why, len, IMG_ESOFTWARE, "no decoder for this format");
    }
}

int img_read(const char *path, rf_image *out, char *err, size_t errlen)
{
    char why[REASON_MAX];
    FILE *fp = NULL;
    out->width = out->height = 0;
    out->rgb = NULL;
    img_format fmt = img_format_from_path(path);
    int rc = check_format(path, fmt, 0, why, sizeof why);
    if (rc == IMG_OK && !(fp = fopen(path, "rb")))
        rc = img_error(why, sizeof why, IMG_ENOINPUT, "%s", strerror(errno));
    if (rc == IMG_OK)
        rc = decode(fp, fmt, out, why, sizeof why);
    if (fp)
        fclose(fp);
    if (rc != IMG_OK) {
        img_free(out);
        img_error(err, errlen, rc, "cannot read '%s': %s", path ? path : "(null)", why);
    }
    return rc;
}
