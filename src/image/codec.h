/*
 * codec.h - the format back ends, called by image_file.c only.
 */
#ifndef REFRAY_CODEC_H
#define REFRAY_CODEC_H

#include <stdio.h>
#include "image/image.h"
#include "image/tile.h"

/* Each writer encodes a valid image (checked by the caller) to fp and
 * checks its own writes, asking o->cancel once per row; the caller
 * flushes.  Each reader checks the header with img_check_header(o) before
 * it allocates anything for the pixels, then fills *out (only its size
 * with o->header_only) or leaves it empty.  Both return the codes of
 * img_write / img_read, with a reason in err that does not name the file. */
int img_png_write(FILE *fp, const img_buf *img, const img_write_opts *o, img_write_stats *st,
                  char *err, size_t errlen);
int img_png_read(FILE *fp, const img_read_opts *o, img_buf *out, char *err, size_t errlen);
int img_exr_write(FILE *fp, const img_buf *img, const img_write_opts *o, img_write_stats *st,
                  char *err, size_t errlen);
int img_exr_read(FILE *fp, const img_read_opts *o, img_buf *out, char *err, size_t errlen);
int img_exr_write_tile(FILE *fp, const tile_info *t, const img_buf *img, const img_write_opts *o,
                       img_write_stats *st, char *err, size_t errlen);
int img_exr_read_tile(FILE *fp, const img_read_opts *o, tile_info *t, img_buf *out, char *err, size_t errlen);
int img_pfm_write(FILE *fp, const img_buf *img, const img_write_opts *o, img_write_stats *st,
                  char *err, size_t errlen);
int img_pfm_read(FILE *fp, const img_read_opts *o, img_buf *out, char *err, size_t errlen);
int img_ppm_write(FILE *fp, const img_buf *img, const img_write_opts *o, img_write_stats *st,
                  char *err, size_t errlen);
int img_ppm_read(FILE *fp, const img_read_opts *o, img_buf *out, char *err, size_t errlen);

#endif
