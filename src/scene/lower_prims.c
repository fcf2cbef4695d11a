/*
 * lower_prims.c - sphere, plane, triangle, disk, box and mesh statements,
 * and the shared path of every primitive (the cylinder, cone and torus
 * shapes are read in lower_quadrics.c; a mesh's file is read here,
 * lower_mesh.c builds its store).
 *
 * Transforms are applied in the order written.  They are baked into the
 * shape's parameters whenever the transformed shape is the same kind of
 * shape (see scene_prim in scene.h); otherwise the primitive keeps its local
 * parameters and the matrix pair, and is intersected in its own frame.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "scene/loader.h"
#include "lang/obj.h"
#include "lang/ply.h"

static int one_transform(loader *L, const ast *prop, xform *out)
{
    value v;
    if (!eval_expr(&L->env, &L->diag, prop->first, &v))
        return 0;
    if (v.kind == VAL_NUMBER && prop->keyword == KW_SCALE)
        v.vector = vec_splat(v.number);
    else if (v.kind != VAL_VECTOR) {
        diag_report(&L->diag, DIAG_ERROR, v.span, "%s takes a vector%s", keyword_name((keyword_id)prop->keyword),
                    prop->keyword == KW_SCALE ? " or a number" : "");
        return 0;
    }
    if (prop->keyword == KW_TRANSLATE) {
        *out = xform_translate(v.vector);
    } else if (prop->keyword == KW_ROTATE) {
        *out = xform_rotate_xyz(v.vector);
    } else {
        if (v.vector.x == 0 || v.vector.y == 0 || v.vector.z == 0) {
            diag_report(&L->diag, DIAG_ERROR, v.span, "scale must not be zero along any axis (it would flatten the shape)");
            return 0;
        }
        *out = xform_scale(v.vector);
    }
    return 1;
}

/* The product of the transforms, first written applied first. */
static int transforms(loader *L, const props *p, xform *to_world, xform *to_local)
{
    *to_world = xform_identity();
    if (p->xform_count == 0) {
        /* Most primitives (100 000 spheres of a big grid): the inverse
         * xform_invert gives the identity, its translations -0, made here
         * without testing the matrix entry by entry. */
        *to_local = *to_world;
        for (int i = 0; i < 3; i++)
            to_local->m[i][3] = -0.0;
        return 1;
    }
    for (int i = 0; i < p->xform_count; i++) {
        xform step;
        if (!one_transform(L, p->xforms[i], &step))
            return 0;
        *to_world = xform_compose(&step, to_world);
    }
    src_span last = p->xform_count > 0 ? p->xforms[p->xform_count - 1]->head : p->block->head;
    check_at at = check_at_fixed(&last);
    return check_invert(L, &at, to_world, to_local);
}

static int unit_vector(loader *L, const props *p, keyword_id kw, vec3 fallback, vec3 *out)
{
    if (!props_vector(L, p, kw, fallback, out))
        return 0;
    if (loader_unit(*out, out))
        return 1;
    diag_report(&L->diag, DIAG_ERROR, props_value_span(p, kw), "%s must not be a zero-length vector", keyword_name(kw));
    return 0;
}

static int place_sphere(loader *L, scene_prim *prim, const xform *w, const xform *l)
{
    double s;
    if (xform_is_identity(w))
        return 1;
    if (!xform_is_similarity(w, &s))
        return lower_keep_frame(L, prim, w, l);
    prim->u.sphere.center = xform_point(w, prim->u.sphere.center);
    prim->u.sphere.radius *= s;
    return 1;
}

static int place_disk(loader *L, scene_prim *prim, const xform *w, const xform *l)
{
    double s;
    if (xform_is_identity(w))
        return 1;
    if (!xform_is_similarity(w, &s))
        return lower_keep_frame(L, prim, w, l);
    prim->u.disk.center = xform_point(w, prim->u.disk.center);
    prim->u.disk.normal = lower_transformed_normal(l, prim->u.disk.normal);
    prim->u.disk.radius *= s;
    return 1;
}

static int is_axis_aligned(const xform *w)
{
    return w->m[0][1] == 0 && w->m[0][2] == 0 && w->m[1][0] == 0 && w->m[1][2] == 0 && w->m[2][0] == 0 &&
           w->m[2][1] == 0;
}

static int place_box(loader *L, scene_prim *prim, const xform *w, const xform *l)
{
    if (!is_axis_aligned(w))
        return lower_keep_frame(L, prim, w, l);
    vec3 a = xform_point(w, prim->u.box.lo), b = xform_point(w, prim->u.box.hi);
    prim->u.box.lo = vec_min(a, b);
    prim->u.box.hi = vec_max(a, b);
    return 1;
}

/* Vertices in world space; a mirroring transform would turn the winding
 * (and so the normal) inside out, so two corners are swapped back.  (A
 * triangle statement gives no vertex normals: u.triangle.n stays NULL.) */
static void place_triangle(scene_prim *prim, const xform *w)
{
    for (int i = 0; i < 3; i++)
        prim->u.triangle.p[i] = xform_point(w, prim->u.triangle.p[i]);
    if (lower_mirrors(w)) {
        vec3 t = prim->u.triangle.p[1];
        prim->u.triangle.p[1] = prim->u.triangle.p[2];
        prim->u.triangle.p[2] = t;
    }
}

static int sphere(loader *L, const props *p, scene_prim *prim)
{
    prim->kind = PRIM_SPHERE;
    check_at at = props_at(p);
    int ok = props_vector(L, p, KW_CENTER, vec_splat(0), &prim->u.sphere.center);
    ok &= props_number(L, p, KW_RADIUS, 1, &prim->u.sphere.radius) && check_radius(L, &at, prim->u.sphere.radius);
    return ok;
}

static int plane(loader *L, const props *p, scene_prim *prim)
{
    prim->kind = PRIM_PLANE;
    int ok = props_vector(L, p, KW_POINT, vec_splat(0), &prim->u.plane.point);
    ok &= unit_vector(L, p, KW_NORMAL, vec_make(0, 1, 0), &prim->u.plane.normal);
    return ok;
}

static int disk(loader *L, const props *p, scene_prim *prim)
{
    prim->kind = PRIM_DISK;
    int ok = props_vector(L, p, KW_CENTER, vec_splat(0), &prim->u.disk.center);
    ok &= unit_vector(L, p, KW_NORMAL, vec_make(0, 1, 0), &prim->u.disk.normal);
    check_at at = props_at(p);
    ok &= props_number(L, p, KW_RADIUS, 1, &prim->u.disk.radius) && check_radius(L, &at, prim->u.disk.radius);
    return ok;
}

static int box(loader *L, const props *p, scene_prim *prim)
{
    vec3 a, b;
    prim->kind = PRIM_BOX;
    int ok = props_require(L, p, KW_FROM);
    ok &= props_require(L, p, KW_TO);
    if (!ok)
        return 0;
    ok = props_vector(L, p, KW_FROM, vec_splat(0), &a);
    ok &= props_vector(L, p, KW_TO, vec_splat(0), &b);
    check_at at = props_at(p);
    return ok && check_box(L, &at, a, b, prim);
}

static int triangle(loader *L, const props *p, scene_prim *prim)
{
    prim->kind = PRIM_TRIANGLE;
    if (!props_require(L, p, KW_VERTICES))
        return 0;
    const ast *v = p->by_keyword[KW_VERTICES]->first;
    for (int i = 0; i < 3; i++, v = v->next) {
        value corner;
        if (!props_value_at(L, v, VAL_VECTOR, &corner))
            return 0;
        prim->u.triangle.p[i] = corner.vector;
    }
    return 1;
}

static scene_prim *emit(loader *L, const scene_prim *prim)
{
    scene_prim *slot = loader_add_prim(L, prim->where);
    if (slot)
        *slot = *prim;
    return slot;
}

/* A PLY file by its name (".ply", any case) or by its first line. */
static int is_ply(const source_file *f)
{
    size_t n = strlen(f->path);
    const char *ext = n >= 4 ? f->path + n - 4 : "";
    int named = ext[0] == '.' && (ext[1] | 0x20) == 'p' && (ext[2] | 0x20) == 'l' && (ext[3] | 0x20) == 'y';
    return named || ply_is_ply(f->text, f->len);
}

int lower_parse_mesh(loader *L, int file, polymesh *pm)
{
    const source_set *sources = &L->scene->sources;
    long limit = L->limits->max_mesh_triangles;
    int ok = is_ply(sources->files[file]) ? ply_parse(sources, file, &L->diag, limit, pm)
                                          : obj_parse(sources, file, &L->diag, limit, pm);
    if (ok < 0)
        L->out_of_memory = 1; /* the reader said so at the place it ran out */
    return ok > 0;
}

/* `file a` with no constant a: a file name without its quotes. */
static int unquoted_file(loader *L, const props *p)
{
    const ast *v = p->by_keyword[KW_FILE] ? p->by_keyword[KW_FILE]->first : NULL;
    if (!v || v->kind != AST_NAME || env_find(&L->env, v->text))
        return 0;
    diag_report(&L->diag, DIAG_ERROR, v->span, "file names are strings: write \"%s\"", v->text);
    return 1;
}

static int mesh(loader *L, const props *p, scene_prim *proto, const xform *w, const xform *l)
{
    const char *name;
    src_span at;
    int file;
    scene_source held;
    if (!props_require(L, p, KW_FILE) || unquoted_file(L, p) || !props_string(L, p, KW_FILE, &name, &at) ||
        !loader_read_mesh(L, name, at, &held, &file))
        return 0;
    polymesh pm;
    int ok = lower_parse_mesh(L, file, &pm) && lower_mesh(L, &pm, file, &held, at, proto, w, l);
    polymesh_free(&pm);
    /* Nothing points into the file after this: its text goes back (when
     * lower_mesh has not given it back already). */
    loader_release_mesh(L, file, &held);
    return ok;
}

/* The transforms baked in or the frame kept; 0 when out of memory. */
static int place(loader *L, scene_prim *prim, const xform *w, const xform *l)
{
    switch (prim->kind) {
    case PRIM_SPHERE: return place_sphere(L, prim, w, l);
    case PRIM_DISK: return place_disk(L, prim, w, l);
    case PRIM_BOX: return place_box(L, prim, w, l);
    case PRIM_TRIANGLE: place_triangle(prim, w); break;
    case PRIM_CYLINDER:
    case PRIM_CONE:
    case PRIM_TORUS: return lower_place_quadric(L, prim, w, l);
    case PRIM_MESH: break; /* lower_mesh.c places every vertex */
    case PRIM_PLANE:
        prim->u.plane.point = xform_point(w, prim->u.plane.point);
        prim->u.plane.normal = lower_transformed_normal(l, prim->u.plane.normal);
        /* Any point of the plane names it; the one nearest the origin keeps
         * the hit point's rounding, and so the offset of rays leaving the
         * plane, relative to the plane's distance from the origin rather
         * than to how far along the plane the scene wrote its point. */
        prim->u.plane.point = vec_scale(prim->u.plane.normal,
                                        vec_dot(prim->u.plane.normal, prim->u.plane.point));
        break;
    }
    return 1;
}

int lower_primitive(loader *L, const ast *block)
{
    props p;
    scene_prim prim;
    xform w, l;
    memset(&prim, 0, sizeof prim);
    prim.mesh = -1;
    prim.where = block->head;
    if (!props_collect(L, block, &p))
        return 0;
    /* Shape, then material, then transforms: the order they are usually
     * written in, so the first error reported is the first in the text. */
    int ok = 1;
    switch (block->keyword) {
    case KW_SPHERE: ok = sphere(L, &p, &prim); break;
    case KW_PLANE: ok = plane(L, &p, &prim); break;
    case KW_DISK: ok = disk(L, &p, &prim); break;
    case KW_BOX: ok = box(L, &p, &prim); break;
    case KW_TRIANGLE: ok = triangle(L, &p, &prim); break;
    case KW_CYLINDER:
    case KW_CONE:
    case KW_TORUS: ok = lower_quadric(L, &p, (keyword_id)block->keyword, &prim); break;
    default: break;
    }
    prim.material = lower_material_ref(L, &p);
    ok &= prim.material >= 0;
    ok &= transforms(L, &p, &w, &l);
    if (block->keyword == KW_MESH)
        return ok && mesh(L, &p, &prim, &w, &l);
    if (!ok || !place(L, &prim, &w, &l))
        return 0;
    check_at at = props_at(&p);
    return check_placed(L, &at, &prim) && emit(L, &prim) != NULL;
}
