/*
 * cli_args.h - what the commands share: the scene-reading options, the
 * argument loop of one-scene commands, number parsing, the render and view
 * size options, and image statuses as exit codes.
 */
#ifndef REFRAY_CLI_ARGS_H
#define REFRAY_CLI_ARGS_H

#include <stddef.h>
#include "refray.h"
#include "render/render.h"
#include "scene/scene.h"
#include "verify/conform.h"
#include "verify/verify.h"

/* Options every scene-reading command accepts: the input limits and
 * whether warnings are shown.  Returns the number of argv entries consumed
 * at argv[i] (0 when argv[i] is not one of them, -1 on a bad value). */
enum { CLI_MAX_ALLOW_READ = 64 };
typedef struct cli_scene_opts {
    scene_limits limits;
    int warnings;
    /* --allow-read DIR, in order, NULL-terminated: where include and mesh
     * files may come from besides the scene's directory ([REL-READ-1]) */
    const char *allow_read[CLI_MAX_ALLOW_READ + 1];
    int allow_count;
} cli_scene_opts;

void cli_scene_opts_init(cli_scene_opts *o);

/* The public API's load options for o: its limits and warnings, the
 * diagnostics printed to stderr, files from the file system confined to
 * the scene's directory and --allow-read's, stopped by a signal
 * (cli_signal_cancel).  The result points into o. */
rf_load_options cli_load_options(const cli_scene_opts *o);

/* Loads the scene file path the same way through the library's own
 * interface (for the commands that need the scene model); NULL with
 * *status on failure ("refray: interrupted" printed when a signal
 * stopped it). */
scene_model *cli_load_scene(const cli_scene_opts *o, const char *path, int *status);
int cli_scene_opt(cli_scene_opts *o, int argc, char **argv, int i);

/* The value after option argv[*i] (advancing *i); 0 with the usage error
 * printed when it is missing. */
int cli_take_value(int argc, char **argv, int *i, const char **value);

/* A whole-number option value in [1, hi] into *out; 0 after the usage error. */
int cli_int_value(int argc, char **argv, int *i, long hi, int *out);

/* The options that size a render (--width --height --samples --max-depth
 * --light-samples) and --no-shortcuts into o; 1 consumed, 0 error, -1 not
 * one.  The sizes are checked against the limits only by cli_check_sizes,
 * after every option. */
int cli_render_option(render_opts *o, int argc, char **argv, int *i);

/* The sizing options given (0: not given) against the limits: 0, or
 * STATUS_USAGE after the error naming the flag that raises the limit. */
int cli_check_sizes(int width, int height, int samples, int light_samples, int max_depth, const scene_limits *lim);
/* cli_check_sizes of a render's options. */
int cli_check_render_sizes(const render_opts *r, const scene_limits *lim);
/* [LANG-EXTENT-1] The image size r overrides (if any) against scene's
 * orthographic view (scene_check_view): 0, or STATUS_DATA after the error
 * at the camera's width, before anything is rendered or written. */
int cli_check_view(const rf_scene *scene, const render_opts *r);
/* The same for a width and height given whole (refray oracle's view). */
int cli_check_view_size(const scene_model *s, int width, int height);

/* The options of an image file (--linear --exr-float --exposure
 * --bit-depth --tone) into o; 1 consumed, 0 error reported, -1 not one. */
int cli_image_option(rf_write_options *o, int argc, char **argv, int *i);

/* Before a long job, whether an image file can be written at path: a
 * known extension this build writes (else the usage error, 64) in a
 * path the atomic writer takes (else 74; io/image_io.h's img_write_check).  0 when it can; the error printed. */
int cli_check_output_file(const char *command, const char *path);
/* Only the path part of that (the format is checked by the caller). */
int cli_check_output_dir(const char *path);

/* One command's own options: 1 consumed (with its value), 0 an error
 * already reported, -1 not one of its options. */
typedef int (*cli_option_fn)(void *args, int argc, char **argv, int *i);

/* What a command does with an argument that is not an option (a scene or
 * a file): 0, or STATUS_USAGE after the error was printed. */
typedef int (*cli_operand_fn)(void *args, const char *arg);

/*
 * The argument loop of a command: --help (prints help, returns -1), the
 * shared scene options into scene, every operand ("-" included) through
 * operand, and the command's own options through option (an unknown one
 * is reported here).  Returns 0 to go on, -1 after help, or STATUS_USAGE
 * after the error was printed.
 */
int cli_parse_command(const char *command, const char *help, int argc, char **argv, cli_scene_opts *scene,
                      cli_operand_fn operand, cli_option_fn option, void *args);

/*
 * The argument loop of a command that reads one scene: cli_parse_command
 * with one SCENE into *input (a second one, or none, is an error).
 */
int cli_parse_one_scene(const char *command, const char *help, int argc, char **argv, cli_scene_opts *scene,
                        const char **input, cli_option_fn option, void *args);

/* Parses a whole number option value in [lo, hi]; prints the usage error. */
int cli_parse_long(const char *option, const char *text, long lo, long hi, long *out);
int cli_parse_double(const char *option, const char *text, double *out);

/* Prints "refray: error: MESSAGE" to stderr, the message escaped and cut
 * (base/text.h: no input byte reaches the terminal raw). */
void cli_error(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

/* Prints before (as it is: "" or the line feed that ends a progress bar),
 * then "refray: MESSAGE" to stderr, the message escaped and cut like
 * cli_error's. */
void cli_note(const char *before, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Prints "refray: error: ..." for command-line mistakes, returns 64. */
int cli_usage_error(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

/*
 * The view options verify and oracle share: --width, --height, --samples,
 * --max-depth and --light-samples (light only when allow_light), checked
 * against the limits by cli_check_sizes.  Returns 1 when argv[*i] was one of them (its
 * value consumed, *i moved onto it), 0 after printing a usage error, -1
 * when argv[*i] is not one of them.
 */
int cli_view_option(verify_opts *o, int allow_light, int argc, char **argv, int *i);

/* 1 when view v (the scene's size with the overrides) is within
 * lim->max_pixels; else 0 with the reason in why.  The scene's own size is
 * checked by the loader, so only an override can exceed it. */
int cli_view_fits(const oracle_view *v, const scene_limits *lim, char *why, size_t why_size);

/* --downsample K|manifest and --scale S|manifest (conform, compare) into
 * a; 1 consumed, 0 error reported, -1 not one of them. */
int cli_adjust_option(conform_adjust *a, int argc, char **argv, int *i);

#endif
