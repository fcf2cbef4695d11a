/*
 * lambert_cylinder.c - family `lambert_cylinder`: a closed matte cylinder
 * under distant and point lights, seen by an orthographic camera
 * (spec/analytic.md (section `lambert_cylinder`), [ORACLE-LAMBERT-CYLINDER-1]).
 *
 * The view ray's entry into the solid is the later of its entries into
 * the slab between the end planes and into the infinite side; the side's
 * is solved by Pythagoras in the plane across the axis
 * (oracle_line_frustum), with no intersection routine.  A convex solid
 * cannot shadow itself where N.L > 0, so the value is
 * Kd (Ia + sum I max(0, N.L)).
 *
 * Ambiguous: the outline, the rims, the terminator.
 */
#include "oracle/quadric_family.h"

#define FAMILY "lambert_cylinder"

static int accepts(const oracle_view *v, char *why, size_t n)
{
    const scene_model *s = v->scene;
    vec3 c;
    double r;
    if (s->prim_count == 1 && s->prims[0].kind == PRIM_CYLINDER && s->prims[0].u.cylinder.open)
        return oracle_refuse(why, n, FAMILY ": the cylinder must be closed (an open one shows, and shadows, its inside)");
    oracle_frustum f = s->prim_count == 1 && s->prims[0].kind == PRIM_CYLINDER ? oracle_frustum_of(&s->prims[0])
                                                                               : (oracle_frustum){{0, 0, 0}, {0, 0, 1}, 1, 1, 1};
    oracle_frustum_ball(&f, &c, &r);
    return quadric_family_accepts(v, PRIM_CYLINDER, "cylinder", c, r, 0, FAMILY, why, n);
}

const oracle_family oracle_lambert_cylinder = {
    "lambert_cylinder", "Lambert cylinder with its caps, orthographic view: Kd (Ia + E max(0, N.L))", 0,
    accepts, quadric_family_frustum_radiance, oracle_tolerance_exact,
};
