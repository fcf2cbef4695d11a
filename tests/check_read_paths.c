/*
 * check_read_paths.c - where a scene's include and mesh files may come
 * from ([REL-READ-1], spec/reliability.md): the refray program reads them
 * only inside the scene's directory tree and --allow-read's, judged by
 * real path; the library's file loader reads anywhere unless the host
 * confines it.
 *
 * The layout, in a scratch directory W:
 *   W/other/o.scene, W/other/m.obj       outside the scene's tree
 *   W/sub/inner/b.scene                  inside
 *   W/sub/inner/link.scene -> ../../other/o.scene
 *   W/sub/NAME.scene                     the scenes run
 */
/* realpath is an XSI function. */
#define _XOPEN_SOURCE 700
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cli_testlib.h"
#include "io/scene_file.h"
#include "refray.h"

static char w[64];

static void put(const char *name, const char *text)
{
    char path[300];
    FILE *f = fopen(cli_path(path, sizeof path, w, name), "w");
    ck_assert_ptr_nonnull(f);
    ck_assert_int_eq(fputs(text, f) >= 0, 1);
    ck_assert_int_eq(fclose(f), 0);
}

static void layout(void)
{
    char cmd[400];
    cli_scratch(w, sizeof w, "readpaths");
    snprintf(cmd, sizeof cmd, "mkdir -p '%s/other' '%s/sub/inner' && ln -s ../../other/o.scene '%s/sub/inner/link.scene'",
             w, w, w);
    ck_assert_int_eq(system(cmd), 0);
    put("other/o.scene", "sphere { center [0, 0, -5] }\n");
    put("other/m.obj", "v 0 0 -3\nv 1 0 -3\nv 0 1 -3\nf 1 2 3\n");
    put("sub/inner/b.scene", "sphere { center [0, 0, -5] }\n");
    put("sub/up.scene", "include \"../other/o.scene\"\n");
    put("sub/link.scene", "include \"inner/link.scene\"\n");
    put("sub/mesh.scene", "image { width 4 height 3 }\nmesh { file \"../other/m.obj\" }\n");
    put("sub/ok.scene", "image { width 4 height 3 }\ninclude \"inner/b.scene\"\ninclude \"./inner/../inner/b.scene\"\n");
    put("sub/missing.scene", "include \"inner/none.scene\"\n");
    char text[400];
    snprintf(text, sizeof text, "include \"%s/other/o.scene\"\n", w);
    put("sub/abs.scene", text);
}

static char *real_of(const char *name)
{
    char path[300];
    char *real_path = realpath(cli_path(path, sizeof path, w, name), NULL);
    ck_assert_ptr_nonnull(real_path);
    return real_path;
}

/* [REL-READ-1] Out of the scene's tree by "..", by an absolute path, by a
 * symbolic link inside the tree, and a mesh file: each refused (65) at its
 * statement with the caret, naming the real path and --allow-read; with
 * --allow-read naming the other directory, each loads. */
START_TEST(test_read_paths_outside_refused)
{
    static const char *const scenes[] = {"sub/up.scene", "sub/abs.scene", "sub/link.scene", "sub/mesh.scene"};
    static const char *const targets[] = {"other/o.scene", "other/o.scene", "other/o.scene", "other/m.obj"};
    cli_run *r = malloc(sizeof *r);
    layout();
    char other[300];
    cli_path(other, sizeof other, w, "other");
    char *sub_real = real_of("sub");
    for (int i = 0; i < 4; i++) {
        char scene[300], want[700];
        cli_path(scene, sizeof scene, w, scenes[i]);
        const char *args[] = {"check", scene, NULL};
        cli_refray(r, args);
        ck_assert_msg(r->code == 65, "%s: exit %d, stderr %s", scenes[i], r->code, r->err);
        char *target = real_of(targets[i]);
        snprintf(want, sizeof want, "': its real path '%s' is outside the directories this load may read (the "
                 "scene's own, '%s', and 0 given with --allow-read); allow another with --allow-read DIR\n", target,
                 sub_real);
        ck_assert_msg(strstr(r->err, want) != NULL, "%s: stderr %s\nwant %s", scenes[i], r->err, want);
        ck_assert_msg(strstr(r->err, scene) == r->err && strstr(r->err, " ^~~") != NULL,
                      "%s: %s", scenes[i], r->err);
        free(target);
        const char *allowed[] = {"check", scene, "--allow-read", other, NULL};
        cli_refray(r, allowed);
        ck_assert_msg(r->code == 0, "%s --allow-read: exit %d, stderr %s", scenes[i], r->code, r->err);
    }
    /* render goes through the public API's loader: the same rule. */
    char out[300], scene[300];
    cli_path(out, sizeof out, w, "o.pfm");
    cli_path(scene, sizeof scene, w, "sub/mesh.scene");
    const char *render[] = {"render", scene, "-o", out, "-q", NULL};
    cli_refray(r, render);
    ck_assert_int_eq(r->code, 65);
    ck_assert(!cli_exists(out));
    free(sub_real);
    cli_remove(w);
    free(r);
}
END_TEST

/* [REL-READ-1] Inside the tree (also through "./" and ".." that stay in
 * it) loads; a missing file inside is still "cannot open"; --allow-read
 * takes only a directory (64). */
START_TEST(test_read_paths_inside_and_usage)
{
    cli_run *r = malloc(sizeof *r);
    layout();
    char scene[300], file[300];
    cli_path(scene, sizeof scene, w, "sub/ok.scene");
    const char *ok[] = {"check", scene, NULL};
    cli_refray(r, ok);
    ck_assert_msg(r->code == 0, "exit %d, stderr %s", r->code, r->err);
    cli_path(scene, sizeof scene, w, "sub/missing.scene");
    const char *missing[] = {"check", scene, NULL};
    cli_refray(r, missing);
    ck_assert_int_eq(r->code, 65);
    ck_assert_msg(strstr(r->err, "cannot open") && strstr(r->err, "No such file"), "%s", r->err);
    cli_path(file, sizeof file, w, "other/o.scene");
    const char *not_dir[] = {"check", scene, "--allow-read", file, NULL};
    cli_refray(r, not_dir);
    ck_assert_int_eq(r->code, 64);
    ck_assert_msg(strstr(r->err, "--allow-read: '") && strstr(r->err, "' is not a directory"), "%s", r->err);
    cli_remove(w);
    free(r);
}
END_TEST

/* [REL-READ-1] The library's choice is the host's: rf_scene_load_file
 * reads outside the tree by default, and refuses with read_confined; an
 * entry of read_dirs lets it through. */
START_TEST(test_read_paths_library_is_the_hosts_choice)
{
    layout();
    char scene[300], other[300];
    cli_path(scene, sizeof scene, w, "sub/up.scene");
    cli_path(other, sizeof other, w, "other");
    rf_load_options o;
    rf_load_options_init(&o);
    rf_scene *s = NULL;
    ck_assert_int_eq(rf_scene_load_file(scene, &o, &s), RF_OK);
    rf_scene_free(s);
    o.read_confined = 1;
    ck_assert_int_eq(rf_scene_load_file(scene, &o, &s), RF_ERR_DATA);
    ck_assert_ptr_null(s);
    const char *dirs[] = {other, NULL};
    o.read_dirs = dirs;
    ck_assert_int_eq(rf_scene_load_file(scene, &o, &s), RF_OK);
    rf_scene_free(s);
    cli_remove(w);
}
END_TEST

/* The commands of the program's dispatch (src/cli/cli.c's
 * `strcmp(cmd, "NAME")`) that are neither in loads[] nor in none[]; the
 * count of them, their names joined in out. */
static int unclassified(const char *const *loads, size_t n_loads, const char *const *none, size_t n_none,
                        char *out, size_t size)
{
    FILE *f = fopen("src/cli/cli.c", "r");
    ck_assert_ptr_nonnull(f);
    char line[400];
    int found = 0, missing = 0;
    out[0] = '\0';
    while (fgets(line, sizeof line, f)) {
        const char *p = strstr(line, "strcmp(cmd, \"");
        char name[64];
        if (!p || sscanf(p + 13, "%63[a-z]\"", name) != 1)
            continue; /* none, or an option ("--help") */
        found++;
        int known = 0;
        for (size_t i = 0; i < n_loads; i++)
            known |= strcmp(name, loads[i]) == 0;
        for (size_t i = 0; i < n_none; i++)
            known |= strcmp(name, none[i]) == 0;
        if (!known && strlen(out) + strlen(name) + 2 < size) {
            strcat(out, " ");
            strcat(out, name);
        }
        missing += !known;
    }
    fclose(f);
    ck_assert_int_ge(found, 9);
    return missing;
}

/* [REL-READ-1] Every command that loads scenes confines them: check,
 * render, kit, verify (and verify --stability), export and oracle, each
 * refusing "../" (65) with the rule's message before reading a byte of
 * the file outside.  Every command of the program is either run here or
 * named as one that loads no scene, so a new command must be added to
 * one list or the other. */
START_TEST(test_read_paths_every_command)
{
    cli_run *r = malloc(sizeof *r);
    layout();
    char scene[300], out[300], kit[300];
    cli_path(scene, sizeof scene, w, "sub/up.scene");
    cli_path(out, sizeof out, w, "o.pfm");
    cli_path(kit, sizeof kit, w, "kit");
    const char *const commands[][7] = {
        {"kit", "-o", kit, scene, NULL},
        {"check", scene, NULL},
        {"render", scene, "-o", out, "-q", NULL},
        {"verify", scene, NULL},
        {"verify", "--stability", scene, NULL},
        {"export", scene, "--to", "pov", NULL},
        {"oracle", scene, "-o", out, NULL},
    };
    static const char *const loads[] = {"kit", "check", "render", "verify", "export", "oracle"};
    /* compare and merge read images, conform a kit's manifest and runs
     * another renderer on its scenes. */
    static const char *const none[] = {"compare", "conform", "merge"};
    char names[400];
    ck_assert_msg(unclassified(loads, sizeof loads / sizeof loads[0], none, sizeof none / sizeof none[0], names,
                               sizeof names) == 0,
                  "commands neither tested here nor named as loading no scene:%s", names);
    size_t first = 0;
    if (!REFRAY_HAVE_JSON) {
        /* Without jansson kit refuses before it loads anything. */
        cli_refray(r, commands[0]);
        ck_assert_msg(r->code == 64 && strstr(r->err, "without JSON support") != NULL, "kit: exit %d, stderr %s",
                      r->code, r->err);
        first = 1;
    }
    for (size_t i = first; i < sizeof commands / sizeof commands[0]; i++) {
        cli_refray(r, commands[i]);
        ck_assert_msg(r->code == 65, "%s: exit %d, stderr %s", commands[i][0], r->code, r->err);
        ck_assert_msg(strstr(r->err, "is outside the directories this load may read") != NULL
                      && strstr(r->err, "other/o.scene:1:") == NULL, "%s: stderr %s", commands[i][0], r->err);
        ck_assert(!cli_exists(out));
    }
    cli_remove(w);
    free(r);
}
END_TEST

/* [REL-READ-1] The file loaders of src/io confine by default, so a new
 * command cannot forget it: the short forms and scene_file_load_confined
 * without --allow-read directories keep to the scene's tree, a reader
 * nobody confined reads nothing, and only scene_file_load_anywhere (the
 * library host's opt-out) reads outside. */
START_TEST(test_read_paths_io_confined_by_default)
{
    layout();
    char up[300], ok[300];
    cli_path(up, sizeof up, w, "sub/up.scene");
    cli_path(ok, sizeof ok, w, "sub/ok.scene");
    static const char text[] = "include \"inner/b.scene\"\n";
    int status = -1;
    ck_assert_ptr_null(scene_file_load(up, NULL, NULL, 0, &status));
    ck_assert_int_eq(status, STATUS_DATA);
    status = -1;
    ck_assert_ptr_null(scene_file_load_confined(up, NULL, NULL, &status));
    ck_assert_int_eq(status, STATUS_DATA);
    status = -1;
    ck_assert_ptr_null(scene_file_load_text(up, "include \"../other/o.scene\"\n", 27, NULL, NULL, 0, &status));
    ck_assert_int_eq(status, STATUS_DATA);
    /* The text form with extra directories (the difftest's meshes): a mesh
     * outside the tree loads once its directory is allowed, not before. */
    static const char mesh_text[] = "mesh { file \"../other/m.obj\" }\n";
    char other[300];
    const char *allowed[] = {cli_path(other, sizeof other, w, "other"), NULL};
    status = -1;
    ck_assert_ptr_null(scene_file_load_text_confined(up, mesh_text, sizeof mesh_text - 1, NULL, NULL, 0, NULL,
                                                     &status));
    ck_assert_int_eq(status, STATUS_DATA);
    scene_model *m = scene_file_load_text_confined(up, mesh_text, sizeof mesh_text - 1, NULL, NULL, 0, allowed,
                                                   &status);
    ck_assert_msg(m != NULL, "status %d", status);
    scene_free(m);
    scene_model *s = scene_file_load(ok, NULL, NULL, 0, &status);
    ck_assert_msg(s != NULL, "status %d", status);
    scene_free(s);
    s = scene_file_load_anywhere(up, NULL, &status);
    ck_assert_msg(s != NULL, "status %d", status);
    scene_free(s);
    /* A bare reader: not told where it may read, it reads nothing. */
    scene_file_reader files;
    scene_file_reader_init(&files, -1, NULL);
    scene_load_opts o;
    scene_load_opts_init(&o);
    o.resolver = scene_file_resolver(&files);
    scene_source root = {ok, NULL, text, sizeof text - 1, 0};
    status = -1;
    ck_assert_ptr_null(scene_file_load_source(&root, &o, &status));
    ck_assert_int_eq(status, STATUS_DATA);
    scene_file_reader_free(&files);
    cli_remove(w);
}
END_TEST

/* [REL-READ-1] A link in the tree whose resolution passes PATH_MAX on
 * the way (h1/h2 lead 25 names of 200 bytes deep, then ../ back out to
 * other/o.scene): realpath fails where open succeeds, so the file cannot be
 * judged and is refused (65), not read as if it were missing. */
START_TEST(test_read_paths_unresolvable_link)
{
    cli_run *r = malloc(sizeof *r);
    layout();
    char cmd[1400];
    snprintf(cmd, sizeof cmd, "cd '%s/sub' && A=$(printf '%%0200d' 0 | tr 0 A) && "
             "h=$A && up=../ && i=1 && while [ $i -lt 12 ]; do h=$h/$A; i=$((i+1)); done && mkdir -p $h && "
             "ln -s $h h1 && (cd $h && mkdir -p $A/$h && ln -s $A/$h h2) && i=1 && while [ $i -lt 25 ]; do up=$up../; i=$((i+1)); done && "
             "ln -s h1/h2/${up}../other/o.scene long.scene && cat long.scene >/dev/null", w);
    ck_assert_int_eq(system(cmd), 0);
    put("sub/long_link.scene", "include \"long.scene\"\n");
    char scene[300];
    cli_path(scene, sizeof scene, w, "sub/long_link.scene");
    const char *args[] = {"check", scene, NULL};
    cli_refray(r, args);
    ck_assert_msg(r->code == 65, "exit %d, stderr %s", r->code, r->err);
    ck_assert_msg(strstr(r->err, "cannot read 'long.scene': its real path cannot be found") != NULL, "%s", r->err);
    cli_remove(w);
    free(r);
}
END_TEST

Suite *suite_read_paths(void)
{
    Suite *s = suite_create("read_paths");
    TCase *tc = tcase_create("read_paths");
    tcase_set_timeout(tc, 10);
    tcase_add_test(tc, test_read_paths_outside_refused);
    tcase_add_test(tc, test_read_paths_inside_and_usage);
    tcase_add_test(tc, test_read_paths_every_command);
    tcase_add_test(tc, test_read_paths_unresolvable_link);
    tcase_add_test(tc, test_read_paths_library_is_the_hosts_choice);
    tcase_add_test(tc, test_read_paths_io_confined_by_default);
    suite_add_tcase(s, tc);
    return s;
}
