/*
 * lower_quadrics.c - the cylinder, cone and torus statements: reading their
 * properties with the defaults of spec/language.md, placing them under
 * their transforms, and the range check of the placed shape.
 *
 * A similarity (rotation, mirror, uniform scale, translation) maps each of
 * them to the same kind of shape: the end centres or the centre are moved,
 * the axis turned, the radii scaled.  Any other transform keeps the local
 * parameters and the matrix pair (lower_keep_frame), as for spheres.
 */
#include <math.h>
#include <string.h>
#include "scene/loader.h"

static int report(loader *L, src_span at, const char *message, double got)
{
    diag_report(&L->diag, DIAG_ERROR, at, "%s, got %.17g", message, got);
    return 0;
}

static int positive(loader *L, const props *p, keyword_id kw, double fallback, double *out)
{
    if (!props_number(L, p, kw, fallback, out))
        return 0;
    if (*out > 0)
        return 1;
    diag_report(&L->diag, DIAG_ERROR, props_value_span(p, kw), "%s must be > 0, got %.17g", keyword_name(kw), *out);
    return 0;
}

/* from and to, which must differ: the axis of a cylinder or cone. */
static int ends(loader *L, const props *p, vec3 *from, vec3 *to)
{
    int ok = props_vector(L, p, KW_FROM, vec_splat(0), from);
    ok &= props_vector(L, p, KW_TO, vec_make(0, 1, 0), to);
    if (ok && from->x == to->x && from->y == to->y && from->z == to->z) {
        diag_report(&L->diag, DIAG_ERROR, props_value_span(p, p->by_keyword[KW_TO] ? KW_TO : KW_FROM),
                    "from and to must differ (they are the centres of the two ends)");
        return 0;
    }
    return ok;
}

static int cylinder(loader *L, const props *p, scene_prim *prim)
{
    prim->kind = PRIM_CYLINDER;
    int ok = ends(L, p, &prim->u.cylinder.from, &prim->u.cylinder.to);
    ok &= positive(L, p, KW_RADIUS, 1, &prim->u.cylinder.radius);
    prim->u.cylinder.open = p->by_keyword[KW_OPEN] != NULL;
    return ok;
}

/* radii R0 R1: both >= 0, at least one > 0 (defaults 1 0: an apex at to). */
static int cone_radii(loader *L, const props *p, double radius[2])
{
    const ast *prop = p->by_keyword[KW_RADII];
    radius[0] = 1;
    radius[1] = 0;
    if (!prop)
        return 1;
    value v[2];
    if (!props_value_at(L, prop->first, VAL_NUMBER, &v[0]) ||
        !props_value_at(L, prop->first->next, VAL_NUMBER, &v[1]))
        return 0;
    for (int i = 0; i < 2; i++) {
        if (!(v[i].number >= 0))
            return report(L, v[i].span, "a cone's radii must be >= 0", v[i].number);
        radius[i] = v[i].number;
    }
    if (radius[0] == 0 && radius[1] == 0) {
        diag_report(&L->diag, DIAG_ERROR, prop->span, "a cone needs a radius > 0 at one end at least");
        return 0;
    }
    return 1;
}

static int cone(loader *L, const props *p, scene_prim *prim)
{
    prim->kind = PRIM_CONE;
    int ok = ends(L, p, &prim->u.cone.from, &prim->u.cone.to);
    ok &= cone_radii(L, p, prim->u.cone.radius);
    prim->u.cone.open = p->by_keyword[KW_OPEN] != NULL;
    return ok;
}

/* A ring torus: 0 < minor < major (a horn or spindle torus would cross
 * itself, and its inside would no longer be the tube's). */
static int torus(loader *L, const props *p, scene_prim *prim)
{
    prim->kind = PRIM_TORUS;
    int ok = props_vector(L, p, KW_CENTER, vec_splat(0), &prim->u.torus.center);
    int axis = props_vector(L, p, KW_AXIS, vec_make(0, 1, 0), &prim->u.torus.axis);
    if (axis && !loader_unit(prim->u.torus.axis, &prim->u.torus.axis)) {
        diag_report(&L->diag, DIAG_ERROR, props_value_span(p, KW_AXIS), "axis must not be a zero-length vector");
        axis = 0;
    }
    int radii = positive(L, p, KW_MAJOR, 1, &prim->u.torus.major);
    radii &= positive(L, p, KW_MINOR, 0.25, &prim->u.torus.minor);
    if (radii && !(prim->u.torus.minor < prim->u.torus.major)) {
        diag_report(&L->diag, DIAG_ERROR, props_value_span(p, p->by_keyword[KW_MINOR] ? KW_MINOR : KW_MAJOR),
                    "minor must be less than major (a ring torus), got minor %.17g and major %.17g",
                    prim->u.torus.minor, prim->u.torus.major);
        radii = 0;
    }
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

void lower_place_quadric(scene_prim *prim, const xform *w, const xform *l)
{
    double s;
    if (xform_is_identity(w))
        return;
    if (!xform_is_similarity(w, &s)) {
        lower_keep_frame(prim, w, l);
        return;
    }
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
}

static int ends_in_range(vec3 from, vec3 to)
{
    vec3 d = vec_sub(to, from);
    return vec_is_finite(from) && vec_is_finite(to) && vec_is_finite(d) && vec_length(d) > 0;
}

int lower_quadric_in_range(const scene_prim *prim)
{
    switch (prim->kind) {
    case PRIM_CYLINDER:
        return ends_in_range(prim->u.cylinder.from, prim->u.cylinder.to) && isfinite(prim->u.cylinder.radius) &&
               prim->u.cylinder.radius > 0;
    case PRIM_CONE:
        return ends_in_range(prim->u.cone.from, prim->u.cone.to) && isfinite(prim->u.cone.radius[0]) &&
               isfinite(prim->u.cone.radius[1]);
    default:
        return vec_is_finite(prim->u.torus.center) && fabs(vec_length(prim->u.torus.axis) - 1) < 1e-9 &&
               isfinite(prim->u.torus.major) && prim->u.torus.minor > 0 &&
               prim->u.torus.minor < prim->u.torus.major;
    }
}
