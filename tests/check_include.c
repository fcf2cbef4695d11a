/* Tests of `include` and `for` (src/scene/lower.c) and of reading scene files
 * (src/io/scene_file.c, src/io/fileio.c, src/scene/lower.c).  Include trees are fixtures
 * under tests/scenes/include/; the tests run from the repository root.
 * IDs are those of spec/language.md. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "loadlib.h"

#define INC "tests/scenes/include/"

static void load_text(loaded *l, const char *text, const scene_limits *limits)
{
    load_as(l, "t.scene", text, limits, 1);
}

/* [LANG-INCLUDE-1] a path is relative to the directory of the file that
 * holds the include; what an included file defines is visible after it. */
START_TEST(test_scene_load_include_relative_paths)
{
    loaded l;
    load_file(&l, INC "main.scene", NULL);
    ck_assert_msg(l.scene != NULL, "%s", l.messages);
    const scene_model *s = l.scene;
    ck_assert_int_eq(s->light_count, 1);
    ck_assert_vec_near(s->lights[0].position, vec_make(0, 10, 0), 0);
    /* r = 2 comes from parts/more.scene, found next to parts/lamps.scene. */
    ck_assert_near(s->prims[0].u.sphere.radius, 2, 0);
    ck_assert_str_eq(s->materials[s->prims[0].material].name, "chrome");
    ck_assert_vec_near(s->materials[s->prims[0].material].ks, vec_splat(0.9), 0);
    /* Every file read is kept: main, lamps, more, materials. */
    ck_assert_int_eq(s->sources.count, 4);
    ck_assert_str_eq(s->sources.files[1]->path, INC "parts/lamps.scene");
    ck_assert_str_eq(s->sources.files[2]->path, INC "parts/more.scene");
    ck_assert_int_eq(s->sources.files[2]->included_from.file, 1);
    loaded_done(&l);
}
END_TEST

/* Including the same file twice in a row is allowed: it is no cycle. */
START_TEST(test_scene_load_include_twice)
{
    loaded l;
    load_file(&l, INC "twice.scene", NULL);
    ck_assert_ptr_nonnull(l.scene);
    ck_assert_int_eq(l.scene->light_count, 2);
    loaded_done(&l);
}
END_TEST

/* [LANG-INCLUDE-2] an error in an included file points into that file,
 * followed by the chain of includes that led there. */
START_TEST(test_scene_load_include_error_location)
{
    loaded l;
    load_file(&l, INC "with_error.scene", NULL);
    ck_assert_ptr_null(l.scene);
    ck_assert_int_eq(l.status, STATUS_DATA);
    ck_assert_str_eq(l.messages, INC "parts/bad.scene:2:17: error: radius must be > 0, got -1\n"
                                 "    2 | sphere { radius -1 }\n"
                                 "      |                 ^~\n"
                                 INC "with_error.scene:2:1: note: included from here\n");
    loaded_done(&l);
}
END_TEST

/* [LANG-INCLUDE-3] a file that includes itself, directly or not, is
 * refused at the include that closes the cycle. */
START_TEST(test_scene_load_include_cycle)
{
    loaded l;
    load_file(&l, INC "cycle_a.scene", NULL);
    ck_assert_ptr_null(l.scene);
    ck_assert_int_eq(l.status, STATUS_DATA);
    ck_assert_str_eq(first_line(&l), INC "cycle_b.scene:1:9: error: include cycle: 'cycle_a.scene' is already being read");
    loaded_done(&l);
}
END_TEST

/* [LANG-INCLUDE-4] at most max_include_depth includes inside each other
 * (32 by default, --max-include-depth). */
START_TEST(test_scene_load_include_depth)
{
    /* chain.scene -> c1 -> c2 -> c3: three levels of include. */
    scene_limits lim = scene_default_limits();
    loaded l;
    lim.max_include_depth = 3;
    load_file(&l, INC "chain.scene", &lim);
    ck_assert_msg(l.scene != NULL, "%s", l.messages);
    loaded_done(&l);
    lim.max_include_depth = 2;
    load_file(&l, INC "chain.scene", &lim);
    ck_assert_ptr_null(l.scene);
    ck_assert_str_eq(first_line(&l),
                     INC "chain/c2.scene:1:9: error: includes nested more than 2 deep (--max-include-depth)");
    loaded_done(&l);
    lim.max_include_depth = 0;
    load_file(&l, INC "chain.scene", &lim);
    ck_assert_str_eq(first_line(&l),
                     INC "chain.scene:1:9: error: includes nested more than 0 deep (--max-include-depth)");
    loaded_done(&l);
}
END_TEST

/* [LANG-INCLUDE-5] an include that names a directory or a missing file is
 * a bad scene (65), located at the path. */
START_TEST(test_scene_load_include_directory_and_missing)
{
    loaded l;
    load_file(&l, INC "directory.scene", NULL);
    ck_assert_int_eq(l.status, STATUS_DATA);
    ck_assert_str_eq(first_line(&l), INC "directory.scene:2:9: error: '" INC "parts' is a directory, not a file");
    loaded_done(&l);
    load_file(&l, INC "missing.scene", NULL);
    ck_assert_int_eq(l.status, STATUS_DATA);
    ck_assert_str_eq(first_line(&l), INC "missing.scene:2:9: error: cannot open '" INC
                                     "parts/nowhere.scene': No such file or directory");
    loaded_done(&l);
}
END_TEST

/* [LANG-EXIT-1] the top-level file: missing or a directory is 66 with a
 * message without location; too large is 65. */
START_TEST(test_scene_load_file_errors)
{
    loaded l;
    load_file(&l, INC "no_such.scene", NULL);
    ck_assert_ptr_null(l.scene);
    ck_assert_int_eq(l.status, STATUS_NO_INPUT);
    ck_assert_str_eq(first_line(&l), "refray: error: cannot open '" INC "no_such.scene': No such file or directory");
    loaded_done(&l);
    load_file(&l, INC "parts", NULL);
    ck_assert_int_eq(l.status, STATUS_NO_INPUT);
    ck_assert_str_eq(first_line(&l), "refray: error: '" INC "parts' is a directory, not a file");
    loaded_done(&l);
    scene_limits lim = scene_default_limits();
    lim.max_file_bytes = 10;
    load_file(&l, INC "main.scene", &lim);
    ck_assert_int_eq(l.status, STATUS_DATA);
    ck_assert_ptr_nonnull(strstr(first_line(&l), "bytes, over the limit of 10 (--max-file-size)"));
    loaded_done(&l);
    /* The limit holds for included files too. */
    lim.max_file_bytes = 100;
    load_file(&l, INC "chain.scene", &lim);
    ck_assert_ptr_nonnull(l.scene);
    loaded_done(&l);
    /* big_include.scene is 26 bytes, parts/big.scene 110. */
    lim.max_file_bytes = 109;
    load_file(&l, INC "big_include.scene", &lim);
    ck_assert_int_eq(l.status, STATUS_DATA);
    ck_assert_str_eq(first_line(&l), INC "big_include.scene:1:9: error: '" INC "parts/big.scene' is 110 bytes, over "
                                     "the limit of 109 (--max-file-size)");
    loaded_done(&l);
    lim.max_file_bytes = 110;
    load_file(&l, INC "big_include.scene", &lim);
    ck_assert_ptr_nonnull(l.scene);
    loaded_done(&l);
}
END_TEST

/* [LANG-FOR-1] both bounds are included; the variable takes whole values. */
START_TEST(test_lower_for_inclusive_bounds)
{
    loaded l;
    load_text(&l, "for i in 1 .. 3 { sphere { radius i  center [i * 10, 0, 0] } }", NULL);
    ck_assert_msg(l.scene != NULL, "%s", l.messages);
    ck_assert_int_eq(l.scene->prim_count, 3);
    for (int i = 0; i < 3; i++) {
        ck_assert_near(l.scene->prims[i].u.sphere.radius, i + 1, 0);
        ck_assert_near(l.scene->prims[i].u.sphere.center.x, 10 * (i + 1), 0);
    }
    loaded_done(&l);
    /* One iteration when the bounds are equal; negative bounds work. */
    load_text(&l, "for i in -2 .. -2 { sphere { center [i, 0, 0] } }", NULL);
    ck_assert_msg(l.scene != NULL, "%s", l.messages);
    ck_assert_int_eq(l.scene->prim_count, 1);
    ck_assert_near(l.scene->prims[0].u.sphere.center.x, -2, 0);
    loaded_done(&l);
    /* Bounds are expressions; `0..n` needs no blanks. */
    load_text(&l, "let k = 2 for i in 0..k*2 { sphere {} }", NULL);
    ck_assert_msg(l.scene != NULL, "%s", l.messages);
    ck_assert_int_eq(l.scene->prim_count, 5);
    loaded_done(&l);
}
END_TEST

/* [LANG-FOR-2] A > B runs nothing (with a warning). */
START_TEST(test_lower_for_empty_range)
{
    loaded l;
    load_text(&l, "sphere {} for i in 3 .. 1 { sphere {} }", NULL);
    ck_assert_ptr_nonnull(l.scene);
    ck_assert_int_eq(l.scene->prim_count, 1);
    ck_assert_str_eq(first_line(&l), "t.scene:1:20: warning: this loop runs 0 times (3 > 1)");
    loaded_done(&l);
}
END_TEST

/* [LANG-FOR-3] bounds must be whole numbers. */
START_TEST(test_lower_for_bounds_must_be_whole)
{
    static const struct {
        const char *text, *message;
    } cases[] = {
        {"for i in 0 .. 2.5 {}", "t.scene:1:15: error: a loop bound must be a whole number"},
        {"for i in 0.5 .. 2 {}", "t.scene:1:10: error: a loop bound must be a whole number"},
        {"for i in 0 .. [1, 2, 3] {}", "t.scene:1:15: error: a loop bound must be a whole number"},
        {"for i in \"a\" .. 1 {}", "t.scene:1:10: error: a loop bound must be a whole number"},
        {"for i in 0 .. q {}", "t.scene:1:15: error: unknown constant 'q'"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        loaded l;
        load_text(&l, cases[i].text, NULL);
        ck_assert_ptr_null(l.scene);
        ck_assert_str_eq(first_line(&l), cases[i].message);
        loaded_done(&l);
    }
}
END_TEST

/* [LANG-FOR-4] the iteration cap is checked before a loop runs, per loop
 * and over the whole load; an error in the body is never reached then. */
START_TEST(test_lower_for_iteration_cap)
{
    scene_limits lim = scene_default_limits();
    lim.max_loop_iterations = 10;
    loaded l;
    load_text(&l, "for i in 1 .. 11 { sphere { radius -1 } }", &lim);
    ck_assert_ptr_null(l.scene);
    ck_assert_str_eq(l.messages, "t.scene:1:10: error: this loop would run 11 times, over the limit of 10 (--max-loop)\n"
                                 "    1 | for i in 1 .. 11 { sphere { radius -1 } }\n"
                                 "      |          ^~~~~~~\n");
    loaded_done(&l);
    load_text(&l, "for i in 1 .. 10 { sphere {} }", &lim);
    ck_assert_ptr_nonnull(l.scene);
    ck_assert_int_eq(l.scene->prim_count, 10);
    loaded_done(&l);
    load_text(&l, "for i in 1 .. 6 { sphere {} }\nfor j in 1 .. 5 { sphere {} }", &lim);
    ck_assert_str_eq(first_line(&l), "t.scene:2:10: error: this loop would bring the iterations of the scene to 11, "
                                     "over the limit of 10 (--max-loop)");
    loaded_done(&l);
    /* A huge count is refused at once, not run (the test would time out). */
    load_text(&l, "for i in 0 .. 1e15 { sphere {} }", NULL);
    ck_assert_str_eq(first_line(&l), "t.scene:1:10: error: this loop would run 1000000000000001 times, over the "
                                     "limit of 1000000 (--max-loop)");
    loaded_done(&l);
}
END_TEST

/* [LANG-FOR-5] nested loops: the inner one runs once per outer value, and
 * every run counts toward the cap. */
START_TEST(test_lower_for_nested)
{
    loaded l;
    load_text(&l, "for i in 0 .. 2 { for j in 0 .. 3 { sphere { center [i, j, 0] radius 0.1 } } }", NULL);
    ck_assert_msg(l.scene != NULL, "%s", l.messages);
    ck_assert_int_eq(l.scene->prim_count, 12);
    /* Written order: j runs fastest. */
    ck_assert_vec_near(l.scene->prims[0].u.sphere.center, vec_make(0, 0, 0), 0);
    ck_assert_vec_near(l.scene->prims[1].u.sphere.center, vec_make(0, 1, 0), 0);
    ck_assert_vec_near(l.scene->prims[4].u.sphere.center, vec_make(1, 0, 0), 0);
    ck_assert_vec_near(l.scene->prims[11].u.sphere.center, vec_make(2, 3, 0), 0);
    loaded_done(&l);
    /* 3 outer + 3 x 4 inner = 15 iterations. */
    scene_limits lim = scene_default_limits();
    lim.max_loop_iterations = 15;
    load_text(&l, "for i in 0 .. 2 { for j in 0 .. 3 { sphere {} } }", &lim);
    ck_assert_ptr_nonnull(l.scene);
    loaded_done(&l);
    lim.max_loop_iterations = 14;
    load_text(&l, "for i in 0 .. 2 { for j in 0 .. 3 { sphere {} } }", &lim);
    ck_assert_ptr_null(l.scene);
    ck_assert_str_eq(first_line(&l), "t.scene:1:28: error: this loop would bring the iterations of the scene to 15, "
                                     "over the limit of 14 (--max-loop)");
    loaded_done(&l);
}
END_TEST

/* [LANG-FOR-6] an error in a loop body is reported once, not once per
 * pass, with a note naming the pass. */
START_TEST(test_lower_for_error_reported_once)
{
    loaded l;
    load_text(&l, "for i in 0 .. 9 { sphere { radius i - 5 } }", NULL);
    ck_assert_ptr_null(l.scene);
    ck_assert_str_eq(l.messages, "t.scene:1:35: error: radius must be > 0, got -5\n"
                                 "    1 | for i in 0 .. 9 { sphere { radius i - 5 } }\n"
                                 "      |                                   ^~~~~\n"
                                 "t.scene:1:5: note: in the pass where i = 0\n"
                                 "    1 | for i in 0 .. 9 { sphere { radius i - 5 } }\n"
                                 "      |     ^\n");
    loaded_done(&l);
    /* Nested loops name both passes, the inner first. */
    load_text(&l, "for i in 1 .. 2 {\n for j in 0 .. 3 {\n  sphere { radius 2 - i - j }\n }\n}", NULL);
    ck_assert_ptr_nonnull(strstr(l.messages, "t.scene:3:19: error: radius must be > 0, got 0\n"));
    const char *inner = strstr(l.messages, "t.scene:2:6: note: in the pass where j = 1\n");
    const char *outer = strstr(l.messages, "t.scene:1:5: note: in the pass where i = 1\n");
    ck_assert_ptr_nonnull(inner);
    ck_assert_ptr_nonnull(outer);
    ck_assert(inner < outer);
    loaded_done(&l);
}
END_TEST

/* [LANG-FOR-7] the loop variable and a body's constants live for one
 * pass; the variable may not hide a constant. */
START_TEST(test_lower_for_scope)
{
    loaded l;
    load_text(&l, "for i in 0 .. 2 { let x = i * 2  sphere { radius x + 1 } }", NULL);
    ck_assert_msg(l.scene != NULL, "%s", l.messages);
    ck_assert_near(l.scene->prims[2].u.sphere.radius, 5, 0);
    loaded_done(&l);
    load_text(&l, "for i in 0 .. 2 { sphere {} }\nsphere { radius i }", NULL);
    ck_assert_str_eq(first_line(&l), "t.scene:2:17: error: unknown constant 'i'; did you mean 'pi'?");
    loaded_done(&l);
    load_text(&l, "let i = 1\nfor i in 0 .. 2 { sphere {} }", NULL);
    ck_assert_str_eq(first_line(&l), "t.scene:2:5: error: loop variable 'i' hides a constant of the same name");
    loaded_done(&l);
    load_text(&l, "for pi in 0 .. 2 { sphere {} }", NULL);
    ck_assert_str_eq(first_line(&l), "t.scene:1:5: error: loop variable 'pi' hides a constant of the same name");
    loaded_done(&l);
    load_text(&l, "for i in 0 .. 1 { for i in 0 .. 1 { sphere {} } }", NULL);
    ck_assert_str_eq(first_line(&l), "t.scene:1:23: error: loop variable 'i' hides a constant of the same name");
    loaded_done(&l);
}
END_TEST

Suite *suite_include(void)
{
    Suite *s = suite_create("include");
    TCase *tc = tcase_create("include");
    tcase_add_test(tc, test_scene_load_include_relative_paths);
    tcase_add_test(tc, test_scene_load_include_twice);
    tcase_add_test(tc, test_scene_load_include_error_location);
    tcase_add_test(tc, test_scene_load_include_cycle);
    tcase_add_test(tc, test_scene_load_include_depth);
    tcase_add_test(tc, test_scene_load_include_directory_and_missing);
    tcase_add_test(tc, test_scene_load_file_errors);
    tcase_add_test(tc, test_lower_for_inclusive_bounds);
    tcase_add_test(tc, test_lower_for_empty_range);
    tcase_add_test(tc, test_lower_for_bounds_must_be_whole);
    tcase_add_test(tc, test_lower_for_iteration_cap);
    tcase_add_test(tc, test_lower_for_nested);
    tcase_add_test(tc, test_lower_for_error_reported_once);
    tcase_add_test(tc, test_lower_for_scope);
    suite_add_tcase(s, tc);
    return s;
}
