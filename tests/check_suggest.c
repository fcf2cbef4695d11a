/* Tests of "did you mean" (src/base/suggest.c): the edit distance on hand
 * examples and the closeness thresholds of [LANG-DIAG-SUGGEST-1]. */
#include <string.h>
#include "testlib.h"
#include "base/suggest.h"

static int distance(const char *a, const char *b)
{
    return suggest_distance(a, strlen(a), b);
}

START_TEST(test_suggest_distance)
{
    ck_assert_int_eq(distance("radius", "radius"), 0);
    ck_assert_int_eq(distance("", ""), 0);
    ck_assert_int_eq(distance("", "abc"), 3);
    ck_assert_int_eq(distance("abc", ""), 3);
    /* kitten -> sitten -> sittin -> sitting */
    ck_assert_int_eq(distance("kitten", "sitting"), 3);
    ck_assert_int_eq(distance("radus", "radius"), 1);     /* one insertion */
    ck_assert_int_eq(distance("radiuss", "radius"), 1);   /* one deletion */
    ck_assert_int_eq(distance("radios", "radius"), 1);    /* one substitution */
    ck_assert_int_eq(distance("raidus", "radius"), 1);    /* one adjacent swap */
    ck_assert_int_eq(distance("ab", "ba"), 1);
    /* Optimal string alignment: a swapped pair is not edited again, so
     * "ca" -> "abc" costs 3 (true Damerau-Levenshtein would say 2). */
    ck_assert_int_eq(distance("ca", "abc"), 3);
    /* Case does not count. */
    ck_assert_int_eq(distance("KD", "kd"), 0);
    ck_assert_int_eq(distance("Look_At", "look_at"), 0);
    /* Only len bytes of the word are read. */
    ck_assert_int_eq(suggest_distance("spherex", 6, "sphere"), 0);
}
END_TEST

START_TEST(test_suggest_distance_long_words)
{
    char long_word[80];
    memset(long_word, 'a', 64);
    long_word[64] = '\0';
    ck_assert_int_eq(suggest_distance(long_word, 64, long_word), 1000);
    ck_assert_int_eq(suggest_distance(long_word, 63, long_word), 1000);
    ck_assert_int_eq(suggest_distance(long_word, 63, long_word + 1), 0);
}
END_TEST

/* [LANG-DIAG-SUGGEST-1] a candidate is offered when it is at most 1 edit
 * away for words of up to 4 bytes, 2 up to 8, 3 beyond; ties go to the
 * earlier candidate; nothing close enough gives NULL. */
START_TEST(test_suggest_nearest)
{
    static const char *const props[] = {"center", "radius", "material", "translate", "rotate", "scale"};
    static const char *const colours[] = {"color", "Kd", "Ks"};
    static const char *const far[] = {"direction"};
#define NEAREST(word, list) suggest_nearest(word, strlen(word), list, (int)(sizeof list / sizeof list[0]))
    ck_assert_str_eq(NEAREST("radus", props), "radius");
    ck_assert_str_eq(NEAREST("centre", props), "center");
    ck_assert_str_eq(NEAREST("materail", props), "material");
    ck_assert_str_eq(NEAREST("rotat", props), "rotate");
    ck_assert_str_eq(NEAREST("scal", props), "scale");
    ck_assert_ptr_null(NEAREST("colour", props));
    /* Up to 4 bytes: one edit. */
    ck_assert_str_eq(NEAREST("colr", colours), "color");
    ck_assert_ptr_null(NEAREST("clr", colours));
    ck_assert_str_eq(NEAREST("ks", colours), "Ks");
    /* A tie (Kd and Ks both one away) goes to the earlier. */
    ck_assert_str_eq(NEAREST("Kx", colours), "Kd");
    /* 5 to 8 bytes: two edits. */
    ck_assert_str_eq(NEAREST("colorxy", colours), "color");
    ck_assert_ptr_null(NEAREST("colorxyz", colours));
    /* 9 and more: three edits. */
    ck_assert_str_eq(NEAREST("directionxyz", far), "direction");
    ck_assert_ptr_null(NEAREST("directionwxyz", far));
    ck_assert_ptr_null(suggest_nearest("radius", 6, props, 0));
#undef NEAREST
}
END_TEST

Suite *suite_suggest(void)
{
    Suite *s = suite_create("suggest");
    TCase *tc = tcase_create("suggest");
    tcase_add_test(tc, test_suggest_distance);
    tcase_add_test(tc, test_suggest_distance_long_words);
    tcase_add_test(tc, test_suggest_nearest);
    suite_add_tcase(s, tc);
    return s;
}
