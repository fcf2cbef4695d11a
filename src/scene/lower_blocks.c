/*
 * lower_blocks.c - image, camera, ambient, lights and materials: read the
 * properties, apply the documented defaults (spec/language.md), check them
 * with the rules of check.c at the offending value, and append to the scene.
 */
#include <string.h>
#include "scene/loader.h"
#include "base/suggest.h"

/* A direction or normal: any non-zero length, returned normalised. */
static int direction(loader *L, const props *p, keyword_id kw, vec3 fallback, vec3 *out)
{
    if (!props_vector(L, p, kw, fallback, out))
        return 0;
    if (!loader_unit(*out, out)) {
        diag_report(&L->diag, DIAG_ERROR, props_value_span(p, kw), "%s must not be a zero-length vector",
                    keyword_name(kw));
        return 0;
    }
    return 1;
}

static int first_block(loader *L, const ast *block, src_span *seen)
{
    if (seen->file < 0) {
        *seen = block->head;
        return 1;
    }
    int line, col;
    source_line_col(L->scene->sources.files[seen->file], seen->begin, &line, &col);
    diag_report(&L->diag, DIAG_ERROR, block->head, "a second '%s' block (the first is at line %d)",
                keyword_name((keyword_id)block->keyword), line);
    return 0;
}

int lower_image(loader *L, const ast *block)
{
    props p;
    scene_image_spec *im = &L->scene->image;
    double size[4];
    rgb background;
    int first = first_block(L, block, &L->image_where);
    if (!props_collect(L, block, &p) || !first)
        return 0;
    int ok = props_number(L, &p, KW_WIDTH, im->width, &size[0]);
    ok &= props_number(L, &p, KW_HEIGHT, im->height, &size[1]);
    ok &= props_number(L, &p, KW_SAMPLES, im->samples, &size[2]);
    ok &= props_number(L, &p, KW_MAX_DEPTH, im->max_depth, &size[3]);
    ok &= props_color(L, &p, KW_BACKGROUND, im->background, &background);
    check_at at = props_at(&p);
    L->max_depth_where = props_value_span(&p, KW_MAX_DEPTH);
    return check_image(L, &at, size, background, im) && ok;
}

/* Perspective or orthographic, and no property of the other kind; both
 * mistakes are reported when both are made. */
static int camera_kind(loader *L, const props *p, scene_camera *cam)
{
    const ast *persp = p->by_keyword[KW_PERSPECTIVE], *ortho = p->by_keyword[KW_ORTHOGRAPHIC];
    if (persp && ortho) {
        diag_report(&L->diag, DIAG_ERROR, ortho->head, "a camera is either perspective or orthographic, not both");
        return 0;
    }
    cam->kind = ortho ? CAMERA_ORTHOGRAPHIC : CAMERA_PERSPECTIVE;
    const ast *wrong = ortho ? p->by_keyword[KW_FOV] : p->by_keyword[KW_WIDTH];
    if (wrong) {
        diag_report(&L->diag, DIAG_ERROR, wrong->head, "'%s' applies to %s cameras; this one is %s",
                    keyword_name((keyword_id)wrong->keyword), ortho ? "perspective" : "orthographic",
                    ortho ? "orthographic" : "perspective");
        return 0;
    }
    return 1;
}

/* look_at - eye is reported at look_at, or at eye when look_at is not given. */
static src_span camera_field_span(const void *ctx, int field)
{
    const props *p = ctx;
    if (field == KW_LOOK_AT && !p->by_keyword[KW_LOOK_AT])
        field = KW_EYE;
    return field >= KEYWORD_COUNT ? p->block->head : props_value_span(p, (keyword_id)field);
}

/* Every property is checked even after an error, so one run reports all
 * of a camera's mistakes ([LANG-CAMERA-2]).  A second camera is checked
 * into a copy and reported, the first one kept. */
int lower_camera(loader *L, const ast *block)
{
    props p;
    scene_camera copy = L->scene->camera;
    int first = first_block(L, block, &L->camera_where);
    scene_camera *cam = first ? &L->scene->camera : &copy;
    int ok = props_collect(L, block, &p) & first;
    cam->where = block->head;
    ok &= camera_kind(L, &p, cam);
    int placed = props_vector(L, &p, KW_EYE, cam->eye, &cam->eye);
    placed &= props_vector(L, &p, KW_LOOK_AT, cam->look_at, &cam->look_at);
    placed &= props_vector(L, &p, KW_UP, cam->up, &cam->up);
    ok &= props_number(L, &p, KW_FOV, cam->fov, &cam->fov);
    ok &= props_number(L, &p, KW_WIDTH, cam->width, &cam->width);
    check_at at = {camera_field_span, &p};
    ok &= check_camera_ranges(L, &at, cam);
    int basis = placed && check_camera_basis(L, &at, cam);
    return ok && basis;
}

int lower_ambient(loader *L, const ast *block)
{
    props p;
    rgb color;
    if (!props_collect(L, block, &p) || !props_require(L, &p, KW_COLOR) ||
        !props_color(L, &p, KW_COLOR, vec_splat(0), &color))
        return 0;
    check_at at = props_at(&p);
    if (!check_ambient(L, &at, color))
        return 0;
    /* Each block is finite, their sum need not be: an infinite Ia would give
     * Kd * Ia = 0 * Inf = NaN for a zero channel of Kd (shade_ambient's
     * precondition, spec/proofs.md). */
    rgb sum = vec_add(L->scene->ambient, color);
    if (!vec_is_finite(sum)) {
        diag_report(&L->diag, DIAG_ERROR, props_value_span(&p, KW_COLOR),
                    "the ambient colours add up beyond the largest number (about 1.8e308)");
        return 0;
    }
    L->scene->ambient = sum;
    return 1;
}

static int falloff(loader *L, const props *p, scene_falloff *out)
{
    static const char *const names[] = {"linear", "inverse_square", "none"};
    const char *name;
    src_span at;
    *out = FALLOFF_LINEAR;
    if (!props_name(L, p, KW_FALLOFF, &name, &at))
        return 0;
    if (!name)
        return 1;
    for (int i = 0; i < 3; i++) {
        if (strcmp(name, names[i]) == 0) {
            *out = (scene_falloff)i;
            return 1;
        }
    }
    const char *hint = suggest_nearest(name, strlen(name), names, 3);
    diag_report(&L->diag, DIAG_ERROR, at, "unknown falloff '%s'; %s%s%s", name, hint ? "did you mean '" : "",
                hint ? hint : "it is linear, inverse_square or none", hint ? "'?" : "");
    return 0;
}

/* power and, for lights that have a distance, d0 and falloff. */
static int light_common(loader *L, const props *p, const check_at *at, scene_light *light)
{
    int ok = props_color(L, p, KW_POWER, vec_splat(1), &light->power);
    if (light->kind != LIGHT_DISTANT) {
        ok &= props_number(L, p, KW_D0, 0, &light->d0);
        ok &= falloff(L, p, &light->falloff);
    }
    return check_light(L, at, light) && ok;
}

/* A distributed light's shape is one property of three values: a field
 * reports at the value it names. */
typedef struct shape_props {
    const props *p;
    src_span value[3];
} shape_props;

static src_span shape_field_span(const void *ctx, int field)
{
    const shape_props *sp = ctx;
    switch (field) {
    case CHECK_RECT_EDGES: return src_span_join(sp->value[1], sp->value[2]);
    case CHECK_RECT_EXTENT: return src_span_join(sp->value[0], sp->value[2]);
    case KW_CENTER: return sp->value[0];
    case KW_RADIUS: return sp->value[2];
    default: {
        check_at whole = props_at(sp->p);
        return check_span(&whole, field);
    }
    }
}

static int rectangle_light(loader *L, const props *p, shape_props *sp, scene_light *light)
{
    const ast *prop = p->by_keyword[KW_RECTANGLE];
    value corner, u, v;
    if (!props_value_at(L, prop->first, VAL_VECTOR, &corner) ||
        !props_value_at(L, prop->first->next, VAL_VECTOR, &u) ||
        !props_value_at(L, prop->first->next->next, VAL_VECTOR, &v))
        return 0;
    sp->value[0] = corner.span;
    sp->value[1] = u.span;
    sp->value[2] = v.span;
    light->kind = LIGHT_RECTANGLE;
    light->position = corner.vector;
    light->edge_u = u.vector;
    light->edge_v = v.vector;
    check_at at = {shape_field_span, sp};
    return check_rectangle(L, &at, light);
}

static int disk_light(loader *L, const props *p, shape_props *sp, scene_light *light)
{
    const ast *prop = p->by_keyword[KW_DISK];
    value center, normal, radius;
    if (!props_value_at(L, prop->first, VAL_VECTOR, &center) ||
        !props_value_at(L, prop->first->next, VAL_VECTOR, &normal) ||
        !props_value_at(L, prop->first->next->next, VAL_NUMBER, &radius))
        return 0;
    sp->value[0] = center.span;
    sp->value[1] = normal.span;
    sp->value[2] = radius.span;
    if (!loader_unit(normal.vector, &light->normal)) {
        diag_report(&L->diag, DIAG_ERROR, normal.span, "the disk's normal must not be a zero-length vector");
        return 0;
    }
    check_at at = {shape_field_span, sp};
    if (!check_radius(L, &at, radius.number))
        return 0;
    light->kind = LIGHT_DISK;
    light->position = center.vector;
    light->radius = radius.number;
    return check_light_extent(L, &at, light);
}

static int distributed_shape(loader *L, const props *p, scene_light *light)
{
    const ast *rect = p->by_keyword[KW_RECTANGLE], *disk = p->by_keyword[KW_DISK];
    if (rect && disk) {
        diag_report(&L->diag, DIAG_ERROR, disk->head, "a distributed light is a rectangle or a disk, not both");
        return 0;
    }
    if (!rect && !disk) {
        diag_report(&L->diag, DIAG_ERROR, p->block->head, "distributed_light needs 'rectangle' or 'disk'");
        return 0;
    }
    double samples;
    shape_props sp;
    memset(&sp, 0, sizeof sp);
    sp.p = p;
    check_at at = props_at(p);
    light->samples = 16;
    int ok = props_number(L, p, KW_SAMPLES, light->samples, &samples) &&
             check_light_samples(L, &at, samples, &light->samples);
    return ok & (rect ? rectangle_light(L, p, &sp, light) : disk_light(L, p, &sp, light));
}

int lower_light(loader *L, const ast *block)
{
    props p;
    scene_light light;
    memset(&light, 0, sizeof light);
    light.where = block->head;
    if (!props_collect(L, block, &p))
        return 0;
    int ok = 1;
    switch (block->keyword) {
    case KW_POINT_LIGHT:
        light.kind = LIGHT_POINT;
        ok = props_require(L, &p, KW_POSITION) && props_vector(L, &p, KW_POSITION, light.position, &light.position);
        break;
    case KW_DISTANT_LIGHT:
        light.kind = LIGHT_DISTANT;
        light.falloff = FALLOFF_NONE;
        ok = props_require(L, &p, KW_DIRECTION) && direction(L, &p, KW_DIRECTION, light.direction, &light.direction);
        break;
    default:
        ok = distributed_shape(L, &p, &light);
    }
    check_at at = props_at(&p);
    ok &= light_common(L, &p, &at, &light);
    scene_light *slot = ok ? loader_add_light(L) : NULL;
    if (slot)
        *slot = light;
    return slot != NULL;
}

/* Material properties; the defaults are those of spec/language.md. */
static int material_props(loader *L, const ast *block, scene_material *m)
{
    props p;
    if (!props_collect(L, block, &p))
        return 0;
    int ok = props_color(L, &p, KW_KD, vec_splat(0.8), &m->kd);
    ok &= props_color(L, &p, KW_KS, vec_splat(0), &m->ks);
    ok &= props_number(L, &p, KW_N, 1, &m->n);
    ok &= props_number(L, &p, KW_T, 0, &m->t);
    ok &= props_number(L, &p, KW_IOR, 1, &m->ior);
    m->where = block->head;
    check_at at = props_at(&p);
    return check_material(L, &at, m) && ok;
}

static int find_material(loader *L, const char *name)
{
    return name_index_find(&L->material_names, name);
}

int lower_material_def(loader *L, const ast *block)
{
    int previous = find_material(L, block->text);
    if (previous >= 0) {
        int line, col;
        src_span first = L->scene->materials[previous].where;
        source_line_col(L->scene->sources.files[first.file], first.begin, &line, &col);
        diag_report(&L->diag, DIAG_ERROR, block->head, "material '%s' is already defined (at line %d)",
                    block->text, line);
        return 0;
    }
    scene_material m;
    memset(&m, 0, sizeof m);
    if (!material_props(L, block, &m))
        return 0;
    m.where = block->head;
    scene_material *slot = loader_add_material(L);
    if (!slot || !(m.name = loader_strdup(L, block->text)))
        return 0;
    *slot = m;
    if (!name_index_add(&L->material_names, L->scene->material_count - 1)) {
        loader_oom(L);
        return 0;
    }
    return 1;
}

static int default_material(loader *L)
{
    if (L->default_material >= 0)
        return L->default_material;
    scene_material *m = loader_add_material(L);
    if (!m)
        return -1;
    memset(m, 0, sizeof *m);
    m->kd = vec_splat(0.8);
    m->n = 1;
    m->ior = 1;
    m->where = src_span_none();
    L->default_material = L->scene->material_count - 1;
    return L->default_material;
}

/* Named materials defined anywhere in the file being lowered after
 * offset `after` (loop bodies included): names and the spans of their names. */
enum { LATER_MAX = 256 };
typedef struct later_materials {
    const char *names[LATER_MAX];
    src_span where[LATER_MAX];
    int count;
} later_materials;

static void collect_later(const ast *list, size_t after, later_materials *out)
{
    for (const ast *node = list ? list->first : NULL; node && out->count < LATER_MAX; node = node->next) {
        if (node->kind == AST_FOR)
            collect_later(node->first->next->next, after, out);
        else if (node->kind == AST_BLOCK && node->keyword == KW_MATERIAL && node->text && node->head.begin > after) {
            out->names[out->count] = node->text;
            out->where[out->count++] = node->head;
        }
    }
}

/* "did you mean" among the materials the file defines only further down:
 * 1 when it reported. */
static int report_defined_later(loader *L, const char *name, src_span at)
{
    later_materials later;
    later.count = 0;
    if (!L->tree)
        return 0;
    collect_later(L->tree, at.begin, &later);
    const char *hint = suggest_nearest(name, strlen(name), later.names, later.count);
    int k = 0;
    while (hint && later.names[k] != hint)
        k++;
    if (!hint || later.where[k].file != at.file)
        return 0;
    int line, col;
    source_line_col(L->scene->sources.files[at.file], later.where[k].begin, &line, &col);
    if (strcmp(hint, name) == 0)
        diag_report(&L->diag, DIAG_ERROR, at, "unknown material '%s': it is defined only later, at line %d "
                    "(define a material before its first use)", name, line);
    else
        diag_report(&L->diag, DIAG_ERROR, at, "unknown material '%s'; did you mean '%s' (defined at line %d)?",
                    name, hint, line);
    return 1;
}

static int named_material(loader *L, const char *name, src_span at)
{
    int index = find_material(L, name);
    if (index >= 0)
        return index;
    const char *names[256];
    int count = 0;
    for (int i = 0; i < L->scene->material_count && count < 256; i++)
        if (L->scene->materials[i].name)
            names[count++] = L->scene->materials[i].name;
    const char *hint = suggest_nearest(name, strlen(name), names, count);
    if (hint)
        diag_report(&L->diag, DIAG_ERROR, at, "unknown material '%s'; did you mean '%s'?", name, hint);
    else if (!report_defined_later(L, name, at))
        diag_report(&L->diag, DIAG_ERROR, at, "unknown material '%s' (define it with `material %s { ... }` before use)",
                    name, name);
    return -1;
}

int lower_material_ref(loader *L, const props *p)
{
    const ast *prop = p->by_keyword[KW_MATERIAL];
    int index;
    if (!prop) {
        index = default_material(L);
    } else if (prop->first->kind == AST_BLOCK) {
        scene_material m;
        memset(&m, 0, sizeof m);
        if (!material_props(L, prop->first, &m))
            return -1;
        scene_material *slot = loader_add_material(L);
        if (!slot)
            return -1;
        *slot = m;
        index = L->scene->material_count - 1;
    } else {
        const char *name;
        src_span at;
        if (!props_name(L, p, KW_MATERIAL, &name, &at))
            return -1;
        index = named_material(L, name, at);
    }
    if (index >= 0)
        L->material_uses[index]++;
    return index;
}
