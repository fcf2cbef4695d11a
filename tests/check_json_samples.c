/*
 * check_json_samples.c - the camera rays and the light samples of a scene
 * recomputed from its JSON export alone (spec/json.md, "Camera rays",
 * "Light samples"), and matched with the renderer bit for bit.
 *
 * The code here is written from the export's description (conventions,
 * camera.basis, camera.screen, lights[].sampling), not from refray's source:
 * the hash's constants are read from the document, the grid is found by
 * another search, the frame and the concentric map from the formulas in
 * the text.  The renderer's side is what render_pixel and the tracer call:
 * render_sample_key, camera_ray, trace_light_setup, trace_light_point; a
 * whole rendered pixel is checked too, against a sum computed from the
 * recomputed samples [JSON-SAMPLES-1] [JSON-CAMERA-1].
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "base/sampler.h"
#include "export/export_json.h"
#include "io/scene_file.h"
#include "render/camera.h"
#include "render/render.h"
#include "testlib.h"

#ifdef REFRAY_HAVE_JSON

#include "testjson.h"

/* A tilted disk with a prime sample count (one row), a rectangle of 12
 * (3 x 4) and a disk facing -z (the other branch of the frame); 3 x 3
 * camera samples. */
static const char lights_scene[] =
    "image { width 7 height 5 samples 3 max_depth 3 }\n"
    "camera { eye [0.3, 4, 5] look_at [0, 0, 0] up [0, 1, 0] fov 50 }\n"
    "distributed_light { disk [0.5, 3, -0.25] [0.3, -1, 0.2] 0.75 samples 7 power 3 }\n"
    "distributed_light { rectangle [-1, 4, -1] [2, 0, 0.5] [0, 0.25, 2] samples 12 power [1, 2, 3] }\n"
    "distributed_light { disk [0, 1, 3] [0, 0, -1] 1.5 samples 16 falloff inverse_square }\n"
    /* past the tracer's TRACE_MIXED_SAMPLES (64): counters mixed per sample */
    "distributed_light { rectangle [1, 5, 0.5] [-0.5, 0, 0.25] [0, -0.5, 1] samples 70 power 0.5 }\n"
    "sphere { radius 0.5 material { Ks 0.5 t 0.5 ior 1.5 } }\n"
    "plane { }\n";

/* An orthographic camera straight down on a white plane lit by a
 * rectangle: a pixel is a sum over the light's samples only. */
static const char pixel_scene[] =
    "image { width 8 height 6 samples 2 max_depth 1 }\n"
    "camera { orthographic eye [0.1, 5, 0.2] look_at [0.1, 0, 0.2] up [0, 0, -1] width 4 }\n"
    "distributed_light { rectangle [-1, 2, -1.25] [2, 0, 0] [0, 0.5, 2.5] samples 6 power 8 falloff none }\n"
    "plane { material { Kd 1 } }\n";

/* The same with 150 samples: past add_distributed's batch of 64 points
 * (two whole batches and part of a third) and the tracer's 64 premixed
 * counters. */
static const char pixel_scene_many[] =
    "image { width 8 height 6 samples 2 max_depth 1 }\n"
    "camera { orthographic eye [0.1, 5, 0.2] look_at [0.1, 0, 0.2] up [0, 0, -1] width 4 }\n"
    "distributed_light { rectangle [-1, 2, -1.25] [2, 0, 0] [0, 0.5, 2.5] samples 150 power 8 falloff none }\n"
    "plane { material { Kd 1 } }\n";

typedef struct rule {
    uint64_t gamma, mul1, mul2, salt, light, mirror, transmitted;
    int shift1, shift2, shift3;
} rule;

static vec3 vec(json_t *v, const char *path)
{
    json_t *x = testjson_at(v, path);
    return vec_make(testjson_num(x, "0"), testjson_num(x, "1"), testjson_num(x, "2"));
}

static uint64_t hex_or_int(json_t *c, const char *key)
{
    json_t *x = testjson_at(c, key);
    if (json_is_integer(x))
        return (uint64_t)json_integer_value(x);
    ck_assert_msg(json_is_string(x), "%s is neither a number nor a hex string", key);
    return strtoull(json_string_value(x), NULL, 16);
}

static rule read_rule(json_t *doc)
{
    json_t *c = testjson_at(doc, "conventions/light_samples/constants");
    rule r;
    r.gamma = hex_or_int(c, "gamma");
    r.mul1 = hex_or_int(c, "mul1");
    r.mul2 = hex_or_int(c, "mul2");
    r.shift1 = (int)hex_or_int(c, "shift1");
    r.shift2 = (int)hex_or_int(c, "shift2");
    r.shift3 = (int)hex_or_int(c, "shift3");
    r.salt = hex_or_int(c, "pixel_salt");
    r.light = hex_or_int(c, "light");
    r.mirror = hex_or_int(c, "mirror");
    r.transmitted = hex_or_int(c, "transmitted");
    return r;
}

static uint64_t mix(const rule *r, uint64_t z)
{
    z += r->gamma;
    z = (z ^ (z >> r->shift1)) * r->mul1;
    z = (z ^ (z >> r->shift2)) * r->mul2;
    return z ^ (z >> r->shift3);
}

static uint64_t key(const rule *r, uint64_t k, uint64_t c)
{
    return mix(r, k ^ mix(r, c));
}

static double uniform(const rule *r, uint64_t k)
{
    return (double)(mix(r, k) >> 11) * 0x1p-53;
}

/* rows: the largest divisor of n not above sqrt(n), found upward. */
static void grid(int n, int *rows, int *cols)
{
    *rows = 1;
    for (int d = 1; (long)d * d <= n; d++)
        if (n % d == 0)
            *rows = d;
    *cols = n / *rows;
}

static void frame(vec3 n, vec3 *t1, vec3 *t2)
{
    double sign = n.z < 0 || (n.z == 0 && signbit(n.z)) ? -1.0 : 1.0;
    double a = -1 / (sign + n.z), b = n.x * n.y * a;
    *t1 = vec_make(1 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    *t2 = vec_make(b, sign + n.y * n.y * a, -n.y);
}

static void concentric(double s, double t, double *x, double *y)
{
    double a = 2 * s - 1, b = 2 * t - 1, r, phi;
    const double pi = 3.14159265358979323846;
    if (a == 0 && b == 0) {
        *x = *y = 0;
        return;
    }
    if (fabs(a) > fabs(b)) {
        r = a;
        phi = (pi / 4) * (b / a);
    } else {
        r = b;
        phi = pi / 2 - (pi / 4) * (a / b);
    }
    *x = r * cos(phi);
    *y = r * sin(phi);
}

/* Sample j of light li (the JSON object l) at a hit of a ray with key K. */
static vec3 sample_point(const rule *r, json_t *l, int li, uint64_t K, int j)
{
    int rows, cols, n = (int)testjson_num(l, "samples");
    grid(n, &rows, &cols);
    uint64_t L = key(r, K, r->light + (uint64_t)li);
    double u1 = uniform(r, key(r, L, 2 * (uint64_t)j)), u2 = uniform(r, key(r, L, 2 * (uint64_t)j + 1));
    double s = (j % cols + u1) / cols, t = (j / cols + u2) / rows;
    if (strcmp(json_string_value(testjson_at(l, "kind")), "rectangle") == 0)
        return vec_add(vec(l, "corner"), vec_add(vec_scale(vec(l, "edge_u"), s), vec_scale(vec(l, "edge_v"), t)));
    vec3 t1, t2;
    double x, y, radius = testjson_num(l, "radius");
    frame(vec(l, "normal"), &t1, &t2);
    concentric(s, t, &x, &y);
    return vec_add(vec(l, "center"), vec_add(vec_scale(t1, x * radius), vec_scale(t2, y * radius)));
}

static uint64_t camera_key(const rule *r, int width, int k, int i, int j, int a, int b)
{
    return key(r, key(r, (uint64_t)j * (uint64_t)width + (uint64_t)i, r->salt), (uint64_t)(b * k + a));
}

static scene_model *load(const char *text)
{
    int status;
    FILE *null = fopen("/dev/null", "w");
    scene_model *s = scene_file_load_text("t.scene", text, strlen(text), NULL, null, 1, &status);
    fclose(null);
    ck_assert_msg(s != NULL, "scene did not load (%d)", status);
    return s;
}

static int same_bits(vec3 a, vec3 b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* The grid, the frame and the worked example of each light as exported
 * agree with the description. */
START_TEST(test_json_light_sampling_block)
{
    scene_model *s = load(lights_scene);
    json_t *doc = testjson_export(s);
    rule r = read_rule(doc);
    static const int want_rows[] = {1, 3, 4}, want_cols[] = {7, 4, 4};
    for (int li = 0; li < 3; li++) {
        json_t *l = json_array_get(testjson_at(doc, "lights"), (size_t)li);
        int rows, cols;
        grid((int)testjson_num(l, "samples"), &rows, &cols);
        ck_assert_int_eq(rows, want_rows[li]);
        ck_assert_int_eq(cols, want_cols[li]);
        ck_assert_int_eq((int)testjson_num(l, "sampling/grid/rows"), rows);
        ck_assert_int_eq((int)testjson_num(l, "sampling/grid/cols"), cols);
        if (strcmp(json_string_value(testjson_at(l, "kind")), "disk") == 0) {
            vec3 t1, t2;
            frame(vec(l, "normal"), &t1, &t2);
            ck_assert(same_bits(t1, vec(l, "sampling/frame/t1")));
            ck_assert(same_bits(t2, vec(l, "sampling/frame/t2")));
        }
        uint64_t K = camera_key(&r, 7, 3, 0, 0, 0, 0);
        ck_assert_uint_eq(K, strtoull(json_string_value(testjson_at(l, "sampling/example/key")), NULL, 16));
        json_t *points = testjson_at(l, "sampling/example/points");
        for (size_t j = 0; j < json_array_size(points); j++) {
            char path[32];
            snprintf(path, sizeof path, "%zu", j);
            ck_assert_msg(same_bits(sample_point(&r, l, li, K, (int)j), vec(points, path)),
                          "light %d: example point %zu", li, j);
        }
    }
    json_decref(doc);
    scene_free(s);
}
END_TEST

/* [JSON-SAMPLES-1] Every sample of every light, for camera rays of
 * several pixels and sub-samples and for rays spawned below them, is the
 * renderer's point to the last bit. */
START_TEST(test_json_light_samples_match_renderer)
{
    scene_model *s = load(lights_scene);
    json_t *doc = testjson_export(s);
    rule r = read_rule(doc);
    static const int pixels[][2] = {{0, 0}, {3, 2}, {6, 4}, {1, 4}};
    int w = s->image.width, k = s->image.samples, checked = 0;
    for (int li = 0; li < s->light_count; li++) {
        json_t *l = json_array_get(testjson_at(doc, "lights"), (size_t)li);
        light_setup setup = trace_light_setup(&s->lights[li], s->lights[li].samples);
        for (size_t p = 0; p < sizeof pixels / sizeof pixels[0]; p++)
            for (int b = 0; b < k; b++)
                for (int a = 0; a < k; a++) {
                    uint64_t mine[4], theirs[4];
                    mine[0] = camera_key(&r, w, k, pixels[p][0], pixels[p][1], a, b);
                    theirs[0] = render_sample_key(w, k, pixels[p][0], pixels[p][1], a, b);
                    mine[1] = key(&r, mine[0], r.mirror);
                    theirs[1] = sampler_key(theirs[0], TRACE_KEY_MIRROR);
                    mine[2] = key(&r, mine[0], r.transmitted);
                    theirs[2] = sampler_key(theirs[0], TRACE_KEY_REFRACT);
                    mine[3] = key(&r, mine[1], r.transmitted);
                    theirs[3] = sampler_key(theirs[1], TRACE_KEY_REFRACT);
                    for (int path = 0; path < 4; path++)
                        for (int j = 0; j < s->lights[li].samples; j++, checked++)
                            ck_assert_msg(same_bits(sample_point(&r, l, li, mine[path], j),
                                                    trace_light_point(&s->lights[li], &setup, li, theirs[path], j)),
                                          "light %d, pixel %zu, sample (%d, %d), path %d, point %d", li, p, a, b,
                                          path, j);
                }
    }
    ck_assert_int_eq(checked, 4 * 9 * 4 * (7 + 12 + 16 + 70));
    json_decref(doc);
    scene_free(s);
}
END_TEST

/* |v| and v / |v| as conventions.camera_ray defines them. */
static vec3 unit(vec3 v)
{
    double m = fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
    double x = v.x / m, y = v.y / m, z = v.z / m, len = m * sqrt(x * x + y * y + z * z);
    return vec_make(v.x / len, v.y / len, v.z / len);
}

/* The camera ray through image point (x, y), from the export. */
static void export_ray(json_t *cam, int width, int height, double x, double y, vec3 *origin, vec3 *dir)
{
    double aspect = testjson_num(cam, "screen/aspect"), half = testjson_num(cam, "screen/half");
    double sx = 2 * x / width - 1, sy = 1 - 2 * y / height;
    vec3 right = vec(cam, "basis/right"), up = vec(cam, "basis/up"), forward = vec(cam, "basis/forward");
    vec3 offset = vec_add(vec_scale(right, sx * half), vec_scale(up, sy * half * aspect));
    if (strcmp(json_string_value(testjson_at(cam, "projection")), "orthographic") == 0) {
        *origin = vec_add(vec(cam, "eye"), offset);
        *dir = forward;
    } else {
        *origin = vec(cam, "eye");
        *dir = unit(vec_add(forward, offset));
    }
}

/* [JSON-CAMERA-1] Every camera sample of every pixel: the exported offsets
 * are (a + 0.5) / k, and the ray from the formula is camera_ray's, bit for
 * bit, perspective and orthographic. */
START_TEST(test_json_camera_rays_match_renderer)
{
    static const char *const scenes[] = {lights_scene, pixel_scene};
    for (int sc = 0; sc < 2; sc++) {
        scene_model *s = load(scenes[sc]);
        json_t *doc = testjson_export(s), *cam = testjson_at(doc, "camera");
        int w = s->image.width, h = s->image.height, k = s->image.samples;
        ck_assert_int_eq((int)testjson_num(cam, "pixel_samples/k"), k);
        json_t *offsets = testjson_at(cam, "pixel_samples/offsets");
        ck_assert_int_eq(json_array_size(offsets), k * k);
        for (int b = 0; b < k; b++)
            for (int a = 0; a < k; a++) {
                char path[32];
                snprintf(path, sizeof path, "%d/0", b * k + a);
                ck_assert_double_eq(testjson_num(offsets, path), (a + 0.5) / k);
                snprintf(path, sizeof path, "%d/1", b * k + a);
                ck_assert_double_eq(testjson_num(offsets, path), (b + 0.5) / k);
                for (int j = 0; j < h; j++)
                    for (int i = 0; i < w; i++) {
                        double x = i + (a + 0.5) / k, y = j + (b + 0.5) / k;
                        vec3 o, d;
                        export_ray(cam, w, h, x, y, &o, &d);
                        ray want = camera_ray(&s->camera, camera_half(&s->camera), w, h, x, y);
                        ck_assert_msg(same_bits(o, want.origin) && same_bits(d, want.dir),
                                      "scene %d: pixel (%d, %d) sample (%d, %d)", sc, i, j, a, b);
                    }
            }
        json_decref(doc);
        scene_free(s);
    }
}
END_TEST

/* [JSON-SAMPLES-1] A rendered pixel is the mean over its camera samples of
 * the sum over the light's samples of Kd E/N max(0, N.L): computed here
 * from the export (camera rays meet the plane y = 0; N = +y), it matches
 * the renderer to rounding, so the renderer uses these samples and keys. */
static void pixel_from_export(const char *text)
{
    scene_model *s = load(text);
    json_t *doc = testjson_export(s), *cam = testjson_at(doc, "camera"), *l = testjson_at(doc, "lights/0");
    rule r = read_rule(doc);
    img_buf img;
    ck_assert_int_eq(render_image(s, NULL, &img, NULL), 0);
    int w = s->image.width, h = s->image.height, k = s->image.samples, n = (int)testjson_num(l, "samples");
    double e = testjson_num(l, "sampling/sample_power/0"), kd = testjson_num(doc, "materials/0/Kd/0");
    for (int j = 0; j < h; j++)
        for (int i = 0; i < w; i++) {
            double sum = 0;
            for (int b = 0; b < k; b++)
                for (int a = 0; a < k; a++) {
                    vec3 o, d;
                    export_ray(cam, w, h, i + (a + 0.5) / k, j + (b + 0.5) / k, &o, &d);
                    vec3 on_plane = vec_make(o.x, 0, o.z);
                    uint64_t K = camera_key(&r, w, k, i, j, a, b);
                    for (int q = 0; q < n; q++) {
                        vec3 to = vec_sub(sample_point(&r, l, 0, K, q), on_plane);
                        sum += kd * e * fmax(0, to.y / vec_length(to));
                    }
                }
            ck_assert_rel(img_pixel(&img, i, j)[0], sum / (k * k), 1e-13);
        }
    img_free(&img);
    json_decref(doc);
    scene_free(s);
}

START_TEST(test_json_pixel_from_export)
{
    pixel_from_export(pixel_scene);
}
END_TEST

/* Each batch of points is the samples' own: a batch that reused the first
 * one's points or went past the light's samples would fail here. */
START_TEST(test_json_pixel_from_export_many_samples)
{
    pixel_from_export(pixel_scene_many);
}
END_TEST

#endif

Suite *suite_json_samples(void)
{
    Suite *s = suite_create("json_samples");
    TCase *tc = tcase_create("json_samples");
#ifdef REFRAY_HAVE_JSON
    tcase_add_test(tc, test_json_light_sampling_block);
    tcase_add_test(tc, test_json_light_samples_match_renderer);
    tcase_add_test(tc, test_json_camera_rays_match_renderer);
    tcase_add_test(tc, test_json_pixel_from_export);
    tcase_add_test(tc, test_json_pixel_from_export_many_samples);
#endif
    suite_add_tcase(s, tc);
    return s;
}
