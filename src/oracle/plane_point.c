/*
 * plane_point.c - family `plane_point`: a matte plane under point lights
 * with the falloffs linear, inverse_square and none
 * (spec/analytic.md (section `plane_point`), [ORACLE-PLANE-POINT-1]).
 *
 * The view ray o + s D meets the plane (p0, N) at s = N.(p0 - o)/(N.D), a
 * line/plane formula; with d = |light - P| and cos(theta) = N.(light - P)/d
 * (N turned toward the viewer) the value is
 *   Kd (Ia + sum falloff(E, d, d0) max(0, cos theta))           (slides 15-18)
 * falloff: E/(d+d0), E/(d+d0)^2 or E.  A lone plane shadows nothing.
 *
 * Assumptions: one plane with Ks = 0 and t = 0; point or distant lights,
 * point lights off the plane; any camera whose eye is off the plane.
 * Ambiguous: view rays within ORACLE_COS_MARGIN of the plane's direction
 * (the horizon) and, for an orthographic camera, an image plane crossing
 * the plane.
 */
#include "oracle/oracle.h"
#include "oracle/oracle_util.h"

#define FAMILY "plane_point"

static int accepts(const oracle_view *v, char *why, size_t n)
{
    const scene_model *s = v->scene;
    if (s->prim_count != 1 || s->prims[0].kind != PRIM_PLANE)
        return oracle_refuse(why, n, FAMILY ": the scene must be one plane");
    return oracle_accept_matte(oracle_material(s, 0), FAMILY, "plane's material", why, n) &&
           oracle_accept_lights(s, FAMILY, why, n) && oracle_accept_off_plane(s, &s->prims[0], FAMILY, why, n);
}

const oracle_family oracle_plane_point = {
    "plane_point", "plane under a point light: Kd (Ia + falloff(E, d) cos theta) (slides 15-18)", 0,
    accepts, oracle_view_lambert, oracle_tolerance_exact,
};
