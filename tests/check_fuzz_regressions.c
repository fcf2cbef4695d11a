/*
 * Inputs that once crashed or hung the front end (found by fuzzing, see
 * `make fuzz`), kept in tests/fuzz-regressions/.  Each must load to a
 * verdict, valid (0) or a scene error (65), under the default limits; a
 * crash fails the test (Check runs it in its own process), and the timeout
 * catches a hang.  The first line of each file's comment, if any, is free.
 *   long-comment-heap-overflow.scene  a comment and a word of over 16 kB
 *       overflowed flex's state buffer (variable trailing context)
 *   deep-sum-stack-overflow.scene     a sum of 100 000 terms overflowed
 *       the evaluator's stack
 */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testlib.h"
#include "io/scene_file.h"
#include "scene/scene.h"

#define REGRESSIONS "tests/fuzz-regressions"

START_TEST(test_fuzz_regressions_load_to_a_verdict)
{
    DIR *d = opendir(REGRESSIONS);
    ck_assert_ptr_nonnull(d);
    int files = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        size_t n = strlen(e->d_name);
        if (n < 7 || strcmp(e->d_name + n - 6, ".scene") != 0)
            continue;
        char path[512];
        snprintf(path, sizeof path, "%s/%s", REGRESSIONS, e->d_name);
        FILE *sink = fopen("/dev/null", "w");
        int status;
        scene_model *s = scene_file_load(path, NULL, sink, 1, &status);
        fclose(sink);
        ck_assert_msg(status == STATUS_OK || status == STATUS_DATA, "%s: status %d", path, status);
        ck_assert_msg((s != NULL) == (status == STATUS_OK), "%s: scene and status disagree", path);
        scene_free(s);
        files++;
    }
    closedir(d);
    ck_assert_int_ge(files, 2);
}
END_TEST

Suite *suite_fuzz_regressions(void)
{
    Suite *s = suite_create("fuzz_regressions");
    TCase *tc = tcase_create("load");
    tcase_set_timeout(tc, 10);
    tcase_add_test(tc, test_fuzz_regressions_load_to_a_verdict);
    suite_add_tcase(s, tc);
    return s;
}
