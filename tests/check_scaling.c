/*
 * check_scaling.c - big renders through the refray program
 * (spec/scaling.md): tiles and regions hold the pixels of a render in one
 * piece; merged tiles, --jobs N and a resumed --checkpoint render write its
 * very bytes; GNU parallel and a Slurm job array (run as Slurm runs a task)
 * do too; and tiles that do not fit together, a worker killed by a signal,
 * SIGINT, a full disk and a checkpoint of another render each give their
 * message and exit code and leave no output, no temporary file and no
 * worker behind.  The reference is always a plain `refray render` of the
 * whole image (--jobs 1), compared byte for byte or double for double.
 */
/* posix_openpt and its kin, for the progress bar's terminal. */
#define _XOPEN_SOURCE 700
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include "cli_testlib.h"
#include "image/image_file.h"
#include "io/image_io.h"
#include "image/tile.h"

#define SCENE "scenes/demo.scene"

/* A small view of the demo (reflection, refraction, an area light) and a
 * slower one, for the runs that are interrupted (80 rows: bands enough). */
static const char *const SMALL[] = {"--width", "40", "--height", "24", "--light-samples", "8", NULL};
static const char *const SLOW[] = {"--width", "96", "--height", "80", "--light-samples", "32", NULL};

static int have(img_format f)
{
    return img_format_available(f);
}

/* The exact-format extension of this build's display image. */
static const char *display_ext(void)
{
    return have(IMG_FORMAT_PNG) ? "png" : "ppm";
}

/* args = "render" SCENE view... extra... (NULL-terminated lists). */
static void render_args(const char **args, const char *const *view, const char *const *extra)
{
    int n = 0;
    args[n++] = "render";
    args[n++] = SCENE;
    for (int i = 0; view[i]; i++)
        args[n++] = view[i];
    for (int i = 0; extra && extra[i]; i++)
        args[n++] = extra[i];
    args[n] = NULL;
}

/* Runs refray render on the small view with extra; asserts exit code want. */
static cli_run *render(int want, const char *const *extra)
{
    static cli_run r;
    const char *args[64];
    render_args(args, SMALL, extra);
    cli_refray(&r, args);
    ck_assert_msg(r.code == want, "render exited %d, not %d: %s", r.code, want, r.err);
    return &r;
}

static void render_to(const char *out, const char *opt1, const char *opt2)
{
    const char *extra[] = {"-q", "-o", out, opt1, opt2, NULL};
    render(0, extra);
}

static void read_all(const char *path, char **data, long *len)
{
    FILE *f = fopen(path, "rb");
    ck_assert_msg(f != NULL, "cannot open %s", path);
    fseek(f, 0, SEEK_END);
    *len = ftell(f);
    rewind(f);
    *data = malloc((size_t)*len + 1);
    ck_assert_ptr_nonnull(*data);
    ck_assert_int_eq((long)fread(*data, 1, (size_t)*len, f), *len);
    fclose(f);
}

static void same_bytes(const char *a, const char *b)
{
    char *x, *y;
    long n, m;
    read_all(a, &x, &n);
    read_all(b, &y, &m);
    ck_assert_msg(n == m && memcmp(x, y, (size_t)n) == 0, "%s and %s differ", a, b);
    free(x);
    free(y);
}

/* The files of dir whose name holds part. */
static int files_with(const char *dir, const char *part)
{
    DIR *d = opendir(dir);
    int n = 0;
    ck_assert_ptr_nonnull(d);
    for (struct dirent *e; (e = readdir(d)) != NULL;)
        n += strstr(e->d_name, part) != NULL;
    closedir(d);
    return n;
}

#define ASSERT_ERR_HAS(r, text) \
    ck_assert_msg(strstr((r)->err, (text)) != NULL, "stderr lacks \"%s\":\n%s", (text), (r)->err)

/* Every pixel of the tile image at (x0, y0) equals the whole image's. */
static void tile_matches(const char *whole, const char *tile, int x0, int y0, int w, int h)
{
    img_buf a, b;
    char why[600];
    ck_assert_msg(img_read(whole, NULL, &a, why, sizeof why) == 0, "%s", why);
    ck_assert_msg(img_read(tile, NULL, &b, why, sizeof why) == 0, "%s", why);
    ck_assert_int_eq(b.width, w);
    ck_assert_int_eq(b.height, h);
    for (int y = 0; y < h; y++)
        ck_assert_msg(memcmp(img_pixel(&b, 0, y), img_pixel(&a, x0, y0 + y), 3 * (size_t)w * sizeof(double)) == 0,
                      "%s: row %d differs from %s", tile, y0 + y, whole);
    img_free(&a);
    img_free(&b);
}

/* [SCALE-TILE-1] A tile's and a region's pixels are those of the whole
 * render: PFM and 32-bit EXR (floats), half EXR (halves). */
START_TEST(test_scaling_tile_pixels_are_the_whole_renders)
{
    char dir[64], whole[300], tile[300], name[32];
    static const char *const kinds[][2] = {{"pfm", NULL}, {"exr", "--exr-float"}, {"exr", NULL}};
    cli_scratch(dir, sizeof dir, "scale");
    for (size_t k = 0; k < 3; k++) {
        if (strcmp(kinds[k][0], "exr") == 0 && !have(IMG_FORMAT_EXR))
            continue;
        snprintf(name, sizeof name, "whole%zu.%s", k, kinds[k][0]);
        render_to(cli_path(whole, sizeof whole, dir, name), kinds[k][1], NULL);
        for (int i = 0; i < 3; i++) {
            int y0, y1;
            char spec[8];
            snprintf(spec, sizeof spec, "%d/3", i);
            snprintf(name, sizeof name, "t%zu-%d.%s", k, i, kinds[k][0]);
            const char *extra[] = {"-q", "--tile", spec, "-o", cli_path(tile, sizeof tile, dir, name), kinds[k][1],
                                   NULL};
            render(0, extra);
            tile_band(0, 24, 3, i, &y0, &y1);
            tile_matches(whole, tile, 0, y0, 40, y1 - y0);
        }
        snprintf(name, sizeof name, "r%zu.%s", k, kinds[k][0]);
        const char *extra[] = {"-q", "--region", "5", "3", "29", "17", "-o", cli_path(tile, sizeof tile, dir, name),
                               kinds[k][1], NULL};
        render(0, extra);
        tile_matches(whole, tile, 5, 3, 24, 14);
    }
    cli_remove(dir);
}
END_TEST

/* Renders the four tiles of `--tile i/4` and four quadrant regions, as
 * EXT tiles, into dir: t0..t3.EXT, q0..q3.EXT. */
static void make_tiles(const char *dir, const char *ext)
{
    static const char *const quads[4][4] = {
        {"0", "0", "17", "10"}, {"17", "0", "40", "10"}, {"0", "10", "23", "24"}, {"23", "10", "40", "24"}};
    char path[300], name[32], spec[8];
    for (int i = 0; i < 4; i++) {
        snprintf(spec, sizeof spec, "%d/4", i);
        snprintf(name, sizeof name, "t%d.%s", i, ext);
        const char *tile[] = {"-q", "--tile", spec, "-o", cli_path(path, sizeof path, dir, name), NULL};
        render(0, tile);
        snprintf(name, sizeof name, "q%d.%s", i, ext);
        const char *quad[] = {"-q", "--region", quads[i][0], quads[i][1], quads[i][2], quads[i][3], "-o",
                              cli_path(path, sizeof path, dir, name), NULL};
        render(0, quad);
    }
}

/* refray merge of dir/PREFIX0..3.EXT into out with opt; asserts want. */
static cli_run *merge4(const char *dir, const char *prefix, const char *ext, const char *out, const char *opt,
                       int want)
{
    static cli_run r;
    char p[4][300], name[32];
    for (int i = 0; i < 4; i++) {
        snprintf(name, sizeof name, "%s%d.%s", prefix, i, ext);
        cli_path(p[i], sizeof p[i], dir, name);
    }
    const char *args[] = {"merge", p[0], p[1], p[2], p[3], "-o", out, opt, NULL};
    cli_refray(&r, args);
    ck_assert_msg(r.code == want, "merge exited %d, not %d: %s", r.code, want, r.err);
    return &r;
}

/* [SCALE-MERGE-1] Merged tiles, bands or quadrants, PFM or EXR tiles, are
 * the bytes of the whole render in every output format and option. */
START_TEST(test_scaling_merge_writes_the_whole_renders_bytes)
{
    static const struct {
        const char *name, *opt;
        img_format needs;
    } outs[] = {
        {"o.pfm", NULL, IMG_FORMAT_PFM},          {"o.ppm", NULL, IMG_FORMAT_PPM},
        {"o.png", NULL, IMG_FORMAT_PNG},          {"o16.png", "--linear", IMG_FORMAT_PNG},
        {"oh.exr", NULL, IMG_FORMAT_EXR},         {"of.exr", "--exr-float", IMG_FORMAT_EXR},
        {"ol.ppm", "--linear", IMG_FORMAT_PPM},
    };
    static const char *const exts[] = {"pfm", "exr"};
    char dir[64], whole[300], merged[300], name[40];
    cli_scratch(dir, sizeof dir, "scale");
    for (size_t e = 0; e < 2; e++) {
        if (e == 1 && !have(IMG_FORMAT_EXR))
            continue;
        make_tiles(dir, exts[e]);
        for (size_t k = 0; k < sizeof outs / sizeof outs[0]; k++) {
            const char *opt = outs[k].opt;
            if (!have(outs[k].needs))
                continue;
            cli_path(whole, sizeof whole, dir, outs[k].name);
            render_to(whole, opt, NULL);
            for (int q = 0; q < 2; q++) {
                snprintf(name, sizeof name, "m%d-%s", q, outs[k].name);
                merge4(dir, q ? "q" : "t", exts[e], cli_path(merged, sizeof merged, dir, name), opt, 0);
                same_bytes(whole, merged);
            }
        }
    }
    if (have(IMG_FORMAT_EXR)) {
        /* PFM and EXR tiles in one merge. */
        static cli_run r;
        char p[4][300];
        for (int i = 0; i < 4; i++) {
            snprintf(name, sizeof name, "t%d.%s", i, exts[i % 2]);
            cli_path(p[i], sizeof p[i], dir, name);
        }
        const char *args[] = {"merge", p[0], p[1], p[2], p[3], "-o", cli_path(merged, sizeof merged, dir, "mix.pfm"),
                              NULL};
        cli_refray(&r, args);
        ck_assert_msg(r.code == 0, "merge: %s", r.err);
        same_bytes(cli_path(whole, sizeof whole, dir, "o.pfm"), merged);
    }
    cli_remove(dir);
}
END_TEST

/* The "rays: ..." line of --stats in err. */
static void rays_line(const char *err, char *line, size_t size)
{
    const char *p = strstr(err, "  rays: ");
    ck_assert_msg(p != NULL, "no rays line in: %s", err);
    size_t n = strcspn(p, "\n");
    snprintf(line, size, "%.*s", (int)n, p);
}

/* [SCALE-JOBS-1] --jobs 2, 3 and 0 write the bytes of --jobs 1, for a
 * whole image and for a tile, and --stats counts the same rays. */
START_TEST(test_scaling_jobs_write_the_bytes_of_one)
{
    static const char *const jobs[] = {"2", "3", "0"};
    char dir[64], one[300], many[300], name[32], tile1[300], tilen[300], side1[320], siden[320];
    char rays1[200], raysn[200];
    cli_scratch(dir, sizeof dir, "scale");
    snprintf(name, sizeof name, "one.%s", display_ext());
    const char *extra1[] = {"-q", "--stats", "-o", cli_path(one, sizeof one, dir, name), NULL};
    rays_line(render(0, extra1)->err, rays1, sizeof rays1);
    for (size_t k = 0; k < 3; k++) {
        snprintf(name, sizeof name, "jobs%s.%s", jobs[k], display_ext());
        const char *extra[] = {"-q", "--stats", "--jobs", jobs[k], "-o", cli_path(many, sizeof many, dir, name),
                               NULL};
        rays_line(render(0, extra)->err, raysn, sizeof raysn);
        same_bytes(one, many);
        ck_assert_str_eq(raysn, rays1);
    }
    const char *t1[] = {"-q", "--tile", "1/2", "-o", cli_path(tile1, sizeof tile1, dir, "t1.pfm"), NULL};
    const char *tn[] = {"-q", "--tile", "1/2", "--jobs", "2", "-o", cli_path(tilen, sizeof tilen, dir, "tn.pfm"),
                        NULL};
    render(0, t1);
    render(0, tn);
    same_bytes(tile1, tilen);
    snprintf(side1, sizeof side1, "%s.tile", tile1);
    snprintf(siden, sizeof siden, "%s.tile", tilen);
    same_bytes(side1, siden);
    cli_remove(dir);
}
END_TEST

/* [SCALE-MERGE-2] [SCALE-MERGE-3] Tiles that are not one render's exact cover: exit 65
 * (66 for a missing file) with the region or the files named, and no
 * output or temporary file. */
START_TEST(test_scaling_merge_refusals)
{
    char dir[64], p[12][300], out[300], lone[300], cmd[700];
    static const char *const names[] = {"t0.pfm", "t1.pfm", "t2.pfm", "t3.pfm", "top.pfm", "other.pfm",
                                        "wide.pfm", "nope.pfm", "lone.pfm", "whole.exr"};
    cli_scratch(dir, sizeof dir, "scale");
    for (int i = 0; i < 10; i++)
        cli_path(p[i], sizeof p[i], dir, names[i]);
    make_tiles(dir, "pfm");
    const char *top[] = {"-q", "--region", "0", "0", "40", "8", "-o", p[4], NULL};
    const char *other[] = {"-q", "--samples", "1", "--tile", "2/4", "-o", p[5], NULL};
    const char *wide[] = {"-q", "--width", "41", "--tile", "3/4", "-o", p[6], NULL};
    render(0, top);
    render(0, other);
    render(0, wide);
    snprintf(cmd, sizeof cmd, "cp '%s' '%s'", p[3], cli_path(lone, sizeof lone, dir, "lone.pfm"));
    ck_assert_int_eq(system(cmd), 0);
    static const struct {
        int tiles[5], count, code;
        const char *message;
    } cases[] = {
        {{0, 1, 1, 2, 3}, 5, 65, "overlap in x 0..39, y 6..11"},
        {{4, 1, 2, 3}, 4, 65, "overlap in x 0..39, y 6..7"},
        {{0, 1, 3}, 3, 65, "no tile covers x 0..39, y 12..17 (240 of the 40x24 image's pixels have no tile)"},
        {{0, 1, 5, 3}, 4, 65, "comes from another render"},
        {{0, 1, 2, 6}, 4, 65, "is a tile of a 41x24 image"},
        {{0, 1, 2, 7}, 4, 66, "No such file"},
        {{0, 1, 2, 8}, 4, 66, "sidecar"},
    };
    cli_path(out, sizeof out, dir, "out.pfm");
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        cli_run r;
        const char *args[12];
        int n = 0;
        args[n++] = "merge";
        for (int i = 0; i < cases[k].count; i++)
            args[n++] = p[cases[k].tiles[i]];
        args[n++] = "-o";
        args[n++] = out;
        args[n] = NULL;
        cli_refray(&r, args);
        ck_assert_msg(r.code == cases[k].code, "case %zu: exit %d: %s", k, r.code, r.err);
        ASSERT_ERR_HAS(&r, cases[k].message);
        ck_assert(!cli_exists(out));
    }
    if (have(IMG_FORMAT_EXR)) {
        cli_run r;
        render_to(p[9], NULL, NULL);
        const char *args[] = {"merge", p[9], "-o", out, NULL};
        cli_refray(&r, args);
        ck_assert_int_eq(r.code, 65);
        ASSERT_ERR_HAS(&r, "not a refray tile");
    }
    ck_assert_int_eq(files_with(dir, ".refray-tmp-"), 0);
    ck_assert(!cli_exists(out));
    cli_remove(dir);
}
END_TEST

/* [SCALE-MERGE-5] Tiles are input files like any other (spec/reliability.md):
 * the whole image they claim is held to merge's --max-pixels before a
 * pixel is allocated (the 40x24 image of make_tiles: 960 pixels), and a
 * FIFO or a directory in place of a tile's file is refused at once (66),
 * not waited on. */
START_TEST(test_scaling_merge_limits)
{
    char dir[64], t[4][300], out[300], name[32], fifo[300], side[330], cmd[700];
    cli_run r;
    cli_scratch(dir, sizeof dir, "scale");
    make_tiles(dir, "pfm");
    for (int i = 0; i < 4; i++) {
        snprintf(name, sizeof name, "t%d.pfm", i);
        cli_path(t[i], sizeof t[i], dir, name);
    }
    cli_path(out, sizeof out, dir, "out.pfm");
    const char *over[] = {"merge", t[0], t[1], t[2], t[3], "-o", out, "--max-pixels", "959", NULL};
    cli_refray(&r, over);
    ck_assert_msg(r.code == 65, "exit %d: %s", r.code, r.err);
    ASSERT_ERR_HAS(&r, "the image is 40x24, over --max-pixels 959");
    ck_assert(!cli_exists(out));
    const char *at[] = {"merge", t[0], t[1], t[2], t[3], "-o", out, "--max-pixels", "960", NULL};
    cli_refray(&r, at);
    ck_assert_msg(r.code == 0, "exit %d: %s", r.code, r.err);
    ck_assert_int_eq(unlink(out), 0);
    /* t3's pixels swapped for a FIFO nobody writes, then a directory. */
    cli_path(fifo, sizeof fifo, dir, "f.pfm");
    snprintf(cmd, sizeof cmd, "cp '%s' '%s'", t[3], fifo);
    ck_assert_int_eq(system(cmd), 0);
    snprintf(side, sizeof side, "%s.tile", fifo);
    ck_assert_int_eq(mkfifo(side, 0600), 0);
    const char *with_fifo[] = {"merge", t[0], t[1], t[2], fifo, "-o", out, NULL};
    cli_refray(&r, with_fifo);
    ck_assert_msg(r.code == 66, "exit %d: %s", r.code, r.err);
    ASSERT_ERR_HAS(&r, "not a regular file");
    ck_assert_int_eq(unlink(side), 0);
    ck_assert_int_eq(mkdir(side, 0700), 0);
    cli_refray(&r, with_fifo);
    ck_assert_msg(r.code == 66, "exit %d: %s", r.code, r.err);
    ASSERT_ERR_HAS(&r, "is a directory");
    ck_assert(!cli_exists(out));
    ck_assert_int_eq(files_with(dir, ".refray-tmp-"), 0);
    cli_remove(dir);
}
END_TEST

/* Renders tile 0/2 of scenes[0] and 1/2 of scenes[1] and scenes[2] at
 * width x height with light_samples into dir/t0.pfm .. t2.pfm (paths into t). */
static void render_tiles(const char *dir, const char *const *scenes, const char *width, const char *height,
                         const char *light_samples, char t[3][300])
{
    static const char *const specs[3] = {"0/2", "1/2", "1/2"};
    static cli_run r;
    char name[32];
    for (int i = 0; i < 3; i++) {
        snprintf(name, sizeof name, "t%d.pfm", i);
        const char *args[] = {"render", scenes[i], "-q", "--width", width, "--height", height, "--light-samples",
                              light_samples, "--tile", specs[i], "-o", cli_path(t[i], sizeof t[i], dir, name), NULL};
        cli_refray(&r, args);
        ck_assert_msg(r.code == 0, "render: %s", r.err);
    }
}

/* [SCALE-MERGE-2] Merging tiles a and b into dir/x.pfm (its path into
 * merged) is refused (65) as two renders', writing nothing. */
static void merge_refused(const char *dir, const char *a, const char *b, char *merged, size_t size)
{
    static cli_run r;
    const char *mixed[] = {"merge", a, b, "-o", cli_path(merged, size, dir, "x.pfm"), NULL};
    cli_refray(&r, mixed);
    ck_assert_msg(r.code == 65, "exit %d: %s", r.code, r.err);
    ASSERT_ERR_HAS(&r, "comes from another render");
    ck_assert(!cli_exists(merged));
}

#if REFRAY_HAVE_JSON
/* [SCALE-MERGE-1] [SCALE-MERGE-2] Tiles of a JSON scene (spec/json.md; the
 * demo exported) merge into the bytes of its whole render; the JSON's text
 * is in the key, so a tile of the same scene written with one more space
 * is refused as another render's. */
START_TEST(test_scaling_json_scene)
{
    char dir[64], json[300], edited[300], whole[300], merged[300], t[3][300], cmd[1000], name[32];
    static cli_run r;
    cli_scratch(dir, sizeof dir, "scale");
    const char *exp[] = {"export", SCENE, "--to", "json", "-o", cli_path(json, sizeof json, dir, "demo.json"), NULL};
    cli_refray(&r, exp);
    ck_assert_msg(r.code == 0, "export: %s", r.err);
    snprintf(cmd, sizeof cmd, "{ cat '%s'; echo ' '; } > '%s'", json, cli_path(edited, sizeof edited, dir, "e.json"));
    ck_assert_int_eq(system(cmd), 0);
    const char *which[3] = {json, json, edited};
    render_tiles(dir, which, "40", "24", "8", t);
    snprintf(name, sizeof name, "whole.%s", display_ext());
    const char *args[] = {"render", json, "-q", "--width", "40", "--height", "24", "--light-samples", "8", "-o",
                          cli_path(whole, sizeof whole, dir, name), NULL};
    cli_refray(&r, args);
    ck_assert_int_eq(r.code, 0);
    snprintf(name, sizeof name, "m.%s", display_ext());
    const char *merge[] = {"merge", t[0], t[1], "-o", cli_path(merged, sizeof merged, dir, name), NULL};
    cli_refray(&r, merge);
    ck_assert_msg(r.code == 0, "merge: %s", r.err);
    same_bytes(whole, merged);
    merge_refused(dir, t[0], t[2], merged, sizeof merged);
    cli_remove(dir);
}
END_TEST
#endif

/* Copies scenes/mesh.scene and its OBJ into dir/sub, the OBJ's first
 * vertex line ("v ...") replaced by vertex when not NULL; the scene's path
 * into scene. */
static void mesh_scene_copy(const char *dir, const char *sub, const char *vertex, char *scene, size_t size)
{
    char cmd[1400], where[300];
    cli_path(where, sizeof where, dir, sub);
    snprintf(cmd, sizeof cmd,
             "mkdir -p '%s/models' && cp scenes/mesh.scene '%s/' && "
             "awk -v v='%s' '!done && /^v / && v != \"\" { print v; done = 1; next } { print }' "
             "scenes/models/icosahedron.obj > '%s/models/icosahedron.obj'",
             where, where, vertex ? vertex : "", where);
    ck_assert_int_eq(system(cmd), 0);
    cli_path(scene, size, where, "mesh.scene");
}

/* [TILE-FILE-1] [SCALE-MERGE-2] The key covers a scene's meshes (whose
 * file text the loader lets go once the mesh is built): tiles of the same
 * scene text whose OBJ differs in one vertex are refused as two renders';
 * tiles of two copies of the same files merge into the whole render. */
START_TEST(test_scaling_mesh_in_the_key)
{
    char dir[64], a[300], b[300], c[300], t[3][300], whole[300], merged[300];
    static cli_run r;
    cli_scratch(dir, sizeof dir, "scale");
    mesh_scene_copy(dir, "a", NULL, a, sizeof a);
    mesh_scene_copy(dir, "b", "v 0 1.2 0.2", b, sizeof b);
    mesh_scene_copy(dir, "c", NULL, c, sizeof c);
    const char *scenes[3] = {a, b, c};
    render_tiles(dir, scenes, "32", "20", "4", t);
    merge_refused(dir, t[0], t[1], merged, sizeof merged);
    const char *args[] = {"render", a, "-q", "--width", "32", "--height", "20", "--light-samples", "4", "-o",
                          cli_path(whole, sizeof whole, dir, "whole.pfm"), NULL};
    cli_refray(&r, args);
    ck_assert_int_eq(r.code, 0);
    const char *same[] = {"merge", t[0], t[2], "-o", merged, NULL};
    cli_refray(&r, same);
    ck_assert_msg(r.code == 0, "merge: %s", r.err);
    same_bytes(whole, merged);
    cli_remove(dir);
}
END_TEST

/* [SCALE-TILE-2] Options that cannot give a tile are usage errors (64). */
START_TEST(test_scaling_usage_errors)
{
    static const struct {
        const char *args[8];
        const char *message;
    } cases[] = {
        {{"--tile", "0/2", "-o", "/tmp/t.png", NULL}, "display codes"},
        {{"--tile", "0/2", "-o", "-", NULL}, "not to -o -"},
        {{"--tile", "4/4", "-o", "/tmp/t.pfm", NULL}, "--tile's I"},
        {{"--tile", "0/25", "-o", "/tmp/t.pfm", NULL}, "the image has 24 rows"},
        {{"--tile", "2", "-o", "/tmp/t.pfm", NULL}, "I/N"},
        {{"--region", "0", "0", "41", "5", "-o", "/tmp/t.pfm", NULL}, "not inside the 40x24 image"},
        {{"--region", "0", "0", "40", "-o", "/tmp/t.pfm", NULL}, "Y1"},
        {{"-o", "/tmp/t.pfm", "--checkpoint", NULL}, "--checkpoint needs a value"},
        {{"--jobs", "-1", "-o", "/tmp/t.pfm", NULL}, "--jobs"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        cli_run *r = render(64, cases[k].args);
        ASSERT_ERR_HAS(r, cases[k].message);
    }
    const char *both[] = {"--region", "0", "0", "4", "4", "--tile", "0/2", "-o", "/tmp/t.pfm", NULL};
    cli_run r;
    const char *args[64];
    render_args(args, SMALL, both);
    cli_refray(&r, args);
    ck_assert_int_eq(r.code, 64);
    ASSERT_ERR_HAS(&r, "give one");
    const char *none[] = {"merge", "-o", "/tmp/x.pfm", NULL};
    cli_refray(&r, none);
    ck_assert_int_eq(r.code, 64);
    ASSERT_ERR_HAS(&r, "no tiles given");
}
END_TEST

/* refray with args (NULL-terminated) in the background, its output in
 * dir/err.txt; with a file size limit when limit > 0. */
static pid_t spawn(const char *dir, const char *const *args, long limit)
{
    char err[300];
    const char *argv[64];
    int n = 0;
    argv[n++] = cli_refray_bin();
    for (int i = 0; args[i]; i++)
        argv[n++] = args[i];
    argv[n] = NULL;
    cli_path(err, sizeof err, dir, "err.txt");
    fflush(NULL);
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        int fd = open(err, O_WRONLY | O_CREAT | O_TRUNC, 0644), null = open("/dev/null", O_RDWR);
        struct rlimit rl = {(rlim_t)limit, (rlim_t)limit};
        if (limit > 0)
            setrlimit(RLIMIT_FSIZE, &rl);
        dup2(null, 0);
        dup2(null, 1);
        dup2(fd, 2);
        cli_signals_default();
        execv(argv[0], (char *const *)argv);
        _exit(127);
    }
    return pid;
}

/* Waits for pid; its exit code (-1 after a signal) and stderr into r. */
static void finish(const char *dir, pid_t pid, cli_run *r)
{
    int status;
    char path[300];
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    r->code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    FILE *f = fopen(cli_path(path, sizeof path, dir, "err.txt"), "rb");
    ck_assert_ptr_nonnull(f);
    cli_slurp(f, r->err, sizeof r->err);
    r->out[0] = '\0';
}

/* [SCALE-MERGE-4] A full disk (a file size limit, RLIMIT_FSIZE) while
 * merge writes, or while render writes a tile or the image of --jobs:
 * exit 74 with the reason, nothing written, no temporary file. */
START_TEST(test_scaling_full_disk)
{
    char dir[64], out[300], tile[300];
    static cli_run r;
    cli_scratch(dir, sizeof dir, "scale");
    make_tiles(dir, "pfm");
    cli_path(out, sizeof out, dir, "out.pfm");
    char p[4][300];
    for (int i = 0; i < 4; i++) {
        char name[16];
        snprintf(name, sizeof name, "t%d.pfm", i);
        cli_path(p[i], sizeof p[i], dir, name);
    }
    const char *merge[] = {"merge", p[0], p[1], p[2], p[3], "-o", out, NULL};
    finish(dir, spawn(dir, merge, 4096), &r);
    ck_assert_msg(r.code == 74, "exit %d: %s", r.code, r.err);
    ASSERT_ERR_HAS(&r, "File too large");
    const char *tile_args[] = {"--tile", "0/2", "-q", "-o", cli_path(tile, sizeof tile, dir, "big.pfm"), NULL};
    const char *jobs_args[] = {"--jobs", "2", "-q", "-o", out, NULL};
    const char *const *extras[] = {tile_args, jobs_args};
    for (int k = 0; k < 2; k++) {
        const char *args[64];
        render_args(args, SMALL, extras[k]);
        finish(dir, spawn(dir, args, 2048), &r);
        ck_assert_msg(r.code == 74, "exit %d: %s", r.code, r.err);
        ASSERT_ERR_HAS(&r, "File too large");
    }
    ck_assert(!cli_exists(out));
    ck_assert_int_eq(files_with(dir, "big.pfm"), 0);
    ck_assert_int_eq(files_with(dir, ".refray-tmp-"), 0);
    cli_remove(dir);
}
END_TEST

/* Valgrind and the sanitizers make everything slower. */
static double slowness(void)
{
    const char *v = getenv("REFRAY_TEST_VALGRIND");
    return v && strcmp(v, "1") == 0 ? 20 : 1;
}

static void nap_ms(long ms)
{
    struct timespec ts = {ms / 1000, (ms % 1000) * 1000000L};
    nanosleep(&ts, NULL);
}

/* The children of pid (its workers), up to max, from /proc. */
static int children_of(pid_t pid, pid_t *kids, int max)
{
    DIR *d = opendir("/proc");
    int n = 0;
    ck_assert_ptr_nonnull(d);
    for (struct dirent *e; (e = readdir(d)) != NULL && n < max;) {
        char path[300], text[512];
        if (e->d_name[0] < '0' || e->d_name[0] > '9')
            continue;
        snprintf(path, sizeof path, "/proc/%s/stat", e->d_name);
        FILE *f = fopen(path, "r");
        if (!f)
            continue;
        size_t got = fread(text, 1, sizeof text - 1, f);
        fclose(f);
        text[got] = '\0';
        const char *close = strrchr(text, ')');
        long ppid = 0;
        if (close && sscanf(close + 1, " %*c %ld", &ppid) == 1 && ppid == (long)pid)
            kids[n++] = (pid_t)atol(e->d_name);
    }
    closedir(d);
    return n;
}

/* Waits up to a few seconds for pid to have want workers. */
static int wait_for_workers(pid_t pid, pid_t *kids, int want)
{
    int n = 0;
    for (int i = 0; i < (int)(2000 * slowness()) && (n = children_of(pid, kids, 8)) < want; i++)
        nap_ms(5);
    return n;
}

static void no_process_left(const pid_t *kids, int n)
{
    for (int i = 0; i < n; i++) {
        int gone = 0;
        for (int k = 0; k < 200 && !gone; k++) {
            gone = kill(kids[i], 0) != 0 && errno == ESRCH;
            if (!gone)
                nap_ms(10);
        }
        ck_assert_msg(gone, "worker %ld is still there", (long)kids[i]);
    }
}

/* [SCALE-JOBS-3] [SCALE-JOBS-4] A worker killed by SIGKILL: exit 70
 * naming it; SIGINT to refray: exit 130, SIGTERM: 143 (128 + the signal,
 * spec/reliability.md).  Either way no output, no temporary file, no
 * worker left. */
START_TEST(test_scaling_killed_worker_and_sigint)
{
    char dir[64], out[300];
    static cli_run r;
    cli_scratch(dir, sizeof dir, "scale");
    cli_path(out, sizeof out, dir, "out.pfm");
    static const int stop[3] = {SIGKILL, SIGINT, SIGTERM};
    for (int k = 0; k < 3; k++) {
        pid_t kids[8];
        const char *extra[] = {"--jobs", "2", "-q", "-o", out, NULL}, *args[64];
        render_args(args, SLOW, extra);
        pid_t pid = spawn(dir, args, 0);
        int n = wait_for_workers(pid, kids, 2);
        ck_assert_msg(n == 2, "refray has %d workers", n);
        nap_ms(50);
        ck_assert_int_eq(kill(k == 0 ? kids[1] : pid, stop[k]), 0);
        finish(dir, pid, &r);
        if (k == 0) {
            ck_assert_msg(r.code == 70, "exit %d: %s", r.code, r.err);
            ASSERT_ERR_HAS(&r, "was killed by SIGKILL while rendering rows");
        } else {
            ck_assert_msg(r.code == 128 + stop[k], "exit %d: %s", r.code, r.err);
            ASSERT_ERR_HAS(&r, "interrupted; nothing written");
        }
        no_process_left(kids, n);
        ck_assert(!cli_exists(out));
        ck_assert_int_eq(files_with(dir, ".refray-tmp-"), 0);
    }
    cli_remove(dir);
}
END_TEST

/* What refray with args writes to its standard error when that is a
 * terminal (a pseudo-terminal here), into buf. */
static void run_on_terminal(const char *const *args, char *buf, size_t size)
{
    const char *argv[64];
    int n = 0, master = posix_openpt(O_RDWR | O_NOCTTY), status;
    ck_assert_int_ge(master, 0);
    ck_assert_int_eq(grantpt(master), 0);
    ck_assert_int_eq(unlockpt(master), 0);
    const char *slave = ptsname(master);
    ck_assert_ptr_nonnull(slave);
    argv[n++] = cli_refray_bin();
    for (int i = 0; args[i]; i++)
        argv[n++] = args[i];
    argv[n] = NULL;
    fflush(NULL);
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        int tty = open(slave, O_RDWR | O_NOCTTY), null = open("/dev/null", O_RDWR);
        dup2(null, 0);
        dup2(null, 1);
        dup2(tty, 2);
        close(master);
        cli_signals_default();
        execv(argv[0], (char *const *)argv);
        _exit(127);
    }
    size_t used = 0;
    ssize_t got;
    /* Linux reports EIO once the last holder of the terminal has gone. */
    while (used + 1 < size && (got = read(master, buf + used, size - 1 - used)) > 0)
        used += (size_t)got;
    buf[used] = '\0';
    close(master);
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    ck_assert_msg(WIFEXITED(status) && WEXITSTATUS(status) == 0, "refray failed: %s", buf);
}

/* [SCALE-JOBS-5] --jobs 3 draws one progress bar for the whole image on
 * a terminal: its percentages never go back, it reaches 100 % once, and
 * it ends its line once. */
START_TEST(test_scaling_one_progress_bar)
{
    char dir[64], out[300];
    static char text[1 << 16];
    cli_scratch(dir, sizeof dir, "scale");
    const char *extra[] = {"--jobs", "3", "-o", cli_path(out, sizeof out, dir, "o.pfm"), NULL}, *args[64];
    render_args(args, SLOW, extra);
    run_on_terminal(args, text, sizeof text);
    int last = -1, full = 0, bars = 0, lines = 0;
    for (const char *p = text; *p; p++) {
        lines += *p == '\n';
        if (*p != '[')
            continue;
        const char *pct = strchr(p, '%');
        ck_assert_ptr_nonnull(pct);
        int v = atoi(pct - 3);
        ck_assert_msg(v >= last, "the bar went back from %d %% to %d %%:\n%s", last, v, text);
        last = v;
        full += v == 100;
        bars++;
    }
    ck_assert_msg(bars >= 2 && full == 1 && last == 100, "%d bars, %d at 100 %%:\n%s", bars, full, text);
    ck_assert_msg(lines == 1, "%d lines:\n%s", lines, text);
    cli_remove(dir);
}
END_TEST

/* [SCALE-RESUME-1] A render with --checkpoint stopped by SIGINT after its
 * first tiles keeps them and writes nothing; the same command renders
 * only the other bands (the checkpoint's split, [TILE-SPLIT-2], though
 * --jobs changed) and
 * writes the bytes of an uninterrupted render; the checkpoint is gone.
 * The checkpoint's name holds a line feed and an ESC sequence, which both
 * messages naming it print escaped ([REL-ESCAPE-1]). */
START_TEST(test_scaling_resume)
{
    char dir[64], ck[300], out[300], plain[300], note[400];
    static cli_run r;
    cli_scratch(dir, sizeof dir, "scale");
    cli_path(ck, sizeof ck, dir, "ck\n\033[31m");
    snprintf(note, sizeof note, "out.%s", display_ext());
    cli_path(out, sizeof out, dir, note);
    const char *first[] = {"--jobs", "20", "-q", "--checkpoint", ck, "-o", out, NULL}, *args[64];
    render_args(args, SLOW, first);
    pid_t pid = spawn(dir, args, 0);
    int kept = 0;
    for (int i = 0; i < (int)(4000 * slowness()) && kept < 1; i++) {
        nap_ms(5);
        kept = cli_exists(ck) ? files_with(ck, ".pfm.tile") : 0;
    }
    ck_assert_int_ge(kept, 1);
    ck_assert_int_eq(kill(pid, SIGINT), 0);
    finish(dir, pid, &r);
    ck_assert_msg(r.code == 130, "exit %d: %s", r.code, r.err);
    snprintf(note, sizeof note, "nothing written but the finished tiles in '%s/ck\\x0a\\x1b[31m' (", dir);
    ASSERT_ERR_HAS(&r, note);
    ck_assert_msg(strchr(r.err, '\033') == NULL, "%s", r.err);
    ck_assert(!cli_exists(out));
    kept = files_with(ck, ".pfm.tile");
    /* 80 rows, 20 workers: min(80, max(64, 4 x 20)) = 80 bands. */
    ck_assert_msg(kept >= 1 && kept < 80, "%d tiles kept", kept);
    ck_assert_int_eq(files_with(ck, ".refray-tmp-"), 0);

    const char *again[] = {"--jobs", "1", "--checkpoint", ck, "-o", out, NULL};
    render_args(args, SLOW, again);
    cli_refray(&r, args);
    ck_assert_msg(r.code == 0, "exit %d: %s", r.code, r.err);
    snprintf(note, sizeof note, "refray: resuming from '%s/ck\\x0a\\x1b[31m': %d of 80 tiles are done\n", dir,
             kept);
    ASSERT_ERR_HAS(&r, note);
    ck_assert_msg(strchr(r.err, '\033') == NULL, "%s", r.err);
    ck_assert(!cli_exists(ck));
    snprintf(note, sizeof note, "plain.%s", display_ext());
    const char *whole[] = {"-q", "-o", cli_path(plain, sizeof plain, dir, note), NULL};
    render_args(args, SLOW, whole);
    cli_refray(&r, args);
    ck_assert_int_eq(r.code, 0);
    same_bytes(plain, out);
    cli_remove(dir);
}
END_TEST

/* Sets the last double of the sidecar at path (the last pixel's blue) to
 * a value a render could write that is far from the one there: a changed
 * byte that neither the length nor the value check can see. */
static void change_last_value(const char *path)
{
    FILE *f = fopen(path, "r+b");
    unsigned char le[8];
    ck_assert_ptr_nonnull(f);
    ck_assert_int_eq(fseek(f, -8, SEEK_END), 0);
    ck_assert_int_eq(fread(le, 1, 8, f), 8);
    uint64_t bits = 0;
    for (int i = 7; i >= 0; i--)
        bits = bits << 8 | le[i];
    double v;
    memcpy(&v, &bits, sizeof v);
    v = v < 0.5 ? 0.75 : 0.125;
    memcpy(&bits, &v, sizeof bits);
    for (int i = 0; i < 8; i++)
        le[i] = (unsigned char)(bits >> (8 * i));
    ck_assert_int_eq(fseek(f, -8, SEEK_END), 0);
    ck_assert_int_eq(fwrite(le, 1, 8, f), 8);
    ck_assert_int_eq(fclose(f), 0);
}

/* The whole tile sidecars of dir (a checkpoint), not the temporary files
 * of their writes; the first one's path into path. */
static int sidecars(const char *dir, char *path, size_t size)
{
    DIR *d = opendir(dir);
    int found = 0;
    ck_assert_ptr_nonnull(d);
    for (struct dirent *e; (e = readdir(d)) != NULL;) {
        size_t n = strlen(e->d_name);
        if (strncmp(e->d_name, "tile-", 5) == 0 && n > 9 && strcmp(e->d_name + n - 9, ".pfm.tile") == 0 &&
            found++ == 0 && path)
            cli_path(path, size, dir, e->d_name);
    }
    closedir(d);
    return found;
}

/* [SCALE-RESUME-1] [SCALE-RESUME-3] --jobs 2 --checkpoint stopped the hard
 * way: refray itself killed by SIGKILL (a power cut: nothing of it runs
 * after), or one of its workers killed (exit 70).  The finished tiles stay;
 * after the parent's death its workers are gone too.  The same command
 * then resumes from them (a tile damaged meanwhile, cut short or one of
 * its values changed (tests/attack12 finding 3), is rendered again, with
 * a warning), writes the bytes of an uninterrupted render, and removes the
 * checkpoint with the temporary files of the cut writes. */
START_TEST(test_scaling_resume_after_kill)
{
    char dir[64], ck[300], out[300], plain[300], name[40], side[330], note[200];
    static cli_run r;
    cli_scratch(dir, sizeof dir, "scale");
    cli_path(ck, sizeof ck, dir, "ck");
    snprintf(name, sizeof name, "plain.%s", display_ext());
    const char *whole[] = {"-q", "-o", cli_path(plain, sizeof plain, dir, name), NULL}, *args[64];
    render_args(args, SLOW, whole);
    cli_refray(&r, args);
    ck_assert_int_eq(r.code, 0);
    snprintf(name, sizeof name, "out.%s", display_ext());
    cli_path(out, sizeof out, dir, name);
    for (int k = 0; k < 2; k++) {
        pid_t kids[8];
        const char *extra[] = {"--jobs", "2", "--checkpoint", ck, "-o", out, NULL};
        render_args(args, SLOW, extra);
        pid_t pid = spawn(dir, args, 0);
        int n = wait_for_workers(pid, kids, 2), kept = 0;
        ck_assert_msg(n == 2, "refray has %d workers", n);
        /* Two tiles: one stays whole when the other is damaged. */
        for (int i = 0; i < (int)(4000 * slowness()) && kept < 2; i++) {
            nap_ms(5);
            kept = cli_exists(ck) ? sidecars(ck, NULL, 0) : 0;
        }
        ck_assert_int_ge(kept, 2);
        ck_assert_int_eq(kill(k == 0 ? pid : kids[0], SIGKILL), 0);
        finish(dir, pid, &r);
        if (k == 0) {
            ck_assert_msg(r.code == -1, "exit %d: %s", r.code, r.err);
        } else {
            ck_assert_msg(r.code == 70, "exit %d: %s", r.code, r.err);
            ASSERT_ERR_HAS(&r, "was killed by SIGKILL");
        }
        no_process_left(kids, n);
        ck_assert(!cli_exists(out));
        kept = sidecars(ck, side, sizeof side);
        /* 80 rows, 2 workers: min(80, max(64, 4 x 2)) = 64 bands. */
        ck_assert_msg(kept >= 2 && kept < 64, "%d tiles kept", kept);
        if (k == 0)
            ck_assert_int_eq(truncate(side, 40), 0);
        else
            change_last_value(side);
        kept--;
        cli_refray(&r, args);
        ck_assert_msg(r.code == 0, "exit %d: %s", r.code, r.err);
        snprintf(note, sizeof note, "%d of 64 tiles are done", kept);
        ASSERT_ERR_HAS(&r, note);
        ASSERT_ERR_HAS(&r, "rendering that tile again");
        ck_assert(!cli_exists(ck));
        same_bytes(plain, out);
        ck_assert_int_eq(files_with(dir, ".refray-tmp-"), 0);
        ck_assert_int_eq(unlink(out), 0);
    }
    cli_remove(dir);
}
END_TEST

/* Counts the times needle is in text. */
static int occurrences(const char *text, const char *needle)
{
    int n = 0;
    for (const char *p = text; (p = strstr(p, needle)) != NULL; p += strlen(needle))
        n++;
    return n;
}

/* [SCALE-RESUME-5] Two renders of the same command at once with one
 * --checkpoint DIR (tests/attack13 finding 5): B loads A's tiles, renders
 * the rest, writes its output and removes DIR while A is still rendering;
 * A then cannot save its next band.  Before, A gave up with exit 74 and
 * its finished image ("nothing written"); now both write the bytes of an
 * uninterrupted render, A after one warning.  The interleaving is made,
 * not waited for: A is stopped (SIGSTOP) with a band still to save and no
 * write of its in flight, B runs whole, then A goes on. */
START_TEST(test_scaling_checkpoint_shared_by_two)
{
    char dir[64], ck[300], plain[300], a_out[300], b_out[300];
    static cli_run r;
    cli_scratch(dir, sizeof dir, "scale");
    cli_path(ck, sizeof ck, dir, "ck");
    const char *whole[] = {"-q", "-o", cli_path(plain, sizeof plain, dir, "plain.pfm"), NULL}, *args[64];
    render_args(args, SLOW, whole);
    cli_refray(&r, args);
    ck_assert_int_eq(r.code, 0);
    const char *a_extra[] = {"--jobs", "2", "-q", "--checkpoint", ck, "-o",
                             cli_path(a_out, sizeof a_out, dir, "a.pfm"), NULL};
    render_args(args, SLOW, a_extra);
    pid_t pid = spawn(dir, args, 0);
    int kept = 0, stopped = 0;
    for (int i = 0; i < (int)(4000 * slowness()) && !stopped; i++) {
        nap_ms(5);
        if (!cli_exists(ck) || sidecars(ck, NULL, 0) < 1)
            continue;
        ck_assert_int_eq(kill(pid, SIGSTOP), 0);
        nap_ms(20);
        kept = sidecars(ck, NULL, 0);
        /* A write cut by the stop would keep DIR from going. */
        stopped = files_with(ck, ".refray-tmp-") == 0;
        if (!stopped)
            ck_assert_int_eq(kill(pid, SIGCONT), 0);
    }
    ck_assert_msg(stopped, "A never stopped between two saves");
    /* 80 rows, 2 workers: 64 bands; A has at least one band to save. */
    ck_assert_msg(kept >= 1 && kept < 64, "%d tiles kept", kept);

    const char *b_extra[] = {"--jobs", "2", "--checkpoint", ck, "-o", cli_path(b_out, sizeof b_out, dir, "b.pfm"),
                             NULL};
    render_args(args, SLOW, b_extra);
    cli_refray(&r, args);
    ck_assert_msg(r.code == 0, "B: exit %d: %s", r.code, r.err);
    ASSERT_ERR_HAS(&r, "resuming from");
    ck_assert(!cli_exists(ck));
    same_bytes(plain, b_out);

    ck_assert_int_eq(kill(pid, SIGCONT), 0);
    finish(dir, pid, &r);
    ck_assert_msg(r.code == 0, "A: exit %d: %s", r.code, r.err);
    ck_assert_msg(occurrences(r.err, "warning: cannot save a tile into the checkpoint") == 1, "%s", r.err);
    ASSERT_ERR_HAS(&r, "rendering on without the checkpoint");
    same_bytes(plain, a_out);
    ck_assert(!cli_exists(ck));
    ck_assert_int_eq(files_with(dir, ".refray-tmp-"), 0);
    cli_remove(dir);
}
END_TEST

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    ck_assert_ptr_nonnull(f);
    fputs(text, f);
    ck_assert_int_eq(fclose(f), 0);
}

/* [SCALE-RESUME-2] A checkpoint directory of another render (another
 * key, another size) or with a manifest that is not one: exit 65, the
 * directory untouched, nothing written. */
START_TEST(test_scaling_checkpoint_of_another_render)
{
    static const struct {
        const char *manifest, *message;
    } cases[] = {
        {"refray-checkpoint 1\nimage 40 24\nregion 0 0 40 24\nkey 0000000000000001\nbands 24\n",
         "belongs to another render (a 40x24 image, x 0..39, y 0..23, key 0000000000000001)"},
        {"refray-checkpoint 1\nimage 64 24\nregion 0 0 64 24\nkey 0000000000000001\nbands 24\n",
         "belongs to another render (a 64x24 image"},
        {"hello\n", "is not a refray checkpoint manifest"},
    };
    char dir[64], ck[300], manifest[330], out[300];
    cli_scratch(dir, sizeof dir, "scale");
    cli_path(ck, sizeof ck, dir, "ck");
    ck_assert_int_eq(mkdir(ck, 0777), 0);
    snprintf(manifest, sizeof manifest, "%s/refray-checkpoint", ck);
    cli_path(out, sizeof out, dir, "out.pfm");
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char *back;
        long len;
        write_text(manifest, cases[k].manifest);
        const char *extra[] = {"-q", "--checkpoint", ck, "-o", out, NULL};
        cli_run *r = render(65, extra);
        ASSERT_ERR_HAS(r, cases[k].message);
        read_all(manifest, &back, &len);
        back[len] = '\0';
        ck_assert_str_eq(back, cases[k].manifest);
        free(back);
        ck_assert_int_eq(cli_entries(ck), 1);
        ck_assert(!cli_exists(out));
    }
    cli_remove(dir);
}
END_TEST

/* sh -c command; its exit code. */
static int shell(const char *command)
{
    int status = system(command);
    return status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/* The whole render of the small view into dir/NAME. */
static void whole_render(const char *dir, const char *name, char *path, size_t size)
{
    render_to(cli_path(path, size, dir, name), NULL, NULL);
}

/* [SCALE-RESUME-4] The checkpoint removes its own files by exact name and
 * nothing else (tests/attack12 finding 2: every tile-* and
 * refray-checkpoint* name went, the user's files and the output among
 * them, after exit 0); an output named as one of its files is refused
 * before rendering (64), and a directory without a manifest holding a
 * file named as one of its tiles is refused (65), each leaving DIR as it
 * was. */
START_TEST(test_scaling_checkpoint_leaves_others)
{
    static const char *const theirs[] = {"tile-0.exr", "tile-1.pfm", "tile-1.pfm.tile", "tile-notes.txt",
                                         "refray-checkpoint-notes.md", "tile-00000.pfm.bak", "tile-000001.pfm"};
    char dir[64], ck[300], out[340], path[340], plain[300];
    size_t n = sizeof theirs / sizeof theirs[0];
    cli_scratch(dir, sizeof dir, "scale");
    cli_path(ck, sizeof ck, dir, "ck");
    ck_assert_int_eq(mkdir(ck, 0777), 0);
    for (size_t k = 0; k < n; k++)
        write_text(cli_path(path, sizeof path, ck, theirs[k]), "mine\n");
    whole_render(dir, "plain.pfm", plain, sizeof plain);
    /* The output itself named like a tile, in the checkpoint: kept. */
    const char *extra[] = {"-q", "--checkpoint", ck, "-o", cli_path(out, sizeof out, ck, "tile-final.pfm"), NULL};
    render(0, extra);
    same_bytes(plain, out);
    for (size_t k = 0; k < n; k++)
        ck_assert_msg(cli_exists(cli_path(path, sizeof path, ck, theirs[k])), "%s was removed", theirs[k]);
    ck_assert_int_eq(cli_entries(ck), (int)n + 1);
    ck_assert_int_eq(unlink(out), 0);

    /* An output the checkpoint would write and remove: 64, nothing made. */
    static const char *const clashes[] = {"tile-00003.pfm", "tile-00000.pfm"};
    for (size_t k = 0; k < sizeof clashes / sizeof clashes[0]; k++) {
        char other[360];
        snprintf(other, sizeof other, "%s/../ck/%s", ck, clashes[k]);
        const char *clash[] = {"-q", "--checkpoint", ck, "-o", other, NULL};
        cli_run *r = render(64, clash);
        ASSERT_ERR_HAS(r, "a name the checkpoint");
        ck_assert_int_eq(cli_entries(ck), (int)n);
    }

    /* A tile's name there without a manifest: someone else's file. */
    write_text(cli_path(path, sizeof path, ck, "tile-00002.pfm"), "mine\n");
    const char *fresh[] = {"-q", "--checkpoint", ck, "-o", cli_path(out, sizeof out, dir, "out.pfm"), NULL};
    cli_run *r = render(65, fresh);
    ASSERT_ERR_HAS(r, "a name the checkpoint writes, but no checkpoint manifest");
    ck_assert_int_eq(cli_entries(ck), (int)n + 1);
    ck_assert(!cli_exists(out));
    cli_remove(dir);
}
END_TEST

/* [SCALE-PARALLEL-1] The GNU parallel recipe of spec/scaling.md,
 * examples/scaling/parallel-tiles.sh, renders 5 tiles on this machine and
 * merges them into the bytes of the whole render. */
START_TEST(test_scaling_gnu_parallel)
{
    char dir[64], whole[300], out[300], name[32], cmd[1200];
    ck_assert_msg(shell("command -v parallel >/dev/null") == 0,
                  "GNU parallel is missing (make deps installs Debian's parallel)");
    cli_scratch(dir, sizeof dir, "scale");
    snprintf(name, sizeof name, "whole.%s", display_ext());
    whole_render(dir, name, whole, sizeof whole);
    snprintf(name, sizeof name, "par.%s", display_ext());
    snprintf(cmd, sizeof cmd,
             "REFRAY='%s' TILE_EXT=%s TILES='%s/tiles' sh examples/scaling/parallel-tiles.sh %s '%s' 5 "
             "--width 40 --height 24 --light-samples 8 2>'%s/err.txt' && ! ls '%s/tiles' 2>/dev/null | grep -q tmp",
             cli_refray_bin(), have(IMG_FORMAT_EXR) ? "exr" : "pfm", dir, SCENE,
             cli_path(out, sizeof out, dir, name), dir, dir);
    ck_assert_msg(shell(cmd) == 0, "%s failed", cmd);
    same_bytes(whole, out);
    cli_remove(dir);
}
END_TEST

/* [SCALE-SLURM-1] The Slurm recipe's task script, run as Slurm runs the
 * tasks of `sbatch --array=0-4` (SLURM_ARRAY_TASK_ID, _COUNT set; one task
 * with SLURM_CPUS_PER_TASK=2), then merged: the whole render's bytes.
 * Outside an array it refuses to run. */
START_TEST(test_scaling_slurm_array_task)
{
    char dir[64], whole[300], out[300], name[32], cmd[1200];
    const char *ext = have(IMG_FORMAT_EXR) ? "exr" : "pfm";
    cli_scratch(dir, sizeof dir, "scale");
    snprintf(name, sizeof name, "whole.%s", display_ext());
    whole_render(dir, name, whole, sizeof whole);
    for (int id = 0; id < 5; id++) {
        snprintf(cmd, sizeof cmd,
                 "SLURM_ARRAY_TASK_ID=%d SLURM_ARRAY_TASK_COUNT=5 %s REFRAY='%s' TILE_EXT=%s "
                 "sh examples/scaling/slurm-tiles.sbatch %s '%s' --width 40 --height 24 --light-samples 8",
                 id, id == 2 ? "SLURM_CPUS_PER_TASK=2" : "", cli_refray_bin(), ext, SCENE, dir);
        ck_assert_msg(shell(cmd) == 0, "%s failed", cmd);
    }
    snprintf(name, sizeof name, "slurm.%s", display_ext());
    snprintf(cmd, sizeof cmd, "'%s' merge '%s'/tile-*.%s -o '%s'", cli_refray_bin(), dir, ext,
             cli_path(out, sizeof out, dir, name));
    ck_assert_msg(shell(cmd) == 0, "%s failed", cmd);
    same_bytes(whole, out);
    snprintf(cmd, sizeof cmd, "REFRAY='%s' sh examples/scaling/slurm-tiles.sbatch %s '%s' 2>/dev/null",
             cli_refray_bin(), SCENE, dir);
    ck_assert_int_ne(shell(cmd), 0);
    cli_remove(dir);
}
END_TEST

/* The [SCALE-...] and [TILE-...] IDs of a text one after another: the
 * next one at or after *from into id, *from moved past it; 0 at the end. */
static int next_id(const char **from, char *id, size_t size)
{
    for (const char *p = *from; (p = strchr(p, '[')) != NULL; p++) {
        size_t n = strspn(p + 1, "ABCDEFGHIJKLMNOPQRSTUVWXYZ-0123456789");
        if ((strncmp(p + 1, "SCALE-", 6) == 0 || strncmp(p + 1, "TILE-", 5) == 0) && p[1 + n] == ']' &&
            n < size && p[n] >= '0' && p[n] <= '9') {
            memcpy(id, p + 1, n);
            id[n] = '\0';
            *from = p + 1 + n;
            return 1;
        }
    }
    return 0;
}

/* The text of every test file: the .c files of tests, the .sh of tests/scaling. */
static char *all_tests(void)
{
    static const char *const dirs[] = {"tests", "tests/scaling"};
    size_t len = 0;
    char *all = calloc(1, 1);
    for (int d = 0; d < 2; d++) {
        DIR *dir = opendir(dirs[d]);
        ck_assert_ptr_nonnull(dir);
        for (struct dirent *e; (e = readdir(dir)) != NULL;) {
            size_t n = strlen(e->d_name);
            if (n < 3 || (strcmp(e->d_name + n - 2, ".c") != 0 && strcmp(e->d_name + n - 3, ".sh") != 0))
                continue;
            char path[300], *text;
            long size;
            snprintf(path, sizeof path, "%s/%s", dirs[d], e->d_name);
            read_all(path, &text, &size);
            all = realloc(all, len + (size_t)size + 1);
            ck_assert_ptr_nonnull(all);
            memcpy(all + len, text, (size_t)size);
            len += (size_t)size;
            all[len] = '\0';
            free(text);
        }
        closedir(dir);
    }
    return all;
}

/* spec/scaling.md and the tests agree: every ID the spec defines is cited
 * by a test, every ID a test cites is in the spec. */
START_TEST(test_scaling_spec_ids)
{
    char *spec, *tests = all_tests(), id[64], quoted[70];
    long len;
    read_all("spec/scaling.md", &spec, &len);
    spec[len] = '\0';
    int count = 0;
    for (const char *p = spec; next_id(&p, id, sizeof id); count++) {
        snprintf(quoted, sizeof quoted, "[%s]", id);
        ck_assert_msg(strstr(tests, quoted) != NULL, "no test cites %s of spec/scaling.md", quoted);
    }
    ck_assert_int_ge(count, 15);
    for (const char *p = tests; next_id(&p, id, sizeof id);) {
        snprintf(quoted, sizeof quoted, "[%s]", id);
        ck_assert_msg(strstr(spec, quoted) != NULL, "a test cites %s, which spec/scaling.md lacks", quoted);
    }
    free(spec);
    free(tests);
}
END_TEST

Suite *suite_scaling(void)
{
    Suite *s = suite_create("scaling");
    TCase *files = tcase_create("tiles");
    tcase_set_timeout(files, 60);
    tcase_add_test(files, test_scaling_tile_pixels_are_the_whole_renders);
    tcase_add_test(files, test_scaling_merge_writes_the_whole_renders_bytes);
    tcase_add_test(files, test_scaling_jobs_write_the_bytes_of_one);
    tcase_add_test(files, test_scaling_merge_refusals);
    tcase_add_test(files, test_scaling_merge_limits);
    tcase_add_test(files, test_scaling_mesh_in_the_key);
#if REFRAY_HAVE_JSON
    tcase_add_test(files, test_scaling_json_scene);
#endif
    tcase_add_test(files, test_scaling_usage_errors);
    tcase_add_test(files, test_scaling_full_disk);
    tcase_add_test(files, test_scaling_spec_ids);
    suite_add_tcase(s, files);
    TCase *runs = tcase_create("runs");
    tcase_set_timeout(runs, 120);
    tcase_add_test(runs, test_scaling_killed_worker_and_sigint);
    tcase_add_test(runs, test_scaling_one_progress_bar);
    tcase_add_test(runs, test_scaling_resume);
    tcase_add_test(runs, test_scaling_resume_after_kill);
    tcase_add_test(runs, test_scaling_checkpoint_shared_by_two);
    tcase_add_test(runs, test_scaling_checkpoint_of_another_render);
    tcase_add_test(runs, test_scaling_checkpoint_leaves_others);
    tcase_add_test(runs, test_scaling_gnu_parallel);
    tcase_add_test(runs, test_scaling_slurm_array_task);
    suite_add_tcase(s, runs);
    return s;
}
