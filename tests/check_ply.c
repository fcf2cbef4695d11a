/* Tests of src/lang/ply.c, the PLY reader behind `mesh { file "x.ply" }`
 * (spec/language.md, section 8).  Inputs are in-memory files "m.ply"
 * included from a one-line scene, diagnostics go to a memory stream so
 * their exact text is checked, and the fixtures of tests/ply/ (written by
 * tests/gen/gen_ply_corpus.c) are one mesh in OBJ and in the three PLY
 * encodings.  Expected values are worked out by hand from the inputs. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/scene_file.h"
#include "meshrun.h"
#include "lang/obj.h"
#include "lang/ply.h"
#include "render/render.h"
#include "scene/scene.h"

static void run_parse_len(run *r, const char *text, size_t len, long max_triangles)
{
    meshrun_parse(r, "m.ply", ply_parse, text, len, max_triangles, 1);
}

static void run_parse(run *r, const char *text)
{
    run_parse_len(r, text, strlen(text), 1000);
}

#define HEAD "ply\nformat ascii 1.0\n"
#define TRI_HEADER                                                                            \
    "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"                  \
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n"

START_TEST(test_ply_ascii_triangle)
{
    run r;
    run_parse(&r, HEAD TRI_HEADER "0 0 0\n1 0 0\n0 1.5 -2\n3 0 1 2\n");
    ck_assert_msg(r.ok == 1, "%s", r.log);
    ck_assert_int_eq(r.mesh.position_count, 3);
    ck_assert_vec_near(r.mesh.positions[2], vec_make(0, 1.5, -2), 0);
    ck_assert_int_eq(r.mesh.triangle_count, 1);
    ck_assert(r.mesh.tri[0][0] == 0 && r.mesh.tri[0][1] == 1 && r.mesh.tri[0][2] == 2);
    ck_assert_ptr_null(r.mesh.tri_normal);
    ck_assert_uint_eq(r.log_size, 0);
    run_free(&r);
}
END_TEST

START_TEST(test_ply_header_forms)
{
    /* Comments and obj_info anywhere, blank lines, CRLF, extra blanks, the
     * index list named vertex_index, an element of its own skipped, and
     * properties before and after the ones the mesh uses. */
    run r;
    run_parse(&r, "ply\r\nformat   ascii 1.0\r\ncomment made by hand\r\n\r\nobj_info x\r\n"
                  "element extra 1\r\nproperty list uchar short s\r\nproperty double d\r\n"
                  "element vertex 4\r\nproperty int flags\r\nproperty double x\r\nproperty double y\r\n"
                  "comment in between\r\nproperty double z\r\nproperty uchar red\r\n"
                  "element face 1\r\nproperty uchar kind\r\nproperty list uint uint vertex_index\r\n"
                  "property list uchar float uv\r\nend_header\r\n"
                  "2 -3 4 0.5\r\n"
                  "9 0 0 0 255\r\n9 2 0 0 0\r\n9 2 2 0 1\r\n9 0 2 0 2\r\n"
                  "7 4 0 1 2 3 2 0.5 0.5\r\n");
    ck_assert_msg(r.ok == 1, "%s", r.log);
    ck_assert_int_eq(r.mesh.position_count, 4);
    ck_assert_vec_near(r.mesh.positions[2], vec_make(2, 2, 0), 0);
    ck_assert_int_eq(r.mesh.face_count, 1);
    ck_assert_int_eq(r.mesh.triangle_count, 2);
    run_free(&r);
}
END_TEST

START_TEST(test_ply_normals_and_polygons)
{
    /* nx ny nz give each vertex its normal (normal index = vertex index);
     * an L-shaped hexagon is ear-clipped into 4 triangles of total area 3;
     * a face of 2 corners has no area and is counted. */
    run r;
    run_parse(&r, HEAD "element vertex 6\nproperty float x\nproperty float y\nproperty float z\n"
                       "property float nx\nproperty float ny\nproperty float nz\n"
                       "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
                       "2 1 0 0 0 1\n1 1 0 0 0 1\n1 2 0 0 0 1\n0 2 0 0 0 1\n0 0 0 0 0 1\n2 0 0 0 0 1\n"
                       "6 0 1 2 3 4 5\n2 0 1\n");
    ck_assert_msg(r.ok == 1, "%s", r.log);
    ck_assert_int_eq(r.mesh.normal_count, 6);
    ck_assert_int_eq(r.mesh.triangle_count, 4);
    ck_assert_int_eq(r.mesh.face_count, 2);
    ck_assert_int_eq(r.mesh.no_area.count, 1);
    double area = 0;
    for (int k = 0; k < 4; k++) {
        const int *t = r.mesh.tri[k];
        vec3 a = r.mesh.positions[t[0]];
        vec3 n = vec_cross(vec_sub(r.mesh.positions[t[1]], a), vec_sub(r.mesh.positions[t[2]], a));
        ck_assert(n.z > 0); /* the hexagon's winding kept */
        area += n.z / 2;
        for (int i = 0; i < 3; i++)
            ck_assert_int_eq(r.mesh.tri_normal[k][i], t[i]);
    }
    ck_assert_near(area, 3.0, 0);
    run_free(&r);
}
END_TEST

START_TEST(test_ply_repeated_corners)
{
    /* [MESH-POLY-2] The L of tests/attack14 finding 1 as a PLY face with
     * its corners 2 and 4 given twice in a row, "8 0 1 2 2 3 4 4 5": the
     * hexagon's 4 triangles, each wound as the face and with its centroid
     * in the L, of total area 4 x 1 + 2 x 0.75 = 5.5; nothing fanned or
     * dropped (before: 3 triangles, fanned). */
    run r;
    run_parse(&r, HEAD "element vertex 6\nproperty float x\nproperty float y\nproperty float z\n"
                       "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                       "0 0 0\n4 0 0\n4 1 0\n2 1 0\n2 1.75 0\n0 1.75 0\n8 0 1 2 2 3 4 4 5\n");
    ck_assert_msg(r.ok == 1, "%s", r.log);
    ck_assert_int_eq(r.mesh.triangle_count, 4);
    ck_assert_int_eq(r.mesh.fanned.count, 0);
    ck_assert_int_eq(r.mesh.no_area.count, 0);
    double area = 0;
    for (int k = 0; k < 4; k++) {
        const int *t = r.mesh.tri[k];
        vec3 a = r.mesh.positions[t[0]], b = r.mesh.positions[t[1]], c = r.mesh.positions[t[2]];
        vec3 n = vec_cross(vec_sub(b, a), vec_sub(c, a)), g = vec_scale(vec_add(a, vec_add(b, c)), 1.0 / 3);
        ck_assert(n.z > 0);
        ck_assert_msg(g.x < 2 || g.y < 1, "triangle %d lies in the notch of the L", k);
        area += n.z / 2;
    }
    ck_assert_near(area, 5.5, 0);
    run_free(&r);
}
END_TEST

/* Header and ASCII data errors: input (after HEAD unless it starts with
 * "ply"), the first diagnostic. */
static const struct {
    const char *text, *message;
} ascii_errors[] = {
    {"plx\n", "m.ply:1:1: error: not a PLY file: the first line must be 'ply'"},
    {"ply\nelement vertex 3\n", "m.ply:2:1: error: expected the 'format' line after 'ply'"},
    {"ply\nformat ascii 2.0\n", "m.ply:2:14: error: unsupported PLY version '2.0' (only 1.0 is known)"},
    {"ply\nformat ascii 1.0\nformat ascii 1.0\n", "m.ply:3:1: error: a second 'format' line"},
    {"property float x\n", "m.ply:3:1: error: 'property' before any 'element'"},
    {"element vertex -1\n", "m.ply:3:16: error: element count '-1' is not a whole number from 0 to 2147483647"},
    {"element vertex 3000000000\n",
     "m.ply:3:16: error: element count '3000000000' is not a whole number from 0 to 2147483647"},
    {"element vertex 1\nproperty float64x x\n",
     "m.ply:4:10: error: unknown PLY type 'float64x' (expected char, uchar, short, ushort, int, uint, float or double)"},
    {"element vertex 1\nproperty float x y\n",
     "m.ply:4:1: error: expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'"},
    {"element vertex 1\nproperty float x\nproperty double x\n", "m.ply:5:17: error: a second property 'x'"},
    {"element vertex 1\nelement vertex 1\n", "m.ply:4:9: error: a second element 'vertex'"},
    {"element vertex 1\nproperty list float int x\n", "m.ply:4:15: error: a list's count must have an integer type"},
    {"element vertex 0\nmaterial 3\n", "m.ply:4:1: error: unknown PLY header keyword 'material'"},
    {"element vertex 0\nproperty float x\nproperty float y\nproperty float z\nelement face 0\n"
     "property list uchar int vertex_indices\nend_header\n",
     "m.ply:7:1: error: mesh has no faces"},
    {"element vertex 1\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\n"
     "element face 0\nproperty list uchar int vertex_indices\nend_header\n",
     "m.ply:3:1: error: element 'vertex' has some of nx, ny, nz but not all three"},
    {"element vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n",
     "m.ply:1:1: error: mesh has no faces (the PLY header has no element 'face')"},
    {"element vertex 1\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
     "property list uchar int indices\nend_header\n",
     "m.ply:7:1: error: element 'face' has no list property 'vertex_indices' (or 'vertex_index')"},
    {TRI_HEADER "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
     "m.ply:13:7: error: element 'face' 0: vertex index 3 is out of range (3 vertices)"},
    {TRI_HEADER "0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n",
     "m.ply:13:7: error: element 'face' 0: vertex index -1 is out of range (3 vertices)"},
    {TRI_HEADER "0 0 0\n1 0 0\n0 1 0\n256 0 1 2\n",
     "m.ply:13:1: error: element 'face' 0: property 'vertex_indices' (its count): '256' is not a whole number in "
     "the range of uchar"},
    {TRI_HEADER "0 0 0\n1 0 0\n0 1 0\n3 0 1.0 2\n",
     "m.ply:13:5: error: element 'face' 0: property 'vertex_indices': '1.0' is not a whole number in the range of int"},
    {TRI_HEADER "0 0 0\n1 0 0\n0 1 inf\n3 0 1 2\n",
     "m.ply:12:5: error: element 'vertex' 2: property 'z': 'inf' is not a finite number"},
    {TRI_HEADER "0 0 0\n1 0 0\n0 1 1e999\n3 0 1 2\n",
     "m.ply:12:5: error: element 'vertex' 2: property 'z': '1e999' is not a finite number"},
    {TRI_HEADER "0 0 0\n1 0 0\n0 1 0\n3 0 1\n", "m.ply:14:1: error: element 'face' 0: the file ends before property "
                                               "'vertex_indices'"},
};

START_TEST(test_ply_errors)
{
    char text[1024], line[512];
    const char *t = ascii_errors[_i].text;
    snprintf(text, sizeof text, "%s%s", strncmp(t, "ply", 3) == 0 || strncmp(t, "plx", 3) == 0 ? "" : HEAD, t);
    run r;
    run_parse(&r, text);
    ck_assert_int_eq(r.ok, 0);
    ck_assert_str_eq(first_line(&r, line, sizeof line), ascii_errors[_i].message);
    ck_assert_ptr_null(r.mesh.tri);
    ck_assert_int_eq(r.mesh.triangle_count + r.mesh.position_count, 0);
    run_free(&r);
}
END_TEST

START_TEST(test_ply_trailing_data_warns)
{
    char line[512];
    run r;
    run_parse(&r, HEAD TRI_HEADER "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n4 5\n");
    ck_assert_int_eq(r.ok, 1);
    ck_assert_str_eq(first_line(&r, line, sizeof line), "m.ply:14:1: warning: data after the last element ignored ('4')");
    run_free(&r);
}
END_TEST

/* A binary triangle in either byte order, x y z as float, the face list as
 * uchar count and int indices; `cut` bytes removed from the end. */
static size_t binary_triangle(char *buf, int big, int cut)
{
    static const char header[] = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                                 "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    size_t n = (size_t)sprintf(buf, "ply\nformat %s 1.0\n%s", big ? "binary_big_endian" : "binary_little_endian",
                               header);
    static const float v[9] = {0, 0, 0, 1, 0, 0, 0.25f, 1, -3};
    static const int32_t idx[3] = {0, 1, 2};
    unsigned char bytes[4];
    for (int i = 0; i < 9; i++) {
        uint32_t u;
        memcpy(&u, &v[i], 4);
        for (int k = 0; k < 4; k++)
            bytes[k] = (unsigned char)(u >> (big ? 24 - 8 * k : 8 * k));
        memcpy(buf + n, bytes, 4);
        n += 4;
    }
    buf[n++] = 3;
    for (int i = 0; i < 3; i++) {
        uint32_t u = (uint32_t)idx[i];
        for (int k = 0; k < 4; k++)
            buf[n++] = (char)(u >> (big ? 24 - 8 * k : 8 * k));
    }
    return n - (size_t)cut;
}

START_TEST(test_ply_binary_both_orders)
{
    char buf[512];
    for (int big = 0; big < 2; big++) {
        run r;
        run_parse_len(&r, buf, binary_triangle(buf, big, 0), 10);
        ck_assert_msg(r.ok == 1, "%s", r.log);
        ck_assert_vec_near(r.mesh.positions[2], vec_make(0.25, 1, -3), 0);
        ck_assert(r.mesh.tri[0][0] == 0 && r.mesh.tri[0][1] == 1 && r.mesh.tri[0][2] == 2);
        run_free(&r);
    }
}
END_TEST

/* binary_triangle (little-endian) with the face element ahead of the
 * vertex element ([MESH-PLY-2]): the header's two element blocks swapped,
 * the face's 13 bytes moved ahead of the vertices' 36. */
static size_t binary_faces_first(char *out)
{
    char buf[512];
    static const char vertex_block[] = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
    static const char face_block[] = "element face 1\nproperty list uchar int vertex_indices\n";
    size_t n = binary_triangle(buf, 0, 0), body = n - 49;
    char *v = strstr(buf, vertex_block);
    ck_assert_ptr_nonnull(v);
    size_t at = (size_t)(v - buf), vn = strlen(vertex_block), fn = strlen(face_block);
    memcpy(out, buf, at);
    memcpy(out + at, face_block, fn);
    memcpy(out + at + fn, vertex_block, vn);
    memcpy(out + at + fn + vn, buf + at + vn + fn, body - (at + vn + fn));
    memcpy(out + body, buf + body + 36, 13);
    memcpy(out + body + 13, buf + body, 36);
    return n;
}

/* [MESH-PLY-2] PLY puts no order on elements: faces before the vertices
 * (with an element of its own between) give the mesh the same file with
 * the vertices first gives, in ASCII (a square cut into 0 1 2 and 0 2 3)
 * and in binary (the triangle above with its face element moved ahead);
 * an index is checked against every vertex, and data after the last
 * element still warn (tests/attack12 finding 10: "element 'face' must come
 * after element 'vertex'"). */
START_TEST(test_ply_faces_first)
{
    char line[512], buf[512];
    static const char *const faces_first =
        HEAD "element face 2\nproperty list uchar int vertex_indices\nelement extra 1\nproperty float e\n"
             "element vertex 4\nproperty float x\nproperty float y\nproperty float z\nend_header\n"
             "3 0 1 2\n3 0 2 3\n7\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
    run r;
    run_parse(&r, faces_first);
    ck_assert_msg(r.ok == 1, "%s", r.log);
    ck_assert_uint_eq(r.log_size, 0);
    ck_assert_int_eq(r.mesh.position_count, 4);
    ck_assert_vec_near(r.mesh.positions[2], vec_make(1, 1, 0), 0);
    ck_assert_vec_near(r.mesh.positions[3], vec_make(0, 1, 0), 0);
    ck_assert_int_eq(r.mesh.triangle_count, 2);
    ck_assert(r.mesh.tri[0][0] == 0 && r.mesh.tri[0][1] == 1 && r.mesh.tri[0][2] == 2);
    ck_assert(r.mesh.tri[1][0] == 0 && r.mesh.tri[1][1] == 2 && r.mesh.tri[1][2] == 3);
    run_free(&r);

    snprintf(buf, sizeof buf, "%s9\n", faces_first);
    run_parse(&r, buf);
    ck_assert_int_eq(r.ok, 1);
    ck_assert_str_eq(first_line(&r, line, sizeof line), "m.ply:19:1: warning: data after the last element ignored ('9')");
    run_free(&r);

    run_parse(&r, HEAD "element face 1\nproperty list uchar int vertex_indices\n"
                       "element vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n"
                       "3 0 1 3\n0 0 0\n1 0 0\n0 1 0\n");
    ck_assert_int_eq(r.ok, 0);
    ck_assert_str_eq(first_line(&r, line, sizeof line),
                     "m.ply:10:7: error: element 'face' 0: vertex index 3 is out of range (3 vertices)");
    run_free(&r);

    char moved[512];
    run_parse_len(&r, moved, binary_faces_first(moved), 10);
    ck_assert_msg(r.ok == 1, "%s", r.log);
    ck_assert_vec_near(r.mesh.positions[2], vec_make(0.25, 1, -3), 0);
    ck_assert(r.mesh.tri[0][0] == 0 && r.mesh.tri[0][1] == 1 && r.mesh.tri[0][2] == 2);
    run_free(&r);
}
END_TEST

START_TEST(test_ply_binary_truncated)
{
    /* Cut inside the last index, and inside the last vertex's z: the
     * message names the element, its number, the property and the byte. */
    char buf[512], line[512];
    run r;
    size_t whole = binary_triangle(buf, 0, 0);
    run_parse_len(&r, buf, binary_triangle(buf, 0, 14), 10);
    ck_assert_int_eq(r.ok, 0);
    snprintf(buf, sizeof buf,
             "m.ply:3:1: error: element 'vertex' 2, at byte %zu: the file ends in the middle of property 'z'",
             whole - 13 - 4);
    ck_assert_str_eq(first_line(&r, line, sizeof line), buf);
    run_free(&r);
}
END_TEST

START_TEST(test_ply_triangle_limit)
{
    char line[512];
    run r;
    run_parse_len(&r, HEAD TRI_HEADER "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                  strlen(HEAD TRI_HEADER "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), 0);
    ck_assert_int_eq(r.ok, 0);
    ck_assert_str_eq(first_line(&r, line, sizeof line),
                     "m.ply:13:1: error: element 'face' 0: mesh exceeds the limit of 0 triangles");
    run_free(&r);
}
END_TEST

START_TEST(test_ply_is_ply)
{
    ck_assert(ply_is_ply("ply\n", 4));
    ck_assert(ply_is_ply("ply\r\nformat", 9));
    ck_assert(!ply_is_ply("ply", 3));
    ck_assert(!ply_is_ply("plyx\n", 5));
    ck_assert(!ply_is_ply("v 1 2 3\n", 8));
}
END_TEST

/* Every byte of the little-endian triangle changed in turn to a few
 * values: the reader accepts or refuses, never more (ok when no error),
 * and what it accepts indexes in range. */
START_TEST(test_ply_mutations_are_safe)
{
    char buf[512], copy[512];
    static const unsigned char values[] = {0, 1, 0x7f, 0x80, 0xff, '\n', ' '};
    /* The vertices first, and the faces first (read in two passes). */
    for (int layout = 0; layout < 2; layout++) {
        size_t n = layout ? binary_faces_first(buf) : binary_triangle(buf, 0, 0);
        for (size_t i = 0; i < n; i++)
            for (size_t v = 0; v < sizeof values; v++) {
                memcpy(copy, buf, n);
                copy[i] = (char)values[v];
                run r;
                run_parse_len(&r, copy, n, 10);
                ck_assert_int_eq(r.ok, r.d.errors == 0);
                for (int t = 0; t < r.mesh.triangle_count; t++)
                    for (int k = 0; k < 3; k++)
                        ck_assert(r.mesh.tri[t][k] >= 0 && r.mesh.tri[t][k] < r.mesh.position_count);
                run_free(&r);
            }
    }
}
END_TEST

/* ---- the fixtures: one mesh, four files ---------------------------------- */

static char *read_file(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    ck_assert_msg(f != NULL, "cannot open %s", path);
    char *text = malloc(1 << 16);
    ck_assert_ptr_nonnull(text);
    *len = fread(text, 1, 1 << 16, f);
    fclose(f);
    return text;
}

static void parse_file(const char *path, polymesh *out)
{
    size_t len;
    char *text = read_file(path, &len);
    source_set set;
    diag d;
    source_set_init(&set, NULL);
    int file = source_set_add(&set, path, text, len, src_span_none());
    diag_init(&d, &set, diag_print, stderr);
    int ok = ply_is_ply(text, len) ? ply_parse(&set, file, &d, 1000, out) : obj_parse(&set, file, &d, 1000, out);
    ck_assert_msg(ok, "%s did not parse", path);
    source_set_free(&set);
    free(text);
}

static const char *const encodings[] = {"tests/ply/uvsphere_ascii.ply", "tests/ply/uvsphere_le.ply",
                                        "tests/ply/uvsphere_be.ply"};

START_TEST(test_ply_fixtures_hold_the_obj_mesh)
{
    /* Same positions and normals, bit for bit; same triangles. */
    polymesh obj, ply;
    parse_file("tests/ply/uvsphere.obj", &obj);
    parse_file(encodings[_i], &ply);
    ck_assert_int_eq(obj.position_count, 42);
    ck_assert_int_eq(ply.position_count, 42);
    ck_assert_int_eq(ply.normal_count, 42);
    ck_assert_int_eq(ply.face_count, 48);
    ck_assert_int_eq(ply.triangle_count, 80);
    ck_assert_int_eq(obj.triangle_count, 80);
    ck_assert(same_vecs_bits(obj.positions, ply.positions, 42));
    ck_assert(same_vecs_bits(obj.normals, ply.normals, 42));
    ck_assert(memcmp(obj.tri, ply.tri, 80 * sizeof *obj.tri) == 0);
    ck_assert(memcmp(obj.tri_normal, ply.tri_normal, 80 * sizeof *obj.tri_normal) == 0);
    polymesh_free(&obj);
    polymesh_free(&ply);
}
END_TEST

static img_buf render_mesh(const char *file)
{
    char text[512];
    snprintf(text, sizeof text,
             "image { width 48 height 36 max_depth 3 }\n"
             "camera { eye [0.3, 1, 5] look_at [0, 0, 0] up [0, 1, 0] fov 40 }\n"
             "ambient { color 0.1 }\n"
             "distant_light { direction [-1, -1, -2] power 1 }\n"
             "mesh { file \"%s\" rotate [0, 10, 0] material { Kd 0.6 Ks 0.3 n 30 } }\n",
             file);
    int status;
    scene_model *s = scene_file_load_text("tests/ply/t.scene", text, strlen(text), NULL, stderr, 0, &status);
    ck_assert_msg(s != NULL, "%s did not load", file);
    img_buf img;
    render_stats st;
    ck_assert_int_eq(render_image(s, NULL, &img, &st), STATUS_OK);
    scene_free(s);
    return img;
}

START_TEST(test_ply_renders_as_the_obj)
{
    /* [MESH-PLY-1] ASCII and both binary orders: the same image as the OBJ,
     * bit for bit. */
    img_buf a = render_mesh("uvsphere.obj"), b = render_mesh(encodings[_i] + strlen("tests/ply/"));
    ck_assert(memcmp(a.rgb, b.rgb, 3 * sizeof *a.rgb * (size_t)a.width * (size_t)a.height) == 0);
    int lit = 0;
    for (long i = 0; i < a.width * a.height; i++)
        lit += a.rgb[3 * i] > 0.2;
    ck_assert_int_gt(lit, 200);
    img_free(&a);
    img_free(&b);
}
END_TEST

Suite *suite_ply(void)
{
    Suite *s = suite_create("ply");
    TCase *tc = tcase_create("parse");
    tcase_add_test(tc, test_ply_ascii_triangle);
    tcase_add_test(tc, test_ply_header_forms);
    tcase_add_test(tc, test_ply_normals_and_polygons);
    tcase_add_test(tc, test_ply_repeated_corners);
    tcase_add_loop_test(tc, test_ply_errors, 0, (int)(sizeof ascii_errors / sizeof ascii_errors[0]));
    tcase_add_test(tc, test_ply_trailing_data_warns);
    tcase_add_test(tc, test_ply_binary_both_orders);
    tcase_add_test(tc, test_ply_faces_first);
    tcase_add_test(tc, test_ply_binary_truncated);
    tcase_add_test(tc, test_ply_triangle_limit);
    tcase_add_test(tc, test_ply_is_ply);
    tcase_add_test(tc, test_ply_mutations_are_safe);
    suite_add_tcase(s, tc);
    TCase *fx = tcase_create("fixtures");
    tcase_add_loop_test(fx, test_ply_fixtures_hold_the_obj_mesh, 0, 3);
    tcase_add_loop_test(fx, test_ply_renders_as_the_obj, 0, 3);
    suite_add_tcase(s, fx);
    return s;
}
