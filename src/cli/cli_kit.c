/*
 * cli_kit.c - `refray kit -o DIR [SCENE...]`: the conformance kit
 * (verify/kit.h, spec/conformance.md).  Without scenes it takes
 * every scenes/analytic/NAME.scene of the current directory (refray's source tree).
 */
#include <glob.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cli/cli.h"
#include "cli/cli_args.h"
#include "cli/cli_signal.h"
#include "cli/commands.h"
#include "verify/kit.h"

static const char kit_help[] =
    "usage: refray kit -o DIR [SCENE...] [OPTIONS]\n"
    "Writes the conformance kit: for every analytic scene its .scene, .pov (and .json),\n"
    "exact image (.exr 32-bit float, .pfm), mask of excluded pixels (.pgm, .png), and\n"
    "one manifest.json with the tolerances, plus README.md for another renderer's\n"
    "author (spec/conformance.md).  Without SCENEs: scenes/analytic/*.scene.\n"
    "options:\n"
    "  -o, --output DIR   the kit's directory: new, empty, or an earlier kit (replaced\n"
    "                     whole once the new one is complete)\n"
    "  -q, --quiet        no table of the scenes\n"
    "and -W and the input limits of `refray --help`.\n"
    "exit: 0 written; 64 usage (also: a build without JSON, DIR not a kit); 65 a bad\n"
    "scene or one without an exact image; 66 a missing scene; 74 I/O error.\n";

typedef struct kit_args {
    cli_scene_opts scene;
    const char *output;
    const char **scenes;
    int count, quiet;
} kit_args;

static int kit_operand(void *args, const char *arg)
{
    kit_args *a = args;
    a->scenes[a->count++] = arg;
    return 0;
}

static int kit_option(void *args, int argc, char **argv, int *i)
{
    kit_args *a = args;
    const char *opt = argv[*i];
    if (strcmp(opt, "-o") == 0 || strcmp(opt, "--output") == 0)
        return cli_take_value(argc, argv, i, &a->output);
    if (strcmp(opt, "-q") == 0 || strcmp(opt, "--quiet") == 0)
        return a->quiet = 1;
    return -1;
}

static int parse_args(kit_args *a, int argc, char **argv)
{
    int status = cli_parse_command("kit", kit_help, argc, argv, &a->scene, kit_operand, kit_option, a);
    if (status != 0)
        return status;
    if (!a->output)
        return cli_usage_error("kit: no directory given (-o DIR)");
    return 0;
}

static void print_table(const manifest *m, const char *dir)
{
    printf("%-28s %-18s %9s %3s %5s %10s %10s %10s %6s %s\n", "scene", "family", "size", "k", "depth", "relative",
           "absolute", "peak", "masked", "missing");
    for (int i = 0; i < m->scene_count; i++) {
        const manifest_scene *s = &m->scenes[i];
        char size[32], missing[128] = "";
        snprintf(size, sizeof size, "%dx%d", s->width, s->height);
        for (int f = 0; f < MANIFEST_FILE_COUNT; f++)
            if (!s->files[f][0])
                snprintf(missing + strlen(missing), sizeof missing - strlen(missing), "%s%s",
                         missing[0] ? "," : "", manifest_file_key((manifest_file)f));
        printf("%-28s %-18s %9s %3d %5d %10.3g %10.3g %10.4g %6ld %s\n", s->name, s->family, size, s->samples,
               s->max_depth, s->relative, s->absolute, s->peak, s->masked, missing[0] ? missing : "-");
    }
    printf("%d scenes written to %s (manifest.json, README.md)\n", m->scene_count, dir);
}

/* Every scenes/analytic/NAME.scene, sorted, when no scene is named. */
static int default_scenes(glob_t *g)
{
    if (glob("scenes/analytic/*.scene", 0, NULL, g) == 0 && g->gl_pathc > 0)
        return 0;
    cli_error("kit: no scenes given, and ./scenes/analytic/*.scene matches nothing "
            "(name the scenes, or run from refray's source tree)");
    return STATUS_NO_INPUT;
}

int cli_kit(int argc, char **argv)
{
    kit_args a;
    memset(&a, 0, sizeof a);
    cli_scene_opts_init(&a.scene);
    a.scenes = calloc((size_t)argc, sizeof *a.scenes);
    if (!a.scenes)
        return STATUS_NO_MEMORY;
    int status = parse_args(&a, argc, argv);
    glob_t g;
    memset(&g, 0, sizeof g);
    if (status == 0 && a.count == 0 && (status = default_scenes(&g)) == 0) {
        free(a.scenes);
        a.scenes = (const char **)g.gl_pathv;
        a.count = (int)g.gl_pathc;
    }
    if (status == 0) {
        kit_opts o = {a.scene.limits, a.scene.warnings, stderr, rf_version(), cli_signal_cancel, NULL,
                      a.scene.allow_read};
        /* A signal stops the build after the scene in hand. */
        cli_signal_cooperate(1);
        manifest m;
        char why[1024];
        status = kit_build(a.output, a.scenes, a.count, &o, &m, why, sizeof why);
        if (status == STATUS_CANCELLED)
            fputs("refray: kit: interrupted; nothing written\n", stderr);
        else if (status != 0)
            cli_error("kit: %s", why);
        else if (!a.quiet)
            print_table(&m, a.output);
        if (status == 0)
            manifest_free(&m);
    }
    if (g.gl_pathv)
        globfree(&g);
    else
        free(a.scenes);
    return status < 0 ? STATUS_OK : status;
}
