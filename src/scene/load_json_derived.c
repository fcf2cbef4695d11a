/*
 * load_json_derived.c - the members a JSON scene derives from its primary
 * ones (spec/json.md, [JSON-DERIVED-1]) checked against the scene the
 * primary members made.  Built only with JSON=1.
 *
 * refray renders from the primary members and derives the rest again; a
 * reader of the document may instead take a derived member as data (the
 * camera basis, the sampling grid, to_local).  So a document whose derived
 * members were edited would render one way here and another way there,
 * silently.  A derived member may be left out (the schema wants it in an
 * export, the loader does not); when it is there it must agree:
 *   - a number within DERIVED_TOL of the value derived here, relative to
 *     max(1, |value|): another exporter's libm or order of evaluation moves
 *     the last bits, an edit that changes an image moves far more;
 *   - an integer, a flag, a constant or a text exactly.
 * Values refray keeps in the model (the camera basis, a rectangle's
 * normal, to_local, the features) are compared with the model; the others
 * are computed here by the formulas of spec/json.md, the same rules the
 * renderer follows ([JSON-CAMERA-1], [JSON-SAMPLES-1]).  The prose of
 * `conventions` is for people and is not compared; its constants are.
 * The first member that disagrees is reported, by its JSON pointer, with
 * the primary members it is derived from and the tolerance.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "base/sampler.h"
#include "scene/json_read.h"

#define DERIVED_TOL 1e-9
#define DERIVED_TOL_TEXT "1e-9"
/* The end of every message: the rule. */
#define DERIVED_RULE "(a derived member agrees with what it is derived from, numbers within " DERIVED_TOL_TEXT \
                     " relative, or is left out: spec/json.md)"

/* The double nearest pi, as the renderer uses it. */
#define PI ((double)REAL_PI)

/* At most this many example points per light are written (export). */
enum { EXAMPLE_POINTS = 16 };

static int agree(double got, double want)
{
    return fabs(got - want) <= DERIVED_TOL * fmax(1.0, fabs(want));
}

/* The member key of obj, or NULL: a derived member may be left out. */
static json_t *present(json_t *obj, const char *key)
{
    return json_is_object(obj) ? json_object_get(obj, key) : NULL;
}

/* The number val at the current path against want. */
static int number(jreader *r, json_t *val, double want, const char *from)
{
    if (!json_is_number(val)) {
        diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, NULL), "expected a number");
        return 0;
    }
    double got = json_number_value(val);
    if (agree(got, want))
        return 1;
    diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, NULL),
                "disagrees with %s, from which it is derived: expected %.17g, got %.17g " DERIVED_RULE, from, want, got);
    return 0;
}

/* val at the current path: an array of n numbers against want. */
static int numbers(jreader *r, json_t *val, const double *want, size_t n, const char *from)
{
    if (!json_is_array(val) || json_array_size(val) != n) {
        diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, NULL), "expected an array of %zu numbers", n);
        return 0;
    }
    int ok = 1;
    for (size_t i = 0; ok && i < n; i++) {
        jread_push_index(r, i);
        ok = number(r, json_array_get(val, i), want[i], from);
        jread_pop(r);
    }
    return ok;
}

/* Member key of obj, when there: n numbers (n 0: one number). */
static int member(jreader *r, json_t *obj, const char *key, const double *want, size_t n, const char *from)
{
    json_t *v = present(obj, key);
    if (!v)
        return 1;
    jread_push_key(r, key);
    int ok = n ? numbers(r, v, want, n, from) : number(r, v, want[0], from);
    jread_pop(r);
    return ok;
}

static int member_number(jreader *r, json_t *obj, const char *key, double want, const char *from)
{
    return member(r, obj, key, &want, 0, from);
}

static int member_vec(jreader *r, json_t *obj, const char *key, vec3 want, const char *from)
{
    double w[3] = {(double)want.x, (double)want.y, (double)want.z};
    return member(r, obj, key, w, 3, from);
}

/* Member key of obj, when there: an array of count values, each checked
 * by one(r, value, i, ctx). */
static int member_list(jreader *r, json_t *obj, const char *key, size_t count, const char *what,
                       int (*one)(jreader *, json_t *, size_t, const void *), const void *ctx)
{
    json_t *v = present(obj, key);
    if (!v)
        return 1;
    jread_push_key(r, key);
    int ok = json_is_array(v) && json_array_size(v) == count;
    if (!ok)
        diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, NULL), "expected an array of %zu %s", count, what);
    for (size_t i = 0; ok && i < count; i++) {
        jread_push_index(r, i);
        ok = one(r, json_array_get(v, i), i, ctx);
        jread_pop(r);
    }
    jread_pop(r);
    return ok;
}

static int member_flag(jreader *r, json_t *obj, const char *key, int want, const char *from)
{
    int got;
    if (!present(obj, key))
        return 1;
    if (!jread_bool(r, obj, key, &got))
        return 0;
    if (!got == !want)
        return 1;
    diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, key), "disagrees with %s, from which it is derived: expected %s, got %s " DERIVED_RULE, from,
                want ? "true" : "false", got ? "true" : "false");
    return 0;
}

static int member_text(jreader *r, json_t *obj, const char *key, const char *want, const char *from)
{
    const char *got;
    if (!present(obj, key))
        return 1;
    if (!jread_string(r, obj, key, 0, &got))
        return 0;
    if (strcmp(got, want) == 0)
        return 1;
    diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, key), "disagrees with %s, from which it is derived: expected '%s' " DERIVED_RULE,
                from, want);
    return 0;
}

/* A 64-bit constant written as a hex string ("0x9e37..."). */
static int member_hex(jreader *r, json_t *obj, const char *key, uint64_t want, const char *from)
{
    const char *got;
    char *end;
    if (!present(obj, key))
        return 1;
    if (!jread_string(r, obj, key, 0, &got))
        return 0;
    /* Hex digits only after the 0x: strtoull alone would also take spaces,
     * a sign and a second "0x". */
    int hex = got[0] == '0' && (got[1] == 'x' || got[1] == 'X') && got[2] != '\0' &&
              strspn(got + 2, "0123456789abcdefABCDEF") == strlen(got + 2);
    unsigned long long v = hex ? strtoull(got + 2, &end, 16) : 0;
    if (hex && *end == '\0' && v == want)
        return 1;
    diag_report(&r->L->diag, DIAG_ERROR, jread_span(r, key), "disagrees with %s, from which it is derived: expected \"0x%llx\" " DERIVED_RULE, from, (unsigned long long)want);
    return 0;
}

/* Enters member key of obj when it is there, an object with the members
 * allowed; returns it with the path on it (pop after), or NULL: absent,
 * or not such an object (*ok then 0, after the error). */
static json_t *enter(jreader *r, json_t *obj, const char *key, const char *const *allowed, int *ok)
{
    json_t *v = present(obj, key);
    if (!v)
        return NULL;
    jread_push_key(r, key);
    if (jread_is_object(r, v) && jread_known(r, v, allowed))
        return v;
    jread_pop(r);
    *ok = 0;
    return NULL;
}

/* ---- the camera ---- */

static double sample_offset(int k, int a)
{
    return (a + 0.5) / k;
}

/* pixel_samples.offsets[i] = ((a + 0.5) / k, (b + 0.5) / k), i = b k + a. */
static int offset_pair(jreader *r, json_t *val, size_t i, const void *ctx)
{
    int k = *(const int *)ctx;
    double want[2] = {sample_offset(k, (int)i % k), sample_offset(k, (int)i / k)};
    return numbers(r, val, want, 2, "image.samples");
}

/* The camera ray through image point (x, y) ([JSON-CAMERA-1]). */
static void camera_ray_at(const scene_model *s, double half, double x, double y, vec3 *origin, vec3 *dir)
{
    const scene_camera *cam = &s->camera;
    double aspect = (double)s->image.height / s->image.width;
    double sx = 2 * x / s->image.width - 1, sy = 1 - 2 * y / s->image.height;
    vec3 across = vec_add(vec_scale(cam->right, sx * half), vec_scale(cam->true_up, sy * half * aspect));
    if (cam->kind == CAMERA_ORTHOGRAPHIC) {
        *origin = vec_add(cam->eye, across);
        *dir = cam->forward;
    } else {
        *origin = cam->eye;
        *dir = vec_normalize(vec_add(cam->forward, across));
    }
}

static int screen(jreader *r, json_t *c)
{
    static const char *const keys[] = {"aspect", "half", "example", NULL};
    static const char *const example_keys[] = {"point", "origin", "direction", NULL};
    static const char from[] = "the camera and image";
    const scene_model *s = r->L->scene;
    const scene_camera *cam = &s->camera;
    int ok = 1;
    json_t *sc = enter(r, c, "screen", keys, &ok);
    if (!sc)
        return ok;
    int ortho = cam->kind == CAMERA_ORTHOGRAPHIC;
    double half = ortho ? 0.5 * cam->width : tan(0.5 * cam->fov * (PI / 180));
    ok = member_number(r, sc, "aspect", (double)s->image.height / s->image.width, "image.width, image.height") &&
         member_number(r, sc, "half", half, ortho ? "camera.width" : "camera.fov");
    json_t *ex = ok ? enter(r, sc, "example", example_keys, &ok) : NULL;
    if (ex) {
        double x = sample_offset(s->image.samples, 0), point[2] = {x, x};
        vec3 origin, dir;
        camera_ray_at(s, half, x, x, &origin, &dir);
        ok = member(r, ex, "point", point, 2, "image.samples") && member_vec(r, ex, "origin", origin, from) &&
             member_vec(r, ex, "direction", dir, from);
        jread_pop(r);
    }
    jread_pop(r);
    return ok;
}

static int camera(jreader *r, json_t *root)
{
    static const char *const basis_keys[] = {"forward", "right", "up", NULL};
    static const char *const sample_keys[] = {"k", "offsets", NULL};
    const scene_model *s = r->L->scene;
    const scene_camera *cam = &s->camera;
    json_t *c = present(root, "camera");
    int ok = 1, k = s->image.samples;
    jread_push_key(r, "camera");
    json_t *b = enter(r, c, "basis", basis_keys, &ok);
    if (b) {
        ok = member_vec(r, b, "forward", cam->forward, "camera.eye, camera.look_at") &&
             member_vec(r, b, "right", cam->right, "camera.eye, camera.look_at, camera.up") &&
             member_vec(r, b, "up", cam->true_up, "camera.eye, camera.look_at, camera.up");
        jread_pop(r);
    }
    ok = ok && screen(r, c);
    json_t *ps = ok ? enter(r, c, "pixel_samples", sample_keys, &ok) : NULL;
    if (ps) {
        ok = member_number(r, ps, "k", k, "image.samples") &&
             member_list(r, ps, "offsets", (size_t)k * (size_t)k, "offsets (k x k)", offset_pair, &k);
        jread_pop(r);
    }
    jread_pop(r);
    return ok;
}

/* ---- features and conventions ---- */

static int features(jreader *r, json_t *root)
{
    static const char *const keys[] = {"shadows", "specular", "reflection", "refraction", "sampled_lights", "meshes",
                                       NULL};
    static const char from[] = "the materials, lights and primitives";
    const scene_features *f = &r->L->scene->features;
    int ok = 1;
    json_t *fe = enter(r, root, "features", keys, &ok);
    if (!fe)
        return ok;
    ok = member_flag(r, fe, "shadows", f->shadows, from) && member_flag(r, fe, "specular", f->specular, from) &&
         member_flag(r, fe, "reflection", f->reflection, from) &&
         member_flag(r, fe, "refraction", f->refraction, from) &&
         member_flag(r, fe, "sampled_lights", f->sampled_lights, from) &&
         member_flag(r, fe, "meshes", f->meshes, from);
    jread_pop(r);
    return ok;
}

/* conventions.light_samples.constants: the numbers of the sampling rule. */
static int conventions(jreader *r, json_t *root)
{
    static const char from[] = "the sampling rule this refray renders with";
    static const char *const keys[] = {"gamma", "mul1", "mul2", "shift1", "shift2", "shift3", "pixel_salt", "mirror",
                                       "transmitted", "light", NULL};
    json_t *ls = present(present(root, "conventions"), "light_samples");
    int ok = 1;
    if (!present(ls, "constants"))
        return 1;
    jread_push_key(r, "conventions");
    jread_push_key(r, "light_samples");
    /* The constants are data a reader may take (unlike the prose around
     * them): an object of these members only, as every derived object. */
    json_t *c = enter(r, ls, "constants", keys, &ok);
    if (c) {
        ok = member_hex(r, c, "gamma", SAMPLER_GAMMA, from) && member_hex(r, c, "mul1", SAMPLER_MUL1, from) &&
             member_hex(r, c, "mul2", SAMPLER_MUL2, from) && member_number(r, c, "shift1", SAMPLER_SHIFT1, from) &&
             member_number(r, c, "shift2", SAMPLER_SHIFT2, from) &&
             member_number(r, c, "shift3", SAMPLER_SHIFT3, from) &&
             member_hex(r, c, "pixel_salt", SCENE_JSON_PIXEL_SALT, from) &&
             member_number(r, c, "mirror", SCENE_JSON_KEY_MIRROR, from) &&
             member_number(r, c, "transmitted", SCENE_JSON_KEY_TRANSMITTED, from) &&
             member_hex(r, c, "light", SCENE_JSON_KEY_LIGHT, from);
        jread_pop(r);
    }
    jread_pop(r);
    jread_pop(r);
    return ok;
}

/* ---- lights ---- */

/* What [JSON-SAMPLES-1] derives for one distributed light. */
typedef struct light_rule {
    const scene_light *light;
    int index;                  /* in `lights`: part of the sample keys */
    int rows, cols;             /* the grid */
    vec3 t1, t2;                /* a disk's frame */
    uint64_t key;               /* of camera sample (0, 0) of pixel (0, 0) */
} light_rule;

static light_rule rule_for(const scene_model *s, int index)
{
    light_rule u;
    const scene_light *l = &s->lights[index];
    memset(&u, 0, sizeof u);
    u.light = l;
    u.index = index;
    u.rows = (int)floor(sqrt((double)l->samples));
    while (u.rows > 1 && l->samples % u.rows != 0)
        u.rows--;
    u.rows = u.rows < 1 ? 1 : u.rows;
    u.cols = l->samples / u.rows;
    if (l->kind == LIGHT_DISK) {
        /* Duff et al. 2017: an orthonormal frame without a branch on n. */
        vec3 n = l->normal;
        double sign = copysign(1.0, (double)n.z), a = -1 / (sign + n.z), b = n.x * n.y * a;
        u.t1 = vec_make(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
        u.t2 = vec_make(b, sign + n.y * n.y * a, -n.y);
    }
    u.key = sampler_key(sampler_key(0, SCENE_JSON_PIXEL_SALT), 0);
    return u;
}

/* Sample j of the light at the example's key: its cell, jittered, then
 * the rectangle or (Shirley and Chiu's concentric map) the disk. */
static vec3 sample_point(const light_rule *u, int j)
{
    const scene_light *l = u->light;
    uint64_t lk = sampler_key(u->key, SCENE_JSON_KEY_LIGHT + (uint64_t)u->index);
    double u1 = sampler_uniform(sampler_key(lk, 2 * (uint64_t)j));
    double u2 = sampler_uniform(sampler_key(lk, 2 * (uint64_t)j + 1));
    double s = (j % u->cols + u1) / u->cols, t = (j / u->cols + u2) / u->rows;
    if (l->kind == LIGHT_RECTANGLE)
        return vec_add(l->position, vec_add(vec_scale(l->edge_u, s), vec_scale(l->edge_v, t)));
    double a = 2 * s - 1, b = 2 * t - 1, radius = 0, phi = 0;
    if (a != 0 || b != 0) {
        int wide = fabs(a) > fabs(b);
        radius = wide ? a : b;
        phi = wide ? (PI / 4) * (b / a) : PI / 2 - (PI / 4) * (a / b);
    }
    double x = radius * cos(phi), y = radius * sin(phi);
    return vec_add(l->position, vec_add(vec_scale(u->t1, x * l->radius), vec_scale(u->t2, y * l->radius)));
}

static int example_point(jreader *r, json_t *val, size_t j, const void *ctx)
{
    vec3 p = sample_point(ctx, (int)j);
    double want[3] = {(double)p.x, (double)p.y, (double)p.z};
    return numbers(r, val, want, 3, "the light, image.width, image.samples and the sampling rule");
}

static int sampling_example(jreader *r, json_t *sa, const light_rule *u)
{
    static const char *const keys[] = {"pixel", "camera_sample", "ray", "key", "points", NULL};
    static const double origin[2] = {0, 0};
    int ok = 1, n = u->light->samples < EXAMPLE_POINTS ? u->light->samples : EXAMPLE_POINTS;
    json_t *ex = enter(r, sa, "example", keys, &ok);
    if (!ex)
        return ok;
    ok = member(r, ex, "pixel", origin, 2, "the example's definition") &&
         member(r, ex, "camera_sample", origin, 2, "the example's definition") &&
         member_text(r, ex, "ray", "the camera ray", "the example's definition") &&
         member_hex(r, ex, "key", u->key, "the pixel and camera sample (0, 0)") &&
         member_list(r, ex, "points", (size_t)n, "points (the first samples, at most 16)", example_point, u);
    jread_pop(r);
    return ok;
}

static int sampling(jreader *r, json_t *l, const light_rule *u)
{
    static const char *const rect_keys[] = {"grid", "sample_power", "example", NULL};
    static const char *const disk_keys[] = {"grid", "sample_power", "frame", "example", NULL};
    static const char *const grid_keys[] = {"rows", "cols", NULL};
    static const char *const frame_keys[] = {"t1", "t2", NULL};
    const scene_light *light = u->light;
    int ok = 1, disk = light->kind == LIGHT_DISK;
    json_t *sa = enter(r, l, "sampling", disk ? disk_keys : rect_keys, &ok);
    if (!sa)
        return ok;
    json_t *g = enter(r, sa, "grid", grid_keys, &ok);
    if (g) {
        ok = member_number(r, g, "rows", u->rows, "samples") && member_number(r, g, "cols", u->cols, "samples");
        jread_pop(r);
    }
    vec3 each = vec_make(light->power.x / light->samples, light->power.y / light->samples,
                         light->power.z / light->samples);
    ok = ok && member_vec(r, sa, "sample_power", each, "power, samples");
    json_t *f = ok && disk ? enter(r, sa, "frame", frame_keys, &ok) : NULL;
    if (f) {
        ok = member_vec(r, f, "t1", u->t1, "normal") && member_vec(r, f, "t2", u->t2, "normal");
        jread_pop(r);
    }
    ok = ok && sampling_example(r, sa, u);
    jread_pop(r);
    return ok;
}

/* one(r, element, i) for the first count elements of the array root[key]
 * (those it has), each under its JSON pointer; 1 while every one is. */
static int each_element(jreader *r, json_t *root, const char *key, int count,
                        int (*one)(jreader *r, json_t *element, int i))
{
    json_t *list = present(root, key);
    int ok = 1;
    jread_push_key(r, key);
    for (int i = 0; ok && i < count && (size_t)i < json_array_size(list); i++) {
        jread_push_index(r, (size_t)i);
        ok = one(r, json_array_get(list, (size_t)i), i);
        jread_pop(r);
    }
    jread_pop(r);
    return ok;
}

/* Light i's derived members, for a rectangle or a disk. */
static int light_derived(jreader *r, json_t *l, int i)
{
    const scene_model *s = r->L->scene;
    const scene_light *light = &s->lights[i];
    if (light->kind != LIGHT_RECTANGLE && light->kind != LIGHT_DISK)
        return 1;
    light_rule u = rule_for(s, i);
    int ok = light->kind != LIGHT_RECTANGLE || member_vec(r, l, "normal", light->normal, "edge_u, edge_v");
    return ok && sampling(r, l, &u);
}

static int lights(jreader *r, json_t *root)
{
    return each_element(r, root, "lights", r->L->scene->light_count, light_derived);
}

/* ---- primitives ---- */

static int matrix_row(jreader *r, json_t *val, size_t i, const void *ctx)
{
    const xform *m = ctx;
    double want[4] = {0, 0, 0, 1};
    if (i < 3)
        for (int j = 0; j < 4; j++)
            want[j] = m->m[i][j];
    return numbers(r, val, want, 4, "to_world (its inverse)");
}

/* Primitive i's transform.to_local, when it has a transform. */
static int primitive_derived(jreader *r, json_t *element, int i)
{
    const scene_prim *p = &r->L->scene->prims[i];
    json_t *t = present(element, "transform");
    if (!p->frame || !json_is_object(t))
        return 1;
    jread_push_key(r, "transform");
    int ok = member_list(r, t, "to_local", 4, "rows", matrix_row, &p->frame->to_local);
    jread_pop(r);
    return ok;
}

static int primitives(jreader *r, json_t *root)
{
    return each_element(r, root, "primitives", r->L->scene->prim_count, primitive_derived);
}

int load_json_derived(jreader *r, json_t *root)
{
    int ok = features(r, root);
    ok = ok && conventions(r, root);
    ok = ok && camera(r, root);
    ok = ok && lights(r, root);
    return ok && primitives(r, root);
}
