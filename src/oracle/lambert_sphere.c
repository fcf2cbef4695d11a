/*
 * lambert_sphere.c - family `lambert_sphere`: a matte sphere under distant
 * (and point) lights seen by an orthographic camera
 * (spec/analytic.md (section `lambert_sphere`), [ORACLE-LAMBERT-SPHERE-1]).
 *
 * In the camera frame the view ray through a screen point is a line at
 * distance off from the centre; it enters the sphere at depth
 * half = sqrt(r^2 - off^2) before the centre's plane, so the visible
 * normal is N = (-q - half*F)/r (q: from the line's nearest point to the
 * centre, negated; F: forward), solved directly, with no intersection
 * routine.  The value is Kd*(Ia + sum_i I_i max(0, N.L_i)) (slides 11,
 * 17-18): one convex primitive cannot shadow itself where N.L > 0.
 *
 * Assumptions: one untransformed sphere, material with Ks = 0 and t = 0;
 * an orthographic camera whose image plane lies wholly in front of the
 * sphere; point lights outside the sphere; no distributed lights.
 * Ambiguous: the silhouette (ORACLE_EDGE_MARGIN radii) and the terminator
 * (|N.L| <= ORACLE_COS_MARGIN).
 */
#include "oracle/oracle.h"
#include "oracle/oracle_util.h"

#define FAMILY "lambert_sphere"

static int accepts(const oracle_view *v, char *why, size_t n)
{
    const scene_model *s = v->scene;
    if (s->prim_count != 1 || s->prims[0].kind != PRIM_SPHERE)
        return oracle_refuse(why, n, FAMILY ": the scene must be one sphere");
    const scene_prim *sphere = &s->prims[0];
    return oracle_accept_untransformed(s, FAMILY, why, n) &&
           oracle_accept_matte(oracle_material(s, 0), FAMILY, "sphere's material", why, n) &&
           oracle_accept_lights(s, FAMILY, why, n) &&
           oracle_accept_lights_outside(s, sphere->u.sphere.center, sphere->u.sphere.radius, FAMILY, why, n) &&
           oracle_accept_ortho_in_front(s, sphere->u.sphere.center, sphere->u.sphere.radius, FAMILY, why, n);
}

const oracle_family oracle_lambert_sphere = {
    "lambert_sphere", "Lambert sphere, orthographic view: Kd (Ia + E max(0, N.L)) (slides 11, 17)", 0,
    accepts, oracle_view_lambert, oracle_tolerance_exact,
};
