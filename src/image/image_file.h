/*
 * image_file.h - image formats: PNG, OpenEXR, PFM, PPM, chosen by the file
 * name's extension, encoded to and decoded from open streams (the writers'
 * contract: image.h; files: io/image_io.h).
 */
#ifndef REFRAY_IMAGE_FILE_H
#define REFRAY_IMAGE_FILE_H

#include <stdio.h>
#include "image/image.h"
#include "image/tile.h"

typedef enum img_format {
    IMG_FORMAT_UNKNOWN = 0,
    IMG_FORMAT_PNG,
    IMG_FORMAT_EXR,
    IMG_FORMAT_PFM,
    IMG_FORMAT_PPM
} img_format;

/* The format named by path's extension (.png .exr .pfm .ppm, any case), or
 * IMG_FORMAT_UNKNOWN. */
img_format img_format_from_path(const char *path);

/* 1 if this build can write and read fmt (PNG needs PNG=1, EXR needs EXR=1). */
int img_format_available(img_format fmt);

/* Every check of img_write_stream that needs no stream: the format is
 * known and compiled in, the image valid (width, height >= 1, pixels),
 * the options in range.  STATUS_OK, STATUS_USAGE, STATUS_INTERNAL. */
int img_check_write(img_format fmt, const img_buf *img, const img_write_opts *o, char *err, size_t errlen);

/* STATUS_OK when path's extension names a format this build can read
 * (writing 0) or write (1); else STATUS_USAGE with the reason. */
int img_check_format(const char *path, int writing, char *err, size_t errlen);

/* Encodes img in format fmt to an open stream, which is flushed but not
 * closed; the caller owns atomicity (io/image_io.h writes files).  o may
 * be NULL for the defaults.  An EXR to a stream that cannot seek is built
 * in memory first.  Returns 0; STATUS_USAGE for a format this build lacks
 * or bad options; STATUS_INTERNAL for an invalid image; STATUS_IO;
 * STATUS_NO_MEMORY; STATUS_CANCELLED (o->cancel); err holds the reason
 * without a file name. */
int img_write_stream(FILE *fp, img_format fmt, const img_buf *img, const img_write_opts *o,
                     char *err, size_t errlen);

/* Decodes the image in fp (format fmt) into *out, which the caller frees
 * with img_free; o (NULL: img_read_opts_default) is checked against the
 * header before the pixels are decoded.  Values are returned as stored,
 * non-finite ones included:
 *   .exr  the R, G and B channels of the first part (scanline files),
 *         half/float/uint converted to double;
 *   .pfm  PF (RGB) or Pf (grey, copied to R, G, B), either byte order;
 *   .png  any bit depth and colour type, alpha discarded, codes made
 *         linear: an sRGB chunk, or no colour information at all, means
 *         the sRGB curve; a gAMA of 1.0 means linear; another gAMA g means
 *         code^(1/g) (the PNG specification's rule);
 *   .ppm  binary P6, maxval up to 65535, decoded as sRGB (PPM cannot say
 *         otherwise; a PPM written with linear_png reads back wrong).
 * Returns 0; STATUS_USAGE for an unknown or compiled-out format;
 * STATUS_DATA for a malformed or unsupported file or a size o refuses;
 * STATUS_IO for a read error; STATUS_NO_MEMORY when out of memory.  On
 * failure *out is empty (no pixels). */
int img_read_stream(FILE *fp, img_format fmt, const img_read_opts *o, img_buf *out, char *err, size_t errlen);

/*
 * Tiles in OpenEXR (image/tile.h, spec/scaling.md [TILE-FILE-1]): the
 * display window is t's whole image, the data window its region, whose
 * pixels img holds (region-sized).  R, G, B are written as img_write
 * writes them with o; the channels f64hi.R .. f64lo.B hold each value's
 * double exactly; the attributes refrayKey and refrayTile hold the key and
 * the layout's version.  To fp, which must be seekable; returns as
 * img_write_stream, STATUS_USAGE in a build without OpenEXR.
 */
int img_write_exr_tile(FILE *fp, const tile_info *t, const img_buf *img, const img_write_opts *o, char *err,
                       size_t errlen);

/* Reads an OpenEXR tile from fp into *t, and, unless img is NULL, the
 * region's exact doubles into *img (the caller frees it).  The whole
 * image's size is held to o->max_pixels (o NULL: the default) before any
 * pixel is decoded.  Returns as img_read; STATUS_DATA for a file that is
 * not a refray tile or is over the limit. */
int img_read_exr_tile(FILE *fp, const img_read_opts *o, tile_info *t, img_buf *img, char *err, size_t errlen);

#endif
