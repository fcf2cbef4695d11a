/*
 * image_io.h - image files: written through the atomic writer (io/atomic.h)
 * and read through file_open_read (io/fileio.h), encoded and decoded by
 * image/image_file.h.
 */
#ifndef REFRAY_IMAGE_IO_H
#define REFRAY_IMAGE_IO_H

#include "image/image_file.h"

/* Checks everything a write of a width x height image in path's format
 * can check before the image exists: the format (STATUS_USAGE) and the
 * path (file_write_check: STATUS_IO).  STATUS_OK, or the status with the
 * reason naming path in err. */
int img_write_check(const char *path, char *err, size_t errlen);

/* Writes img to path, format by extension, atomically (io/atomic.h): the
 * new file, or nothing, is at path afterwards.  o may be NULL for the
 * defaults; o->cancel is asked per row and before the rename.  Returns 0;
 * STATUS_USAGE for an unknown extension, a format this build lacks or bad
 * options; STATUS_INTERNAL for an invalid image; STATUS_IO when the path
 * is refused or the file cannot be created, written or renamed;
 * STATUS_NO_MEMORY; STATUS_CANCELLED; with the reason naming path in err. */
int img_write(const char *path, const img_buf *img, const img_write_opts *o, char *err, size_t errlen);

/* Reads path (format by extension) into *out as img_read_stream does with
 * o (NULL: the defaults).  Returns as img_read_stream, and STATUS_NO_INPUT
 * when path is missing, unreadable, a directory or not a regular file (a
 * FIFO is never waited on); err names path. */
int img_read(const char *path, const img_read_opts *o, img_buf *out, char *err, size_t errlen);

/* The size in path's header, nothing decoded (o->header_only). */
int img_read_size(const char *path, const img_read_opts *o, int *width, int *height, char *err, size_t errlen);

#endif
