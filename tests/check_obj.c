/* Tests of src/lang/obj.c: the OBJ reader behind the `mesh` statement.  Every
 * input is an in-memory file "m.obj" included from a one-line scene
 * "s.scene", and diagnostics go to a memory stream so their exact text is
 * checked.  Expected indices, columns and messages are worked out by hand
 * from the input text. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "meshrun.h"
#include "lang/obj.h"

static void run_parse_len(run *r, const char *text, size_t len, long max_triangles, int logged)
{
    meshrun_parse(r, "m.obj", obj_parse, text, len, max_triangles, logged);
}

static void run_parse(run *r, const char *text, long max_triangles)
{
    run_parse_len(r, text, strlen(text), max_triangles, 1);
}

static void assert_triangle(const polymesh *m, int i, int a, int b, int c)
{
    ck_assert_int_lt(i, m->triangle_count);
    const int *t = m->tri[i];
    ck_assert_msg(t[0] == a && t[1] == b && t[2] == c,
                  "triangle %d is (%d,%d,%d), expected (%d,%d,%d)", i, t[0], t[1], t[2],
                  a, b, c);
}

static void assert_normals(const polymesh *m, int i, int a, int b, int c)
{
    static const int none[3] = {-1, -1, -1};
    const int *t = m->tri_normal ? m->tri_normal[i] : none;
    ck_assert_msg(t[0] == a && t[1] == b && t[2] == c,
                  "triangle %d normals (%d,%d,%d), expected (%d,%d,%d)", i, t[0], t[1],
                  t[2], a, b, c);
}

#define TRI3 "v 0 0 0\nv 1 0 0\nv 0 1 0\n"

static const char cube_text[] =
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
    "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";

START_TEST(test_obj_parse_cube)
{
    /* Each quad a b c d becomes (a,b,c), (a,c,d), 0-based. */
    static const int want[12][3] = {{0, 3, 2}, {0, 2, 1}, {4, 5, 6}, {4, 6, 7},
                                    {0, 1, 5}, {0, 5, 4}, {3, 7, 6}, {3, 6, 2},
                                    {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};
    run r;
    run_parse(&r, cube_text, 1000);
    ck_assert_int_eq(r.ok, 1);
    ck_assert_int_eq(r.d.errors + r.d.warnings, 0);
    ck_assert_int_eq(r.mesh.position_count, 8);
    ck_assert_int_eq(r.mesh.normal_count, 0);
    ck_assert_int_eq(r.mesh.triangle_count, 12);
    ck_assert_vec_near(r.mesh.positions[0], vec_make(-1, -1, -1), 0);
    ck_assert_vec_near(r.mesh.positions[6], vec_make(1, 1, 1), 0);
    for (int i = 0; i < 12; i++) {
        assert_triangle(&r.mesh, i, want[i][0], want[i][1], want[i][2]);
        assert_normals(&r.mesh, i, -1, -1, -1);
        /* The cube is centred at the origin: an outward face's normal points
         * the way its centroid does. */
        vec3 a = r.mesh.positions[want[i][0]], b = r.mesh.positions[want[i][1]];
        vec3 c = r.mesh.positions[want[i][2]];
        vec3 n = vec_cross(vec_sub(b, a), vec_sub(c, a));
        ck_assert(vec_dot(n, vec_add(a, vec_add(b, c))) > 0);
    }
    ck_assert_uint_eq(r.log_size, 0);
    run_free(&r);
}
END_TEST

START_TEST(test_obj_parse_negative_indices)
{
    run r;
    run_parse(&r, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf -4 -3 -2 -1\n"
                  "v 0 0 1\nv 1 0 1\nv 1 1 1\nf -3 -2 -1\nf 1 -1 -7\n", 100);
    ck_assert_int_eq(r.ok, 1);
    ck_assert_int_eq(r.mesh.triangle_count, 4);
    assert_triangle(&r.mesh, 0, 0, 1, 2);
    assert_triangle(&r.mesh, 1, 0, 2, 3);
    /* After 7 vertices, -3 is the 5th (index 4) and -1 the 7th (index 6). */
    assert_triangle(&r.mesh, 2, 4, 5, 6);
    assert_triangle(&r.mesh, 3, 0, 6, 0);
    run_free(&r);
}
END_TEST

START_TEST(test_obj_parse_face_forms)
{
    run r;
    run_parse(&r, TRI3 "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nvn 0 0 -1\n"
                       "f 1 2 3\nf 1/1 2/2 3/3\nf 1//2 2//1 3//2\nf 3/3/1 2/2/2 1/1/-1\n", 100);
    ck_assert_int_eq(r.ok, 1);
    ck_assert_int_eq(r.mesh.normal_count, 2);
    ck_assert_int_eq(r.mesh.triangle_count, 4);
    assert_triangle(&r.mesh, 0, 0, 1, 2);
    assert_normals(&r.mesh, 0, -1, -1, -1);
    assert_triangle(&r.mesh, 1, 0, 1, 2);
    assert_normals(&r.mesh, 1, -1, -1, -1);
    assert_triangle(&r.mesh, 2, 0, 1, 2);
    assert_normals(&r.mesh, 2, 1, 0, 1);
    assert_triangle(&r.mesh, 3, 2, 1, 0);
    assert_normals(&r.mesh, 3, 0, 1, 1);
    run_free(&r);
}
END_TEST

START_TEST(test_obj_parse_polygon_fan)
{
    static const char text[] = "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nf 1 2 3 4 5 # pentagon\n";
    run r;
    run_parse(&r, text, 100);
    ck_assert_int_eq(r.ok, 1);
    ck_assert_int_eq(r.mesh.triangle_count, 3);
    assert_triangle(&r.mesh, 0, 0, 1, 2);
    assert_triangle(&r.mesh, 1, 0, 2, 3);
    assert_triangle(&r.mesh, 2, 0, 3, 4);
    /* Each triangle points at the 'f' of "f 1 2 3 4 5". */
    size_t f_at = (size_t)(strstr(text, "f 1") - text);
    for (int i = 0; i < 3; i++)
        ck_assert_uint_eq(r.mesh.tri_at[i], f_at);
    run_free(&r);
}
END_TEST

START_TEST(test_obj_parse_keeps_values_as_read)
{
    run r;
    run_parse(&r, "v 1 2 3 4\nv -1.5e-3 +2 .5 0.5 0.25 0.125\nv 5. 0 1e-400\n"
                  "vn 0 0 2\nvn\t3\t4\t0\t\nf 1//1 2//2 3//1\n", 100);
    ck_assert_int_eq(r.ok, 1);
    ck_assert_int_eq(r.mesh.position_count, 3);
    ck_assert_vec_near(r.mesh.positions[0], vec_make(1, 2, 3), 0);
    ck_assert_vec_near(r.mesh.positions[1], vec_make(-0.0015, 2, 0.5), 0);
    ck_assert_vec_near(r.mesh.positions[2], vec_make(5, 0, 0), 0);
    ck_assert_int_eq(r.mesh.normal_count, 2);
    ck_assert_vec_near(r.mesh.normals[0], vec_make(0, 0, 2), 0);
    ck_assert_vec_near(r.mesh.normals[1], vec_make(3, 4, 0), 0);
    assert_normals(&r.mesh, 0, 0, 1, 0);
    run_free(&r);
}
END_TEST

/* The same two-triangle mesh written with every kind of line end. */
START_TEST(test_obj_parse_line_endings)
{
    static const char *const texts[] = {
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n",
        "v 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nv 0 1 0\r\nf 1 2 3 4\r\n",
        "v 0 0 0\rv 1 0 0\rv 1 1 0\rv 0 1 0\rf 1 2 3 4\r",
        "v 0 0 0\nv 1 0 0\r\nv 1 1 0\rv 0 1 0\n\r\n\rf 1 2 3 4",
        "\xEF\xBB\xBF  v 0 0 0 \n\tv 1 0 0\t\nv 1 1 0\nv 0 1 0\nf 1 2 3 4",
    };
    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        run r;
        run_parse(&r, texts[i], 100);
        ck_assert_msg(r.ok == 1, "text %zu: %s", i, r.log);
        ck_assert_int_eq(r.mesh.position_count, 4);
        ck_assert_vec_near(r.mesh.positions[2], vec_make(1, 1, 0), 0);
        assert_triangle(&r.mesh, 1, 0, 2, 3);
        run_free(&r);
    }
}
END_TEST

START_TEST(test_obj_parse_continuation)
{
    static const char text[] = "v 0 0 0\nv 1 \\\n 0 0\nv 0 1 0 \\  \t\r\n\nf 1 \\\r\n 2 \\\r3\n";
    run r;
    run_parse(&r, text, 100);
    ck_assert_msg(r.ok == 1, "%s", r.log);
    ck_assert_int_eq(r.mesh.position_count, 3);
    ck_assert_vec_near(r.mesh.positions[1], vec_make(1, 0, 0), 0);
    ck_assert_int_eq(r.mesh.triangle_count, 1);
    assert_triangle(&r.mesh, 0, 0, 1, 2);
    /* The face spans three physical lines; it is located at its 'f'. */
    ck_assert_uint_eq(r.mesh.tri_at[0], (size_t)(strstr(text, "f 1") - text));
    run_free(&r);
    /* Joining acts as a blank: "1\\" at a line end is the index 1. */
    run_parse(&r, TRI3 "f 1\\\n2 3\n", 100);
    ck_assert_int_eq(r.ok, 1);
    assert_triangle(&r.mesh, 0, 0, 1, 2);
    run_free(&r);
}
END_TEST

START_TEST(test_obj_parse_comments_and_blank_lines)
{
    run r;
    run_parse(&r, "# header \\\nv 0 0 0 # a comment\n\n   \n\t\nv 1 0 0#tight\nv 0 1 0\n"
                  "# f 9 9 9\nf 1 2 3# done\n#", 100);
    ck_assert_msg(r.ok == 1, "%s", r.log);
    ck_assert_int_eq(r.mesh.position_count, 3);
    ck_assert_int_eq(r.mesh.triangle_count, 1);
    ck_assert_int_eq(r.d.warnings, 0);
    run_free(&r);
}
END_TEST

START_TEST(test_obj_parse_ignores_common_statements)
{
    run r;
    run_parse(&r, "mtllib m.mtl\no thing\ng a b\ns 1\nusemtl red\n" TRI3 "vt 0 0\nf 1/1 2/1 3/1\n",
              100);
    ck_assert_int_eq(r.ok, 1);
    ck_assert_int_eq(r.d.warnings, 0);
    ck_assert_uint_eq(r.log_size, 0);
    run_free(&r);
}
END_TEST

START_TEST(test_obj_parse_warns_once_per_unknown_statement)
{
    char buf[200];
    run r;
    run_parse(&r, TRI3 "l 1 2\nl 2 3\np 1\nf 1 2 3\np 2\n", 100);
    ck_assert_int_eq(r.ok, 1);
    ck_assert_int_eq(r.d.warnings, 2);
    ck_assert_int_eq(r.d.errors, 0);
    ck_assert_str_eq(first_line(&r, buf, sizeof buf), "m.obj:4:1: warning: unknown OBJ statement 'l' ignored");
    ck_assert_ptr_nonnull(strstr(r.log, "m.obj:6:1: warning: unknown OBJ statement 'p' ignored\n"));
    ck_assert_ptr_null(strstr(r.log, "m.obj:5:"));
    ck_assert_ptr_null(strstr(r.log, "m.obj:8:"));
    run_free(&r);
}
END_TEST

START_TEST(test_obj_parse_caps_unknown_statement_warnings)
{
    run r;
    run_parse(&r, TRI3 "a\nb\nc\nd\ne\nh\ni\nj\nk\nm\nf 1 2 3\n", 100);
    ck_assert_int_eq(r.ok, 1);
    ck_assert_int_eq(r.d.warnings, 8);
    ck_assert_ptr_nonnull(strstr(r.log, "m.obj:11:1: warning: unknown OBJ statement 'j' ignored "
                                        "(further unknown statements are not reported)\n"));
    ck_assert_ptr_null(strstr(r.log, "'k'"));
    run_free(&r);
}
END_TEST

typedef struct error_case {
    const char *text;
    size_t len;          /* 0: strlen(text) */
    const char *first;   /* the first line of the diagnostics */
} error_case;

static const error_case error_cases[] = {
    {TRI3 "f 1 0 3\n", 0,
     "m.obj:4:5: error: index 0 is invalid: OBJ indices start at 1 (or count back from -1)"},
    {TRI3 "f 1 2 12\n", 0, "m.obj:4:7: error: index 12 refers to a vertex not yet defined (3 so far)"},
    {TRI3 "f -1 -2 -4\n", 0, "m.obj:4:9: error: index -4 reaches before the first vertex (3 so far)"},
    {TRI3 "f 1 2 99999999999999999999999\n", 0,
     "m.obj:4:7: error: index 99999999999999999999999 refers to a vertex not yet defined (3 so far)"},
    {TRI3 "f 1 2 -99999999999999999999999\n", 0,
     "m.obj:4:7: error: index -99999999999999999999999 reaches before the first vertex (3 so far)"},
    {TRI3 "vn 0 0 1\nf 1//1 2//2 3//1\n", 0,
     "m.obj:5:11: error: index 2 refers to a normal not yet defined (1 so far)"},
    {TRI3 "vn 0 0 1\nf 1//1 2//-2 3//1\n", 0,
     "m.obj:5:11: error: index -2 reaches before the first normal (1 so far)"},
    {TRI3 "f 1/1 2/1 3/1\n", 0,
     "m.obj:4:5: error: index 1 refers to a texture coordinate not yet defined (0 so far)"},
    {TRI3 "f 1 2\n", 0, "m.obj:4:1: error: face has 2 vertices, needs at least 3"},
    {TRI3 "f\n", 0, "m.obj:4:1: error: face has 0 vertices, needs at least 3"},
    {"v 1 2 x\n", 0, "m.obj:1:7: error: malformed number 'x'"},
    {"v 1 2.3.4 0\n", 0, "m.obj:1:5: error: malformed number '2.3.4'"},
    {"v 1e 0 0\n", 0, "m.obj:1:3: error: malformed number '1e'"},
    {"v inf 0 0\n", 0, "m.obj:1:3: error: malformed number 'inf'"},
    {"v 0x10 0 0\n", 0, "m.obj:1:3: error: malformed number '0x10'"},
    {"v 0 0 0 w\n", 0, "m.obj:1:9: error: malformed number 'w'"},
    {"v 1,5 0 0\n", 0, "m.obj:1:3: error: malformed number '1,5'"},
    {"v 1e400 0 0\n", 0, "m.obj:1:3: error: number '1e400' is not finite"},
    {"v 0 -1e999 0\n", 0, "m.obj:1:5: error: number '-1e999' is not finite"},
    {"v 1 2\n", 0, "m.obj:1:6: error: 'v' needs 3 coordinates, got 2"},
    {"v\n", 0, "m.obj:1:2: error: 'v' needs 3 coordinates, got 0"},
    {"vn 1 # 2 3\n", 0, "m.obj:1:5: error: 'vn' needs 3 coordinates, got 1"},
    {"vn 0 0 1 2\n", 0, "m.obj:1:10: error: unexpected '2' after the 3 coordinates of 'vn'"},
    {TRI3 "vn 0 0 1\nf 1//1 2 3\n", 0,
     "m.obj:5:8: error: face vertex '2' lacks a normal index but the face's first vertex has one"},
    {TRI3 "vn 0 0 1\nf 1 2//1 3//1\n", 0,
     "m.obj:5:5: error: face vertex '2//1' has a normal index but the face's first vertex has none"},
    {TRI3 "f 1/ 2 3\n", 0,
     "m.obj:4:3: error: malformed face vertex '1/' (expected i, i/t, i//n or i/t/n)"},
    {TRI3 "f 1 2 3//\n", 0,
     "m.obj:4:7: error: malformed face vertex '3//' (expected i, i/t, i//n or i/t/n)"},
    {TRI3 "f //1 2 3\n", 0,
     "m.obj:4:3: error: malformed face vertex '//1' (expected i, i/t, i//n or i/t/n)"},
    {TRI3 "f 1 2/1/1/1 3\n", 0,
     "m.obj:4:5: error: malformed face vertex '2/1/1/1' (expected i, i/t, i//n or i/t/n)"},
    {TRI3 "f 1 2a 3\n", 0, "m.obj:4:5: error: malformed index '2a'"},
    {TRI3 "f 1 2 3/x\n", 0, "m.obj:4:9: error: malformed index 'x'"},
    {TRI3 "f 1 - 3\n", 0, "m.obj:4:5: error: malformed index '-'"},
    {TRI3 "f 1 +2 3\n", 0, "m.obj:4:5: error: malformed index '+2'"},
    {"v 0 0 0\nv 1\0 0 0\nf 1 1 1\n", 25, "m.obj:2:4: error: NUL byte in OBJ file"},
    {"", 0, "m.obj:1:1: error: mesh has no faces"},
    {"# nothing\n" TRI3, 0, "m.obj:1:1: error: mesh has no faces"},
    {"v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 4\r\n", 0,
     "m.obj:4:7: error: index 4 refers to a vertex not yet defined (3 so far)"},
    {"v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 4\r", 0,
     "m.obj:4:7: error: index 4 refers to a vertex not yet defined (3 so far)"},
    {TRI3 "f 1 2 \\\n 9\n", 0, "m.obj:5:2: error: index 9 refers to a vertex not yet defined (3 so far)"},
    {TRI3 "f 1 2\\x 3\n", 0, "m.obj:4:5: error: malformed index '2\\x'"},
    {TRI3 "f 1 2 3 \\ x\n", 0, "m.obj:4:9: error: malformed index '\\'"},
};

START_TEST(test_obj_parse_errors)
{
    const error_case *c = &error_cases[_i];
    char buf[300];
    run r;
    run_parse_len(&r, c->text, c->len ? c->len : strlen(c->text), 100, 1);
    ck_assert_int_eq(r.ok, 0);
    ck_assert_str_eq(first_line(&r, buf, sizeof buf), c->first);
    ck_assert_int_eq(r.d.errors, 1);
    ck_assert_ptr_null(r.mesh.positions);
    ck_assert_ptr_null(r.mesh.tri);
    ck_assert_int_eq(r.mesh.position_count + r.mesh.normal_count + r.mesh.triangle_count, 0);
    run_free(&r);
}
END_TEST

START_TEST(test_obj_parse_error_excerpt_and_include_note)
{
    run r;
    run_parse(&r, TRI3 "f 1 2 12\n", 100);
    ck_assert_str_eq(r.log, "m.obj:4:7: error: index 12 refers to a vertex not yet defined (3 so far)\n"
                            "    4 | f 1 2 12\n"
                            "      |       ^~\n"
                            "s.scene:1:1: note: included from here\n");
    run_free(&r);
}
END_TEST

START_TEST(test_obj_parse_reports_each_bad_statement)
{
    char buf[200];
    run r;
    run_parse(&r, TRI3 "f 1 2 0\nv 1 x 2\nf 1 2 3\nvn 1\n", 100);
    ck_assert_int_eq(r.ok, 0);
    ck_assert_int_eq(r.d.errors, 3);
    ck_assert_str_eq(first_line(&r, buf, sizeof buf),
                     "m.obj:4:7: error: index 0 is invalid: OBJ indices start at 1 (or count back from -1)");
    ck_assert_ptr_nonnull(strstr(r.log, "\nm.obj:5:5: error: malformed number 'x'\n"));
    ck_assert_ptr_nonnull(strstr(r.log, "\nm.obj:7:5: error: 'vn' needs 3 coordinates, got 1\n"));
    ck_assert_int_eq(r.mesh.triangle_count, 0);
    run_free(&r);
}
END_TEST

START_TEST(test_obj_parse_stops_at_error_limit)
{
    run r;
    static const char text[] = "f 0\nf 0\nf 0\nf 0\nf 0\n";
    memset(&r, 0, sizeof r);
    source_set_init(&r.set, NULL);
    int file = source_set_add(&r.set, "m.obj", text, sizeof text - 1, src_span_none());
    diag_init(&r.d, &r.set, NULL, NULL);
    r.d.max_errors = 2;
    ck_assert_int_eq(obj_parse(&r.set, file, &r.d, 100, &r.mesh), 0);
    ck_assert_int_eq(r.d.errors, 2);
    run_free(&r);
}
END_TEST

START_TEST(test_obj_parse_triangle_limit)
{
    static const char text[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nf 4 3 2 1\n";
    char buf[200];
    run r;
    run_parse(&r, text, 4);
    ck_assert_int_eq(r.ok, 1);
    ck_assert_int_eq(r.mesh.triangle_count, 4);
    run_free(&r);
    run_parse(&r, text, 3);
    ck_assert_int_eq(r.ok, 0);
    ck_assert_int_eq(r.d.errors, 1);
    ck_assert_str_eq(first_line(&r, buf, sizeof buf), "m.obj:6:1: error: mesh exceeds the limit of 3 triangles (--max-mesh-triangles)");
    run_free(&r);
    run_parse(&r, text, 0);
    ck_assert_str_eq(first_line(&r, buf, sizeof buf), "m.obj:5:1: error: mesh exceeds the limit of 0 triangles (--max-mesh-triangles)");
    run_free(&r);
    run_parse(&r, text, -5);
    ck_assert_int_eq(r.ok, 0);
    run_free(&r);
}
END_TEST

static char *repeat(const char *head, const char *unit, size_t times, const char *tail)
{
    size_t h = strlen(head), u = strlen(unit), t = strlen(tail);
    char *s = malloc(h + u * times + t + 1);
    ck_assert_ptr_nonnull(s);
    memcpy(s, head, h);
    for (size_t i = 0; i < times; i++)
        memcpy(s + h + i * u, unit, u);
    memcpy(s + h + u * times, tail, t + 1);
    return s;
}

START_TEST(test_obj_parse_hostile_sizes)
{
    char buf[300];
    run r;
    /* A 1 MB face: refused at the limit, with no room made for its triangles. */
    char *text = repeat(TRI3 "f", " -1", 400000, "\n");
    run_parse(&r, text, 1000);
    ck_assert_str_eq(first_line(&r, buf, sizeof buf), "m.obj:4:1: error: mesh exceeds the limit of 1000 triangles (--max-mesh-triangles)");
    run_free(&r);
    free(text);
    /* A 1 MB number, quoted in the message only in part. */
    text = repeat("v ", "1", 1000000, " 0 0\n");
    run_parse(&r, text, 1000);
    ck_assert_str_eq(first_line(&r, buf, sizeof buf),
                     "m.obj:1:3: error: number '1111111111111111111111111111111111111111...' "
                     "is too long (more than 255 characters)");
    run_free(&r);
    free(text);
    /* [REL-INPUT-3] A 'v' of a million values is refused at the eighth
     * (x y z and w or r g b make at most 7; before: accepted whole). */
    text = repeat("v", " 0", 1000000, "\n");
    run_parse(&r, text, 1000);
    ck_assert_int_eq(r.ok, 0);
    ck_assert_str_eq(first_line(&r, buf, sizeof buf),
                     "m.obj:1:17: error: 'v' takes at most 7 numbers (x y z, then w or r g b)");
    run_free(&r);
    free(text);
    /* A 1 MB keyword of control bytes and 100000 continuations in a row. */
    text = repeat("", "\x01", 1000000, "\n");
    run_parse(&r, text, 1000);
    ck_assert_str_eq(first_line(&r, buf, sizeof buf),
                     "m.obj:1:1: warning: unknown OBJ statement '????????????????????????????????????????...' ignored");
    run_free(&r);
    free(text);
    text = repeat(TRI3 "f 1 2 3", " \\\n", 100000, "\n");
    run_parse(&r, text, 1000);
    ck_assert_int_eq(r.ok, 1);
    ck_assert_int_eq(r.mesh.triangle_count, 1);
    run_free(&r);
    free(text);
}
END_TEST

static size_t random_obj(uint64_t seed, char *buf, size_t cap)
{
    static const char *const pieces[] = {"v", "vn", "vt", "f", "l", " ", " ", "\t", "1", "2", "-1",
                                         "0", "3", "/", "//", "\n", "\n", "\r\n", "\r", "\\",
                                         "#", ".5", "e9", "1e400", "x", "\0", "-"};
    size_t n = 0, count = test_mix(seed) % 60;
    for (size_t i = 0; i < count; i++) {
        const char *p = pieces[test_mix(seed * 131 + i + 1) % (sizeof pieces / sizeof pieces[0])];
        size_t len = *p ? strlen(p) : 1;
        if (n + len > cap)
            break;
        memcpy(buf + n, p, len);
        n += len;
    }
    return n;
}

START_TEST(test_obj_parse_random_input_invariants)
{
    char buf[600];
    for (uint64_t seed = 0; seed < 4000; seed++) {
        run r;
        size_t n = random_obj(seed, buf, sizeof buf);
        run_parse_len(&r, buf, n, 8, 0);
        ck_assert_int_eq(r.ok, r.d.errors == 0);
        if (!r.ok) {
            ck_assert_ptr_null(r.mesh.tri);
            ck_assert_int_eq(r.mesh.triangle_count, 0);
        }
        ck_assert_int_le(r.mesh.triangle_count, 8);
        for (int t = 0; t < r.mesh.triangle_count; t++)
            for (int k = 0; k < 3; k++) {
                const int *v = r.mesh.tri[t];
                ck_assert(v[k] >= 0 && v[k] < r.mesh.position_count);
                if (r.mesh.tri_normal)
                    ck_assert(r.mesh.tri_normal[t][k] >= -1 && r.mesh.tri_normal[t][k] < r.mesh.normal_count);
                ck_assert(r.mesh.tri_at[t] < n);
            }
        run_free(&r);
    }
}
END_TEST

START_TEST(test_obj_free_is_idempotent)
{
    polymesh m;
    memset(&m, 0, sizeof m);
    polymesh_free(&m);
    ck_assert_ptr_null(m.positions);
    run r;
    run_parse(&r, TRI3 "f 1 2 3\n", 10);
    polymesh_free(&r.mesh);
    ck_assert_ptr_null(r.mesh.tri);
    ck_assert_int_eq(r.mesh.triangle_count, 0);
    run_free(&r);
}
END_TEST

/* Reads a fixture file; the tests run from the top of the repository. */
static char *read_fixture(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    ck_assert_msg(f != NULL, "cannot open %s", path);
    size_t cap = 1 << 16;
    char *text = malloc(cap + 1);
    ck_assert_ptr_nonnull(text);
    *len = fread(text, 1, cap, f);
    fclose(f);
    ck_assert_uint_lt(*len, cap);
    text[*len] = '\0';
    return text;
}

/* Closed and consistently wound: every directed edge a->b occurs once and
 * its reverse b->a occurs once. */
static int is_closed(const polymesh *m)
{
    for (int i = 0; i < m->triangle_count; i++)
        for (int k = 0; k < 3; k++) {
            int a = m->tri[i][k], b = m->tri[i][(k + 1) % 3];
            int same = 0, reverse = 0;
            for (int j = 0; j < m->triangle_count; j++)
                for (int l = 0; l < 3; l++) {
                    int c = m->tri[j][l], d = m->tri[j][(l + 1) % 3];
                    same += c == a && d == b;
                    reverse += c == b && d == a;
                }
            if (same != 1 || reverse != 1)
                return 0;
        }
    return 1;
}

/* Divergence theorem: the volume is the sum of the signed tetrahedra
 * (origin, a, b, c), a.(b x c) / 6; positive when the faces wind outward. */
static double volume(const polymesh *m)
{
    double v = 0;
    for (int i = 0; i < m->triangle_count; i++) {
        const int *t = m->tri[i];
        v += vec_dot(m->positions[t[0]], vec_cross(m->positions[t[1]], m->positions[t[2]])) / 6;
    }
    return v;
}

static void parse_fixture(run *r, const char *path)
{
    size_t len;
    char *text = read_fixture(path, &len);
    run_parse_len(r, text, len, 1000, 1);
    free(text);
    ck_assert_msg(r->ok == 1, "%s: %s", path, r->log);
    ck_assert_uint_eq(r->log_size, 0);
}

START_TEST(test_obj_parse_fixture_cube)
{
    run r;
    parse_fixture(&r, "tests/obj/cube.obj");
    ck_assert_int_eq(r.mesh.position_count, 8);
    ck_assert_int_eq(r.mesh.normal_count, 6);
    ck_assert_int_eq(r.mesh.triangle_count, 12);
    ck_assert(is_closed(&r.mesh));
    ck_assert_near(volume(&r.mesh), 8.0, 1e-12);
    /* Each corner's normal is its face's unit geometric normal. */
    for (int i = 0; i < 12; i++) {
        const int *t = r.mesh.tri[i], *tn = r.mesh.tri_normal[i];
        vec3 a = r.mesh.positions[t[0]], b = r.mesh.positions[t[1]];
        vec3 n = vec_normalize(vec_cross(vec_sub(b, a), vec_sub(r.mesh.positions[t[2]], a)));
        for (int k = 0; k < 3; k++) {
            ck_assert_int_ge(tn[k], 0);
            ck_assert_vec_near(r.mesh.normals[tn[k]], n, 1e-15);
        }
    }
    run_free(&r);
}
END_TEST

START_TEST(test_obj_parse_fixture_tetrahedron)
{
    run r;
    parse_fixture(&r, "tests/obj/tetrahedron.obj");
    ck_assert_int_eq(r.mesh.position_count, 4);
    ck_assert_int_eq(r.mesh.triangle_count, 4);
    ck_assert(is_closed(&r.mesh));
    ck_assert_near(volume(&r.mesh), 1.0 / 6.0, 1e-15);
    run_free(&r);
}
END_TEST

START_TEST(test_obj_parse_fixture_quad)
{
    run r;
    parse_fixture(&r, "tests/obj/quad.obj");
    ck_assert_int_eq(r.mesh.position_count, 4);
    ck_assert_int_eq(r.mesh.triangle_count, 2);
    assert_triangle(&r.mesh, 0, 0, 1, 2);
    assert_triangle(&r.mesh, 1, 0, 2, 3);
    assert_normals(&r.mesh, 1, -1, -1, -1);
    for (int i = 0; i < 2; i++) {
        const int *t = r.mesh.tri[i];
        vec3 a = r.mesh.positions[t[0]];
        vec3 n = vec_cross(vec_sub(r.mesh.positions[t[1]], a), vec_sub(r.mesh.positions[t[2]], a));
        ck_assert_vec_near(n, vec_make(0, 0, 4), 0);
    }
    run_free(&r);
}
END_TEST

Suite *suite_obj(void)
{
    Suite *s = suite_create("obj");
    TCase *tc = tcase_create("parse");
    tcase_add_test(tc, test_obj_parse_cube);
    tcase_add_test(tc, test_obj_parse_negative_indices);
    tcase_add_test(tc, test_obj_parse_face_forms);
    tcase_add_test(tc, test_obj_parse_polygon_fan);
    tcase_add_test(tc, test_obj_parse_keeps_values_as_read);
    tcase_add_test(tc, test_obj_parse_line_endings);
    tcase_add_test(tc, test_obj_parse_continuation);
    tcase_add_test(tc, test_obj_parse_comments_and_blank_lines);
    tcase_add_test(tc, test_obj_parse_ignores_common_statements);
    tcase_add_test(tc, test_obj_parse_warns_once_per_unknown_statement);
    tcase_add_test(tc, test_obj_parse_caps_unknown_statement_warnings);
    tcase_add_loop_test(tc, test_obj_parse_errors, 0,
                        (int)(sizeof error_cases / sizeof error_cases[0]));
    tcase_add_test(tc, test_obj_parse_error_excerpt_and_include_note);
    tcase_add_test(tc, test_obj_parse_reports_each_bad_statement);
    tcase_add_test(tc, test_obj_parse_stops_at_error_limit);
    tcase_add_test(tc, test_obj_parse_triangle_limit);
    tcase_add_test(tc, test_obj_parse_hostile_sizes);
    tcase_add_test(tc, test_obj_parse_random_input_invariants);
    tcase_add_test(tc, test_obj_free_is_idempotent);
    suite_add_tcase(s, tc);
    TCase *fx = tcase_create("fixtures");
    tcase_add_test(fx, test_obj_parse_fixture_cube);
    tcase_add_test(fx, test_obj_parse_fixture_tetrahedron);
    tcase_add_test(fx, test_obj_parse_fixture_quad);
    suite_add_tcase(s, fx);
    return s;
}
