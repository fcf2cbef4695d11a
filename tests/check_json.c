/*
 * check_json.c - JSON scenes (spec/json.md): `refray export --to json`
 * (src/export/export_json*.c) and reading them back (src/scene/
 * load_json*.c), through the library and the command line.
 *
 * The test that the export is complete [JSON-ROUNDTRIP-1]: for every scene
 * under scenes/, the model read back from its export equals the model read
 * from the .scene field by field, bit for bit, and the two render to the
 * same doubles, compared with memcmp.  Scenes that take long to render are
 * rendered at a small size (the same for both), which is enough: the model
 * itself is compared whole.
 *
 * Expected values elsewhere come from spec/language.md (the defaults) and
 * from decimal literals read by strtod, never from the export itself.
 * Without jansson (JSON=0) only the refusal tests run [JSON-NOJSON-1].
 */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "export/export_json.h"
#include "io/scene_file.h"
#include "render/render.h"
#include "cli_testlib.h"
#include "testlib.h"

#if REFRAY_HAVE_JSON

#include "testjson.h"

enum { MIN_SCENES = 70, MAX_SCENES = 256, NAME_MAX_LEN = 256 };

typedef struct scene_list {
    char names[MAX_SCENES][NAME_MAX_LEN];
    int count;
} scene_list;

static int by_name(const void *a, const void *b)
{
    return strcmp((const char *)a, (const char *)b);
}

static void list_dir(scene_list *l, const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    while (d && (e = readdir(d)) != NULL && l->count < MAX_SCENES) {
        size_t n = strlen(e->d_name);
        char path[NAME_MAX_LEN];
        if (e->d_name[0] == '.' || (size_t)snprintf(path, sizeof path, "%s/%s", dir, e->d_name) >= sizeof path)
            continue;
        struct stat sb;
        if (stat(path, &sb) == 0 && S_ISDIR(sb.st_mode) && strchr(dir, '/') == NULL)
            list_dir(l, path);
        else if (n > 6 && strcmp(e->d_name + n - 6, ".scene") == 0)
            strcpy(l->names[l->count++], path);
    }
    if (d)
        closedir(d);
}

/* Every .scene file of scenes/ and its subfolders, sorted. */
static void scenes_read(scene_list *l)
{
    l->count = 0;
    list_dir(l, "scenes");
    qsort(l->names, (size_t)l->count, sizeof l->names[0], by_name);
}

static scene_model *load_quiet(const char *path, const char *text, size_t len, int *status)
{
    FILE *null = fopen("/dev/null", "w");
    scene_model *s = text ? scene_file_load_text(path, text, len, NULL, null, 1, status)
                       : scene_file_load(path, NULL, null, 1, status);
    if (null)
        fclose(null);
    return s;
}

/* The export of s as text (malloc'd). */
static char *export_text(const scene_model *s, const export_json_opts *o, size_t *len)
{
    char *buf = NULL, err[256] = "";
    FILE *fp = open_memstream(&buf, len);
    ck_assert_ptr_nonnull(fp);
    int rc = export_json_write(s, o, fp, err, sizeof err);
    fclose(fp);
    ck_assert_msg(rc == 0, "export failed (%d): %s", rc, err);
    return buf;
}

/* The scene read back from its export (json_path names it for messages
 * and mesh files). */
static scene_model *round_trip(const scene_model *s, const export_json_opts *o, const char *json_path)
{
    size_t len;
    int status;
    char *text = export_text(s, o, &len);
    FILE *errs = tmpfile();
    scene_model *back = scene_file_load_text(json_path, text, len, NULL, errs, 0, &status);
    if (!back) {
        char msg[1024] = "";
        rewind(errs);
        size_t n = fread(msg, 1, sizeof msg - 1, errs);
        msg[n] = '\0';
        ck_abort_msg("%s: the export does not load (status %d):\n%s", json_path, status, msg);
    }
    fclose(errs);
    free(text);
    return back;
}

#define SAME_BITS(a, b, what, i)                                                                    \
    ck_assert_msg(memcmp(&(a), &(b), sizeof(a)) == 0, "%s: %s %d differs after the round trip", name, \
                  what, (int)(i))

static void same_name(const char *a, const char *b, const char *name, const char *what)
{
    ck_assert_msg((!a && !b) || (a && b && strcmp(a, b) == 0), "%s: %s: '%s' != '%s'", name, what,
                  a ? a : "(null)", b ? b : "(null)");
}

static void same_prim(const scene_prim *a, const scene_prim *b, const char *name, int i)
{
    ck_assert_msg(a->kind == b->kind && a->material == b->material && a->mesh == b->mesh &&
                      (a->frame != NULL) == (b->frame != NULL),
                  "%s: primitive %d: kind, material, mesh or frame presence differs", name, i);
    switch (a->kind) {
    case PRIM_SPHERE: SAME_BITS(a->u.sphere, b->u.sphere, "sphere", i); break;
    case PRIM_PLANE: SAME_BITS(a->u.plane, b->u.plane, "plane", i); break;
    case PRIM_DISK: SAME_BITS(a->u.disk, b->u.disk, "disk", i); break;
    case PRIM_BOX: SAME_BITS(a->u.box, b->u.box, "box", i); break;
    case PRIM_CYLINDER:
        SAME_BITS(a->u.cylinder.from, b->u.cylinder.from, "cylinder from", i);
        SAME_BITS(a->u.cylinder.to, b->u.cylinder.to, "cylinder to", i);
        SAME_BITS(a->u.cylinder.radius, b->u.cylinder.radius, "cylinder radius", i);
        ck_assert_int_eq(a->u.cylinder.open, b->u.cylinder.open);
        break;
    case PRIM_CONE:
        SAME_BITS(a->u.cone.from, b->u.cone.from, "cone from", i);
        SAME_BITS(a->u.cone.to, b->u.cone.to, "cone to", i);
        SAME_BITS(a->u.cone.radius, b->u.cone.radius, "cone radii", i);
        ck_assert_int_eq(a->u.cone.open, b->u.cone.open);
        break;
    case PRIM_TORUS: SAME_BITS(a->u.torus, b->u.torus, "torus", i); break;
    case PRIM_TRIANGLE:
        SAME_BITS(a->u.triangle.p, b->u.triangle.p, "triangle", i);
        ck_assert_int_eq(a->u.triangle.n != NULL, b->u.triangle.n != NULL);
        if (a->u.triangle.n)
            ck_assert_msg(memcmp(a->u.triangle.n, b->u.triangle.n, 3 * sizeof *a->u.triangle.n) == 0,
                          "%s: triangle normals %d differ after the round trip", name, i);
        break;
    case PRIM_MESH: break; /* a view of its mesh's store: same_mesh */
    }
    if (a->frame) {
        SAME_BITS(a->frame->to_world, b->frame->to_world, "to_world of primitive", i);
        SAME_BITS(a->frame->to_local, b->frame->to_local, "to_local of primitive", i);
    }
}

static void same_light(const scene_light *a, const scene_light *b, const char *name, int i)
{
    ck_assert_msg(a->kind == b->kind && a->falloff == b->falloff && a->samples == b->samples,
                  "%s: light %d: kind, falloff or samples differs", name, i);
    SAME_BITS(a->power, b->power, "power of light", i);
    SAME_BITS(a->d0, b->d0, "d0 of light", i);
    SAME_BITS(a->position, b->position, "position of light", i);
    SAME_BITS(a->direction, b->direction, "direction of light", i);
    SAME_BITS(a->edge_u, b->edge_u, "edge_u of light", i);
    SAME_BITS(a->edge_v, b->edge_v, "edge_v of light", i);
    SAME_BITS(a->normal, b->normal, "normal of light", i);
    SAME_BITS(a->radius, b->radius, "radius of light", i);
}

static void same_material(const scene_material *a, const scene_material *b, const char *name, int i)
{
    SAME_BITS(a->kd, b->kd, "Kd of material", i);
    SAME_BITS(a->ks, b->ks, "Ks of material", i);
    SAME_BITS(a->n, b->n, "n of material", i);
    SAME_BITS(a->t, b->t, "t of material", i);
    SAME_BITS(a->ior, b->ior, "ior of material", i);
    same_name(a->name, b->name, name, "material name");
}

static void same_camera(const scene_camera *a, const scene_camera *b, const char *name)
{
    ck_assert_int_eq(a->kind, b->kind);
    SAME_BITS(a->eye, b->eye, "camera eye", 0);
    SAME_BITS(a->look_at, b->look_at, "camera look_at", 0);
    SAME_BITS(a->up, b->up, "camera up", 0);
    SAME_BITS(a->fov, b->fov, "camera fov", 0);
    SAME_BITS(a->width, b->width, "camera width", 0);
    SAME_BITS(a->forward, b->forward, "camera forward", 0);
    SAME_BITS(a->right, b->right, "camera right", 0);
    SAME_BITS(a->true_up, b->true_up, "camera true_up", 0);
}

#define SAME_ARRAY(a, b, n, what)                                                                          \
    ck_assert_msg(((a) == NULL) == ((b) == NULL) && (!(a) || memcmp((a), (b), (size_t)(n) * sizeof *(a)) == 0), \
                  "%s: mesh %d: %s differ after the round trip", name, i, what)

/* A mesh's store, every array the tracer reads, bit for bit. */
static void same_mesh(const scene_mesh *ma, const scene_mesh *mb, const char *name, int i)
{
    const scene_trimesh *a = &ma->geom, *b = &mb->geom;
    ck_assert_msg(ma->prim == mb->prim && a->position_count == b->position_count &&
                      a->normal_count == b->normal_count && a->tri_count == b->tri_count && a->closed == b->closed,
                  "%s: mesh %d: primitive, counts or closedness differ", name, i);
    SAME_ARRAY(a->positions, b->positions, a->position_count, "positions");
    SAME_ARRAY(a->normals, b->normals, a->normal_count, "normals");
    SAME_ARRAY(a->tri, b->tri, a->tri_count, "triangles");
    SAME_ARRAY(a->tri_normal, b->tri_normal, a->tri_count, "triangle normals");
    SAME_ARRAY(a->open, b->open, a->tri_count, "open edges");
}

/* Everything the tracer reads, compared bit for bit (spans and mesh
 * paths, which only diagnostics read, are left out). */
static void same_scene(const scene_model *a, const scene_model *b, const char *name)
{
    ck_assert_msg(a->prim_count == b->prim_count && a->light_count == b->light_count &&
                      a->material_count == b->material_count && a->mesh_count == b->mesh_count,
                  "%s: counts differ after the round trip", name);
    ck_assert_msg(memcmp(&a->image, &b->image, sizeof a->image) == 0, "%s: image differs", name);
    ck_assert_msg(memcmp(&a->features, &b->features, sizeof a->features) == 0, "%s: features differ", name);
    SAME_BITS(a->ambient, b->ambient, "ambient", 0);
    same_name(a->oracle, b->oracle, name, "oracle");
    same_camera(&a->camera, &b->camera, name);
    for (int i = 0; i < a->material_count; i++)
        same_material(&a->materials[i], &b->materials[i], name, i);
    for (int i = 0; i < a->light_count; i++)
        same_light(&a->lights[i], &b->lights[i], name, i);
    for (int i = 0; i < a->prim_count; i++)
        same_prim(&a->prims[i], &b->prims[i], name, i);
    for (int i = 0; i < a->mesh_count; i++)
        same_mesh(&a->meshes[i], &b->meshes[i], name, i);
}

/* Renders small enough for a unit test: scenes over the budget at 40 x 30
 * pixels (both the same way). */
static render_opts view_of(const scene_model *s)
{
    render_opts o;
    memset(&o, 0, sizeof o);
    double cost = (double)s->image.width * s->image.height * s->image.samples * s->image.samples;
    if (cost > 20000 || s->prim_count > 5000) {
        o.width = 40;
        o.height = 30;
    }
    return o;
}

static void same_render(const scene_model *a, const scene_model *b, const char *name)
{
    img_buf ia, ib;
    render_opts o = view_of(a);
    int ra = render_image(a, &o, &ia, NULL), rb = render_image(b, &o, &ib, NULL);
    ck_assert_msg(ra == rb, "%s: render status %d, from JSON %d", name, ra, rb);
    if (ra != 0)
        return;
    size_t bytes = (size_t)ia.width * (size_t)ia.height * 3 * sizeof(double);
    ck_assert_msg(ia.width == ib.width && ia.height == ib.height && memcmp(ia.rgb, ib.rgb, bytes) == 0,
                  "%s: the image rendered from the JSON export differs", name);
    img_free(&ia);
    img_free(&ib);
}

/* A broken listing must not pass by checking nothing. */
START_TEST(test_json_roundtrip_scene_count)
{
    scene_list l;
    scenes_read(&l);
    ck_assert_msg(l.count >= MIN_SCENES, "scenes/ holds %d .scene files, expected at least %d", l.count, MIN_SCENES);
}
END_TEST

/* [JSON-ROUNDTRIP-1] scene number _i of scenes/: export -> load gives the
 * same model and the same image, bit for bit. */
START_TEST(test_json_roundtrip_scene)
{
    scene_list l;
    int status;
    scenes_read(&l);
    ck_assert_int_lt(_i, l.count);
    const char *name = l.names[_i];
    scene_model *s = load_quiet(name, NULL, 0, &status);
    ck_assert_msg(s != NULL, "%s does not load (%d)", name, status);
    export_json_opts o;
    memset(&o, 0, sizeof o);
    o.source = name;
    scene_model *back = round_trip(s, &o, "roundtrip.json");
    same_scene(s, back, name);
    same_render(s, back, name);
    scene_free(s);
    scene_free(back);
}
END_TEST

/* [JSON-ROUNDTRIP-1] [JSON-MESH-1] Mesh scenes outside scenes/, meshes
 * inline: three PLY meshes (ASCII and both binary orders), a closed glass
 * prism seen head on through its shared edges, and the messy-OBJ corpus
 * (dropped, non-convex, non-planar, open, inconsistently wound faces, vt/vn
 * mixes): the same store and the same image, bit for bit. */
static const char *const mesh_scenes[] = {
    "tests/ply/encodings.scene",
    "tests/obj/prism_head_on.scene",
    "mesh { file \"tests/obj/messy-degenerate.obj\" }\n",
    "mesh { file \"tests/obj/messy-nonconvex.obj\" material { t 0.5 ior 1.5 } }\n",
    "mesh { file \"tests/obj/messy-nonplanar.obj\" rotate [10, 20, 30] }\n",
    "mesh { file \"tests/obj/messy-open.obj\" material { t 0.5 ior 1.5 } }\n",
    "mesh { file \"tests/obj/messy-winding.obj\" scale [1, -1, 1] material { t 0.9 ior 1.5 } }\n",
    "mesh { file \"tests/obj/messy-vtvn.obj\" translate [0, 0, -3] }\n",
    "mesh { file \"tests/obj/messy-negative.obj\" }\n",
};

START_TEST(test_json_roundtrip_mesh_scenes)
{
    const char *what = mesh_scenes[_i];
    int status, is_text = strchr(what, '{') != NULL;
    scene_model *s = is_text ? load_quiet("t.scene", what, strlen(what), &status) : load_quiet(what, NULL, 0, &status);
    ck_assert_msg(s != NULL, "%s does not load (%d)", what, status);
    ck_assert_int_gt(s->mesh_count, 0);
    export_json_opts o;
    memset(&o, 0, sizeof o);
    o.source = is_text ? "t.scene" : what;
    scene_model *back = round_trip(s, &o, "roundtrip.json");
    same_scene(s, back, what);
    same_render(s, back, what);
    scene_free(s);
    scene_free(back);
}
END_TEST

/* [JSON-MESH-1] With mesh files the meshes are OBJ files beside the JSON,
 * named after it, and the scene still comes back bit for bit. */
START_TEST(test_json_roundtrip_mesh_files)
{
    static const char *const scenes[] = {"scenes/mesh.scene", "scenes/stress/thin_triangles.scene",
                                         "scenes/stress/watertight_mesh.scene", "tests/ply/encodings.scene",
                                         "tests/obj/prism_head_on.scene"};
    char dir[256], json[320], obj[320];
    cli_scratch(dir, sizeof dir, "json");
    for (size_t k = 0; k < sizeof scenes / sizeof scenes[0]; k++) {
        int status;
        scene_model *s = load_quiet(scenes[k], NULL, 0, &status);
        ck_assert_ptr_nonnull(s);
        export_json_opts o;
        memset(&o, 0, sizeof o);
        o.mesh_dir = "meshes";
        o.json_dir = dir;
        o.mesh_stem = "x";
        snprintf(json, sizeof json, "%s/x.json", dir);
        scene_model *back = round_trip(s, &o, json);
        for (int m = 0; m < s->mesh_count; m++) {
            snprintf(obj, sizeof obj, "%s/meshes/x.mesh%d.obj", dir, m);
            ck_assert_msg(access(obj, F_OK) == 0, "%s: no %s", scenes[k], obj);
        }
        same_scene(s, back, scenes[k]);
        same_render(s, back, scenes[k]);
        scene_free(s);
        scene_free(back);
    }
    cli_remove(dir);
}
END_TEST

/* The document of text, parsed. */
static json_t *export_doc(const char *text)
{
    int status;
    scene_model *s = load_quiet("t.scene", text, strlen(text), &status);
    ck_assert_msg(s != NULL, "scene did not load (%d)", status);
    json_t *doc = testjson_export(s);
    scene_free(s);
    return doc;
}

/* [JSON-DEFAULTS-1] What a scene leaves out is written out with the values
 * of spec/language.md: a lone `sphere {}`. */
START_TEST(test_json_export_defaults_explicit)
{
    json_t *doc = export_doc("sphere {}\n");
    ck_assert_double_eq(testjson_num(doc, "image/width"), 640);
    ck_assert_double_eq(testjson_num(doc, "image/height"), 480);
    ck_assert_double_eq(testjson_num(doc, "image/samples"), 1);
    ck_assert_double_eq(testjson_num(doc, "image/max_depth"), 5);
    ck_assert_double_eq(testjson_num(doc, "image/background/1"), 0);
    ck_assert_double_eq(testjson_num(doc, "camera/eye/2"), 5);
    ck_assert_double_eq(testjson_num(doc, "camera/up/1"), 1);
    ck_assert_double_eq(testjson_num(doc, "camera/fov"), 60);
    ck_assert_double_eq(testjson_num(doc, "ambient/0"), 0);
    ck_assert_double_eq(testjson_num(doc, "materials/0/Kd/2"), 0.8);
    ck_assert_double_eq(testjson_num(doc, "materials/0/Ks/0"), 0);
    ck_assert_double_eq(testjson_num(doc, "materials/0/n"), 1);
    ck_assert_double_eq(testjson_num(doc, "materials/0/t"), 0);
    ck_assert_double_eq(testjson_num(doc, "materials/0/ior"), 1);
    ck_assert_double_eq(testjson_num(doc, "primitives/0/radius"), 1);
    ck_assert_double_eq(testjson_num(doc, "primitives/0/material"), 0);
    ck_assert(json_is_null(json_object_get(json_array_get(json_object_get(doc, "primitives"), 0), "transform")));
    ck_assert(json_is_null(json_object_get(json_array_get(json_object_get(doc, "materials"), 0), "name")));
    ck_assert(json_is_null(json_object_get(doc, "oracle")));
    ck_assert_str_eq(json_string_value(json_object_get(json_object_get(doc, "camera"), "projection")), "perspective");
    json_decref(doc);
}
END_TEST

/* A light's falloff and d0 default to linear and 0, a distributed light's
 * samples to 16; a named material keeps its name; a rotated box keeps its
 * matrices (to_world rotates +x onto +y for rotate [0, 0, 90]). */
START_TEST(test_json_export_lights_materials_transforms)
{
    json_t *doc = export_doc("point_light { position [0, 4, 0] }\n"
                             "distributed_light { rectangle [0, 4, 0] [1, 0, 0] [0, 0, 1] }\n"
                             "material paint { Kd 0.5 }\n"
                             "box { from [0, 0, 0] to [1, 2, 3] rotate [0, 0, 90] material paint }\n");
    json_t *lights = json_object_get(doc, "lights"), *point = json_array_get(lights, 0);
    ck_assert_str_eq(json_string_value(json_object_get(point, "falloff")), "linear");
    ck_assert_double_eq(testjson_num(doc, "lights/0/d0"), 0);
    ck_assert_double_eq(testjson_num(doc, "lights/0/power/0"), 1);
    ck_assert_double_eq(testjson_num(doc, "lights/1/samples"), 16);
    ck_assert_double_eq(testjson_num(doc, "lights/1/sampling/grid/rows"), 4);
    ck_assert_double_eq(testjson_num(doc, "lights/1/sampling/sample_power/1"), 1.0 / 16);
    ck_assert_str_eq(json_string_value(json_object_get(json_array_get(json_object_get(doc, "materials"), 0), "name")),
                     "paint");
    ck_assert_near(testjson_num(doc, "primitives/0/transform/to_world/1/0"), 1, 1e-15);
    ck_assert_near(testjson_num(doc, "primitives/0/transform/to_world/0/1"), -1, 1e-15);
    ck_assert_double_eq(testjson_num(doc, "primitives/0/transform/to_world/3/3"), 1);
    ck_assert_near(testjson_num(doc, "primitives/0/transform/to_local/0/1"), 1, 1e-15);
    json_decref(doc);
}
END_TEST

/* [JSON-NUMBER-1] Doubles are written with 17 significant digits and read
 * back to the same bits: 0.1, a subnormal, the largest double (a power:
 * a position is within 2^500, [LANG-EXTENT-1], the largest one here), -0. */
START_TEST(test_json_export_numbers_round_trip)
{
    static const char text[] = "ambient { color [0.1, 4.9406564584124654e-324, 0] }\n"
                               "point_light { position [3.2733906078961419e150, -0, 0.30000000000000004]\n"
                               "              power [1.7976931348623157e308, 1, 1] }\n"
                               "sphere {}\n";
    int status;
    scene_model *s = load_quiet("t.scene", text, strlen(text), &status);
    ck_assert_ptr_nonnull(s);
    export_json_opts o;
    memset(&o, 0, sizeof o);
    size_t len;
    char *out = export_text(s, &o, &len);
    ck_assert(strstr(out, "\"ambient\": [0.10000000000000001, 4.9406564584124654e-324, 0.0]"));
    ck_assert(strstr(out, "\"position\": [3.2733906078961419e150, -0.0, 0.30000000000000004]"));
    ck_assert(strstr(out, "\"power\": [1.7976931348623157e308, 1.0, 1.0]"));
    scene_model *back = round_trip(s, &o, "t.json");
    double want[3] = {strtod("0.1", NULL), strtod("4.9406564584124654e-324", NULL), 0};
    ck_assert(memcmp(&back->ambient.x, &want[0], sizeof(double)) == 0);
    ck_assert(memcmp(&back->ambient.y, &want[1], sizeof(double)) == 0);
    ck_assert_int_eq(signbit(back->lights[0].position.y), 1);
    same_scene(s, back, "numbers");
    free(out);
    scene_free(s);
    scene_free(back);
}
END_TEST

/* [JSON-NUMBER-1] Any JSON number is read as the double nearest it, an
 * integer too large for 64 bits included; an integer-valued real is a
 * whole number. */
START_TEST(test_json_load_numbers_as_doubles)
{
    static const char text[] =
        "{\"format\": {\"name\": \"refray-scene\", \"version\": 1.0}, \"oracle\": null,\n"
        " \"image\": {\"width\": 8.0, \"height\": 6, \"samples\": 1, \"max_depth\": 1, \"background\": [0, 0, 0]},\n"
        " \"camera\": {\"projection\": \"perspective\", \"eye\": [0, 0, 12345678901234567890123], \"look_at\": [0, 0, 0],\n"
        "            \"up\": [0, 1, 0], \"fov\": 60},\n"
        " \"ambient\": [0, 0, 0], \"lights\": [],\n"
        " \"materials\": [{\"name\": null, \"Kd\": [1, 1, 1], \"Ks\": [0, 0, 0], \"n\": 1, \"t\": 0, \"ior\": 1}],\n"
        " \"primitives\": [{\"kind\": \"sphere\", \"material\": 0, \"center\": [0, 0, 0], \"radius\": 1e-3,\n"
        "                  \"transform\": null}]}\n";
    int status;
    scene_model *s = load_quiet("n.json", text, strlen(text), &status);
    ck_assert_msg(s != NULL, "did not load (%d)", status);
    ck_assert_double_eq(s->camera.eye.z, strtod("12345678901234567890123", NULL));
    ck_assert_double_eq(s->prims[0].u.sphere.radius, strtod("1e-3", NULL));
    ck_assert_int_eq(s->image.width, 8);
    scene_free(s);
}
END_TEST

/* The document's top-level members, in the order spec/json.md lists. */
START_TEST(test_json_export_top_level_members)
{
    static const char *const want[] = {"format", "conventions", "source", "oracle", "features", "image", "camera",
                                       "ambient", "materials", "lights", "primitives"};
    json_t *doc = export_doc("oracle lambert_sphere\nsphere {}\n");
    const char *key;
    json_t *v;
    size_t i = 0;
    json_object_foreach(doc, key, v) {
        ck_assert_msg(i < sizeof want / sizeof want[0], "extra member '%s'", key);
        ck_assert_str_eq(key, want[i++]);
    }
    ck_assert_int_eq(i, sizeof want / sizeof want[0]);
    ck_assert_str_eq(json_string_value(json_object_get(json_object_get(doc, "format"), "name")), "refray-scene");
    ck_assert_double_eq(testjson_num(doc, "format/version"), 1);
    ck_assert_str_eq(json_string_value(json_object_get(doc, "oracle")), "lambert_sphere");
    json_decref(doc);
}
END_TEST

/* The whole of a file (malloc'd, *len bytes). */
static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    ck_assert_msg(f != NULL, "cannot open %s", path);
    char *buf = NULL;
    FILE *out = open_memstream(&buf, len);
    int c;
    while ((c = fgetc(f)) != EOF)
        fputc(c, out);
    fclose(f);
    fclose(out);
    return buf;
}

/* [JSON-ROUNDTRIP-1] through the command line: export -o, then render the
 * .scene and the .json to PFM: the same bytes; check gives the same summary. */
START_TEST(test_cli_json_export_render_check)
{
    static cli_run r1, r2;
    char dir[256], json[320], a[320], b[320];
    const char *scene = "scenes/analytic/rect_light.scene";
    cli_scratch(dir, sizeof dir, "json");
    cli_path(json, sizeof json, dir, "rect.json");
    cli_path(a, sizeof a, dir, "a.pfm");
    cli_path(b, sizeof b, dir, "b.pfm");
    const char *exp[] = {"export", scene, "--to", "json", "-o", json, NULL};
    cli_refray(&r1, exp);
    ck_assert_msg(r1.code == 0, "%s", r1.err);
    ck_assert_str_eq(r1.out, "");
    const char *ra[] = {"render", scene, "-o", a, NULL}, *rb[] = {"render", json, "-o", b, NULL};
    cli_refray(&r1, ra);
    cli_refray(&r2, rb);
    ck_assert_int_eq(r1.code, 0);
    ck_assert_int_eq(r2.code, 0);
    size_t la, lb;
    char *pa = slurp(a, &la), *pb = slurp(b, &lb);
    ck_assert_msg(la == lb && memcmp(pa, pb, la) == 0, "the PFM rendered from the JSON differs");
    free(pa);
    free(pb);
    const char *c1[] = {"check", scene, NULL}, *c2[] = {"check", json, NULL};
    cli_refray(&r1, c1);
    cli_refray(&r2, c2);
    ck_assert_int_eq(r1.code, 0);
    ck_assert_int_eq(r2.code, 0);
    ck_assert_str_eq(strchr(r1.out, ':'), strchr(r2.out, ':'));
    cli_remove(dir);
}
END_TEST

/* [JSON-ROUNDTRIP-1] The kit's NAME.json (spec/conformance.md) is the
 * export: it loads to the scene of the kit's NAME.scene. */
START_TEST(test_cli_kit_writes_the_json_export)
{
    static cli_run r;
    char dir[256], kit[320], json[400], scene[400];
    int status;
    cli_scratch(dir, sizeof dir, "json");
    cli_path(kit, sizeof kit, dir, "kit");
    const char *args[] = {"kit", "-q", "-o", kit, "scenes/analytic/disk_light.scene", NULL};
    cli_refray(&r, args);
    ck_assert_msg(r.code == 0, "%s", r.err);
    cli_path(json, sizeof json, kit, "scenes/disk_light/disk_light.json");
    cli_path(scene, sizeof scene, kit, "scenes/disk_light/disk_light.scene");
    scene_model *a = load_quiet(scene, NULL, 0, &status), *b = load_quiet(json, NULL, 0, &status);
    ck_assert_msg(a && b, "the kit's scene or its JSON does not load (%d)", status);
    same_scene(a, b, json);
    scene_free(a);
    scene_free(b);
    cli_remove(dir);
}
END_TEST

/* POV-Ray's options do not apply to JSON, nor --mesh-files to POV-Ray. */
START_TEST(test_cli_json_export_usage)
{
    static cli_run r;
    const char *scale[] = {"export", "scenes/analytic/rect_light.scene", "--to", "json", "--scale", "2", NULL};
    cli_refray(&r, scale);
    ck_assert_int_eq(r.code, 64);
    ck_assert_msg(strstr(r.err, "refray: error: export: --scale applies to --to pov"), "%s", r.err);
    const char *mesh[] = {"export", "scenes/mesh.scene", "--to", "pov", "--mesh-files", "m", NULL};
    cli_refray(&r, mesh);
    ck_assert_int_eq(r.code, 64);
    ck_assert_msg(strstr(r.err, "refray: error: export: --mesh-files applies to --to json"), "%s", r.err);
    const char *features[] = {"--features", NULL};
    cli_refray(&r, features);
    ck_assert_int_eq(r.code, 0);
    ck_assert_msg(strstr(r.out, "json"), "--features: %s", r.out);
}
END_TEST

#else

/* [JSON-NOJSON-1] Without jansson a .json scene and --to json are usage
 * errors (exit 64) that say why, and --features does not list json. */
START_TEST(test_json_refused_without_jansson)
{
    static const char text[] = "{}";
    static cli_run r;
    int status;
    FILE *msgs = tmpfile();
    scene_model *s = scene_file_load_text("x.json", text, strlen(text), NULL, msgs, 1, &status);
    ck_assert_ptr_null(s);
    ck_assert_int_eq(status, STATUS_USAGE);
    ck_assert_int_eq(scene_json_available(), 0);
    fclose(msgs);
    const char *exp[] = {"export", "scenes/analytic/rect_light.scene", "--to", "json", NULL};
    cli_refray(&r, exp);
    ck_assert_int_eq(r.code, 64);
    ck_assert_msg(strstr(r.err, "without JSON support"), "%s", r.err);
    const char *chk[] = {"check", "tests/bad/json-malformed.json", NULL};
    cli_refray(&r, chk);
    ck_assert_int_eq(r.code, 64);
    ck_assert_msg(strstr(r.err, "is a JSON scene, and this refray was built without JSON support"), "%s", r.err);
    const char *features[] = {"--features", NULL};
    cli_refray(&r, features);
    ck_assert_int_eq(r.code, 0);
    ck_assert_msg(!strstr(r.out, "json"), "--features: %s", r.out);
}
END_TEST

#endif

Suite *suite_json(void)
{
    Suite *s = suite_create("json");
    TCase *tc = tcase_create("json");
#if REFRAY_HAVE_JSON
    scene_list l;
    scenes_read(&l);
    tcase_add_test(tc, test_json_roundtrip_scene_count);
    tcase_add_loop_test(tc, test_json_roundtrip_scene, 0, l.count > 0 ? l.count : 1);
    tcase_add_test(tc, test_json_roundtrip_mesh_files);
    tcase_add_loop_test(tc, test_json_roundtrip_mesh_scenes, 0, (int)(sizeof mesh_scenes / sizeof mesh_scenes[0]));
    tcase_add_test(tc, test_json_export_defaults_explicit);
    tcase_add_test(tc, test_json_export_lights_materials_transforms);
    tcase_add_test(tc, test_json_export_numbers_round_trip);
    tcase_add_test(tc, test_json_load_numbers_as_doubles);
    tcase_add_test(tc, test_json_export_top_level_members);
    tcase_add_test(tc, test_cli_json_export_render_check);
    tcase_add_test(tc, test_cli_json_export_usage);
    tcase_add_test(tc, test_cli_kit_writes_the_json_export);
#else
    tcase_add_test(tc, test_json_refused_without_jansson);
#endif
    tcase_set_timeout(tc, 20);
    suite_add_tcase(s, tc);
    return s;
}
