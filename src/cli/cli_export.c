/*
 * cli_export.c - `refray export SCENE --to pov|json [-o OUT]`: the scene as
 * POV-Ray 3.7 SDL (export_pov.h) or as refray's JSON scene format
 * (export_json.h), to OUT atomically or to stdout.  Every POV-Ray
 * approximation is printed to stderr (and written as a comment in the
 * SDL); a scene that cannot be exported exits 65 with the reason.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "refray.h"
#include "io/fileio.h"
#include "io/scene_file.h"
#include "cli/cli_args.h"
#include "cli/cli_signal.h"
#include "cli/commands.h"
#include "export/export_json.h"
#include "export/export_pov.h"

typedef struct export_args {
    cli_scene_opts scene;
    const char *input, *output, *format;
    const char *pov_only;    /* the first POV-Ray option given, to refuse with --to json */
    const char *mesh_dir;    /* --mesh-files */
    pov_opts pov;
} export_args;

static const char export_help[] =
    "usage: refray export SCENE --to pov|json [-o OUT] [OPTIONS]\n"
    "Writes SCENE as POV-Ray 3.7 scene description (SDL), for checking POV-Ray\n"
    "against refray's oracle (spec/crosscheck.md), or as refray's JSON scene\n"
    "format (spec/json.md), which any program can read and which `refray render`\n"
    "reads back to the bit-identical image.  What POV-Ray cannot map exactly\n"
    "is listed on stderr and in the file's header; what cannot be mapped at all\n"
    "is refused (exit 65) with the reason.\n"
    "options:\n"
    "  --to pov|json       the target\n"
    "  -o, --output OUT    write OUT atomically (default, or OUT -: stdout)\n"
    "json:\n"
    "  --mesh-files DIR    meshes as OBJ files DIR/STEM.meshI.obj instead of inline\n"
    "                      arrays; DIR is relative to OUT's directory, as the\n"
    "                      JSON's references are (STEM: OUT's name without .json)\n"
    "pov:\n"
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
    if (strcmp(opt, "--mesh-files") == 0)
        return cli_take_value(argc, argv, i, &a->mesh_dir);
    if (!a->pov_only && (strcmp(opt, "--area-lights") == 0 || strcmp(opt, "--plain-sheets") == 0 ||
                         strcmp(opt, "--scale") == 0))
        a->pov_only = opt;
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
        return cli_usage_error("export: no target given (--to pov or --to json)");
    int json = strcmp(a->format, "json") == 0;
    if (!json && strcmp(a->format, "pov") != 0)
        return cli_usage_error("export: unknown target '%s' (it is 'pov' or 'json')", a->format);
    if (json && !scene_json_available())
        return cli_usage_error("export: this refray was built without JSON support (JSON=0); rebuild it with "
                               "JSON=1 (libjansson-dev)");
    if (json && a->pov_only)
        return cli_usage_error("export: %s applies to --to pov", a->pov_only);
    if (!json && a->mesh_dir)
        return cli_usage_error("export: --mesh-files applies to --to json");
    /* "-" is standard output, as for render (spec/json.md [JSON-OUT-1]). */
    if (a->output && strcmp(a->output, "-") == 0)
        a->output = NULL;
    return 0;
}

/* The name of path without its directory and its ".json" or ".scene". */
static char *stem_of(const char *path)
{
    const char *base = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
    size_t n = strlen(base);
    const char *dot = strrchr(base, '.');
    if (dot && dot != base && (strcmp(dot, ".json") == 0 || strcmp(dot, ".scene") == 0))
        n = (size_t)(dot - base);
    char *stem = malloc(n + 1);
    if (stem) {
        memcpy(stem, base, n);
        stem[n] = '\0';
    }
    return stem;
}

static int export_json(export_args *a, const scene_model *scene)
{
    export_json_opts o;
    char err[600];
    int status;
    char generator[64];
    memset(&o, 0, sizeof o);
    snprintf(generator, sizeof generator, "refray %s", rf_version());
    o.source = a->input;
    o.generator = generator;
    o.mesh_dir = a->mesh_dir;
    char *dir = a->output ? file_dirname(NULL, a->output) : NULL, *stem = stem_of(a->output ? a->output : a->input);
    o.json_dir = dir;
    o.mesh_stem = stem;
    if ((a->output && !dir) || !stem) {
        status = STATUS_NO_MEMORY;
        snprintf(err, sizeof err, "out of memory");
    } else if (a->output) {
        status = export_json_file(scene, &o, a->output, err, sizeof err);
    } else {
        status = export_json_write(scene, &o, stdout, err, sizeof err);
        if (status == STATUS_OK && fflush(stdout) != 0)
            status = STATUS_IO;
        if (status == STATUS_IO && !err[0])
            snprintf(err, sizeof err, "cannot write to stdout");
    }
    if (status != STATUS_OK)
        fprintf(stderr, "refray: error: %s\n", err);
    mem_free_string(NULL, dir);
    free(stem);
    return status;
}

static void print_notes(const char *input, const pov_notes *n)
{
    for (int i = 0; i < n->count && i < POV_NOTE_MAX; i++)
        fprintf(stderr, "refray: approximation: %s\n", n->text[i]);
    if (n->count > POV_NOTE_MAX)
        cli_note("", "approximation: ... and %d more in '%s'", n->count - POV_NOTE_MAX, input);
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
        cli_error("cannot export '%s' to POV-Ray: %s", a->input, notes.reason);
        return status;
    }
    if (status != 0) {
        cli_error("%s", a->output ? err : "cannot write to stdout");
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
    cli_signal_cooperate(1);
    scene_model *scene = cli_load_scene(&a.scene, a.input, &status);
    if (!scene)
        return status;
    status = strcmp(a.format, "json") == 0 ? export_json(&a, scene) : export_scene(&a, scene);
    scene_free(scene);
    return status;
}
