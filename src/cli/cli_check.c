/*
 * cli_check.c - `refray check FILE...`: parse and validate each scene and
 * print one summary line per good file, through the public API (refray.h).
 * The exit code is the worst of all files (65 for a bad scene, 66 for a
 * missing one).
 */
#include <stdio.h>
#include <string.h>
#include "cli/cli_args.h"
#include "cli/cli_signal.h"
#include "cli/commands.h"

static const char check_help[] =
    "usage: refray check [OPTIONS] FILE...\n"
    "Parses and validates each scene; prints diagnostics to stderr and, for each\n"
    "valid file, one line to stdout:\n"
    "  FILE: ok: P primitives, L lights, M materials; uses: FEATURES\n"
    "and one line per mesh:\n"
    "  mesh PATH: T triangles from F faces, D dropped; closed|open (...);\n"
    "  consistently oriented|not consistently oriented; K pieces\n"
    "Options: -W (no warnings) and the input limits of `refray --help`.\n";

static void print_features(unsigned features)
{
    static const char *const names[] = {"shadows", "specular", "reflection", "refraction", "sampled-lights",
                                        "meshes"};
    static const unsigned bits[] = {RF_FEATURE_SHADOWS, RF_FEATURE_SPECULAR, RF_FEATURE_REFLECTION,
                                    RF_FEATURE_REFRACTION, RF_FEATURE_SAMPLED_LIGHTS, RF_FEATURE_MESHES};
    int any = 0;
    for (int i = 0; i < 6; i++)
        if (features & bits[i])
            printf("%s%s", any++ ? " " : "", names[i]);
    if (!any)
        printf("none");
}

/* [MESH-CHECK-1] One line per mesh: what the loader found and did. */
static void print_mesh(const rf_mesh_info *m)
{
    printf("  mesh %s: %d triangle%s from %d face%s, %d dropped; ", m->path, m->triangles,
           m->triangles == 1 ? "" : "s", m->faces, m->faces == 1 ? "" : "s", m->dropped);
    if (m->closed)
        printf("closed");
    else
        printf("open (%d open edge%s, %d edge%s of 3 or more triangles)", m->open_edges,
               m->open_edges == 1 ? "" : "s", m->crowded_edges, m->crowded_edges == 1 ? "" : "s");
    printf("; %s oriented; %d piece%s", m->oriented ? "consistently" : "not consistently", m->pieces,
           m->pieces == 1 ? "" : "s");
    if (m->nonplanar)
        printf("; %d non-planar", m->nonplanar);
    if (m->fanned)
        printf("; %d fanned", m->fanned);
    printf("\n");
}

static void print_summary(const char *path, const rf_scene *scene)
{
    static const char *const kinds[] = {"sphere", "plane", "triangle", "disk", "box", "cylinder", "cone", "torus"};
    static const char *const plural[] = {"spheres", "planes", "triangles", "disks",
                                         "boxes",   "cylinders", "cones", "tori"};
    rf_scene_info s;
    rf_scene_get_info(scene, &s);
    int counts[] = {s.spheres, s.planes, s.triangles, s.disks, s.boxes, s.cylinders, s.cones, s.tori};
    printf("%s: ok: %d primitive%s (", path, s.primitives, s.primitives == 1 ? "" : "s");
    int listed = 0;
    for (int k = 0; k < (int)(sizeof counts / sizeof counts[0]); k++)
        if (counts[k])
            printf("%s%d %s", listed++ ? ", " : "", counts[k], counts[k] == 1 ? kinds[k] : plural[k]);
    if (s.meshes)
        printf("%s%d mesh%s of %d triangles", listed++ ? ", " : "", s.meshes, s.meshes == 1 ? "" : "es",
               s.mesh_triangles);
    printf("), %d light%s, %d material%s; uses: ", s.lights, s.lights == 1 ? "" : "s", s.materials,
           s.materials == 1 ? "" : "s");
    print_features(s.features);
    if (s.oracle)
        printf("; oracle %s", s.oracle);
    printf("\n");
    for (int i = 0; i < s.meshes; i++) {
        rf_mesh_info m;
        if (rf_scene_get_mesh_info(scene, i, &m) == RF_OK)
            print_mesh(&m);
    }
}

int cli_check(int argc, char **argv)
{
    cli_scene_opts opts;
    cli_scene_opts_init(&opts);
    int files = 0, worst = STATUS_OK;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(check_help, stdout);
            return STATUS_OK;
        }
        int used = argv[i][0] == '-' && argv[i][1] ? cli_scene_opt(&opts, argc, argv, i) : 0;
        if (used < 0)
            return STATUS_USAGE;
        if (used == 0 && argv[i][0] == '-' && argv[i][1])
            return cli_usage_error("check: unknown option '%s'", argv[i]);
        i += used > 0 ? used - 1 : 0;
        files += used == 0;
    }
    if (files == 0)
        return cli_usage_error("check: no scene files given");
    cli_signal_cooperate(1);
    for (int i = 1; i < argc && worst != STATUS_CANCELLED; i++) {
        int used = argv[i][0] == '-' && argv[i][1] ? cli_scene_opt(&opts, argc, argv, i) : 0;
        if (used > 0) {
            i += used - 1;
            continue;
        }
        rf_load_options lo = cli_load_options(&opts);
        rf_scene *s;
        int status = (int)rf_scene_load_file(argv[i], &lo, &s);
        if (s)
            print_summary(argv[i], s);
        else if (status == STATUS_CANCELLED)
            fputs("refray: interrupted\n", stderr);
        rf_scene_free(s);
        worst = status_worse(worst, status);
    }
    fflush(stdout);
    return worst;
}
