/*
 * load_json.c - JSON scenes (spec/json.md): the values jansson parsed become
 * the scene model, and the rules of check.c validate them as they validate
 * a .scene.  Built only with JSON=1.
 *
 * A JSON scene holds the model after the scene language's lowering:
 * directions are unit already, transforms are matrices, materials are
 * resolved, mesh triangles are in world coordinates.  So nothing here
 * normalises, bakes or rounds: a number is stored as read, bit for bit, and
 * refused when it breaks a rule.  That is what makes export -> load give
 * the same scene.  The members refray derives (conventions, features, the
 * camera's basis and samples, light sampling, to_local, a rectangle light's
 * normal) are not read: they are derived again, and checked against the
 * document's when it has them (load_json_derived.c, [JSON-DERIVED-1]).
 */
#include <ctype.h>
#include <math.h>
#include <string.h>
#include "lang/obj.h"
#include "scene/json_read.h"

static const char *const falloff_names[] = {"linear", "inverse_square", "none"};

/* Out of memory, too many errors, or cancelled (a step of the load's
 * cancel poll per element: [REL-CANCEL-1]). */
static int stop(const loader *L)
{
    return loader_stop(L);
}

/* The member key of obj, read with the path on it. */
static json_t *enter(jreader *r, json_t *obj, const char *key)
{
    json_t *v = jread_member(r, obj, key);
    if (v)
        jread_push_key(r, key);
    return v;
}

static int read_format(jreader *r, json_t *root)
{
    static const char *const keys[] = {"name", "version", "generator", NULL};
    const char *name;
    double version;
    json_t *f = enter(r, root, "format");
    if (!f)
        return 0;
    int ok = jread_is_object(r, f) && jread_known(r, f, keys) && jread_string(r, f, "name", 0, &name) &&
             jread_number(r, f, "version", &version);
    if (ok && strcmp(name, SCENE_JSON_FORMAT) != 0) {
        diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, "name"), "not a refray scene: the format is '%s', not '%s'",
                    name, SCENE_JSON_FORMAT);
        ok = 0;
    } else if (ok && version != SCENE_JSON_VERSION) {
        diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, "version"),
                    "format version %.17g: this refray reads version %d", version, SCENE_JSON_VERSION);
        ok = 0;
    }
    jread_pop(r);
    return ok;
}

static int read_image(jreader *r, json_t *root)
{
    static const char *const keys[] = {"width", "height", "samples", "max_depth", "background", NULL};
    double size[4];
    rgb background;
    json_t *im = enter(r, root, "image");
    if (!im)
        return 0;
    int ok = jread_is_object(r, im) && jread_known(r, im, keys);
    ok = ok && jread_number(r, im, "width", &size[0]) && jread_number(r, im, "height", &size[1]) &&
         jread_number(r, im, "samples", &size[2]) && jread_number(r, im, "max_depth", &size[3]) &&
         jread_vec3(r, im, "background", &background);
    check_at at = jread_at(r);
    ok = ok && check_image(r->L, &at, size, background, &r->L->scene->image);
    jread_pop(r);
    return ok;
}

static int read_camera(jreader *r, json_t *root)
{
    static const char *const projections[] = {"perspective", "orthographic"};
    static const char *const persp_keys[] = {"projection", "eye", "look_at", "up", "fov", "basis", "screen",
                                             "pixel_samples", NULL};
    static const char *const ortho_keys[] = {"projection", "eye", "look_at", "up", "width", "basis", "screen",
                                             "pixel_samples", NULL};
    scene_camera *cam = &r->L->scene->camera;
    int kind;
    json_t *c = enter(r, root, "camera");
    if (!c)
        return 0;
    int ok = jread_is_object(r, c) && jread_enum(r, c, "projection", projections, 2, &kind);
    if (ok) {
        cam->kind = kind == 0 ? CAMERA_PERSPECTIVE : CAMERA_ORTHOGRAPHIC;
        cam->where = jread_span(r, NULL);
        ok = jread_known(r, c, kind == 0 ? persp_keys : ortho_keys) && jread_vec3(r, c, "eye", &cam->eye) &&
             jread_vec3(r, c, "look_at", &cam->look_at) && jread_vec3(r, c, "up", &cam->up) &&
             jread_number(r, c, kind == 0 ? "fov" : "width", kind == 0 ? &cam->fov : &cam->width);
    }
    check_at at = jread_at(r);
    ok = ok && check_camera(r->L, &at, cam);
    jread_pop(r);
    return ok;
}

static int read_ambient(jreader *r, json_t *root)
{
    rgb color;
    if (!jread_vec3(r, root, "ambient", &color))
        return 0;
    jread_push_key(r, "ambient");
    check_at at = jread_at(r);
    int ok = check_ambient(r->L, &at, color);
    jread_pop(r);
    r->L->scene->ambient = color;
    return ok;
}

/* The span of each element of the top-level array key: where a record
 * came from, found in one walk of the text.  NULL when out of memory; free
 * with count (at least 1) entries. */
static size_t *element_begins(jreader *r, const char *key, size_t count)
{
    const source_file *f = r->L->scene->sources.files[r->file];
    jsonloc_step step = {key, 0};
    size_t *begins = mem_calloc(r->L->mem, count ? count : 1, sizeof *begins);
    if (!begins)
        loader_oom(r->L);
    else
        jsonloc_elements(f->text, f->len, &step, 1, begins, count);
    return begins;
}

static src_span element_span(const jreader *r, const size_t *begins, size_t i)
{
    src_span s = {r->file, begins[i], begins[i] + 1};
    return s;
}

static int read_material(jreader *r, json_t *m, src_span where)
{
    static const char *const keys[] = {"name", "Kd", "Ks", "n", "t", "ior", NULL};
    scene_material mat;
    const char *name;
    memset(&mat, 0, sizeof mat);
    mat.where = where;
    int ok = jread_is_object(r, m) && jread_known(r, m, keys) && jread_string(r, m, "name", 1, &name) &&
             jread_vec3(r, m, "Kd", &mat.kd) && jread_vec3(r, m, "Ks", &mat.ks) && jread_number(r, m, "n", &mat.n) &&
             jread_number(r, m, "t", &mat.t) && jread_number(r, m, "ior", &mat.ior);
    check_at at = jread_at(r);
    if (!ok || !check_material(r->L, &at, &mat))
        return 0;
    scene_material *slot = loader_add_material(r->L);
    if (!slot || (name && !(mat.name = loader_strdup(r->L, name))))
        return 0;
    *slot = mat;
    return 1;
}

/* Each element of the top-level array key through read_one. */
static int read_list(jreader *r, json_t *root, const char *key, int (*read_one)(jreader *, json_t *, src_span))
{
    json_t *list, *item;
    size_t i;
    if (!jread_array(r, root, key, &list))
        return 0;
    size_t count = json_array_size(list);
    size_t *begins = element_begins(r, key, count);
    if (!begins)
        return 0;
    int ok = 1;
    jread_push_key(r, key);
    json_array_foreach(list, i, item) {
        if (stop(r->L))
            break;
        jread_push_index(r, i);
        ok &= read_one(r, item, element_span(r, begins, i));
        jread_pop(r);
    }
    jread_pop(r);
    mem_free(r->L->mem, begins, (count ? count : 1) * sizeof *begins);
    return ok && !stop(r->L);
}

/* ---- lights ---- */

static int light_falloff(jreader *r, json_t *l, scene_light *light)
{
    int f;
    if (light->kind == LIGHT_DISTANT) {
        light->falloff = FALLOFF_NONE;
        return jread_enum(r, l, "falloff", falloff_names + 2, 1, &f);
    }
    if (!jread_enum(r, l, "falloff", falloff_names, 3, &f) || !jread_number(r, l, "d0", &light->d0))
        return 0;
    light->falloff = (scene_falloff)f;
    return 1;
}

static int light_samples(jreader *r, json_t *l, scene_light *light)
{
    double samples;
    check_at at = jread_at(r);
    return jread_number(r, l, "samples", &samples) && check_light_samples(r->L, &at, samples, &light->samples);
}

static int light_shape(jreader *r, json_t *l, scene_light *light)
{
    check_at at = jread_at(r);
    switch (light->kind) {
    case LIGHT_POINT: return jread_vec3(r, l, "position", &light->position);
    case LIGHT_DISTANT:
        return jread_vec3(r, l, "direction", &light->direction) &&
               check_unit(r->L, &at, KW_DIRECTION, "direction", light->direction);
    case LIGHT_RECTANGLE:
        return jread_vec3(r, l, "corner", &light->position) && jread_vec3(r, l, "edge_u", &light->edge_u) &&
               jread_vec3(r, l, "edge_v", &light->edge_v) && light_samples(r, l, light) &&
               check_rectangle(r->L, &at, light);
    case LIGHT_DISK:
        return jread_vec3(r, l, "center", &light->position) && jread_vec3(r, l, "normal", &light->normal) &&
               jread_number(r, l, "radius", &light->radius) && light_samples(r, l, light) &&
               check_unit(r->L, &at, KW_NORMAL, "normal", light->normal) && check_radius(r->L, &at, light->radius) &&
               check_light_extent(r->L, &at, light);
    }
    return 0;
}

static int read_light(jreader *r, json_t *l, src_span where)
{
    static const char *const kinds[] = {"point", "distant", "rectangle", "disk"};
    static const char *const keys[4][11] = {
        {"kind", "position", "power", "falloff", "d0", NULL},
        {"kind", "direction", "power", "falloff", NULL},
        {"kind", "corner", "edge_u", "edge_v", "normal", "power", "falloff", "d0", "samples", "sampling", NULL},
        {"kind", "center", "normal", "radius", "power", "falloff", "d0", "samples", "sampling", NULL},
    };
    scene_light light;
    int kind;
    memset(&light, 0, sizeof light);
    light.where = where;
    if (!jread_is_object(r, l) || !jread_enum(r, l, "kind", kinds, 4, &kind))
        return 0;
    light.kind = (scene_light_kind)kind;
    int ok = jread_known(r, l, keys[kind]) && light_shape(r, l, &light) &&
             jread_vec3(r, l, "power", &light.power) && light_falloff(r, l, &light);
    check_at at = jread_at(r);
    if (!ok || !check_light(r->L, &at, &light))
        return 0;
    scene_light *slot = loader_add_light(r->L);
    if (slot)
        *slot = light;
    return slot != NULL;
}

/* ---- primitives ---- */

/* to_world: four rows of four numbers, the last [0, 0, 0, 1]. */
static int read_matrix(jreader *r, json_t *t, xform *out)
{
    json_t *rows;
    if (!jread_array(r, t, "to_world", &rows))
        return 0;
    jread_push_key(r, "to_world");
    int ok = json_array_size(rows) == 4;
    for (size_t i = 0; ok && i < 4; i++) {
        json_t *row = json_array_get(rows, i);
        ok = json_is_array(row) && json_array_size(row) == 4;
        for (size_t j = 0; ok && j < 4; j++) {
            json_t *e = json_array_get(row, j);
            ok = json_is_number(e);
            double x = ok ? json_number_value(e) : 0;
            if (i < 3)
                out->m[i][j] = x;
            else
                ok = ok && x == (j == 3 ? 1 : 0);
        }
    }
    if (!ok)
        diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, NULL),
                    "expected a 4 x 4 matrix: four rows of four numbers, the last row [0, 0, 0, 1]");
    jread_pop(r);
    return ok;
}

static int read_transform(jreader *r, json_t *p, scene_prim *prim)
{
    static const char *const keys[] = {"to_world", "to_local", NULL};
    json_t *t = jread_member(r, p, "transform");
    if (!t)
        return 0;
    if (json_is_null(t))
        return 1;
    jread_push_key(r, "transform");
    scene_frame f;
    int ok = jread_is_object(r, t) && jread_known(r, t, keys) && read_matrix(r, t, &f.to_world);
    jread_pop(r);
    check_at at = jread_at(r);
    return ok && check_invert(r->L, &at, &f.to_world, &f.to_local) &&
           lower_keep_frame(r->L, prim, &f.to_world, &f.to_local);
}

static int read_vertices(jreader *r, json_t *p, scene_prim *prim)
{
    json_t *v;
    if (!jread_array(r, p, "vertices", &v))
        return 0;
    jread_push_key(r, "vertices");
    int ok = json_array_size(v) == 3;
    if (!ok)
        diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, NULL), "expected 3 vertices, got %zu", json_array_size(v));
    for (size_t i = 0; ok && i < 3; i++) {
        jread_push_index(r, i);
        ok = jread_value_vec3(r, json_array_get(v, i), &prim->u.triangle.p[i]);
        jread_pop(r);
    }
    jread_pop(r);
    return ok;
}

/* radii: [at from, at to]. */
static int read_cone(jreader *r, json_t *p, scene_prim *prim)
{
    check_at at = jread_at(r);
    json_t *radii;
    if (!jread_vec3(r, p, "from", &prim->u.cone.from) || !jread_vec3(r, p, "to", &prim->u.cone.to) ||
        !jread_array(r, p, "radii", &radii) || !jread_bool(r, p, "open", &prim->u.cone.open))
        return 0;
    jread_push_key(r, "radii");
    int ok = json_array_size(radii) == 2;
    if (!ok)
        diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, NULL), "expected an array of 2 numbers, got %zu value%s",
                    json_array_size(radii), json_array_size(radii) == 1 ? "" : "s");
    for (size_t i = 0; ok && i < 2; i++) {
        json_t *e = json_array_get(radii, i);
        jread_push_index(r, i);
        ok = json_is_number(e);
        if (!ok)
            diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, NULL), "expected a number");
        else
            prim->u.cone.radius[i] = json_number_value(e);
        jread_pop(r);
    }
    jread_pop(r);
    return ok && check_ends(r->L, &at, prim->u.cone.from, prim->u.cone.to) &&
           check_cone_radii(r->L, &at, prim->u.cone.radius);
}

static int prim_shape(jreader *r, json_t *p, scene_prim *prim)
{
    check_at at = jread_at(r);
    vec3 from, to;
    switch (prim->kind) {
    case PRIM_SPHERE:
        return jread_vec3(r, p, "center", &prim->u.sphere.center) &&
               jread_number(r, p, "radius", &prim->u.sphere.radius) && check_radius(r->L, &at, prim->u.sphere.radius);
    case PRIM_PLANE:
        return jread_vec3(r, p, "point", &prim->u.plane.point) && jread_vec3(r, p, "normal", &prim->u.plane.normal) &&
               check_unit(r->L, &at, KW_NORMAL, "normal", prim->u.plane.normal);
    case PRIM_TRIANGLE: return read_vertices(r, p, prim);
    case PRIM_DISK:
        return jread_vec3(r, p, "center", &prim->u.disk.center) && jread_vec3(r, p, "normal", &prim->u.disk.normal) &&
               jread_number(r, p, "radius", &prim->u.disk.radius) &&
               check_unit(r->L, &at, KW_NORMAL, "normal", prim->u.disk.normal) &&
               check_radius(r->L, &at, prim->u.disk.radius);
    case PRIM_BOX:
        return jread_vec3(r, p, "from", &from) && jread_vec3(r, p, "to", &to) && check_box(r->L, &at, from, to, prim);
    case PRIM_CYLINDER:
        return jread_vec3(r, p, "from", &prim->u.cylinder.from) && jread_vec3(r, p, "to", &prim->u.cylinder.to) &&
               jread_number(r, p, "radius", &prim->u.cylinder.radius) &&
               jread_bool(r, p, "open", &prim->u.cylinder.open) &&
               check_ends(r->L, &at, prim->u.cylinder.from, prim->u.cylinder.to) &&
               check_radius(r->L, &at, prim->u.cylinder.radius);
    case PRIM_CONE: return read_cone(r, p, prim);
    case PRIM_TORUS:
        return jread_vec3(r, p, "center", &prim->u.torus.center) && jread_vec3(r, p, "axis", &prim->u.torus.axis) &&
               jread_number(r, p, "major", &prim->u.torus.major) && jread_number(r, p, "minor", &prim->u.torus.minor) &&
               check_unit(r->L, &at, KW_AXIS, "axis", prim->u.torus.axis) &&
               check_torus(r->L, &at, prim->u.torus.major, prim->u.torus.minor);
    case PRIM_MESH: break; /* load_json_mesh.c */
    }
    return 0;
}

static int use_material(jreader *r, json_t *p, int *material)
{
    if (!jread_index(r, p, "material", r->L->scene->material_count, "material", material))
        return 0;
    r->L->material_uses[*material]++;
    return 1;
}

static int read_prim(jreader *r, json_t *p, src_span where)
{
    static const char *const kinds[PRIM_KINDS] = {"sphere", "plane", "triangle", "disk", "box",
                                                  "cylinder", "cone", "torus", "mesh"};
    static const char *const keys[PRIM_KINDS][8] = {
        {"kind", "material", "transform", "center", "radius", NULL},
        {"kind", "material", "transform", "point", "normal", NULL},
        {"kind", "material", "transform", "vertices", NULL},
        {"kind", "material", "transform", "center", "normal", "radius", NULL},
        {"kind", "material", "transform", "from", "to", NULL},
        {"kind", "material", "transform", "from", "to", "radius", "open", NULL},
        {"kind", "material", "transform", "from", "to", "radii", "open", NULL},
        {"kind", "material", "transform", "center", "axis", "major", "minor", NULL},
    };
    scene_prim prim;
    int kind;
    memset(&prim, 0, sizeof prim);
    prim.mesh = -1;
    prim.where = where;
    if (!jread_is_object(r, p) || !jread_enum(r, p, "kind", kinds, PRIM_KINDS, &kind))
        return 0;
    if (kind == PRIM_MESH)
        return use_material(r, p, &prim.material) && load_json_mesh(r, p, &prim);
    prim.kind = (scene_prim_kind)kind;
    int ok = jread_known(r, p, keys[kind]) && prim_shape(r, p, &prim) &&
             use_material(r, p, &prim.material) && read_transform(r, p, &prim);
    check_at at = jread_at(r);
    if (!ok || !check_placed(r->L, &at, &prim))
        return 0;
    scene_prim *slot = loader_add_prim(r->L, where);
    if (slot)
        *slot = prim;
    return slot != NULL;
}

/* ---- the document ---- */

static int read_oracle(jreader *r, json_t *root)
{
    const char *name;
    if (!jread_string(r, root, "oracle", 1, &name))
        return 0;
    if (!name)
        return 1;
    /* The scene language's `oracle NAME` takes a name; so does this, which
     * also keeps control bytes out of what `refray check` prints. */
    int word = (isalpha((unsigned char)name[0]) || name[0] == '_');
    for (const char *c = name; word && *c; c++)
        word = isalnum((unsigned char)*c) || *c == '_';
    if (!word) {
        diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, "oracle"),
                    "an oracle family is a name (a letter or _, then letters, digits and _), got '%s'", name);
        return 0;
    }
    r->L->scene->oracle = loader_strdup(r->L, name);
    r->L->scene->oracle_where = jread_span(r, "oracle");
    return r->L->scene->oracle != NULL;
}

static int read_scene(jreader *r, json_t *root)
{
    static const char *const keys[] = {"format", "conventions", "source", "oracle", "features", "image", "camera",
                                       "ambient", "materials", "lights", "primitives", NULL};
    if (!jread_is_object(r, root) || !jread_known(r, root, keys) || !read_format(r, root))
        return 0;
    int ok = read_oracle(r, root);
    ok &= read_image(r, root);
    ok &= read_camera(r, root);
    ok &= read_ambient(r, root);
    if (!ok || stop(r->L))
        return 0;
    ok = read_list(r, root, "materials", read_material);
    ok &= read_list(r, root, "lights", read_light);
    return ok && read_list(r, root, "primitives", read_prim);
}

/* The diag subject of a span in the JSON text: the pointer of its value.
 * The only other files of a JSON load are the OBJ files its meshes read. */
static size_t json_subject(const void *ctx, src_span span, char *buf, size_t size)
{
    const source_set *set = ctx;
    const source_file *f = set->files[span.file];
    if (f->is_mesh)
        return 0;
    return jsonloc_pointer_at(f->text, f->len, span.begin, buf, size);
}

int loader_lower_json(loader *L, int file)
{
    json_t *root = jread_parse(L, file);
    if (!root)
        return 0;
    L->diag.subject = json_subject;
    L->diag.subject_ctx = &L->scene->sources;
    jreader r;
    memset(&r, 0, sizeof r);
    r.L = L;
    r.file = file;
    int ok = read_scene(&r, root);
    /* The tree is kept for the check of the derived members, which needs
     * the scene validated (its features). */
    L->json_root = root;
    L->json_file = file;
    return ok && !stop(L);
}

int loader_json_finish(loader *L, int ok)
{
    json_t *root = L->json_root;
    if (root && ok) {
        jreader r;
        memset(&r, 0, sizeof r);
        r.L = L;
        r.file = L->json_file;
        ok = load_json_derived(&r, root);
    }
    json_decref(root);
    L->json_root = NULL;
    return ok;
}
