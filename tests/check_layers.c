/*
 * check_layers.c - the layers of src/ as the #include lines draw them.
 *
 * Every source file lives in src/<layer>/ and names the header it includes
 * by its layer ("render/shade.h").  A file may include a header of its own
 * layer or of a layer below it in LAYER_ORDER, never one above; and no
 * chain of includes returns to where it started.  Generated headers (the parser's
 * and the oracle list, under build/) are written without a folder and are
 * allowed everywhere they are used.  The public header, include/refray.h,
 * is included as "refray.h" by the layers from PUBLIC_FROM up only, and
 * itself includes standard headers only.
 */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testlib.h"

/* The allowed order, lowest first: written here and nowhere else. */
static const char *const LAYER_ORDER[] = {
    "base", "image", "lang", "scene", "render", "io", "oracle", "export", "verify", "api", "cli", NULL
};

static const char *const GENERATED[] = {"scene.tab.h", "scene.lex.h", "oracle_list.h", NULL};

#define PUBLIC_HEADER "refray.h"
#define PUBLIC_FROM "api"

/* The headers of the C99 standard library, and of POSIX that the public
 * header could need: the only ones refray.h may include. */
static const char *const STANDARD[] = {
    "assert.h", "complex.h", "ctype.h", "errno.h", "fenv.h", "float.h", "inttypes.h", "iso646.h", "limits.h",
    "locale.h", "math.h", "setjmp.h", "signal.h", "stdarg.h", "stdbool.h", "stddef.h", "stdint.h", "stdio.h",
    "stdlib.h", "string.h", "tgmath.h", "time.h", "wchar.h", "wctype.h", NULL};

enum { MAX_FILES = 512, MAX_INCLUDES = 64, NAME_LEN = 600 };

typedef struct src_file {
    char path[NAME_LEN];      /* "render/shade.c", relative to src/ */
    int layer;
    int include_count;
    char includes[MAX_INCLUDES][NAME_LEN];
} src_file;

typedef struct tree {
    src_file files[MAX_FILES];
    int count;
} tree;

static int layer_rank(const char *name, size_t len)
{
    for (int i = 0; LAYER_ORDER[i]; i++)
        if (strlen(LAYER_ORDER[i]) == len && strncmp(LAYER_ORDER[i], name, len) == 0)
            return i;
    return -1;
}

static int is_generated(const char *inc)
{
    for (int i = 0; GENERATED[i]; i++)
        if (strcmp(GENERATED[i], inc) == 0)
            return 1;
    return 0;
}

/* The quoted includes of path, in order. */
static void read_includes(const char *path, src_file *f)
{
    FILE *fp = fopen(path, "r");
    char line[512];
    ck_assert_msg(fp != NULL, "cannot open %s", path);
    f->include_count = 0;
    while (fgets(line, sizeof line, fp)) {
        const char *p = line;
        while (*p == ' ' || *p == '\t')
            p++;
        if (strncmp(p, "#include", 8) != 0)
            continue;
        p += 8;
        while (*p == ' ' || *p == '\t')
            p++;
        if (*p != '"')
            continue;
        const char *end = strchr(p + 1, '"');
        ck_assert_msg(end && (size_t)(end - p - 1) < NAME_LEN, "%s: unreadable include: %s", path, line);
        ck_assert_msg(f->include_count < MAX_INCLUDES, "%s: more than %d includes", path, MAX_INCLUDES);
        memcpy(f->includes[f->include_count], p + 1, (size_t)(end - p - 1));
        f->includes[f->include_count][end - p - 1] = '\0';
        f->include_count++;
    }
    fclose(fp);
}

static int is_source(const char *name)
{
    size_t n = strlen(name);
    return n > 2 && name[n - 2] == '.' && (name[n - 1] == 'c' || name[n - 1] == 'h');
}

/* Every .c and .h under src/<layer>/; a folder that is not a layer fails. */
static void scan_tree(tree *t)
{
    DIR *top = opendir("src");
    struct dirent *e;
    ck_assert_msg(top != NULL, "run the tests from the repository root (no src/)");
    t->count = 0;
    while ((e = readdir(top)) != NULL) {
        if (e->d_name[0] == '.')
            continue;
        ck_assert_msg(!is_source(e->d_name), "src/%s is outside every layer folder", e->d_name);
        int rank = layer_rank(e->d_name, strlen(e->d_name));
        ck_assert_msg(rank >= 0, "src/%s is not a layer named in LAYER_ORDER", e->d_name);
        char dir[NAME_LEN];
        snprintf(dir, sizeof dir, "src/%s", e->d_name);
        DIR *sub = opendir(dir);
        ck_assert_msg(sub != NULL, "cannot open %s", dir);
        struct dirent *s;
        while ((s = readdir(sub)) != NULL) {
            if (!is_source(s->d_name))
                continue;
            ck_assert_int_lt(t->count, MAX_FILES);
            src_file *f = &t->files[t->count++];
            snprintf(f->path, sizeof f->path, "%s/%s", e->d_name, s->d_name);
            f->layer = rank;
            char full[NAME_LEN + 8];
            snprintf(full, sizeof full, "src/%s", f->path);
            read_includes(full, f);
        }
        closedir(sub);
    }
    closedir(top);
    ck_assert_int_gt(t->count, 0);
}

static int find_file(const tree *t, const char *path)
{
    for (int i = 0; i < t->count; i++)
        if (strcmp(t->files[i].path, path) == 0)
            return i;
    return -1;
}

START_TEST(test_no_include_runs_up)
{
    static tree t;
    int checked = 0;
    scan_tree(&t);
    for (int i = 0; i < t.count; i++) {
        const src_file *f = &t.files[i];
        for (int k = 0; k < f->include_count; k++) {
            const char *inc = f->includes[k];
            if (is_generated(inc))
                continue;
            if (strcmp(inc, PUBLIC_HEADER) == 0) {
                ck_assert_msg(f->layer >= layer_rank(PUBLIC_FROM, strlen(PUBLIC_FROM)),
                              "src/%s (layer %s) includes the public header; only %s and above may", f->path,
                              LAYER_ORDER[f->layer], PUBLIC_FROM);
                continue;
            }
            const char *slash = strchr(inc, '/');
            ck_assert_msg(slash != NULL, "src/%s includes \"%s\" without its layer folder", f->path, inc);
            int rank = layer_rank(inc, (size_t)(slash - inc));
            ck_assert_msg(rank >= 0, "src/%s includes \"%s\": not a layer", f->path, inc);
            ck_assert_msg(find_file(&t, inc) >= 0, "src/%s includes \"%s\", which does not exist", f->path, inc);
            ck_assert_msg(rank <= f->layer, "src/%s (layer %s) includes \"%s\" from the higher layer %s", f->path,
                          LAYER_ORDER[f->layer], inc, LAYER_ORDER[rank]);
            checked++;
        }
    }
    ck_assert_int_gt(checked, 100);
}
END_TEST

/* Depth-first search; state 1 = on the current path, 2 = done. */
static int find_cycle(const tree *t, int at, int *state, char *trail, size_t trail_len)
{
    state[at] = 1;
    const src_file *f = &t->files[at];
    for (int k = 0; k < f->include_count; k++) {
        int to = find_file(t, f->includes[k]);
        if (to < 0)
            continue;
        if (state[to] == 1 || (state[to] == 0 && find_cycle(t, to, state, trail, trail_len))) {
            size_t used = strlen(trail);
            snprintf(trail + used, trail_len - used, " <- %s", f->path);
            return 1;
        }
    }
    state[at] = 2;
    return 0;
}

START_TEST(test_no_include_circle)
{
    static tree t;
    static int state[MAX_FILES];
    char trail[2048] = "";
    scan_tree(&t);
    memset(state, 0, sizeof state);
    for (int i = 0; i < t.count; i++)
        if (state[i] == 0)
            ck_assert_msg(!find_cycle(&t, i, state, trail, sizeof trail), "include circle:%s", trail);
}
END_TEST

/* The test's own reading, on a file made to break each rule. */
START_TEST(test_reader_sees_includes)
{
    const char *path = "build/check_layers_probe.h";
    FILE *fp = fopen(path, "w");
    ck_assert_ptr_nonnull(fp);
    fputs("#include <stdio.h>\n  #  include \"cli/cli.h\"\n#include \"scene.tab.h\"\n", fp);
    fclose(fp);
    src_file f;
    read_includes(path, &f);
    remove(path);
    /* "#  include" with inner spaces is an include too but is not matched:
     * the house style writes "#include", and the sources are checked for it. */
    ck_assert_int_eq(f.include_count, 1);
    ck_assert_str_eq(f.includes[0], "scene.tab.h");
    ck_assert_int_eq(layer_rank("cli", 3), (int)(sizeof LAYER_ORDER / sizeof LAYER_ORDER[0]) - 2);
    ck_assert_int_lt(layer_rank("base", 4), layer_rank("render", 6));
    ck_assert_int_eq(layer_rank("nowhere", 7), -1);
}
END_TEST

/* The circle finder on a made-up tree: a.h -> b.h -> c.h -> a.h. */
START_TEST(test_cycle_finder_sees_circle)
{
    static tree t;
    static int state[MAX_FILES];
    char trail[512] = "";
    memset(&t, 0, sizeof t);
    const char *names[] = {"base/a.h", "base/b.h", "base/c.h"};
    for (int i = 0; i < 3; i++) {
        snprintf(t.files[i].path, NAME_LEN, "%s", names[i]);
        snprintf(t.files[i].includes[0], NAME_LEN, "%s", names[(i + 1) % 3]);
        t.files[i].include_count = 1;
    }
    t.count = 3;
    memset(state, 0, sizeof state);
    ck_assert_int_eq(find_cycle(&t, 0, state, trail, sizeof trail), 1);
    ck_assert_ptr_nonnull(strstr(trail, "base/c.h"));
    t.files[2].include_count = 0;
    memset(state, 0, sizeof state);
    ck_assert_int_eq(find_cycle(&t, 0, state, trail, sizeof trail), 0);
}
END_TEST

/* The #include lines of path, quoted and angled, as "<x>" or "\"x\"". */
static int all_includes(const char *path, char names[][NAME_LEN], int max)
{
    FILE *fp = fopen(path, "r");
    char line[512];
    int n = 0;
    ck_assert_msg(fp != NULL, "cannot open %s", path);
    while (fgets(line, sizeof line, fp)) {
        const char *p = line;
        while (*p == ' ' || *p == '\t')
            p++;
        if (*p++ != '#')
            continue;
        while (*p == ' ' || *p == '\t')
            p++;
        if (strncmp(p, "include", 7) != 0)
            continue;
        p += 7;
        while (*p == ' ' || *p == '\t')
            p++;
        ck_assert_int_lt(n, max);
        snprintf(names[n++], NAME_LEN, "%.*s", (int)strcspn(p, "\r\n"), p);
    }
    fclose(fp);
    return n;
}

static int is_standard(const char *include)
{
    size_t n = strlen(include);
    if (n < 3 || include[0] != '<' || include[n - 1] != '>')
        return 0;
    for (int i = 0; STANDARD[i]; i++)
        if (strlen(STANDARD[i]) == n - 2 && strncmp(include + 1, STANDARD[i], n - 2) == 0)
            return 1;
    return 0;
}

/* [EMBED-HEADER-1] include/refray.h includes standard headers only. */
START_TEST(test_public_header_standard_only)
{
    static char names[MAX_INCLUDES][NAME_LEN];
    int n = all_includes("include/" PUBLIC_HEADER, names, MAX_INCLUDES);
    ck_assert_int_gt(n, 0);
    for (int i = 0; i < n; i++)
        ck_assert_msg(is_standard(names[i]), "include/refray.h includes %s, not a standard header", names[i]);
    ck_assert(is_standard("<stdio.h>"));
    ck_assert(!is_standard("\"stdio.h\""));
    ck_assert(!is_standard("<png.h>"));
    ck_assert(!is_standard("<scene/scene.h>"));
}
END_TEST

START_TEST(test_includes_written_plainly)
{
    static tree t;
    scan_tree(&t);
    for (int i = 0; i < t.count; i++) {
        char full[NAME_LEN + 8], line[512];
        snprintf(full, sizeof full, "src/%s", t.files[i].path);
        FILE *fp = fopen(full, "r");
        ck_assert_ptr_nonnull(fp);
        while (fgets(line, sizeof line, fp)) {
            const char *p = line;
            while (*p == ' ' || *p == '\t')
                p++;
            if (*p != '#')
                continue;
            p++;
            while (*p == ' ' || *p == '\t')
                p++;
            if (strncmp(p, "include", 7) == 0)
                ck_assert_msg(line[0] == '#' && strncmp(line, "#include", 8) == 0,
                              "src/%s: write includes as \"#include\" at the line start: %s", t.files[i].path, line);
        }
        fclose(fp);
    }
}
END_TEST

Suite *suite_layers(void)
{
    Suite *s = suite_create("layers");
    TCase *tc = tcase_create("includes");
    tcase_add_test(tc, test_reader_sees_includes);
    tcase_add_test(tc, test_no_include_runs_up);
    tcase_add_test(tc, test_no_include_circle);
    tcase_add_test(tc, test_cycle_finder_sees_circle);
    tcase_add_test(tc, test_includes_written_plainly);
    tcase_add_test(tc, test_public_header_standard_only);
    suite_add_tcase(s, tc);
    return s;
}
