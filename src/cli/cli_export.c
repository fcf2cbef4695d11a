/*
 * cli_export.c - `refray export SCENE --to pov [-o OUT.pov]`: the scene as
 * POV-Ray 3.7 SDL (export_pov.h), to OUT atomically or to stdout.  Every
 * approximation is printed to stderr (and written as a comment in the
 * SDL); a scene that cannot be exported exits 65 with the reason.
 */
#include <stdio.h>
#include <string.h>
#include "io/scene_file.h"
#include "cli/cli_args.h"
#include "cli/commands.h"
#include "export/export_pov.h"

typedef struct export_args {
    cli_scene_opts scene;
    const char *input, *output, *format;
    pov_opts pov;
} export_args;

static const char export_help[] =
    "usage: refray export SCENE --to pov [-o OUT.pov] [OPTIONS]\n"
    "Writes SCENE as POV-Ray 3.7 scene description (SDL), for checking POV-Ray\n"
    "against refray's oracle (spec/crosscheck.md).  What cannot be mapped exactly\n"
    "is listed on stderr and in the file's header; what cannot be mapped at all\n"
    "is refused (exit 65) with the reason.\n"
    "options:\n"
    "  --to pov            the target (the only one)\n"
    "  -o, --output OUT    write OUT atomically (default: stdout)\n"
    "  --area-lights       distributed lights as POV-Ray area_light (approximate)\n"
    "                      instead of their samples as point lights (the default)\n"
    "  --plain-sheets      keep ior 1 on surfaces that pass rays straight on (POV-Ray\n"
    "                      then does not count those passes as trace levels)\n"
    "  --scale S           multiply every light, the ambient light and the background\n"
    "                      by S > 0, and so the image (a power of two keeps it exact;\n"
    "                      lets a picture brighter than 1 fit a 16-bit file)\n"
    "and -W and the input limits of `refray --help`.\n";

/* 1: consumed, 0: error (reported), -1: not an export option. */
static int export_option(void *args, int argc, char **argv, int *i)
{
    export_args *a = args;
    const char *opt = argv[*i];
    if (strcmp(opt, "-o") == 0 || strcmp(opt, "--output") == 0)
        return cli_take_value(argc, argv, i, &a->output);
    if (strcmp(opt, "--to") == 0)
        return cli_take_value(argc, argv, i, &a->format);
    if (strcmp(opt, "--area-lights") == 0)
        return a->pov.area_lights = 1;
    if (strcmp(opt, "--plain-sheets") == 0)
        return a->pov.plain_sheets = 1;
    if (strcmp(opt, "--scale") == 0) {
        const char *v;
        if (!cli_take_value(argc, argv, i, &v) || !cli_parse_double(opt, v, &a->pov.scale))
            return 0;
        if (!(a->pov.scale > 0)) {
            cli_usage_error("--scale takes a number > 0, not '%s'", v);
            return 0;
        }
        return 1;
    }
    return -1;
}

/* 0: go on; -1: help printed; else the usage exit code. */
static int parse_args(export_args *a, int argc, char **argv)
{
    int status = cli_parse_one_scene("export", export_help, argc, argv, &a->scene, &a->input, export_option, a);
    if (status != 0)
        return status;
    if (!a->format)
        return cli_usage_error("export: no target given (--to pov)");
    if (strcmp(a->format, "pov") != 0)
        return cli_usage_error("export: unknown target '%s' (the only one is 'pov')", a->format);
    return 0;
}

static void print_notes(const char *input, const pov_notes *n)
{
    for (int i = 0; i < n->count && i < POV_NOTE_MAX; i++)
        fprintf(stderr, "refray: approximation: %s\n", n->text[i]);
    if (n->count > POV_NOTE_MAX)
        fprintf(stderr, "refray: approximation: ... and %d more in '%s'\n", n->count - POV_NOTE_MAX, input);
}

static int export_scene(export_args *a, const scene_model *scene)
{
    pov_notes notes;
    char err[600];
    int status;
    a->pov.source = a->input;
    if (a->output)
        status = pov_export_file(scene, &a->pov, a->output, &notes, err, sizeof err);
    else
        status = pov_export_write(scene, &a->pov, stdout, &notes);
    if (status == STATUS_DATA) {
        fprintf(stderr, "refray: error: cannot export '%s' to POV-Ray: %s\n", a->input, notes.reason);
        return status;
    }
    if (status != 0) {
        fprintf(stderr, "refray: error: %s\n", a->output ? err : "cannot write to stdout");
        return status;
    }
    print_notes(a->input, &notes);
    return STATUS_OK;
}

int cli_export(int argc, char **argv)
{
    export_args a;
    memset(&a, 0, sizeof a);
    cli_scene_opts_init(&a.scene);
    int status = parse_args(&a, argc, argv);
    if (status != 0)
        return status < 0 ? STATUS_OK : status;
    scene_model *scene = scene_file_load(a.input, &a.scene.limits, stderr, a.scene.warnings, &status);
    if (!scene)
        return status;
    status = export_scene(&a, scene);
    scene_free(scene);
    return status;
}
