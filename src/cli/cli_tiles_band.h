/*
 * cli_tiles_band.h - what a tiled render of refray render is (the
 * renderer, the region, the workers, the checkpoint directory) and its
 * split into bands of rows: the ground that the tile engine (cli_tiles.h)
 * and the checkpoint (cli_checkpoint.h) both stand on.  spec/scaling.md.
 */
#ifndef REFRAY_CLI_TILES_BAND_H
#define REFRAY_CLI_TILES_BAND_H

#include <stddef.h>
#include "refray.h"
#include "image/image.h"
#include "image/tile.h"

/* What cli_tiles_render renders and reports. */
typedef struct cli_tiles {
    rf_renderer *renderer;   /* made before any worker starts; its cancel polls the stop flag */
    tile_info target;        /* the image, the region to render, the key */
    double *pixels;          /* the region's pixels: 3 doubles a pixel, rows from the top */
    int jobs;                /* worker processes; 1: in this process */
    const char *checkpoint;  /* the directory, or NULL */
    const char *output;      /* the output file, or "-": never one of the checkpoint's */
    int quiet;               /* no progress bar, no notes */
    int bands;               /* out: the bands of the split */
    rf_render_stats stats;   /* out: summed over the workers; seconds: wall time */
    int overflow_x, overflow_y; /* out after STATUS_DATA: the pixel */
    int overflow_medium;        /* 1: glass nested too deep there, not a ray tree */
    int checkpoint_lost;        /* out: a band could not be saved, so no more were ([SCALE-RESUME-5]) */
    img_read_opts read;         /* checkpoint tiles: the render's --max-pixels */
} cli_tiles;

/*
 * The bands of a region of `rows` rows rendered by `jobs` workers
 * ([TILE-SPLIT-2]): min(rows, max(64, 4 x jobs)), each band the split of
 * tile_band, so that free workers always find work while the slowest band
 * is still small.
 */
int cli_tiles_band_count(int rows, int jobs);

/* The region of band b of t. */
tile_rect cli_tiles_band(const cli_tiles *t, int b);

#endif
