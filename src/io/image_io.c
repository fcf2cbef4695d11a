/*
 * image_io.c - image files (image_io.h).
 */
#include <string.h>
#include "base/status.h"
#include "io/atomic.h"
#include "io/fileio.h"
#include "io/image_io.h"

/* Room for a back end's reason before the file name is put in front. */
#define REASON_MAX 512

int img_write_check(const char *path, char *err, size_t errlen)
{
    char why[REASON_MAX];
    int rc = img_check_format(path, 1, why, sizeof why);
    if (rc != STATUS_OK)
        return img_error(err, errlen, rc, "cannot write '%s': %s", path, why);
    rc = file_write_check(path, NULL, why, sizeof why);
    return rc == STATUS_OK ? rc : img_error(err, errlen, rc, "%s", why);
}

int img_write(const char *path, const img_buf *img, const img_write_opts *o, char *err, size_t errlen)
{
    char why[REASON_MAX];
    img_write_opts defaults = img_write_opts_default();
    if (!o)
        o = &defaults;
    img_format fmt = img_format_from_path(path);
    int rc = img_check_format(path, 1, why, sizeof why);
    if (rc == STATUS_OK)
        rc = img_check_write(fmt, img, o, why, sizeof why);
    if (rc != STATUS_OK)
        return img_error(err, errlen, rc, "cannot write '%s': %s", path, why);
    file_out out;
    if ((rc = file_out_open(&out, path, o->cancel, why, sizeof why)) != STATUS_OK)
        return img_error(err, errlen, rc, "%s", why);
    if ((rc = img_write_stream(out.fp, fmt, img, o, why, sizeof why)) != STATUS_OK) {
        file_out_abort(&out);
        return img_error(err, errlen, rc, "cannot write '%s': %s", path, why);
    }
    rc = file_out_commit(&out, why, sizeof why);
    return rc == STATUS_OK ? rc : img_error(err, errlen, rc, "%s", why);
}

int img_read(const char *path, const img_read_opts *o, img_buf *out, char *err, size_t errlen)
{
    char why[REASON_MAX];
    int rc = img_check_format(path, 0, why, sizeof why);
    FILE *fp = NULL;
    memset(out, 0, sizeof *out);
    if (rc == STATUS_OK && !(fp = file_fopen_read(path, &rc, why, sizeof why)))
        return img_error(err, errlen, rc, "%s", why);
    if (rc == STATUS_OK)
        rc = img_read_stream(fp, img_format_from_path(path), o, out, why, sizeof why);
    if (fp)
        fclose(fp);
    return rc == STATUS_OK ? rc : img_error(err, errlen, rc, "cannot read '%s': %s", path, why);
}

int img_read_size(const char *path, const img_read_opts *o, int *width, int *height, char *err, size_t errlen)
{
    img_read_opts header = o ? *o : img_read_opts_default();
    img_buf size;
    header.header_only = 1;
    int rc = img_read(path, &header, &size, err, errlen);
    *width = rc == STATUS_OK ? size.width : 0;
    *height = rc == STATUS_OK ? size.height : 0;
    return rc;
}
