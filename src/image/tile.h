/*
 * tile.h - a tile: one rectangle of a larger image, with what it takes to
 * put tiles back together (spec/scaling.md): the whole image's size, the
 * rectangle, and the fingerprint of the render that made it.  Here the
 * pure parts: the fixed split of rows into bands, and the checks a merge
 * makes before it reads a pixel.  (Tile files: image_file.h for OpenEXR,
 * io/tile_file.h for every format.)
 */
#ifndef REFRAY_TILE_H
#define REFRAY_TILE_H

#include <stddef.h>
#include <stdint.h>

/* Pixels x0 <= x < x1, y0 <= y < y1; y = 0 is the top row. */
typedef struct tile_rect {
    int x0, y0, x1, y1;
} tile_rect;

typedef struct tile_info {
    int width, height;   /* the whole image */
    tile_rect region;    /* inside it, not empty */
    uint64_t key;        /* the render's fingerprint (rf_renderer_fingerprint) */
} tile_info;

/*
 * Band i of n of the rows [y0, y1) ([TILE-SPLIT-1]): the rows from
 * y0 + floor(i * R / n) to y0 + floor((i + 1) * R / n), R = y1 - y0, in
 * 64-bit integers.  The n bands cover [y0, y1) in order without overlap;
 * each has floor(R / n) or that plus one rows, so none is empty when
 * n <= R.  Needs 0 <= i < n.
 */
void tile_band(int y0, int y1, int n, int i, int *band_y0, int *band_y1);

/* 1 when t is a tile: an image of at least 1 x 1 pixels and at most
 * max_pixels, and a non-empty region inside it; else 0 with the reason. */
int tile_info_valid(const tile_info *t, long max_pixels, char *why, size_t why_size);

/* 1 when a and b are the same tile: image, region and key. */
int tile_info_equal(const tile_info *a, const tile_info *b);

/* 1 when a and b share a pixel, with the shared rectangle in *out. */
int tile_overlap(const tile_rect *a, const tile_rect *b, tile_rect *out);

/* Pixels in r. */
long tile_area(const tile_rect *r);

/*
 * The first rectangle of the width x height image that none of the count
 * regions covers: the first uncovered pixel in row order, as wide as the
 * uncovered run of its row, and as tall as the rows below it in which no
 * region touches that run.  Returns 1 with it in *gap, 0 when every pixel
 * is covered.  Allocates nothing; O(height x count).
 */
int tile_find_gap(const tile_rect *regions, int count, int width, int height, tile_rect *gap);

/* "x 0..1919, y 135..269" (inclusive, as people count pixels) into buf. */
const char *tile_rect_text(const tile_rect *r, char *buf, size_t size);

/* The key as 16 lower-case hex digits and back (1 when s is exactly that). */
void tile_key_text(uint64_t key, char out[17]);
int tile_key_parse(const char *s, uint64_t *key);

#endif
