/*
 * phong_plane.c - family `phong_plane`: the Phong highlight on a plane
 * (spec/analytic.md (section `phong_plane`), [ORACLE-PHONG-PLANE-1],
 * [ORACLE-PHONG-PLANE-2]).
 *
 * The hit point comes from the line/plane formula; with N turned toward the
 * viewer, V = -D and, per light, I = falloff(E, d, d0), cos = N.L and
 * V.R = 2 cos (N.V) - L.V (R never formed):
 *   Kd (Ia + sum I cos) + Ks sum I max(0, V.R)^n  [+ Ks * background]
 * the last term when max_depth > 1: a lone plane's mirror ray leaves it and
 * meets nothing (slide 48).  V.R = 1 exactly where the eye sees the mirror
 * image of the light: for an orthographic camera along -N the foot of the
 * light, for a perspective eye the crossing of the eye -> mirror-light line
 * with the plane (oracle_mirror_point, oracle_mirror_point_ortho); there the
 * highlight is Ks*I.
 *
 * Assumptions: one plane with t = 0 (any Kd, Ks, n); point or distant
 * lights, point lights off the plane; any camera whose eye is off the
 * plane.  Ambiguous: the horizon, and |V.R| near 0 when n < 1.
 */
#include "oracle/oracle.h"
#include "oracle/oracle_util.h"

#define FAMILY "phong_plane"

static int accepts(const oracle_view *v, char *why, size_t n)
{
    const scene_model *s = v->scene;
    if (s->prim_count != 1 || s->prims[0].kind != PRIM_PLANE)
        return oracle_refuse(why, n, FAMILY ": the scene must be one plane");
    if (oracle_material(s, 0)->t != 0)
        return oracle_refuse(why, n, FAMILY ": the plane's material must be opaque (t = 0)");
    return oracle_accept_lights(s, FAMILY, why, n) && oracle_accept_off_plane(s, &s->prims[0], FAMILY, why, n);
}

const oracle_family oracle_phong_plane = {
    "phong_plane", "Phong highlight on a plane: Ks I max(0, V.R)^n, peak at the light's mirror point (slides 24-28)",
    0, accepts, oracle_view_phong, oracle_tolerance_exact,
};
