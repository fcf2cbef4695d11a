/*
 * lower_quadrics.c - the cylinder, cone and torus statements: reading their
 * properties with the defaults of spec/language.md and placing them under
 * their transforms (the range check of the placed shape is in check.c).
 *
 * A similarity (rotation, mirror, uniform scale, translation) maps each of
 * them to the same kind of shape: the end centres or the centre are moved,
 * the axis turned, the radii scaled.  Any other transform keeps the local
 * parameters and the matrix pair (lower_keep_frame), as for spheres.
 */
#include <math.h>
#include <string.h>
#include "scene/loader.h"

/* Where the rules of check.c report for these blocks: the ends at to (at
 * from when to is not written), the ring at minor (at major when minor is
 * not written), each of a cone's radii at its value, the radii together
 * at the whole property. */
typedef struct quadric_props {
    const props *p;
    src_span radius[2];
} quadric_props;

static src_span quadric_span(const void *ctx, int field)
{
    const quadric_props *q = ctx;
    const props *p = q->p;
    if (field == CHECK_CONE_RADIUS0 || field == CHECK_CONE_RADIUS1)
        return q->radius[field - CHECK_CONE_RADIUS0];
    if (field == KW_RADII && p->by_keyword[KW_RADII])
        return p->by_keyword[KW_RADII]->span;
    if (field == KW_TO && !p->by_keyword[KW_TO])
        field = KW_FROM;
    if (field == KW_MINOR && !p->by_keyword[KW_MINOR])
        field = KW_MAJOR;
    check_at whole = props_at(p);
    return check_span(&whole, field);
}

/* from and to, which must differ: the axis of a cylinder or cone. */
static int ends(loader *L, const props *p, vec3 *from, vec3 *to)
{
    quadric_props q = {p, {{-1, 0, 0}, {-1, 0, 0}}};
    check_at at = {quadric_span, &q};
    int ok = props_vector(L, p, KW_FROM, vec_splat(0), from);
    ok &= props_vector(L, p, KW_TO, vec_make(0, 1, 0), to);
    return ok && check_ends(L, &at, *from, *to);
}

static int cylinder(loader *L, const props *p, scene_prim *prim)
{
    check_at at = props_at(p);
    prim->kind = PRIM_CYLINDER;
    int ok = ends(L, p, &prim->u.cylinder.from, &prim->u.cylinder.to);
    ok &= props_number(L, p, KW_RADIUS, 1, &prim->u.cylinder.radius) &&
          check_radius(L, &at, prim->u.cylinder.radius);
    prim->u.cylinder.open = p->by_keyword[KW_OPEN] != NULL;
    return ok;
}

/* radii R0 R1: both >= 0, at least one > 0 (defaults 1 0: an apex at to). */
static int cone_radii(loader *L, const props *p, double radius[2])
{
    const ast *prop = p->by_keyword[KW_RADII];
    quadric_props q = {p, {{-1, 0, 0}, {-1, 0, 0}}};
    check_at at = {quadric_span, &q};
    radius[0] = 1;
    radius[1] = 0;
    if (!prop)
        return 1;
    value v[2];
    if (!props_value_at(L, prop->first, VAL_NUMBER, &v[0]) ||
        !props_value_at(L, prop->first->next, VAL_NUMBER, &v[1]))
        return 0;
    for (int i = 0; i < 2; i++) {
        radius[i] = v[i].number;
        q.radius[i] = v[i].span;
    }
    return check_cone_radii(L, &at, radius);
}

static int cone(loader *L, const props *p, scene_prim *prim)
{
    prim->kind = PRIM_CONE;
    int ok = ends(L, p, &prim->u.cone.from, &prim->u.cone.to);
    ok &= cone_radii(L, p, prim->u.cone.radius);
    prim->u.cone.open = p->by_keyword[KW_OPEN] != NULL;
    return ok;
}

static int torus(loader *L, const props *p, scene_prim *prim)
{
    quadric_props q = {p, {{-1, 0, 0}, {-1, 0, 0}}};
    check_at at = {quadric_span, &q};
    prim->kind = PRIM_TORUS;
    int ok = props_vector(L, p, KW_CENTER, vec_splat(0), &prim->u.torus.center);
    int axis = props_vector(L, p, KW_AXIS, vec_make(0, 1, 0), &prim->u.torus.axis);
    if (axis && !loader_unit(prim->u.torus.axis, &prim->u.torus.axis)) {
        diag_report(&L->diag, DIAG_ERROR, props_value_span(p, KW_AXIS), "axis must not be a zero-length vector");
        axis = 0;
    }
    int radii = props_number(L, p, KW_MAJOR, 1, &prim->u.torus.major);
    radii &= props_number(L, p, KW_MINOR, 0.25, &prim->u.torus.minor);
    radii = radii && check_torus(L, &at, prim->u.torus.major, prim->u.torus.minor);
    return ok & axis & radii;
}

int lower_quadric(loader *L, const props *p, keyword_id block, scene_prim *prim)
{
    switch (block) {
    case KW_CYLINDER: return cylinder(L, p, prim);
    case KW_CONE: return cone(L, p, prim);
    default: return torus(L, p, prim);
    }
}

int lower_place_quadric(loader *L, scene_prim *prim, const xform *w, const xform *l)
{
    double s;
    if (xform_is_identity(w))
        return 1;
    if (!xform_is_similarity(w, &s))
        return lower_keep_frame(L, prim, w, l);
    switch (prim->kind) {
    case PRIM_CYLINDER:
        prim->u.cylinder.from = xform_point(w, prim->u.cylinder.from);
        prim->u.cylinder.to = xform_point(w, prim->u.cylinder.to);
        prim->u.cylinder.radius *= s;
        break;
    case PRIM_CONE:
        prim->u.cone.from = xform_point(w, prim->u.cone.from);
        prim->u.cone.to = xform_point(w, prim->u.cone.to);
        prim->u.cone.radius[0] *= s;
        prim->u.cone.radius[1] *= s;
        break;
    default:
        prim->u.torus.center = xform_point(w, prim->u.torus.center);
        prim->u.torus.axis = lower_transformed_normal(l, prim->u.torus.axis);
        prim->u.torus.major *= s;
        prim->u.torus.minor *= s;
    }
    return 1;
}
