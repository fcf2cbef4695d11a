/*
 * phong_sphere.c - family `phong_sphere`: the Phong highlight on a sphere
 * seen by an orthographic camera (spec/analytic.md (section `phong_sphere`),
 * [ORACLE-PHONG-SPHERE-1], [ORACLE-PHONG-SPHERE-2]).
 *
 * V = -F is the same for every pixel.  The visible normal N is solved as in
 * lambert_sphere; the lobe uses V.R = 2(N.L)(N.V) - L.V (R never formed),
 * so the value is
 *   Kd (Ia + sum I (N.L)) + Ks sum I max(0, V.R)^n  [+ Ks * background]
 * the last term when max_depth > 1: the mirror ray of a lone convex sphere
 * leaves it and meets nothing (slide 48).  For a distant light the lobe
 * peaks (V.R = 1) where N = normalize(L + V), the half vector: the point
 * c + r*normalize(L + V) (oracle_phong_sphere_peak in the tests).
 *
 * Assumptions: one untransformed sphere, material with t = 0 (any Kd, Ks,
 * n); an orthographic camera with the sphere in front of its image plane;
 * point and distant lights, point lights outside the sphere.  Ambiguous:
 * the silhouette, the terminator, and |V.R| near 0 when n < 1.
 */
#include "oracle/oracle.h"
#include "oracle/oracle_util.h"

#define FAMILY "phong_sphere"

static int accepts(const oracle_view *v, char *why, size_t n)
{
    const scene_model *s = v->scene;
    if (s->prim_count != 1 || s->prims[0].kind != PRIM_SPHERE)
        return oracle_refuse(why, n, FAMILY ": the scene must be one sphere");
    const scene_prim *sphere = &s->prims[0];
    if (oracle_material(s, 0)->t != 0)
        return oracle_refuse(why, n, FAMILY ": the sphere's material must be opaque (t = 0)");
    return oracle_accept_untransformed(s, FAMILY, why, n) && oracle_accept_lights(s, FAMILY, why, n) &&
           oracle_accept_lights_outside(s, sphere->u.sphere.center, sphere->u.sphere.radius, FAMILY, why, n) &&
           oracle_accept_ortho_in_front(s, sphere->u.sphere.center, sphere->u.sphere.radius, FAMILY, why, n);
}

const oracle_family oracle_phong_sphere = {
    "phong_sphere", "Phong highlight on a sphere, orthographic view: Ks I max(0, V.R)^n (slides 24-28)", 0,
    accepts, oracle_view_phong, oracle_tolerance_exact,
};
