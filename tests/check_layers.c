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

/* A tree and a module graph are tens of megabytes: they go on the heap, not
 * in static storage, which LeakSanitizer scans whole at the exit of every
 * forked test of the sanitizer build (130 MB, 0.08 s of CPU per test). */
static void *zeroed(size_t size)
{
    void *p = calloc(1, size);
    ck_assert_ptr_nonnull(p);
    return p;
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
    tree *t = zeroed(sizeof *t);
    int checked = 0;
    scan_tree(t);
    for (int i = 0; i < t->count; i++) {
        const src_file *f = &t->files[i];
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
            ck_assert_msg(find_file(t, inc) >= 0, "src/%s includes \"%s\", which does not exist", f->path, inc);
            ck_assert_msg(rank <= f->layer, "src/%s (layer %s) includes \"%s\" from the higher layer %s", f->path,
                          LAYER_ORDER[f->layer], inc, LAYER_ORDER[rank]);
            checked++;
        }
    }
    ck_assert_int_gt(checked, 100);
    free(t);
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
    tree *t = zeroed(sizeof *t);
    static int state[MAX_FILES];
    char trail[2048] = "";
    scan_tree(t);
    memset(state, 0, sizeof state);
    for (int i = 0; i < t->count; i++)
        if (state[i] == 0)
            ck_assert_msg(!find_cycle(t, i, state, trail, sizeof trail), "include circle:%s", trail);
    free(t);
}
END_TEST

/*
 * Circles of calls between modules.  A module is a .c file with the header
 * of the same name ("cli/cli_tiles.c" and "cli/cli_tiles.h"); module A
 * uses module B when A's .c calls a function that B's .c defines, through
 * whichever header declares it (the include circles of files are
 * test_no_include_circle's).  No module may come back to itself that way:
 * files that call each other in a circle share a part that belongs in a
 * module below them all.
 */
enum { MAX_DEFS = 8192, DEF_LEN = 64 };

typedef struct module_graph {
    int count;
    char name[MAX_FILES][NAME_LEN];            /* "cli/cli_tiles" */
    unsigned char uses[MAX_FILES][MAX_FILES];
    char why[MAX_FILES][MAX_FILES][DEF_LEN];   /* the first name called */
    int def_count;
    char def_name[MAX_DEFS][DEF_LEN];
    int def_module[MAX_DEFS];
} module_graph;


static int module_of(module_graph *g, const char *path)
{
    size_t n = strlen(path) - 2;   /* without ".c" or ".h" */
    for (int i = 0; i < g->count; i++)
        if (strlen(g->name[i]) == n && strncmp(g->name[i], path, n) == 0)
            return i;
    ck_assert_int_lt(g->count, MAX_FILES);
    snprintf(g->name[g->count], NAME_LEN, "%.*s", (int)n, path);
    return g->count++;
}

/* Blanks the comments and the string and character literals of t, so
 * that a name in them is not read as a call; lines stay where they were. */
static void blank_code(char *t)
{
    for (char *p = t; *p; p++) {
        char *end = NULL;
        if (p[0] == '/' && p[1] == '*') {
            end = strstr(p + 2, "*/");
            end = end ? end + 2 : p + strlen(p);
        } else if (p[0] == '/' && p[1] == '/') {
            end = p + strcspn(p, "\n");
        } else if (*p == '"' || *p == '\'') {
            for (end = p + 1; *end && *end != *p && *end != '\n'; end++)
                end += end[0] == '\\' && end[1] != '\0';
            end += *end == *p;
        }
        for (; end && p < end; p++)
            *p = *p == '\n' ? '\n' : ' ';
        if (end)
            p--;
    }
}

/* The text of src/path, blanked (blank_code; malloc'd). */
static char *code_text(const char *path)
{
    char full[NAME_LEN + 8];
    snprintf(full, sizeof full, "src/%s", path);
    FILE *fp = fopen(full, "rb");
    ck_assert_msg(fp != NULL, "cannot open %s", full);
    ck_assert_int_eq(fseek(fp, 0, SEEK_END), 0);
    long n = ftell(fp);
    rewind(fp);
    char *t = malloc((size_t)n + 1);
    ck_assert_ptr_nonnull(t);
    t[fread(t, 1, (size_t)n, fp)] = '\0';
    fclose(fp);
    blank_code(t);
    return t;
}

static int is_name_char(char c)
{
    return c == '_' || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
}

/* The name before the '(' at paren, into out; 0 when there is none. */
static int name_before(const char *text, const char *paren, char *out)
{
    const char *e = paren;
    while (e > text && (e[-1] == ' ' || e[-1] == '\t'))
        e--;
    const char *b = e;
    while (b > text && is_name_char(b[-1]))
        b--;
    if (b == e || (size_t)(e - b) >= DEF_LEN || (*b >= '0' && *b <= '9'))
        return 0;
    snprintf(out, DEF_LEN, "%.*s", (int)(e - b), b);
    return 1;
}

/* The functions that the blanked text of a .c file defines with external
 * linkage: a line that starts a declaration in column 0 (not static, not a
 * preprocessor line) whose first parenthesis closes right before a '{'. */
static void read_definitions(module_graph *g, int module, const char *text)
{
    for (const char *line = text; *line; line += strcspn(line, "\n"), line += *line == '\n') {
        if (!is_name_char(*line) || strncmp(line, "static", 6) == 0 || strncmp(line, "typedef", 7) == 0)
            continue;
        const char *paren = line + strcspn(line, "(;{=\n");
        if (*paren != '(')
            continue;
        const char *p = paren;
        for (int depth = 0; *p; p++) {
            depth += (*p == '(') - (*p == ')');
            if (depth == 0)
                break;
        }
        if (!*p)
            continue;
        for (p++; *p == ' ' || *p == '\t' || *p == '\n';)
            p++;
        char name[DEF_LEN];
        if (*p != '{' || !name_before(line, paren, name))
            continue;
        ck_assert_int_lt(g->def_count, MAX_DEFS);
        memcpy(g->def_name[g->def_count], name, DEF_LEN);
        g->def_module[g->def_count++] = module;
    }
}

static void use(module_graph *g, int from, int to, const char *why)
{
    if (from == to || g->uses[from][to])
        return;
    g->uses[from][to] = 1;
    snprintf(g->why[from][to], DEF_LEN, "%s", why);
}

/* Every name followed by '(' in the blanked text of a .c file that another
 * module defines. */
static void read_calls(module_graph *g, int module, const char *text)
{
    for (const char *p = strchr(text, '('); p; p = strchr(p + 1, '(')) {
        char name[DEF_LEN];
        if (!name_before(text, p, name))
            continue;
        for (int d = 0; d < g->def_count; d++)
            if (strcmp(g->def_name[d], name) == 0)
                use(g, module, g->def_module[d], name);
    }
}

static void build_module_graph(const tree *t, module_graph *g)
{
    char *texts[MAX_FILES] = {NULL};
    memset(g, 0, sizeof *g);
    for (int i = 0; i < t->count; i++) {
        int m = module_of(g, t->files[i].path);
        const char *path = t->files[i].path;
        if (path[strlen(path) - 1] == 'c') {
            texts[i] = code_text(path);
            read_definitions(g, m, texts[i]);
        }
    }
    for (int i = 0; i < t->count; i++) {
        if (texts[i])
            read_calls(g, module_of(g, t->files[i].path), texts[i]);
        free(texts[i]);
    }
}

/* Depth-first from at over the modules; on a circle its path "a -(name)-> b ..." is written into trail. */
static int find_module_cycle(const module_graph *g, int at, int *state, int *stack, int depth, char *trail,
                             size_t trail_len)
{
    state[at] = 1;
    stack[depth] = at;
    for (int to = 0; to < g->count; to++) {
        if (!g->uses[at][to] || state[to] == 2)
            continue;
        if (state[to] == 1) {
            int from = depth;
            while (stack[from] != to)
                from--;
            for (int k = from; k <= depth; k++) {
                int next = k < depth ? stack[k + 1] : to;
                size_t used = strlen(trail);
                snprintf(trail + used, trail_len - used, " %s -(%s)->", g->name[stack[k]], g->why[stack[k]][next]);
            }
            size_t used = strlen(trail);
            snprintf(trail + used, trail_len - used, " %s", g->name[to]);
            return 1;
        }
        if (find_module_cycle(g, to, state, stack, depth + 1, trail, trail_len))
            return 1;
    }
    state[at] = 2;
    return 0;
}

static int module_circle(const module_graph *g, char *trail, size_t trail_len)
{
    static int state[MAX_FILES], stack[MAX_FILES];
    memset(state, 0, sizeof state);
    trail[0] = '\0';
    for (int i = 0; i < g->count; i++)
        if (state[i] == 0 && find_module_cycle(g, i, state, stack, 0, trail, trail_len))
            return 1;
    return 0;
}

START_TEST(test_no_module_circle)
{
    tree *t = zeroed(sizeof *t);
    module_graph *g = zeroed(sizeof *g);
    char trail[4096];
    scan_tree(t);
    build_module_graph(t, g);
    ck_assert_int_gt(g->def_count, 500);
    ck_assert_msg(!module_circle(g, trail, sizeof trail), "modules in a circle:%s", trail);
    free(t);
    free(g);
}
END_TEST

/* The module reader on made-up code: definitions with their parameters
 * on two lines are found, static ones and prototypes are not, and a call
 * in a comment or a string is no call; the circle finder sees a circle of
 * calls. */
START_TEST(test_module_reader_sees_calls)
{
    module_graph *g = zeroed(sizeof *g);
    int a = module_of(g, "base/a.c"), b = module_of(g, "base/b.c");
    ck_assert_int_eq(module_of(g, "base/a.h"), a);
    char text_a[] = "int a_one(int x,\n          int y)\n{\n    return b_two(x) /* a_one(y) */;\n}\n"
                    "static int hidden(void)\n{\n    return 0;\n}\nint a_proto(void);\n";
    char text_b[] = "int b_two(int x)\n{\n    puts(\"a_one(1)\");\n    return x;\n}\n";
    blank_code(text_a);
    blank_code(text_b);
    read_definitions(g, a, text_a);
    read_definitions(g, b, text_b);
    ck_assert_int_eq(g->def_count, 2);
    ck_assert_str_eq(g->def_name[0], "a_one");
    ck_assert_str_eq(g->def_name[1], "b_two");
    read_calls(g, a, text_a);
    read_calls(g, b, text_b);
    ck_assert(g->uses[a][b] && !g->uses[b][a]);
    char trail[512];
    ck_assert_int_eq(module_circle(g, trail, sizeof trail), 0);
    use(g, b, a, "a_one");
    ck_assert_int_eq(module_circle(g, trail, sizeof trail), 1);
    ck_assert_msg(strstr(trail, "base/a -(b_two)-> base/b -(a_one)-> base/a") != NULL, "%s", trail);
    free(g);
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
    tree *t = zeroed(sizeof *t);
    static int state[MAX_FILES];
    char trail[512] = "";
    const char *names[] = {"base/a.h", "base/b.h", "base/c.h"};
    for (int i = 0; i < 3; i++) {
        snprintf(t->files[i].path, NAME_LEN, "%s", names[i]);
        snprintf(t->files[i].includes[0], NAME_LEN, "%s", names[(i + 1) % 3]);
        t->files[i].include_count = 1;
    }
    t->count = 3;
    memset(state, 0, sizeof state);
    ck_assert_int_eq(find_cycle(t, 0, state, trail, sizeof trail), 1);
    ck_assert_ptr_nonnull(strstr(trail, "base/c.h"));
    t->files[2].include_count = 0;
    memset(state, 0, sizeof state);
    ck_assert_int_eq(find_cycle(t, 0, state, trail, sizeof trail), 0);
    free(t);
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

/* check(path, n, line) for every line n of every source file under src/
 * (path relative to src/). */
static void each_source_line(void (*check)(const char *path, int n, const char *line))
{
    tree *t = zeroed(sizeof *t);
    scan_tree(t);
    for (int i = 0; i < t->count; i++) {
        char full[NAME_LEN + 8], line[512];
        snprintf(full, sizeof full, "src/%s", t->files[i].path);
        FILE *fp = fopen(full, "r");
        ck_assert_ptr_nonnull(fp);
        for (int n = 1; fgets(line, sizeof line, fp); n++)
            check(t->files[i].path, n, line);
        fclose(fp);
    }
    free(t);
}

static void include_written_plainly(const char *path, int n, const char *line)
{
    const char *p = line;
    while (*p == ' ' || *p == '\t')
        p++;
    if (*p != '#')
        return;
    p++;
    while (*p == ' ' || *p == '\t')
        p++;
    if (strncmp(p, "include", 7) == 0)
        ck_assert_msg(line[0] == '#' && strncmp(line, "#include", 8) == 0,
                      "src/%s:%d: write includes as \"#include\" at the line start: %s", path, n, line);
}

START_TEST(test_includes_written_plainly)
{
    each_source_line(include_written_plainly);
}
END_TEST

/* [REL-CANCEL-1] A caller's cancel callback is asked only through
 * base/cancel.h (cancel_poll: one rule for when it is asked and for a stop
 * that sticks): no file under src/ calls a `cancel` member itself
 * ("->cancel(" or ".cancel("). */
static void cancel_through_helper(const char *path, int n, const char *line)
{
    ck_assert_msg(strcmp(path, "base/cancel.h") == 0 || (!strstr(line, "->cancel(") && !strstr(line, ".cancel(")),
                  "src/%s:%d asks a cancel callback itself; use base/cancel.h: %s", path, n, line);
}

START_TEST(test_cancel_through_helper)
{
    each_source_line(cancel_through_helper);
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
    tcase_add_test(tc, test_no_module_circle);
    tcase_add_test(tc, test_module_reader_sees_calls);
    tcase_add_test(tc, test_includes_written_plainly);
    tcase_add_test(tc, test_public_header_standard_only);
    tcase_add_test(tc, test_cancel_through_helper);
    suite_add_tcase(s, tc);
    return s;
}
