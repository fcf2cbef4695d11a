/*
 * Meshes as real files have them (issue 13, spec/language.md section 8):
 * the messy-OBJ corpus tests/obj/messy-*.obj, each holding in its header
 * the warnings it must give (`# warning: ...`, in order) and the line
 * `refray check` must print for it (`# report: ...`); polygon cutting
 * (src/lang/polygon.c); the topology of a mesh (src/scene/mesh_topo.c);
 * and what an open or inconsistently wound glass mesh renders as.
 */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include "io/diag_print.h"
#include "io/scene_file.h"
#include "testlib.h"
#include "base/diag.h"
#include "base/source.h"
#include "lang/polygon.h"
#include "render/render.h"
#include "scene/mesh_topo.h"
#include "scene/scene.h"

#define OBJ_DIR "tests/obj"

enum { MAX_LINES = 8, LINE_LEN = 512, CORPUS_MAX = 32 };

/* The header lines of a corpus file that start with tag ("# warning: "). */
static int header_lines(const char *path, const char *tag, char out[MAX_LINES][LINE_LEN])
{
    char line[LINE_LEN];
    int n = 0;
    FILE *f = fopen(path, "r");
    ck_assert_msg(f != NULL, "cannot open %s", path);
    while (fgets(line, sizeof line, f) && line[0] == '#')
        if (strncmp(line, tag, strlen(tag)) == 0 && n < MAX_LINES) {
            line[strcspn(line, "\n")] = '\0';
            strcpy(out[n++], line + strlen(tag));
        }
    fclose(f);
    return n;
}

/* The messy-*.obj files, sorted. */
static int corpus(char names[CORPUS_MAX][64])
{
    int n = 0;
    DIR *dir = opendir(OBJ_DIR);
    ck_assert_ptr_nonnull(dir);
    for (struct dirent *e = readdir(dir); e; e = readdir(dir))
        if (strncmp(e->d_name, "messy-", 6) == 0 && strstr(e->d_name, ".obj") && n < CORPUS_MAX &&
            strlen(e->d_name) < 64)
            strcpy(names[n++], e->d_name);
    closedir(dir);
    qsort(names, (size_t)n, 64, (int (*)(const void *, const void *))strcmp);
    return n;
}

/* The scene that reads the corpus file `name` as `file`, with the file's
 * `# material:` if it has one. */
static void corpus_scene(const char *name, const char *file, char *text, size_t size)
{
    char path[4096], material[MAX_LINES][LINE_LEN];
    snprintf(path, sizeof path, "%s/%s", OBJ_DIR, name);
    int m = header_lines(path, "# material: ", material);
    snprintf(text, size, "mesh { file \"%s\" material { %s } }\n", file, m ? material[0] : "Kd 0.8");
}

START_TEST(test_mesh_corpus_warnings)
{
    /* [MESH-WARN-1] [MESH-WARN-2] Every warning, in order, with its text. */
    char names[CORPUS_MAX][64], text[4096], path[4096], want[MAX_LINES][LINE_LEN];
    int n = corpus(names);
    ck_assert_int_ge(n, 8);
    for (int k = 0; k < n; k++) {
        snprintf(path, sizeof path, "%s/%s", OBJ_DIR, names[k]);
        int expected = header_lines(path, "# warning: ", want);
        corpus_scene(names[k], names[k], text, sizeof text);
        char *log = NULL;
        size_t log_size = 0;
        FILE *out = open_memstream(&log, &log_size);
        int status;
        scene_model *s = scene_file_load_text(OBJ_DIR "/t.scene", text, strlen(text), NULL, out, 1, &status);
        fclose(out);
        ck_assert_msg(s != NULL, "%s did not load: %s", names[k], log);
        int got = 0;
        for (char *line = log; line && *line; line = strchr(line, '\n') ? strchr(line, '\n') + 1 : NULL) {
            char *w = strstr(line, ": warning: ");
            size_t len = strcspn(line, "\n");
            if (!w || w > line + len)
                continue;
            w += strlen(": warning: ");
            ck_assert_msg(got < expected, "%s: unexpected warning %.*s", names[k], (int)(line + len - w), w);
            ck_assert_msg(strlen(want[got]) == (size_t)(line + len - w) && strncmp(w, want[got], strlen(want[got])) == 0,
                          "%s: warning %d is\n  %.*s\nexpected\n  %s", names[k], got, (int)(line + len - w), w, want[got]);
            got++;
        }
        ck_assert_msg(got == expected, "%s: %d warnings, expected %d", names[k], got, expected);
        scene_free(s);
        free(log);
    }
}
END_TEST

static const char *refray_bin(void)
{
    const char *bin = getenv("REFRAY_BIN");
    return bin && *bin ? bin : "build/refray";
}

START_TEST(test_mesh_corpus_check_report)
{
    /* [MESH-CHECK-1] `refray check` prints, per mesh: triangles, faces,
     * dropped faces, closed or open, consistently oriented or not, pieces. */
    char names[CORPUS_MAX][64], text[8192], path[4096], want[MAX_LINES][LINE_LEN], cmd[4096], line[8192];
    int n = corpus(names);
    char scene[] = "/tmp/refray-mesh-XXXXXX";
    int fd = mkstemp(scene);
    ck_assert_int_ge(fd, 0);
    close(fd);
    char cwd[256];
    ck_assert_ptr_nonnull(getcwd(cwd, sizeof cwd));
    for (int k = 0; k < n; k++) {
        snprintf(path, sizeof path, "%s/%s", OBJ_DIR, names[k]);
        ck_assert_int_eq(header_lines(path, "# report: ", want), 1);
        char rel[4096];
        snprintf(rel, sizeof rel, "%s/%s/%s", cwd, OBJ_DIR, names[k]);
        corpus_scene(names[k], rel, text, sizeof text);
        FILE *f = fopen(scene, "w");
        ck_assert_ptr_nonnull(f);
        fputs(text, f);
        fclose(f);
        /* The scene is in /tmp, the corpus in the repository: allowed
         * explicitly ([REL-READ-1]). */
        snprintf(cmd, sizeof cmd, "%s check -W --allow-read %s/%s %s 2>/dev/null | grep '^  mesh '", refray_bin(), cwd,
                 OBJ_DIR, scene);
        FILE *p = popen(cmd, "r");
        ck_assert_ptr_nonnull(p);
        ck_assert_msg(fgets(line, sizeof line, p) != NULL, "%s: no mesh line from refray check", names[k]);
        ck_assert_int_eq(pclose(p), 0);
        line[strcspn(line, "\n")] = '\0';
        char expected[8192 + LINE_LEN];
        snprintf(expected, sizeof expected, "  mesh %s: %s", rel, want[0]);
        ck_assert_str_eq(line, expected);
    }
    unlink(scene);
}
END_TEST

START_TEST(test_mesh_store_bytes)
{
    /* [MESH-SCALE-1] The cube: 8 positions and 6 normals of 3 doubles, 12
     * triangles of 3 corner and 3 normal indices, closed (no open-edge
     * bits): 8*24 + 6*24 + 12*12 + 12*12 = 624 bytes. */
    int status;
    static const char text[] = "mesh { file \"cube.obj\" }";
    scene_model *s = scene_file_load_text(OBJ_DIR "/t.scene", text, strlen(text), NULL, stderr, 0, &status);
    ck_assert_ptr_nonnull(s);
    long triangles;
    ck_assert_int_eq(scene_mesh_bytes(s, &triangles), sizeof(real) == 8 ? 624 : 624 + 14 * 3 * (sizeof(real) - 8));
    ck_assert_int_eq(triangles, 12);
    scene_free(s);
}
END_TEST

START_TEST(test_mesh_corpus_negative_indices_are_the_cube)
{
    int status;
    static const char a[] = "mesh { file \"messy-negative.obj\" }", b[] = "mesh { file \"cube.obj\" }";
    scene_model *n = scene_file_load_text(OBJ_DIR "/t.scene", a, strlen(a), NULL, stderr, 0, &status);
    scene_model *c = scene_file_load_text(OBJ_DIR "/t.scene", b, strlen(b), NULL, stderr, 0, &status);
    ck_assert(n && c);
    const scene_trimesh *gn = &n->meshes[0].geom, *gc = &c->meshes[0].geom;
    ck_assert_int_eq(gn->tri_count, 12);
    ck_assert_int_eq(gc->tri_count, 12);
    for (int k = 0; k < 12; k++)
        for (int i = 0; i < 3; i++)
            ck_assert_vec_near(gn->positions[gn->tri[k][i]], gc->positions[gc->tri[k][i]], 0);
    scene_free(n);
    scene_free(c);
}
END_TEST

/* ---- rendering what the corpus reports ----------------------------------- */

static img_buf render_text(const char *text)
{
    int status;
    scene_model *s = scene_file_load_text(OBJ_DIR "/t.scene", text, strlen(text), NULL, stderr, 0, &status);
    ck_assert_msg(s != NULL, "did not load:\n%s", text);
    img_buf img;
    render_stats st;
    ck_assert_int_eq(render_image(s, NULL, &img, &st), STATUS_OK);
    scene_free(s);
    return img;
}

static const char glass_view[] = "image { width 24 height 18 max_depth 8 background [1, 0.8, 0.6] }\n"
                                 "camera { eye [2.5, 3, 4] look_at [0, 0, 0] up [0, 1, 0] fov 45 }\n"
                                 "ambient { color 0.1 }\n"
                                 "distant_light { direction [-1, -2, -1] power 0.8 }\n"
                                 "plane { point [0, -1.5, 0] normal [0, 1, 0] material { Kd 0.6 } }\n"
                                 "mesh { file \"%s\" material { Kd 0 t 0.9 ior 1.5 } }\n";

START_TEST(test_mesh_winding_does_not_matter)
{
    /* The cube with two faces wound the other way renders in glass exactly
     * as the consistent cube: a closed mesh's inside comes from counting
     * crossings, not from its normals. */
    char text[1024];
    snprintf(text, sizeof text, glass_view, "messy-winding.obj");
    img_buf w = render_text(text);
    snprintf(text, sizeof text, glass_view, "cube.obj");
    img_buf c = render_text(text);
    ck_assert(memcmp(w.rgb, c.rgb, 3 * sizeof *w.rgb * (size_t)w.width * (size_t)w.height) == 0);
    img_free(&w);
    img_free(&c);
}
END_TEST

START_TEST(test_mesh_open_glass_is_sheets)
{
    /* The cube without its top, in glass, head on from above: each ray
     * passes the bottom sheet straight down (no refraction: sheets) to the
     * floor and back; the same as two stacked sheets, which a plane of
     * glass (t 0.9, two-sided) is.  So the pixel equals the one of a scene
     * whose only glass is a `plane` sheet at the bottom face. */
    static const char view[] = "image { width 8 height 8 max_depth 8 background 0.5 }\n"
                               "camera { orthographic eye [0.3, 5, 0.2] look_at [0.3, 0, 0.2] up [0, 0, 1] width 1 }\n"
                               "ambient { color 0.2 }\n"
                               "plane { point [0, -3, 0] normal [0, 1, 0] material { Kd [0.6, 0.5, 0.4] } }\n"
                               "%s material { Kd 0 t 0.9 ior 1.5 } }\n";
    char text[1024];
    snprintf(text, sizeof text, view, "mesh { file \"messy-open.obj\"");
    img_buf open_mesh = render_text(text);
    snprintf(text, sizeof text, view, "plane { point [0, -1, 0] normal [0, 1, 0]");
    img_buf sheet = render_text(text);
    for (long i = 0; i < 3L * 64; i++)
        ck_assert_msg(fabs(open_mesh.rgb[i] - sheet.rgb[i]) <= 1e-15, "value %ld: %.17g vs %.17g", i,
                      open_mesh.rgb[i], sheet.rgb[i]);
    img_free(&open_mesh);
    img_free(&sheet);
}
END_TEST

/* ---- the file text of a mesh ------------------------------------------------ */

START_TEST(test_mesh_file_text_lent_and_released)
{
    /* A mesh file's text is used where its owner holds it (no copy, no
     * NUL after it) and has no line index: a message finds its line by
     * scanning (LF, CRLF and lone CR all end a line).  Once released, the
     * owner's text is untouched and a message pointing into the file
     * names it without a line. */
    static const char body[] = "v 0 0 0\r\nv 1 0 0\rv 0 1 0\nf 1 2 3\n";
    source_set set;
    source_set_init(&set, NULL);
    char *text = malloc(sizeof body - 1);
    ck_assert_ptr_nonnull(text);
    memcpy(text, body, sizeof body - 1);
    int file = source_set_lend(&set, "m.obj", text, sizeof body - 1, src_span_none());
    ck_assert_int_eq(file, 0);
    ck_assert_ptr_eq(set.files[0]->text, text);
    ck_assert_ptr_null(set.files[0]->line_start);
    int line, col;
    source_line_col(set.files[0], (size_t)(strstr(body, "f 1") - body) + 2, &line, &col);
    ck_assert_int_eq(line, 4);
    ck_assert_int_eq(col, 3);
    size_t len;
    const char *at = source_line_text(set.files[0], 10, &len);
    ck_assert_uint_eq(len, 7);
    ck_assert(strncmp(at, "v 1 0 0", 7) == 0);
    at = source_line_text(set.files[0], sizeof body - 1, &len);
    ck_assert_uint_eq(len, 0);
    char *log = NULL;
    size_t log_size = 0;
    FILE *out = open_memstream(&log, &log_size);
    diag d;
    diag_init(&d, &set, diag_print, out);
    source_set_release(&set, file);
    ck_assert_ptr_null(set.files[0]->text);
    ck_assert(memcmp(text, body, sizeof body - 1) == 0);
    free(text);
    src_span s = {file, 9, 10};
    diag_report(&d, DIAG_WARNING, s, "after the release");
    fclose(out);
    ck_assert_str_eq(log, "m.obj: warning: after the release\n");
    free(log);
    source_set_free(&set);
}
END_TEST

/* A resolver that hands out exact-size copies of one OBJ text (no NUL
 * after them) and counts what it gives and gets back. */
typedef struct lender {
    const char *text;
    int fetched, released;
    char *last;
} lender;

static int lend_fetch(void *user, const char *from, const char *name, scene_source *out, char *why, size_t size)
{
    lender *l = user;
    (void)from;
    (void)why;
    (void)size;
    size_t n = strlen(l->text);
    char *copy = malloc(n);
    ck_assert_ptr_nonnull(copy);
    memcpy(copy, l->text, n);
    out->path = name;
    out->text = copy;
    out->len = n;
    l->fetched++;
    l->last = copy;
    return STATUS_OK;
}

static void lend_release(void *user, scene_source *src)
{
    lender *l = user;
    ck_assert_ptr_eq(src->text, l->last);
    free((char *)src->text);
    l->released++;
}

START_TEST(test_mesh_text_goes_back_to_the_resolver)
{
    /* The load reads a mesh file where the resolver holds it and gives it
     * back exactly once, whether the mesh is good or not; the scene keeps
     * the file's name only. */
    static const char *const objs[] = {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3", "v 0 0 0\nf 1 2 7"};
    static const char scene[] = "mesh { file \"m.obj\" }\n";
    for (int k = 0; k < 2; k++) {
        lender l = {objs[k], 0, 0, NULL};
        scene_load_opts o;
        scene_load_opts_init(&o);
        o.resolver.fetch = lend_fetch;
        o.resolver.release = lend_release;
        o.resolver.user = &l;
        scene_source root = {"t.scene", NULL, scene, sizeof scene - 1, 0};
        int status;
        scene_model *s = scene_load_source(&root, &o, &status);
        ck_assert_int_eq(l.fetched, 1);
        ck_assert_int_eq(l.released, 1);
        ck_assert_int_eq(status, k == 0 ? STATUS_OK : STATUS_DATA);
        if (s) {
            ck_assert_int_eq(s->meshes[0].geom.tri_count, 1);
            ck_assert_str_eq(s->sources.files[1]->path, "m.obj");
            ck_assert_ptr_null(s->sources.files[1]->text);
        }
        scene_free(s);
    }
}
END_TEST

/* ---- polygons -------------------------------------------------------------- */

/* Twice the signed area of the cut triangles about +z (corners at z = 0). */
static double cut_area(const vec3 *at, const int (*t)[3], int n)
{
    double sum = 0;
    for (int k = 0; k < n; k++) {
        vec3 a = at[t[k][0]];
        sum += vec_cross(vec_sub(at[t[k][1]], a), vec_sub(at[t[k][2]], a)).z;
    }
    return sum;
}

START_TEST(test_polygon_l_shape)
{
    /* [MESH-POLY-1] The L from the corner that does not see all of it:
     * 4 triangles, all wound as the L, covering area 3 (twice: 6); the fan
     * from that corner would have a triangle outside the L. */
    static const vec3 l[6] = {{2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}, {0, 0, 0}, {2, 0, 0}};
    polygon_work w;
    polygon_work_init(&w, NULL);
    int t[6][3], flags;
    int n = polygon_triangulate(l, 6, &w, t, &flags);
    ck_assert_int_eq(n, 4);
    ck_assert_int_eq(flags, 0);
    ck_assert_near(cut_area(l, (const int(*)[3])t, n), 6, 0);
    for (int k = 0; k < n; k++) {
        vec3 a = l[t[k][0]];
        ck_assert(vec_cross(vec_sub(l[t[k][1]], a), vec_sub(l[t[k][2]], a)).z > 0);
        vec3 c = vec_scale(vec_add(a, vec_add(l[t[k][1]], l[t[k][2]])), 1.0 / 3);
        ck_assert_msg(!(c.x > 1 && c.y > 1), "triangle %d lies outside the L", k);
    }
    /* The naive fan's second-to-none: (c0, c1, c2) is outside the L. */
    vec3 c = vec_scale(vec_add(l[0], vec_add(l[1], l[2])), 1.0 / 3);
    ck_assert(c.x > 1 && c.y > 1);
    polygon_work_free(&w);
}
END_TEST

START_TEST(test_polygon_keeps_corners_on_edges)
{
    /* A square with a corner in the middle of its bottom edge (a T-junction
     * seen from the neighbour below): 3 triangles with area, every corner
     * used, none of them a sliver along the edge. */
    static const vec3 q[5] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
    polygon_work w;
    polygon_work_init(&w, NULL);
    int t[5][3], flags, used[5] = {0};
    int n = polygon_triangulate(q, 5, &w, t, &flags);
    ck_assert_int_eq(n, 3);
    ck_assert_near(cut_area(q, (const int(*)[3])t, n), 8, 0);
    for (int k = 0; k < n; k++) {
        vec3 a = q[t[k][0]];
        ck_assert(vec_cross(vec_sub(q[t[k][1]], a), vec_sub(q[t[k][2]], a)).z > 0);
        for (int i = 0; i < 3; i++)
            used[t[k][i]] = 1;
    }
    for (int i = 0; i < 5; i++)
        ck_assert_int_eq(used[i], 1);
    polygon_work_free(&w);
}
END_TEST

START_TEST(test_polygon_flags)
{
    polygon_work w;
    polygon_work_init(&w, NULL);
    int t[8][3], flags;
    /* Every corner on one line: no triangle, no area. */
    static const vec3 line[4] = {{0, 0, 0}, {1, 1, 1}, {3, 3, 3}, {2, 2, 2}};
    ck_assert_int_eq(polygon_triangulate(line, 4, &w, t, &flags), 0);
    ck_assert_int_eq(flags, POLYGON_NO_AREA);
    /* A corner 0.01 off the plane of the other three of a unit square:
     * 1e-2 > 1e-4, not planar; 1e-6 is planar enough. */
    vec3 bent[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.01}, {0, 1, 0}};
    ck_assert_int_eq(polygon_triangulate(bent, 4, &w, t, &flags), 2);
    ck_assert_int_eq(flags, POLYGON_NONPLANAR);
    bent[2].z = 1e-6;
    polygon_triangulate(bent, 4, &w, t, &flags);
    ck_assert_int_eq(flags, 0);
    /* Out of budget: a non-convex polygon is fanned, and said to be. */
    static const vec3 l[6] = {{2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}, {0, 0, 0}, {2, 0, 0}};
    w.budget = 0;
    ck_assert_int_eq(polygon_triangulate(l, 6, &w, t, &flags), 4);
    ck_assert_int_eq(flags, POLYGON_FANNED);
    ck_assert(t[0][0] == 0 && t[0][1] == 1 && t[0][2] == 2);
    polygon_work_free(&w);
}
END_TEST

/* ---- topology -------------------------------------------------------------- */

static scene_trimesh trimesh(vec3 *pos, int np, int (*tri)[3], int nt)
{
    scene_trimesh m;
    memset(&m, 0, sizeof m);
    m.positions = pos;
    m.position_count = np;
    m.tri = tri;
    m.tri_count = nt;
    return m;
}

START_TEST(test_mesh_topo_cases)
{
    /* [MESH-CLOSED-1] A tetrahedron: closed, oriented, one piece.  With one
     * face turned: still closed, not oriented.  With one face gone: 3 open
     * edges.  With a fourth face on one edge: crowded.  Two tetrahedra
     * apart: two pieces.  Vertices repeated under other indices (the same
     * positions): welded, still closed. */
    vec3 pos[12] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {5, 0, 0}, {6, 0, 0},
                    {5, 1, 0}, {5, 0, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    int tri[9][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {4, 6, 5}, {4, 5, 7}, {4, 7, 6}, {5, 6, 7}, {0, 1, 2}};
    mesh_topo t;
    unsigned char open[9];
    scene_trimesh m = trimesh(pos, 12, tri, 4);
    ck_assert(mesh_topo_analyse(&m, NULL, &t, open));
    ck_assert(t.closed && t.oriented && t.components == 1 && t.open_edges == 0);
    for (int k = 0; k < 4; k++)
        ck_assert_int_eq(open[k], 0);
    m = trimesh(pos, 12, tri, 8);
    ck_assert(mesh_topo_analyse(&m, NULL, &t, NULL));
    ck_assert(t.closed && t.oriented && t.components == 2);
    m = trimesh(pos, 12, tri, 3);
    ck_assert(mesh_topo_analyse(&m, NULL, &t, open));
    ck_assert(!t.closed && t.oriented && t.open_edges == 3 && t.crowded_edges == 0);
    /* The missing face was (1, 2, 3): its edges 1-2, 2-3, 3-1 are open in
     * the others: (0,2,1) edge 2->1 is its corner 1 -> 2, bit 1. */
    ck_assert_int_eq(open[0], 2);
    int turned[4][3] = {{0, 1, 2}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    m = trimesh(pos, 12, turned, 4);
    ck_assert(mesh_topo_analyse(&m, NULL, &t, NULL));
    ck_assert(t.closed && !t.oriented);
    int crowded[5][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 1, 4}};
    m = trimesh(pos, 12, crowded, 5);
    ck_assert(mesh_topo_analyse(&m, NULL, &t, NULL));
    ck_assert(!t.closed && t.crowded_edges == 1 && t.open_edges == 2);
    int welded[4][3] = {{8, 10, 9}, {0, 1, 11}, {0, 3, 2}, {9, 2, 3}};
    m = trimesh(pos, 12, welded, 4);
    ck_assert(mesh_topo_analyse(&m, NULL, &t, NULL));
    ck_assert(t.closed && t.oriented && t.components == 1);
}
END_TEST

Suite *suite_mesh(void)
{
    Suite *s = suite_create("mesh");
    TCase *tc = tcase_create("corpus");
    tcase_set_timeout(tc, 30);
    tcase_add_test(tc, test_mesh_corpus_warnings);
    tcase_add_test(tc, test_mesh_corpus_check_report);
    tcase_add_test(tc, test_mesh_corpus_negative_indices_are_the_cube);
    tcase_add_test(tc, test_mesh_store_bytes);
    tcase_add_test(tc, test_mesh_file_text_lent_and_released);
    tcase_add_test(tc, test_mesh_text_goes_back_to_the_resolver);
    tcase_add_test(tc, test_mesh_winding_does_not_matter);
    tcase_add_test(tc, test_mesh_open_glass_is_sheets);
    suite_add_tcase(s, tc);
    TCase *pc = tcase_create("polygons and topology");
    tcase_add_test(pc, test_polygon_l_shape);
    tcase_add_test(pc, test_polygon_keeps_corners_on_edges);
    tcase_add_test(pc, test_polygon_flags);
    tcase_add_test(pc, test_mesh_topo_cases);
    suite_add_tcase(s, pc);
    return s;
}
