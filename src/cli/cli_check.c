/*
 * cli_check.c - `refray check FILE...`: parse and validate each scene and
 * print one summary line per good file.  The exit code is the worst of all
 * files (65 for a bad scene, 66 for a missing one).
 */
#include <stdio.h>
#include <string.h>
#include "cli/cli_args.h"
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

enum { KINDS = PRIM_MESH + 1 };

static void count_kinds(const rf_scene *s, int counts[KINDS])
{
    memset(counts, 0, KINDS * sizeof counts[0]);
    for (int i = 0; i < s->prim_count; i++)
        counts[s->prims[i].kind]++;
}

static void print_features(const rf_features *f)
{
    const char *names[] = {"shadows", "specular", "reflection", "refraction", "sampled-lights", "meshes"};
    int on[] = {f->shadows, f->specular, f->reflection, f->refraction, f->sampled_lights, f->meshes};
    int any = 0;
    for (int i = 0; i < 6; i++)
        if (on[i])
            printf("%s%s", any++ ? " " : "", names[i]);
    if (!any)
        printf("none");
}

/* [MESH-CHECK-1] One line per mesh: what the loader found and did. */
static void print_mesh(const rf_mesh *m)
{
    const rf_mesh_report *r = &m->report;
    printf("  mesh %s: %d triangle%s from %d face%s, %d dropped; ", m->path, m->geom.tri_count,
           m->geom.tri_count == 1 ? "" : "s", r->faces, r->faces == 1 ? "" : "s", r->dropped);
    if (m->geom.closed)
        printf("closed");
    else
        printf("open (%d open edge%s, %d edge%s of 3 or more triangles)", r->open_edges,
               r->open_edges == 1 ? "" : "s", r->crowded_edges, r->crowded_edges == 1 ? "" : "s");
    printf("; %s oriented; %d piece%s", r->oriented ? "consistently" : "not consistently", r->components,
           r->components == 1 ? "" : "s");
    if (r->nonplanar)
        printf("; %d non-planar", r->nonplanar);
    if (r->fanned)
        printf("; %d fanned", r->fanned);
    printf("\n");
}

static void print_summary(const char *path, const rf_scene *s)
{
    static const char *kinds[] = {"sphere", "plane", "triangle", "disk", "box"};
    static const char *plural[] = {"spheres", "planes", "triangles", "disks", "boxes"};
    int counts[KINDS], mesh_triangles = 0;
    count_kinds(s, counts);
    for (int i = 0; i < s->mesh_count; i++)
        mesh_triangles += s->meshes[i].geom.tri_count;
    printf("%s: ok: %d primitive%s (", path, s->prim_count, s->prim_count == 1 ? "" : "s");
    int listed = 0;
    for (int k = 0; k < PRIM_MESH; k++)
        if (counts[k])
            printf("%s%d %s", listed++ ? ", " : "", counts[k], counts[k] == 1 ? kinds[k] : plural[k]);
    if (s->mesh_count)
        printf("%s%d mesh%s of %d triangles", listed++ ? ", " : "", s->mesh_count, s->mesh_count == 1 ? "" : "es",
               mesh_triangles);
    printf("), %d light%s, %d material%s; uses: ", s->light_count, s->light_count == 1 ? "" : "s",
           s->material_count, s->material_count == 1 ? "" : "s");
    print_features(&s->features);
    if (s->oracle)
        printf("; oracle %s", s->oracle);
    printf("\n");
    for (int i = 0; i < s->mesh_count; i++)
        print_mesh(&s->meshes[i]);
}

int cli_check(int argc, char **argv)
{
    cli_scene_opts opts;
    cli_scene_opts_init(&opts);
    int files = 0, worst = REFRAY_EXIT_OK;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(check_help, stdout);
            return REFRAY_EXIT_OK;
        }
        int used = argv[i][0] == '-' && argv[i][1] ? cli_scene_opt(&opts, argc, argv, i) : 0;
        if (used < 0)
            return REFRAY_EXIT_USAGE;
        if (used == 0 && argv[i][0] == '-' && argv[i][1])
            return cli_usage_error("check: unknown option '%s'", argv[i]);
        i += used > 0 ? used - 1 : 0;
        files += used == 0;
    }
    if (files == 0)
        return cli_usage_error("check: no scene files given");
    for (int i = 1; i < argc; i++) {
        int used = argv[i][0] == '-' && argv[i][1] ? cli_scene_opt(&opts, argc, argv, i) : 0;
        if (used > 0) {
            i += used - 1;
            continue;
        }
        int status;
        rf_scene *s = scene_load(argv[i], &opts.limits, stderr, opts.warnings, &status);
        if (s)
            print_summary(argv[i], s);
        scene_free(s);
        if (status > worst)
            worst = status;
    }
    fflush(stdout);
    return worst;
}
