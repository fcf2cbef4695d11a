/*
 * cli_verify.h - the analytic-oracle commands of the driver (spec/verify.md):
 *   refray verify SCENE...      render, compare with the exact image, table
 *   refray oracle SCENE -o OUT  write the exact image
 *   refray compare A B          compare two image files
 * Each returns an exit code (scene.h); the work is in verify.h.
 */
#ifndef REFRAY_CLI_VERIFY_H
#define REFRAY_CLI_VERIFY_H

#include "cli/cli.h"
#include "verify/verify.h"

int cli_verify(int argc, char **argv);
int cli_oracle(int argc, char **argv);
int cli_compare(int argc, char **argv);

/*
 * The view options verify and oracle share: --width, --height, --samples,
 * --max-depth and --light-samples (light only when allow_light), bounded
 * by the input limits lim.  Returns 1 when argv[*i] was one of them (its
 * value consumed, *i moved onto it), 0 after printing a usage error, -1
 * when argv[*i] is not one of them.
 */
int cli_view_option(verify_opts *o, const rf_limits *lim, int allow_light, int argc, char **argv, int *i);

/* 1 when view v (the scene's size with the overrides) is within
 * lim->max_pixels; else 0 with the reason in why.  The scene's own size is
 * checked by the loader, so only an override can exceed it. */
int cli_view_fits(const oracle_view *v, const rf_limits *lim, char *why, size_t why_size);

/* Maps an image-library status to the exit code the commands use. */
int cli_image_status(int img_status);

#endif
