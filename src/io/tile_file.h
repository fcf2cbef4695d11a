/*
 * tile_file.h - tile files (image/tile.h, spec/scaling.md): part of a
 * render with the whole image's size, its region and the render's key.
 * Two formats, chosen by the name, both carrying every value's exact
 * double, so that a merge writes the bytes a whole render writes:
 *   .exr  OpenEXR with the region as data window (image_file.h)
 *   .pfm  the region as a PFM (float, for viewers) and the sidecar
 *         NAME.pfm.tile: five text lines
 *             refray-tile 2
 *             image W H
 *             region X0 Y0 X1 Y1
 *             key 16-HEX-DIGITS
 *             pixels f64le fnv1a64 16-HEX-DIGITS
 *         then the region's values as little-endian IEEE doubles, R G B
 *         per pixel, rows from the top; nothing after them; the hex digits
 *         are the FNV-1a hash of those bytes ([TILE-FILE-4]).  A merge
 *         reads the sidecar only.
 * PNG and PPM are no tile formats: they hold display codes.
 */
#ifndef REFRAY_TILE_FILE_H
#define REFRAY_TILE_FILE_H

#include <stddef.h>
#include "image/image.h"
#include "image/tile.h"

/* 1 when path names a tile format this build writes (.exr needs EXR=1);
 * else 0 with the reason in why. */
int tile_file_format_ok(const char *path, char *why, size_t why_size);

/* Writes the tile t (px: its region's pixels, region-sized) to path,
 * atomically: for a PFM, the PFM first and then the sidecar, so a sidecar
 * is only ever there with a complete tile.  Returns STATUS_OK, STATUS_USAGE
 * (not a tile format), STATUS_IO or STATUS_NO_MEMORY with a reason naming
 * the file in why. */
int tile_file_write(const char *path, const tile_info *t, const img_buf *px, const img_write_opts *o, char *why,
                    size_t why_size);

/* Reads the tile at path into *t and, unless px is NULL, its region's
 * exact pixels into *px (free with img_free); the whole image's size is
 * held to o->max_pixels (o NULL: the default limit) before any pixel is
 * read, and only a regular file is read.  Returns STATUS_OK;
 * STATUS_NO_INPUT (no such file, or a PFM without its sidecar),
 * STATUS_DATA (not a refray tile, damaged), STATUS_USAGE (not a tile
 * format), STATUS_IO or STATUS_NO_MEMORY, with the reason in why. */
int tile_file_read(const char *path, const img_read_opts *o, tile_info *t, img_buf *px, char *why, size_t why_size);

/* Removes the tile at path and its sidecar; 0, or -1 when some file
 * that exists could not be removed. */
int tile_file_remove(const char *path);

#endif
