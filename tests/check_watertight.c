/*
 * Closed meshes are crossed exactly once per surface (issue 13,
 * spec/numerics.md [NUM-WATERTIGHT-1], [NUM-WATERTIGHT-2]): rays shot
 * exactly through every vertex and through points of every edge of closed
 * meshes (tetrahedron, cube, icosahedron, 45-45-90 prism, an icosphere of
 * 1280 triangles), camera rays whose pixel centres fall on shared edges,
 * secondary rays inside glass and mirror meshes, shadow rays through edges;
 * and a mesh against the same solid written as a `box`, for opaque, mirror
 * and glass materials.
 *
 * The expected values come from geometry, not from the tracer: a ray from
 * outside aimed at a point of a convex solid's surface crosses it twice,
 * from inside once; a head-on view through a glass face sees the same thing
 * through every pixel of it; a closed mirror keeps every bounce (so the
 * pixel is the geometric series of the ambient term).
 */
#include <string.h>
#include "io/scene_file.h"
#include "testlib.h"
#include "render/bvh.h"
#include "render/render.h"
#include "render/trace.h"
#include "scene/scene.h"
#include "base/xform.h"

/* The closed test meshes, each with three points strictly inside. */
typedef struct solid {
    const char *file;      /* relative to tests/obj/ */
    vec3 inside[3];
} solid;

static const solid solids[] = {
    {"tetrahedron.obj", {{0.2, 0.2, 0.2}, {0.1, 0.15, 0.3}, {0.3, 0.05, 0.1}}},
    {"cube.obj", {{0.1, -0.2, 0.3}, {-0.6, 0.5, 0.2}, {0.7, 0.6, -0.8}}},
    {"../../scenes/models/icosahedron.obj", {{0.1, 0.2, -0.1}, {-0.9, 0.3, 0.4}, {0.5, -0.8, 0.6}}},
    {"prism.obj", {{-0.5, -0.5, 0.1}, {-0.2, -0.7, -0.6}, {-0.8, 0.3, 0.7}}},
    {"../../scenes/stress/geosphere.obj", {{0.05, -0.1, 0.02}, {0.4, 0.3, -0.2}, {-0.3, -0.5, 0.4}}},
};

enum { SOLIDS = sizeof solids / sizeof solids[0] };

/* Loads a scene written here as if it were ./t.scene, so that its tree
 * (where its files may come from, [REL-READ-1]) is the repository's. */
static scene_model *load(const char *text)
{
    int status;
    scene_model *s = scene_file_load_text("t.scene", text, strlen(text), NULL, stderr, 0, &status);
    ck_assert_msg(s != NULL, "scene did not load (status %d):\n%s", status, text);
    return s;
}

static scene_model *load_solid(const solid *so, const char *material, const char *xforms)
{
    char text[1024];
    snprintf(text, sizeof text,
             "image { width 8 height 8 max_depth 8 background 1 }\n"
             "distant_light { direction [-1, -2, -3] power 1 }\n"
             "mesh { file \"tests/obj/%s\" material { %s } %s }\n",
             so->file, material, xforms);
    return load(text);
}

static int count_crossing(void *ctx, const hit *h)
{
    (void)h;
    ++*(int *)ctx;
    return 0;
}

static ray ray_from_to(vec3 from, vec3 to)
{
    ray r;
    r.origin = from;
    r.dir = vec_normalize(vec_sub(to, from));
    r.tmin = 0;
    r.tmax = HUGE_VAL;
    return r;
}

typedef struct tally {
    long rays, misses, wrong;
} tally;

/* A ray through point: it must hit, and cross the surface `want` times. */
static void shoot(const tracer *t, const scene_model *s, vec3 from, vec3 point, int want, tally *out)
{
    ray r = ray_from_to(from, point), near = r;
    hit h;
    int crossings = 0;
    out->rays++;
    out->misses += !bvh_intersect(&t->accel, s->prims, &near, &h);
    bvh_visit(&t->accel, s->prims, &r, count_crossing, &crossings);
    out->wrong += crossings != want;
}

/* Rays through point: from each inside point outward (one crossing), and
 * from outside toward each inside point (two: in here, out on the far
 * side; the direction points into the solid there because the solid is
 * convex and the inside point strictly inside it). */
static void shoot_through(const tracer *t, const scene_model *s, const vec3 inside[3], vec3 point, tally *out)
{
    for (int k = 0; k < 3; k++) {
        shoot(t, s, inside[k], point, 1, out);
        shoot(t, s, vec_madd(point, vec_normalize(vec_sub(point, inside[k])), 5), point, 2, out);
    }
}

/* Every vertex, and five points of every edge (its midpoint among them),
 * of the mesh's triangles. */
static tally sweep_mesh(const scene_model *s, const vec3 inside[3])
{
    static const double at[] = {0.5, 0.1, 0.3337, 0.71, 0.9};
    tracer t;
    tally out = {0, 0, 0};
    ck_assert(tracer_init(&t, s, 0, 0));
    const scene_trimesh *g = &s->meshes[0].geom;
    for (int k = 0; k < g->tri_count; k++)
        for (int e = 0; e < 3; e++) {
            vec3 a = g->positions[g->tri[k][e]], b = g->positions[g->tri[k][(e + 1) % 3]];
            shoot_through(&t, s, inside, a, &out);
            for (int i = 0; i < 5; i++)
                shoot_through(&t, s, inside, vec_add(a, vec_scale(vec_sub(b, a), at[i])), &out);
        }
    tracer_free(&t);
    return out;
}

START_TEST(test_watertight_every_edge_and_vertex)
{
    /* [NUM-WATERTIGHT-1] As written (axis-aligned faces, edges on exact
     * coordinates) and turned and moved off the axes. */
    static const char *const frames[2] = {"", "rotate [17, 29, 41] translate [0.5, 0.25, 0.125]"};
    const solid *so = &solids[_i / 2];
    scene_model *s = load_solid(so, "Kd 0.8", frames[_i % 2]);
    ck_assert(s->meshes[0].geom.closed);
    vec3 inside[3];
    xform turn = xform_rotate_xyz(vec_make(17, 29, 41)), move = xform_translate(vec_make(0.5, 0.25, 0.125));
    xform both = xform_compose(&move, &turn);
    /* The inside points move with the mesh (the transforms in order). */
    for (int k = 0; k < 3; k++)
        inside[k] = _i % 2 ? xform_point(&both, so->inside[k]) : so->inside[k];
    tally t = sweep_mesh(s, inside);
    ck_assert_int_gt(t.rays, 100);
    ck_assert_msg(t.misses == 0 && t.wrong == 0, "%s (%s): %ld of %ld rays missed, %ld crossed wrongly", so->file,
                  _i % 2 ? "turned" : "as written", t.misses, t.rays, t.wrong);
    scene_free(s);
}
END_TEST

/* ---- camera rays on shared edges ----------------------------------------- */

static img_buf render(const scene_model *s)
{
    img_buf img;
    render_stats st;
    ck_assert_int_eq(render_image(s, NULL, &img, &st), STATUS_OK);
    ck_assert_int_eq(st.trace.nonfinite, 0);
    return img;
}

START_TEST(test_watertight_prism_pixels_on_the_diagonal)
{
    /* [NUM-WATERTIGHT-2] The glass prism head on through its square face
     * x = -1, cut along y = z: the pixel centres (i, 15 - i) lie exactly on
     * that diagonal (z = -1 + (i + 0.5)/8, y = 1 - (j + 0.5)/8).  Every ray
     * enters the face, is totally reflected by the hypotenuse (45 degrees
     * > asin(1/1.5)) and leaves through the face y = -1 (cut along x = z)
     * into the background: one path for all of them, so every pixel of the
     * face shows the same value.  Counting the diagonal twice made those
     * pixels darker by t (0.9). */
    scene_model *s = load("image { width 16 height 16 max_depth 8 background 1 }\n"
                       "camera { orthographic eye [-10, 0, 0] look_at [0, 0, 0] up [0, 1, 0] width 2 }\n"
                       "mesh { file \"tests/obj/prism.obj\" material { Kd 0 t 0.9 ior 1.5 } }\n");
    img_buf img = render(s);
    double first = img_pixel(&img, 0, 15)[0];
    int on_diagonal = 0;
    for (int j = 0; j < 16; j++)
        for (int i = 0; i < 16; i++) {
            double y = 1 - (j + 0.5) / 8, z = -1 + (i + 0.5) / 8, v = img_pixel(&img, i, j)[0];
            if (!(z > -1 && z < 1 && y > -1 && y < 1))
                continue;
            on_diagonal += y == z;
            ck_assert_msg(v == first, "pixel (%d, %d)%s: %.17g, the face elsewhere %.17g", i, j,
                          y == z ? " on the diagonal" : "", v, first);
        }
    ck_assert_int_eq(on_diagonal, 16);
    /* Three crossings of a surface of t = 0.9 (in, the reflection, out). */
    ck_assert_rel(first, 0.9 * 0.9 * 0.9, 1e-15);
    img_free(&img);
    scene_free(s);
}
END_TEST

/* Two renders agree at every pixel whose centre is farther than `margin`
 * (in pixels) from where the solid's silhouette could pass: pixels that both
 * show the background, or both the solid's inside, agree to rel. */
static void assert_same_image(const img_buf *a, const img_buf *b, double rel, const char *what)
{
    ck_assert_int_eq(a->width, b->width);
    ck_assert_int_eq(a->height, b->height);
    for (int j = 0; j < a->height; j++)
        for (int i = 0; i < a->width; i++)
            for (int c = 0; c < 3; c++) {
                double x = img_pixel(a, i, j)[c], y = img_pixel(b, i, j)[c];
                ck_assert_msg(fabs(x - y) <= rel * fmax(fabs(y), 1e-300), "%s: pixel (%d, %d) channel %d: %.17g vs %.17g",
                              what, i, j, c, x, y);
            }
}

START_TEST(test_watertight_cube_head_on_equals_box)
{
    /* The glass cube mesh and the glass box, head on with pixel centres on
     * the diagonals of the front and back faces (i = j, 32 x 32 over
     * [-1, 1]^2 exactly: no pixel centre is on the silhouette).  Identical. */
    static const char scene[] = "image { width 32 height 32 max_depth 8 background [1, 0.8, 0.6] }\n"
                                "camera { orthographic eye [0, 0, 10] look_at [0, 0, 0] up [0, 1, 0] width 2 }\n"
                                "ambient { color 0.1 }\n"
                                "distant_light { direction [1, -2, -3] power 0.7 }\n"
                                "%s { %s material { Kd [0.2, 0.3, 0.4] Ks 0.1 n 20 t 0.8 ior 1.5 } }\n";
    char text[1024];
    snprintf(text, sizeof text, scene, "mesh", "file \"tests/obj/cube.obj\"");
    scene_model *m = load(text);
    snprintf(text, sizeof text, scene, "box", "from [-1, -1, -1] to [1, 1, 1]");
    scene_model *b = load(text);
    img_buf im = render(m), ib = render(b);
    assert_same_image(&im, &ib, 1e-12, "glass cube head on");
    img_free(&im);
    img_free(&ib);
    scene_free(m);
    scene_free(b);
}
END_TEST

/* The mesh cube and the box in one frame: turned, under a light that casts
 * their shadow (through their edges too) on a floor, seen in perspective. */
static void mesh_against_box(const char *material, double rel)
{
    static const char scene[] =
        "image { width 48 height 36 max_depth 6 background [0.2, 0.3, 0.5] }\n"
        "camera { perspective eye [3, 4, 6] look_at [0, 0.5, 0] up [0, 1, 0] fov 50 }\n"
        "ambient { color 0.1 }\n"
        "point_light { position [-3, 6, 2] power 20 }\n"
        "plane { point [0, -1.5, 0] normal [0, 1, 0] material { Kd [0.8, 0.7, 0.6] } }\n"
        "%s { %s rotate [0, 30, 0] rotate [20, 0, 0] translate [0, 0.5, 0] material { %s } }\n";
    char text[1024];
    snprintf(text, sizeof text, scene, "mesh", "file \"tests/obj/cube.obj\"", material);
    scene_model *m = load(text);
    snprintf(text, sizeof text, scene, "box", "from [-1, -1, -1] to [1, 1, 1]", material);
    scene_model *b = load(text);
    ck_assert_ptr_nonnull(b->prims[1].frame);
    img_buf im = render(m), ib = render(b);
    int differ = 0;
    for (int j = 0; j < im.height; j++)
        for (int i = 0; i < im.width; i++)
            for (int c = 0; c < 3; c++) {
                double x = img_pixel(&im, i, j)[c], y = img_pixel(&ib, i, j)[c];
                differ += !(fabs(x - y) <= rel * fmax(fabs(y), 1e-300));
            }
    ck_assert_msg(differ == 0, "%s: %d pixel channels differ", material, differ);
    img_free(&im);
    img_free(&ib);
    scene_free(m);
    scene_free(b);
}

START_TEST(test_watertight_turned_cube_equals_box)
{
    /* Opaque, mirror and glass: the mesh cube renders as the turned box. */
    static const char *const materials[] = {"Kd [0.8, 0.2, 0.1]", "Kd 0.1 Ks 0.8 n 50",
                                            "Kd 0.05 Ks 0.05 n 100 t 0.85 ior 1.5"};
    mesh_against_box(materials[_i], 1e-9);
}
END_TEST

/* ---- secondary rays: a closed mirror keeps the light ---------------------- */

/* Rays from inside a closed mirror solid aimed exactly at its vertices and
 * at points of its edges: each must bounce max_depth times, and the pixel is
 * Kd Ia summed over the bounces (Ks = 1). */
static void assert_mirror_keeps_light(const char *shape, int depth)
{
    char text[1024];
    snprintf(text, sizeof text,
             "image { width 1 height 1 max_depth %d background 0 }\n"
             "ambient { color 0.002 }\n"
             "%s material { Kd 0.5 Ks 1 } }\n",
             depth, shape);
    scene_model *s = load(text);
    tracer t;
    ck_assert(tracer_init(&t, s, 0, 0));
    static const double origins[3][3] = {{0.05, 0.02, -0.03}, {0.3, -0.2, 0.1}, {-0.4, 0.35, -0.25}};
    static const double at[] = {0, 0.5, 0.23};
    int rays = 0, lost = 0;
    vec3 corner[8];
    for (int k = 0; k < 8; k++)
        corner[k] = vec_make(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
    const scene_prim *p = &s->prims[0];
    for (int o = 0; o < 3; o++)
        for (int a = 0; a < 8; a++)
            for (int b = 0; b < 8; b++) {
                int axes = (a ^ b) == 1 || (a ^ b) == 2 || (a ^ b) == 4 || a == b;
                for (int q = 0; axes && q < 3 && (q == 0 || a != b); q++) {
                    vec3 target = vec_add(corner[a], vec_scale(vec_sub(corner[b], corner[a]), at[q]));
                    if (p->frame)
                        target = xform_point(&p->frame->to_world, target);
                    ray r = ray_from_to(vec_make(origins[o][0], origins[o][1], origins[o][2]), target);
                    trace_stats st;
                    memset(&st, 0, sizeof st);
                    rgb c = trace_ray(&t, &r, 1, &t.eye_media, 0, &st);
                    rays++;
                    lost += !(fabs(c.x - depth * 0.001) <= 1e-12 * depth);
                }
            }
    ck_assert_int_gt(rays, 100);
    ck_assert_msg(lost == 0, "%s: %d of %d rays lost their light", shape, lost, rays);
    tracer_free(&t);
    scene_free(s);
}

START_TEST(test_watertight_mirror_mesh_keeps_the_light)
{
    /* [NUM-MESH-EDGE-1] The cube as a mesh, axis-aligned and turned: a ray
     * spawned from it starts off the triangle's edges, so none escapes. */
    assert_mirror_keeps_light("mesh { file \"tests/obj/cube.obj\"", 200);
    assert_mirror_keeps_light("mesh { file \"tests/obj/cube.obj\" rotate [17, 29, 41]", 200);
}
END_TEST

START_TEST(test_watertight_turned_mirror_box_keeps_the_light)
{
    /* [NUM-BOX-1] A turned box (intersected in its own frame) gets the
     * treatment of an axis-aligned one: a ray spawned into it starts inside
     * it on every axis, so no bounce next to an edge escapes. */
    assert_mirror_keeps_light("box { from [-1, -1, -1] to [1, 1, 1] rotate [17, 29, 41]", 200);
}
END_TEST

/* ---- shadow rays through edges -------------------------------------------- */

typedef struct carried {
    const scene_model *s;
    double through;
} carried;

static int carry(void *ctx, const hit *h)
{
    carried *c = ctx;
    c->through *= c->s->materials[c->s->prims[h->prim].material].t;
    return 0;
}

START_TEST(test_watertight_shadow_rays_through_edges)
{
    /* Shadow rays from a point below the glass cube toward a light above
     * it, on a line through a vertex or an edge point of the cube and a
     * point inside it: each is attenuated by t^2 (in and out), never t^3 or
     * t^4 (an edge counted twice), never t or 1 (a leak). */
    scene_model *s = load("point_light { position [0, 10, 0] power 1 }\n"
                       "mesh { file \"tests/obj/cube.obj\" rotate [17, 29, 41] material { Kd 0 t 0.5 ior 1.5 } }\n");
    tracer t;
    ck_assert(tracer_init(&t, s, 0, 0));
    const scene_trimesh *g = &s->meshes[0].geom;
    static const double inside[3][3] = {{0.1, -0.2, 0.3}, {-0.6, 0.5, 0.2}, {0.05, 0.02, -0.1}};
    int rays = 0, wrong = 0;
    for (int k = 0; k < g->tri_count; k++)
        for (int e = 0; e < 3; e++)
            for (int q = 0; q < 3; q++)
                for (int in = 0; in < 3; in++) {
                    vec3 a = g->positions[g->tri[k][e]], b = g->positions[g->tri[k][(e + 1) % 3]];
                    vec3 point = vec_add(a, vec_scale(vec_sub(b, a), q * 0.37));
                    vec3 d = vec_normalize(vec_sub(vec_make(inside[in][0], inside[in][1], inside[in][2]), point));
                    ray r = ray_from_to(vec_madd(point, d, -4), vec_madd(point, d, 8));
                    r.tmax = 12;
                    carried c = {s, 1};
                    bvh_visit(&t.accel, s->prims, &r, carry, &c);
                    rays++;
                    wrong += c.through != 0.25;
                }
    ck_assert_int_eq(rays, 12 * 27);
    ck_assert_msg(wrong == 0, "%d of %d shadow rays not attenuated by t^2", wrong, rays);
    tracer_free(&t);
    scene_free(s);
}
END_TEST

Suite *suite_watertight(void)
{
    Suite *s = suite_create("watertight");
    TCase *tc = tcase_create("crossings");
    tcase_set_timeout(tc, 30);
    tcase_add_loop_test(tc, test_watertight_every_edge_and_vertex, 0, 2 * SOLIDS);
    tcase_add_test(tc, test_watertight_prism_pixels_on_the_diagonal);
    tcase_add_test(tc, test_watertight_cube_head_on_equals_box);
    tcase_add_loop_test(tc, test_watertight_turned_cube_equals_box, 0, 3);
    tcase_add_test(tc, test_watertight_mirror_mesh_keeps_the_light);
    tcase_add_test(tc, test_watertight_turned_mirror_box_keeps_the_light);
    tcase_add_test(tc, test_watertight_shadow_rays_through_edges);
    suite_add_tcase(s, tc);
    return s;
}
