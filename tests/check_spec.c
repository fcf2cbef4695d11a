/* Keeps spec/language.md complete: every reserved word of the scanner's
 * table appears in it backquoted, every property of every block appears in
 * that block's section (`### \`name\``), every [LANG-...] ID a test cites
 * is defined there, and every ID defined there is cited by some test.
 * Tests run from the repository root. */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testlib.h"
#include "lang/keywords.h"
#include "lang/schema.h"

#define SPEC "spec/language.md"
#define TESTS "tests"

/* The whole of path, NUL-terminated; fails the test when unreadable. */
static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    ck_assert_msg(f != NULL, "cannot open %s (tests run from the repository root)", path);
    ck_assert_int_eq(fseek(f, 0, SEEK_END), 0);
    long size = ftell(f);
    ck_assert_int_ge(size, 0);
    rewind(f);
    char *text = malloc((size_t)size + 1);
    ck_assert_ptr_nonnull(text);
    ck_assert_uint_eq(fread(text, 1, (size_t)size, f), (size_t)size);
    text[size] = '\0';
    fclose(f);
    return text;
}

static int has_backquoted(const char *text, size_t len, const char *word)
{
    char quoted[80];
    int n = snprintf(quoted, sizeof quoted, "`%s`", word);
    for (size_t i = 0; n > 0 && i + (size_t)n <= len; i++)
        if (memcmp(text + i, quoted, (size_t)n) == 0)
            return 1;
    return 0;
}

/* The section under the heading "### `block`", up to the next heading. */
static const char *section(const char *spec, const char *block, size_t *len)
{
    char heading[80];
    snprintf(heading, sizeof heading, "\n### `%s`\n", block);
    const char *start = strstr(spec, heading);
    if (!start)
        return NULL;
    start += strlen(heading);
    const char *end = start;
    while (*end && !(end[0] == '\n' && end[1] == '#'))
        end++;
    *len = (size_t)(end - start);
    return start;
}

START_TEST(test_spec_lists_every_keyword)
{
    char *spec = read_text(SPEC);
    size_t len = strlen(spec);
    for (int i = 0; i < KEYWORD_COUNT; i++) {
        const char *word = keyword_get((keyword_id)i)->name;
        ck_assert_msg(has_backquoted(spec, len, word), "%s does not mention `%s`", SPEC, word);
    }
    free(spec);
}
END_TEST

START_TEST(test_spec_lists_every_property_of_every_block)
{
    char *spec = read_text(SPEC);
    int blocks = 0;
    for (int i = 0; i < KEYWORD_COUNT; i++) {
        const block_schema *schema = schema_of((keyword_id)i);
        if (!schema)
            continue;
        blocks++;
        const char *block = keyword_name((keyword_id)i);
        size_t len;
        const char *body = section(spec, block, &len);
        ck_assert_msg(body != NULL, "%s has no section \"### `%s`\"", SPEC, block);
        for (int k = 0; k < schema->prop_count; k++) {
            const char *prop = keyword_name(schema->props[k]);
            ck_assert_msg(has_backquoted(body, len, prop), "the section of `%s` in %s does not mention `%s`", block,
                          SPEC, prop);
        }
    }
    /* image camera ambient 3 lights material 9 primitives */
    ck_assert_int_eq(blocks, 16);
    free(spec);
}
END_TEST

/* The helpers themselves: a word must be whole and backquoted. */
START_TEST(test_spec_helpers)
{
    static const char text[] = "intro\n### `sphere`\nthe `radius` and n\n### `plane`\n`normal`\n";
    size_t len;
    const char *body = section(text, "sphere", &len);
    ck_assert_ptr_nonnull(body);
    ck_assert(has_backquoted(body, len, "radius"));
    ck_assert(!has_backquoted(body, len, "n"));
    ck_assert(!has_backquoted(body, len, "normal"));
    ck_assert(!has_backquoted(body, len, "radiu"));
    ck_assert_ptr_null(section(text, "box", &len));
}
END_TEST

typedef struct id_list {
    char ids[256][48];
    int count;
} id_list;

static int id_listed(const id_list *l, const char *id)
{
    for (int i = 0; i < l->count; i++)
        if (strcmp(l->ids[i], id) == 0)
            return 1;
    return 0;
}

/* Adds every "[PREFIX-...]" of text to l (once each); prefix is "[LANG-",
 * "[JSON-" or "[REL-". */
static void collect_ids(const char *text, const char *prefix, id_list *l)
{
    for (const char *p = strstr(text, prefix); p; p = strstr(p + 1, prefix)) {
        size_t n = strspn(p + 1, "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-");
        if (p[1 + n] != ']' || n + 1 >= sizeof l->ids[0])
            continue;
        char id[48];
        memcpy(id, p + 1, n);
        id[n] = '\0';
        if (!id_listed(l, id) && l->count < 256)
            strcpy(l->ids[l->count++], id);
    }
}

/* The IDs cited by the test sources check_NAME.c and the test scripts
 * NAME.sh of directory dir, added to l. */
static void cited_ids_in(const char *dir_path, const char *prefix, id_list *l)
{
    DIR *dir = opendir(dir_path);
    ck_assert_ptr_nonnull(dir);
    for (struct dirent *e = readdir(dir); e; e = readdir(dir)) {
        size_t n = strlen(e->d_name);
        int script = n > 3 && strcmp(e->d_name + n - 3, ".sh") == 0;
        if (!script && (strncmp(e->d_name, "check_", 6) != 0 || n < 3 || strcmp(e->d_name + n - 2, ".c") != 0 ||
                        strcmp(e->d_name, "check_spec.c") == 0))
            continue;
        char path[512];
        snprintf(path, sizeof path, "%s/%s", dir_path, e->d_name);
        char *text = read_text(path);
        collect_ids(text, prefix, l);
        free(text);
    }
    closedir(dir);
}

/* The IDs cited by tests/ and by the embedding examples' script. */
static void cited_ids(const char *prefix, id_list *l)
{
    l->count = 0;
    cited_ids_in(TESTS, prefix, l);
    cited_ids_in(TESTS "/embed", prefix, l);
}

/* Every ID of spec_path with prefix is cited by a test, and every one a
 * test cites is defined there; at least `least` of them. */
static void check_ids(const char *spec_path, const char *prefix, int least)
{
    id_list cited, defined;
    char *spec = read_text(spec_path);
    cited_ids(prefix, &cited);
    defined.count = 0;
    collect_ids(spec, prefix, &defined);
    ck_assert_int_ge(cited.count, least);
    for (int i = 0; i < cited.count; i++)
        ck_assert_msg(id_listed(&defined, cited.ids[i]), "a test cites [%s], which %s does not define",
                      cited.ids[i], spec_path);
    for (int i = 0; i < defined.count; i++)
        ck_assert_msg(id_listed(&cited, defined.ids[i]), "%s defines [%s], which no test cites", spec_path,
                      defined.ids[i]);
    free(spec);
}

START_TEST(test_spec_defines_every_cited_id)
{
    check_ids(SPEC, "[LANG-", 40);
}
END_TEST

/* The same for the JSON format's statements (spec/json.md). */
START_TEST(test_spec_json_defines_every_cited_id)
{
    check_ids("spec/json.md", "[JSON-", 10);
}
END_TEST

/* The same for the reliability policies (spec/reliability.md). */
START_TEST(test_spec_reliability_defines_every_cited_id)
{
    check_ids("spec/reliability.md", "[REL-", 25);
}
END_TEST

/* The same for the embedding guarantees (spec/embedding.md). */
START_TEST(test_spec_embedding_defines_every_cited_id)
{
    check_ids("spec/embedding.md", "[EMBED-", 20);
}
END_TEST

/* The first ID defined twice in text: a definition is the bold
 * "**[ID]**"; NULL when none is.  id gets the ID. */
static const char *duplicate_definition(const char *text, char *id, size_t size)
{
    for (const char *p = strstr(text, "**["); p; p = strstr(p + 1, "**[")) {
        const char *end = strstr(p + 3, "]**");
        size_t n = end ? (size_t)(end - p) + 3 : 0;
        if (!end || n >= size || strspn(p + 3, "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-") != n - 6)
            continue;
        memcpy(id, p, n);
        id[n] = '\0';
        if (strstr(end, id))
            return p;
    }
    return NULL;
}

/* No statement ID is defined twice in the spec: a citation must name one
 * statement.  All spec/ files are read as one text, since an ID belongs to
 * one file only. */
START_TEST(test_spec_no_id_defined_twice)
{
    char id[64];
    ck_assert_ptr_nonnull(duplicate_definition("**[A-1]** x **[B-1]** y **[A-1]**", id, sizeof id));
    ck_assert_str_eq(id, "**[A-1]**");
    ck_assert_ptr_null(duplicate_definition("**[A-1]** x [A-1] **[A-10]** **[B-1]**", id, sizeof id));
    DIR *dir = opendir("spec");
    ck_assert_ptr_nonnull(dir);
    size_t len = 0, files = 0;
    char *all = calloc(1, 1);
    for (struct dirent *e = readdir(dir); e; e = readdir(dir)) {
        size_t n = strlen(e->d_name);
        if (n < 4 || strcmp(e->d_name + n - 3, ".md") != 0)
            continue;
        char path[512];
        snprintf(path, sizeof path, "spec/%s", e->d_name);
        char *text = read_text(path);
        size_t add = strlen(text);
        all = realloc(all, len + add + 2);
        ck_assert_ptr_nonnull(all);
        memcpy(all + len, text, add);
        all[len + add] = '\n';
        all[len += add + 1] = '\0';
        free(text);
        files++;
    }
    closedir(dir);
    ck_assert_uint_ge(files, 10);
    ck_assert_msg(duplicate_definition(all, id, sizeof id) == NULL, "%s is defined twice in spec/", id);
    free(all);
}
END_TEST

Suite *suite_spec(void)
{
    Suite *s = suite_create("spec");
    TCase *tc = tcase_create("spec");
    tcase_add_test(tc, test_spec_lists_every_keyword);
    tcase_add_test(tc, test_spec_lists_every_property_of_every_block);
    tcase_add_test(tc, test_spec_helpers);
    tcase_add_test(tc, test_spec_defines_every_cited_id);
    tcase_add_test(tc, test_spec_json_defines_every_cited_id);
    tcase_add_test(tc, test_spec_reliability_defines_every_cited_id);
    tcase_add_test(tc, test_spec_embedding_defines_every_cited_id);
    tcase_add_test(tc, test_spec_no_id_defined_twice);
    suite_add_tcase(s, tc);
    return s;
}
