/*
 * image_pfm.c - the two formats that need no library.
 *
 * PFM (Portable Float Map, as written by HDRShop and read by most HDR
 * tools): a text header "PF\n<width> <height>\n<scale>\n", then raw 32-bit
 * floats, R G B per pixel, rows from the BOTTOM of the image to the top.
 * A negative scale means little-endian floats, a positive one big-endian;
 * its magnitude is a scale factor readers conventionally ignore.  We write
 * "-1.0" and explicit little-endian bytes whatever the host.  "Pf" is the
 * one-channel variant.
 *
 * PPM (Netpbm P6): "P6\n<width> <height>\n<maxval>\n", then one byte per
 * sample when maxval < 256, else two big-endian bytes, rows from the top.
 * We write maxval 255 with the same display mapping as an 8-bit PNG.
 *
 * In both headers the tokens are separated by white space (and '#'
 * comments in PPM, which we also accept in PFM), and exactly one white
 * character separates the last token from the raster in PPM.  A PFM's
 * raster is its last bytes, found from the file's size, with nothing
 * between the header and them but the LF of a CR LF (raster_fits).
 */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "image/codec.h"
#include "image/tonemap.h"

static int write_failed(char *err, size_t errlen)
{
    return img_error(err, errlen, STATUS_IO, "write error: %s", strerror(errno));
}

/* A short fread is either an I/O error or a file that ends too soon. */
static int read_failed(FILE *fp, char *err, size_t errlen)
{
    if (ferror(fp))
        return img_error(err, errlen, STATUS_IO, "read error: %s", strerror(errno));
    return img_error(err, errlen, STATUS_DATA, "file is truncated (the pixel data ends early)");
}

static int is_white(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

/* The next header token into buf: skips white space and '#' comments,
 * then takes the non-white characters.  The white character that ends the
 * token is consumed: after the last token that is the raster separator.
 * Returns 0, or -1 at end of file or for a token that does not fit. */
static int read_token(FILE *fp, char *buf, size_t size)
{
    int c = fgetc(fp);
    for (;;) {
        while (is_white(c))
            c = fgetc(fp);
        if (c != '#')
            break;
        while (c != EOF && c != '\n')
            c = fgetc(fp);
    }
    size_t n = 0;
    for (; c != EOF && !is_white(c); c = fgetc(fp)) {
        if (n + 1 >= size)
            return -1;
        buf[n++] = (char)c;
    }
    buf[n] = '\0';
    return n > 0 ? 0 : -1;
}

/* A whole decimal token in [lo, hi], or -1. */
static long parse_long(const char *s, long lo, long hi)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (end == s || *end || errno || v < lo || v > hi)
        return -1;
    return v;
}

/* Width and height tokens, checked against o (img_check_header). */
static int read_size(FILE *fp, const img_read_opts *o, int *w, int *h, char *err, size_t errlen)
{
    char a[24], b[24];
    long wl = read_token(fp, a, sizeof a) ? -1 : parse_long(a, 1, INT_MAX);
    long hl = wl < 0 || read_token(fp, b, sizeof b) ? -1 : parse_long(b, 1, INT_MAX);
    if (wl < 0 || hl < 0)
        return img_error(err, errlen, STATUS_DATA, "bad width or height in the header");
    int rc = img_check_header(wl, hl, o, err, errlen);
    *w = (int)wl;
    *h = (int)hl;
    return rc;
}

/* After the header: the size alone (o->header_only), or the pixels' room. */
static int make_target(const img_read_opts *o, int w, int h, img_buf *out, char *err, size_t errlen)
{
    if (o->header_only) {
        out->width = w;
        out->height = h;
        return STATUS_OK;
    }
    int rc = img_create(out, w, h);
    return rc == STATUS_OK ? rc : img_error(err, errlen, rc, "out of memory");
}

/* The raster's bytes, rows x bytes_per_row, fit in what the file holds
 * after the header: a header of 16384 x 16384 on a 1 KB file must not
 * allocate gigabytes before the first row comes up short.  A stream that
 * cannot seek (a pipe) is read as it comes.
 *
 * With `last` (PFM, [IMG-PFM-1]) the raster is the file's last bytes:
 * between the header's separator and them there may be only the LF of a
 * CR LF (a text-mode writer's header); anything else there is a file whose
 * size does not fit its header, refused rather than read some bytes off. */
static int raster_fits(FILE *fp, int rows, size_t bytes_per_row, int last, char *err, size_t errlen)
{
    long here = ftell(fp);
    if (here < 0 || fseek(fp, 0, SEEK_END) != 0) {
        clearerr(fp);
        return STATUS_OK;
    }
    long end = ftell(fp);
    if (fseek(fp, here, SEEK_SET) != 0)
        return img_error(err, errlen, STATUS_IO, "cannot seek back in the file: %s", strerror(errno));
    if (end >= here && (size_t)(end - here) / bytes_per_row < (size_t)rows)
        return img_error(err, errlen, STATUS_DATA, "file is truncated (the pixel data ends early)");
    if (!last || end < here)
        return STATUS_OK;
    size_t extra = (size_t)(end - here) - (size_t)rows * bytes_per_row;
    if (extra == 0)
        return STATUS_OK;
    /* Only the LF of a CR LF line end: the separator read must be the CR.
     * Any other white space would let a file one byte too long whose first
     * pixel byte happens to be a white-space value be read one byte off. */
    int sep = EOF, c = EOF;
    if (extra == 1 && here > 0 && fseek(fp, here - 1, SEEK_SET) == 0) {
        sep = fgetc(fp);
        c = sep == EOF ? EOF : fgetc(fp);
        if (c == EOF)
            return read_failed(fp, err, errlen);
    }
    if (sep == '\r' && c == '\n')
        return STATUS_OK;
    return img_error(err, errlen, STATUS_DATA, "the file is %zu byte%s longer than its header and the %d rows of %zu "
                     "bytes of pixel data it announces, and they are not the LF of a CR LF ending the header "
                     "(bytes after the pixels, or a wrong size)", extra, extra == 1 ? "" : "s", rows,
                     bytes_per_row);
}

/* ---- PFM ---- */

static void put_le32(unsigned char *p, uint32_t u)
{
    p[0] = (unsigned char)(u & 0xFF);
    p[1] = (unsigned char)((u >> 8) & 0xFF);
    p[2] = (unsigned char)((u >> 16) & 0xFF);
    p[3] = (unsigned char)((u >> 24) & 0xFF);
}

static uint32_t get32(const unsigned char *p, int little)
{
    if (little)
        return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
    return (uint32_t)p[3] | (uint32_t)p[2] << 8 | (uint32_t)p[1] << 16 | (uint32_t)p[0] << 24;
}

/* Image row y as little-endian floats, sanitised and range-clamped. */
static void pack_float_row(unsigned char *out, const img_buf *img, int y, img_write_stats *st)
{
    const double *p = img_pixel(img, 0, y);
    for (size_t i = 0; i < 3 * (size_t)img->width; i++) {
        int clamped;
        float f = img_float_from_double(img_sanitize(p[i], st), &clamped);
        uint32_t bits;
        memcpy(&bits, &f, sizeof bits);
        put_le32(out + 4 * i, bits);
        st->clamped += (size_t)clamped;
    }
}

int img_pfm_write(FILE *fp, const img_buf *img, const img_write_opts *o, img_write_stats *st,
                  char *err, size_t errlen)
{
    /* PFM stores linear values: of o, only cancel applies. */
    size_t rowlen = 12 * (size_t)img->width;
    unsigned char *row = malloc(rowlen);
    if (!row)
        return img_error(err, errlen, STATUS_NO_MEMORY, "out of memory");
    int rc = STATUS_OK;
    if (fprintf(fp, "PF\n%d %d\n-1.0\n", img->width, img->height) < 0)
        rc = write_failed(err, errlen);
    for (int y = img->height - 1; rc == STATUS_OK && y >= 0; y--) {
        if (img_row_cancelled(o, img)) {
            rc = img_error(err, errlen, STATUS_CANCELLED, "interrupted");
            break;
        }
        pack_float_row(row, img, y, st);
        if (fwrite(row, 1, rowlen, fp) != rowlen)
            rc = write_failed(err, errlen);
    }
    free(row);
    return rc;
}

/* The scale token: finite and non-zero; its sign gives the byte order. */
static int read_pfm_scale(FILE *fp, int *little, char *err, size_t errlen)
{
    char s[64] = "", *end = s;
    double scale = read_token(fp, s, sizeof s) ? 0.0 : strtod(s, &end);
    if (scale == 0.0 || !isfinite(scale) || *end)
        return img_error(err, errlen, STATUS_DATA, "bad scale in the PFM header");
    *little = scale < 0;
    return STATUS_OK;
}

/* Reads the file row that is image row y; nch floats per pixel. */
static int read_pfm_row(FILE *fp, img_buf *out, int y, int nch, int little, unsigned char *buf,
                        char *err, size_t errlen)
{
    size_t rowlen = 4 * (size_t)nch * (size_t)out->width;
    if (fread(buf, 1, rowlen, fp) != rowlen)
        return read_failed(fp, err, errlen);
    double *p = img_pixel(out, 0, y);
    for (int x = 0; x < out->width; x++)
        for (int c = 0; c < 3; c++) {
            uint32_t bits = get32(buf + 4 * ((size_t)x * (size_t)nch + (nch == 3 ? (size_t)c : 0)), little);
            float f;
            memcpy(&f, &bits, sizeof f);
            p[3 * x + c] = f;
        }
    return STATUS_OK;
}

int img_pfm_read(FILE *fp, const img_read_opts *o, img_buf *out, char *err, size_t errlen)
{
    char magic[4];
    int w = 0, h = 0, little = 1;
    if (read_token(fp, magic, sizeof magic) || (strcmp(magic, "PF") && strcmp(magic, "Pf")))
        return img_error(err, errlen, STATUS_DATA, "not a PFM file (it does not start with PF or Pf)");
    int nch = magic[1] == 'F' ? 3 : 1;
    int rc = read_size(fp, o, &w, &h, err, errlen);
    if (rc == STATUS_OK)
        rc = read_pfm_scale(fp, &little, err, errlen);
    if (rc == STATUS_OK)
        rc = o->header_only ? STATUS_OK : raster_fits(fp, h, 4 * (size_t)nch * (size_t)w, 1, err, errlen);
    if (rc == STATUS_OK)
        rc = make_target(o, w, h, out, err, errlen);
    if (rc != STATUS_OK || o->header_only)
        return rc;
    unsigned char *buf = malloc(4 * (size_t)nch * (size_t)w);
    if (rc == STATUS_OK && !buf)
        rc = img_error(err, errlen, STATUS_NO_MEMORY, "out of memory");
    for (int y = h - 1; rc == STATUS_OK && y >= 0; y--)
        rc = read_pfm_row(fp, out, y, nch, little, buf, err, errlen);
    free(buf);
    return rc;
}

/* ---- PPM ---- */

int img_ppm_write(FILE *fp, const img_buf *img, const img_write_opts *o, img_write_stats *st,
                  char *err, size_t errlen)
{
    size_t rowlen = 3 * (size_t)img->width;
    unsigned char *row = malloc(rowlen);
    if (!row)
        return img_error(err, errlen, STATUS_NO_MEMORY, "out of memory");
    int rc = STATUS_OK;
    if (fprintf(fp, "P6\n%d %d\n255\n", img->width, img->height) < 0)
        rc = write_failed(err, errlen);
    for (int y = 0; rc == STATUS_OK && y < img->height; y++) {
        if (img_row_cancelled(o, img)) {
            rc = img_error(err, errlen, STATUS_CANCELLED, "interrupted");
            break;
        }
        const double *p = img_pixel(img, 0, y);
        for (size_t i = 0; i < rowlen; i++)
            row[i] = (unsigned char)tonemap_quantize(img_display_value(img_sanitize(p[i], st), o), 255);
        if (fwrite(row, 1, rowlen, fp) != rowlen)
            rc = write_failed(err, errlen);
    }
    free(row);
    return rc;
}

/* Reads image row y of samples of nb bytes each (1 or 2, big-endian). */
static int read_ppm_row(FILE *fp, img_buf *out, int y, long maxval, unsigned char *buf,
                        char *err, size_t errlen)
{
    size_t nb = maxval < 256 ? 1 : 2, n = 3 * (size_t)out->width;
    if (fread(buf, nb, n, fp) != n)
        return read_failed(fp, err, errlen);
    double *p = img_pixel(out, 0, y);
    for (size_t i = 0; i < n; i++) {
        long code = nb == 1 ? buf[i] : (long)buf[2 * i] << 8 | buf[2 * i + 1];
        if (code > maxval)
            return img_error(err, errlen, STATUS_DATA, "sample %ld exceeds maxval %ld", code, maxval);
        p[i] = tonemap_srgb_decode((double)code / (double)maxval);
    }
    return STATUS_OK;
}

int img_ppm_read(FILE *fp, const img_read_opts *o, img_buf *out, char *err, size_t errlen)
{
    char magic[4], m[16];
    int w = 0, h = 0;
    if (read_token(fp, magic, sizeof magic) || strcmp(magic, "P6"))
        return img_error(err, errlen, STATUS_DATA, "not a binary PPM file (it does not start with P6)");
    int rc = read_size(fp, o, &w, &h, err, errlen);
    long maxval = rc != STATUS_OK || read_token(fp, m, sizeof m) ? -1 : parse_long(m, 1, 65535);
    if (rc == STATUS_OK && maxval < 0)
        rc = img_error(err, errlen, STATUS_DATA, "bad maxval in the PPM header (1 to 65535)");
    if (rc == STATUS_OK)
        rc = o->header_only ? STATUS_OK : raster_fits(fp, h, (maxval < 256 ? 3 : 6) * (size_t)w, 0, err, errlen);
    if (rc == STATUS_OK)
        rc = make_target(o, w, h, out, err, errlen);
    if (rc != STATUS_OK || o->header_only)
        return rc;
    unsigned char *buf = malloc(6 * (size_t)w);
    if (rc == STATUS_OK && !buf)
        rc = img_error(err, errlen, STATUS_NO_MEMORY, "out of memory");
    for (int y = 0; rc == STATUS_OK && y < h; y++)
        rc = read_ppm_row(fp, out, y, maxval, buf, err, errlen);
    free(buf);
    return rc;
}
