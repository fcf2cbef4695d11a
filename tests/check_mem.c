/*
 * check_mem.c - the allocator hook (src/base/mem.h, spec/embedding.md):
 * every allocation of a load and a render goes through the mem it was
 * given, every release names the size that was allocated, nothing is left
 * when the scene is freed, and a failure at any allocation ends the load
 * or the render cleanly with STATUS_NO_MEMORY ([EMBED-MEM-1], [EMBED-MEM-2]).
 */
#include <stdio.h>
#include <string.h>
#include "testlib.h"
#include "memcheck.h"
#include "base/arena.h"
#include "base/mem.h"
#include "io/scene_file.h"
#include "render/render.h"

static mem checked(memcheck *c)
{
    mem m = {memcheck_alloc, memcheck_resize, memcheck_release, c};
    return m;
}

/* The checker itself sees a wrong size and a leak. */
START_TEST(test_memcheck_sees_mistakes)
{
    memcheck c;
    memcheck_init(&c);
    mem m = checked(&c);
    char *p = mem_alloc(&m, 10);
    ck_assert_ptr_nonnull(p);
    ck_assert_uint_eq(c.live, 10);
    mem_free(&m, p, 9);
    ck_assert_int_eq(c.bad_sizes, 1);
    ck_assert_uint_eq(c.live, 0);
    p = mem_resize(&m, NULL, 0, 5);
    p = mem_resize(&m, p, 5, 50);
    ck_assert_uint_eq(c.live, 50);
    ck_assert_int_eq(c.blocks, 1);
    mem_free(&m, p, 50);
    c.fail_after = c.calls;
    ck_assert_ptr_null(mem_alloc(&m, 1));
    ck_assert_int_eq(c.failures, 1);
    ck_assert_int_eq(c.bad_sizes, 1);
}
END_TEST

/* A zeroed mem is the C library; sizes 0 become 1 on both sides. */
START_TEST(test_mem_default_and_zero_sizes)
{
    mem none;
    memset(&none, 0, sizeof none);
    char *p = mem_calloc(&none, 0, 8);
    ck_assert_ptr_nonnull(p);
    mem_free(&none, p, 0);
    ck_assert_ptr_null(mem_calloc(NULL, (size_t)-1 / 2, 4));
    char *s = mem_strndup(NULL, "abcdef", 3);
    ck_assert_str_eq(s, "abc");
    mem_free_string(NULL, s);
    memcheck c;
    memcheck_init(&c);
    mem m = checked(&c);
    p = mem_calloc(&m, 0, 8);
    mem_free(&m, p, 0);
    ck_assert_int_eq(c.bad_sizes, 0);
    ck_assert_int_eq(c.blocks, 0);
}
END_TEST

/* The sizes of the blocks an arena takes, each less the first: the
 * header a block carries cancels, whatever its size on the target. */
static void arena_steps(size_t first, size_t last, size_t piece, int count, size_t *step)
{
    memcheck c;
    memcheck_init(&c);
    mem m = checked(&c);
    arena a;
    arena_init_growing(&a, &m, first, last);
    size_t before = 0, one = 0;
    char *kept = NULL;
    for (int k = 0; k < count;) {
        char *p = arena_alloc(&a, piece);
        ck_assert_ptr_nonnull(p);
        if (!kept)
            kept = memset(p, 'k', piece);
        if ((long)k + 1 == c.blocks) {
            if (k == 0)
                one = c.live;
            step[k++] = c.live - before - one;
            before = c.live;
        }
    }
    ck_assert_int_eq(kept[0], 'k');
    ck_assert_int_eq(kept[piece - 1], 'k');
    ck_assert_uint_eq(a.bytes, c.live);
    arena_free(&a);
    ck_assert(c.live == 0 && c.blocks == 0 && c.bad_sizes == 0);
}

/* Blocks double from first to last and stay there; a request larger than
 * a block gets one of its own; what was handed out stays where it was. */
START_TEST(test_arena_growing_blocks)
{
    size_t step[5];
    arena_steps(512, 2048, 8, 5, step);
    ck_assert_uint_eq(step[0], 0);
    ck_assert_uint_eq(step[1], 1024 - 512);
    ck_assert_uint_eq(step[2], 2048 - 512);
    ck_assert_uint_eq(step[3], 2048 - 512);
    ck_assert_uint_eq(step[4], 2048 - 512);
    arena_steps(512, 2048, 4096, 2, step);
    ck_assert_uint_eq(step[1], 0);
    arena_steps(0, 0, 100, 3, step);
    ck_assert_uint_eq(step[2], 0);
}
END_TEST

/* Loads path (or text when not NULL) and renders a w x h image with mem m;
 * returns the status of the first step that failed. */
static int load_and_render(const char *path, const char *text, const mem *m, int w, int h)
{
    scene_load_opts o;
    scene_load_opts_init(&o);
    o.mem = *m;
    o.warnings = 0;
    int status;
    scene_model *s;
    if (text) {
        /* Files the text names come from beside path; a .json path makes it
         * a JSON scene. */
        scene_file_reader files;
        scene_file_reader_init(&files, -1, m);
        scene_source root = {path, NULL, text, strlen(text), 0};
        o.resolver = scene_file_resolver(&files);
        status = scene_file_reader_confine(&files, path, NULL);
        s = status == STATUS_OK ? scene_file_load_source(&root, &o, &status) : NULL;
        scene_file_reader_free(&files);
    } else {
        s = scene_file_load_with(path, &o, &status);
    }
    if (!s)
        return status;
    img_buf img;
    render_opts ro;
    memset(&ro, 0, sizeof ro);
    ro.width = w;
    ro.height = h;
    status = render_image(s, &ro, &img, NULL);
    if (status == STATUS_OK) {
        ck_assert_int_eq(img.width, w);
        img_free(&img);
    }
    scene_free(s);
    return status;
}

static const char *const scenes[] = {"scenes/demo.scene", "scenes/mesh.scene", "tests/scenes/include/main.scene",
                                     "scenes/cornell.scene", "tests/ply/encodings.scene"};

/* [EMBED-MEM-1] A load and a render allocate only through the mem given,
 * release every block with its size, and leave nothing behind. */
START_TEST(test_mem_whole_life)
{
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++) {
        memcheck c;
        memcheck_init(&c);
        mem m = checked(&c);
        ck_assert_int_eq(load_and_render(scenes[i], NULL, &m, 6, 4), STATUS_OK);
        ck_assert_msg(c.calls > 10, "%s: only %ld allocations seen", scenes[i], c.calls);
        ck_assert_int_eq(c.bad_sizes, 0);
        ck_assert_msg(c.live == 0 && c.blocks == 0, "%s: %zu bytes in %ld blocks left", scenes[i], c.live,
                      c.blocks);
    }
}
END_TEST

/* Runs the job with every allocation in turn made to fail: each run ends
 * with success or STATUS_NO_MEMORY (or want_other, the input's own
 * verdict), leaks nothing and names every size right; the last run, with
 * no failure, ends as want_other. */
static void sweep(const char *path, const char *text, int want_other)
{
    memcheck c;
    memcheck_init(&c);
    mem m = checked(&c);
    ck_assert_int_eq(load_and_render(path, text, &m, 3, 2), want_other);
    long needed = c.calls;
    for (long n = 0; n <= needed; n++) {
        memcheck_init(&c);
        c.fail_after = n;
        int status = load_and_render(path, text, &m, 3, 2);
        ck_assert_msg(status == STATUS_NO_MEMORY || status == want_other,
                      "%s: failing allocation %ld of %ld gave status %d", path, n, needed, status);
        ck_assert_msg(n < needed || status == want_other, "%s: ran out with no failure", path);
        ck_assert_msg(c.failures == 0 || status == STATUS_NO_MEMORY || want_other != STATUS_OK,
                      "%s: allocation %ld failed unnoticed", path, n);
        ck_assert_int_eq(c.bad_sizes, 0);
        ck_assert_msg(c.live == 0 && c.blocks == 0, "%s: failing allocation %ld left %zu bytes in %ld blocks",
                      path, n, c.live, c.blocks);
    }
}

/* [EMBED-MEM-2] Out of memory at any allocation of a load or a render:
 * STATUS_NO_MEMORY, nothing leaked (run under SANITIZE=1 too). */
START_TEST(test_mem_fail_everywhere)
{
    sweep(scenes[_i], NULL, STATUS_OK);
}
END_TEST

/* The parser's stacks past their first 200 entries (a long chain of
 * unary minus), a diagnostic longer than the formatting buffer, and a
 * scene with errors, under the same sweep. */
START_TEST(test_mem_fail_parser_and_diagnostics)
{
    char text[4096] = "let a = ";
    for (int i = 0; i < 600; i++)
        strcat(text, "-");
    strcat(text, "1\nsphere { radius a * a }\n");
    sweep("deep.scene", text, STATUS_OK);
    char bad[2048] = "sphere { radius ";
    for (int i = 0; i < 900; i++)
        strcat(bad, "q");
    strcat(bad, " }\nsphere { radius -1 }\n");
    sweep("bad.scene", bad, STATUS_DATA);
}
END_TEST

/* The build's median split (parts whose centroids coincide, where no
 * binned plane separates them) under the same sweep: two such clusters, so
 * a second split follows one whose sort buffers failed to allocate.  Its
 * keys failing after its spare buffer was made once left spare held, and
 * the next split wrote through the missing keys (an outside attack's
 * finding: SIGSEGV through the public API). */
START_TEST(test_mem_fail_median_split)
{
    static const char text[] = "for i in 0..39 {\n"
                               "  sphere { center [0, 0, 0] radius 1 + i / 100 }\n"
                               "  sphere { center [10, 0, 0] radius 1 + i / 100 }\n"
                               "}\n";
    sweep("median.scene", text, STATUS_OK);
}
END_TEST

#ifdef REFRAY_HAVE_JSON
/* [EMBED-MEM-2] for the JSON reader (spec/json.md): its own allocations
 * (element spans, inline mesh arrays, names, an OBJ file's mesh) fail in
 * turn too, in a good scene and in one with errors.  jansson's parse tree
 * is jansson's, not the hook's (spec/embedding.md), and is not swept. */
START_TEST(test_mem_fail_json)
{
    static const char head[] =
        "{\"format\": {\"name\": \"refray-scene\", \"version\": 1}, \"oracle\": \"none_such\",\n"
        " \"image\": {\"width\": 4, \"height\": 3, \"samples\": 1, \"max_depth\": 3, \"background\": [0, 0, 0]},\n"
        " \"camera\": {\"projection\": \"perspective\", \"eye\": [0, 0, 5], \"look_at\": [0, 0, 0],"
        " \"up\": [0, 1, 0], \"fov\": 60},\n"
        " \"ambient\": [0.1, 0.1, 0.1],\n"
        " \"materials\": [{\"name\": \"grey\", \"Kd\": [0.5, 0.5, 0.5], \"Ks\": [0.2, 0.2, 0.2], \"n\": 8,"
        " \"t\": 0, \"ior\": 1}],\n"
        " \"lights\": [{\"kind\": \"rectangle\", \"corner\": [-1, 3, 2], \"edge_u\": [2, 0, 0],"
        " \"edge_v\": [0, 0, 2], \"power\": [4, 4, 4], \"falloff\": \"linear\", \"d0\": 0, \"samples\": 4}],\n"
        " \"primitives\": [\n"
        "  {\"kind\": \"sphere\", \"material\": 0, \"transform\": null, \"center\": [0, 0, 0], \"radius\": %s},\n"
        "  {\"kind\": \"mesh\", \"material\": 0, \"source\": null, \"vertices\": [[0, 0, 1], [1, 0, 1], [0, 1, 1]],"
        " \"normals\": [[0, 0, 1]], \"triangles\": [[0, 1, 2]], \"triangle_normals\": [[0, 0, 0]]},\n"
        "  {\"kind\": \"mesh\", \"material\": 0, \"source\": null, \"file\": \"tetrahedron.obj\"}]}\n";
    char text[2048];
    snprintf(text, sizeof text, head, "0.5");
    sweep("tests/obj/mem.json", text, STATUS_OK);
    snprintf(text, sizeof text, head, "-1");
    sweep("tests/obj/mem.json", text, STATUS_DATA);
}
END_TEST
#endif

Suite *suite_mem(void)
{
    Suite *s = suite_create("mem");
    TCase *tc = tcase_create("hook");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, test_memcheck_sees_mistakes);
    tcase_add_test(tc, test_mem_default_and_zero_sizes);
    tcase_add_test(tc, test_arena_growing_blocks);
    tcase_add_test(tc, test_mem_whole_life);
    tcase_add_loop_test(tc, test_mem_fail_everywhere, 0, (int)(sizeof scenes / sizeof scenes[0]));
    tcase_add_test(tc, test_mem_fail_parser_and_diagnostics);
    tcase_add_test(tc, test_mem_fail_median_split);
#ifdef REFRAY_HAVE_JSON
    tcase_add_test(tc, test_mem_fail_json);
#endif
    suite_add_tcase(s, tc);
    return s;
}
