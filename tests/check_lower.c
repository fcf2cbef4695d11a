/* Tests of lowering and validation (src/lower*.c, src/scene/validate.c,
 * src/scene/scene.c): every default of spec/language.md read back from a loaded
 * scene, every validation error with its location, transforms in written
 * order, the baking rules, the feature record, the warnings and meshes
 * read through `mesh`.  Expected numbers are worked out by hand in the
 * comments; IDs are those of spec/language.md. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "loadlib.h"

static void load(loaded *l, const char *text)
{
    load_as(l, "t.scene", text, NULL, 1);
}

/* Loads text that must be valid and print nothing. */
static scene_model *load_ok(loaded *l, const char *text)
{
    load(l, text);
    ck_assert_msg(l->scene != NULL, "%s: %s", text, l->messages);
    ck_assert_int_eq(l->status, STATUS_OK);
    return l->scene;
}

/* Loads text that must be refused (STATUS_DATA, no scene) with message
 * among what it printed. */
static void assert_refused(const char *text, const char *message)
{
    loaded l;
    load(&l, text);
    ck_assert_msg(l.scene == NULL && l.status == STATUS_DATA, "%s: loaded", text);
    ck_assert_msg(strstr(l.messages, message) != NULL, "%s: %s", text, l.messages);
    loaded_done(&l);
}

/* [LANG-IMAGE-1] [LANG-CAMERA-1] [LANG-AMBIENT-1] [LANG-MAT-DEFAULT-1]
 * [LANG-SPHERE-1]: what a scene that says nothing else gets. */
START_TEST(test_scene_load_defaults_of_an_almost_empty_scene)
{
    loaded l;
    const scene_model *s = load_ok(&l, "sphere {}");
    ck_assert_str_eq(l.messages, "");
    ck_assert_int_eq(s->image.width, 640);
    ck_assert_int_eq(s->image.height, 480);
    ck_assert_int_eq(s->image.samples, 1);
    ck_assert_int_eq(s->image.max_depth, 5);
    ck_assert_vec_near(s->image.background, vec_make(0, 0, 0), 0);
    ck_assert_int_eq(s->camera.kind, CAMERA_PERSPECTIVE);
    ck_assert_vec_near(s->camera.eye, vec_make(0, 0, 5), 0);
    ck_assert_vec_near(s->camera.look_at, vec_make(0, 0, 0), 0);
    ck_assert_vec_near(s->camera.up, vec_make(0, 1, 0), 0);
    ck_assert_near(s->camera.fov, 60, 0);
    ck_assert_near(s->camera.width, 2, 0);
    /* forward = (0,0,-5)/5; right = forward x up = (0,0,-1) x (0,1,0) = (1,0,0);
     * true_up = right x forward = (1,0,0) x (0,0,-1) = (0,1,0). */
    ck_assert_vec_near(s->camera.forward, vec_make(0, 0, -1), 0);
    ck_assert_vec_near(s->camera.right, vec_make(1, 0, 0), 0);
    ck_assert_vec_near(s->camera.true_up, vec_make(0, 1, 0), 0);
    ck_assert_vec_near(s->ambient, vec_make(0, 0, 0), 0);
    ck_assert_ptr_null(s->oracle);
    ck_assert_int_eq(s->light_count, 0);
    ck_assert_int_eq(s->mesh_count, 0);
    ck_assert_int_eq(s->prim_count, 1);
    ck_assert_int_eq(s->prims[0].kind, PRIM_SPHERE);
    ck_assert_vec_near(s->prims[0].u.sphere.center, vec_make(0, 0, 0), 0);
    ck_assert_near(s->prims[0].u.sphere.radius, 1, 0);
    ck_assert_ptr_null(s->prims[0].frame);
    ck_assert_int_eq(s->prims[0].mesh, -1);
    /* The implicit material: Kd 0.8, Ks 0, n 1, t 0, ior 1, no name. */
    ck_assert_int_eq(s->material_count, 1);
    ck_assert_int_eq(s->prims[0].material, 0);
    ck_assert_ptr_null(s->materials[0].name);
    ck_assert_vec_near(s->materials[0].kd, vec_splat(0.8), 0);
    ck_assert_vec_near(s->materials[0].ks, vec_splat(0), 0);
    ck_assert_near(s->materials[0].n, 1, 0);
    ck_assert_near(s->materials[0].t, 0, 0);
    ck_assert_near(s->materials[0].ior, 1, 0);
    const scene_features *f = &s->features;
    ck_assert(!f->shadows && !f->specular && !f->reflection && !f->refraction && !f->sampled_lights && !f->meshes);
    loaded_done(&l);
}
END_TEST

/* [LANG-PLANE-1] [LANG-DISK-1] [LANG-MAT-1]: defaults of the other shapes
 * and of a material block that gives nothing; primitives without a
 * material share one implicit material. */
START_TEST(test_scene_load_defaults_of_shapes_and_materials)
{
    loaded l;
    const scene_model *s = load_ok(&l, "material m {}\nplane {}\ndisk {}\nsphere { material m }\nbox { from [0, 0, 0] to [1, 1, 1] }");
    ck_assert_int_eq(s->prim_count, 4);
    ck_assert_vec_near(s->prims[0].u.plane.point, vec_make(0, 0, 0), 0);
    ck_assert_vec_near(s->prims[0].u.plane.normal, vec_make(0, 1, 0), 0);
    ck_assert_vec_near(s->prims[1].u.disk.center, vec_make(0, 0, 0), 0);
    ck_assert_vec_near(s->prims[1].u.disk.normal, vec_make(0, 1, 0), 0);
    ck_assert_near(s->prims[1].u.disk.radius, 1, 0);
    ck_assert_int_eq(s->material_count, 2);
    ck_assert_str_eq(s->materials[0].name, "m");
    ck_assert_vec_near(s->materials[0].kd, vec_splat(0.8), 0);
    ck_assert_vec_near(s->materials[0].ks, vec_splat(0), 0);
    ck_assert_near(s->materials[0].n, 1, 0);
    ck_assert_near(s->materials[0].t, 0, 0);
    ck_assert_near(s->materials[0].ior, 1, 0);
    ck_assert_int_eq(s->prims[0].material, 1);
    ck_assert_int_eq(s->prims[1].material, 1);
    ck_assert_int_eq(s->prims[2].material, 0);
    ck_assert_int_eq(s->prims[3].material, 1);
    ck_assert_vec_near(s->prims[3].u.box.lo, vec_make(0, 0, 0), 0);
    ck_assert_vec_near(s->prims[3].u.box.hi, vec_make(1, 1, 1), 0);
    loaded_done(&l);
}
END_TEST

/* [LANG-POINT-1] [LANG-DISTANT-1] [LANG-DIST-1] light defaults. */
START_TEST(test_scene_load_defaults_of_lights)
{
    loaded l;
    const scene_model *s = load_ok(&l, "sphere { center [0, 0, -10] }\n"
                                    "point_light { position [0, 5, 0] }\n"
                                    "distant_light { direction [0, -2, 0] }\n"
                                    "distributed_light { rectangle [0, 4, 0] [2, 0, 0] [0, 0, 3] }\n"
                                    "distributed_light { disk [0, 4, 0] [0, -3, 0] 0.5 }");
    ck_assert_int_eq(s->light_count, 4);
    const scene_light *point = &s->lights[0], *distant = &s->lights[1], *rect = &s->lights[2], *disk = &s->lights[3];
    ck_assert_int_eq(point->kind, LIGHT_POINT);
    ck_assert_vec_near(point->position, vec_make(0, 5, 0), 0);
    ck_assert_vec_near(point->power, vec_splat(1), 0);
    ck_assert_near(point->d0, 0, 0);
    ck_assert_int_eq(point->falloff, FALLOFF_LINEAR);
    ck_assert_int_eq(distant->kind, LIGHT_DISTANT);
    ck_assert_vec_near(distant->direction, vec_make(0, -1, 0), 0);
    ck_assert_vec_near(distant->power, vec_splat(1), 0);
    ck_assert_int_eq(distant->falloff, FALLOFF_NONE);
    ck_assert_int_eq(rect->kind, LIGHT_RECTANGLE);
    ck_assert_int_eq(rect->samples, 16);
    ck_assert_vec_near(rect->power, vec_splat(1), 0);
    ck_assert_near(rect->d0, 0, 0);
    ck_assert_int_eq(rect->falloff, FALLOFF_LINEAR);
    ck_assert_vec_near(rect->position, vec_make(0, 4, 0), 0);
    ck_assert_vec_near(rect->edge_u, vec_make(2, 0, 0), 0);
    ck_assert_vec_near(rect->edge_v, vec_make(0, 0, 3), 0);
    /* normal = u x v / |u x v| = (0, -6, 0) / 6: the rectangle faces down. */
    ck_assert_vec_near(rect->normal, vec_make(0, -1, 0), 0);
    ck_assert_int_eq(disk->kind, LIGHT_DISK);
    ck_assert_int_eq(disk->samples, 16);
    ck_assert_vec_near(disk->position, vec_make(0, 4, 0), 0);
    ck_assert_vec_near(disk->normal, vec_make(0, -1, 0), 0);
    ck_assert_near(disk->radius, 0.5, 0);
    loaded_done(&l);
}
END_TEST

/* The example: every value written is the value loaded; a number
 * where a colour goes is grey [LANG-COLOR-1]; ambient blocks add up. */
START_TEST(test_scene_load_reads_every_value)
{
    loaded l;
    const scene_model *s = load_ok(&l,
        "let r = 1.5\n"
        "image  { width 320  height 200  samples 2  max_depth 8  background [0.05, 0.05, 0.1] }\n"
        "camera { perspective  eye [0, 1, -5]  look_at [0, r, 0]  up [0, 1, 0]  fov 45 }\n"
        "ambient { color [0.2, 0.2, 0.2] }\nambient { color 0.1 }\n"
        "point_light   { position [5, 10, -5]  power 60  d0 1  falloff inverse_square }\n"
        "distant_light { direction [-1, -1, 1]  power [0.8, 0.8, 0.7] }\n"
        "distributed_light { rectangle [-1, 4, -1] [2, 0, 0] [0, 0, 2]  power 40  samples 9  d0 0.5  falloff none }\n"
        "material glass { Kd 0  Ks 0.1  n 200  t 0.9  ior 1.5 }\n"
        "material red   { Kd [0.8, 0.1, 0.1]  Ks 0.2  n 40 }\n"
        "sphere { center [0, r, 0]  radius r  material glass }\n"
        "plane  { point [0, -1, 0]  normal [0, 3, 0]  material red }\n");
    ck_assert_int_eq(s->image.width, 320);
    ck_assert_int_eq(s->image.height, 200);
    ck_assert_int_eq(s->image.samples, 2);
    ck_assert_int_eq(s->image.max_depth, 8);
    ck_assert_vec_near(s->image.background, vec_make(0.05, 0.05, 0.1), 0);
    ck_assert_near(s->camera.fov, 45, 0);
    ck_assert_vec_near(s->camera.look_at, vec_make(0, 1.5, 0), 0);
    /* forward = (0, 0.5, 5)/sqrt(25.25); right = forward x up = (-f.z, 0, f.x)
     * normalised = (-1, 0, 0); true_up = right x forward = (0, f.z, -f.y). */
    double len = sqrt(25.25);
    ck_assert_vec_near(s->camera.forward, vec_make(0, 0.5 / len, 5 / len), 1e-15);
    ck_assert_vec_near(s->camera.right, vec_make(-1, 0, 0), 1e-15);
    ck_assert_vec_near(s->camera.true_up, vec_make(0, 5 / len, -0.5 / len), 1e-15);
    ck_assert_vec_near(s->ambient, vec_make(0.3, 0.3, 0.3), 1e-15);
    ck_assert_vec_near(s->lights[0].power, vec_splat(60), 0);
    ck_assert_near(s->lights[0].d0, 1, 0);
    ck_assert_int_eq(s->lights[0].falloff, FALLOFF_INVERSE_SQUARE);
    double k = 1 / sqrt(3);
    ck_assert_vec_near(s->lights[1].direction, vec_make(-k, -k, k), 1e-15);
    ck_assert_vec_near(s->lights[1].power, vec_make(0.8, 0.8, 0.7), 0);
    ck_assert_int_eq(s->lights[2].samples, 9);
    ck_assert_near(s->lights[2].d0, 0.5, 0);
    ck_assert_int_eq(s->lights[2].falloff, FALLOFF_NONE);
    ck_assert_vec_near(s->lights[2].power, vec_splat(40), 0);
    const scene_material *glass = &s->materials[0], *red = &s->materials[1];
    ck_assert_str_eq(glass->name, "glass");
    ck_assert_vec_near(glass->kd, vec_splat(0), 0);
    ck_assert_vec_near(glass->ks, vec_splat(0.1), 0);
    ck_assert_near(glass->n, 200, 0);
    ck_assert_near(glass->t, 0.9, 0);
    ck_assert_near(glass->ior, 1.5, 0);
    ck_assert_vec_near(red->kd, vec_make(0.8, 0.1, 0.1), 0);
    ck_assert_near(s->prims[0].u.sphere.radius, 1.5, 0);
    ck_assert_vec_near(s->prims[0].u.sphere.center, vec_make(0, 1.5, 0), 0);
    ck_assert_int_eq(s->prims[0].material, 0);
    ck_assert_int_eq(s->prims[1].material, 1);
    ck_assert_vec_near(s->prims[1].u.plane.normal, vec_make(0, 1, 0), 0);
    loaded_done(&l);
}
END_TEST

/* An orthographic camera keeps its width; its fov is not used. */
START_TEST(test_scene_load_orthographic_camera)
{
    loaded l;
    const scene_model *s = load_ok(&l, "sphere {} camera { orthographic width 7 eye [0, 10, 0] up [0, 0, -1] }");
    ck_assert_int_eq(s->camera.kind, CAMERA_ORTHOGRAPHIC);
    ck_assert_near(s->camera.width, 7, 0);
    /* forward (0,-1,0); right = (0,-1,0) x (0,0,-1) = (1, 0, 0); true_up =
     * (1,0,0) x (0,-1,0) = (0, 0, -1). */
    ck_assert_vec_near(s->camera.forward, vec_make(0, -1, 0), 0);
    ck_assert_vec_near(s->camera.right, vec_make(1, 0, 0), 0);
    ck_assert_vec_near(s->camera.true_up, vec_make(0, 0, -1), 0);
    loaded_done(&l);
    s = load_ok(&l, "sphere {} camera { orthographic }");
    ck_assert_near(s->camera.width, 2, 0);
    loaded_done(&l);
}
END_TEST

/* [LANG-VALID-1] every check of the issue, each at the offending value. */
START_TEST(test_scene_load_validation_errors)
{
    static const struct {
        const char *text, *message;
    } cases[] = {
        /* zero-length directions */
        {"plane { normal [0, 0, 0] }", "t.scene:1:16: error: normal must not be a zero-length vector"},
        {"sphere {}\ndistant_light { direction [0, 0, 0] }",
         "t.scene:2:27: error: direction must not be a zero-length vector"},
        {"disk { normal [0, 0, 0] }", "t.scene:1:15: error: normal must not be a zero-length vector"},
        {"sphere {}\ncamera { up [0, 0, 0] }", "t.scene:2:13: error: up must not be a zero-length vector"},
        {"sphere {}\ndistributed_light { disk [0, 0, 0] [0, 0, 0] 1 }",
         "t.scene:2:36: error: the disk's normal must not be a zero-length vector"},
        /* degenerate triangles */
        {"triangle { vertices [0, 0, 0] [1, 1, 1] [2, 2, 2] }",
         "t.scene:1:21: error: degenerate triangle: its corners are on one line (no area)"},
        {"triangle { vertices [1, 0, 0] [1, 0, 0] [0, 1, 0] }",
         "t.scene:1:21: error: degenerate triangle: its corners are on one line (no area)"},
        /* radius <= 0 */
        {"sphere { radius 0 }", "t.scene:1:17: error: radius must be > 0, got 0"},
        {"disk { radius -2 }", "t.scene:1:15: error: radius must be > 0, got -2"},
        {"sphere {}\ndistributed_light { disk [0, 0, 0] [0, 1, 0] 0 }",
         "t.scene:2:46: error: radius must be > 0, got 0"},
        /* t, Kd, Ks outside [0, 1]; ior <= 0; n < 0 */
        {"material m { t 1.5 }", "t.scene:1:16: error: t must be in [0, 1], got 1.5"},
        {"material m { t -0.1 }", "t.scene:1:16: error: t must be in [0, 1], got -0.10000000000000001"},
        {"material m { Kd [0.5, 1.2, 0] }", "t.scene:1:17: error: Kd must be in [0, 1], got 1.2 (green)"},
        {"material m { Kd -1 }", "t.scene:1:17: error: Kd must be in [0, 1], got -1 (red)"},
        {"material m { Ks [0, 0, 2] }", "t.scene:1:17: error: Ks must be in [0, 1], got 2 (blue)"},
        {"material m { ior 0 }", "t.scene:1:18: error: ior must be > 0, got 0"},
        {"material m { n -1 }", "t.scene:1:16: error: n must be >= 0, got -1"},
        {"sphere { material { ior -1 } }", "t.scene:1:25: error: ior must be > 0, got -1"},
        /* unknown material, defined before use */
        {"sphere { material glass }",
         "t.scene:1:19: error: unknown material 'glass' (define it with `material glass { ... }` before use)"},
        {"sphere { material glass }\nmaterial glass {}",
         "t.scene:1:19: error: unknown material 'glass': it is defined only later, at line 2 (define a material "
         "before its first use)"},
        /* [LANG-DIAG-STUMBLE-1] a close name defined further down */
        {"sphere { material glas }\nfor i in 0 .. 1 { }\nmaterial glass {}",
         "t.scene:1:19: error: unknown material 'glas'; did you mean 'glass' (defined at line 3)?"},
        {"material glass {}\nsphere { material glas }",
         "t.scene:2:19: error: unknown material 'glas'; did you mean 'glass'?"},
        /* duplicate names */
        {"material m {}\nmaterial m {}", "t.scene:2:10: error: material 'm' is already defined (at line 1)"},
        {"let a = 1\nlet a = 2", "t.scene:2:5: error: 'a' is already defined"},
        {"oracle a\noracle b", "t.scene:2:8: error: a scene names one oracle; 'a' is already named"},
        {"sphere { radius 1 radius 2 }", "t.scene:1:19: error: 'radius' given twice (first at line 1)"},
        /* empty scene */
        {"", "t.scene:1:1: error: the scene has no primitives: nothing to render"},
        {"# only a comment\nlet x = 1\nmaterial m {}\npoint_light { position [0, 0, 0] }",
         "t.scene:1:1: error: the scene has no primitives: nothing to render"},
        /* non-finite values */
        {"sphere { radius 1e400 }", "t.scene:1:17: error: number out of range (the largest is about 1.8e308)"},
        {"sphere { center [0, 1e308 * 2, 0] }", "t.scene:1:27: error: the result is not a finite number"},
        {"sphere { center [1e308, 0, 0] translate [1e308, 0, 0] }",
         "t.scene:1:1: error: this sphere is out of range: a coordinate or size passes the largest number "
         "(about 1.8e308)"},
        {"sphere { radius 1e308 scale 10 }",
         "t.scene:1:1: error: this sphere is out of range: a coordinate or size passes the largest number "
         "(about 1.8e308)"},
        {"plane { point [-1e308, 0, 0] translate [-1e308, 0, 0] }",
         "t.scene:1:1: error: this plane is out of range: a coordinate or size passes the largest number "
         "(about 1.8e308)"},
        /* a positive size a transform takes below the smallest double (an
         * outside attack's finding: `refray check` said ok, the JSON loader
         * refused the export) */
        {"sphere { radius 1e-300 scale 1e-100 }",
         "t.scene:1:1: error: this sphere's size is 0 after its transforms: it passes below the smallest "
         "number (about 4.9e-324)"},
        {"disk { radius 1e-300 scale 1e-100 }",
         "t.scene:1:1: error: this disk's size is 0 after its transforms: it passes below the smallest "
         "number (about 4.9e-324)"},
        {"cone { from [0, 0, 0] to [0, 1e100, 0] radii 0 1e-300 scale 1e-100 }",
         "t.scene:1:1: error: this cone's size is 0 after its transforms: it passes below the smallest "
         "number (about 4.9e-324)"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        loaded l;
        load(&l, cases[i].text);
        ck_assert_msg(l.scene == NULL, "%s loaded", cases[i].text);
        ck_assert_int_eq(l.status, STATUS_DATA);
        ck_assert_str_eq(first_line(&l), cases[i].message);
        loaded_done(&l);
    }
}
END_TEST

/* The caret line under a validation error, and the note of a duplicate. */
START_TEST(test_scene_load_error_excerpt)
{
    loaded l;
    load(&l, "let a = 1\nsphere {\n\tradius -a\n}\nlet a = 2");
    ck_assert_ptr_null(l.scene);
    ck_assert_str_eq(l.messages, "t.scene:3:9: error: radius must be > 0, got -1\n"
                                 "    3 | \tradius -a\n"
                                 "      | \t       ^~\n"
                                 "t.scene:5:5: error: 'a' is already defined\n"
                                 "    5 | let a = 2\n"
                                 "      |     ^\n"
                                 "t.scene:1:5: note: first defined here\n"
                                 "    1 | let a = 1\n"
                                 "      |     ^\n");
    loaded_done(&l);
}
END_TEST

static vec3 sphere_center(const char *text, double *radius)
{
    loaded l;
    const scene_model *s = load_ok(&l, text);
    ck_assert_ptr_null(s->prims[0].frame);
    vec3 c = s->prims[0].u.sphere.center;
    *radius = s->prims[0].u.sphere.radius;
    loaded_done(&l);
    return c;
}

/* [LANG-XFORM-ORDER-1] transforms apply in the order written, the first
 * written first. */
START_TEST(test_scene_load_transform_order)
{
    double r;
    /* (1,0,0) + (1,0,0) = (2,0,0), then x2: (4,0,0), radius 2. */
    ck_assert_vec_near(sphere_center("sphere { center [1, 0, 0] translate [1, 0, 0] scale 2 }", &r),
                       vec_make(4, 0, 0), 0);
    ck_assert_near(r, 2, 0);
    /* (1,0,0) x2 = (2,0,0), then + (1,0,0): (3,0,0). */
    ck_assert_vec_near(sphere_center("sphere { center [1, 0, 0] scale 2 translate [1, 0, 0] }", &r),
                       vec_make(3, 0, 0), 0);
    ck_assert_near(r, 2, 0);
    /* Turn by 90 degrees about z, (1,0,0) -> (0,1,0), then + (1,0,0). */
    ck_assert_vec_near(sphere_center("sphere { center [1, 0, 0] rotate [0, 0, 90] translate [1, 0, 0] }", &r),
                       vec_make(1, 1, 0), 1e-15);
    /* (2,0,0) turned about z: (0,2,0). */
    ck_assert_vec_near(sphere_center("sphere { center [1, 0, 0] translate [1, 0, 0] rotate [0, 0, 90] }", &r),
                       vec_make(0, 2, 0), 1e-15);
    ck_assert_near(r, 1, 1e-15);
}
END_TEST

/* [LANG-XFORM-ROTATE-1] rotate [x, y, z] turns by x degrees about the x
 * axis, then y about y, then z about z, each by the right-hand rule. */
START_TEST(test_scene_load_rotate)
{
    double r;
    /* About z: x -> y. */
    ck_assert_vec_near(sphere_center("sphere { center [1, 0, 0] rotate [0, 0, 90] }", &r), vec_make(0, 1, 0), 1e-15);
    /* About y: z -> x, so x -> -z. */
    ck_assert_vec_near(sphere_center("sphere { center [1, 0, 0] rotate [0, 90, 0] }", &r), vec_make(0, 0, -1), 1e-15);
    /* About x: y -> z. */
    ck_assert_vec_near(sphere_center("sphere { center [0, 1, 0] rotate [90, 0, 0] }", &r), vec_make(0, 0, 1), 1e-15);
    /* x first: (0,1,0) -> (0,0,1); then y: (0,0,1) -> (1,0,0).  Doing y
     * first would leave (0,1,0) alone and then give (0,0,1). */
    ck_assert_vec_near(sphere_center("sphere { center [0, 1, 0] rotate [90, 90, 0] }", &r), vec_make(1, 0, 0), 1e-15);
    ck_assert_vec_near(sphere_center("sphere { center [0, 1, 0] rotate [90, 0, 0] rotate [0, 90, 0] }", &r),
                       vec_make(1, 0, 0), 1e-15);
    ck_assert_vec_near(sphere_center("sphere { center [0, 1, 0] rotate [0, 90, 0] rotate [90, 0, 0] }", &r),
                       vec_make(0, 0, 1), 1e-15);
    /* 30 degrees about z: (cos 30, sin 30, 0). */
    ck_assert_vec_near(sphere_center("sphere { center [2, 0, 0] rotate [0, 0, 30] }", &r),
                       vec_make(2 * sqrt(3) / 2, 1, 0), 1e-15);
    /* A uniform scale may be a number. */
    ck_assert_vec_near(sphere_center("sphere { center [1, 1, 1] scale 3 }", &r), vec_make(3, 3, 3), 0);
    ck_assert_near(r, 3, 0);
}
END_TEST

/* [LANG-XFORM-BAKE-1] a transform is baked into the shape whenever the
 * result is the same kind of shape; otherwise the shape keeps its local
 * parameters and the matrices. */
START_TEST(test_scene_load_baking_rules)
{
    loaded l;
    const scene_model *s = load_ok(&l,
        "sphere { center [0, 0, 0] scale [1, 2, 1] translate [5, 0, 0] }\n"     /* 0: ellipsoid */
        "sphere { scale -1 }\n"                                                 /* 1: mirror */
        "box { from [0, 0, 0] to [1, 1, 1] scale [2, 3, 4] translate [1, 0, 0] }\n" /* 2: baked */
        "box { from [0, 0, 0] to [1, 1, 1] scale -1 }\n"                        /* 3: baked, reordered */
        "box { from [0, 0, 0] to [1, 1, 1] rotate [0, 45, 0] }\n"               /* 4: turned */
        "disk { radius 2 rotate [90, 0, 0] scale 0.5 translate [0, 0, 3] }\n"   /* 5: baked */
        "disk { scale [1, 2, 1] }\n"                                            /* 6: not round */
        "plane { point [0, 1, 0] normal [1, 1, 0] scale [2, 1, 1] }\n"          /* 7: baked */
        "plane { rotate [0, 0, 90] }\n"                                         /* 8: baked */
        "triangle { vertices [0, 0, 0] [1, 0, 0] [0, 1, 0] scale [-1, 1, 1] }\n" /* 9: mirrored */
        "triangle { vertices [0, 0, 0] [1, 0, 0] [0, 1, 0] rotate [0, 0, 90] scale [1, 2, 3] }\n");
    const scene_prim *p = s->prims;
    ck_assert_int_eq(s->prim_count, 11);
    ck_assert_ptr_nonnull(p[0].frame);
    ck_assert_vec_near(p[0].u.sphere.center, vec_make(0, 0, 0), 0);
    ck_assert_vec_near(xform_point(&p[0].frame->to_world, vec_make(0, 1, 0)), vec_make(5, 2, 0), 0);
    ck_assert_vec_near(xform_point(&p[0].frame->to_local, vec_make(5, 2, 0)), vec_make(0, 1, 0), 0);
    ck_assert_ptr_nonnull(p[1].frame);
    ck_assert_ptr_null(p[2].frame);
    ck_assert_vec_near(p[2].u.box.lo, vec_make(1, 0, 0), 0);
    ck_assert_vec_near(p[2].u.box.hi, vec_make(3, 3, 4), 0);
    ck_assert_ptr_null(p[3].frame);
    ck_assert_vec_near(p[3].u.box.lo, vec_make(-1, -1, -1), 0);
    ck_assert_vec_near(p[3].u.box.hi, vec_make(0, 0, 0), 0);
    ck_assert_ptr_nonnull(p[4].frame);
    ck_assert_vec_near(p[4].u.box.hi, vec_make(1, 1, 1), 0);
    /* The disk's normal (0,1,0) turned about x by 90: (0,0,1); radius 2 x 0.5. */
    ck_assert_ptr_null(p[5].frame);
    ck_assert_vec_near(p[5].u.disk.normal, vec_make(0, 0, 1), 1e-15);
    ck_assert_vec_near(p[5].u.disk.center, vec_make(0, 0, 3), 1e-15);
    ck_assert_near(p[5].u.disk.radius, 1, 1e-15);
    ck_assert_ptr_nonnull(p[6].frame);
    /* Point (0,1,0) -> (0,1,0); normal through the inverse transpose
     * diag(1/2, 1, 1): (0.5, 1, 0) / sqrt(1.25).  The plane is then stored
     * by its point nearest the origin, (n.p) n = (0.5, 1, 0) / 1.25. */
    ck_assert_ptr_null(p[7].frame);
    ck_assert_vec_near(p[7].u.plane.point, vec_make(0.4, 0.8, 0), 1e-15);
    ck_assert_vec_near(p[7].u.plane.normal, vec_make(0.5 / sqrt(1.25), 1 / sqrt(1.25), 0), 1e-15);
    /* (0,1,0) about z by 90: (-1, 0, 0). */
    ck_assert_vec_near(p[8].u.plane.normal, vec_make(-1, 0, 0), 1e-15);
    /* Mirrored corners (0,0,0) (-1,0,0) (0,1,0), the last two swapped so
     * that (p1-p0) x (p2-p0) = (0,1,0) x (-1,0,0) = (0,0,1) still faces +z
     * as the mirror image of the normal does. */
    ck_assert_ptr_null(p[9].frame);
    ck_assert_vec_near(p[9].u.triangle.p[0], vec_make(0, 0, 0), 0);
    ck_assert_vec_near(p[9].u.triangle.p[1], vec_make(0, 1, 0), 0);
    ck_assert_vec_near(p[9].u.triangle.p[2], vec_make(-1, 0, 0), 0);
    /* (1,0,0) -> (0,1,0) -> (0,2,0); (0,1,0) -> (-1,0,0) -> (-1,0,0). */
    ck_assert_vec_near(p[10].u.triangle.p[1], vec_make(0, 2, 0), 1e-15);
    ck_assert_vec_near(p[10].u.triangle.p[2], vec_make(-1, 0, 0), 1e-15);
    loaded_done(&l);
}
END_TEST

static scene_features features_of(const char *text)
{
    loaded l;
    scene_features f = load_ok(&l, text)->features;
    loaded_done(&l);
    return f;
}

/* [LANG-FEATURES-1] [LANG-FEATURES-2] the record of what a scene uses. */
START_TEST(test_scene_load_features)
{
    /* A lone flat primitive cannot shadow itself; a lone solid can, seen
     * from inside (a closed cylinder or cone too); nothing without a light. */
    static const struct { const char *scene; int shadows; } lone[] = {
        {"plane {} point_light { position [0, 5, 0] }", 0},
        {"disk {} point_light { position [0, 5, 0] }", 0},
        {"triangle { vertices [0, 0, 0] [1, 0, 0] [0, 1, 0] } distant_light { direction [0, -1, 0] }", 0},
        {"sphere {} point_light { position [0, 5, 0] }", 1},
        {"box { from [0, 0, 0] to [1, 1, 1] } point_light { position [0, 5, 0] }", 1},
        {"cylinder {} point_light { position [0, 5, 0] }", 1},
        {"cone {} distant_light { direction [0, -1, 0] }", 1},
        {"sphere {} sphere { center [3, 0, 0] }", 0},
    };
    scene_features f;
    for (size_t i = 0; i < sizeof lone / sizeof lone[0]; i++) {
        f = features_of(lone[i].scene);
        ck_assert_msg(f.shadows == lone[i].shadows, "%s: shadows %d", lone[i].scene, f.shadows);
    }
    f = features_of("sphere {} plane { point [0, -1, 0] } point_light { position [0, 5, 0] }");
    ck_assert_int_eq(f.shadows, 1);
    ck_assert_int_eq(f.specular | f.reflection | f.refraction | f.sampled_lights | f.meshes, 0);
    f = features_of("material shiny { Ks 0.5 } sphere { material shiny }");
    ck_assert_int_eq(f.specular, 1);
    ck_assert_int_eq(f.reflection, 1);
    ck_assert_int_eq(f.refraction, 0);
    /* A material nobody uses does not count. */
    f = features_of("material shiny { Ks 0.5 t 0.5 } sphere {}");
    ck_assert_int_eq(f.specular | f.reflection | f.refraction, 0);
    f = features_of("sphere { material { t 0.5 } }");
    ck_assert_int_eq(f.refraction, 1);
    ck_assert_int_eq(f.specular, 0);
    f = features_of("sphere {} distributed_light { disk [0, 5, 0] [0, -1, 0] 1 }");
    ck_assert_int_eq(f.sampled_lights, 1);
    f = features_of("sphere {} distant_light { direction [0, -1, 0] }");
    ck_assert_int_eq(f.sampled_lights, 0);
}
END_TEST

/* [LANG-WARN-1] unused material, Kd + Ks > 1, a light inside an opaque
 * sphere or box: printed, but the scene loads. */
START_TEST(test_scene_load_warnings)
{
    static const struct {
        const char *text, *message;
    } cases[] = {
        {"material m {}\nsphere {}", "t.scene:1:10: warning: material 'm' is never used"},
        {"material hot { Kd 0.8 Ks [0.1, 0.3, 0.1] }\nsphere { material hot }",
         "t.scene:1:10: warning: Kd + Ks = 1.1 exceeds 1: this surface reflects more light than it receives"},
        {"sphere { radius 2 }\npoint_light { position [0, 1, 0] }",
         "t.scene:2:1: warning: this light is inside an opaque sphere: it lights nothing outside it"},
        {"box { from [-1, -1, -1] to [1, 1, 1] }\ndistributed_light { rectangle [-0.5, 0, -0.5] [1, 0, 0] [0, 0, 1] }",
         "t.scene:2:1: warning: this light is inside an opaque box: it lights nothing outside it"},
        {"sphere { scale [1, 4, 1] }\npoint_light { position [0, 3, 0] }",
         "t.scene:2:1: warning: this light is inside an opaque sphere: it lights nothing outside it"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        loaded l;
        load(&l, cases[i].text);
        ck_assert_msg(l.scene != NULL, "%s: %s", cases[i].text, l.messages);
        ck_assert_int_eq(l.status, STATUS_OK);
        ck_assert_str_eq(first_line(&l), cases[i].message);
        loaded_done(&l);
        /* Switched off, nothing is printed. */
        load_as(&l, "t.scene", cases[i].text, NULL, 0);
        ck_assert_ptr_nonnull(l.scene);
        ck_assert_str_eq(l.messages, "");
        loaded_done(&l);
    }
    /* No warning: a transparent sphere, a light outside, on the surface. */
    const char *quiet[] = {
        "sphere { radius 2 material { t 0.5 } }\npoint_light { position [0, 1, 0] }",
        "sphere { radius 2 }\npoint_light { position [0, 3, 0] }",
        "sphere { radius 2 }\npoint_light { position [0, 2, 0] }",
        "sphere { radius 2 }\ndistant_light { direction [0, -1, 0] }",
        "material ok { Kd 0.5 Ks 0.5 }\nsphere { material ok }",
    };
    for (int i = 0; i < 5; i++) {
        loaded l;
        load_ok(&l, quiet[i]);
        ck_assert_msg(strcmp(l.messages, "") == 0, "%s: %s", quiet[i], l.messages);
        loaded_done(&l);
    }
}
END_TEST

/* [LANG-SCOPE-1] constants and materials have separate names; both must
 * be defined before use. */
START_TEST(test_scene_load_names)
{
    loaded l;
    const scene_model *s = load_ok(&l, "let red = 2\nmaterial red { Kd [1, 0, 0] }\nsphere { radius red material red }\n"
                                    "let floor = 1\nmaterial floor {}\nplane { point [0, -floor, 0] material floor }");
    ck_assert_near(s->prims[0].u.sphere.radius, 2, 0);
    ck_assert_vec_near(s->materials[s->prims[0].material].kd, vec_make(1, 0, 0), 0);
    ck_assert_vec_near(s->prims[1].u.plane.point, vec_make(0, -1, 0), 0);
    loaded_done(&l);
    load(&l, "sphere { radius r }\nlet r = 1");
    ck_assert_str_eq(first_line(&l), "t.scene:1:17: error: unknown constant 'r'");
    loaded_done(&l);
    load(&l, "let sphere = 1");
    ck_assert_str_eq(first_line(&l), "t.scene:1:5: error: 'sphere' is a reserved word and cannot name a constant");
    loaded_done(&l);
    load(&l, "let pi = 3");
    ck_assert_str_eq(first_line(&l), "t.scene:1:5: error: 'pi' is built in and cannot be redefined");
    loaded_done(&l);
}
END_TEST

/* [LANG-ORACLE-1] `oracle NAME` is kept as written. */
START_TEST(test_scene_load_oracle)
{
    loaded l;
    const scene_model *s = load_ok(&l, "oracle two_spheres\nsphere {}");
    ck_assert_str_eq(s->oracle, "two_spheres");
    ck_assert_int_eq(s->oracle_where.file, 0);
    ck_assert_uint_eq(s->oracle_where.begin, 7);
    loaded_done(&l);
}
END_TEST

/* [LANG-LIMIT-1] image limits are checked before anything is allocated,
 * with the flag that raises them. */
START_TEST(test_scene_load_image_limits)
{
    loaded l;
    load(&l, "sphere {} image { width 20000 }");
    ck_assert_str_eq(first_line(&l),
                     "t.scene:1:25: error: width of 20000 is over the limit of 16384 (raise it with --max-width)");
    loaded_done(&l);
    load(&l, "sphere {} image { width 16000 height 16000 }");
    ck_assert_str_eq(first_line(&l), "t.scene:1:11: error: 16000 x 16000 pixels is over the limit of 67108864 "
                                     "(--max-pixels)");
    loaded_done(&l);
    scene_limits lim = scene_default_limits();
    lim.max_samples = 4;
    lim.max_primitives = 2;
    load_as(&l, "t.scene", "sphere {} image { samples 5 }", &lim, 1);
    ck_assert_str_eq(first_line(&l),
                     "t.scene:1:27: error: samples of 5 is over the limit of 4 (raise it with --max-samples)");
    loaded_done(&l);
    load_as(&l, "t.scene", "sphere {} sphere {} sphere {}", &lim, 1);
    ck_assert_str_eq(first_line(&l), "t.scene:1:21: error: more than 2 primitives (--max-primitives)");
    loaded_done(&l);
    load(&l, "sphere {} image { samples 0 }");
    ck_assert_str_eq(first_line(&l), "t.scene:1:27: error: samples must be at least 1, got 0");
    loaded_done(&l);
    load(&l, "sphere {} image { max_depth 2.5 }");
    ck_assert_str_eq(first_line(&l), "t.scene:1:29: error: max_depth must be a whole number, got 2.5");
    loaded_done(&l);
    /* [REL-STACK-1] max_depth's ceiling holds whatever a library caller's
     * limits say, with a note why; below it the limit is the caller's. */
    lim = scene_default_limits();
    lim.max_depth = 5000;
    load_as(&l, "t.scene", "sphere {} image { max_depth 1001 }", &lim, 1);
    /* (first_line cuts the messages at the first line's end) */
    ck_assert_msg(strstr(l.messages, "note: 1000 is the ceiling: the tracer recurses once a bounce") != NULL, "%s",
                  l.messages);
    ck_assert_str_eq(first_line(&l), "t.scene:1:29: error: max_depth of 1001 is over the limit of 1000");
    loaded_done(&l);
    load_as(&l, "t.scene", "sphere {} image { max_depth 1000 }", &lim, 1);
    ck_assert_ptr_nonnull(l.scene);
    ck_assert_int_eq(l.scene->image.max_depth, 1000);
    loaded_done(&l);
    lim.max_depth = 7;
    load_as(&l, "t.scene", "sphere {} image { max_depth 8 }", &lim, 1);
    ck_assert_str_eq(first_line(&l),
                     "t.scene:1:29: error: max_depth of 8 is over the limit of 7 (raise it with --max-depth-limit)");
    loaded_done(&l);
}
END_TEST

/* Meshes read through `mesh`, relative to the scene file's directory (and
 * in its tree, [REL-READ-1]). */
START_TEST(test_scene_load_mesh)
{
    loaded l;
    load_as(&l, "tests/mesh.scene",
            "mesh { file \"obj/cube.obj\" }\n"
            "mesh { file \"obj/quad.obj\" translate [0, 0, 5] scale 2 material { Kd 0.5 } }\n"
            "mesh { file \"./obj/tetrahedron.obj\" }", NULL, 1);
    ck_assert_msg(l.scene != NULL, "%s", l.messages);
    const scene_model *s = l.scene;
    ck_assert_int_eq(s->mesh_count, 3);
    ck_assert_int_eq(s->prim_count, 3);
    ck_assert_int_eq(s->meshes[0].geom.tri_count, 12);
    ck_assert_int_eq(s->meshes[1].geom.tri_count, 2);
    ck_assert_int_eq(s->meshes[2].geom.tri_count, 4);
    ck_assert_str_eq(s->meshes[0].path, "tests/obj/cube.obj");
    ck_assert(s->features.meshes);
    for (int i = 0; i < s->prim_count; i++) {
        ck_assert_int_eq(s->prims[i].kind, PRIM_MESH);
        ck_assert_int_eq(s->prims[i].mesh, i);
        ck_assert_int_eq(s->meshes[i].prim, i);
        /* The primitive's view shares the mesh's arrays. */
        ck_assert_ptr_eq(s->prims[i].u.mesh.tri, s->meshes[i].geom.tri);
    }
    /* The cube's first face `f 1//1 4//1 3//1 2//1` is cut into (1,4,3):
     * (-1,-1,-1) (-1,1,-1) (1,1,-1), with the normal (0,0,-1). */
    const scene_trimesh *g = &s->meshes[0].geom;
    ck_assert_ptr_nonnull(g->tri_normal);
    ck_assert_vec_near(g->positions[g->tri[0][0]], vec_make(-1, -1, -1), 0);
    ck_assert_vec_near(g->positions[g->tri[0][1]], vec_make(-1, 1, -1), 0);
    ck_assert_vec_near(g->positions[g->tri[0][2]], vec_make(1, 1, -1), 0);
    ck_assert_vec_near(g->normals[g->tri_normal[0][0]], vec_make(0, 0, -1), 0);
    ck_assert(g->closed);
    /* The quad's second triangle (1,3,4): corners translated by (0,0,5),
     * then doubled: (-2,-2,10) (2,2,10) (-2,2,10). */
    g = &s->meshes[1].geom;
    ck_assert_ptr_null(g->tri_normal);
    ck_assert_vec_near(g->positions[g->tri[1][0]], vec_make(-2, -2, 10), 0);
    ck_assert_vec_near(g->positions[g->tri[1][1]], vec_make(2, 2, 10), 0);
    ck_assert_vec_near(g->positions[g->tri[1][2]], vec_make(-2, 2, 10), 0);
    ck_assert(!g->closed);
    ck_assert_vec_near(s->materials[s->prims[1].material].kd, vec_splat(0.5), 0);
    loaded_done(&l);
}
END_TEST

START_TEST(test_scene_load_mesh_errors)
{
    loaded l;
    load_as(&l, "tests/scenes/mesh.scene", "mesh { file \"../scenes/none.obj\" }", NULL, 1);
    ck_assert_str_eq(first_line(&l),
                     "tests/scenes/mesh.scene:1:13: error: cannot open 'tests/scenes/../scenes/none.obj': "
                     "No such file or directory");
    ck_assert_int_eq(l.status, STATUS_DATA);
    loaded_done(&l);
    load(&l, "mesh {}");
    ck_assert_str_eq(first_line(&l), "t.scene:1:1: error: mesh needs 'file'");
    loaded_done(&l);
    load(&l, "mesh { file 3 }");
    ck_assert_str_eq(first_line(&l), "t.scene:1:13: error: expected a string, got a number");
    loaded_done(&l);
    /* The triangle limit is the OBJ reader's, at the face that passes it. */
    scene_limits lim = scene_default_limits();
    lim.max_mesh_triangles = 11;
    load_as(&l, "tests/mesh.scene", "mesh { file \"obj/cube.obj\" }", &lim, 1);
    ck_assert_ptr_null(l.scene);
    ck_assert_str_eq(first_line(&l), "tests/obj/cube.obj:24:1: error: mesh exceeds the limit of 11 triangles (--max-mesh-triangles)");
    loaded_done(&l);
}
END_TEST

/* After loading no number of the scene is infinite or NaN and every
 * direction is unit [LANG-VALID-2]: the bounds of the number range. */
START_TEST(test_scene_load_huge_but_finite)
{
    loaded l;
    const scene_model *s = load_ok(&l, "plane { normal [1.5e308, 1.5e308, 0] }\n"
                                    "sphere { radius 3e150 center [3e150, -3e150, 0] }\n"
                                    "distant_light { direction [1e308, 1e308, 1e308] }\n"
                                    "triangle { vertices [1e150, 0, 0] [0, 1e150, 0] [0, 0, 1e150] }\n"
                                    "camera { eye [3e150, 0, 0] look_at [-3e150, 0, 0] up [0, 1e308, 1e308] }\n"
                                    "plane { normal [4.9e-324, 0, 0] }\n");
    double k = 1 / sqrt(2), c = 1 / sqrt(3);
    ck_assert_vec_near(s->prims[0].u.plane.normal, vec_make(k, k, 0), 1e-15);
    ck_assert_vec_near(s->lights[0].direction, vec_make(c, c, c), 1e-15);
    ck_assert_vec_near(s->camera.forward, vec_make(-1, 0, 0), 0);
    ck_assert_vec_near(s->camera.true_up, vec_make(0, k, k), 1e-15);
    ck_assert_vec_near(s->prims[3].u.plane.normal, vec_make(1, 0, 0), 0);
    loaded_done(&l);
}
END_TEST

/* [LANG-EXTENT-1] What test_scene_load_huge_but_finite placed before the
 * scene had an extent is refused, each with the value and the bound; the
 * bounds themselves pass: 2^500 = 3.2733906078961419e150 as a coordinate
 * and a size, 2^-500 = 3.0549363634996047e-151 as a size, and a subnormal
 * coordinate (coordinates have no least magnitude). */
START_TEST(test_scene_load_refuses_beyond_the_extent)
{
    static const struct {
        const char *text, *message;
    } refused[] = {
        {"sphere { radius 1e300 center [1e308, -1e308, 0] }",
         "t.scene:1:1: error: this sphere is outside the scene's extent: its center has a coordinate of 1e+308"},
        {"triangle { vertices [1e200, 0, 0] [0, 1e200, 0] [0, 0, 1e200] }",
         "t.scene:1:1: error: this triangle is outside the scene's extent: its vertex has a coordinate of "
         "9.9999999999999997e+199, beyond 2^500"},
        {"camera { eye [1.5e308, 0, 0] look_at [-1.5e308, 0, 0] }\nsphere {}",
         "t.scene:1:14: error: the camera is outside the scene's extent: its eye has a coordinate of 1.5e+308"},
        {"sphere { center [2^500 * (1 + 2^-52), 0, 0] }", "coordinate of 3.2733906078961426e+150, beyond 2^500"},
        {"sphere { radius 2^500 * (1 + 2^-52) }", "its radius is 3.2733906078961426e+150, beyond 2^500"},
        {"sphere { radius 2^-500 * (1 - 2^-53) }", "its radius is 3.0549363634996043e-151, below 2^-500"},
        {"cylinder { from [0, 0, 0] to [0, 1e-160, 0] }", "its length is 9.9999999999999999e-161, below 2^-500"},
        {"torus { major 1e-150 minor 1e-152 }", "its minor radius is 1.0000000000000001e-152, below 2^-500"},
        {"box { from [0, 0, 0] to [1, 1e-160, 1] }", "its height is 9.9999999999999999e-161, below 2^-500"},
        {"sphere {}\ndistributed_light { disk [0, 0, 0] [0, 1, 0] 1e200 }", "its radius is 9.9999999999999997e+199"},
        {"sphere {}\ndistributed_light { rectangle [3e150, 0, 0] [1e150, 0, 0] [0, 0, 1] }",
         "t.scene:2:31: error: this light is outside the scene's extent: its corner has a coordinate of 3.9999999999999999e+150"},
    };
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++)
        assert_refused(refused[i].text, refused[i].message);
    loaded l;
    const scene_model *s = load_ok(&l, "sphere { center [2^500, -2^500, 4.9e-324] radius 2^500 }\n"
                                    "sphere { radius 2^-500 }\n"
                                    "cone { from [0, 0, 0] to [0, 1, 0] radii 1 0 }\n");
    ck_assert(s->prims[0].u.sphere.center.x == 3.2733906078961419e150);
    ck_assert(s->prims[0].u.sphere.radius == 3.2733906078961419e150);
    ck_assert(s->prims[1].u.sphere.radius == 3.0549363634996047e-151);
    loaded_done(&l);
}
END_TEST

/* [LANG-EXTENT-1] A shape that keeps its local frame is bounded in the
 * world too: the world images of its local box's corners within 2^500.
 * The cone of tests/attack8/cone_frame_huge.scene has the local box
 * x, z in [-2^499, 2^499] (the larger radius), y in [-2^500, 2^500] (the
 * ends and that radius); scaled by [2^522, 2^522, 2^521] its first corner
 * is (-2^1021, -2^1022, -2^1020), and x is checked first.  A unit sphere
 * stretched 2^501 along x reaches x = -2^501; stretched 2^500 it is at the
 * bound and loads, as does a box 2^500 long turned 45 degrees (its far
 * corner at about 0.71 * 2^500 on x and y) and a shape squeezed 2^-400
 * (the frame's matrix itself is not bounded). */
START_TEST(test_scene_load_refuses_a_kept_frame_beyond_the_extent)
{
    static const struct {
        const char *text, *message;
    } refused[] = {
        {"cone { from [0, -2 ^ 499, 0] to [0, 2 ^ 499, 0] radii 2 ^ 499 2 ^ 498 scale [2 ^ 522, 2 ^ 522, 2 ^ 521] }",
         "t.scene:1:1: error: this cone is outside the scene's extent: its world box has a coordinate of "
         "-2.2471164185778949e+307, beyond 2^500"},
        {"sphere { radius 1 scale [2 ^ 501, 1, 1] }",
         "t.scene:1:1: error: this sphere is outside the scene's extent: its world box has a coordinate of "
         "-6.5467812157922837e+150, beyond 2^500"},
        {"torus { major 2^499 minor 2^490 scale [1, 1, 4] }", "its world box has a coordinate of"},
        {"cylinder { radius 2^499 scale [1, 1e300, 1] }", "its world box has a coordinate of"},
        {"box { from [0, 0, 0] to [2^500, 1, 1] rotate [0, 0, 45] scale [4, 1, 1] }", "its world box"},
        {"disk { radius 2^499 scale [1, 1, 1e10] }", "its world box"},
    };
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++)
        assert_refused(refused[i].text, refused[i].message);
    loaded l;
    const scene_model *s = load_ok(&l, "sphere { radius 1 scale [2 ^ 500, 1, 1] }\n"
                                    "box { from [0, 0, 0] to [2^500, 1, 1] rotate [0, 0, 45] }\n"
                                    "cone { radii 2^499 0 scale [2^-400, 1, 1] }\n");
    ck_assert_int_eq(s->prim_count, 3);
    for (int i = 0; i < 3; i++)
        ck_assert_msg(s->prims[i].frame != NULL, "primitive %d keeps its frame", i);
    loaded_done(&l);
}
END_TEST

/* [LANG-EXTENT-1] An orthographic camera's view is width wide and width
 * times height/width (the image's aspect) tall, and its rays start
 * anywhere on it: every corner, eye +- right w/2 +- up (w/2)(h/w), is held
 * within 2^500.  With the eye at 0, right (1, 0, 0) and up (0, 1, 0), a
 * camera 2^500 wide on an image 1 x 16384 has the corner (-2^499, -2^513, 0)
 * (tests/attack9, finding 1: it loaded, and rays started 2^513 away); one
 * 2^487 wide has (-2^486, -2^500, 0), exactly at the bound, and loads, and
 * one 2^487 (1 + 2^-52) wide is one step over. */
START_TEST(test_scene_load_refuses_an_orthographic_view_beyond_the_extent)
{
    static const char *const form = "image { width 1 height 16384 }\n"
                                    "camera { orthographic eye [0, 0, 0] look_at [0, 0, -1] up [0, 1, 0] width %s }\n"
                                    "plane { point [0, 0, -1] normal [0, 0, 1] }";
    static const struct {
        const char *width, *message;
    } refused[] = {
        {"2 ^ 500", "t.scene:2:75: error: the camera is outside the scene's extent: its view on an image of 1 x 16384 "
                    "pixels (width 3.2733906078961419e+150, height 5.3631231719770388e+154) has a corner with a "
                    "coordinate of -2.6815615859885194e+154, beyond 2^500"},
        {"2 ^ 487 * (1 + 2 ^ -52)", "has a corner with a coordinate of -3.2733906078961426e+150"},
    };
    char text[512];
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        snprintf(text, sizeof text, form, refused[i].width);
        assert_refused(text, refused[i].message);
    }
    loaded l;
    snprintf(text, sizeof text, form, "2 ^ 487");
    const scene_model *s = load_ok(&l, text);
    double c = 0;
    ck_assert_int_eq(scene_view_out(&s->camera, 1, 16384, &c), 0);
    ck_assert_int_eq(scene_view_out(&s->camera, 1, 16385, &c), 1);
    ck_assert_double_eq(c, -0x1p500 * (16385.0 / 16384));
    ck_assert_int_eq(scene_view_out(&s->camera, 2, 16384, &c), 0);
    loaded_done(&l);
}
END_TEST

/* [LANG-TORUS-2] A torus thinner than minor/major 2^-16 is refused at
 * minor: past about 2^-22 its quartic lost roots and reported hits off the
 * tube (tests/attack9, finding 3; spec/numerics.md 2.15's sweep).  The
 * bound itself loads, one step below it does not, and the ratio is what
 * counts, not the size (the same tube at major 2^100). */
START_TEST(test_scene_load_refuses_a_torus_thinner_than_its_quartic_resolves)
{
    static const struct {
        const char *text, *message;
    } refused[] = {
        {"torus { major 1 minor 2^-28 }",
         "t.scene:1:23: error: minor must be at least major / 65536 (2^-16): a thinner tube is beyond what the "
         "torus's hit test resolves, got minor 3.7252902984619141e-09 and major 1"},
        {"torus { major 1 minor 2^-16 * (1 - 2^-53) }", "got minor 1.5258789062499998e-05 and major 1"},
        {"torus { major 2^100 minor 2^83 }", "minor must be at least major / 65536"},
    };
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++)
        assert_refused(refused[i].text, refused[i].message);
    loaded l;
    const scene_model *s = load_ok(&l, "torus { major 1 minor 2^-16 }\ntorus { major 2^100 minor 2^84 }\n");
    ck_assert_int_eq(s->prim_count, 2);
    ck_assert_double_eq(s->prims[0].u.torus.minor, 0x1p-16);
    loaded_done(&l);
}
END_TEST

/* [LANG-CAMERA-2] Every mistake of a camera is reported, in one run: the
 * kind and a value out of range, then look_at at the eye and a zero up. */
START_TEST(test_scene_load_camera_reports_everything)
{
    loaded l;
    load(&l, "camera { perspective orthographic fov 400 eye [1, 1, 1] look_at [1, 1, 1] up [0, 0, 0] }\nsphere {}");
    ck_assert_ptr_null(l.scene);
    ck_assert_ptr_nonnull(strstr(l.messages, "t.scene:1:22: error: a camera is either perspective or orthographic"));
    ck_assert_ptr_nonnull(strstr(l.messages, "t.scene:1:39: error: fov must be in (0, 180), got 400"));
    ck_assert_ptr_nonnull(strstr(l.messages, "error: look_at must differ from eye"));
    ck_assert_ptr_nonnull(strstr(l.messages, "error: up must not be a zero-length vector"));
    loaded_done(&l);
}
END_TEST

/* [LANG-CYLINDER-1] [LANG-CONE-1] [LANG-TORUS-1]: defaults, open, and
 * [LANG-XFORM-BAKE-1] baking under a similarity (rotate 90 about x takes
 * y to z and z to -y; scale 2; translate): the ends or the centre moved,
 * the axis turned, the radii doubled.  A non-uniform scale keeps the frame. */
START_TEST(test_scene_load_quadrics)
{
    loaded l;
    const scene_model *s = load_ok(&l,
        "cylinder { }\n"
        "cone { open }\n"
        "torus { }\n"
        "cylinder { from [0, 0, 0] to [0, 0, 1] radius 1 rotate [90, 0, 0] scale 2 translate [1, 0, 0] }\n"
        "cone { radii 0.5 0.25 rotate [90, 0, 0] scale 2 }\n"
        "torus { center [0, 1, 0] major 2 minor 0.5 rotate [90, 0, 0] scale 2 }\n"
        "torus { scale [1, 2, 1] }\n"
        "let radius = 3\nlet minor = 0.1\ncylinder { radius radius open }\ntorus { minor minor }\n");
    const scene_prim *p = s->prims;
    ck_assert_int_eq(s->prim_count, 9);
    ck_assert_int_eq(p[0].kind, PRIM_CYLINDER);
    ck_assert_vec_near(p[0].u.cylinder.from, vec_make(0, 0, 0), 0);
    ck_assert_vec_near(p[0].u.cylinder.to, vec_make(0, 1, 0), 0);
    ck_assert_near(p[0].u.cylinder.radius, 1, 0);
    ck_assert_int_eq(p[0].u.cylinder.open, 0);
    ck_assert_int_eq(p[1].kind, PRIM_CONE);
    ck_assert_near(p[1].u.cone.radius[0], 1, 0);
    ck_assert_near(p[1].u.cone.radius[1], 0, 0);
    ck_assert_int_eq(p[1].u.cone.open, 1);
    ck_assert_int_eq(p[2].kind, PRIM_TORUS);
    ck_assert_vec_near(p[2].u.torus.axis, vec_make(0, 1, 0), 0);
    ck_assert_near(p[2].u.torus.major, 1, 0);
    ck_assert_near(p[2].u.torus.minor, 0.25, 0);
    ck_assert_ptr_null(p[3].frame);
    ck_assert_vec_near(p[3].u.cylinder.from, vec_make(1, 0, 0), 1e-15);
    ck_assert_vec_near(p[3].u.cylinder.to, vec_make(1, -2, 0), 1e-15);
    ck_assert_near(p[3].u.cylinder.radius, 2, 1e-15);
    ck_assert_ptr_null(p[4].frame);
    ck_assert_vec_near(p[4].u.cone.to, vec_make(0, 0, 2), 1e-15);
    ck_assert_near(p[4].u.cone.radius[0], 1, 1e-15);
    ck_assert_near(p[4].u.cone.radius[1], 0.5, 1e-15);
    ck_assert_ptr_null(p[5].frame);
    ck_assert_vec_near(p[5].u.torus.center, vec_make(0, 0, 2), 1e-15);
    ck_assert_vec_near(p[5].u.torus.axis, vec_make(0, 0, 1), 1e-15);
    ck_assert_near(p[5].u.torus.major, 4, 1e-15);
    ck_assert_near(p[5].u.torus.minor, 1, 1e-15);
    ck_assert_ptr_nonnull(p[6].frame);
    ck_assert_near(p[7].u.cylinder.radius, 3, 0);
    ck_assert_int_eq(p[7].u.cylinder.open, 1);
    ck_assert_near(p[8].u.torus.minor, 0.1, 0);
    loaded_done(&l);
}
END_TEST

Suite *suite_lower(void)
{
    Suite *s = suite_create("lower");
    TCase *tc = tcase_create("lower");
    tcase_add_test(tc, test_scene_load_defaults_of_an_almost_empty_scene);
    tcase_add_test(tc, test_scene_load_defaults_of_shapes_and_materials);
    tcase_add_test(tc, test_scene_load_defaults_of_lights);
    tcase_add_test(tc, test_scene_load_reads_every_value);
    tcase_add_test(tc, test_scene_load_orthographic_camera);
    tcase_add_test(tc, test_scene_load_validation_errors);
    tcase_add_test(tc, test_scene_load_error_excerpt);
    tcase_add_test(tc, test_scene_load_transform_order);
    tcase_add_test(tc, test_scene_load_rotate);
    tcase_add_test(tc, test_scene_load_baking_rules);
    tcase_add_test(tc, test_scene_load_features);
    tcase_add_test(tc, test_scene_load_warnings);
    tcase_add_test(tc, test_scene_load_names);
    tcase_add_test(tc, test_scene_load_oracle);
    tcase_add_test(tc, test_scene_load_image_limits);
    tcase_add_test(tc, test_scene_load_mesh);
    tcase_add_test(tc, test_scene_load_mesh_errors);
    tcase_add_test(tc, test_scene_load_huge_but_finite);
    tcase_add_test(tc, test_scene_load_refuses_beyond_the_extent);
    tcase_add_test(tc, test_scene_load_refuses_a_kept_frame_beyond_the_extent);
    tcase_add_test(tc, test_scene_load_refuses_an_orthographic_view_beyond_the_extent);
    tcase_add_test(tc, test_scene_load_refuses_a_torus_thinner_than_its_quartic_resolves);
    tcase_add_test(tc, test_scene_load_quadrics);
    tcase_add_test(tc, test_scene_load_camera_reports_everything);
    suite_add_tcase(s, tc);
    return s;
}
