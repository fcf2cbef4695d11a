/*
 * The one test runner: every test file that defines `Suite *suite_NAME(void)`
 * is listed in the generated suites.h and run here.  `check_refray NAME...`
 * runs only the named suites; an unknown name is an error, so a typo can
 * never pass by running nothing.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <check.h>
#include "testlib.h"

#ifndef SUITES_HEADER
#define SUITES_HEADER "suites.h"
#endif

#define SUITE(name) Suite *suite_##name(void);
#include SUITES_HEADER
#undef SUITE

typedef struct suite_entry {
    const char *name;
    Suite *(*make)(void);
} suite_entry;

static const suite_entry all_suites[] = {
#define SUITE(name) {#name, suite_##name},
#include SUITES_HEADER
#undef SUITE
};

enum { SUITE_COUNT = sizeof all_suites / sizeof all_suites[0] };

static const suite_entry *find_suite(const char *name)
{
    for (int i = 0; i < SUITE_COUNT; i++)
        if (strcmp(all_suites[i].name, name) == 0)
            return &all_suites[i];
    return NULL;
}

int main(int argc, char **argv)
{
    SRunner *runner = NULL;
    for (int i = 1; i <= argc - 1 || (argc == 1 && i <= SUITE_COUNT); i++) {
        const suite_entry *entry = argc > 1 ? find_suite(argv[i]) : &all_suites[i - 1];
        if (!entry) {
            fprintf(stderr, "check_refray: no suite named '%s'\n", argv[i]);
            return 2;
        }
        if (!runner)
            runner = srunner_create(entry->make());
        else
            srunner_add_suite(runner, entry->make());
    }
    if (!runner) {
        fprintf(stderr, "check_refray: no suites\n");
        return 2;
    }
    srunner_run_all(runner, CK_NORMAL);
    int run = srunner_ntests_run(runner);
    int failed = srunner_ntests_failed(runner);
    srunner_free(runner);
    if (run == 0) {
        fprintf(stderr, "check_refray: no test ran\n");
        return 2;
    }
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
