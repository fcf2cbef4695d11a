/*
 * check_json_derived.c - the derived members of a JSON scene (the camera's
 * basis, screen and samples, a light's normal and sampling, to_local, the
 * features, the sampling constants) must agree with the primary members
 * they are derived from, or be left out ([JSON-DERIVED-1], spec/json.md).
 * An export loads; an export with one derived member edited is refused at
 * that member, by its pointer, naming the primary members and the
 * tolerance; an edit under the tolerance, and a document without derived
 * members, load.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/scene_file.h"
#include "testlib.h"

#ifdef REFRAY_HAVE_JSON

#include "testjson.h"

/* The camera of the example in spec/json.md (whose basis that text gives),
 * a rectangle and a disk light, a sphere with a transform. */
static const char scene_text[] =
    "image  { width 64 height 48 samples 2 max_depth 3 }\n"
    "camera { eye [0, 2, 6] look_at [0, 0.5, 0] fov 40 }\n"
    "point_light { position [2, 5, 3] power 40 falloff inverse_square }\n"
    "distributed_light { rectangle [-1, 4, -1] [2, 0, 0] [0, 0, 2] power 10 samples 4 falloff none }\n"
    "distributed_light { disk [0, 4, 0] [0, -1, 0] 0.5 power 10 samples 6 }\n"
    "plane { point [0, 0, 0] normal [0, 1, 0] }\n"
    "sphere { center [0, 1, 0] radius 1 scale [1, 0.5, 1] }\n";

static json_t *exported(void)
{
    int status;
    FILE *null = fopen("/dev/null", "w");
    scene_model *s = scene_file_load_text("d.scene", scene_text, strlen(scene_text), NULL, null, 1, &status);
    fclose(null);
    ck_assert_msg(s != NULL, "the scene does not load (%d)", status);
    json_t *doc = testjson_export(s);
    scene_free(s);
    return doc;
}

/* Loads doc; returns the status, the first diagnostic line in first. */
static int load_doc(json_t *doc, char *first, size_t size)
{
    char *text = json_dumps(doc, JSON_INDENT(1) | JSON_REAL_PRECISION(17));
    ck_assert_ptr_nonnull(text);
    FILE *errs = tmpfile();
    int status;
    scene_model *s = scene_file_load_text("d.json", text, strlen(text), NULL, errs, 0, &status);
    rewind(errs);
    if (!fgets(first, (int)size, errs))
        first[0] = '\0';
    fclose(errs);
    free(text);
    scene_free(s);
    return status;
}

/* Sets the number at path (see testjson_at) of a copy of doc to value. */
static json_t *with_number(json_t *doc, const char *path, double value)
{
    json_t *copy = json_deep_copy(doc), *v = testjson_at(copy, path);
    ck_assert_int_eq(json_is_integer(v) ? json_integer_set(v, (json_int_t)value) : json_real_set(v, value), 0);
    return copy;
}

typedef struct edit {
    const char *path;  /* a number of the export */
    double value;      /* what it is set to */
    const char *want;  /* the start of the message, after "error: " */
} edit;

/* Expected values worked out from the scene by hand: forward =
 * (0, -1.5, -6) / sqrt(38.25) = (0, -0.2425.., -0.9701..) (the figures of
 * spec/json.md's example); the 2 x 2 offsets are 0.25 and 0.75; 4 samples
 * make a 2 x 2 grid and 6 a 2 x 3 one; the rectangle's normal is
 * (2, 0, 0) x (0, 0, 2) / 4 = (0, -1, 0); a disk of normal (0, -1, 0)
 * has frame t1 = (1, 0, -0) (Duff et al.: sign 1, a = -1, b = 0); the
 * sample power of 10 over 6 is 1.666..; scale y 0.5 inverts to 2. */
static const edit edits[] = {
    {"camera/basis/forward/1", 0,
     "/camera/basis/forward/1: disagrees with camera.eye, camera.look_at, from which it is derived: expected "
     "-0.24253562503633297, got 0 (a derived member agrees with what it is derived from, numbers within 1e-9 "
     "relative, or is left out: spec/json.md)"},
    {"camera/basis/up/2", 0.5, "/camera/basis/up/2: disagrees with camera.eye, camera.look_at, camera.up"},
    {"camera/screen/aspect", 1, "/camera/screen/aspect: disagrees with image.width, image.height, from which it is "
                                "derived: expected 0.75, got 1"},
    {"camera/screen/half", 0.5, "/camera/screen/half: disagrees with camera.fov"},
    {"camera/screen/example/direction/0", 0, "/camera/screen/example/direction/0: disagrees with the camera and "
                                             "image"},
    {"camera/pixel_samples/offsets/3/0", 0.7, "/camera/pixel_samples/offsets/3/0: disagrees with image.samples, "
                                              "from which it is derived: expected 0.75, got 0.69999999999999996"},
    {"lights/1/normal/1", 1, "/lights/1/normal/1: disagrees with edge_u, edge_v, from which it is derived: expected "
                             "-1, got 1"},
    {"lights/1/sampling/grid/rows", 1, "/lights/1/sampling/grid/rows: disagrees with samples, from which it is "
                                       "derived: expected 2, got 1"},
    {"lights/2/sampling/grid/cols", 2, "/lights/2/sampling/grid/cols: disagrees with samples, from which it is "
                                       "derived: expected 3, got 2"},
    {"lights/2/sampling/sample_power/0", 2, "/lights/2/sampling/sample_power/0: disagrees with power, samples, "
                                            "from which it is derived: expected 1.6666666666666667, got 2"},
    {"lights/2/sampling/frame/t1/0", 0.5, "/lights/2/sampling/frame/t1/0: disagrees with normal, from which it is "
                                          "derived: expected 1, got 0.5"},
    {"lights/2/sampling/example/points/2/1", 3.9, "/lights/2/sampling/example/points/2/1: disagrees with the light, "
                                                  "image.width, image.samples and the sampling rule, from which it "
                                                  "is derived: expected 4, got 3.8999999999999999"},
    {"primitives/1/transform/to_local/1/1", 0.5, "/primitives/1/transform/to_local/1/1: disagrees with to_world (its "
                                                 "inverse), from which it is derived: expected 2, got 0.5"},
    {"conventions/light_samples/constants/shift1", 31, "/conventions/light_samples/constants/shift1: disagrees with "
                                                       "the sampling rule this refray renders with"},
};

/* [JSON-DERIVED-1] An export loads as it is. */
START_TEST(test_json_derived_export_agrees)
{
    char first[1024];
    json_t *doc = exported();
    ck_assert_msg(load_doc(doc, first, sizeof first) == STATUS_OK, "%s", first);
    json_decref(doc);
}
END_TEST

/* [JSON-DERIVED-1] Each derived member edited in turn: refused (65) at it,
 * with its pointer, what it is derived from and the tolerance. */
START_TEST(test_json_derived_edited_refused)
{
    char first[1024];
    json_t *doc = exported();
    const edit *e = &edits[_i];
    json_t *copy = with_number(doc, e->path, e->value);
    ck_assert_int_eq(load_doc(copy, first, sizeof first), STATUS_DATA);
    const char *msg = strstr(first, "error: ");
    ck_assert_msg(strncmp(first, "d.json:", 7) == 0 && msg, "%s: %s", e->path, first);
    ck_assert_msg(strncmp(msg + 7, e->want, strlen(e->want)) == 0, "%s:\n got  %s want %s", e->path, msg + 7,
                  e->want);
    json_decref(copy);
    json_decref(doc);
}
END_TEST

/* [JSON-DERIVED-1] A flag, a hex constant and a text are compared exactly. */
START_TEST(test_json_derived_exact_members)
{
    char first[1024];
    json_t *doc = exported();
    json_t *copy = json_deep_copy(doc);
    json_object_set_new(testjson_at(copy, "features"), "shadows", json_false());
    ck_assert_int_eq(load_doc(copy, first, sizeof first), STATUS_DATA);
    ck_assert_msg(strstr(first, "error: /features/shadows: disagrees with the materials, lights and primitives, from "
                                "which it is derived: expected true, got false"), "%s", first);
    json_decref(copy);
    copy = json_deep_copy(doc);
    json_object_set_new(testjson_at(copy, "conventions/light_samples/constants"), "pixel_salt", json_string("0x5eee"));
    ck_assert_int_eq(load_doc(copy, first, sizeof first), STATUS_DATA);
    ck_assert_msg(strstr(first, "error: /conventions/light_samples/constants/pixel_salt: disagrees with the sampling "
                                "rule this refray renders with, from which it is derived: expected \"0x5eed\""),
                  "%s", first);
    json_decref(copy);
    copy = json_deep_copy(doc);
    json_object_set_new(testjson_at(copy, "lights/1/sampling/example"), "key", json_string("0x1"));
    ck_assert_int_eq(load_doc(copy, first, sizeof first), STATUS_DATA);
    ck_assert_msg(strstr(first, "error: /lights/1/sampling/example/key: disagrees with the pixel and camera sample"),
                  "%s", first);
    json_decref(copy);
    copy = json_deep_copy(doc);
    json_object_set_new(testjson_at(copy, "camera/basis"), "fwd", json_true());
    ck_assert_int_eq(load_doc(copy, first, sizeof first), STATUS_DATA);
    ck_assert_msg(strstr(first, "error: /camera/basis/fwd: unknown field 'fwd'"), "%s", first);
    json_decref(copy);
    /* The sampling constants are an object of their members only, as every
     * derived object: an unknown constant or a number in their place was
     * taken silently before. */
    copy = json_deep_copy(doc);
    json_object_set_new(testjson_at(copy, "conventions/light_samples/constants"), "mul3", json_string("0x1"));
    ck_assert_int_eq(load_doc(copy, first, sizeof first), STATUS_DATA);
    ck_assert_msg(strstr(first, "error: /conventions/light_samples/constants/mul3: unknown field 'mul3'"), "%s", first);
    json_decref(copy);
    /* A hex constant is hex digits after 0x: "0x0x5eed" and "0x 5eed" (which
     * strtoull reads as 0x5eed) loaded before. */
    static const char *const not_hex[] = {"0x0x5eed", "0x 5eed", "0x-5eed"};
    for (int i = 0; i < 3; i++) {
        copy = json_deep_copy(doc);
        json_object_set_new(testjson_at(copy, "conventions/light_samples/constants"), "pixel_salt",
                            json_string(not_hex[i]));
        ck_assert_msg(load_doc(copy, first, sizeof first) == STATUS_DATA, "%s loaded", not_hex[i]);
        json_decref(copy);
    }
    copy = json_deep_copy(doc);
    json_object_set_new(testjson_at(copy, "conventions/light_samples"), "constants", json_integer(5));
    ck_assert_int_eq(load_doc(copy, first, sizeof first), STATUS_DATA);
    ck_assert_msg(strstr(first, "error: /conventions/light_samples/constants: expected an object"), "%s", first);
    json_decref(copy);
    json_decref(doc);
}
END_TEST

/* [JSON-DERIVED-1] The tolerance: 1e-12 relative passes (another
 * exporter's last bits), 1e-8 relative does not; a document with every
 * derived member left out loads. */
START_TEST(test_json_derived_tolerance_and_absence)
{
    char first[1024];
    json_t *doc = exported();
    double t = testjson_num(doc, "camera/basis/forward/2");
    json_t *copy = with_number(doc, "camera/basis/forward/2", t * (1 + 1e-12));
    ck_assert_msg(load_doc(copy, first, sizeof first) == STATUS_OK, "%s", first);
    json_decref(copy);
    copy = with_number(doc, "camera/basis/forward/2", t * (1 + 1e-8));
    ck_assert_int_eq(load_doc(copy, first, sizeof first), STATUS_DATA);
    json_decref(copy);
    copy = json_deep_copy(doc);
    json_object_del(copy, "conventions");
    json_object_del(copy, "features");
    json_t *cam = testjson_at(copy, "camera");
    json_object_del(cam, "basis");
    json_object_del(cam, "screen");
    json_object_del(cam, "pixel_samples");
    for (size_t i = 1; i < 3; i++) {
        json_t *l = json_array_get(json_object_get(copy, "lights"), i);
        json_object_del(l, "sampling");
        if (i == 1)
            json_object_del(l, "normal");
    }
    json_object_del(testjson_at(copy, "primitives/1/transform"), "to_local");
    ck_assert_msg(load_doc(copy, first, sizeof first) == STATUS_OK, "%s", first);
    json_decref(copy);
    json_decref(doc);
}
END_TEST

#endif

Suite *suite_json_derived(void)
{
    Suite *s = suite_create("json_derived");
    TCase *tc = tcase_create("json_derived");
#ifdef REFRAY_HAVE_JSON
    tcase_add_test(tc, test_json_derived_export_agrees);
    tcase_add_loop_test(tc, test_json_derived_edited_refused, 0, (int)(sizeof edits / sizeof edits[0]));
    tcase_add_test(tc, test_json_derived_exact_members);
    tcase_add_test(tc, test_json_derived_tolerance_and_absence);
#endif
    suite_add_tcase(s, tc);
    return s;
}
