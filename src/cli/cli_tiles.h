/*
 * cli_tiles.h - rendering one rectangle of an image in bands of rows,
 * here or on worker processes (refray render --jobs), into doubles, with
 * an optional checkpoint directory that keeps every finished band
 * (--checkpoint).  spec/scaling.md.
 */
#ifndef REFRAY_CLI_TILES_H
#define REFRAY_CLI_TILES_H

#include "cli/cli_tiles_band.h"

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

#endif
