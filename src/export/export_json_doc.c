/*
 * export_json_doc.c - the document of a scene (spec/json.md, member by
 * member): the model as the loader left it, every number the double refray
 * renders with, plus what refray derives from it (camera basis and
 * samples, light sampling, inverse matrices, features), marked derived in
 * the spec because the loader does not read it back.  JSON=1 builds only.
 */
#include <stdio.h>
#include "export/export_json_impl.h"
#include "render/camera.h"
#include "render/render.h"
#include "render/shade.h"

/* How many sample points a light's worked example lists. */
enum { EXAMPLE_POINTS = 16 };

static void set_vec(export_json_build *b, json_t *obj, const char *key, vec3 v)
{
    export_json_set(b, obj, key, export_json_vec3(v));
}

static void set_real(export_json_build *b, json_t *obj, const char *key, double x)
{
    export_json_set(b, obj, key, json_real(x));
}

static void set_int(export_json_build *b, json_t *obj, const char *key, long x)
{
    export_json_set(b, obj, key, json_integer(x));
}

/* A string, or null for NULL (and for a path that is not UTF-8, which a
 * JSON string cannot hold). */
static void set_text(export_json_build *b, json_t *obj, const char *key, const char *text)
{
    json_t *v = text ? json_string(text) : NULL;
    export_json_set(b, obj, key, v ? v : json_null());
}

static json_t *format(export_json_build *b, const export_json_opts *o)
{
    json_t *f = json_object();
    set_text(b, f, "name", SCENE_JSON_FORMAT);
    set_int(b, f, "version", SCENE_JSON_VERSION);
    if (o->generator)
        set_text(b, f, "generator", o->generator);
    return f;
}

static json_t *features(export_json_build *b, const scene_features *f)
{
    json_t *out = json_object();
    export_json_set(b, out, "shadows", json_boolean(f->shadows));
    export_json_set(b, out, "specular", json_boolean(f->specular));
    export_json_set(b, out, "reflection", json_boolean(f->reflection));
    export_json_set(b, out, "refraction", json_boolean(f->refraction));
    export_json_set(b, out, "sampled_lights", json_boolean(f->sampled_lights));
    export_json_set(b, out, "meshes", json_boolean(f->meshes));
    return out;
}

static json_t *image(export_json_build *b, const scene_image_spec *im)
{
    json_t *out = json_object();
    set_int(b, out, "width", im->width);
    set_int(b, out, "height", im->height);
    set_int(b, out, "samples", im->samples);
    set_int(b, out, "max_depth", im->max_depth);
    set_vec(b, out, "background", im->background);
    return out;
}

/* The offsets of the k x k camera samples from the pixel's corner, in the
 * order of their index b * k + a (render_pixel's loop). */
static json_t *pixel_samples(export_json_build *b, int k)
{
    json_t *out = json_object(), *offsets = json_array();
    set_int(b, out, "k", k);
    for (int j = 0; j < k; j++)
        for (int i = 0; i < k; i++)
            export_json_append(b, offsets, json_pack("[ff]", render_sample_offset(k, i), render_sample_offset(k, j)));
    export_json_set(b, out, "offsets", offsets);
    return out;
}

/* The scalars of the camera_ray formula, and the ray of the first sample
 * of pixel (0, 0) as a worked example. */
static json_t *screen(export_json_build *b, const scene_model *s)
{
    const scene_camera *cam = &s->camera;
    const scene_image_spec *im = &s->image;
    json_t *out = json_object(), *example = json_object();
    real half = cam->kind == CAMERA_ORTHOGRAPHIC ? 0.5 * cam->width : tan(0.5 * cam->fov * (REAL_PI / 180));
    set_real(b, out, "aspect", (double)((real)im->height / (real)im->width));
    set_real(b, out, "half", (double)half);
    double x = render_sample_offset(im->samples, 0);
    ray r = camera_ray(cam, camera_half(cam), im->width, im->height, x, x);
    export_json_set(b, example, "point", json_pack("[ff]", x, x));
    set_vec(b, example, "origin", r.origin);
    set_vec(b, example, "direction", r.dir);
    export_json_set(b, out, "example", example);
    return out;
}

static json_t *camera(export_json_build *b, const scene_model *s)
{
    const scene_camera *cam = &s->camera;
    json_t *out = json_object(), *basis = json_object();
    int ortho = cam->kind == CAMERA_ORTHOGRAPHIC;
    set_text(b, out, "projection", ortho ? "orthographic" : "perspective");
    set_vec(b, out, "eye", cam->eye);
    set_vec(b, out, "look_at", cam->look_at);
    set_vec(b, out, "up", cam->up);
    set_real(b, out, ortho ? "width" : "fov", ortho ? cam->width : cam->fov);
    set_vec(b, basis, "forward", cam->forward);
    set_vec(b, basis, "right", cam->right);
    set_vec(b, basis, "up", cam->true_up);
    export_json_set(b, out, "basis", basis);
    export_json_set(b, out, "screen", screen(b, s));
    export_json_set(b, out, "pixel_samples", pixel_samples(b, s->image.samples));
    return out;
}

static json_t *material(export_json_build *b, const scene_material *m)
{
    json_t *out = json_object();
    set_text(b, out, "name", m->name);
    set_vec(b, out, "Kd", m->kd);
    set_vec(b, out, "Ks", m->ks);
    set_real(b, out, "n", m->n);
    set_real(b, out, "t", m->t);
    set_real(b, out, "ior", m->ior);
    return out;
}

/* The stratification, per-sample power and frame refray uses, and the
 * points of the first camera sample of pixel (0, 0) as a worked example
 * (conventions.light_samples has the rule). */
static json_t *sampling(export_json_build *b, const scene_model *s, int index)
{
    const scene_light *light = &s->lights[index];
    light_setup setup = trace_light_setup(light, light->samples);
    json_t *out = json_object(), *grid = json_object(), *example = json_object(), *points = json_array();
    set_int(b, grid, "rows", setup.grid.rows);
    set_int(b, grid, "cols", setup.grid.cols);
    export_json_set(b, out, "grid", grid);
    set_vec(b, out, "sample_power", shade_sample_power(light->power, light->samples));
    if (light->kind == LIGHT_DISK) {
        json_t *frame = json_object();
        set_vec(b, frame, "t1", setup.t1);
        set_vec(b, frame, "t2", setup.t2);
        export_json_set(b, out, "frame", frame);
    }
    uint64_t key = render_sample_key(s->image.width, s->image.samples, 0, 0, 0, 0);
    export_json_set(b, example, "pixel", json_pack("[ii]", 0, 0));
    export_json_set(b, example, "camera_sample", json_pack("[ii]", 0, 0));
    set_text(b, example, "ray", "the camera ray");
    export_json_set(b, example, "key", export_json_hex(key));
    for (int j = 0; j < light->samples && j < EXAMPLE_POINTS; j++)
        export_json_append(b, points, export_json_vec3(trace_light_point(light, &setup, index, key, j)));
    export_json_set(b, example, "points", points);
    export_json_set(b, out, "example", example);
    return out;
}

static json_t *light(export_json_build *b, const scene_model *s, int index)
{
    static const char *const kinds[] = {"point", "distant", "rectangle", "disk"};
    static const char *const falloffs[] = {"linear", "inverse_square", "none"};
    const scene_light *l = &s->lights[index];
    json_t *out = json_object();
    set_text(b, out, "kind", kinds[l->kind]);
    switch (l->kind) {
    case LIGHT_POINT: set_vec(b, out, "position", l->position); break;
    case LIGHT_DISTANT: set_vec(b, out, "direction", l->direction); break;
    case LIGHT_RECTANGLE:
        set_vec(b, out, "corner", l->position);
        set_vec(b, out, "edge_u", l->edge_u);
        set_vec(b, out, "edge_v", l->edge_v);
        set_vec(b, out, "normal", l->normal);
        break;
    case LIGHT_DISK:
        set_vec(b, out, "center", l->position);
        set_vec(b, out, "normal", l->normal);
        set_real(b, out, "radius", l->radius);
        break;
    }
    set_vec(b, out, "power", l->power);
    set_text(b, out, "falloff", falloffs[l->falloff]);
    if (l->kind != LIGHT_DISTANT)
        set_real(b, out, "d0", l->d0);
    if (l->kind == LIGHT_RECTANGLE || l->kind == LIGHT_DISK) {
        set_int(b, out, "samples", l->samples);
        export_json_set(b, out, "sampling", sampling(b, s, index));
    }
    return out;
}

static json_t *matrix(const xform *a)
{
    const double(*m)[4] = a->m;
    return json_pack("[[ffff][ffff][ffff][ffff]]", m[0][0], m[0][1], m[0][2], m[0][3], m[1][0], m[1][1], m[1][2],
                     m[1][3], m[2][0], m[2][1], m[2][2], m[2][3], 0.0, 0.0, 0.0, 1.0);
}

static json_t *transform(export_json_build *b, const scene_prim *p)
{
    if (!p->frame)
        return json_null();
    json_t *out = json_object();
    export_json_set(b, out, "to_world", matrix(&p->frame->to_world));
    export_json_set(b, out, "to_local", matrix(&p->frame->to_local));
    return out;
}

static json_t *primitive(export_json_build *b, const scene_prim *p)
{
    json_t *out = json_object(), *corners;
    set_text(b, out, "kind", scene_prim_name(p->kind));
    set_int(b, out, "material", p->material);
    switch (p->kind) {
    case PRIM_SPHERE:
        set_vec(b, out, "center", p->u.sphere.center);
        set_real(b, out, "radius", p->u.sphere.radius);
        break;
    case PRIM_PLANE:
        set_vec(b, out, "point", p->u.plane.point);
        set_vec(b, out, "normal", p->u.plane.normal);
        break;
    case PRIM_TRIANGLE:
        corners = json_array();
        for (int i = 0; i < 3; i++)
            export_json_append(b, corners, export_json_vec3(p->u.triangle.p[i]));
        export_json_set(b, out, "vertices", corners);
        break;
    case PRIM_DISK:
        set_vec(b, out, "center", p->u.disk.center);
        set_vec(b, out, "normal", p->u.disk.normal);
        set_real(b, out, "radius", p->u.disk.radius);
        break;
    case PRIM_BOX:
        set_vec(b, out, "from", p->u.box.lo);
        set_vec(b, out, "to", p->u.box.hi);
        break;
    case PRIM_CYLINDER:
        set_vec(b, out, "from", p->u.cylinder.from);
        set_vec(b, out, "to", p->u.cylinder.to);
        set_real(b, out, "radius", p->u.cylinder.radius);
        export_json_set(b, out, "open", json_boolean(p->u.cylinder.open));
        break;
    case PRIM_CONE:
        set_vec(b, out, "from", p->u.cone.from);
        set_vec(b, out, "to", p->u.cone.to);
        export_json_set(b, out, "radii", json_pack("[ff]", p->u.cone.radius[0], p->u.cone.radius[1]));
        export_json_set(b, out, "open", json_boolean(p->u.cone.open));
        break;
    case PRIM_TORUS:
        set_vec(b, out, "center", p->u.torus.center);
        set_vec(b, out, "axis", p->u.torus.axis);
        set_real(b, out, "major", p->u.torus.major);
        set_real(b, out, "minor", p->u.torus.minor);
        break;
    case PRIM_MESH: break; /* written by export_json_mesh, never here */
    }
    export_json_set(b, out, "transform", transform(b, p));
    return out;
}

/* The primitives in the scene's order; a mesh (one primitive) as its
 * mesh entry. */
static json_t *primitives(export_json_build *b, const scene_model *s, const export_json_opts *o, int *status, char *err,
                          size_t errlen)
{
    json_t *out = json_array();
    for (int i = 0; i < s->prim_count && *status == 0; i++) {
        int m = s->prims[i].mesh;
        if (m < 0) {
            export_json_append(b, out, primitive(b, &s->prims[i]));
            continue;
        }
        json_t *mesh = export_json_mesh(s, m, o, status, err, errlen);
        if (!mesh)
            break;
        export_json_append(b, out, mesh);
    }
    return out;
}

json_t *export_json_document(const scene_model *s, const export_json_opts *o, int *status, char *err, size_t errlen)
{
    export_json_build b = {0};
    json_t *doc = json_object(), *materials = json_array(), *lights = json_array();
    *status = 0;
    export_json_set(&b, doc, "format", format(&b, o));
    export_json_set(&b, doc, "conventions", export_json_conventions(&b));
    set_text(&b, doc, "source", o->source);
    set_text(&b, doc, "oracle", s->oracle);
    export_json_set(&b, doc, "features", features(&b, &s->features));
    export_json_set(&b, doc, "image", image(&b, &s->image));
    export_json_set(&b, doc, "camera", camera(&b, s));
    set_vec(&b, doc, "ambient", s->ambient);
    for (int i = 0; i < s->material_count; i++)
        export_json_append(&b, materials, material(&b, &s->materials[i]));
    export_json_set(&b, doc, "materials", materials);
    for (int i = 0; i < s->light_count; i++)
        export_json_append(&b, lights, light(&b, s, i));
    export_json_set(&b, doc, "lights", lights);
    export_json_set(&b, doc, "primitives", primitives(&b, s, o, status, err, errlen));
    if (*status == 0 && b.failed) {
        *status = STATUS_NO_MEMORY;
        snprintf(err, errlen, "out of memory");
    }
    if (*status != 0) {
        json_decref(doc);
        return NULL;
    }
    return doc;
}
