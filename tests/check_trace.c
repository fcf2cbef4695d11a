/*
 * End-to-end tests of the tracer: tiny scenes whose pixel values are
 * derived by hand from the seed's formulas (spec/shading.md), written out
 * above each expectation.  The derivations use plain geometry, not the
 * tracer's helper functions.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include "testlib.h"
#include "render/render.h"
#include "io/scene_file.h"
#include "scene/scene.h"
#include "render/interface.h"
#include "render/medium.h"
#include "render/trace.h"

static scene_model *load(const char *text)
{
    int status;
    scene_model *s = scene_file_load_text("test.scene", text, strlen(text), NULL, stderr, 0, &status);
    ck_assert_msg(s != NULL, "scene did not load (status %d):\n%s", status, text);
    return s;
}

/* The colour of pixel (i, j) of the scene as rendered. */
static rgb pixel(const scene_model *s, int i, int j, trace_stats *st)
{
    tracer t;
    trace_stats local;
    memset(&local, 0, sizeof local);
    ck_assert(tracer_init(&t, s, 0, 0));
    rgb c = render_pixel(&t, s->image.width, s->image.height, s->image.samples, i, j, st ? st : &local);
    tracer_free(&t);
    return c;
}

/* An orthographic camera looking straight down -y at the plane y = 0: the
 * centre pixel of a 1x1 image hits the origin with N = V = +y. */
#define CAMERA_DOWN "camera { orthographic eye [0, 10, 0] look_at [0, 0, 0] up [0, 0, 1] width 1 }\n"
#define LOOK_DOWN "image { width 1 height 1 background 0 }\n" CAMERA_DOWN
#define LOOK_DOWN_DEPTH1 "image { width 1 height 1 background 0 max_depth 1 }\n" CAMERA_DOWN

START_TEST(test_trace_ambient_only_is_kd_times_ia)
{
    /* [SHADE-AMB-1] R_a = Kd * Ia channel-wise, no lights: 0.5*0.2, 0.25*0.4, 1*0.1. */
    scene_model *s = load(LOOK_DOWN "ambient { color [0.2, 0.4, 0.1] }\n"
                                 "plane { material { Kd [0.5, 0.25, 1] } }\n");
    ck_assert_vec_near(pixel(s, 0, 0, NULL), vec_make(0.1, 0.1, 0.1), 1e-15);
    scene_free(s);
}
END_TEST

START_TEST(test_trace_background_when_nothing_is_hit)
{
    scene_model *s = load("image { width 3 height 3 background [0.1, 0.2, 0.3] }\n"
                       "sphere { center [100, 0, 0] radius 1 }\n");
    ck_assert_vec_near(pixel(s, 1, 1, NULL), vec_make(0.1, 0.2, 0.3), 0);
    scene_free(s);
}
END_TEST

START_TEST(test_trace_distant_light_lambert)
{
    /* Light travels along (1, -1, 0)/sqrt2, so L = (-1, 1, 0)/sqrt2 and
     * N.L = cos 45 = 1/sqrt2.  Pixel = Kd*E*N.L = 0.6 * 2 / sqrt2. */
    scene_model *s = load(LOOK_DOWN "distant_light { direction [1, -1, 0] power 2 }\n"
                                 "plane { material { Kd 0.6 } }\n");
    double want = 0.6 * 2 / sqrt(2.0);
    ck_assert_vec_near(pixel(s, 0, 0, NULL), vec_splat(want), 1e-15);
    scene_free(s);
}
END_TEST

START_TEST(test_trace_point_light_falloffs)
{
    /* Light at (0, 3, 4): d = 5, N.L = 3/5.  linear: E/(d+d0) = 10/(5+1);
     * inverse_square: 10/36; none: 10.  Pixel = Kd * I * 3/5 with Kd 0.5. */
    const char *falloff[] = {"linear", "inverse_square", "none"};
    double intensity[] = {10.0 / 6.0, 10.0 / 36.0, 10.0};
    for (int k = 0; k < 3; k++) {
        char text[512];
        snprintf(text, sizeof text,
                 LOOK_DOWN "point_light { position [0, 3, 4] power 10 d0 1 falloff %s }\n"
                           "plane { material { Kd 0.5 } }\n", falloff[k]);
        scene_model *s = load(text);
        ck_assert_vec_near(pixel(s, 0, 0, NULL), vec_splat(0.5 * intensity[k] * 0.6), 1e-14);
        scene_free(s);
    }
}
END_TEST

START_TEST(test_trace_light_a_subnormal_distance_away)
{
    /* [SHADE-DIFFUSE-1] A light 1e-310 above the hit point (the origin):
     * L = (0, 1, 0), N.L = 1, falloff none, so the pixel is Kd * E = 0.5.
     * L must not be formed as to * (1/d): 1/d overflows for d < 2^-1024,
     * and that L (Inf and NaN) dropped the light (shade_diffuse's
     * precondition: L finite). */
    const char *where[] = {"[0, 1e-310, 0]", "[0, 5e-324, 0]", "[0, 1e-300, 0]"};
    for (int k = 0; k < 3; k++) {
        char text[512];
        snprintf(text, sizeof text, LOOK_DOWN "point_light { position %s power 1 falloff none }\n"
                                              "plane { material { Kd 0.5 } }\n", where[k]);
        scene_model *s = load(text);
        ck_assert_vec_near(pixel(s, 0, 0, NULL), vec_splat(0.5), 1e-15);   /* L to rounding */
        scene_free(s);
    }
}
END_TEST

START_TEST(test_trace_light_below_the_horizon_adds_nothing)
{
    /* The light is under the plane: N.L < 0 on the side the camera sees. */
    scene_model *s = load(LOOK_DOWN "point_light { position [0, -3, 0] power 10 }\n"
                                 "plane { material { Kd 0.5 } }\n");
    ck_assert_vec_near(pixel(s, 0, 0, NULL), vec_splat(0), 0);
    scene_free(s);
}
END_TEST

START_TEST(test_trace_phong_highlight_at_the_mirror_direction)
{
    /* Camera straight above at V = +y; a light straight above too gives
     * R = 2(N.L)N - L = +y = V: the lobe is 1.  With the light at height 4,
     * d = 4, d0 = 0, linear: I = 8/4 = 2.  Pixel = Kd*I*1 + Ks*I*1^n
     * = 0.25*2 + 0.5*2 = 1.5.  (The camera at height 10 does not block: the
     * camera is not an object.) */
    scene_model *s = load(LOOK_DOWN_DEPTH1 "point_light { position [0, 4, 0] power 8 }\n"
                                        "plane { material { Kd 0.25 Ks 0.5 n 50 } }\n");
    ck_assert_vec_near(pixel(s, 0, 0, NULL), vec_splat(1.5), 1e-14);
    scene_free(s);
}
END_TEST

START_TEST(test_trace_opaque_occluder_casts_a_shadow)
{
    /* A sphere at height 2 stands between the origin and the light at
     * height 4.  A narrow camera from the side (which does not pass the
     * sphere) sees the origin: only ambient is left, Kd*Ia = 0.5*0.1. */
    scene_model *s = load("image { width 1 height 1 }\n"
                       "camera { perspective eye [0, 1, 5] look_at [0, 0, 0] fov 10 }\n"
                       "ambient { color 0.1 }\n"
                       "point_light { position [0, 4, 0] power 8 }\n"
                       "plane { material { Kd 0.5 } }\n"
                       "sphere { center [0, 2, 0] radius 0.5 material { Kd 1 } }\n");
    ck_assert_vec_near(pixel(s, 0, 0, NULL), vec_splat(0.05), 1e-15);
    scene_free(s);
}
END_TEST

START_TEST(test_trace_transparent_occluder_lets_t_squared_through)
{
    /* The same, but the sphere has t = 0.5: the shadow ray crosses its
     * surface twice, so 0.5^2 = 0.25 of the light arrives (slide 47).  At the
     * origin: d = 4, I = 8/4 = 2, N.L = 1; pixel = 0.5*0.1 + 0.5*2*0.25. */
    scene_model *s = load("image { width 1 height 1 }\n"
                       "camera { perspective eye [0, 1, 5] look_at [0, 0, 0] fov 10 }\n"
                       "ambient { color 0.1 }\n"
                       "point_light { position [0, 4, 0] power 8 }\n"
                       "plane { material { Kd 0.5 } }\n"
                       "sphere { center [0, 2, 0] radius 0.5 material { Kd 1 t 0.5 } }\n");
    ck_assert_vec_near(pixel(s, 0, 0, NULL), vec_splat(0.05 + 0.5 * 2 * 0.25), 1e-14);
    scene_free(s);
}
END_TEST

START_TEST(test_trace_mirror_reflects_with_weight_ks)
{
    /* Camera looks down at a mirror plane y = 0 (Kd 0, Ks 0.5); the mirror
     * ray goes straight up and hits a plane y = 20 facing down whose colour
     * is its ambient Kd*Ia = 0.8*0.5 = 0.4.  The camera sits at y = 10, below
     * that plane.  Pixel = Ks * 0.4 = 0.2 (the mirror's own Kd is 0). */
    scene_model *s = load(LOOK_DOWN "ambient { color 0.5 }\n"
                                 "plane { material { Kd 0 Ks 0.5 } }\n"
                                 "plane { point [0, 20, 0] normal [0, -1, 0] material { Kd 0.8 } }\n");
    ck_assert_vec_near(pixel(s, 0, 0, NULL), vec_splat(0.2), 1e-15);
    scene_free(s);
}
END_TEST

START_TEST(test_trace_max_depth_one_keeps_the_local_colour)
{
    /* max_depth 1: no mirror ray; only Kd*Ia of the mirror's Kd 0.2 is left:
     * 0.2 * 0.5 = 0.1 (slide 48: the pseudocode keeps the local colour). */
    scene_model *s = load(LOOK_DOWN_DEPTH1 "ambient { color 0.5 }\n"
                                 "plane { material { Kd 0.2 Ks 0.5 } }\n"
                                 "plane { point [0, 20, 0] normal [0, -1, 0] material { Kd 0.8 } }\n");
    ck_assert_vec_near(pixel(s, 0, 0, NULL), vec_splat(0.1), 1e-15);
    scene_free(s);
}
END_TEST

START_TEST(test_trace_transparent_sheet_blends_front_and_back)
{
    /* A sheet at y = 1 with Kd 0.6, t 0.25 over an opaque floor with Kd 0.4,
     * ambient 1: front = 0.6, back = 0.4, pixel = (1-t)*front + t*back
     * = 0.75*0.6 + 0.25*0.4 = 0.55 (slide 37 with t = transparency). */
    scene_model *s = load(LOOK_DOWN "ambient { color 1 }\n"
                                 "plane { material { Kd 0.4 } }\n"
                                 "disk { center [0, 1, 0] radius 5 material { Kd 0.6 t 0.25 } }\n");
    ck_assert_vec_near(pixel(s, 0, 0, NULL), vec_splat(0.55), 1e-15);
    scene_free(s);
}
END_TEST

START_TEST(test_trace_ior_one_glass_passes_rays_straight)
{
    /* A clear sphere of ior 1 in front of a floor: the ray crosses it
     * unbent (bit for bit) and t=1 passes everything: the pixel is the
     * floor's ambient colour exactly, 0.3*1. */
    scene_model *s = load(LOOK_DOWN "ambient { color 1 }\n"
                                 "plane { material { Kd 0.3 } }\n"
                                 "sphere { center [0, 3, 0] radius 1 material { Kd 0 t 1 ior 1 } }\n");
    ck_assert_vec_near(pixel(s, 0, 0, NULL), vec_splat(0.3), 0);
    scene_free(s);
}
END_TEST

START_TEST(test_trace_glass_sphere_on_axis_is_not_bent)
{
    /* On the axis of a glass sphere the ray meets both surfaces at normal
     * incidence: Snell leaves it straight, so it reaches the floor's origin.
     * Weights: t at entry and t at exit: pixel = t^2 * 0.3 with t = 0.8,
     * plus nothing else (Kd 0, Ks 0). */
    scene_model *s = load(LOOK_DOWN "ambient { color 1 }\n"
                                 "plane { material { Kd 0.3 } }\n"
                                 "sphere { center [0, 3, 0] radius 1 material { Kd 0 t 0.8 ior 1.5 } }\n");
    ck_assert_vec_near(pixel(s, 0, 0, NULL), vec_splat(0.64 * 0.3), 1e-15);
    scene_free(s);
}
END_TEST

START_TEST(test_trace_distributed_light_sums_its_samples)
{
    /* A rectangle light of 4 samples (2x2 grid), every sample straight above
     * at height h with small jitter: with falloff none each sample gives
     * E/4 * N.L.  A tiny rectangle (1e-9 wide) makes N.L = 1 to 1e-18, so the
     * pixel is Kd*E = 0.5*3. */
    scene_model *s = load(LOOK_DOWN "distributed_light { rectangle [0, 5, 0] [1e-9, 0, 0] [0, 0, 1e-9] "
                                 "power 3 samples 4 falloff none }\n"
                                 "plane { material { Kd 0.5 } }\n");
    trace_stats st;
    memset(&st, 0, sizeof st);
    ck_assert_vec_near(pixel(s, 0, 0, &st), vec_splat(1.5), 1e-14);
    ck_assert_int_eq(st.light_samples, 4);
    scene_free(s);
}
END_TEST

START_TEST(test_trace_renders_are_bit_identical)
{
    scene_model *s = load("image { width 16 height 12 samples 2 max_depth 4 }\n"
                       "ambient { color 0.1 }\n"
                       "distributed_light { disk [0, 4, 0] [0, -1, 0] 1 power 5 samples 9 }\n"
                       "plane { point [0, -1, 0] material { Kd 0.7 Ks 0.2 } }\n"
                       "sphere { material { Kd 0.1 Ks 0.1 t 0.8 ior 1.4 } }\n");
    img_buf a, b;
    ck_assert_int_eq(render_image(s, NULL, &a, NULL), 0);
    ck_assert_int_eq(render_image(s, NULL, &b, NULL), 0);
    ck_assert(memcmp(a.rgb, b.rgb, sizeof(double) * 3 * 16 * 12) == 0);
    img_free(&a);
    img_free(&b);
    scene_free(s);
}
END_TEST

START_TEST(test_trace_diffuse_scene_skips_passes)
{
    /* One diffuse disk, one point light: nothing can occlude (a ray that
     * leaves a flat primitive never meets it again), no Ks, no t. */
    scene_model *s = load("image { width 8 height 8 }\n"
                          "point_light { position [0, 5, 5] power 10 }\n"
                          "disk { normal [0, 0, 1] radius 3 material { Kd 0.5 } }\n");
    img_buf img;
    render_stats st;
    ck_assert_int_eq(render_image(s, NULL, &img, &st), 0);
    ck_assert_int_eq(st.shadows, 0);
    ck_assert_int_eq(st.specular, 0);
    ck_assert_int_eq(st.reflection, 0);
    ck_assert_int_eq(st.refraction, 0);
    ck_assert_int_eq(st.trace.shadow_rays, 0);
    ck_assert_int_eq(st.trace.reflection_rays + st.trace.refraction_rays, 0);
    ck_assert_int_eq(st.trace.camera_rays, 64);
    img_free(&img);
    scene_free(s);
}
END_TEST

static int stop_after_two_rows(void *ctx, int done, int total)
{
    (void)ctx;
    (void)total;
    return done >= 2;
}

START_TEST(test_render_image_stops_when_asked)
{
    scene_model *s = load("image { width 4 height 4 }\nsphere { }\n");
    render_opts o;
    memset(&o, 0, sizeof o);
    o.progress = stop_after_two_rows;
    img_buf img = {0};
    ck_assert_int_eq(render_image(s, &o, &img, NULL), STATUS_CANCELLED);
    ck_assert_ptr_null(img.rgb);
    scene_free(s);
}
END_TEST

START_TEST(test_render_image_refuses_an_exploding_ray_tree)
{
    /* Glass that is both a full mirror and fully clear (Ks 1, t 1) inside a
     * mirror box doubles its rays at every bounce: 2^1000 rays at depth
     * 1000.  The budget stops it at once and voids the render. */
    scene_model *s = load("image { width 2 height 2 max_depth 1000 }\n"
                       "camera { eye [0, 0, 5] fov 10 }\n"
                       "material g { Kd 0 Ks 1 t 1 ior 1.5 }\n"
                       "sphere { radius 1 material g }\n"
                       "box { from [-10, -10, -10] to [10, 10, 10] material { Kd 0 Ks 1 } }\n");
    render_opts o;
    memset(&o, 0, sizeof o);
    o.max_tree_rays = 10000;
    img_buf img = {0};
    render_stats st;
    ck_assert_int_eq(render_image(s, &o, &img, &st), STATUS_DATA);
    ck_assert_ptr_null(img.rgb);
    ck_assert(st.trace.tree_overflow);
    ck_assert(st.trace.tree_rays <= 10001);
    scene_free(s);
}
END_TEST

/* [REL-STACK-1] The recursion's stack at the ceiling of max_depth (1000):
 * a chain of 1000 mirror bounces and one of 999 total internal reflections
 * render on a stack limited to 2 MiB, a common thread's default (8 MiB
 * under AddressSanitizer, whose redzones widen every frame: the main
 * stack's default).  Before the interface's hits and the BVH walk's stack
 * left the recursion's frame, the chains needed 2.5 MiB and died with
 * SIGSEGV (tests/attack9, finding 2).  The corridor's value: each of the
 * 1000 hits adds Kd Ia = 0.001 times Ks^k after k bounces, so
 * 0.001 (1 - 0.999^1000) / (1 - 0.999) = 1 - 0.999^1000.  The cube's ray
 * runs along (1, 1, 1): every face meets it at 54.7 degrees, past the
 * critical angle of ior 1.5 (41.8), so every bounce is a total reflection. */
#if defined(__SANITIZE_ADDRESS__)
#define DEEP_STACK_BYTES (8L << 20)
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define DEEP_STACK_BYTES (8L << 20)
#endif
#endif
/* The long double build's frames are half as large again (x87 values take
 * 16 bytes, and spill as such): its chains need 1.8 and 2.7 MiB, 1.8 and
 * 2.7 KiB a bounce (spec/numerics.md section 1).  It is shipped as the
 * stability tool's twin alone, a program on its main stack (8 MiB by
 * default), not as a library for a host's threads: it is held to the 3 MiB
 * it states. */
#ifndef DEEP_STACK_BYTES
#ifdef REFRAY_LONG_DOUBLE
#define DEEP_STACK_BYTES (3L << 20)
#else
#define DEEP_STACK_BYTES (2L << 20)
#endif
#endif

static const char mirror_corridor_1000[] =
    "image { width 1 height 1 max_depth 1000 }\n"
    "camera { eye [0, 0, 0] look_at [0, 0, -1] fov 1 }\n"
    "ambient { color 1 }\n"
    "plane { point [0, 0, -1] normal [0, 0, 1] material { Kd 0.001 Ks 0.999 } }\n"
    "plane { point [0, 0, 1] normal [0, 0, -1] material { Kd 0.001 Ks 0.999 } }\n";
static const char tir_cube_1000[] =
    "image { width 1 height 1 max_depth 1000 }\n"
    "camera { eye [0, 0, 0] look_at [1, 1, 1] fov 0.001 }\n"
    "ambient { color 1 }\n"
    "box { from [-1, -1, -1] to [1, 1, 1] material { Kd 0.001 Ks 0 t 0.999 ior 1.5 } }\n";

/* In a child on the limited stack: 0 when the chain rendered as it must. */
static int deep_chain_on_small_stack(const char *text, int tir)
{
    struct rlimit lim;
    if (getrlimit(RLIMIT_STACK, &lim) != 0)
        return 2;
    lim.rlim_cur = (rlim_t)DEEP_STACK_BYTES;
    if (setrlimit(RLIMIT_STACK, &lim) != 0)
        return 3;
    scene_model *s = load(text);
    trace_stats st;
    memset(&st, 0, sizeof st);
    rgb c = pixel(s, 0, 0, &st);
    scene_free(s);
    if (tir)
        return st.tir_rays == 999 && st.reflection_rays == 0 && vec_is_finite(c) ? 0 : 4;
    double want = 1 - pow(0.999, 1000);
    return st.reflection_rays == 999 && fabs(c.x - want) <= 1e-12 * want ? 0 : 5;
}

START_TEST(test_trace_depth_1000_fits_a_small_stack)
{
    const char *texts[2] = {mirror_corridor_1000, tir_cube_1000};
    for (int k = 0; k < 2; k++) {
        pid_t child = fork();
        ck_assert_int_ge(child, 0);
        if (child == 0)
            _exit(deep_chain_on_small_stack(texts[k], k));
        int status;
        ck_assert_int_eq(waitpid(child, &status, 0), child);
        ck_assert_msg(!WIFSIGNALED(status), "chain %d: killed by signal %d on a stack of %ld bytes", k,
                      WIFSIGNALED(status) ? WTERMSIG(status) : 0, DEEP_STACK_BYTES);
        ck_assert_msg(WIFEXITED(status) && WEXITSTATUS(status) == 0, "chain %d: exit %d", k, WEXITSTATUS(status));
    }
}
END_TEST

/* Nine coincident balls seen from outside, one surface crossing each at
 * the same point: the tracer keeps eight crossings of an interface.  The
 * hit is ball 0 (the lowest index of a tie), glass with Kd = Ks = 0 and no
 * ambient, so the pixel is what comes through; ball 8 is opaque, and an
 * opaque surface on the way lets nothing through ([SHADE-SHADOW-1]): the
 * pixel is 0, with the shortcuts on and off.  (Before, the ninth crossing
 * was dropped and the light behind came through: 1.85 in each channel.) */
static const char nine_balls_one_opaque[] =
    "image { width 1 height 1 max_depth 4 background [0.2, 0.3, 0.4] }\n"
    "camera { eye [0, 0, 10] look_at [0, 0, 0] fov 5 }\n"
    "ambient { color 0 }\n"
    "material g { Kd 0 t 0.9 ior 1 }\n"
    "sphere { material g }\nsphere { material g }\nsphere { material g }\nsphere { material g }\n"
    "sphere { material g }\nsphere { material g }\nsphere { material g }\nsphere { material g }\n"
    "sphere { material { Kd 0.5 } }\n"
    "plane { point [0, 0, -5] normal [0, 0, 1] material { Kd 1 } }\n"
    "point_light { position [0, 0, -3] power 10 falloff none }\n";

START_TEST(test_trace_ninth_coincident_opaque_surface_stops_light)
{
    scene_model *s = load(nine_balls_one_opaque);
    ck_assert_int_eq(s->prim_count, 10);
    for (int off = 0; off <= 1; off++) {
        render_opts o;
        memset(&o, 0, sizeof o);
        o.no_shortcuts = off;
        img_buf img = {0};
        render_stats st;
        ck_assert_int_eq(render_image(s, &o, &img, &st), STATUS_OK);
        for (int c = 0; c < 3; c++)
            ck_assert_msg(img.rgb[c] == 0, "shortcuts %s: channel %d is %.17g, not 0", off ? "off" : "on", c,
                          img.rgb[c]);
        img_free(&img);
    }
    scene_free(s);
}
END_TEST

/* [REL-MEDIUM-2] Nine coincident glass balls: the ray going in crosses nine
 * solids at one interface, more than the tracer keeps (eight); the medium
 * stack would miss one, so the render is refused as on the stack's own
 * overflow ([REL-MEDIUM-1]), not rendered with the wrong media. */
START_TEST(test_render_image_refuses_nine_coincident_glass_solids)
{
    char text[1024];
    int len = snprintf(text, sizeof text, "image { width 1 height 1 max_depth 4 }\n"
                                          "camera { eye [0, 0, 10] look_at [0, 0, 0] fov 5 }\n");
    for (int k = 0; k < 9; k++)
        len += snprintf(text + len, sizeof text - (size_t)len, "sphere { material { Kd 0.1 t 0.5 ior %d.5 } }\n",
                        1 + k % 2);
    ck_assert_int_lt(len, (int)sizeof text);
    scene_model *s = load(text);
    render_opts o;
    memset(&o, 0, sizeof o);
    img_buf img = {0};
    render_stats st;
    ck_assert_int_eq(render_image(s, &o, &img, &st), STATUS_DATA);
    ck_assert_ptr_null(img.rgb);
    ck_assert_int_gt(st.trace.medium_overflow, 0);
    scene_free(s);
}
END_TEST

/* medium_remove takes out the named solid wherever it lies, the ones above
 * it moving down one place in order; the top alone, and a solid the stack
 * does not hold, leave the rest as they were.  Expected stacks by hand. */
START_TEST(test_medium_remove_keeps_the_order)
{
    trace_stats st;
    medium_stack m;
    memset(&st, 0, sizeof st);
    m.count = 0;
    for (int k = 0; k < 4; k++)
        medium_push(&m, 10 + k, 1.25 + k, &st);   /* solids 10 11 12 13, iors 1.25 .. 4.25 */
    medium_remove(&m, 13);                          /* the top */
    ck_assert_int_eq(m.count, 3);
    ck_assert_int_eq(m.solid[2], 12);
    ck_assert(medium_top_ior(&m) == 3.25);
    medium_remove(&m, 11);                          /* a middle one: 12 moves down */
    ck_assert_int_eq(m.count, 2);
    ck_assert_int_eq(m.solid[0], 10);
    ck_assert_int_eq(m.solid[1], 12);
    ck_assert(m.ior[0] == 1.25 && m.ior[1] == 3.25);
    medium_remove(&m, 99);                          /* not held */
    ck_assert_int_eq(m.count, 2);
    medium_remove(&m, 10);                          /* the bottom */
    ck_assert_int_eq(m.count, 1);
    ck_assert_int_eq(m.solid[0], 12);
    ck_assert(m.ior[0] == 3.25);
    ck_assert_int_eq(medium_find(&m, 12), 0);
    ck_assert_int_eq(medium_find(&m, 10), -1);
    medium_remove(&m, 12);
    ck_assert_int_eq(m.count, 0);
    ck_assert(medium_top_ior(&m) == 1.0);
}
END_TEST

/* The crossing of an interface that holds the hit alone (count 1, the
 * transmitted ray's usual case, interface_cross's short path): entering a
 * sphere pushes its ior once, leaving it takes it out wherever it lies, a
 * sheet changes nothing; a closed mesh is toggled by the stack, not by the
 * hit's side.  Expected stacks by hand. */
static int cross_one(const tracer *t, int prim, int entering, const medium_stack *before, medium_stack *next)
{
    interface f;
    trace_stats st;
    memset(&st, 0, sizeof st);
    memset(&f, 0, sizeof f);
    f.scene = t->scene;
    f.count = 1;
    f.h[0].prim = prim;
    f.h[0].entering = entering;
    f.self = &f.h[0];
    *next = *before;
    return interface_cross(t, &f, before, next, &st);
}

START_TEST(test_interface_cross_one_crossing)
{
    /* prims: 0 the sheet, 1 the ball (ior 1.5), 2 the cube (ior 1.25) */
    scene_model *s = load("plane { point [0, 0, 0] normal [0, 1, 0] material { t 0.5 ior 2 } }\n"
                          "sphere { center [0, 3, 0] radius 1 material { t 1 ior 1.5 } }\n"
                          "mesh { file \"tests/obj/cube.obj\" translate [4, 3, 0] material { t 1 ior 1.25 } }\n");
    tracer t;
    trace_stats st;
    medium_stack before, next;
    memset(&st, 0, sizeof st);
    ck_assert(tracer_init(&t, s, 0, 0));
    before.count = 0;
    medium_push(&before, 7, 1.75, &st);
    ck_assert_int_eq(cross_one(&t, 1, 1, &before, &next), 1);   /* into the ball */
    ck_assert_int_eq(next.count, 2);
    ck_assert_int_eq(next.solid[1], 1);
    ck_assert(medium_top_ior(&next) == 1.5);
    before = next;
    ck_assert_int_eq(cross_one(&t, 1, 1, &before, &next), 1);   /* into it again: held once */
    ck_assert_int_eq(next.count, 2);
    medium_push(&before, 9, 1.125, &st);                         /* 7 1 9 */
    ck_assert_int_eq(cross_one(&t, 1, 0, &before, &next), 1);   /* out of it, 9 moves down */
    ck_assert_int_eq(next.count, 2);
    ck_assert_int_eq(next.solid[0], 7);
    ck_assert_int_eq(next.solid[1], 9);
    ck_assert(medium_top_ior(&next) == 1.125);
    before = next;
    ck_assert_int_eq(cross_one(&t, 1, 0, &before, &next), 1);   /* out of one not held */
    ck_assert_int_eq(next.count, 2);
    ck_assert_int_eq(cross_one(&t, 0, 1, &before, &next), 0);   /* the sheet */
    ck_assert_int_eq(next.count, 2);
    ck_assert_int_eq(cross_one(&t, 2, 0, &before, &next), 1);   /* the cube, not held: entered */
    ck_assert_int_eq(next.count, 3);
    ck_assert(medium_top_ior(&next) == 1.25);
    before = next;
    ck_assert_int_eq(cross_one(&t, 2, 1, &before, &next), 1);   /* held: left */
    ck_assert_int_eq(next.count, 2);
    ck_assert(medium_top_ior(&next) == 1.125);
    tracer_free(&t);
    scene_free(s);
}
END_TEST

/* add_source's shadow ray toward a distant light, ray_shadow_along_sized with
 * the light's setup (along_length made once), is the proved
 * ray_shadow_along's to the bit: random points from 2^-20 to 2^20, unit
 * normals, magnitudes and directions.  tmin is offset / |L|, so the count
 * of rays whose tmin is not the offset itself shows the division ran. */
START_TEST(test_ray_shadow_along_sized_is_ray_shadow_along)
{
    int divided = 0;
    for (uint64_t i = 0; i < 4000; i++) {
        real u[10];
        for (int k = 0; k < 10; k++)
            u[k] = (real)(test_mix(10 * i + (uint64_t)k) >> 11) * 0x1p-52 - 1;   /* [-1, 1) */
        vec3 dir = vec_make(u[0], u[1], u[2]), n = vec_make(u[6], u[7], u[8]);
        if (vec_length2(dir) < 0.01 || vec_length2(n) < 0.01)
            continue;
        scene_light light;
        memset(&light, 0, sizeof light);
        light.kind = LIGHT_DISTANT;
        light.direction = vec_normalize(dir);
        hit h;
        memset(&h, 0, sizeof h);
        h.point = vec_scale(vec_make(u[3], u[4], u[5]), ldexp(1, (int)(i % 41) - 20));
        h.normal = vec_normalize(n);
        shadow_start st = ray_shadow_start_sized(&h, fabs(u[9]) * 100);
        vec3 l = vec_neg(light.direction);
        light_setup setup = trace_light_setup(&light, 1);
        ray a = ray_shadow_along_sized(&st, l, setup.along_length), b = ray_shadow_along(&st, l);
        ck_assert(same_vec_bits(a.origin, b.origin) && same_vec_bits(a.dir, b.dir));
        ck_assert(same_real_bits(a.tmin, b.tmin) && same_real_bits(a.tmax, b.tmax));
        divided += a.tmin != st.offset;
    }
    ck_assert_int_gt(divided, 100);
}
END_TEST

Suite *suite_trace(void)
{
    Suite *s = suite_create("trace");
    TCase *local = tcase_create("local shading");
    tcase_add_test(local, test_trace_ambient_only_is_kd_times_ia);
    tcase_add_test(local, test_trace_background_when_nothing_is_hit);
    tcase_add_test(local, test_trace_distant_light_lambert);
    tcase_add_test(local, test_trace_point_light_falloffs);
    tcase_add_test(local, test_trace_light_below_the_horizon_adds_nothing);
    tcase_add_test(local, test_trace_phong_highlight_at_the_mirror_direction);
    tcase_add_test(local, test_trace_distributed_light_sums_its_samples);
    suite_add_tcase(s, local);
    TCase *rays = tcase_create("secondary rays");
    tcase_add_test(rays, test_trace_opaque_occluder_casts_a_shadow);
    tcase_add_test(rays, test_trace_transparent_occluder_lets_t_squared_through);
    tcase_add_test(rays, test_trace_mirror_reflects_with_weight_ks);
    tcase_add_test(rays, test_trace_max_depth_one_keeps_the_local_colour);
    tcase_add_test(rays, test_trace_transparent_sheet_blends_front_and_back);
    tcase_add_test(rays, test_trace_ior_one_glass_passes_rays_straight);
    tcase_add_test(rays, test_trace_glass_sphere_on_axis_is_not_bent);
    tcase_add_test(rays, test_medium_remove_keeps_the_order);
    tcase_add_test(rays, test_ray_shadow_along_sized_is_ray_shadow_along);
    suite_add_tcase(s, rays);
    TCase *whole = tcase_create("whole renders");
    tcase_add_test(whole, test_trace_renders_are_bit_identical);
    tcase_add_test(whole, test_trace_diffuse_scene_skips_passes);
    tcase_add_test(whole, test_trace_light_a_subnormal_distance_away);
    tcase_add_test(whole, test_render_image_stops_when_asked);
    tcase_add_test(whole, test_render_image_refuses_an_exploding_ray_tree);
    tcase_add_test(whole, test_trace_depth_1000_fits_a_small_stack);
    tcase_add_test(whole, test_trace_ninth_coincident_opaque_surface_stops_light);
    tcase_add_test(whole, test_render_image_refuses_nine_coincident_glass_solids);
    tcase_add_test(whole, test_interface_cross_one_crossing);
    suite_add_tcase(s, whole);
    return s;
}
