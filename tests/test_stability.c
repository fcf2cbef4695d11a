/*
 * The stiff-case suite (issue 5, spec/numerics.md): every scene of
 * scenes/stress/ renders with no non-finite value, and each one's own
 * property holds, against a closed form worked out here in long double by a
 * route of its own (geometric sphere test, Snell's law by angles, geometric
 * series), or as bit-for-bit equality with a reference scene.
 *
 * Where a robust method of the tracer was earned by a case, the naive method
 * it replaced is written here (never in the renderer) and the test shows it
 * failing on that same case: the "before" of spec/numerics.md.
 */
#include <dirent.h>
#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include "testlib.h"
#include "render/camera.h"
#include "render/intersect.h"
#include "render/render.h"
#include "io/scene_file.h"
#include "scene/scene.h"
#include "render/shade.h"
#include "verify/stability.h"
#include "render/trace.h"
#include "precision/naive.h"
#include <quadmath.h>

/* The reference precision is __float128: done in software, so it is the same
 * under valgrind, which computes x87 long double in double precision. */
#define REF __float128
#define REF_SQRT sqrtq
#define REF_POW powq
#define REF_FABS fabsq
#define REF_EPSILON ((__float128)0x1p-112)
#include "precision/measure.h"

#define STRESS_DIR "scenes/stress"

typedef __float128 ld;

/* ---- loading and rendering ---------------------------------------------- */

static scene_model *load_stress(const char *name)
{
    char path[256];
    int status;
    snprintf(path, sizeof path, "%s/%s.scene", STRESS_DIR, name);
    scene_model *s = scene_file_load(path, NULL, stderr, 0, &status);
    ck_assert_msg(s != NULL, "%s did not load (status %d)", path, status);
    return s;
}

/* Renders with the scene's own settings; asserts the run-time guard saw
 * nothing non-finite and every stored value is finite. */
static void render_checked(const scene_model *s, img_buf *img, render_stats *st)
{
    ck_assert_int_eq(render_image(s, NULL, img, st), STATUS_OK);
    ck_assert_msg(st->trace.nonfinite == 0, "%ld non-finite values traced", st->trace.nonfinite);
    for (long i = 0; i < 3 * img->width * img->height; i++)
        ck_assert_msg(isfinite(img->rgb[i]), "value %ld is %g", i, img->rgb[i]);
}

static img_buf render_stress(const char *name, render_stats *st)
{
    render_stats local;
    img_buf img;
    scene_model *s = load_stress(name);
    render_checked(s, &img, st ? st : &local);
    scene_free(s);
    return img;
}

/* ---- long double vectors for the closed forms ---------------------------- */

typedef struct lvec {
    ld x, y, z;
} lvec;

static lvec lv(ld x, ld y, ld z)
{
    lvec v = {x, y, z};
    return v;
}

static lvec lv_of(vec3 v) { return lv(v.x, v.y, v.z); }
static lvec lv_add(lvec a, lvec b) { return lv(a.x + b.x, a.y + b.y, a.z + b.z); }
static lvec lv_sub(lvec a, lvec b) { return lv(a.x - b.x, a.y - b.y, a.z - b.z); }
static lvec lv_scale(lvec a, ld s) { return lv(a.x * s, a.y * s, a.z * s); }
static ld lv_dot(lvec a, lvec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static ld lv_len(lvec a) { return sqrtq(lv_dot(a, a)); }
static lvec lv_unit(lvec a) { return lv_scale(a, 1 / lv_len(a)); }

static lvec lv_cross(lvec a, lvec b)
{
    return lv(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

/* The camera ray through the centre of pixel (i, j), from the camera as
 * written (eye, look_at, up, fov or width) and the definitions of
 * spec/shading.md, not from camera.c. */
static void exact_camera_ray(const scene_model *s, int i, int j, lvec *o, lvec *d)
{
    const scene_camera *c = &s->camera;
    int w = s->image.width, h = s->image.height;
    lvec eye = lv_of(c->eye);
    lvec f = lv_unit(lv_sub(lv_of(c->look_at), eye));
    lvec r = lv_unit(lv_cross(f, lv_of(c->up)));
    lvec u = lv_cross(r, f);
    ld sx = 2 * (i + 0.5) / w - 1, sy = 1 - 2 * (j + 0.5) / h, aspect = (ld)h / w;
    if (c->kind == CAMERA_ORTHOGRAPHIC) {
        ld half = c->width / 2.0;
        *o = lv_add(eye, lv_add(lv_scale(r, sx * half), lv_scale(u, sy * half * aspect)));
        *d = f;
    } else {
        ld half = tanq((ld)c->fov / 2 * (acosq(-1) / 180));
        *o = eye;
        *d = lv_unit(lv_add(f, lv_add(lv_scale(r, sx * half), lv_scale(u, sy * half * aspect))));
    }
}

/*
 * Geometric ray/sphere test (unit d): the closest approach of the line to
 * the centre is at t_ca = (c - o).d, at distance |l|; the chord's half
 * length is sqrt(R^2 - |l|^2).  Returns 1 with the nearest t > 0 and the
 * unit normal; *margin is R - |l| relative to R (how far from the
 * silhouette, for skipping pixels no precision can decide).
 */
static int exact_sphere(lvec c, ld radius, lvec o, lvec d, lvec *n, ld *margin)
{
    lvec f = lv_sub(c, o);
    ld tca = lv_dot(f, d);
    ld l = lv_len(lv_sub(f, lv_scale(d, tca)));
    *margin = (radius - l) / radius;
    if (l > radius)
        return 0;
    ld half = sqrtq((radius - l) * (radius + l));
    ld t = tca - half > 0 ? tca - half : tca + half;
    if (!(t > 0))
        return 0;
    *n = lv_scale(lv_sub(lv_add(o, lv_scale(d, t)), c), 1 / radius);
    return 1;
}

/* Kd*Ia + sum over distant lights of Kd*E*max(0, N.L), N facing the viewer:
 * the model (spec/shading.md) for a diffuse surface that nothing shadows.
 * Grey values: channel x. */
static ld exact_lambert(const scene_model *s, const scene_material *m, lvec n, lvec d)
{
    if (lv_dot(n, d) > 0)
        n = lv_scale(n, -1);
    ld v = (ld)m->kd.x * s->ambient.x;
    for (int k = 0; k < s->light_count; k++) {
        const scene_light *light = &s->lights[k];
        ck_assert_int_eq(light->kind, LIGHT_DISTANT);
        ld nl = -lv_dot(n, lv_unit(lv_of(light->direction)));
        if (nl > 0)
            v += (ld)m->kd.x * light->power.x * nl;
    }
    return v;
}

typedef struct sphere_check {
    int hits, misses, skipped;  /* pixels: hit, background, too close to the silhouette */
    ld worst_rel;               /* largest relative error of a hit pixel */
} sphere_check;

/*
 * Compares every pixel of the render of a scene whose prims[0] is a diffuse
 * sphere (lit by distant lights, nothing else visible) with the closed
 * form: hit or background, then the Lambert value.  Pixels within `edge`
 * (relative) of the silhouette are skipped: there the answer depends on the
 * last bit of the camera ray.
 */
static sphere_check check_sphere_scene(const char *name, ld edge, ld tol)
{
    sphere_check out = {0, 0, 0, 0};
    render_stats st;
    img_buf img;
    scene_model *s = load_stress(name);
    const scene_prim *p = &s->prims[0];
    ck_assert(p->kind == PRIM_SPHERE && !p->frame);
    render_checked(s, &img, &st);
    for (int j = 0; j < img.height; j++) {
        for (int i = 0; i < img.width; i++) {
            lvec o, d, n;
            ld margin;
            exact_camera_ray(s, i, j, &o, &d);
            int hits = exact_sphere(lv_of(p->u.sphere.center), p->u.sphere.radius, o, d, &n, &margin);
            double got = img_pixel(&img, i, j)[0];
            if (fabsq(margin) < edge) {
                out.skipped++;
                continue;
            }
            if (!hits) {
                ck_assert_msg(got == s->image.background.x, "%s (%d,%d): %.17g, expected the background",
                              name, i, j, got);
                out.misses++;
                continue;
            }
            ld want = exact_lambert(s, &s->materials[p->material], n, d);
            ld rel = fabsq(got - want) / want;
            ck_assert_msg(rel <= tol, "%s (%d,%d): %.17g, expected %.17g (relative error %.3g > %.3g)", name,
                          i, j, got, (double)want, (double)rel, (double)tol);
            if (rel > out.worst_rel)
                out.worst_rel = rel;
            out.hits++;
        }
    }
    img_free(&img);
    scene_free(s);
    return out;
}

/* ---- the cases --------------------------------------------------------- */

START_TEST(test_stress_tiny_sphere_far)
{
    sphere_check c = check_sphere_scene("tiny_sphere_far", 1e-6, 1e-9);
    ck_assert_int_gt(c.hits, 100);
    ck_assert_int_gt(c.misses, 20);
}
END_TEST

START_TEST(test_stress_huge_sphere_near)
{
    sphere_check c = check_sphere_scene("huge_sphere_near", 1e-9, 1e-9);
    ck_assert_int_eq(c.hits, 256);
}
END_TEST

START_TEST(test_stress_sphere_1e6_far)
{
    sphere_check c = check_sphere_scene("sphere_1e6_far", 1e-9, 1e-9);
    ck_assert_int_gt(c.hits, 50);
    ck_assert_int_gt(c.misses, 50);
}
END_TEST

START_TEST(test_stress_ortho_far_sphere)
{
    sphere_check c = check_sphere_scene("ortho_far_sphere", 1e-9, 1e-12);
    ck_assert_int_gt(c.hits, 400);
}
END_TEST

START_TEST(test_stress_terminator)
{
    sphere_check c = check_sphere_scene("terminator", 1e-9, 1e-12);
    ck_assert_int_gt(c.hits, 300);
}
END_TEST

START_TEST(test_stress_acne_scales)
{
    static const char *const names[] = {"acne_scale_1e-6", "acne_scale_1", "acne_scale_1e6"};
    for (int k = 0; k < 3; k++) {
        sphere_check c = check_sphere_scene(names[k], 1e-9, 1e-9);
        ck_assert_int_gt(c.hits, 50);
    }
    sphere_check c = check_sphere_scene("acne_offset_1e8", 1e-6, 1e-6);
    ck_assert_int_gt(c.hits, 50);
}
END_TEST

/* The pixel (0, 0) of a render, channel c. */
static double pixel0(const img_buf *img, int c) { return img_pixel(img, 0, 0)[c]; }

/* ---- shading at the limits --------------------------------------------- */

/* The view direction V = -forward of a loaded camera, in long double. */
static lvec exact_view(const scene_model *s)
{
    return lv_unit(lv_sub(lv_of(s->camera.eye), lv_of(s->camera.look_at)));
}

/* Kd*Ia + Kd*E*(N.L) + Ks*E*max(0, V.R)^n for prims[0] (a plane) lit by the
 * one distant light, N, L, V normalised in long double from the scene. */
static ld exact_phong(const scene_model *s)
{
    const scene_material *m = &s->materials[s->prims[0].material];
    lvec n = lv_unit(lv_of(s->prims[0].u.plane.normal));
    lvec l = lv_scale(lv_unit(lv_of(s->lights[0].direction)), -1);
    lvec v = exact_view(s);
    ld nl = lv_dot(n, l);
    lvec r = lv_sub(lv_scale(n, 2 * nl), l);
    ld vr = lv_dot(v, r);
    ld lobe = vr > 0 ? powq(vr, m->n) : 0;
    return (ld)m->kd.x * s->ambient.x + (ld)m->kd.x * s->lights[0].power.x * nl +
           (ld)m->ks.x * s->lights[0].power.x * lobe;
}

START_TEST(test_stress_phong_exponent_0_and_1e6_peak)
{
    /* n = 0: Kd*Ia + Kd*E*2/sqrt5 + Ks*E*1 (V.R = 2/sqrt5 > 0, so the lobe is 1). */
    img_buf img = render_stress("phong_n0", NULL);
    ck_assert_rel(pixel0(&img, 0), 0.25 * 0.1 + 0.25 * 2 / sqrt(5.0) + 0.5, 1e-15);
    img_free(&img);
    /* n = 1e6 at V = R: the lobe is exactly 1 (spec [SHADE-PHONG-1]). */
    img = render_stress("phong_n1e6_peak", NULL);
    ck_assert(pixel0(&img, 0) == 0.25 * 0.1 + 0.25 + 0.5);
    img_free(&img);
}
END_TEST

START_TEST(test_stress_phong_exponent_1e6_off_peak)
{
    scene_model *s = load_stress("phong_n1e6_off");
    ld want = exact_phong(s);
    img_buf img;
    render_stats st;
    render_checked(s, &img, &st);
    /* [NUM-PHONG-1] pow of the plain dot product V.R gave 6.2e-11 here: the
     * rounding of |V| and |R| times n = 1e6 (spec/numerics.md). */
    ld rel = fabsq(pixel0(&img, 0) - want) / want;
    ck_assert_msg(rel <= 1e-13, "relative error %.3g", (double)rel);
    img_free(&img);
    scene_free(s);
}
END_TEST

START_TEST(test_stress_critical_angle_both_sides)
{
    /* [NUM-SNELL-1] 1e-12 rad on either side of the critical angle. */
    static const char *const names[] = {"critical_below", "critical_above"};
    ld theta_c = asinq(1 / (ld)1.5);
    for (int k = 0; k < 2; k++) {
        scene_model *s = load_stress(names[k]);
        /* The scene really is within 1e-12 rad of the critical angle, on
         * the side its name says: angle between the view and the face
         * normal +y, from the loaded camera. */
        ld theta = acosq(-exact_view(s).y), off = theta - theta_c;
        ck_assert_msg(k == 0 ? off < -0.9e-12 && off > -1.1e-12 : off > 0.9e-12 && off < 1.1e-12,
                      "%s: %.3g rad from the critical angle", names[k], (double)off);
        img_buf img;
        render_stats st;
        render_checked(s, &img, &st);
        ck_assert_msg(pixel0(&img, 0) == (k == 0 ? 0.5 : 0.0), "%s: %.17g", names[k], pixel0(&img, 0));
        ck_assert_int_eq(st.trace.tir_rays > 0, k == 1);
        img_free(&img);
        scene_free(s);
    }
}
END_TEST

static void assert_images_equal(const img_buf *a, const img_buf *b, double rel, const char *what)
{
    ck_assert_int_eq(a->width, b->width);
    ck_assert_int_eq(a->height, b->height);
    for (long i = 0; i < 3 * a->width * a->height; i++) {
        double x = a->rgb[i], y = b->rgb[i];
        ck_assert_msg(rel == 0 ? x == y : fabs(x - y) <= rel * fmax(fabs(x), fabs(y)),
                      "%s: value %ld (pixel %ld, %ld): %.17g vs %.17g", what, i, i / 3 % a->width,
                      i / 3 / a->width, x, y);
    }
}

static void assert_renders_equal(const char *name, const char *ref, double rel)
{
    img_buf a = render_stress(name, NULL), b = render_stress(ref, NULL);
    assert_images_equal(&a, &b, rel, name);
    img_free(&a);
    img_free(&b);
}

START_TEST(test_stress_ior_one_is_bit_exact)
{
    /* [NUM-IOR1-1] Glass of ior 1 changes nothing, to the bit. */
    assert_renders_equal("ior_one", "ior_one_ref", 0);
}
END_TEST

START_TEST(test_stress_ior_extreme)
{
    static const char *const names[] = {"ior_extreme_high", "ior_extreme_low"};
    for (int k = 0; k < 2; k++) {
        img_buf img = render_stress(names[k], NULL);
        /* Centre pixel (4, 4): on the axis, straight through: t^2 * 0.4. */
        ck_assert_msg(img_pixel(&img, 4, 4)[0] == 0.5 * (0.5 * 0.4), "%s: %.17g", names[k],
                      img_pixel(&img, 4, 4)[0]);
        img_free(&img);
    }
}
END_TEST

START_TEST(test_stress_light_on_and_near_the_surface)
{
    render_stats st;
    img_buf img = render_stress("light_on_surface", &st);
    ck_assert_int_eq(st.trace.lights_on_surface, 1);
    ck_assert(pixel0(&img, 0) == 0.5 * 0.1);
    img_free(&img);
    /* Two lights of 1/(1e-300)^2 each: clamped, summed, saturated. */
    img = render_stress("light_near_surface", &st);
    ck_assert(pixel0(&img, 0) == DBL_MAX);
    img_free(&img);
}
END_TEST

START_TEST(test_stress_mirror_box_depth_1000)
{
    render_stats st;
    img_buf img = render_stress("mirror_box_1000", &st);
    /* Each of the 1000 hits adds its ambient Kd*Ia = 0.5 * 0.002, weighted by
     * Ks^k for the k mirror bounces before it: a geometric series. */
    static const ld ks[3] = {1, 0.9, 0.5};
    for (int c = 0; c < 3; c++) {
        ld want = ks[c] == 1 ? 1000 * 0.001 : 0.001 * (1 - powq(ks[c], 1000)) / (1 - ks[c]);
        ck_assert_msg(fabsq(pixel0(&img, c) - want) <= 1e-13 * want, "channel %d: %.17g vs %.17g", c,
                      pixel0(&img, c), (double)want);
    }
    ck_assert_int_eq(st.trace.reflection_rays, 999);
    img_free(&img);
}
END_TEST

START_TEST(test_stress_camera_and_light_inside_sphere)
{
    img_buf img = render_stress("camera_light_inside_sphere", NULL);
    for (int j = 0; j < img.height; j++)
        for (int i = 0; i < img.width; i++)
            ck_assert_rel(img_pixel(&img, i, j)[0], 0.6 * 0.1 + 0.6 * 4 / 2.0, 1e-14);
    img_free(&img);
}
END_TEST

START_TEST(test_stress_light_inside_box)
{
    img_buf img = render_stress("light_inside_box", NULL);
    int box = 0, floor = 0;
    for (int j = 0; j < img.height; j++)
        for (int i = 0; i < img.width; i++) {
            double v = img_pixel(&img, i, j)[0];
            box += v == 0.6 * 0.1;
            floor += v == 0.4 * 0.1;
            ck_assert_msg(v == 0.6 * 0.1 || v == 0.4 * 0.1 || v == 0.5, "(%d,%d) = %.17g: lit", i, j, v);
        }
    ck_assert_int_gt(box, 10);
    ck_assert_int_gt(floor, 10);
    img_free(&img);
}
END_TEST

START_TEST(test_stress_light_inside_glass)
{
    img_buf img = render_stress("light_inside_glass", NULL);
    ck_assert_rel(pixel0(&img, 0), 0.8 * 0.1 + 0.8 * 1 / 2.0 * 0.5, 1e-13);
    img_free(&img);
}
END_TEST

START_TEST(test_stress_view_along_the_normal)
{
    img_buf img = render_stress("view_along_normal", NULL);
    ck_assert_rel(pixel0(&img, 0), 0.2 * 0.1 + 0.7 * 2 / 10.0 + 0.7 * 1 + 0.5 * 0.3, 1e-12);
    img_free(&img);
}
END_TEST

/* ---- glass that touches and nests --------------------------------------- */

START_TEST(test_stress_touching_glass_is_one_interface)
{
    /* [NUM-GLASS-1] Before the interface gather, pixel (12, 4) was 0.07
     * against 0.2. */
    assert_renders_equal("touching_glass_pair", "touching_glass_single", 1e-9);
}
END_TEST

START_TEST(test_stress_touching_glass_camera_inside)
{
    /* [NUM-GLASS-1] Bent 1.5 -> 1.4 at the shared face, onto the red ball. */
    img_buf img = render_stress("touching_glass_camera_inside", NULL);
    ck_assert_msg(pixel0(&img, 0) == 1 && pixel0(&img, 1) == 0 && pixel0(&img, 2) == 0, "[%g, %g, %g]",
                  pixel0(&img, 0), pixel0(&img, 1), pixel0(&img, 2));
    img_free(&img);
}
END_TEST

START_TEST(test_stress_nested_glass_index_matched)
{
    /* [NUM-GLASS-1] An index-matched inner surface bends nothing. */
    assert_renders_equal("nested_glass_matched", "nested_glass_outer", 1e-9);
}
END_TEST

/* ---- glass standing on an opaque surface ---------------------------------- */

/* [NUM-GLASS-3] Each value of a (touching) within tol of b (the gap g),
 * plus 2 |b2 - b| where b2 (the gap 2g) is given. */
static void assert_gap_limit(const img_buf *a, const img_buf *b, const img_buf *b2, double tol, const char *what)
{
    ck_assert_int_eq(a->width, b->width);
    ck_assert_int_eq(a->height, b->height);
    ck_assert(!b2 || (b2->width == b->width && b2->height == b->height));
    for (long i = 0; i < 3 * a->width * a->height; i++) {
        double bound = tol + (b2 ? 2 * fabs(b2->rgb[i] - b->rgb[i]) : 0);
        ck_assert_msg(fabs(a->rgb[i] - b->rgb[i]) <= bound, "%s: value %ld (pixel %ld, %ld): %.17g, %.17g at g", what,
                      i, i / 3 % a->width, i / 3 / a->width, a->rgb[i], b->rgb[i]);
    }
}

START_TEST(test_stress_glass_on_floor_is_the_gap_limit)
{
    /* [NUM-GLASS-3] The block 1e-9 above the floor (g) against standing on
     * it.  Raising the block by g moves every point a pixel's ray meets by
     * at most g / cos 60 deg = 2g along the camera ray (its rays meet the
     * top face at least 30 deg above it), and refraction at ior 1.5 keeps
     * the further points within 4g (tan of the inside angle <= 0.9, of the
     * outside one <= 1.8); the colour there is Kd (Ia + P S cos / r^2) with
     * r >= 4 from the light (the top face is 4 below it), whose gradient is
     * at most Kd P 3 / r^3 = 0.8 * 4 * 3 / 64 = 0.15 a unit, the shadow
     * factors S (t, t^2) fixed.  So each value moves by at most 0.15 * 4g
     * per point, four points a path: 3e-9 < 1e-8; no pixel centre lies
     * within 1e-8 of an edge of the block or of its shadow (the image is a
     * 32 x 24 grid of generic rays).  Before: 172 pixels off by up to 0.59. */
    img_buf a = render_stress("glass_on_floor", NULL), b = render_stress("glass_on_floor_gap", NULL);
    assert_gap_limit(&a, &b, NULL, 1e-8, "glass_on_floor");
    img_free(&a);
    img_free(&b);
}
END_TEST

START_TEST(test_stress_glass_on_floor_order_free)
{
    /* [NUM-GLASS-3] The coplanar tie of the floor and the block's bottom
     * face is taken in the gap's limit, not by the lower index: the order
     * of the two lines changes no bit.  Before: 176 pixels apart.  So with
     * Ks > 0 on the glass (glass_touch_*, (4)). */
    assert_renders_equal("glass_on_floor_plane_first", "glass_on_floor", 0);
    assert_renders_equal("glass_on_floor_down_plane_first", "glass_on_floor_down_box_first", 0);
    assert_renders_equal("glass_touch_floor_box_plane_last", "glass_touch_floor_box", 0);
    assert_renders_equal("glass_touch_side_box_opaque_first", "glass_touch_side_box", 0);
}
END_TEST

START_TEST(test_stress_glass_on_floor_lit_through_both_faces)
{
    /* [NUM-GLASS-3] Straight down through a clear block (t = 0.5) on a shiny
     * floor (Kd 0.5, Ks 0.4), a distant light straight down (E = 1, Ia =
     * 0.2, background 0.6): the floor's shadow ray and its mirror ray each
     * cross both faces, S = t^2, so C = t^2 (Kd (Ia + S E) + Ks S E + Ks t^2
     * bg).  A shadow ray that missed the face at the floor gives 0.1525, a
     * mirror ray that did 0.11125; before: 0 (box first), 0.335 (plane
     * first). */
    static const char *const names[] = {"glass_on_floor_down_box_first", "glass_on_floor_down_plane_first"};
    const double t = 0.5, s = t * t, want = t * t * (0.5 * (0.2 + s) + 0.4 * s + 0.4 * t * t * 0.6);
    for (int k = 0; k < 2; k++) {
        img_buf img = render_stress(names[k], NULL);
        for (long i = 0; i < 3 * img.width * img.height; i++)
            ck_assert_msg(fabs(img.rgb[i] - want) <= 1e-15, "%s: value %ld is %.17g, want %.17g", names[k], i,
                          img.rgb[i], want);
        img_free(&img);
    }
}
END_TEST

START_TEST(test_stress_glass_touch_is_the_gap_limit)
{
    /* [NUM-GLASS-3] Glass with Ks > 0 touching an opaque surface (the
     * glass_touch_* scenes): the render equals the limit of the gap g -> 0.
     * Each value is a smooth function of g away from the edges of the
     * shapes and shadows (every point a path meets moves by O(g)), so
     * v(0) - v(g) = v(g) - v(2g) + O(g^2): the touching image lies within
     * 2 |v(2g) - v(g)| of the gap's at g = 1e-9, and within 1e-12 where the
     * value does not move with g (the rounding of the points, 1e-16 of
     * their size, through colours of slope below 10).  Before: up to 0.22
     * off (tests/attack11 finding 5: the glass face's mirror and shadow
     * rays started past the opaque surface). */
    static const char *const cases[] = {"side_box", "top_box", "floor_box", "floor_disk", "floor_cylinder",
                                        "floor_mesh"};
    char name[64];
    for (int c = 0; c < 6; c++) {
        snprintf(name, sizeof name, "glass_touch_%s", cases[c]);
        img_buf a = render_stress(name, NULL);
        snprintf(name, sizeof name, "glass_touch_%s_gap", cases[c]);
        img_buf b = render_stress(name, NULL);
        snprintf(name, sizeof name, "glass_touch_%s_gap2", cases[c]);
        img_buf b2 = render_stress(name, NULL);
        assert_gap_limit(&a, &b, &b2, 1e-12, cases[c]);
        img_free(&a);
        img_free(&b);
        img_free(&b2);
    }
}
END_TEST

/* ---- scale ----------------------------------------------------------- */

START_TEST(test_stress_scale_invariance)
{
    /* [NUM-SCALE-1] Power-of-two scales 2^400 and 2^-400: bit for bit.
     * [LANG-EXTENT-1] So at 2^490 and 2^-490, near the extent's bounds. */
    assert_renders_equal("scale_2p400", "scale_1", 0);
    assert_renders_equal("scale_2m400", "scale_1", 0);
    assert_renders_equal("scale_2p490", "scale_1", 0);
    assert_renders_equal("scale_2m490", "scale_1", 0);
}
END_TEST

START_TEST(test_stress_denormal_coordinates)
{
    assert_renders_equal("denormal_coordinates", "scale_1", 1e-12);
}
END_TEST

/* ---- coplanar surfaces ------------------------------------------------ */

START_TEST(test_stress_coplanar_disk_on_plane)
{
    scene_model *s = load_stress("coplanar_disk_on_plane");
    const scene_prim *disk = &s->prims[0];
    ck_assert(disk->kind == PRIM_DISK);
    img_buf img;
    render_stats st;
    render_checked(s, &img, &st);
    lvec n = lv_of(disk->u.disk.normal), c = lv_of(disk->u.disk.center);
    int on_disk = 0, on_plane = 0;
    for (int j = 0; j < img.height; j++)
        for (int i = 0; i < img.width; i++) {
            lvec o, d;
            exact_camera_ray(s, i, j, &o, &d);
            /* The plane through the disk's centre (the two are one plane to
             * rounding); distance of the hit from the centre vs the radius. */
            ld t = lv_dot(n, lv_sub(c, o)) / lv_dot(n, d);
            ld r = lv_len(lv_sub(lv_add(o, lv_scale(d, t)), c)) / disk->u.disk.radius;
            if (fabsq(r - 1) < 1e-9)
                continue;
            double got = img_pixel(&img, i, j)[0];
            int want_disk = r < 1;
            ck_assert_msg(want_disk ? got > 0.5 : got < 0.5, "(%d,%d): %s expected, red %.17g", i, j,
                          want_disk ? "disk" : "plane", got);
            on_disk += want_disk;
            on_plane += !want_disk;
        }
    ck_assert_int_gt(on_disk, 20);
    ck_assert_int_gt(on_plane, 20);
    /* [NUM-COPLANAR-1] Denser: 256 x 256 rays over the same view.  With
     * "least t wins" 12 of about 43000 rays inside the disk showed the plane
     * (the two t differ by an ulp); the tie window makes it 0. */
    tracer t;
    ck_assert(tracer_init(&t, s, 0, 0));
    int plane_inside = 0, inside = 0;
    for (int j = 0; j < 256; j++)
        for (int i = 0; i < 256; i++) {
            ray r = camera_ray(&s->camera, camera_half(&s->camera), 256, 256, i + 0.5, j + 0.5), rd = r;
            hit h, hd;
            if (!isect_prim(disk, &rd, &hd))
                continue;
            ck_assert(bvh_intersect(&t.accel, s->prims, &r, &h));
            inside++;
            plane_inside += h.prim != 0;
        }
    ck_assert_int_gt(inside, 10000);
    ck_assert_int_eq(plane_inside, 0);
    tracer_free(&t);
    img_free(&img);
    scene_free(s);
}
END_TEST

/* ---- robust methods and their naive "before" ----------------------------- */

/* What the textbook quadratic does on the camera rays of a scene whose
 * prims[0] is a sphere: pixels it gets wrong (hit or miss, or a Lambert
 * value off by more than tol), and the worst distance of its hit points
 * from the sphere relative to the radius; *robust_off is the same distance
 * for isect_sphere. */
typedef struct naive_report {
    int wrong;
    ld naive_off, robust_off;
} naive_report;

static ld off_surface(const scene_prim *p, vec3 point)
{
    return fabsq(lv_len(lv_sub(lv_of(point), lv_of(p->u.sphere.center))) - p->u.sphere.radius) /
           p->u.sphere.radius;
}

static naive_report naive_sphere_report(const char *name, ld tol)
{
    naive_report out = {0, 0, 0};
    scene_model *s = load_stress(name);
    const scene_prim *p = &s->prims[0];
    const scene_material *m = &s->materials[p->material];
    for (int j = 0; j < s->image.height; j++)
        for (int i = 0; i < s->image.width; i++) {
            lvec o, d, n;
            ld margin;
            exact_camera_ray(s, i, j, &o, &d);
            int want = exact_sphere(lv_of(p->u.sphere.center), p->u.sphere.radius, o, d, &n, &margin);
            if (fabsq(margin) < 1e-6)
                continue;
            ray r = camera_ray(&s->camera, camera_half(&s->camera), s->image.width, s->image.height, i + 0.5, j + 0.5), rr = r;
            real t;
            hit h;
            int got = naive_sphere(p->u.sphere.center, p->u.sphere.radius, &r, &t);
            if (got != want) {
                out.wrong++;
                continue;
            }
            if (!got || !isect_prim(p, &rr, &h))
                continue;
            vec3 at = ray_at(&r, t), nn = vec_normalize(vec_sub(at, p->u.sphere.center));
            ld exact = exact_lambert(s, m, n, d), naive = exact_lambert(s, m, lv_of(nn), d);
            out.wrong += fabsq(naive - exact) > tol * exact;
            out.naive_off = fmaxq(out.naive_off, off_surface(p, at));
            out.robust_off = fmaxq(out.robust_off, off_surface(p, h.point));
        }
    scene_free(s);
    return out;
}

START_TEST(test_stress_naive_sphere_fails_where_refray_holds)
{
    /* [NUM-SPHERE-1] The same pixels the robust test gets right to 1e-9:
     * the textbook formula misses or misshades many of them
     * (tiny_sphere_far), and puts its hit points far off the surface
     * (hundreds of times the robust test's distance) where one root is lost
     * to cancellation (huge_sphere_near) or the discriminant to rounding
     * (ortho_far_sphere); spec/numerics.md has the figures. */
    naive_report tiny = naive_sphere_report("tiny_sphere_far", 1e-9);
    ck_assert_int_gt(tiny.wrong, 20);
    static const char *const far_near[] = {"huge_sphere_near", "ortho_far_sphere"};
    for (int k = 0; k < 2; k++) {
        naive_report r = naive_sphere_report(far_near[k], 1e-9);
        ck_assert_msg(r.robust_off < 1e-15 && r.naive_off > 100 * r.robust_off, "%s: off the surface %.3g vs %.3g",
                      far_near[k], (double)r.naive_off, (double)r.robust_off);
    }
}
END_TEST

START_TEST(test_stress_concentric_gap_does_not_leak)
{
    scene_model *s = load_stress("concentric_gap");
    img_buf img;
    render_stats st;
    render_checked(s, &img, &st);
    int inner = 0;
    for (int j = 0; j < img.height; j++)
        for (int i = 0; i < img.width; i++) {
            double v = img_pixel(&img, i, j)[0];
            ck_assert_msg(v == 0.8 * 0.1 || v == 0.5 * 0.1, "(%d,%d) = %.17g: light leaked in", i, j, v);
            inner += v == 0.8 * 0.1;
        }
    ck_assert_int_gt(inner, 50);
    /* [NUM-SPAWN-1] The before: a shadow ray pushed off the inner sphere by
     * a fixed 1e-4 starts beyond the outer one (gap 4e-5): every shadow ray
     * leaks. */
    int leaks = 0, tried = 0;
    tracer t;
    ck_assert(tracer_init(&t, s, 0, 0));
    for (int j = 0; j < img.height; j++)
        for (int i = 0; i < img.width; i++) {
            ray r = camera_ray(&s->camera, camera_half(&s->camera), img.width, img.height, i + 0.5, j + 0.5);
            hit h;
            if (!bvh_intersect(&t.accel, s->prims, &r, &h) || h.prim != 0)
                continue;
            vec3 to = vec_normalize(vec_sub(s->lights[0].position, h.point));
            ray shadow = naive_spawn(h.point, h.normal, to, 1e-4);
            hit h2;
            tried++;
            leaks += !bvh_intersect(&t.accel, s->prims, &shadow, &h2);
        }
    tracer_free(&t);
    ck_assert_int_eq(leaks, tried);
    img_free(&img);
    scene_free(s);
}
END_TEST

START_TEST(test_stress_naive_spawn_self_hits_far_from_origin)
{
    /* [NUM-SPAWN-1] The other side: a fixed 1e-9 is below the error of a
     * hit point 1.7e8 from the origin (about 1e-8): shadow rays re-hit their
     * own sphere.  refray's offset (2^-42 of the magnitude) passes the same
     * case (test_stress_acne_scales). */
    scene_model *s = load_stress("acne_offset_1e8");
    const scene_prim *p = &s->prims[0];
    vec3 l = vec_neg(s->lights[0].direction);
    int self = 0, tried = 0;
    for (int j = 0; j < s->image.height; j++)
        for (int i = 0; i < s->image.width; i++) {
            ray r = camera_ray(&s->camera, camera_half(&s->camera), s->image.width, s->image.height, i + 0.5, j + 0.5);
            hit h, h2;
            if (!isect_prim(p, &r, &h) || !(vec_dot(h.normal, l) > 0))
                continue;
            ray naive = naive_spawn(h.point, h.normal, l, 1e-9), robust = ray_spawn_hit(p, &h, l);
            tried++;
            self += isect_prim(p, &naive, &h2);
            ck_assert(!isect_prim(p, &robust, &h2));
        }
    ck_assert_int_gt(tried, 20);
    ck_assert_int_gt(self, tried / 10);
    scene_free(s);
}
END_TEST

/* ---- watertight and thin triangles --------------------------------------- */

typedef struct sweep {
    long rays, misses, naive_misses;
    long wrong_crossings, naive_wrong_crossings; /* rays crossing the surface other than `crossings` times */
} sweep;

/* One ray through the scene's acceleration structure: a miss, and (when
 * crossings > 0) a number of surface crossings other than that.  With
 * count_naive, the same ray against the triangles of every mesh by
 * Moller-Trumbore and by the paper's inclusive Woop test too (until both
 * have said what they have to). */
static void sweep_ray(const tracer *t, const scene_model *s, ray r, sweep *w, int count_naive, int crossings)
{
    hit h;
    ray copy = r;
    int visited = 0;
    w->rays++;
    w->misses += !bvh_intersect(&t->accel, s->prims, &copy, &h);
    bvh_visit(&t->accel, s->prims, &r, count_crossing, &visited);
    w->wrong_crossings += crossings > 0 && visited != crossings;
    if (!count_naive)
        return;
    int any = 0, inclusive = 0;
    for (int m = 0; m < s->mesh_count; m++)
        for (int k = 0; k < s->meshes[m].geom.tri_count && (!any || inclusive <= crossings); k++) {
            vec3 p[3];
            real tt;
            mesh_triangle(&s->meshes[m].geom, k, p);
            any |= naive_triangle(p, &r, &tt);
            inclusive += naive_woop_inclusive(p, &r);
        }
    w->naive_misses += !any;
    w->naive_wrong_crossings += crossings > 0 && inclusive != crossings;
}

static ray ray_through(vec3 point, vec3 from)
{
    ray r;
    r.origin = from;
    r.dir = vec_normalize(vec_sub(point, from));
    r.tmin = 0;
    r.tmax = HUGE_VAL;
    return r;
}

/* Rays through point: from the centre outward (one crossing), and from
 * three places outside, 3 units away in directions that lean off the
 * radial one (in at the point, out on the far side: two).  The naive
 * methods (brute force) run on the first. */
static void sweep_point(const tracer *t, const scene_model *s, vec3 centre, vec3 point, sweep *w)
{
    static const double lean[3][3] = {{0.31, -0.17, 0.05}, {-0.23, 0.11, 0.29}, {0.07, 0.37, -0.19}};
    vec3 out = vec_normalize(vec_sub(point, centre));
    sweep_ray(t, s, ray_through(point, centre), w, 1, 1);
    for (int k = 0; k < 3; k++) {
        vec3 away = vec_normalize(vec_add(out, vec_make(lean[k][0], lean[k][1], lean[k][2])));
        sweep_ray(t, s, ray_through(point, vec_madd(point, away, 3)), w, 0, 2);
    }
}

START_TEST(test_stress_watertight_mesh)
{
    /* [NUM-WATERTIGHT-1] Every edge of the closed icosphere at five points
     * (its midpoint and four others) and every vertex, each from inside and
     * from three directions outside: no ray slips through, and each crosses
     * the surface exactly as often as it should (once from the centre, twice
     * from outside): never two triangles at one edge or vertex. */
    scene_model *s = load_stress("watertight_mesh");
    tracer t;
    ck_assert(tracer_init(&t, s, 0, 0));
    const scene_trimesh *g = &s->meshes[0].geom;
    vec3 centre = vec_make(0.5, 0.25, 0.125);
    static const double at[] = {0.5, 0.1, 0.3337, 0.71, 0.9};
    sweep w;
    memset(&w, 0, sizeof w);
    for (int k = 0; k < g->tri_count; k++) {
        vec3 p[3];
        mesh_triangle(g, k, p);
        for (int e = 0; e < 3; e++) {
            sweep_point(&t, s, centre, p[e], &w);
            for (int a = 0; a < 5; a++)
                sweep_point(&t, s, centre, vec_add(p[e], vec_scale(vec_sub(p[(e + 1) % 3], p[e]), at[a])), &w);
        }
    }
    ck_assert_int_eq(g->tri_count, 1280);
    ck_assert_int_eq(w.misses, 0);
    ck_assert_int_eq(w.wrong_crossings, 0);
    /* The befores: Moller-Trumbore lets some of the same rays through, and
     * the inclusive Woop test counts shared edges and vertices twice. */
    ck_assert_int_gt(w.naive_misses, 0);
    ck_assert_int_gt(w.naive_wrong_crossings, 0);
    tracer_free(&t);
    scene_free(s);
}
END_TEST

/* The point a fraction f of the way from a to b, a and b themselves at the
 * ends: a probe through an edge's end must pass through the vertex exactly. */
static vec3 along_edge(vec3 a, vec3 b, double f)
{
    return f == 1 ? b : vec_add(a, vec_scale(vec_sub(b, a), f));
}

START_TEST(test_stress_thin_triangles)
{
    scene_model *s = load_stress("thin_triangles");
    tracer t;
    ck_assert(tracer_init(&t, s, 0, 0));
    sweep w;
    memset(&w, 0, sizeof w);
    /* The strip's diagonal (0,0,0)-(1,1e-8,0) and the fan's 63 inner spokes
     * and apex (the fan is moved by -0.5 in y), each ray straight down and
     * leaning.  The ends are the meshes' own vertices, not recomputed: the
     * OBJ files hold cos and sin of the spokes' angles to 17 digits, which the
     * long double build reads to 64 bits, up to half a double's ulp from the
     * double the probe computed (before, 64 rays through the outer ends of
     * the spokes, on the fan's rim, passed just outside it there). */
    const scene_trimesh *strip = &s->meshes[0].geom, *fan = &s->meshes[1].geom;
    ck_assert_int_eq(strip->position_count, 4);
    ck_assert_int_eq(fan->position_count, 66);
    vec3 diagonal[2] = {strip->positions[0], strip->positions[2]};
    ck_assert(diagonal[0].x == 0 && diagonal[0].y == 0 && diagonal[1].x == 1 && fabs(diagonal[1].y - 1e-8) < 1e-23);
    for (int k = 0; k <= 1000; k++) {
        double f = k / 1000.0;
        vec3 p = along_edge(diagonal[0], diagonal[1], f);
        sweep_ray(&t, s, ray_through(p, vec_add(p, vec_make(0, 0, 1))), &w, 0, k > 0 && k < 1000 ? 1 : 0);
        sweep_ray(&t, s, ray_through(p, vec_add(p, vec_make(0.3, -0.2, 1))), &w, 0, k > 0 && k < 1000 ? 1 : 0);
    }
    vec3 apex = fan->positions[0];
    ck_assert(apex.x == 0 && apex.y == -0.5);
    for (int spoke = 1; spoke < 64; spoke++)
        for (int k = 0; k <= 64; k++) {
            double f = k / 64.0, a = spoke * 1e-8;
            vec3 end = fan->positions[spoke + 1];
            ck_assert(fabs(end.x - cos(a)) < 1e-15 && fabs(end.y - (sin(a) - 0.5)) < 1e-15);
            vec3 p = along_edge(apex, end, f);
            sweep_ray(&t, s, ray_through(p, vec_add(p, vec_make(0, 0, 1))), &w, 0, k > 0 && k < 64 ? 1 : 0);
            sweep_ray(&t, s, ray_through(p, vec_add(p, vec_make(-0.1, 0.4, 1))), &w, 0, k > 0 && k < 64 ? 1 : 0);
        }
    ck_assert_int_eq(w.misses, 0);
    ck_assert_int_eq(w.wrong_crossings, 0);
    /* The geometric normal of a sliver is still exactly +-z. */
    for (int k = 0; k < s->prim_count; k++) {
        ray r = ray_through(vec_make(0.9, 0.7e-8, 0), vec_make(0.9, 0.7e-8, 1));
        hit h;
        if (isect_prim(&s->prims[k], &r, &h))
            ck_assert(h.normal.x == 0 && h.normal.y == 0 && fabs(h.normal.z) == 1);
    }
    tracer_free(&t);
    scene_free(s);
}
END_TEST

START_TEST(test_stress_surface_starts_no_self_hit)
{
    scene_model *s = load_stress("surface_starts");
    tracer t;
    ck_assert(tracer_init(&t, s, 0, 0));
    int hits = 0;
    for (int j = 0; j < s->image.height; j++)
        for (int i = 0; i < s->image.width; i++) {
            ray r = camera_ray(&s->camera, camera_half(&s->camera), s->image.width, s->image.height, i + 0.5, j + 0.5);
            hit h;
            if (!bvh_intersect(&t.accel, s->prims, &r, &h))
                continue;
            const scene_prim *p = &s->prims[h.prim];
            ray out[3] = {ray_spawn_hit(p, &h, shade_mirror(r.dir, h.normal)), ray_spawn_hit(p, &h, r.dir),
                          ray_spawn_hit_to(p, &h, s->lights[0].position)};
            hits++;
            for (int k = 0; k < 3; k++) {
                hit h2;
                ck_assert_msg(!isect_prim(p, &out[k], &h2) || h2.t > 1e-6, "pixel (%d,%d) kind %d ray %d: self-hit at %g",
                              i, j, p->kind, k, (double)h2.t);
            }
        }
    ck_assert_int_gt(hits, 400);
    tracer_free(&t);
    scene_free(s);
}
END_TEST

START_TEST(test_stress_concave_corner_is_lit)
{
    /* [NUM-SPAWN-2] Rays through 2000 points of the edge where the floor
     * (y = 0) meets the wall (x = -1).  Each is lit as the surface it hits
     * is at the exact edge point: Kd Ia + Kd E/(d + d0) (N.L). */
    scene_model *s = load_stress("concave_corner");
    tracer t;
    ck_assert(tracer_init(&t, s, 0, 0));
    const scene_light *light = &s->lights[0];
    int shadowed = 0;
    for (int k = 0; k < 2000; k++) {
        vec3 edge = vec_make(-1, 0, -2 + 4 * (k + 0.5) / 2000);
        ray r;
        r.origin = s->camera.eye;
        r.dir = vec_normalize(vec_sub(edge, r.origin));
        r.tmin = 0;
        r.tmax = HUGE_VAL;
        ray probe = r;
        hit h;
        ck_assert(bvh_intersect(&t.accel, s->prims, &probe, &h));
        trace_stats st;
        memset(&st, 0, sizeof st);
        rgb c = trace_ray(&t, &r, 1, &t.eye_media, 0, &st);
        const scene_prim *p = &s->prims[h.prim];
        ld kd = s->materials[p->material].kd.x;
        lvec to = lv_sub(lv_of(light->position), lv_of(edge));
        ld d = lv_len(to), nl = lv_dot(lv_of(p->u.plane.normal), to) / d;
        ld want = kd * s->ambient.x + kd * light->power.x / (d + light->d0) * nl;
        shadowed += fabsq(c.x - want) > 1e-9 * want;
    }
    ck_assert_int_eq(shadowed, 0);
    tracer_free(&t);
    scene_free(s);
}
END_TEST

START_TEST(test_stress_mirror_box_edges_keep_the_light)
{
    /* [NUM-BOX-1] Rays from inside the closed mirror box aimed exactly at
     * its edges and corners (where two or three faces meet): each must
     * bounce all 1000 times, red = 1000 Kd Ia = 1.  A mirror ray leaving a
     * face next to an edge used to start on, or an ulp beyond, the adjacent
     * face and escape: 38 of 3072 pixels of a 64 x 48 render of the box lost
     * their light (found by `refray verify --stability`). */
    scene_model *s = load_stress("mirror_box_1000");
    tracer t;
    ck_assert(tracer_init(&t, s, 0, 0));
    static const double origins[3][3] = {{0, 0, 0}, {0.3, -0.2, 0.1}, {-0.7, 0.55, -0.35}};
    int rays = 0, lost = 0;
    for (int o = 0; o < 3; o++)
        for (int k = 0; k < 27; k++) {
            int a = k % 3 - 1, b = k / 3 % 3 - 1, c = k / 9 - 1;
            if ((a != 0) + (b != 0) + (c != 0) < 2)
                continue;   /* edges (two of x, y, z at +-1) and corners (three) */
            for (int q = 0; q < 5; q++) {
                double f = -0.8 + 0.4 * q;
                vec3 target = vec_make(a ? a : f, b ? b : f, c ? c : f);
                ray r;
                r.origin = vec_make(origins[o][0], origins[o][1], origins[o][2]);
                r.dir = vec_normalize(vec_sub(target, r.origin));
                r.tmin = 0;
                r.tmax = HUGE_VAL;
                trace_stats st;
                memset(&st, 0, sizeof st);
                rgb col = trace_ray(&t, &r, 1, &t.eye_media, 0, &st);
                rays++;
                lost += !(fabs(col.x - 1.0) <= 1e-12);
            }
        }
    ck_assert_int_gt(rays, 250);
    ck_assert_int_eq(lost, 0);
    tracer_free(&t);
    scene_free(s);
}
END_TEST

START_TEST(test_stress_camera_inside_nested_glass)
{
    /* [NUM-GLASS-2] The camera ray starts with both balls on its stack. */
    img_buf img = render_stress("camera_inside_nested_glass", NULL);
    ck_assert_msg(pixel0(&img, 0) == 1 && pixel0(&img, 1) == 0 && pixel0(&img, 2) == 0, "[%g, %g, %g]",
                  pixel0(&img, 0), pixel0(&img, 1), pixel0(&img, 2));
    img_free(&img);
}
END_TEST

/* ---- cylinders, cones and tori ---------------------------------------- */

/* The REF reference of precision/measure_shapes.h (a quadratic solved in
 * REF from the ray as given; the torus's quartic by a Sturm sequence) for
 * prims[0] along an exact camera ray: 1 on a hit, with the outward normal;
 * *margin how far the ray is from a graze or a rim, relative. */
static int exact_shape(const scene_prim *p, lvec o, lvec d, lvec *n, ld *margin)
{
    qv qo = {o.x, o.y, o.z}, qd = {d.x, d.y, d.z}, normal = {0, 0, 0};
    ld t, cosine;
    int found;
    ck_assert(!p->frame);
    if (p->kind == PRIM_TORUS) {
        qtorus tr = qtorus_of(p->u.torus.center, p->u.torus.axis, p->u.torus.major, p->u.torus.minor);
        found = qtorus_ref_q(&tr, qo, qd, 0, &t, margin, &cosine, &normal);
    } else if (p->kind == PRIM_CONE) {
        qcone c = qcone_of(p->u.cone.from, p->u.cone.to, p->u.cone.radius[0], p->u.cone.radius[1], p->u.cone.open);
        found = qcone_ref_q(&c, qo, qd, 0, &t, margin, &cosine, &normal);
    } else {
        ck_assert_int_eq(p->kind, PRIM_CYLINDER);
        qcone c = qcone_of(p->u.cylinder.from, p->u.cylinder.to, p->u.cylinder.radius, p->u.cylinder.radius,
                           p->u.cylinder.open);
        found = qcone_ref_q(&c, qo, qd, 0, &t, margin, &cosine, &normal);
    }
    *n = lv(normal.x, normal.y, normal.z);
    return found;
}

/* As check_sphere_scene, for a scene whose prims[0] is a cylinder, cone or
 * torus that nothing shadows (lit by distant lights it cannot hide from
 * itself; any other primitive out of view and out of the way). */
static sphere_check check_shape_scene(const char *name, ld edge, ld tol)
{
    sphere_check out = {0, 0, 0, 0};
    render_stats st;
    img_buf img;
    scene_model *s = load_stress(name);
    const scene_prim *p = &s->prims[0];
    render_checked(s, &img, &st);
    for (int j = 0; j < img.height; j++)
        for (int i = 0; i < img.width; i++) {
            lvec o, d, n;
            ld margin;
            exact_camera_ray(s, i, j, &o, &d);
            int hits = exact_shape(p, o, d, &n, &margin);
            double got = img_pixel(&img, i, j)[0];
            if (fabsq(margin) < edge) {
                out.skipped++;
                continue;
            }
            if (!hits) {
                ck_assert_msg(got == s->image.background.x, "%s (%d,%d): %.17g, expected the background", name,
                              i, j, got);
                out.misses++;
                continue;
            }
            ld want = exact_lambert(s, &s->materials[p->material], n, d), rel = fabsq(got - want) / want;
            ck_assert_msg(rel <= tol, "%s (%d,%d): %.17g, expected %.17g (relative error %.3g > %.3g)", name, i, j,
                          got, (double)want, (double)rel, (double)tol);
            out.worst_rel = rel > out.worst_rel ? rel : out.worst_rel;
            out.hits++;
        }
    img_free(&img);
    scene_free(s);
    return out;
}

/* [NUM-QUADRIC-1] Rays 1e-4 rad from the side of a cylinder 1000 long:
 * every cap and side pixel exact, no shadow ray caught by the side it
 * leaves at that angle. */
START_TEST(test_stress_cylinder_grazing)
{
    sphere_check c = check_shape_scene("cylinder_grazing", 1e-9, 1e-9);
    ck_assert_int_gt(c.hits, 800);
    ck_assert_int_gt(c.misses, 100);
    ck_assert_int_lt(c.skipped, 40);
}
END_TEST

/* [NUM-TORUS-1] The torus edge-on, from inside its hole, and thin and far:
 * the exact silhouette and Lambert value at every pixel away from a graze. */
START_TEST(test_stress_torus_edge_on_hole_far)
{
    sphere_check edge = check_shape_scene("torus_edge_on", 1e-9, 1e-9);
    ck_assert_int_gt(edge.hits, 300);
    ck_assert_int_gt(edge.misses, 300);
    sphere_check hole = check_shape_scene("torus_hole", 1e-9, 1e-9);
    ck_assert_int_gt(hole.hits, 300);
    ck_assert_int_gt(hole.misses, 100);
    /* 2.3e6 from the origin a point is known to ulp = 4.7e-10, so the
     * normal of a tube of radius 1e-3 through it only to 4.7e-7: that is
     * the tolerance of the shading there, and the hit points themselves
     * are checked against the tube below. */
    sphere_check far = check_shape_scene("torus_thin_far", 1e-9, 2e-6);
    ck_assert_int_gt(far.hits, 300);
    ck_assert_int_gt(far.misses, 200);
    scene_model *s = load_stress("torus_thin_far");
    const scene_prim *p = &s->prims[0];
    qtorus tr = qtorus_of(p->u.torus.center, p->u.torus.axis, p->u.torus.major, p->u.torus.minor);
    int hits = 0;
    for (int j = 0; j < s->image.height; j++)
        for (int i = 0; i < s->image.width; i++) {
            ray r = camera_ray(&s->camera, camera_half(&s->camera), s->image.width, s->image.height, i + 0.5, j + 0.5);
            hit h;
            if (!isect_prim(p, &r, &h))
                continue;
            hits++;
            ld off = fabsq(qtorus_distance(&tr, q_of(h.point), NULL) - tr.minor);
            ck_assert_msg(off <= 2 * 0x1p-52 * 2.3e6, "(%d,%d): %.3g off the tube", i, j, (double)off);
        }
    ck_assert_int_gt(hits, 300);
    scene_free(s);
}
END_TEST

/* [NUM-QUADRIC-1] The patch around a cone's apex: every pixel exact. */
START_TEST(test_stress_cone_apex)
{
    sphere_check c = check_shape_scene("cone_apex", 1e-9, 1e-9);
    ck_assert_int_gt(c.hits, 32 * 32 - 8);
}
END_TEST

/* [NUM-TORUS-1] The before: the quartic written about the ray's own origin
 * (2.3e6 away) and solved in double misses or misshades pixels that
 * refray's shifted, scaled and polished solve gets right to 1e-9 (the test
 * above), and its hit points lie far off the tube. */
START_TEST(test_stress_naive_torus_fails_where_refray_holds)
{
    scene_model *s = load_stress("torus_thin_far");
    const scene_prim *p = &s->prims[0];
    int wrong = 0, tried = 0;
    for (int j = 0; j < s->image.height; j++)
        for (int i = 0; i < s->image.width; i++) {
            lvec o, d, n;
            ld margin;
            exact_camera_ray(s, i, j, &o, &d);
            int want = exact_shape(p, o, d, &n, &margin);
            if (fabsq(margin) < 1e-6)
                continue;
            ray r = camera_ray(&s->camera, camera_half(&s->camera), s->image.width, s->image.height, i + 0.5, j + 0.5);
            real t;
            tried++;
            int got = naive_torus(p->u.torus.center, p->u.torus.axis, p->u.torus.major, p->u.torus.minor, &r, &t);
            if (got != want) {
                wrong++;
                continue;
            }
            if (!got)
                continue;
            qtorus tr = qtorus_of(p->u.torus.center, p->u.torus.axis, p->u.torus.major, p->u.torus.minor);
            wrong += fabsq(qtorus_distance(&tr, q_of(ray_at(&r, t)), NULL) - tr.minor) > 1e-6 * tr.minor;
        }
    ck_assert_int_gt(tried, 500);
    ck_assert_msg(wrong > tried / 10, "the unshifted quartic got %d of %d pixels wrong", wrong, tried);
    scene_free(s);
}
END_TEST

/* ---- precision per function -------------------------------------------- */

/* [NUM-PREC-1] Every formula of shade.c and every hit test keeps its
 * documented bound (spec/numerics.md, from `make precision` over 10^6
 * inputs against __float128) on 2000 inputs of another seed, against long
 * double, and makes no wrong decision away from the boundary. */
START_TEST(test_precision_bounds)
{
    for (int i = 0; i < MEASURE_COUNT; i++) {
        const measure_fn *f = &measure_table[i];
        if (f->bound == 0 || f->quad_only)
            continue;
        measure m = {0, "-", 0, 0};
        f->run(2000, 977 + (uint64_t)i, &m);
        ck_assert_msg(m.count > 100, "%s: only %ld inputs measured", f->name, m.count);
        ck_assert_msg(m.worst <= f->bound && m.wrong == 0, "%s: worst %.3g %s (bound %g), %ld wrong, at %s",
                      f->name, m.worst, f->unit, f->bound, m.wrong, m.input);
    }
}
END_TEST

static const measure_fn *find_measure(const char *name)
{
    for (int i = 0; i < MEASURE_COUNT; i++)
        if (strcmp(measure_table[i].name, name) == 0)
            return &measure_table[i];
    ck_abort_msg("no measure named %s", name);
    return NULL;
}

/* The befores are worse by orders of magnitude on the same inputs. */
START_TEST(test_precision_befores_are_worse)
{
    static const struct { const char *before, *after; double factor; } pairs[] = {
        {"before: phong pow(V.R, n)", "shade_phong_lobe", 50},
        {"before: phong exp(n log V.R)", "shade_phong_lobe", 50},
        {"before: textbook sphere point", "isect_sphere point", 1e6},
        {"before: textbook cylinder point", "isect_cylinder point", 1e6},
        {"before: unshifted torus quartic point", "isect_torus point", 1e6},
    };
    for (size_t k = 0; k < sizeof pairs / sizeof pairs[0]; k++) {
        measure b = {0, "-", 0, 0}, a = {0, "-", 0, 0};
        find_measure(pairs[k].before)->run(2000, 31, &b);
        find_measure(pairs[k].after)->run(2000, 31, &a);
        ck_assert_msg(b.worst > pairs[k].factor * a.worst, "%s %.3g vs %s %.3g", pairs[k].before, b.worst,
                      pairs[k].after, a.worst);
    }
    /* The textbook refract makes wrong decisions near the critical angle. */
    measure b = {0, "-", 0, 0};
    find_measure("before: textbook refract")->run(20000, 31, &b);
    ck_assert_int_gt(b.wrong, 0);
}
END_TEST

/* ---- the stability tool (src/verify/stability.c) ------------------------------- */

START_TEST(test_stability_raw_round_trip_is_lossless)
{
    /* [NUM-STAB-1] Every long double survives the raw dump bit for bit:
     * thirds, the neighbours of 1, the extremes, -0 and subnormals. */
    stab_image a = {3, 2, NULL, 1, 7}, b;
    long double v[18] = {1.0L / 3, -0.0L, 0, DBL_MAX, 0x1p-1074, LDBL_MAX, LDBL_MIN, nextafterl(0, 1),
                         nextafterl(1, 2), nextafterl(1, 0), 1e-300L / 3, -2.5L, 0.1L, 0.1, 1e308L * 10,
                         3.14159265358979323846264338327950288L, 1, 1e-4940L};
    a.rgb = v;
    FILE *f = tmpfile();
    ck_assert_ptr_nonnull(f);
    ck_assert_int_eq(stability_write_raw(f, &a), 0);
    rewind(f);
    char err[128];
    ck_assert_int_eq(stability_read_raw(f, &b, err, sizeof err), 0);
    fclose(f);
    ck_assert_int_eq(b.width, 3);
    ck_assert_int_eq(b.height, 2);
    ck_assert_int_eq(b.long_double, 1);
    ck_assert_int_eq(b.nonfinite, 7);
    for (int i = 0; i < 18; i++)
        ck_assert_msg(v[i] == b.rgb[i] && signbit(v[i]) == signbit(b.rgb[i]), "value %d: %La became %La", i, v[i],
                      b.rgb[i]);
    stability_free(&b);
    /* Malformed and truncated dumps are refused with a message. */
    static const char *const bad[] = {"", "refray-raw 2 1 1 double 0\n0 0 0\n", "refray-raw 1 1 1 float 0\n0 0 0\n",
                                      "refray-raw 1 2 1 double 0\n0x1p+0 0 0\n", "refray-raw 1 1 1 double 0\n1 zz 0\n"};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        f = tmpfile();
        fputs(bad[k], f);
        rewind(f);
        ck_assert_int_eq(stability_read_raw(f, &b, err, sizeof err), -1);
        ck_assert(err[0] != '\0');
        fclose(f);
    }
}
END_TEST

START_TEST(test_stability_compare_reports_where_and_how_much)
{
    long double x[18], y[18];
    for (int i = 0; i < 18; i++)
        x[i] = y[i] = 0.25L + i;
    y[3 * 5 + 1] *= 1 + 2e-6L;     /* pixel (2, 1), green: 2e-6 relative */
    y[0] *= 1 + 1e-13L;            /* pixel (0, 0), red: 1e-13 */
    y[3 * 1 + 2] = x[3 * 1 + 2] = 0; /* pixel (1, 0), blue: 0 and 0, identical */
    stab_image a = {3, 2, x, 0, 0}, b = {3, 2, y, 1, 0};
    stab_report r;
    img_buf map;
    ck_assert_int_eq(stability_compare(&a, &b, 1e-9L, &r, &map), 0);
    ck_assert_int_eq(r.pixels, 6);
    ck_assert_int_eq(r.beyond, 1);
    ck_assert_int_eq(r.rel_x, 2);
    ck_assert_int_eq(r.rel_y, 1);
    ck_assert(fabsl(r.max_rel - 2e-6L / (1 + 2e-6L)) < 1e-15L);
    ck_assert_int_eq(r.band[0], 4);
    ck_assert_int_eq(r.band[2], 1);   /* 1e-13: 1e-15 .. 1e-12 */
    ck_assert_int_eq(r.band[5], 1);   /* 1e-6 and more */
    /* The map: (17 + log10 rel) / 17, 0 where identical. */
    ck_assert_near(img_pixel(&map, 2, 1)[1], (17 + log10(2e-6 / (1 + 2e-6))) / 17, 1e-12);
    ck_assert(img_pixel(&map, 1, 0)[2] == 0);
    img_free(&map);
    stab_image c = {2, 3, x, 0, 0};
    ck_assert_int_eq(stability_compare(&a, &c, 1e-9L, &r, NULL), -1);
}
END_TEST

START_TEST(test_stability_render_is_render_image)
{
    /* In this build stability_render's pixels are render_image's, exactly
     * (the same render_pixel, only not rounded to double on the way). */
    scene_model *s = load_stress("touching_glass_pair");
    stab_image si;
    ck_assert_int_eq(stability_render(s, NULL, &si), STATUS_OK);
    ck_assert_str_eq(stability_real_name(), sizeof(real) == sizeof(double) ? "double" : "long-double");
    img_buf img;
    render_stats st;
    render_checked(s, &img, &st);
    for (long i = 0; i < 3L * img.width * img.height; i++)
        ck_assert((double)si.rgb[i] == img.rgb[i]);
    stability_free(&si);
    img_free(&img);
    scene_free(s);
}
END_TEST

/* End to end through the command with the long double twin that `make
 * test` builds next to the refray under test (make refray-ld): a stable
 * scene passes, and acne_offset_1e8 (a unit sphere 1.7e8 from the origin,
 * where a coordinate carries 1e-8 of rounding) is reported unstable with
 * exit status 1.  A missing twin fails. */
START_TEST(test_stability_command_end_to_end)
{
    const char *bin = getenv("REFRAY_BIN");
    char twin[512], cmd[1200];
    if (!bin || !*bin)
        bin = "build/refray";
    snprintf(twin, sizeof twin, "%.*s/refray-ld", (int)(strrchr(bin, '/') ? strrchr(bin, '/') - bin : 1),
             strrchr(bin, '/') ? bin : ".");
    ck_assert_msg(access(twin, X_OK) == 0, "%s is missing: build it with make refray-ld", twin);
    snprintf(cmd, sizeof cmd, "%s verify --stability scenes/stress/ortho_far_sphere.scene >/dev/null 2>&1", bin);
    ck_assert_int_eq(system(cmd), 0);
    snprintf(cmd, sizeof cmd, "%s verify --stability scenes/stress/acne_offset_1e8.scene >/dev/null 2>&1", bin);
    int status = system(cmd);
    ck_assert(WIFEXITED(status) && WEXITSTATUS(status) == 1);
}
END_TEST

/* ---- every scene ------------------------------------------------------- */

static int is_scene(const struct dirent *e)
{
    size_t n = strlen(e->d_name);
    return n > 6 && strcmp(e->d_name + n - 6, ".scene") == 0;
}

/* [NUM-FINITE-1] Every stress scene renders with the non-finite counter at 0
 * and every pixel finite. */
START_TEST(test_stress_every_scene_is_finite)
{
    struct dirent **list;
    int n = scandir(STRESS_DIR, &list, is_scene, alphasort);
    ck_assert_int_ge(n, 30);
    for (int i = 0; i < n; i++) {
        char name[256];
        snprintf(name, sizeof name, "%.*s", (int)(strlen(list[i]->d_name) - 6), list[i]->d_name);
        img_buf img = render_stress(name, NULL);
        img_free(&img);
        free(list[i]);
    }
    free(list);
}
END_TEST

Suite *suite_stability(void)
{
    Suite *s = suite_create("stability");
    TCase *scale = tcase_create("scales and silhouettes");
    tcase_add_test(scale, test_stress_tiny_sphere_far);
    tcase_add_test(scale, test_stress_huge_sphere_near);
    tcase_add_test(scale, test_stress_sphere_1e6_far);
    tcase_add_test(scale, test_stress_ortho_far_sphere);
    tcase_add_test(scale, test_stress_terminator);
    tcase_add_test(scale, test_stress_acne_scales);
    tcase_add_test(scale, test_stress_scale_invariance);
    tcase_add_test(scale, test_stress_denormal_coordinates);
    suite_add_tcase(s, scale);
    TCase *quadrics = tcase_create("cylinders, cones and tori");
    tcase_set_timeout(quadrics, 20);
    tcase_add_test(quadrics, test_stress_cylinder_grazing);
    tcase_add_test(quadrics, test_stress_torus_edge_on_hole_far);
    tcase_add_test(quadrics, test_stress_cone_apex);
    tcase_add_test(quadrics, test_stress_naive_torus_fails_where_refray_holds);
    suite_add_tcase(s, quadrics);
    TCase *shading = tcase_create("shading at the limits");
    tcase_add_test(shading, test_stress_phong_exponent_0_and_1e6_peak);
    tcase_add_test(shading, test_stress_phong_exponent_1e6_off_peak);
    tcase_add_test(shading, test_stress_light_on_and_near_the_surface);
    tcase_add_test(shading, test_stress_view_along_the_normal);
    tcase_add_test(shading, test_stress_camera_and_light_inside_sphere);
    tcase_add_test(shading, test_stress_light_inside_box);
    tcase_add_test(shading, test_stress_light_inside_glass);
    tcase_add_test(shading, test_stress_coplanar_disk_on_plane);
    suite_add_tcase(s, shading);
    TCase *glass = tcase_create("glass and mirrors");
    tcase_add_test(glass, test_stress_critical_angle_both_sides);
    tcase_add_test(glass, test_stress_ior_one_is_bit_exact);
    tcase_add_test(glass, test_stress_ior_extreme);
    tcase_add_test(glass, test_stress_mirror_box_depth_1000);
    tcase_add_test(glass, test_stress_touching_glass_is_one_interface);
    tcase_add_test(glass, test_stress_touching_glass_camera_inside);
    tcase_add_test(glass, test_stress_nested_glass_index_matched);
    tcase_add_test(glass, test_stress_camera_inside_nested_glass);
    tcase_add_test(glass, test_stress_glass_on_floor_is_the_gap_limit);
    tcase_add_test(glass, test_stress_glass_on_floor_order_free);
    tcase_add_test(glass, test_stress_glass_on_floor_lit_through_both_faces);
    tcase_add_test(glass, test_stress_glass_touch_is_the_gap_limit);
    suite_add_tcase(s, glass);
    TCase *robust = tcase_create("robust methods");
    tcase_set_timeout(robust, 10);
    tcase_add_test(robust, test_stress_naive_sphere_fails_where_refray_holds);
    tcase_add_test(robust, test_stress_concentric_gap_does_not_leak);
    tcase_add_test(robust, test_stress_naive_spawn_self_hits_far_from_origin);
    tcase_add_test(robust, test_stress_watertight_mesh);
    tcase_add_test(robust, test_stress_thin_triangles);
    tcase_add_test(robust, test_stress_surface_starts_no_self_hit);
    tcase_add_test(robust, test_stress_concave_corner_is_lit);
    tcase_add_test(robust, test_stress_mirror_box_edges_keep_the_light);
    suite_add_tcase(s, robust);
    TCase *tool = tcase_create("stability tool");
    tcase_set_timeout(tool, 20);
    tcase_add_test(tool, test_stability_raw_round_trip_is_lossless);
    tcase_add_test(tool, test_stability_compare_reports_where_and_how_much);
    tcase_add_test(tool, test_stability_render_is_render_image);
    /* valgrind computes x87 long double in double precision, so the twin
     * cannot be told from refray there: under VALGRIND=1 the case is left
     * out (and said to be), not passed. */
    const char *vg = getenv("REFRAY_TEST_VALGRIND");
    if (vg && strcmp(vg, "1") == 0)
        fprintf(stderr, "test_stability: under valgrind the long double end-to-end case is left out\n");
    else
        tcase_add_test(tool, test_stability_command_end_to_end);
    suite_add_tcase(s, tool);
    TCase *precision = tcase_create("precision");
    tcase_set_timeout(precision, 20);
    tcase_add_test(precision, test_precision_bounds);
    tcase_add_test(precision, test_precision_befores_are_worse);
    suite_add_tcase(s, precision);
    TCase *all = tcase_create("every scene");
    tcase_set_timeout(all, 20);
    tcase_add_test(all, test_stress_every_scene_is_finite);
    suite_add_tcase(s, all);
    return s;
}
