/*
 * check_json_memory.c - the bound of what jansson holds while it parses a
 * JSON scene, and --max-memory applied to it before jansson runs
 * ([REL-MEMORY-2], spec/reliability.md).
 *
 * The bound is checked against jansson itself: this process (a forked
 * test, so the process-wide hook is its own) hands jansson an allocator
 * that counts what glibc gives each block (malloc_usable_size plus the
 * 8-byte chunk header) and keeps the peak.
 */
#include <malloc.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/scene_file.h"
#include "testlib.h"

#ifdef REFRAY_HAVE_JSON

#include <jansson.h>
#include "scene/json_read.h"

static size_t held, peak;

static void *counting_alloc(size_t n)
{
    void *p = malloc(n);
    if (p) {
        held += malloc_usable_size(p) + 8;
        peak = held > peak ? held : peak;
    }
    return p;
}

static void counting_free(void *p)
{
    if (p)
        held -= malloc_usable_size(p) + 8;
    free(p);
}

/* The peak bytes jansson held to parse text as the loader does. */
static double jansson_peak(const char *text)
{
    json_error_t e;
    json_set_alloc_funcs(counting_alloc, counting_free);
    held = peak = 0;
    json_t *root = json_loadb(text, strlen(text), JSON_REJECT_DUPLICATES | JSON_DECODE_INT_AS_REAL, &e);
    ck_assert_msg(root != NULL, "%s", e.text);
    json_decref(root);
    json_set_alloc_funcs(malloc, free);
    return (double)peak;
}

/* Appends to a growing text. */
typedef struct text {
    char *s;
    size_t len, cap;
} text;

/* Appends fmt with a, b, c to t.  It fails by ck_abort_msg, not ck_assert: a
 * passed assertion is a message to Check's parent process, and a document
 * is a million calls (8 s of the sanitizer build's run). */
static void put(text *t, const char *fmt, long a, long b, long c)
{
    int n = snprintf(NULL, 0, fmt, a, b, c);
    if (n < 0)
        ck_abort_msg("snprintf failed on %s", fmt);
    if (t->len + (size_t)n + 1 > t->cap) {
        t->cap = 2 * (t->len + (size_t)n + 1);
        t->s = realloc(t->s, t->cap);
        if (!t->s)
            ck_abort_msg("out of memory at %zu bytes", t->cap);
    }
    snprintf(t->s + t->len, (size_t)n + 1, fmt, a, b, c);
    t->len += (size_t)n;
}

/* Documents of one kind of value each, n of them, and a mesh scene. */
static char *document(int kind, long n)
{
    static const char *const items[] = {
        "%ld.25",                               /* numbers */
        "\"v%ld-%ld-%ld\"",                     /* short strings */
        "[%ld, %ld, %ld]",                      /* small arrays: mesh triangles */
        "[1, 2, 3, 4, 5, 6, 7, 8, %ld, %ld, %ld]", /* arrays past their first table */
        "{\"a%ld\": %ld, \"b\": %ld}",          /* objects */
        "{}",                                   /* empty objects */
        "true",                                 /* shared literals */
    };
    text t = {NULL, 0, 0};
    put(&t, "[", 0, 0, 0);
    for (long i = 0; i < n; i++) {
        put(&t, items[kind], i, i + 1, i + 2);
        if (i + 1 < n)
            put(&t, ",", 0, 0, 0);
    }
    put(&t, "]", 0, 0, 0);
    return t.s;
}

/* [REL-MEMORY-2] The bound is never below what jansson holds, for each
 * kind of value and at each size (the tables and buckets grow by
 * doubling, so sizes on both sides of a doubling are tried), and on a
 * 64-bit build it is within 1.6 times of it. */
START_TEST(test_json_tree_bound_holds)
{
    static const long sizes[] = {1, 9, 1000, 4097, 30000};
    for (int kind = 0; kind < 7; kind++)
        for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
            char *doc = document(kind, sizes[k]);
            double got = jansson_peak(doc), bound = jread_tree_bound(doc, strlen(doc));
            ck_assert_msg(bound >= got, "kind %d, %ld values: bound %.0f < jansson's %.0f", kind, sizes[k], bound,
                          got);
            if (sizeof(void *) == 8 && got > 1e6)
                ck_assert_msg(bound <= 1.6 * got, "kind %d, %ld values: bound %.0f, jansson %.0f", kind, sizes[k],
                              bound, got);
            free(doc);
        }
}
END_TEST

/* [REL-MEMORY-2] jansson's lexer buffers a number's text as it does a
 * string's (its buffer doubling up to twice the token), so a number of a
 * million digits holds about 2 MiB; the bound counts the longest token of
 * any kind, not only strings (it gave 64 KiB here). */
START_TEST(test_json_tree_bound_long_number)
{
    static const long digits[] = {1000, 100000, 1000000};
    for (size_t k = 0; k < sizeof digits / sizeof digits[0]; k++) {
        text t = {NULL, 0, 0};
        put(&t, "[0.", 0, 0, 0);
        for (long i = 0; i < digits[k]; i++)
            put(&t, "1", 0, 0, 0);
        put(&t, "]", 0, 0, 0);
        double got = jansson_peak(t.s), bound = jread_tree_bound(t.s, t.len);
        ck_assert_msg(bound >= got, "%ld digits: bound %.0f < jansson's %.0f", digits[k], bound, got);
        free(t.s);
    }
}
END_TEST

/* A JSON scene of a mesh of n x n vertices, inline. */
static char *mesh_scene(long n)
{
    text t = {NULL, 0, 0};
    put(&t, "{\"format\": {\"name\": \"refray-scene\", \"version\": 1}, \"oracle\": null,\n"
            " \"image\": {\"width\": 4, \"height\": 4, \"samples\": 1, \"max_depth\": 1, \"background\": [0, 0, 0]},\n"
            " \"camera\": {\"projection\": \"perspective\", \"eye\": [0, 0, 5], \"look_at\": [0, 0, 0],\n"
            "            \"up\": [0, 1, 0], \"fov\": 60},\n"
            " \"ambient\": [0, 0, 0], \"lights\": [],\n"
            " \"materials\": [{\"name\": null, \"Kd\": [1, 1, 1], \"Ks\": [0, 0, 0], \"n\": 1, \"t\": 0, \"ior\": 1}],\n"
            " \"primitives\": [{\"kind\": \"mesh\", \"material\": 0, \"source\": null, \"normals\": [],\n"
            "  \"vertices\": [", 0, 0, 0);
    for (long j = 0; j < n; j++)
        for (long i = 0; i < n; i++)
            put(&t, j + i ? ", [%ld, %ld, %ld]" : "[%ld, %ld, %ld]", i, j, 0);
    put(&t, "],\n  \"triangles\": [", 0, 0, 0);
    for (long j = 0; j + 1 < n; j++)
        for (long i = 0; i + 1 < n; i++) {
            long a = j * n + i;
            put(&t, j + i ? ", [%ld, %ld, %ld]" : "[%ld, %ld, %ld]", a, a + 1, a + n + 1);
            put(&t, ", [%ld, %ld, %ld]", a, a + n + 1, a + n);
        }
    put(&t, "],\n  \"triangle_normals\": null}]}\n", 0, 0, 0);
    return t.s;
}

static int load_with_limit(const char *doc, long max_memory_mb, char *first, size_t size)
{
    scene_limits limits = scene_default_limits();
    limits.max_memory_mb = max_memory_mb;
    FILE *errs = tmpfile();
    int status;
    scene_model *s = scene_file_load_text("m.json", doc, strlen(doc), &limits, errs, 1, &status);
    rewind(errs);
    if (!fgets(first, (int)size, errs))
        first[0] = '\0';
    fclose(errs);
    scene_free(s);
    return status;
}

/* [REL-MEMORY-2] A JSON scene whose tree would pass --max-memory is
 * refused at 1:1, before jansson runs, with exit status 65 like the other
 * memory limits and the way out (OBJ/PLY mesh files); with the limit
 * raised the same text loads.  200 x 200 vertices and 79,202 triangles:
 * 119,202 arrays of 3 numbers, about 248 bytes each in the bound: about
 * 36 MiB of tree. */
START_TEST(test_json_tree_refused_over_max_memory)
{
    char first[1024];
    char *doc = mesh_scene(200);
    double bound = jread_tree_bound(doc, strlen(doc)) / 1048576.0;
    ck_assert_msg(bound > 20 && bound < 64, "bound %.1f MiB", bound);
    ck_assert_int_eq(load_with_limit(doc, 16, first, sizeof first), STATUS_DATA);
    ck_assert_msg(strncmp(first, "m.json:1:1: error: parsing this JSON document would take up to ", 63) == 0, "%s",
                  first);
    ck_assert_msg(strstr(first, "over --max-memory 16 MiB; write big meshes as OBJ or PLY files (refray export "
                                "--to json --mesh-files DIR)"), "%s", first);
    ck_assert_msg(load_with_limit(doc, 256, first, sizeof first) == STATUS_OK, "%s", first);
    free(doc);
}
END_TEST

#endif

Suite *suite_json_memory(void)
{
    Suite *s = suite_create("json_memory");
    TCase *tc = tcase_create("json_memory");
    tcase_set_timeout(tc, 20);
#ifdef REFRAY_HAVE_JSON
    tcase_add_test(tc, test_json_tree_bound_holds);
    tcase_add_test(tc, test_json_tree_bound_long_number);
    tcase_add_test(tc, test_json_tree_refused_over_max_memory);
#endif
    suite_add_tcase(s, tc);
    return s;
}
