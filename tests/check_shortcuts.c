/*
 * The tracer's shortcuts (spec/shading.md, "Shortcuts"): every piece of
 * work a scene is known not to need may be left out only when leaving it
 * out changes no bit of the image.  Random scenes (tests/difftest/gen.c,
 * profile DTGEN_ANY: every construct, lone primitives and cameras inside
 * solids often) are rendered with the shortcuts on and with all of them off
 * (tracer_no_shortcuts) and compared with memcmp.  The two scenes that
 * found the unsound one (a lone sphere seen from inside) are checked
 * against values derived by hand.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "cli_testlib.h"
#include "difftest/gen.h"
#include "io/scene_file.h"
#include "render/interface.h"
#include "render/render.h"
#include "render/shade.h"
#include "scene/scene.h"

/* 400 random scenes, 50 to a test: one fork per 50 renders, not per
 * render (the sanitizer build pays for every fork). */
enum { RANDOM_BATCHES = 8, RANDOM_BATCH = 50 };

static scene_model *load(const char *text)
{
    int status;
    scene_model *s = scene_file_load_text("test.scene", text, strlen(text), NULL, stderr, 0, &status);
    ck_assert_msg(s != NULL, "scene did not load (status %d):\n%s", status, text);
    return s;
}

/* Renders s with the shortcuts on (no_shortcuts 0) or off (1). */
static void render(const scene_model *s, int no_shortcuts, img_buf *img, render_stats *st)
{
    render_opts o;
    memset(&o, 0, sizeof o);
    o.no_shortcuts = no_shortcuts;
    ck_assert_int_eq(render_image(s, &o, img, st), STATUS_OK);
}

/* The camera at the origin looking down -z (fov 90, 5 x 5 pixels), a
 * point light at z = 5 outside the lone solid `solid` around the camera:
 * every value is 0 with the shortcuts on and off, and shadow rays ran. */
static void dark_both_ways(const char *solid)
{
    char text[512];
    snprintf(text, sizeof text, "image { width 5 height 5 max_depth 1 }\n"
                                "camera { perspective eye [0, 0, 0] look_at [0, 0, -1] up [0, 1, 0] fov 90 }\n"
                                "point_light { position [0, 0, 5] power 1 falloff none }\n%s", solid);
    scene_model *s = load(text);
    ck_assert_int_eq(s->prim_count, 1);
    ck_assert_int_eq(s->features.shadows, 1);
    for (int off = 0; off <= 1; off++) {
        img_buf img;
        render_stats st;
        render(s, off, &img, &st);
        for (int i = 0; i < 3 * 25; i++)
            ck_assert_msg(img.rgb[i] == 0, "shortcuts %s: value %d is %.17g, not 0", off ? "off" : "on", i,
                          img.rgb[i]);
        ck_assert_int_gt(st.trace.shadow_rays, 0);
        img_free(&img);
    }
    scene_free(s);
}

/* [LANG-FEATURES-2] [SHADE-SHORTCUT-OFF-1] A camera at the centre of an
 * opaque sphere (radius 2, Kd 0.5), a point light outside it at z = 5, no
 * ambient: every camera ray meets the inner wall at some p; where N.L > 0
 * (N the inward normal) the segment from p to the light runs into the ball
 * and leaves it through the wall again before reaching the light, so the
 * light is blocked; where N.L <= 0 it adds nothing.  Every pixel is 0,
 * with the shortcuts on and off.  (The record once left the shadow rays of
 * a lone sphere out: the centre pixel was 0.5 = Kd E N.L, N.L = 1.) */
START_TEST(test_shortcuts_camera_inside_opaque_sphere_is_dark)
{
    dark_both_ways("sphere { center [0, 0, 0] radius 2 material { Kd 0.5 } }\n");
}
END_TEST

/*
 * [SHADE-SHADOW-1] [LANG-FEATURES-2] A lone glass sphere (unit, at the
 * origin; Kd 0.5, Ks 0.5, n 10, t 0.5, ior 1.5) under a distant light
 * travelling down -y (E = 1), max_depth 2, no ambient, black background.
 * The centre pixel's orthographic ray runs from (0, 3, 4) toward the
 * origin, d = (0, -0.6, -0.8): it passes through the centre, so it meets
 * the sphere along the normal at p1 = (0, 0.6, 0.8) and goes on unbent to
 * p2 = (0, -0.6, -0.8).
 *   p1: N = V = (0, 0.6, 0.8), N.L = 0.6 with L = (0, 1, 0); the shadow ray
 *       leaves the ball (y grows from 0.6 on the line x = 0, z = 0.8, whose
 *       other crossing is at y = -0.6): light 1.  R = 2 (N.L) N - L gives
 *       V.R = 2 (0.6)(1) - 0.6 = 0.6.  Body (1 - t) Kd 0.6 = 0.15,
 *       highlight Ks 0.6^10 = 0.0030233088; the mirror ray goes back
 *       along -d into the black background.
 *   p2 (depth 2 = max_depth: local colour only): N, turned toward
 *       V = (0, 0.6, 0.8), is (0, 0.6, 0.8), N.L = 0.6, V.R = 0.6; the shadow
 *       ray climbs the line x = 0, z = -0.8 and leaves the ball through its
 *       own wall at y = 0.6: light t = 0.5.  Body (1 - t) Kd 0.5 0.6 =
 *       0.075, highlight Ks 0.5 0.6^10 = 0.0015116544; weighted by t:
 *       0.0382558272.
 * Pixel: 0.15 + 0.0030233088 + 0.0382558272 = 0.191279136.  (With the
 * wall's shadow left out p2 gets light 1 and the pixel 0.2295349632.)
 */
START_TEST(test_shortcuts_lone_glass_sphere_shadows_itself)
{
    scene_model *s = load("image { width 3 height 3 max_depth 2 background 0 }\n"
                          "camera { orthographic eye [0, 3, 4] look_at [0, 0, 0] up [0, 1, 0] width 0.5 }\n"
                          "distant_light { direction [0, -1, 0] power 1 }\n"
                          "sphere { center [0, 0, 0] radius 1 material { Kd 0.5 Ks 0.5 n 10 t 0.5 ior 1.5 } }\n");
    for (int off = 0; off <= 1; off++) {
        img_buf img;
        render(s, off, &img, NULL);
        const double *px = img_pixel(&img, 1, 1);
        for (int c = 0; c < 3; c++)
            ck_assert_rel(px[c], 0.191279136, 1e-13);
        img_free(&img);
    }
    scene_free(s);
}
END_TEST

/* [SHADE-SHORTCUT-OFF-1] The switch does switch: a lone diffuse plane
 * under a light sends no shadow ray with the shortcuts on (nothing can
 * occlude it) and one per camera ray with them off, and the BVH tests
 * every primitive for every ray with them off. */
START_TEST(test_shortcuts_off_does_all_the_work)
{
    scene_model *s = load("image { width 4 height 4 max_depth 3 }\n"
                          "camera { eye [0, 3, 5] look_at [0, 0, 0] }\n"
                          "point_light { position [0, 5, 0] }\n"
                          "plane { material { Kd 0.5 } }\n");
    img_buf on, off;
    render_stats st_on, st_off;
    render(s, 0, &on, &st_on);
    render(s, 1, &off, &st_off);
    ck_assert_int_eq(st_on.shadows, 0);
    ck_assert_int_eq(st_on.trace.shadow_rays, 0);
    ck_assert_int_eq(st_off.no_shortcuts, 1);
    ck_assert_int_eq(st_off.shadows & st_off.specular & st_off.reflection & st_off.refraction, 1);
    ck_assert_int_ge(st_off.trace.shadow_rays, 16);
    ck_assert_int_gt(st_off.trace.reflection_rays, 0);
    ck_assert_int_gt(st_off.trace.refraction_rays, 0);
    ck_assert(memcmp(on.rgb, off.rgb, sizeof(double) * 3 * 16) == 0);
    img_free(&on);
    img_free(&off);
    scene_free(s);
}
END_TEST

/* [SHADE-SHORTCUT-BVH-1] With culling off the BVH tests every bounded
 * primitive for every ray: a ray that meets one sphere of a row of 20
 * tests all 20, against a handful with culling. */
START_TEST(test_shortcuts_bvh_exhaustive_tests_everything)
{
    scene_prim prims[20];
    bvh b;
    memset(prims, 0, sizeof prims);
    for (int i = 0; i < 20; i++) {
        prims[i].kind = PRIM_SPHERE;
        prims[i].mesh = -1;
        prims[i].u.sphere.center = vec_make(3.0 * i, 0, 0);
        prims[i].u.sphere.radius = 1;
    }
    ck_assert(bvh_build(&b, prims, 20, NULL));
    for (int exhaustive = 0; exhaustive <= 1; exhaustive++) {
        ray r = {vec_make(0, 0, 5), vec_make(0, 0, -1), 0, HUGE_VAL};
        hit h;
        bvh_stats st = {0, 0};
        b.exhaustive = exhaustive;
        ck_assert(bvh_intersect_stats(&b, prims, &r, &h, &st));
        ck_assert_int_eq(h.prim, 0);
        ck_assert_near(h.t, 4, 1e-12);
        if (exhaustive)
            ck_assert_int_eq(st.prims_tested, 20);
        else
            ck_assert_int_lt(st.prims_tested, 20);
    }
    bvh_free(&b);
}
END_TEST

/* The bytes of the file at path into buf (size bytes); how many. */
static size_t file_bytes(const char *path, char *buf, size_t size)
{
    FILE *f = fopen(path, "rb");
    ck_assert_msg(f != NULL, "cannot open %s", path);
    size_t n = fread(buf, 1, size, f);
    fclose(f);
    return n;
}

/* [SHADE-SHORTCUT-OFF-1] [EMBED-API-10] `refray render --no-shortcuts`
 * reaches the tracer through the public API: on a lone plane under a
 * point light the shadow pass, skipped with the shortcuts, runs (one
 * shadow ray for each of the 8 x 6 x 2 x 2 camera rays, all of which meet
 * the plane), and the file written is the same to the byte. */
START_TEST(test_shortcuts_cli_no_shortcuts)
{
    char dir[64], on[128], off[128];
    static char a[8192], b[8192];
    static cli_run r;
    cli_scratch(dir, sizeof dir, "shortcuts");
    cli_path(on, sizeof on, dir, "on.pfm");
    cli_path(off, sizeof off, dir, "off.pfm");
    const char *scene = "scenes/analytic/plane_point_inverse_square.scene";
    const char *with[] = {"render", scene, "--width", "8", "--height", "6", "--stats", "-q", "-o", on, NULL};
    cli_refray(&r, with);
    ck_assert_msg(r.code == 0, "%s", r.err);
    ck_assert_msg(strstr(r.err, "  passes: shadows skipped (nothing can occlude)"), "%s", r.err);
    ck_assert_msg(strstr(r.err, " 0 shadow,"), "%s", r.err);
    const char *without[] = {"render", scene, "--width", "8", "--height", "6", "--stats", "-q", "--no-shortcuts",
                             "-o", off, NULL};
    cli_refray(&r, without);
    ck_assert_msg(r.code == 0, "%s", r.err);
    ck_assert_msg(strstr(r.err, "  passes (every shortcut off): shadows on,"), "%s", r.err);
    ck_assert_msg(strstr(r.err, " 192 shadow,"), "%s", r.err);
    size_t na = file_bytes(on, a, sizeof a), nb = file_bytes(off, b, sizeof b);
    ck_assert(na > 8 * 6 * 12 && na < sizeof a);
    ck_assert(na == nb && memcmp(a, b, na) == 0);
    cli_remove(dir);
}
END_TEST

/* [LANG-FEATURES-2] [SHADE-SHORTCUT-OFF-1] The same with a closed mesh:
 * the camera at the centre of cube.obj ([-1, 1]^3, opaque, Kd 0.5), a
 * point light outside at z = 5.  Fov 90 over 5 x 5 pixels: every camera
 * ray (x, y, -1) with |x|, |y| <= 0.8 meets the inner side of the face
 * z = -1, whose inward normal (0, 0, 1) faces the light (N.L > 0); the
 * segment to the light crosses the cube and leaves it through the face
 * z = 1, which blocks it.  Every pixel is 0 both ways; a mesh alone is
 * not flat, so its scene keeps the shadow pass. */
START_TEST(test_shortcuts_camera_inside_opaque_mesh_is_dark)
{
    dark_both_ways("mesh { file \"tests/obj/cube.obj\" material { Kd 0.5 } }\n");
}
END_TEST

/* The mesh scenes of the tree, each at most 48 x 32 with 1 sample and 4
 * samples a distributed light (their own size when smaller: the prism's
 * pixel centres lie on its shared edges): OBJ and PLY meshes, glass and
 * mirror meshes, smooth meshes (the terminator's lift), slivers, a closed
 * mesh far from the origin, a lone glass prism seen head on. */
static const char *const mesh_scenes[] = {
    "scenes/mesh.scene",
    "scenes/terminator.scene",
    "scenes/stress/watertight_mesh.scene",
    "scenes/stress/thin_triangles.scene",
    "scenes/stress/surface_starts.scene",
    "tests/ply/encodings.scene",
    "tests/obj/prism_head_on.scene",
};

/* [SHADE-SHORTCUT-OFF-1] [SHADE-SHORTCUT-BVH-1] Mesh scenes: identical
 * bits with the shortcuts on and off (the BVH testing every triangle of
 * every mesh for every ray). */
START_TEST(test_shortcuts_mesh_scenes_bit_identical)
{
    const char *path = mesh_scenes[_i];
    int status;
    scene_model *s = scene_file_load(path, NULL, stderr, 0, &status);
    ck_assert_msg(s != NULL, "%s did not load (status %d)", path, status);
    ck_assert_int_gt(s->mesh_count, 0);
    render_opts o;
    memset(&o, 0, sizeof o);
    o.width = s->image.width < 48 ? s->image.width : 48;
    o.height = s->image.height < 32 ? s->image.height : 32;
    o.samples = 1;
    o.light_samples = 4;
    img_buf on, off;
    ck_assert_int_eq(render_image(s, &o, &on, NULL), STATUS_OK);
    o.no_shortcuts = 1;
    ck_assert_int_eq(render_image(s, &o, &off, NULL), STATUS_OK);
    size_t n = 3 * (size_t)on.width * (size_t)on.height;
    for (size_t i = 0; i < n; i++)
        ck_assert_msg(memcmp(&on.rgb[i], &off.rgb[i], sizeof on.rgb[i]) == 0,
                      "%s, value %zu: %.17g with the shortcuts, %.17g without", path, i, on.rgb[i], off.rgb[i]);
    img_free(&on);
    img_free(&off);
    scene_free(s);
}
END_TEST

/* A generated scene (kind, index: for the message) rendered both ways and
 * compared; the failing scene's text is printed. */
static void check_generated_scene(const dtgen_scene *g, const char *kind, int index)
{
    int status;
    scene_model *s = scene_file_load_text("random.scene", g->text, g->len, NULL, stderr, 0, &status);
    ck_assert_msg(s != NULL, "%s scene %d did not load (status %d):\n%s", kind, index, status, g->text);
    img_buf on, off;
    render(s, 0, &on, NULL);
    render(s, 1, &off, NULL);
    size_t n = 3 * (size_t)on.width * (size_t)on.height;
    for (size_t i = 0; i < n; i++)
        ck_assert_msg(memcmp(&on.rgb[i], &off.rgb[i], sizeof on.rgb[i]) == 0,
                      "%s scene %d, value %zu: %.17g with the shortcuts, %.17g without:\n%s", kind, index, i,
                      on.rgb[i], off.rgb[i], g->text);
    img_free(&on);
    img_free(&off);
    scene_free(s);
}

/* Scene index of the random generator, rendered both ways and compared. */
static void check_random_scene(int index)
{
    static dtgen_scene g;   /* 16 kB: off the stack of the forked test */
    dtgen_make(&g, (uint64_t)index, DTGEN_ANY, "tests/obj");
    check_generated_scene(&g, "generated", index);
}

/* The placements of the random scenes at extreme magnitudes: far from the
 * origin (coordinates 1e7, ulps of 2e-9), far and tiny (sizes 1e-6 there:
 * a few hundred ulps across), tiny at the origin, and huge. */
static const struct placement {
    double scale, offset[3];
} placements[] = {
    {1, {1e7, -3e6, 7e6}},
    {1e-6, {-6e6, 1e7, 2e6}},
    {1e-6, {0, 0, 0}},
    {1e6, {3e7, 0, -1e7}},
};
enum { PLACED_BATCH = 25 };

/* [SHADE-SHORTCUT-OFF-1] Scene index of the random generator, moved to
 * placement p, rendered both ways and compared. */
static void check_placed_scene(int index, int p)
{
    static dtgen_scene g;
    dtgen_make_placed(&g, (uint64_t)index, DTGEN_ANY, "tests/obj", placements[p].scale, placements[p].offset);
    check_generated_scene(&g, "placed", index);
}

/*
 * [SHADE-SHORTCUT-BLOCKER-1] A floor under a 1 x 1 area light at height 4
 * (16 samples) with an opaque ball of radius 0.9 at height 2 between them;
 * an orthographic camera (width 0.2, from (0, 1, 5)) sees the floor within
 * |x| <= 0.1, |z| <= 0.51 of the origin, passing 1.8 from the ball's
 * centre (max_depth 1).  A shadow ray from there to the light is at height
 * 2 halfway, within sqrt(0.3^2 + 0.51^2) = 0.6 of the ball's centre, so
 * every one runs into the ball, which is tested first for all but the
 * first ray of a pixel: the shadow rays test under one and a half
 * primitives each on average (the walk alone tests the floor plane and the
 * ball: 2), while the image is the same bits as with the shortcuts off, and
 * black (no ambient).
 */
START_TEST(test_shortcuts_blocker_tried_first)
{
    scene_model *s = load("image { width 4 height 4 max_depth 1 }\n"
                          "camera { orthographic eye [0, 1, 5] look_at [0, 0, 0] up [0, 1, 0] width 0.2 }\n"
                          "distributed_light { rectangle [-0.5, 4, -0.5] [1, 0, 0] [0, 0, 1] power 1 samples 16 }\n"
                          "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0.5 } }\n"
                          "sphere { center [0, 2, 0] radius 0.9 material { Kd 0.5 } }\n");
    img_buf on, off;
    render_stats st_on, st_off;
    render(s, 0, &on, &st_on);
    render(s, 1, &off, &st_off);
    ck_assert_int_eq(st_on.trace.shadow_rays, 16 * 16);
    ck_assert_int_lt(st_on.trace.bvh.prims_tested - st_on.trace.camera_rays * 2, 3 * st_on.trace.shadow_rays / 2);
    for (int i = 0; i < 3 * 16; i++) {
        ck_assert_msg(on.rgb[i] == 0, "value %d is %.17g, not 0", i, on.rgb[i]);
        ck_assert(memcmp(&on.rgb[i], &off.rgb[i], sizeof on.rgb[i]) == 0);
    }
    img_free(&on);
    img_free(&off);
    scene_free(s);
}
END_TEST

/*
 * [SHADE-SHORTCUT-BLOCKER-1] The hint is the last shadow ray's blocker, or
 * none once a shadow ray reached the light.  A 1x1 orthographic view
 * straight down at the floor's origin, a point light at (0, 4, 0) straight
 * above it, and a ball at (5, 1, 5) of radius 0.5, off that shadow ray
 * (the ray runs along x = z = 0).  The hint is set to the ball by hand, as
 * if it had stopped the last ray: the first pixel's shadow ray tests it,
 * misses and reaches the light; the same pixel again makes the same tests
 * less that one, and both pixels are the same lit value.
 */
START_TEST(test_shortcuts_open_ray_clears_the_blocker)
{
    scene_model *s = load("image { width 1 height 1 max_depth 1 }\n"
                          "camera { orthographic eye [0, 10, 0] look_at [0, 0, 0] up [0, 0, 1] width 1 }\n"
                          "point_light { position [0, 4, 0] power 1 }\n"
                          "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0.5 } }\n"
                          "sphere { center [5, 1, 5] radius 0.5 material { Kd 0.5 } }\n");
    ck_assert_int_eq(s->prims[1].kind, PRIM_SPHERE);
    tracer t;
    trace_stats st;
    ck_assert(tracer_init(&t, s, 0, 0));
    memset(&st, 0, sizeof st);
    st.blocker[0].prim = 1 + 1;
    st.blocker[0].part = 0;
    rgb first = render_pixel(&t, 1, 1, 1, 0, 0, &st);
    long tested = st.bvh.prims_tested;
    ck_assert_int_eq(st.shadow_rays, 1);
    ck_assert_int_eq(st.blocker[0].prim, 0);
    rgb second = render_pixel(&t, 1, 1, 1, 0, 0, &st);
    ck_assert_int_eq(st.shadow_rays, 2);
    ck_assert_int_eq(st.bvh.prims_tested - tested, tested - 1);
    ck_assert(first.x > 0 && same_vec_bits(first, second));
    tracer_free(&t);
    scene_free(s);
}
END_TEST

/*
 * [SHADE-SHORTCUT-BLOCKER-1] A camera ray's hit and its mirror ray's hit
 * keep their own hints.  A 1x1 orthographic view along (0, -1, 1) at a
 * glossy floor's origin; its mirror ray, along (0, 1, 1), meets the ball W
 * at (0, 5, 5).  The light at (3, 2, -2): the floor point's shadow ray is
 * stopped by ball A, halfway, the point on W's by ball B, halfway too.
 * After the pixel the first kind's slot holds A and the second's B (one
 * slot for both would hold B alone); the pixel again is stopped by both
 * hints, with the same value.
 */
START_TEST(test_shortcuts_mirror_hit_keeps_its_own_blocker)
{
    scene_model *s = load("image { width 1 height 1 max_depth 2 }\n"
                          "camera { orthographic eye [0, 10, -10] look_at [0, 0, 0] up [0, 1, 0] width 1 }\n"
                          "point_light { position [3, 2, -2] power 1 }\n"
                          "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0.5 Ks 0.5 n 10 } }\n"
                          "sphere { center [0, 5, 5] radius 1 material { Kd 0.5 } }\n"
                          "sphere { center [1.5, 1, -1] radius 0.3 material { Kd 0.5 } }\n"
                          "sphere { center [1.5, 3.1464, 1.1464] radius 0.3 material { Kd 0.5 } }\n");
    tracer t;
    trace_stats st;
    ck_assert(tracer_init(&t, s, 0, 0));
    memset(&st, 0, sizeof st);
    rgb first = render_pixel(&t, 1, 1, 1, 0, 0, &st);
    ck_assert_int_eq(st.shadow_rays, 2);
    ck_assert_int_eq(st.reflection_rays, 1);
    ck_assert_int_eq(st.blocker[0].prim, 1 + 2);
    ck_assert_int_eq(st.blocker[TRACE_BLOCKERS].prim, 1 + 3);
    long tested = st.bvh.prims_tested;
    rgb second = render_pixel(&t, 1, 1, 1, 0, 0, &st);
    ck_assert_int_eq(st.shadow_rays, 4);
    ck_assert_int_eq(st.blocker[0].prim, 1 + 2);
    ck_assert_int_eq(st.blocker[TRACE_BLOCKERS].prim, 1 + 3);
    ck_assert(st.bvh.prims_tested - tested < tested);
    ck_assert(same_vec_bits(first, second));
    tracer_free(&t);
    scene_free(s);
}
END_TEST

/* The ray-tree hash of pixel (0, 0) of s's 1x1 image with the any-crossing
 * walk on or off (t.any_walk as tracer_init left it, or forced). */
static uint64_t any_walk_path(const scene_model *s, int force, int any_walk, int *was)
{
    tracer t;
    trace_stats st;
    ck_assert(tracer_init(&t, s, 0, 0));
    *was = t.any_walk;
    if (force)
        t.any_walk = any_walk;
    memset(&st, 0, sizeof st);
    st.record_path = 1;
    render_pixel(&t, 1, 1, 1, 0, 0, &st);
    ck_assert_int_eq(st.shadow_rays, 1);
    tracer_free(&t);
    return st.path;
}

/*
 * [SHADE-SHORTCUT-ANY-1] The floor's origin seen from above, its shadow ray
 * to the light at (2, 4, 0) stopped halfway by a ball the camera ray misses.  With the ball's t +0 the tracer takes the any-crossing walk,
 * and the ray tree's hash is the counting walk's; with t -0 (the language
 * takes it) the counting walk carries -0, whose bits the hash reads, and the
 * tracer keeps that walk.
 */
START_TEST(test_shortcuts_any_walk_only_with_plus_zero)
{
    static const char *const t_of[2] = {"0", "-0"};
    for (int k = 0; k < 2; k++) {
        char text[512];
        snprintf(text, sizeof text,
                 "image { width 1 height 1 max_depth 1 }\n"
                 "camera { orthographic eye [0, 10, 0] look_at [0, 0, 0] up [0, 0, 1] width 1 }\n"
                 "point_light { position [2, 4, 0] power 1 }\n"
                 "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0.5 } }\n"
                 "sphere { center [1, 2, 0] radius 0.5 material { Kd 0.5 t %s } }\n",
                 t_of[k]);
        scene_model *s = load(text);
        int was, ignored;
        uint64_t counted = any_walk_path(s, 1, 0, &ignored), taken = any_walk_path(s, 0, 0, &was);
        ck_assert_int_eq(was, k == 0);
        ck_assert_msg(taken == counted, "t %s: the hash moved", t_of[k]);
        if (k == 1)   /* why: the any-crossing walk would carry +0 */
            ck_assert_msg(any_walk_path(s, 1, 1, &ignored) != counted, "t -0: the same hash");
        scene_free(s);
    }
}
END_TEST


/* Renders pixel (0, 0) of s's 1x1 image with the ray-tree hash on or off
 * (it turns [SHADE-SHORTCUT-TIR-1] off); the rays traced in *rays. */
static rgb tir_pixel(const scene_model *s, int record_path, long *rays)
{
    tracer t;
    trace_stats st;
    ck_assert(tracer_init(&t, s, 0, 0));
    memset(&st, 0, sizeof st);
    st.record_path = record_path;
    rgb c = render_pixel(&t, 1, 1, 1, 0, 0, &st);
    *rays = st.camera_rays + st.shadow_rays + st.reflection_rays + st.refraction_rays + st.tir_rays;
    tracer_free(&t);
    return c;
}

/* [SHADE-SHORTCUT-TIR-1] A camera inside a glass ball (ior 1.5, Ks 0.5)
 * near its wall, looking along it: its ray meets the wall at sin 0.9 >
 * 1/1.5, totally reflected, and so do the rays after it round the ball.
 * Under a point light the totally reflected ray is the mirror ray, traced
 * once: the same colour to the bit as with the shortcut off (the ray-tree
 * hash on), with fewer rays.  Under a rectangle light (one sample) the
 * keys of the two rays pick their samples: both are traced, the same rays
 * either way. */
START_TEST(test_shortcuts_tir_traced_once_as_the_mirror_ray)
{
    static const char *const lights[] = {"point_light { position [0, 0.5, 0.2] power 1 }\n",
                                         "distributed_light { rectangle [0, 0.5, 0.2] [0.1, 0, 0] [0, 0, 0.1] power 1 samples 1 }\n"};
    for (int k = 0; k < 2; k++) {
        char text[1024];
        snprintf(text, sizeof text,
                 "image { width 1 height 1 max_depth 6 }\n"
                 "camera { perspective eye [0.9, 0, 0] look_at [0.9, 0, 1] up [0, 1, 0] fov 1 }\n%s"
                 "sphere { center [0, 0, 0] radius 1 material { Kd 0 Ks 0.5 n 20 t 0.5 ior 1.5 } }\n"
                 "sphere { center [0, 0.3, 0] radius 0.2 material { Kd 0.7 } }\n",
                 lights[k]);
        scene_model *s = load(text);
        long on, off;
        rgb with = tir_pixel(s, 0, &on), without = tir_pixel(s, 1, &off);
        ck_assert_msg(same_vec_bits(with, without), "light %d: the colours differ", k);
        ck_assert_msg(with.x > 0, "light %d: nothing seen", k);
        if (k == 0)
            ck_assert_msg(on < off, "point light: %ld rays with the shortcut, %ld without", on, off);
        else
            ck_assert_msg(on == off, "rectangle light: %ld rays with the shortcut, %ld without", on, off);
        scene_free(s);
    }
}
END_TEST

/* [SHADE-SHORTCUT-LOBE-2] The floor tracer_build makes once a material
 * (shade's, once a shaded point before): a cosine whose power n is 0 to the
 * lobe, at most 2^-1030 (pow's result times the lobe's correction below
 * DBL_MIN), and not far below it: at least 2^-1031, so few samples whose
 * lobe is 0 still send their shadow ray.  A shininess of 0 has no such
 * cosine: 0. */
START_TEST(test_shortcuts_lobe_floor_once_a_material)
{
    scene_model *s = load("camera { perspective eye [0, 0, 5] look_at [0, 0, 0] up [0, 1, 0] fov 40 }\n"
                          "point_light { position [0, 4, 4] power 1 }\n"
                          "sphere { center [-2, 0, 0] radius 0.5 material { Kd 0 Ks 0.5 n 300 t 0.5 ior 1.5 } }\n"
                          "sphere { center [0, 0, 0] radius 0.5 material { Kd 0 Ks 0.5 n 0 t 0.5 ior 1.5 } }\n"
                          "sphere { center [2, 0, 0] radius 0.5 material { Kd 0.5 Ks 0.5 n 1 } }\n"
                          "sphere { center [0, 2, 0] radius 0.5 material { Kd 0 Ks 0.5 n 70000 } }\n");
    tracer t;
    ck_assert(tracer_init(&t, s, 0, 0));
    int checked = 0;
    for (int i = 0; i < s->material_count; i++) {
        real n = s->materials[i].n, f = t.lobe_floors[i];
        if (n == 0) {
            ck_assert(f == 0);
            continue;
        }
        real p = pow(f, n);
        ck_assert_msg(f > 0 && f < 1 && p <= 0x1p-1030 && p >= 0x1p-1031, "n %g: floor %.17g, floor^n %g", (double)n,
                      (double)f, (double)p);
        checked++;
    }
    ck_assert_int_ge(checked, 3);
    tracer_free(&t);
    scene_free(s);
}
END_TEST
/* The terms tracer_build finds once a material (shade's, once a shaded point
 * before): TRACE_KS where a channel of Ks is above 0, TRACE_NO_BODY where
 * every channel of Kd is 0; expected by hand, sphere by sphere. */
START_TEST(test_shortcuts_material_terms_once_a_material)
{
    scene_model *s = load("camera { perspective eye [0, 0, 5] look_at [0, 0, 0] up [0, 1, 0] fov 40 }\n"
                          "point_light { position [0, 4, 4] power 1 }\n"
                          "sphere { center [-2, 0, 0] radius 0.5 material { Kd 0 Ks 0 t 0.5 ior 1.5 } }\n"
                          "sphere { center [0, 0, 0] radius 0.5 material { Kd [0, 0, 0.1] Ks [0, 0.2, 0] } }\n"
                          "sphere { center [2, 0, 0] radius 0.5 material { Kd 0.5 Ks 0 } }\n"
                          "sphere { center [0, 2, 0] radius 0.5 material { Kd 0 Ks [0, 0, 0.3] n 30 } }\n");
    static const int expected[4] = {TRACE_NO_BODY, TRACE_KS, 0, TRACE_KS | TRACE_NO_BODY};
    tracer t;
    ck_assert(tracer_init(&t, s, 0, 0));
    ck_assert_int_eq(s->prim_count, 4);
    for (int k = 0; k < 4; k++) {
        ck_assert(s->prims[k].kind == PRIM_SPHERE && s->prims[k].u.sphere.center.x == (k == 3 ? 0 : 2 * k - 2));
        ck_assert_int_eq(t.material_terms[s->prims[k].material], expected[k]);
    }
    tracer_free(&t);
    scene_free(s);
}
END_TEST
/*
 * [SHADE-SHORTCUT-LOBE-1] [SHADE-SHORTCUT-LOBE-2] A glass ball (Kd 0) over
 * a floor under a 16-sample area light, for shininess 0, 1, 30, 1000 and
 * 1e6 and for a ball with Ks 0 too: the same bits with the shortcuts on
 * and off, and with them on fewer shadow rays (the samples whose lobe is 0
 * send none; for Ks 0, none at all from the ball).  max_depth 1 and no
 * ambient: the ball's pixels are its highlights alone, so a lobe of 1e-300
 * left out would show.
 */
START_TEST(test_shortcuts_lobe_gate_on_glass)
{
    static const char *const materials[] = {"Kd 0 Ks 0.5 n 0 t 0.5 ior 1.5", "Kd 0 Ks 0.5 n 1 t 0.5 ior 1.5",
                                            "Kd 0 Ks 0.5 n 30 t 0.5 ior 1.5", "Kd 0 Ks 0.5 n 1000 t 0.5 ior 1.5",
                                            "Kd 0 Ks [0, 0.5, 0] n 1e6 t 0.5 ior 1.5", "Kd 0 Ks 0 t 0.7 ior 1.3"};
    for (size_t i = 0; i < sizeof materials / sizeof materials[0]; i++) {
        char text[1024];
        snprintf(text, sizeof text,
                 "image { width 16 height 16 max_depth 1 }\n"
                 "camera { eye [0.3, 2, 4] look_at [0, 1, 0] fov 40 }\n"
                 "distributed_light { rectangle [-0.5, 4, -0.5] [1, 0, 0] [0, 0, 1] power 3 samples 16 }\n"
                 "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0.5 } }\n"
                 "sphere { center [0, 1, 0] radius 0.9 material { %s } }\n",
                 materials[i]);
        scene_model *s = load(text);
        img_buf on, off;
        render_stats st_on, st_off;
        render(s, 0, &on, &st_on);
        render(s, 1, &off, &st_off);
        ck_assert_msg(memcmp(on.rgb, off.rgb, sizeof(double) * 3 * 256) == 0, "%s: the images differ", materials[i]);
        ck_assert_msg(st_on.trace.shadow_rays < st_off.trace.shadow_rays, "%s: %ld shadow rays, %ld without shortcuts",
                      materials[i], st_on.trace.shadow_rays, st_off.trace.shadow_rays);
        img_free(&on);
        img_free(&off);
        scene_free(s);
    }
}
END_TEST

/* [SHADE-SHORTCUT-OFF-1] [SHADE-SHORTCUT-PASS-1] [SHADE-SHORTCUT-RAYS-1]
 * [SHADE-SHORTCUT-GATE-1] [SHADE-SHORTCUT-STOP-1] [SHADE-SHORTCUT-BVH-1] [SHADE-SHORTCUT-LOBE-1]
 * [SHADE-SHORTCUT-BLOCKER-1] Random scenes: identical bits with the shortcuts on and off. */
/* Loads text and renders it with the shortcuts on and off: both render
 * (render() asserts it), to the same bits; the stats of each go back, and
 * the image in *keep unless keep is NULL. */
static void image_both_ways(const char *text, render_stats *st_on, render_stats *st_off, img_buf *keep)
{
    scene_model *s = load(text);
    img_buf on, off;
    render(s, 0, &on, st_on);
    render(s, 1, &off, st_off);
    ck_assert_int_eq(on.width * on.height, off.width * off.height);
    ck_assert_msg(memcmp(on.rgb, off.rgb, 3 * (size_t)(on.width * on.height) * sizeof on.rgb[0]) == 0,
                  "the shortcuts change the image of\n%s", text);
    if (keep)
        *keep = on;
    else
        img_free(&on);
    img_free(&off);
    scene_free(s);
}

static void same_both_ways(const char *text, render_stats *st_on, render_stats *st_off)
{
    image_both_ways(text, st_on, st_off, NULL);
}

/*
 * [SHADE-SHORTCUT-DARK-1] The ball of a distributed light (trace_light_setup's
 * centre and reach) holds every sample point trace_light_point makes: a
 * tilted disk and a skewed rectangle far from the origin, 20 000 keys of 64
 * samples each.  Its reach is the disk's radius and the rectangle's half
 * diagonal, to within 2^-20 (a ball of reach 0, the light's centre alone,
 * or of half the true size would fail the first loop).
 */
START_TEST(test_shortcuts_dark_light_ball_holds_samples)
{
    scene_model *s = load("image { width 1 height 1 }\n"
                          "camera { eye [0, 0, 5] look_at [0, 0, 0] }\n"
                          "distributed_light { disk [1000.5, -3, 7] [0.3, -1, 0.6] 2.5 power 1 samples 64 }\n"
                          "distributed_light { rectangle [-20, 4, 1e4] [3, 0.5, 0] [1, 0, 2] power 1 samples 64 }\n"
                          "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0.5 } }\n");
    ck_assert_int_eq(s->light_count, 2);
    /* The diagonals of the rectangle: |(4, 0.5, 2)| and |(2, 0.5, -2)|. */
    const double expect[2] = {2.5, 0.5 * sqrt(16 + 0.25 + 4)};
    for (int li = 0; li < 2; li++) {
        light_setup setup = trace_light_setup(&s->lights[li], 64);
        ck_assert_msg(setup.reach >= expect[li] && setup.reach <= expect[li] * (1 + 0x1p-20), "light %d: reach %.17g",
                      li, (double)setup.reach);
        /* One assertion on the farthest sample, not one per sample: under
         * Check's fork mode a passed assertion is a message to the parent,
         * and 2.6 M of them took 27 s of the sanitizer build's run.  A NaN
         * distance, once met, stays the farthest. */
        double far = 0;
        int far_key = 0, far_j = 0;
        for (uint64_t key = 0; key < 20000; key++)
            for (int j = 0; j < 64; j++) {
                vec3 p = trace_light_point(&s->lights[li], &setup, li, key, j);
                double d = vec_length(vec_sub(p, setup.centre));
                if (far == far && !(d <= far)) {
                    far = d;
                    far_key = (int)key;
                    far_j = j;
                }
            }
        ck_assert_msg(far <= setup.reach, "light %d key %d sample %d: %.17g from the centre, reach %.17g", li, far_key,
                      far_j, far, (double)setup.reach);
        /* The samples reach out to the rim: the ball is not loose by much. */
        ck_assert_msg(far > 0.95 * expect[li], "light %d: farthest sample %.17g", li, far);
    }
    scene_free(s);
}
END_TEST

/*
 * [SHADE-SHORTCUT-DARK-2] Each cell's ball (tracer_build's cells and
 * cell_reach) holds every sample point trace_light_point makes in that
 * cell: a tilted disk far from the origin, grids of 4 (2x2), 12 (3x4) and
 * 36 (6x6) samples, 20 000 keys.  The centre is formed here from the
 * disk's frame, not read back from the cell's test.  A reach of 1.0 for
 * 1.5 times the half diagonal, or the centre of the next cell, fails.
 */
START_TEST(test_shortcuts_dark_cell_ball_holds_samples)
{
    static const int counts[] = {4, 12, 36};
    for (size_t c = 0; c < sizeof counts / sizeof counts[0]; c++) {
        char text[512];
        snprintf(text, sizeof text,
                 "image { width 1 height 1 }\n"
                 "camera { eye [0, 0, 5] look_at [0, 0, 0] }\n"
                 "distributed_light { disk [1000.5, -3, 7] [0.3, -1, 0.6] 2.5 power 1 samples %d }\n"
                 "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0.5 } }\n",
                 counts[c]);
        scene_model *s = load(text);
        tracer t;
        ck_assert(tracer_init(&t, s, 0, 0));
        const light_setup *setup = &t.lights[0];
        ck_assert_ptr_nonnull(setup->cells);
        double worst = 0;   /* the largest distance over reach; a NaN stays */
        int worst_j = 0;
        for (uint64_t key = 0; key < 20000; key++)
            for (int j = 0; j < counts[c]; j++) {
                vec3 p = trace_light_point(&s->lights[0], setup, 0, key, j);
                vec3 centre = vec_add(s->lights[0].position, vec_add(vec_scale(setup->t1, setup->cells[j].u),
                                                                     vec_scale(setup->t2, setup->cells[j].v)));
                double r = vec_length(vec_sub(p, centre)) / setup->cell_reach;
                if (worst == worst && !(r <= worst)) {
                    worst = r;
                    worst_j = j;
                }
            }
        ck_assert_msg(worst <= 1, "%d samples, cell %d: %.17g of the reach", counts[c], worst_j, worst);
        /* Not loose by much: the cells' samples come within 0.4 of it. */
        ck_assert_msg(worst > 0.4, "%d samples: %.17g of the reach", counts[c], worst);
        tracer_free(&t);
        scene_free(s);
    }
}
END_TEST

/*
 * [SHADE-SHORTCUT-DARK-1] Whole lights left out at a point: a ball under a
 * disk light and a rectangle light (each large: a ball of reach 0 would
 * leave out samples near the terminator and the highlights' rims), an
 * opaque ball (its lower half faces away from both lights) and a glass
 * ball (Kd 0) for shininess 0, 30, 1000 and 1e6 and for Ks 0.  The same
 * bits with the shortcuts on and off, and lights were left out whole
 * (dark_lights > 0).  max_depth 1 and no ambient: the glass pixels are
 * highlights alone.
 */
START_TEST(test_shortcuts_dark_lights_both_ways)
{
    static const char *const materials[] = {"Kd 0.6 Ks 0.3 n 50", "Kd 0 Ks 0.5 n 0 t 0.5 ior 1.5",
                                            "Kd 0 Ks 0.5 n 30 t 0.5 ior 1.5", "Kd 0 Ks 0.5 n 1000 t 0.5 ior 1.5",
                                            "Kd 0 Ks [0, 0.5, 0] n 1e6 t 0.5 ior 1.5", "Kd 0 Ks 0 t 0.7 ior 1.3"};
    for (size_t i = 0; i < sizeof materials / sizeof materials[0]; i++) {
        char text[1024];
        snprintf(text, sizeof text,
                 "image { width 40 height 40 max_depth 1 }\n"
                 "camera { eye [0.3, 1.2, 4] look_at [0, 1, 0] fov 40 }\n"
                 "distributed_light { disk [-1.5, 3.5, 1] [0.5, -1, 0] 1.2 power 3 samples 9 }\n"
                 "distributed_light { rectangle [1, 2.2, -1] [1.5, 0, 0] [0, 0.4, 1.5] power 3 samples 12 }\n"
                 "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0.5 } }\n"
                 "sphere { center [0, 1, 0] radius 0.9 material { %s } }\n",
                 materials[i]);
        render_stats st_on, st_off;
        same_both_ways(text, &st_on, &st_off);
        ck_assert_msg(st_on.trace.dark_lights > 0, "%s: no light left out", materials[i]);
        ck_assert_int_eq(st_off.trace.dark_lights, 0);
        ck_assert_int_eq(st_on.trace.light_samples, st_off.trace.light_samples);
        /* [SHADE-SHORTCUT-DARK-2] The disk's cells on the terminator (Ks 0
         * with Kd 0 leaves the lights out whole, so none there). */
        ck_assert_msg(st_on.trace.dark_cells > 0 || i == sizeof materials / sizeof materials[0] - 1,
                      "%s: no cell left out", materials[i]);
        ck_assert_int_eq(st_off.trace.dark_cells, 0);
    }
}
END_TEST

/* A uniform double in [0, 1) from a 64-bit xorshift state. */
static double next_uniform(uint64_t *state)
{
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    return (double)(*state >> 11) * 0x1p-53;
}

static vec3 next_unit(uint64_t *state)
{
    vec3 a;
    do
        a = vec_make(2 * next_uniform(state) - 1, 2 * next_uniform(state) - 1, 2 * next_uniform(state) - 1);
    while (!(vec_length2(a) > 0.01 && vec_length2(a) <= 1));
    return vec_normalize(a);
}

/*
 * [SHADE-SHORTCUT-ABSORB-1] trace_lobe_above bounds shade_phong_lobe from
 * above for unit V and R, far from the peak and on it (R within 1e-9 to
 * 0.3 of V: the 1 - h branch with its correction), integral exponents and
 * not, up to 1e6; and it is close: within 2 exp(n (-ln c - S) + n 2^-17)
 * of the lobe (S = x + x^2/2 + x^3/3, x = 1 - c: the floor to a power of
 * 2, the series' tail and the margin) where the lobe is at least 2^-900,
 * so a bound that only holds loosely fails.
 */
START_TEST(test_shortcuts_lobe_above_bounds_lobe)
{
    static const double ns[] = {1, 1.5, 2, 7, 20, 20.5, 200, 400, 1000, 4097.25, 65537, 1e6};
    uint64_t state = 0x9e3779b97f4a7c15u;
    long near = 0, close = 0;
    for (int i = 0; i < 240000; i++) {
        double n = ns[i % (int)(sizeof ns / sizeof ns[0])];
        vec3 v = next_unit(&state), r;
        if (i % 3 == 0) {
            r = next_unit(&state);
        } else {
            double scale = pow(10, -9 + 8.5 * next_uniform(&state));
            r = vec_normalize(vec_add(v, vec_scale(next_unit(&state), scale)));
            near++;
        }
        double c = vec_dot(v, r), lobe = shade_phong_lobe(v, r, n), above = trace_lobe_above(c, n);
        ck_assert_msg(lobe <= above, "n %.17g, V.R %.17g: lobe %.17g above its bound %.17g", n, c, lobe, above);
        if (c > 0 && c < 1 && lobe >= 0x1p-900 && above < 1) {
            double x = 1 - c, tail = -log(c) - (x + x * x / 2 + x * x * x / 3);
            ck_assert_msg(above <= 2.01 * lobe * exp(n * tail + n * 0x1p-17), "n %.17g, V.R %.17g: bound %.17g, lobe %.17g",
                          n, c, above, lobe);
            close++;
        }
    }
    ck_assert(near > 100000 && close > 10000);
}
END_TEST

/* A ball of `material` over a floor under `light`, 40 x 40, no ambient, a
 * black background: the same bits with the shortcuts on and off. */
static void ball_both_ways(int max_depth, const char *light, const char *material, render_stats *on,
                           render_stats *off)
{
    char text[1024];
    snprintf(text, sizeof text,
             "image { width 40 height 40 max_depth %d }\ncamera { eye [0.3, 1.2, 4] look_at [0, 1, 0] fov 40 }\n%s\n"
             "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0.5 } }\n"
             "sphere { center [0, 1, 0] radius 0.9 material { %s } }\n",
             max_depth, light, material);
    same_both_ways(text, on, off);
}

/*
 * [SHADE-SHORTCUT-ABSORB-1] A glass ball's highlights (Kd 0, no ambient,
 * max_depth 1: its pixels are the highlight sums alone) under a disk light
 * of 36 samples: the same bits with the shortcuts on and off, and samples
 * whose highlight the sum absorbs are left without their shadow ray.
 */
START_TEST(test_shortcuts_absorbed_highlights_both_ways)
{
    static const char *const materials[] = {"Kd 0 Ks 0.06 n 400 t 0.92 ior 1.45",
                                            "Kd 0 Ks [0.5, 0.02, 0] n 60 t 0.5 ior 1.5",
                                            "Kd 0 Ks [0.2, 0.4, 0.1] n 100.5 t 0.5 ior 1.5",
                                            "Kd 0 Ks 0.3 n 5000 t 0.9 ior 1.3"};
    for (size_t i = 0; i < sizeof materials / sizeof materials[0]; i++) {
        render_stats on, off;
        ball_both_ways(1, "distributed_light { disk [-0.5, 4, 2] [0.2, -1, -0.3] 1.5 power 9 samples 36 }", materials[i],
                       &on, &off);
        ck_assert_msg(on.trace.absorbed > 0 && off.trace.absorbed == 0, "%s: %ld samples absorbed, %ld without shortcuts",
                      materials[i], on.trace.absorbed, off.trace.absorbed);
        ck_assert_int_eq(on.trace.light_samples, off.trace.light_samples);
    }
}
END_TEST

/*
 * [SHADE-SHORTCUT-HIDDEN-1] trace_ball_cosine_above bounds V.R, formed as
 * add_source forms it (L = (p - P) / |p - P|, R = 2(N.L)N - L), for the
 * points of the ball, the tangent point nearest M's direction (where the
 * bound is reached) among them, near the origin and 1e4 from it; and it is
 * tight there, within 2^-19 (the margin 2^-20 and a little).  Fails with
 * the margin left out, and with the cone's angle added (theta + alpha).
 */
START_TEST(test_shortcuts_ball_cosine_above_holds)
{
    uint64_t state = 0x243f6a8885a308d3u;
    int tangent = 0;
    for (int k = 0; k < 200000; k++) {
        double far = k % 2 ? 1e4 : 1;
        vec3 p = vec_scale(next_unit(&state), far * next_uniform(&state));
        vec3 n = next_unit(&state), v = next_unit(&state);
        if (vec_dot(n, v) < 0)
            n = vec_neg(n);
        vec3 m = vec_sub(vec_scale(n, 2 * vec_dot(n, v)), v), d = vec_scale(next_unit(&state), 1 + 40 * next_uniform(&state));
        double dist = vec_length(d), reach = dist * 0.9 * next_uniform(&state);
        double above = trace_ball_cosine_above(d, reach, m);
        vec3 du = vec_scale(d, 1 / dist), mu = vec_normalize(m), w = vec_sub(mu, vec_scale(du, vec_dot(du, mu)));
        double sin_a = reach / dist, cos_a = sqrt(1 - sin_a * sin_a);
        vec3 at[2];
        int count = 0;
        at[count++] = vec_add(vec_add(p, d), vec_scale(next_unit(&state), reach * next_uniform(&state)));
        int open = vec_length2(w) > 1e-20 && vec_dot(du, mu) < cos_a;
        if (open) {
            vec3 l = vec_add(vec_scale(du, cos_a), vec_scale(vec_normalize(w), sin_a));
            at[count++] = vec_add(p, vec_scale(l, dist * cos_a));
        }
        for (int j = 0; j < count; j++) {
            vec3 to = vec_sub(at[j], p);
            vec3 l = vec_scale(to, 1.0 / vec_length_fast(to));
            double c = vec_dot(v, shade_reflect_about(l, n));
            ck_assert_msg(c <= above, "V.R %.17g above its bound %.17g (sample %d, case %d)", c, above, j, k);
            if (j == 1 && above < 1) {
                ck_assert_msg(above - c <= 0x1p-19, "bound %.17g loose over V.R %.17g (case %d)", above, c, k);
                tangent++;
            }
        }
    }
    ck_assert_int_gt(tangent, 50000);
}
END_TEST

/*
 * [SHADE-SHORTCUT-HIDDEN-1] Kd = 0 points whose light loop is left out
 * where no highlight the loop could make shows in their colour: glass
 * balls and mirrors over a floor under a disk light of 36 samples (alone,
 * and with a point and a distant light), the same bits with the shortcuts
 * on and off, and loops left out (their samples counted).  Among them
 * points whose highlight must show: the disk in a mirror's direction with
 * little to mirror (t 0, a black background) and a weak glass (t 0.05),
 * a highlight on the green and blue channels alone, a disk of radius 0.001
 * and 64 samples under a lobe of n 20, whose samples' highlights are all
 * near the bound, so that one sample's bound is hidden where their sum is
 * not.
 */
START_TEST(test_shortcuts_hidden_highlights_both_ways)
{
    static const char *const materials[] = {"Kd 0 Ks 0.06 n 400 t 0.92 ior 1.45",
                                            "Kd 0 Ks [0, 0.3, 0.2] n 200 t 0.6 ior 1.5",
                                            "Kd 0 Ks 0.5 n 40 t 0",
                                            "Kd 0 Ks 0.9 n 1000 t 0.05 ior 1.3",
                                            "Kd 0 Ks 0.5 n 20 t 0.5 ior 1.5"};
    static const char *const lights[] = {
        "distributed_light { disk [-0.5, 4, 2] [0.2, -1, -0.3] 1.5 power 9 samples 36 }",
        ("distributed_light { disk [-0.5, 4, 2] [0.2, -1, -0.3] 1.5 power 9 samples 36 }\n"
         "point_light { position [2, 3, 3] power 20 }\ndistant_light { direction [-0.3, -1, -0.2] power 0.4 }"),
        "distributed_light { disk [-0.5, 4, 2] [0.2, -1, -0.3] 0.001 power 9 samples 64 }"};
    long hidden = 0;
    for (size_t i = 0; i < sizeof materials / sizeof materials[0]; i++)
        for (size_t j = 0; j < sizeof lights / sizeof lights[0]; j++) {
            render_stats on, off;
            ball_both_ways(3, lights[j], materials[i], &on, &off);
            ck_assert_int_eq(off.trace.hidden_highlights, 0);
            hidden += on.trace.hidden_highlights;
        }
    ck_assert_int_gt(hidden, 1000);
    /* Every ray of weight (Ks, t > 0 everywhere) and no total reflection
     * shaded with a recursion (max_depth 2): the shortcuts trace the same
     * points, and the loops left out count their samples. */
    render_stats on, off;
    same_both_ways("image { width 40 height 40 max_depth 2 }\n"
                   "camera { eye [0.3, 1.2, 4] look_at [0, 1, 0] fov 40 }\n"
                   "distributed_light { disk [-0.5, 4, 2] [0.2, -1, -0.3] 1.5 power 9 samples 36 }\n"
                   "point_light { position [2, 3, 3] power 20 }\n"
                   "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0.6 Ks 0.1 t 0.1 } }\n"
                   "sphere { center [0, 1, 0] radius 0.9 material { Kd 0 Ks 0.06 n 400 t 0.92 ior 1.45 } }\n",
                   &on, &off);
    ck_assert_int_gt(on.trace.hidden_highlights, 100);
    ck_assert_int_eq(on.trace.light_samples, off.trace.light_samples);
}
END_TEST

/* [SHADE-SHORTCUT-DARK-1] (found by an outside attack) A scene 1e-160
 * across: a mirror-like plane (Kd 0, Ks 1, n 1e6, lobe floor 0.9993) under a
 * disk light of radius 1e-175 near the mirror direction, power 1e300 (its
 * intensity saturates).  light_dark's |D| = sqrt(vec_length2(D)) squares
 * components near 1e-160: |D|^2 is a subnormal near 2^-1062 with some 12
 * bits, so |D| - R (the gap) can be 2^-13 of itself too large, past the
 * margin E = 2^-20 of the lobe test; pixels on the rim of the highlight
 * (V.R just above the floor, lobe up to 2^-1022 times 1e300) are left dark
 * with the shortcuts on (12 pixels of 64x64 differ, e.g. 592 against 0).
 * Expected: the same bits both ways. */
START_TEST(test_shortcuts_dark_light_subnormal_distance)
{
    const char *text = "image { width 64 height 64 samples 1 max_depth 1 background 0 }\n"
                       "camera { perspective eye [0, 1e-160, -1e-160] look_at [0, 0, 0] up [0, 1, 0] fov 4 }\n"
                       "distributed_light { disk [0, 1e-160, 1e-160] [0, -1, 0] 1e-175 power 1e300 samples 1 "
                       "falloff inverse_square }\n"
                       "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0 Ks 1 n 1000000 } }\n";
    /* A rectangle light 1e-170 across, 2e-161 away, n 1e7: 42 channels. */
    const char *rect = "image { width 64 height 64 samples 1 max_depth 1 background 0 }\n"
                       "camera { perspective eye [0, 2e-161, -2e-161] look_at [0, 0, 0] up [0, 1, 0] fov 8 }\n"
                       "distributed_light { rectangle [0, 2e-161, 2e-161] [1e-170, 0, 0] [0, 0, 1e-170] power 1 "
                       "samples 4 falloff inverse_square }\n"
                       "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0 Ks 1 n 1e7 } }\n";
    render_stats st_on, st_off;
    same_both_ways(rect, &st_on, &st_off);
    same_both_ways(text, &st_on, &st_off);
}
END_TEST

/* [SHADE-SHORTCUT-OFF-1] A glass ball (t 0.5, radius 4) around three
 * shells of six coincident opaque balls each (radii 3, 2, 1; six, so that
 * each shell is one interface of the tracer), seen from outside: 19 solids.
 * With the shortcuts on no ray goes through an opaque shell.  With them off
 * the transmitted rays of weight 0 go in through all of them, more solids
 * than the stack holds (MEDIUM_MAX); that cannot change the image, so the
 * render must not be refused for it: both ways render, to the same bits.
 * (Before, the shortcuts-off render stopped with STATUS_DATA.) */
START_TEST(test_shortcuts_off_weightless_ray_overflow_not_refused)
{
    char text[4096];
    int len = snprintf(text, sizeof text, "image { width 3 height 3 max_depth 6 }\n"
                                          "camera { perspective eye [0, 0, 10] look_at [0, 0, 0] up [0, 1, 0] fov 20 }\n"
                                          "point_light { position [3, 4, 5] power 1 }\n"
                                          "sphere { radius 4 material { Kd 0.2 t 0.5 ior 1.5 } }\n");
    for (int radius = 3; radius >= 1; radius--)
        for (int k = 0; k < 6; k++)
            len += snprintf(text + len, sizeof text - (size_t)len, "sphere { radius %d material { Kd 0.5 } }\n",
                            radius);
    ck_assert_int_gt(1 + 3 * 6, MEDIUM_MAX);
    ck_assert_int_lt(len, (int)sizeof text);
    render_stats st_on, st_off;
    same_both_ways(text, &st_on, &st_off);
    ck_assert_int_gt(st_off.trace.refraction_rays, st_on.trace.refraction_rays);
    ck_assert_int_eq(st_on.trace.medium_overflow, 0);
    ck_assert_int_eq(st_off.trace.medium_overflow, 0);
}
END_TEST

/* The camera inside 16 concentric glass shells (t 0.9), the stack full,
 * looking at a ball at z = -5 made of the coincident balls `balls`. */
static void inside_sixteen_shells_both_ways(const char *balls)
{
    char text[4096];
    int len = snprintf(text, sizeof text, "image { width 6 height 4 max_depth 4 }\n"
                                          "camera { eye [0, 0, 0] look_at [0, 0, -1] fov 40 }\n"
                                          "point_light { position [0, 0, 0] power 10 falloff none }\n"
                                          "material shell { Kd 0.1 t 0.9 ior 1 }\n");
    for (int k = 0; k < MEDIUM_MAX; k++)
        len += snprintf(text + len, sizeof text - (size_t)len, "sphere { radius %d material shell }\n", 50 + k);
    len += snprintf(text + len, sizeof text - (size_t)len, "%s", balls);
    ck_assert_int_lt(len, (int)sizeof text);
    render_stats st_on, st_off;
    same_both_ways(text, &st_on, &st_off);
}

/* [SHADE-SHORTCUT-OFF-1] With the stack full, an opaque ball: only the
 * shortcuts-off render sends a transmitted ray (weight 0) into it, and
 * pushing the ball overflowed the stack before that ray's own count began
 * (the render was refused).  A glass ball and an opaque one in the same
 * place: no ray goes in (the interface lets 0 through), yet the default
 * render was refused when the glass line came first.  Both render, the
 * same bits both ways.  (Found by an outside attack.) */
START_TEST(test_shortcuts_full_stack_weightless_crossing_not_refused)
{
    inside_sixteen_shells_both_ways("sphere { center [0, 0, -5] material { Kd [0.9, 0.5, 0.1] } }\n");
    inside_sixteen_shells_both_ways("sphere { center [0, 0, -5] material { Kd 0.1 t 0.5 ior 1.5 } }\n"
                                    "sphere { center [0, 0, -5] material { Kd [0.9, 0.5, 0.1] } }\n");
    inside_sixteen_shells_both_ways("sphere { center [0, 0, -5] material { Kd [0.9, 0.5, 0.1] } }\n"
                                    "sphere { center [0, 0, -5] material { Kd 0.1 t 0.5 ior 1.5 } }\n");
}
END_TEST

/* A kept-frame shape (scaled unevenly, turned) 2e-6 across, its centre at
 * (x, 1.75e-6, 1e-6) and the camera 7.2e-6 from it at the same x:
 * "%s" is the shape, "%.17g" x twice. */
static const char far_tiny_frame[] =
    "image { width 20 height 15 samples 1 max_depth 1 background 0.1 }\n"
    "camera { perspective eye [%.17g, 3.977874551863094e-06, -5.80152477284702e-06] "
    "look_at [%.17g, 5e-07, 0.0] up [0, 1, 0] fov 60 }\n"
    "ambient { color 0.05 }\n"
    "%s scale [1, 0.5, 1] rotate [80, 62, 0] translate [%.17g, 1.75e-06, 1e-06] material { Kd 0.77 } }\n";

/* [NUM-FRAME-1] [SHADE-SHORTCUT-BVH-1] tests/attack9b, finding 1: the
 * scene above at x = -1e13 (an ulp there is 2^-9, a thousand times the
 * shape) against the same at x = 0.  The eye's and the shape's x are the
 * same double, so o - T, and from it the local ray, is the same in both,
 * and the images must be the same to the bit; the ellipsoid, at most 2e-6
 * across seen from 7.2e-6 with fov 60 (8.3e-6 over 15 rows, 0.55e-6 a
 * pixel), covers between 1 and 36 (6 x 6) pixels.  Before, the local origin
 * L^-1 o + (-L^-1 T) rounded to the sphere's centre: every ray hit it
 * without the shortcuts (300 pixels), 140 with them. */
START_TEST(test_shortcuts_far_tiny_frame)
{
    static const char *const shapes[] = {
        "sphere { center [0, 0, 0] radius 1e-6",
        "box { from [-1e-6, -1e-6, -1e-6] to [1e-6, 1e-6, 1e-6]",
        "cylinder { from [0, -1e-6, 0] to [0, 1e-6, 0] radius 1e-6",
        "cone { from [0, -1e-6, 0] to [0, 1e-6, 0] radii 1e-6 5e-7",
        "torus { major 1e-6 minor 3e-7",
    };
    const double far[] = {-1e13, -3e12, 1e15};
    char text[1024];
    render_stats st_on, st_off;
    for (size_t k = 0; k < sizeof shapes / sizeof shapes[0]; k++) {
        img_buf at0;
        snprintf(text, sizeof text, far_tiny_frame, 0.0, 0.0, shapes[k], 0.0);
        image_both_ways(text, &st_on, &st_off, &at0);
        int shown = 0;
        for (int i = 0; i < 300; i++)
            shown += at0.rgb[3 * i] != 0.1;
        ck_assert_msg(shown >= 1 && shown <= 36, "%s: %d pixels", shapes[k], shown);
        for (size_t j = 0; j < sizeof far / sizeof far[0]; j++) {
            img_buf img;
            snprintf(text, sizeof text, far_tiny_frame, far[j], far[j], shapes[k], far[j]);
            image_both_ways(text, &st_on, &st_off, &img);
            ck_assert_msg(memcmp(img.rgb, at0.rgb, sizeof(double) * 3 * 300) == 0, "%s at x = %g", shapes[k],
                          far[j]);
            img_free(&img);
        }
        img_free(&at0);
    }
}
END_TEST

/* [NUM-FRAME-1] A kept-frame sphere 2e-6 across at the origin seen by an
 * orthographic camera 1e8 .. 1e11 away: o - T rounds at an ulp of the
 * distance (2^-20 .. 2^-16 there, up to 8 times the shape), so the local ray
 * passes the ellipsoid up to that far from where the world ray does.  The
 * image is then not the shape's, but the hit is held to the shape's padded
 * world box by the BVH's own slab test, so the walk with culling and the
 * exhaustive one agree.  Before, 6 (at 1e10) and 72 (1e11) pixels differed. */
START_TEST(test_shortcuts_far_camera_frame)
{
    const double far[] = {1e8, 1e9, 1e10, 1e11, 3e11};
    char text[1024];
    render_stats st_on, st_off;
    for (size_t j = 0; j < sizeof far / sizeof far[0]; j++) {
        img_buf img;
        snprintf(text, sizeof text,
                 "image { width 20 height 15 samples 1 max_depth 1 background 0.1 }\n"
                 "camera { orthographic eye [%.17g, 1e-7, 2e-7] look_at [0, 1e-7, 2e-7] up [0, 1, 0] width 6e-6 }\n"
                 "ambient { color 0.05 }\n"
                 "sphere { radius 1e-6 scale [1, 0.5, 1] rotate [80, 62, 0] material { Kd 0.77 } }\n",
                 -far[j]);
        image_both_ways(text, &st_on, &st_off, &img);
        img_free(&img);
    }
}
END_TEST

/* [BVH-CULL-PAD-1] A triangle 2 S across lying in a glass plane y = 0 (S =
 * 1e6 .. 1e12), glass or opaque, the eye 1.7 from the origin (attack 17,
 * finding 2): the transmitted rays start 2^-42 |P| under the triangle, whose
 * test's t is off by about S eps, so the exhaustive walk finds it crossed
 * at t of about 1e-8; its box, of no thickness in y, culled it.  Before,
 * 62 to 96 of the 432 pixels differed. */
START_TEST(test_shortcuts_flat_huge_triangle_in_plane)
{
    const char *const sizes[] = {"1e6", "1e8", "1e10", "1e12"};
    const char *const kinds[] = {"t 0.5 ior 1.3", "Ks 0.2"};
    char text[1024];
    render_stats st_on, st_off;
    for (size_t j = 0; j < sizeof sizes / sizeof sizes[0]; j++)
        for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++) {
            snprintf(text, sizeof text,
                     "image { width 24 height 18 max_depth 2 background [0.3, 0.5, 0.8] }\n"
                     "camera { perspective eye [1, 1, 1] look_at [0, 0, 0] up [0, 1, 0] fov 60 }\n"
                     "ambient { color 0.1 }\n"
                     "point_light { position [0.3, 4, 0.2] power 20 falloff none }\n"
                     "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd [0.7, 0.7, 0.6] t 0.5 ior 1.5 } }\n"
                     "triangle { vertices [-1, 0, -1] [1, 0, -1] [0, 0, 1] scale %s\n"
                     "           material { Kd [0.2, 0.5, 0.8] %s } }\n",
                     sizes[j], kinds[k]);
            same_both_ways(text, &st_on, &st_off);
        }
}
END_TEST

/* Every crossing of a ray, in the walk's order. */
typedef struct gather_crossings {
    int n;
    hit h[32];
} gather_crossings;

static int gather_collect(void *ctx, const hit *h)
{
    gather_crossings *c = ctx;
    if (c->n < 32)
        c->h[c->n++] = *h;
    return 0;
}

static int same_hit(const hit *a, const hit *b)
{
    return a->prim == b->prim && a->part == b->part && a->entering == b->entering &&
           same_real_bits(a->t, b->t) && same_vec_bits(a->point, b->point);
}

/*
 * [SHADE-SHORTCUT-GATHER-1] [SHADE-SHORTCUT-GATHER-2] Every crossing of r
 * taken as the hit being shaded: interface_gather with the shortcuts on
 * gathers the same crossings (prim, part, side, t and point to the bit),
 * in the same order, with the same product of t, as with them off.
 * Returns the count gathered for the first crossing of primitive self.
 */
static int gather_both_ways(const char *text, ray r, int self)
{
    scene_model *s = load(text);
    tracer on, off;
    ck_assert(tracer_init(&on, s, 0, 0));
    ck_assert(tracer_init(&off, s, 0, 0));
    tracer_no_shortcuts(&off);
    gather_crossings c;
    c.n = 0;
    bvh_visit(&off.accel, s->prims, &r, gather_collect, &c);
    int count = -1;
    for (int k = 0; k < c.n; k++) {
        interface a, b;
        trace_stats sa, sb;
        memset(&sa, 0, sizeof sa);
        memset(&sb, 0, sizeof sb);
        const scene_prim *p = &s->prims[c.h[k].prim];
        real m = isect_part_magnitude(p, c.h[k].part);
        interface_gather(&on, p, &c.h[k], m, &r, &a, &sa);
        interface_gather(&off, p, &c.h[k], m, &r, &b, &sb);
        ck_assert_msg(a.count == b.count, "crossing %d of prim %d: %d gathered against %d\n%s", k, c.h[k].prim,
                      a.count, b.count, text);
        ck_assert(same_real_bits(a.through, b.through));
        /* The spawn's magnitude kept beside it (interface_spawn) is its own. */
        ck_assert(same_real_bits(a.spawn_magnitude, isect_part_magnitude(a.spawn_prim, a.spawn_hit->part)));
        ck_assert(same_real_bits(b.spawn_magnitude, isect_part_magnitude(b.spawn_prim, b.spawn_hit->part)));
        for (int j = 0; j < a.count; j++)
            ck_assert_msg(same_hit(&a.h[j], &b.h[j]), "crossing %d: gathered hit %d differs\n%s", k, j, text);
        if (count < 0 && c.h[k].prim == self)
            count = a.count;
    }
    tracer_free(&on);
    tracer_free(&off);
    scene_free(s);
    return count;
}

/* The interface's reach for a hit on a primitive of magnitude m at a point
 * of magnitude at most m (interface.h: twice the spawn offset,
 * intersect.h's SPAWN_REL m + SPAWN_ABS). */
static double gather_reach(double m)
{
    return 2 * (0x1p-42 * m + 1e-300);
}

/*
 * [SHADE-SHORTCUT-GATHER-1] The walk's start, t_h - D, must lie before every
 * crossing within reach of the hit, however far along the ray it is.  A
 * glass block A (magnitude 1e6 + x0, so a reach of about 2^-41 of that) is
 * hit at P on its face x = x0; a glass ball B, 0.3 reach across, sits on
 * the ray before P, its crossings 0.875 and 0.625 reach (max norm) from P
 * and its box ending 0.6 reach before it; a second ball beside it, off the
 * ray, puts both in a leaf of their own (the tree keeps two parts in one
 * leaf), whose box the walk leaves out when it starts past it (near the
 * origin: at 1e7 the boxes' padding, 2^-40 of 1e7, passes P).  The gather of A's crossing must
 * hold both of B's (3 crossings), with the shortcuts as without, for
 * directions of length 1e-3, 1 and 1e3 (the start is in t: D |d|_max is a
 * distance), near the origin and at 1e7.  Fails with D = 0, with
 * D = reach / |d|_max / 2, and with D = reach (not divided by |d|_max).
 */
START_TEST(test_shortcuts_gather_finds_crossings_before_the_hit)
{
    const double scale[] = {1e-3, 1, 1e3}, offset[] = {0, 1e7};
    char text[1024];
    for (size_t i = 0; i < sizeof offset / sizeof offset[0]; i++)
        for (size_t j = 0; j < sizeof scale / sizeof scale[0]; j++) {
            double x0 = offset[i], reach = gather_reach(x0 + 1e6);
            vec3 u = vec_make(1, 0.6, 0.3), p = vec_make(x0, 0.5, 0.25);
            vec3 c = vec_sub(p, vec_scale(u, 0.75 * reach));
            snprintf(text, sizeof text,
                     "image { width 4 height 3 }\n"
                     "camera { perspective eye [%.17g, 0, -5] look_at [%.17g, 0, 0] up [0, 1, 0] fov 60 }\n"
                     "box { from [%.17g, -1e6, -1e6] to [%.17g, 1e6, 1e6] material { Kd 0 t 0.9 ior 1.5 } }\n"
                     "sphere { center [%.17g, %.17g, %.17g] radius %.17g material { Kd 0 t 0.8 ior 1.3 } }\n"
                     "sphere { center [%.17g, %.17g, %.17g] radius %.17g material { Kd 0 t 0.8 ior 1.3 } }\n",
                     x0 - 1, x0 - 1, x0, x0 + 1e6, (double)c.x, (double)c.y, (double)c.z, 0.15 * reach, (double)c.x,
                     (double)c.y, (double)(c.z + 0.5 * reach), 0.15 * reach);
            ray r = {vec_sub(p, vec_scale(u, 10)), vec_scale(u, scale[j]), 0, INFINITY};
            ck_assert_msg(gather_both_ways(text, r, 0) == 3, "offset %g, scale %g:\n%s", x0, scale[j], text);
        }
}
END_TEST

/* The touching glass of the tests below, its x moved by x0. */
static void touching_glass(char *out, size_t size, int k, double x0)
{
    switch (k) {
    case 0: /* two boxes sharing a face */
        snprintf(out, size,
                 "box { from [%.17g, -1, -1] to [%.17g, 1, 1] material { Kd 0 t 0.9 ior 1.5 } }\n"
                 "box { from [%.17g, -1, -1] to [%.17g, 1, 1] material { Kd 0 t 0.8 ior 1.3 } }\n",
                 x0 - 1, x0, x0, x0 + 1);
        break;
    case 1: /* two disks (sheets) lying on a box's face */
        snprintf(out, size,
                 "box { from [%.17g, -1, -1] to [%.17g, 1, 1] material { Kd 0 t 0.9 ior 1.5 } }\n"
                 "disk { center [%.17g, 0.1, 0] normal [1, 0, 0] radius 0.5 material { Kd 0 t 0.7 } }\n"
                 "disk { center [%.17g, -0.1, 0.05] normal [-1, 0, 0] radius 0.6 material { Kd 0 t 0.6 } }\n",
                 x0 - 1, x0, x0, x0);
        break;
    case 2: /* a ball touching a box */
        snprintf(out, size,
                 "box { from [%.17g, -1, -1] to [%.17g, 1, 1] material { Kd 0 t 0.9 ior 1.5 } }\n"
                 "sphere { center [%.17g, 0, 0] radius 0.5 material { Kd 0 Ks 0.2 t 0.8 ior 1.3 } }\n",
                 x0 - 1, x0, x0 + 0.5);
        break;
    case 3: /* an ellipsoid (a kept frame) touching a box */
        snprintf(out, size,
                 "box { from [%.17g, -1, -1] to [%.17g, 1, 1] material { Kd 0 t 0.9 ior 1.5 } }\n"
                 "sphere { radius 1 scale [0.5, 1, 0.7] rotate [0, 0, 30] rotate [0, 0, -30] "
                 "translate [%.17g, 0, 0] material { Kd 0 t 0.8 ior 1.3 } }\n",
                 x0 - 1, x0, x0 + 0.5);
        break;
    default: /* a ball inside a ball, apart, under a floor plane that touches the outer one */
        snprintf(out, size,
                 "sphere { center [%.17g, 0, 0] radius 1 material { Kd 0 Ks 0.1 t 0.9 ior 1.5 } }\n"
                 "sphere { center [%.17g, 0.45, 0.26] radius 0.3 material { Kd 0 t 1 ior 1 } }\n"
                 "plane { point [0, -1, 0] normal [0, 1, 0] material { Kd 0.8 } }\n",
                 x0 + 1, x0 + 1.3);
        break;
    }
}
enum { TOUCHING_GLASS = 5 };

/*
 * [SHADE-SHORTCUT-GATHER-1] [SHADE-SHORTCUT-GATHER-2] Touching glass
 * (touching_glass) crossed through the contact at x0 by a tilted ray of
 * length 1e-3, 1 and 1e3, near the origin and at 1e7: the gathers agree
 * with the shortcuts on and off, and the second primitive's first crossing
 * (at the contact, or for the nested balls the inner one's, apart) gathers
 * the surfaces there: the two boxes 2, the disks and the box 3, the ball or
 * ellipsoid and the box 2, the inner ball 1.  Fails with gather_alone
 * taking every hit on an eligible primitive as alone (the disks, the ball
 * and the ellipsoid lose the box's crossing).
 */
START_TEST(test_shortcuts_gather_touching_glass_both_ways)
{
    const int expect[TOUCHING_GLASS] = {2, 3, 2, 2, 1};
    const double scale[] = {1e-3, 1, 1e3}, offset[] = {0, 1e7};
    char shapes[768], text[1024];
    for (int k = 0; k < TOUCHING_GLASS; k++)
        for (size_t i = 0; i < sizeof offset / sizeof offset[0]; i++)
            for (size_t j = 0; j < sizeof scale / sizeof scale[0]; j++) {
                touching_glass(shapes, sizeof shapes, k, offset[i]);
                snprintf(text, sizeof text,
                         "image { width 4 height 3 }\n"
                         "camera { perspective eye [0, 0, -5] look_at [0, 0, 0] up [0, 1, 0] fov 60 }\n%s",
                         shapes);
                vec3 u = vec_make(1, 0.35, 0.2), p = vec_make(offset[i], 0, 0);
                ray r = {vec_sub(p, vec_scale(u, 3)), vec_scale(u, scale[j]), 0, INFINITY};
                int n = gather_both_ways(text, r, 1);
                ck_assert_msg(n == expect[k], "%d gathered, %d expected:\n%s", n, expect[k], text);
            }
}
END_TEST

/*
 * [SHADE-SHORTCUT-GATHER-2] A lone glass ball grazed.  Of radius 1e-3 at
 * x = 1e7 (an ulp there is 2^-29, the reach about 4.5e-6), rays one ulp
 * inside its tangent (along y, and tilted in the y-z plane) cross it along
 * a chord of 2 sqrt(2e-3 2^-29) = 3.9e-6, within reach: each crossing's
 * gather must hold the other (2), with the shortcuts as without.  A ray
 * through it a quarter of its radius from the centre gathers 1 (the other
 * crossing 1.9 radii away), and rays exactly tangent to a ball of radius
 * 1 at the origin gather the same both ways.  A ball smaller than the
 * reach, crossed far from tangent, gathers 2.  Fails with gather_self_apart
 * taking every sphere's other crossing as apart, and with its bound on the
 * radius dropped (the small ball).
 */
START_TEST(test_shortcuts_gather_grazed_ball)
{
    char text[512];
    const double x0s[] = {1e7, 0}, rads[] = {1e-3, 1};
    for (int k = 0; k < 2; k++) {
        double x0 = x0s[k], rad = rads[k], x = k ? x0 + rad : nextafter(x0 + rad, 0);
        snprintf(text, sizeof text,
                 "image { width 4 height 3 }\n"
                 "camera { perspective eye [0, 0, -5] look_at [0, 0, 0] up [0, 1, 0] fov 60 }\n"
                 "sphere { center [%.17g, 0, 0] radius %.17g material { Kd 0 t 0.9 ior 1.5 } }\n",
                 x0, rad);
        ray along = {vec_make(x, -5 * rad, 0), vec_make(0, 1, 0), 0, INFINITY};
        ray tilted = {vec_make(x, -3 * rad, -4 * rad), vec_make(0, 0.6, 0.8), 0, INFINITY};
        ray through = {vec_make(x0 + 0.25 * rad, -5 * rad, 0), vec_make(0, 1, 0), 0, INFINITY};
        int na = gather_both_ways(text, along, 0), nt = gather_both_ways(text, tilted, 0);
        ck_assert_msg(k ? na >= 1 && nt >= 1 : na == 2 && nt == 2, "%d, %d gathered:\n%s", na, nt, text);
        ck_assert_msg(gather_both_ways(text, through, 0) == 1, "through:\n%s", text);
    }
    /* Of radius 1e-6 at 1e7 the ball is smaller than the reach: a ray a
     * quarter radius off its centre crosses it along a chord of
     * 2 sqrt(1 - 1/16) 1e-6 = 1.9e-6, far from tangent, yet within reach. */
    snprintf(text, sizeof text,
             "image { width 4 height 3 }\n"
             "camera { perspective eye [0, 0, -5] look_at [0, 0, 0] up [0, 1, 0] fov 60 }\n"
             "sphere { center [1e7, 0, 0] radius 1e-6 material { Kd 0 t 0.9 ior 1.5 } }\n");
    ray small = {vec_make(1e7 + 0.25e-6, -5e-6, 0), vec_make(0, 1, 0), 0, INFINITY};
    ck_assert_msg(gather_both_ways(text, small, 0) == 2, "small:\n%s", text);
}
END_TEST

/*
 * [SHADE-SHORTCUT-GATHER-3] World-frame balls nested or apart by more than
 * their pads and 4 reach are no neighbours of each other: touching_glass's
 * nested balls (a gap of 0.1 between the shells, the floor touching the
 * outer one) keep the floor alone as the outer ball's neighbour and
 * nothing as the inner's.  A ball inside a ball with a gap of 0.3 reach
 * (max norm) at their contact, and one outside it at the same gap, stay
 * neighbours: the gather of the inner (or outer) ball's crossing there
 * holds the other's, 2, with the shortcuts as without.  The first part
 * fails without the step (2 and 1 neighbours); the second with the slack
 * dropped (0.3 reach > 0: the pairs taken as apart, 1 gathered against 2)
 * and with the nested gap taken as R - D + r.
 */
START_TEST(test_shortcuts_gather_spheres_apart)
{
    char shapes[768], text[1024];
    touching_glass(shapes, sizeof shapes, 4, 0);
    snprintf(text, sizeof text,
             "image { width 4 height 3 }\n"
             "camera { perspective eye [0, 0, -5] look_at [0, 0, 0] up [0, 1, 0] fov 60 }\n%s",
             shapes);
    scene_model *s = load(text);
    tracer on;
    ck_assert(tracer_init(&on, s, 0, 0));
    ck_assert_int_eq(on.gather_span[2 * 0 + 1], 1);
    ck_assert_int_eq(on.gather_span[2 * 1 + 1], 0);
    tracer_free(&on);
    scene_free(s);
    /* The contact on the x axis at x = 1 (the outer ball of radius 1 at
     * the origin), the other ball's surface 0.3 reach beyond it, inside
     * (radius 0.5) or outside (radius 0.25); the ray along x, its first
     * crossing of the other ball the one at the contact. */
    const double other[2] = {0.5, 0.25};
    for (int k = 0; k < 2; k++) {
        double gap = 0.3 * gather_reach(2), x = k ? 1 + gap + other[k] : 1 - gap - other[k];
        snprintf(text, sizeof text,
                 "image { width 4 height 3 }\n"
                 "camera { perspective eye [0, 0, -5] look_at [0, 0, 0] up [0, 1, 0] fov 60 }\n"
                 "sphere { center [0, 0, 0] radius 1 material { Kd 0 Ks 0.1 t 0.9 ior 1.5 } }\n"
                 "sphere { center [%.17g, 0, 0] radius %.17g material { Kd 0 t 0.8 ior 1.3 } }\n",
                 x, other[k]);
        ray r = {vec_make(k ? -3 : 3, 0, 0), vec_make(k ? 1 : -1, 0, 0), 0, INFINITY};
        int n = gather_both_ways(text, r, 1);
        ck_assert_msg(n == 2, "%d gathered, 2 expected:\n%s", n, text);
    }
}
END_TEST

/*
 * [SHADE-SHORTCUT-GATHER-2] [SHADE-SHORTCUT-GATHER-3] Cameras 1e10 and 7e12
 * away at the limb of two nearly concentric glass balls (attack 25g,
 * far_graze.scene and gather3_eligible.scene, the second with nine balls
 * nested inside, which GATHER-3 leaves out of the lists): sphere_refine's
 * second solve misses both balls, both crossings stay at o + t d, off both
 * shells by its rounding, more than the alone test's pads.  The full walk
 * takes both crossings; so must the shortcuts (gather_alone.c origin_near sends
 * such a ray to the walk).  Fails with the guard dropped (90 of 3072
 * pixels of the first differ).  And a world-frame ball with a mirrored
 * twin (scale [-1, 1, 1] keeps its frame) whose local centre is 6 away:
 * their shells coincide, so GATHER-3 must not compare the local centre
 * (fails with spheres_apart's frame test dropped).
 */
START_TEST(test_shortcuts_gather_far_graze)
{
    static const char *const scenes[] = {
        "image { width 64 height 48 max_depth 4 background [0.3, 0.5, 0.8] }\n"
        "camera { orthographic width 7.9345703155517583e-06 eye [4504465049.7796335, -7332510264.9271793, "
        "6074904655.1140699] look_at [-0.00080324987406165348, 0, 0.00059559963314085467] up "
        "[-0.80327024397708946, 0, 0.5956147371757915] }\n"
        "ambient { color 0.1 }\n"
        "point_light { position [3, 6, 4] power 40 }\n"
        "sphere { center [0, 0, 0] radius 0.001 material { Kd 0 Ks 0.05 n 30 t 0.95 ior 1.5 } }\n"
        "sphere { center [0, 0, 0] radius 0.00099998474121055603 material { Kd 0 Ks 0.1 n 30 t 0.9 ior 2.4 } }\n",
        "image { width 96 height 96 max_depth 6 background [0.3, 0.5, 0.8] }\n"
        "camera { orthographic width 0.00390625 eye [7020318761497.3623, 6502238695131.5713, "
        "5648572538006.8447] look_at [-0.62587116535642351, 0, 0.77786291224354476] up "
        "[-0.62687955178729982, 0, 0.7791161836022622] }\n"
        "ambient { color 0.1 }\n"
        "point_light { position [3, 6, 4] power 40 }\n"
        "sphere { center [0, 0, 0] radius 1 material { Kd 0 Ks 0.05 n 30 t 0.95 ior 1.5 } }\n"
        "sphere { center [1.4305115103721619e-06, 0, 0] radius 0.99999284744244821 "
        "material { Kd 0 Ks 0.1 n 30 t 0.9 ior 2.4 } }\n"
        "sphere { center [0, 0, 0] radius 0.49999713897697928 material { Kd 0.5 Ks 0 n 30 } }\n"
        "sphere { center [-0.3, -0.3, 0] radius 0.1 material { Kd 0.5 Ks 0.2 n 30 } }\n"
        "sphere { center [0, -0.3, 0] radius 0.1 material { Kd 0.5 Ks 0.2 n 30 t 0.5 ior 1.2 } }\n"
        "sphere { center [0.3, -0.3, 0] radius 0.1 material { Kd 0.5 Ks 0.2 n 30 } }\n"
        "sphere { center [-0.3, 0, 0] radius 0.1 material { Kd 0.5 Ks 0.2 n 30 t 0.5 ior 1.2 } }\n"
        "sphere { center [0, 0, 0] radius 0.1 material { Kd 0.5 Ks 0.2 n 30 } }\n"
        "sphere { center [0.3, 0, 0] radius 0.1 material { Kd 0.5 Ks 0.2 n 30 t 0.5 ior 1.2 } }\n"
        "sphere { center [-0.3, 0.3, 0] radius 0.1 material { Kd 0.5 Ks 0.2 n 30 } }\n"
        "sphere { center [0, 0.3, 0] radius 0.1 material { Kd 0.5 Ks 0.2 n 30 t 0.5 ior 1.2 } }\n"
        "sphere { center [0.3, 0.3, 0] radius 0.1 material { Kd 0.5 Ks 0.2 n 30 } }\n",
        "image { width 48 height 32 max_depth 4 background [0.2, 0.25, 0.35] }\n"
        "camera { perspective eye [-3, 1.5, 5] look_at [-3, 0, 0] up [0, 1, 0] fov 40 }\n"
        "ambient { color 0.15 }\n"
        "point_light { position [3, 6, 4] power 40 d0 1 }\n"
        "plane { point [0, -1, 0] normal [0, 1, 0] material { Kd 0.8 } }\n"
        "sphere { center [-3, 0, 0] radius 1 material { Kd 0 Ks 0.05 n 300 t 0.95 ior 1.5 } }\n"
        "sphere { center [3, 0, 0] radius 1 material { Kd 0 Ks 0.05 n 300 t 0.9 ior 1.3 } scale [-1, 1, 1] }\n"
        "sphere { center [-3, 0, 0] radius 0.5 material { Kd 0 Ks 0.05 n 300 t 0.9 ior 1.9 } }\n"};
    for (size_t k = 0; k < sizeof scenes / sizeof scenes[0]; k++) {
        render_stats on, off;
        same_both_ways(scenes[k], &on, &off);
    }
}
END_TEST

/* [SHADE-SHORTCUT-GATHER-1] [SHADE-SHORTCUT-GATHER-2] The touching glass
 * above rendered, near the origin and at 1e7: the same bits with the
 * shortcuts on and off, and fewer primitive tests with them on. */
START_TEST(test_shortcuts_gather_images_both_ways)
{
    const double offset[] = {0, 1e7};
    char shapes[768], text[2048];
    for (int k = 0; k < TOUCHING_GLASS; k++)
        for (size_t i = 0; i < sizeof offset / sizeof offset[0]; i++) {
            render_stats on, off;
            touching_glass(shapes, sizeof shapes, k, offset[i]);
            snprintf(text, sizeof text,
                     "image { width 24 height 18 samples 1 max_depth 8 background [0.2, 0.3, 0.4] }\n"
                     "camera { perspective eye [%.17g, 0.7, 4] look_at [%.17g, 0, 0] up [0, 1, 0] fov 50 }\n"
                     "point_light { position [3, 5, 4] power 30 }\n"
                     "ambient { color 0.1 }\n%s",
                     offset[i] + 0.4, offset[i], shapes);
            same_both_ways(text, &on, &off);
            ck_assert_msg(on.trace.bvh.prims_tested < off.trace.bvh.prims_tested, "%s", text);
        }
}
END_TEST

START_TEST(test_shortcuts_random_scenes_bit_identical)
{
    for (int k = 0; k < RANDOM_BATCH; k++)
        check_random_scene(_i * RANDOM_BATCH + k);
}
END_TEST

/* The random scenes far away, tiny and huge: the bounds behind the
 * shortcuts (the light's ball, the BVH boxes, the blocker's test) are
 * relative to the coordinates' size, and an outside attack found images
 * that changed at such magnitudes. */
START_TEST(test_shortcuts_placed_random_scenes_bit_identical)
{
    for (int k = 0; k < PLACED_BATCH; k++)
        check_placed_scene(1000 + _i * PLACED_BATCH + k, _i % (int)(sizeof placements / sizeof placements[0]));
}
END_TEST

/*
 * [SHADE-SHORTCUT-PLANE-1] A bundle that keeps no node answers 1 without a
 * walk only where it passes every plane: a ceiling between the floor and a
 * rectangle light, a ball off to the side (so the tree has a node the
 * floor's bundles keep none of).  Every floor point's bundle crosses the
 * ceiling: the floor stays dark (ambient alone) with the shortcuts on, as
 * off.  Attack 24 found no test failing with the planes ignored.
 */
START_TEST(test_shortcuts_plane_between_floor_and_light)
{
    const char *text = "image { width 24 height 18 samples 1 }\n"
                       "camera { perspective eye [0, 1, 6] look_at [0, 0, 0] up [0, 1, 0] fov 60 }\n"
                       "ambient { color 0.05 }\n"
                       "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0.8 } }\n"
                       "plane { point [0, 2, 0] normal [0, -1, 0] material { Kd 0.5 } }\n"
                       "sphere { center [3, 1, -3] radius 0.3 material { Kd 0.5 } }\n"
                       "distributed_light { rectangle [-0.5, 3, -0.5] [1, 0, 0] [0, 0, 1] power 40 samples 4 }\n";
    render_stats on, off;
    img_buf img;
    image_both_ways(text, &on, &off, &img);
    /* The bottom row sees the floor: ambient 0.05 times Kd 0.8, no light. */
    const double *px = img.rgb + 3 * (size_t)(img.width * (img.height - 1) + img.width / 2);
    ck_assert_msg(px[0] == 0.05 * 0.8, "the floor under the ceiling is %.17g, not ambient alone", px[0]);
    ck_assert(on.trace.shadow_rays > 0);
    img_free(&img);
}
END_TEST

/*
 * [SHADE-SHORTCUT-HIDDEN-1] A light with no bound runs the loop: a Kd 0
 * mirror over a background of DBL_MAX (the mirrored colour saturates the
 * point's colour whatever the highlight), seen by one orthographic ray
 * that hits the origin, where a point light sits.  The sample on the
 * surface is counted as with the shortcuts off (attack 24h, finding 1: a
 * bound clamped to DBL_MAX left the loop out and the count at 0).
 */
START_TEST(test_shortcuts_hidden_runs_the_loop_without_a_bound)
{
    const char *text =
        "image { width 1 height 1 max_depth 2 background [1.7976931348623157e308, 1.7976931348623157e308, "
        "1.7976931348623157e308] }\n"
        "camera { orthographic eye [0, 5, 0] look_at [0, 0, 0] up [0, 0, -1] width 2 }\n"
        "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0 Ks 1 n 30 } }\n"
        "sphere { center [-5, 0.5, -8] radius 0.3 material { Kd 0.5 } }\n"
        "point_light { position [0, 0, 0] power 1 }\n";
    render_stats on, off;
    same_both_ways(text, &on, &off);
    ck_assert_int_eq(off.trace.lights_on_surface, 1);
    ck_assert_int_eq(on.trace.lights_on_surface, off.trace.lights_on_surface);
    ck_assert_int_eq(on.trace.light_samples, off.trace.light_samples);
}
END_TEST

/*
 * [SHADE-SHORTCUT-HIDDEN-1] The intensity bound is the falloff at the
 * ball's nearest point: a Kd 0, Ks 1, n 1 mirror floor over a white
 * background, under lights just above it whose power puts the highlight
 * near one ulp of the colour (inverse-square falloff, a disk of radius 1
 * 0.01 above the floor, a 4 x 0.001 rectangle 0.02 above it).  Compared in
 * double; attack 24h found the falloff taken at the ball's far side
 * caught by these alone (farside_probe.sh).
 */
START_TEST(test_shortcuts_hidden_intensity_at_the_nearest_point)
{
    static const char *const lights[] = {
        "disk [0, 0.01, -0.5] [0, -1, 0] 1 power 1e-17 samples 16 falloff inverse_square",
        "disk [0, 0.01, -0.5] [0, -1, 0] 1 power 1.8e-17 samples 16 falloff inverse_square",
        "disk [0, 0.01, -0.5] [0, -1, 0] 1 power 3.2e-17 samples 16 falloff inverse_square",
        "rectangle [-2, 0.02, -0.5] [4, 0, 0] [0, 0, 0.001] power 1.8e-16 samples 16 falloff inverse_square",
    };
    long hidden = 0;
    for (size_t i = 0; i < sizeof lights / sizeof lights[0]; i++) {
        char text[1024];
        int n = snprintf(text, sizeof text,
                         "image { width 32 height 24 max_depth 2 background [1, 1, 1] }\n"
                         "camera { perspective eye [0, 1.5, 3] look_at [0, 0, -0.5] up [0, 1, 0] fov 60 }\n"
                         "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0 Ks 1 n 1 t 0 } }\n"
                         "sphere { center [-5, 0.5, -8] radius 0.3 material { Kd 0.5 } }\n"
                         "distributed_light { %s }\n",
                         lights[i]);
        ck_assert(n > 0 && n < (int)sizeof text);
        render_stats on, off;
        same_both_ways(text, &on, &off);
        hidden += on.trace.hidden_highlights;
    }
    ck_assert_msg(hidden > 0, "no light loop left out: the test has no teeth");
}
END_TEST

Suite *suite_shortcuts(void)
{
    Suite *s = suite_create("shortcuts");
    TCase *tc = tcase_create("shortcuts");
    tcase_set_timeout(tc, 20);
    tcase_add_test(tc, test_shortcuts_camera_inside_opaque_sphere_is_dark);
    tcase_add_test(tc, test_shortcuts_lone_glass_sphere_shadows_itself);
    tcase_add_test(tc, test_shortcuts_off_does_all_the_work);
    tcase_add_test(tc, test_shortcuts_lobe_floor_once_a_material);
    tcase_add_test(tc, test_shortcuts_material_terms_once_a_material);
    tcase_add_test(tc, test_shortcuts_tir_traced_once_as_the_mirror_ray);
    tcase_add_test(tc, test_shortcuts_bvh_exhaustive_tests_everything);
    tcase_add_test(tc, test_shortcuts_cli_no_shortcuts);
    tcase_add_test(tc, test_shortcuts_blocker_tried_first);
    tcase_add_test(tc, test_shortcuts_open_ray_clears_the_blocker);
    tcase_add_test(tc, test_shortcuts_mirror_hit_keeps_its_own_blocker);
    tcase_add_test(tc, test_shortcuts_any_walk_only_with_plus_zero);
    tcase_add_test(tc, test_shortcuts_lobe_gate_on_glass);
    tcase_add_test(tc, test_shortcuts_dark_light_ball_holds_samples);
    tcase_add_test(tc, test_shortcuts_dark_cell_ball_holds_samples);
    tcase_add_test(tc, test_shortcuts_dark_lights_both_ways);
    tcase_add_test(tc, test_shortcuts_dark_light_subnormal_distance);
    tcase_add_test(tc, test_shortcuts_lobe_above_bounds_lobe);
    tcase_add_test(tc, test_shortcuts_absorbed_highlights_both_ways);
    tcase_add_test(tc, test_shortcuts_ball_cosine_above_holds);
    tcase_add_test(tc, test_shortcuts_hidden_highlights_both_ways);
    tcase_add_test(tc, test_shortcuts_hidden_runs_the_loop_without_a_bound);
    tcase_add_test(tc, test_shortcuts_hidden_intensity_at_the_nearest_point);
    tcase_add_test(tc, test_shortcuts_off_weightless_ray_overflow_not_refused);
    tcase_add_test(tc, test_shortcuts_full_stack_weightless_crossing_not_refused);
    tcase_add_test(tc, test_shortcuts_far_tiny_frame);
    tcase_add_test(tc, test_shortcuts_far_camera_frame);
    tcase_add_test(tc, test_shortcuts_flat_huge_triangle_in_plane);
    tcase_add_test(tc, test_shortcuts_gather_finds_crossings_before_the_hit);
    tcase_add_test(tc, test_shortcuts_gather_touching_glass_both_ways);
    tcase_add_test(tc, test_shortcuts_gather_images_both_ways);
    tcase_add_test(tc, test_shortcuts_gather_grazed_ball);
    tcase_add_test(tc, test_shortcuts_gather_spheres_apart);
    tcase_add_test(tc, test_shortcuts_gather_far_graze);
    tcase_add_loop_test(tc, test_shortcuts_random_scenes_bit_identical, 0, RANDOM_BATCHES);
    tcase_add_loop_test(tc, test_shortcuts_placed_random_scenes_bit_identical, 0, 8);
    tcase_add_test(tc, test_shortcuts_camera_inside_opaque_mesh_is_dark);
    tcase_add_test(tc, test_shortcuts_plane_between_floor_and_light);
    tcase_add_loop_test(tc, test_shortcuts_mesh_scenes_bit_identical, 0,
                        (int)(sizeof mesh_scenes / sizeof mesh_scenes[0]));
    suite_add_tcase(s, tc);
    return s;
}
