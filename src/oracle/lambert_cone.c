/*
 * lambert_cone.c - family `lambert_cone`: a closed matte cone, truncated or
 * with an apex, under distant and point lights, seen by an orthographic
 * camera (spec/analytic.md (section `lambert_cone`), [ORACLE-LAMBERT-CONE-1]).
 *
 * The side is solved in the apex form ((p - V).w)^2 = cos^2(theta)
 * |p - V|^2 and its normal is cos(theta) (p - V)/|p - V| - w, where the
 * tracer works with the radius along the axis (oracle_line_frustum).  A
 * convex solid: Kd (Ia + sum I max(0, N.L)).
 *
 * Ambiguous: the outline, the rims, the apex, the terminator.
 */
#include "oracle/quadric_family.h"

#define FAMILY "lambert_cone"

static int accepts(const oracle_view *v, char *why, size_t n)
{
    const scene_model *s = v->scene;
    vec3 c;
    double r;
    const scene_prim *p = &s->prims[0];
    int one = s->prim_count == 1 && p->kind == PRIM_CONE;
    if (one && p->u.cone.open)
        return oracle_refuse(why, n, FAMILY ": the cone must be closed (an open one shows, and shadows, its inside)");
    if (one && p->u.cone.radius[0] == p->u.cone.radius[1])
        return oracle_refuse(why, n, FAMILY ": the radii are equal: that is a cylinder (family lambert_cylinder)");
    oracle_frustum f = one ? oracle_frustum_of(p) : (oracle_frustum){{0, 0, 0}, {0, 0, 1}, 1, 1, 0};
    oracle_frustum_ball(&f, &c, &r);
    return quadric_family_accepts(v, PRIM_CONE, "cone", c, r, 0, FAMILY, why, n);
}

const oracle_family oracle_lambert_cone = {
    "lambert_cone", "Lambert cone (truncated or with an apex), orthographic view: Kd (Ia + E max(0, N.L))", 0,
    accepts, quadric_family_frustum_radiance, oracle_tolerance_exact,
};
