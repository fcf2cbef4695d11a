/*
 * check_jsonloc.c - finding values in a JSON text (src/base/jsonloc.c):
 * the span at a path, the path at an offset, the elements of an array.
 * Expected offsets are counted by hand in the literals below (and
 * cross-checked with strstr, which finds the same text independently).
 */
#include <string.h>
#include "base/jsonloc.h"
#include "testlib.h"

static const char doc[] = "{\"a\": [1, {\"b\": \"x,]}\"}, [2, 3]],\n"
                          " \"c~/d\": {\"e\": null},\n"
                          " \"\\u0066\\\"g\": true}";

static size_t offset_of(const char *needle)
{
    const char *p = strstr(doc, needle);
    ck_assert_ptr_nonnull(p);
    return (size_t)(p - doc);
}

START_TEST(test_jsonloc_find_paths)
{
    jsonloc_step a1b[] = {{"a", 0}, {NULL, 1}, {"b", 0}};
    jsonloc_span key, value;
    ck_assert(jsonloc_find(doc, strlen(doc), a1b, 3, &key, &value));
    ck_assert_uint_eq(value.begin, offset_of("\"x,]}\""));
    ck_assert_uint_eq(value.end, value.begin + 6);
    ck_assert_uint_eq(key.begin, offset_of("\"b\""));
    ck_assert_uint_eq(key.end, key.begin + 3);
    jsonloc_step a21[] = {{"a", 0}, {NULL, 2}, {NULL, 1}};
    ck_assert(jsonloc_find(doc, strlen(doc), a21, 3, &key, &value));
    ck_assert_uint_eq(value.begin, offset_of("3]]"));
    ck_assert_uint_eq(key.begin, value.begin);
    /* A name with '~' and '/', and one written with escapes ("f\"g"). */
    jsonloc_step ce[] = {{"c~/d", 0}, {"e", 0}};
    ck_assert(jsonloc_find(doc, strlen(doc), ce, 2, NULL, &value));
    ck_assert_uint_eq(value.begin, offset_of("null"));
    jsonloc_step fg[] = {{"f\"g", 0}};
    ck_assert(jsonloc_find(doc, strlen(doc), fg, 1, &key, &value));
    ck_assert_uint_eq(value.begin, offset_of("true"));
    ck_assert_uint_eq(key.begin, offset_of("\"\\u0066"));
}
END_TEST

START_TEST(test_jsonloc_find_missing)
{
    jsonloc_step none[] = {{"z", 0}}, past[] = {{"a", 0}, {NULL, 3}}, into_number[] = {{"a", 0}, {NULL, 0}, {"b", 0}};
    jsonloc_span value;
    ck_assert(!jsonloc_find(doc, strlen(doc), none, 1, NULL, &value));
    ck_assert(!jsonloc_find(doc, strlen(doc), past, 2, NULL, &value));
    ck_assert(!jsonloc_find(doc, strlen(doc), into_number, 3, NULL, &value));
    /* The root itself. */
    ck_assert(jsonloc_find(doc, strlen(doc), NULL, 0, NULL, &value));
    ck_assert_uint_eq(value.begin, 0);
    ck_assert_uint_eq(value.end, strlen(doc));
}
END_TEST

START_TEST(test_jsonloc_pointer_at)
{
    char buf[64];
    ck_assert_uint_eq(jsonloc_pointer_at(doc, strlen(doc), offset_of("x,]"), buf, sizeof buf), 6);
    ck_assert_str_eq(buf, "/a/1/b");
    jsonloc_pointer_at(doc, strlen(doc), offset_of("3]]"), buf, sizeof buf);
    ck_assert_str_eq(buf, "/a/2/1");
    jsonloc_pointer_at(doc, strlen(doc), offset_of("null"), buf, sizeof buf);
    ck_assert_str_eq(buf, "/c~0~1d/e");
    /* On a member name: the member. */
    jsonloc_pointer_at(doc, strlen(doc), offset_of("\"e\""), buf, sizeof buf);
    ck_assert_str_eq(buf, "/c~0~1d/e");
    jsonloc_pointer_at(doc, strlen(doc), offset_of("true"), buf, sizeof buf);
    ck_assert_str_eq(buf, "/f\"g");
    /* Between values: the container; the root: "". */
    jsonloc_pointer_at(doc, strlen(doc), offset_of(", [2"), buf, sizeof buf);
    ck_assert_str_eq(buf, "/a");
    ck_assert_uint_eq(jsonloc_pointer_at(doc, strlen(doc), 0, buf, sizeof buf), 0);
    ck_assert_str_eq(buf, "");
    /* Cut short, still terminated, full length returned. */
    ck_assert_uint_eq(jsonloc_pointer_at(doc, strlen(doc), offset_of("x,]"), buf, 4), 6);
    ck_assert_str_eq(buf, "/a/");
}
END_TEST

START_TEST(test_jsonloc_elements)
{
    size_t begins[4];
    jsonloc_step a[] = {{"a", 0}};
    ck_assert_uint_eq(jsonloc_elements(doc, strlen(doc), a, 1, begins, 4), 3);
    ck_assert_uint_eq(begins[0], offset_of("1, {"));
    ck_assert_uint_eq(begins[1], offset_of("{\"b\""));
    ck_assert_uint_eq(begins[2], offset_of("[2, 3]"));
    ck_assert_uint_eq(jsonloc_elements(doc, strlen(doc), a, 1, begins, 2), 2);
    jsonloc_step c[] = {{"c~/d", 0}};
    ck_assert_uint_eq(jsonloc_elements(doc, strlen(doc), c, 1, begins, 4), 0);
}
END_TEST

START_TEST(test_jsonloc_pointer_of_path)
{
    char buf[32];
    jsonloc_step p[] = {{"primitives", 0}, {NULL, 12}, {"a/b~", 0}};
    ck_assert_uint_eq(jsonloc_pointer(p, 3, buf, sizeof buf), strlen("/primitives/12/a~1b~0"));
    ck_assert_str_eq(buf, "/primitives/12/a~1b~0");
}
END_TEST

/* Text that is not JSON (cut short, unbalanced) ends the walk inside the
 * buffer: no answer or some answer, never a read past the end. */
START_TEST(test_jsonloc_broken_text_stays_in_bounds)
{
    static const char *const broken[] = {"{\"a\": [1, 2", "{\"a\": \"unterminated", "{\"a\\", "[[[[", "}}}", "",
                                         "{\"a\": {\"b\": [1, {\"c\"", "\"\\u12"};
    jsonloc_step ab[] = {{"a", 0}, {"b", 0}};
    for (size_t i = 0; i < sizeof broken / sizeof broken[0]; i++) {
        size_t len = strlen(broken[i]), begins[4];
        char buf[32];
        jsonloc_span value;
        if (jsonloc_find(broken[i], len, ab, 2, NULL, &value))
            ck_assert_uint_le(value.end, len);
        for (size_t off = 0; off <= len; off++)
            ck_assert_uint_lt(jsonloc_pointer_at(broken[i], len, off, buf, sizeof buf), 64);
        ck_assert_uint_le(jsonloc_elements(broken[i], len, ab, 1, begins, 4), 4);
    }
}
END_TEST

Suite *suite_jsonloc(void)
{
    Suite *s = suite_create("jsonloc");
    TCase *tc = tcase_create("jsonloc");
    tcase_add_test(tc, test_jsonloc_find_paths);
    tcase_add_test(tc, test_jsonloc_find_missing);
    tcase_add_test(tc, test_jsonloc_pointer_at);
    tcase_add_test(tc, test_jsonloc_elements);
    tcase_add_test(tc, test_jsonloc_pointer_of_path);
    tcase_add_test(tc, test_jsonloc_broken_text_stays_in_bounds);
    suite_add_tcase(s, tc);
    return s;
}
