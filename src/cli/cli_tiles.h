/*
 * cli_tiles.h - rendering one rectangle of an image in bands of rows,
 * here or on worker processes (refray render --jobs), into doubles, with
 * an optional checkpoint directory that keeps every finished band
 * (--checkpoint).  spec/scaling.md.
 */
#ifndef REFRAY_CLI_TILES_H
#define REFRAY_CLI_TILES_H

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
    int quiet;               /* no progress bar, no notes */
    int bands;               /* out: the bands of the split */
    rf_render_stats stats;   /* out: summed over the workers; seconds: wall time */
    int overflow_x, overflow_y; /* out after STATUS_DATA: the pixel */
    int overflow_medium;        /* 1: glass nested too deep there, not a ray tree */
    img_read_opts read;         /* checkpoint tiles: the render's --max-pixels */
} cli_tiles;

/*
 * The bands of a region of `rows` rows rendered by `jobs` workers
 * ([TILE-SPLIT-2]): min(rows, max(64, 4 x jobs)), each band the split of
 * tile_band, so that free workers always find work while the slowest band
 * is still small.
 */
int cli_tiles_band_count(int rows, int jobs);

/*
 * Renders t->target.region into t->pixels: the bands the checkpoint does
 * not hold yet, on t->jobs workers, saving each band into the checkpoint
 * when it is done.  Returns STATUS_OK; STATUS_CANCELLED (the stop flag);
 * STATUS_DATA (a ray tree over the budget: t->overflow_*; or a checkpoint
 * of another render); STATUS_INTERNAL (a worker died); STATUS_IO or
 * STATUS_NO_MEMORY.  Every error but CANCELLED and a ray tree's DATA has
 * been printed.  No worker is left running.
 */
int cli_tiles_render(cli_tiles *t);

/* Removes what the checkpoint of t holds, once the output is written:
 * its tiles, its manifest, and the directory if that leaves it empty. */
void cli_tiles_checkpoint_clear(const cli_tiles *t);

/* ---- The checkpoint (cli_checkpoint.c) ---- */

/* Creates the checkpoint directory t->checkpoint or opens it: its
 * manifest must name the same image, region and key (else STATUS_DATA,
 * printed); sets t->bands from it or, for a new one, writes it with
 * t->bands.  Marks done[b] for every band whose tile it holds and copies
 * that tile's pixels into t->pixels.  Returns as cli_tiles_render. */
int cli_checkpoint_open(cli_tiles *t, unsigned char *done);

/* Saves band b of t->pixels into the checkpoint: STATUS_OK, or the
 * status with the reason in why. */
int cli_checkpoint_save(const cli_tiles *t, int b, char *why, size_t why_size);

/* The region of band b of t. */
tile_rect cli_tiles_band(const cli_tiles *t, int b);

#endif
