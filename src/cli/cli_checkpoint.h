/*
 * cli_checkpoint.h - the checkpoint directory of a tiled render (refray
 * render --checkpoint DIR): every finished band kept, so a stopped render
 * resumes.  spec/scaling.md.
 */
#ifndef REFRAY_CLI_CHECKPOINT_H
#define REFRAY_CLI_CHECKPOINT_H

#include "cli/cli_tiles_band.h"

/* Creates the checkpoint directory t->checkpoint or opens it: its
 * manifest must name the same image, region and key (else STATUS_DATA,
 * printed); sets t->bands from it or, for a new one, writes it with
 * t->bands.  Marks done[b] for every band whose tile it holds and copies
 * that tile's pixels into t->pixels.  Returns as cli_tiles_render. */
int cli_checkpoint_open(cli_tiles *t, unsigned char *done);

/* Saves band b of t->pixels into the checkpoint: STATUS_OK, or the
 * status with the reason in why (the caller goes on rendering:
 * [SCALE-RESUME-5]). */
int cli_checkpoint_save(const cli_tiles *t, int b, char *why, size_t why_size);

/* Removes what the checkpoint of t holds, once the output is written:
 * its tiles, its manifest, and the directory if that leaves it empty. */
void cli_tiles_checkpoint_clear(const cli_tiles *t);

#endif
