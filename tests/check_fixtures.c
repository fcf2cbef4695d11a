/*
 * check_fixtures.c - the generators of committed fixtures (tests/gen/,
 * `make fixtures`) give the committed bytes: each one runs into a fresh
 * directory and writes exactly the files listed here, each equal to the
 * one in the tree.  And the torus of the scale measurement (gen_big_mesh),
 * made small, loads as the closed mesh it is said to be, the same from OBJ
 * and from binary PLY.  The programs are $GEN_BIN_DIR/gen_NAME (set by
 * `make test`, else build/).
 */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include "io/fileio.h"
#include "io/filewrite.h"
#include "io/scene_file.h"
#include "testlib.h"

typedef struct generator {
    const char *name;
    const char *files[12]; /* what it writes, NULL-terminated */
} generator;

static const generator generators[] = {
    {"gen_sphere_meshes",
     {"scenes/models/sphere_12x8.obj", "scenes/models/sphere_24x16.obj", "scenes/models/sphere_48x32.obj", NULL}},
    {"gen_ply_corpus",
     {"tests/ply/uvsphere.obj", "tests/ply/uvsphere_ascii.ply", "tests/ply/uvsphere_le.ply",
      "tests/ply/uvsphere_be.ply", "tests/bad/inc/truncated.ply", "tests/bad/inc/index_range.ply",
      "tests/bad/inc/list_count.ply", "tests/bad/inc/nan.ply", NULL}},
    {"gen_stress",
     {"scenes/stress/critical_below.scene", "scenes/stress/critical_above.scene",
      "scenes/stress/phong_n1e6_off.scene", "scenes/stress/touching_glass_camera_inside.scene",
      "scenes/stress/camera_inside_nested_glass.scene", "scenes/stress/geosphere.obj",
      "scenes/stress/thin_strip.obj", "scenes/stress/thin_fan.obj", NULL}},
};

/* Runs $GEN_BIN_DIR/name with the arguments (NULL-terminated); its exit
 * code, -1 when it did not exit. */
static int run(const char *name, const char *const *args)
{
    const char *dir = getenv("GEN_BIN_DIR");
    char bin[512];
    snprintf(bin, sizeof bin, "%s/%s", dir && *dir ? dir : "build", name);
    ck_assert_msg(access(bin, X_OK) == 0, "no generator at %s (make test builds it)", bin);
    char *argv[8] = {bin};
    for (int i = 0; args[i]; i++)
        argv[i + 1] = (char *)args[i];
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        execv(bin, argv);
        _exit(127);
    }
    int status;
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/* Files under path (recursively). */
static int count_files(const char *path)
{
    DIR *d = opendir(path);
    if (!d)
        return 1;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        char sub[1024];
        snprintf(sub, sizeof sub, "%s/%s", path, e->d_name);
        n += count_files(sub);
    }
    closedir(d);
    return n;
}

static char *read_all(const char *path, size_t *len)
{
    char *text = NULL, why[256];
    ck_assert_msg(file_read_all(path, -1, NULL, &text, len, why, sizeof why) == STATUS_OK, "%s", why);
    return text;
}

static void make_temp(char *dir, size_t size)
{
    snprintf(dir, size, "/tmp/refray-fixtures-XXXXXX");
    ck_assert_ptr_nonnull(mkdtemp(dir));
}

static void remove_temp(const char *dir)
{
    char why[256];
    ck_assert_msg(file_remove_tree(dir, why, sizeof why) == 0, "%s", why);
}

START_TEST(test_fixtures_are_what_the_generators_write)
{
    const generator *g = &generators[_i];
    char dir[64];
    make_temp(dir, sizeof dir);
    const char *args[] = {dir, NULL};
    ck_assert_int_eq(run(g->name, args), 0);
    int n = 0;
    for (; g->files[n]; n++) {
        char made[512];
        size_t want_len, got_len;
        snprintf(made, sizeof made, "%s/%s", dir, g->files[n]);
        char *want = read_all(g->files[n], &want_len), *got = read_all(made, &got_len);
        ck_assert_msg(want_len == got_len && memcmp(want, got, want_len) == 0,
                      "%s: %s is not what is committed (make fixtures writes it)", g->name, g->files[n]);
        free(want);
        free(got);
    }
    ck_assert_int_eq(count_files(dir), n);
    remove_temp(dir);
}
END_TEST

/* [MESH-SCALE-1] The torus generator, at 12 x 6 vertices: 144 triangles
 * (two a grid cell), closed, wound one way, one piece; from OBJ (17
 * digits) and from binary PLY (the doubles themselves) the same vertices. */
START_TEST(test_big_mesh_generator_makes_a_closed_torus)
{
    char dir[64], obj[128], ply[128], path[256];
    make_temp(dir, sizeof dir);
    snprintf(obj, sizeof obj, "%s/obj", dir);
    snprintf(ply, sizeof ply, "%s/ply", dir);
    const char *a[] = {obj, "--u", "12", "--v", "6", NULL}, *b[] = {ply, "--u", "12", "--v", "6", "--ply", NULL};
    ck_assert_int_eq(run("gen_big_mesh", a), 0);
    ck_assert_int_eq(run("gen_big_mesh", b), 0);
    scene_model *s[2];
    for (int k = 0; k < 2; k++) {
        int status;
        snprintf(path, sizeof path, "%s/torus.scene", k ? ply : obj);
        s[k] = scene_file_load(path, NULL, stderr, 1, &status);
        ck_assert_ptr_nonnull(s[k]);
        ck_assert_int_eq(s[k]->mesh_count, 1);
        const scene_mesh *m = &s[k]->meshes[0];
        ck_assert_int_eq(m->geom.tri_count, 144);
        ck_assert_int_eq(m->geom.position_count, 72);
        ck_assert(m->geom.closed && m->report.oriented);
        ck_assert_int_eq(m->report.components, 1);
    }
    const scene_trimesh *g0 = &s[0]->meshes[0].geom, *g1 = &s[1]->meshes[0].geom;
    ck_assert(same_vecs_bits(g0->positions, g1->positions, 72));
    ck_assert(memcmp(g0->tri, g1->tri, 144 * sizeof *g0->tri) == 0);
    scene_free(s[0]);
    scene_free(s[1]);
    remove_temp(dir);
}
END_TEST

Suite *suite_fixtures(void)
{
    Suite *s = suite_create("fixtures");
    TCase *tc = tcase_create("generators");
    tcase_set_timeout(tc, 30);
    tcase_add_loop_test(tc, test_fixtures_are_what_the_generators_write, 0,
                        (int)(sizeof generators / sizeof generators[0]));
    tcase_add_test(tc, test_big_mesh_generator_makes_a_closed_torus);
    suite_add_tcase(s, tc);
    return s;
}
