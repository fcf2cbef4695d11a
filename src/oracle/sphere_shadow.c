/*
 * sphere_shadow.c - family `sphere_shadow`: an opaque sphere's shadow on a
 * plane from point and distant lights (spec/analytic.md (section `sphere_shadow`),
 * [ORACLE-SPHERE-SHADOW-1], [ORACLE-SPHERE-SHADOW-2]).
 *
 * A plane point P is lit by a light exactly when the path from P to the
 * light (the segment to a point light, the half-line toward a distant one)
 * stays farther than r from the sphere's centre C: the distance of C from
 * that path against the radius (slide 47), no ray/sphere intersection.  So
 *   lit:      Kd (Ia + sum I cos theta)          shadowed: Kd Ia
 * per light; within ORACLE_EDGE_MARGIN radii of tangency the sample is on
 * the boundary and ambiguous.  The camera may see the sphere too: it is
 * shaded as a Lambert sphere, which nothing shadows (oracle_util.h:
 * oracle_accept_sphere_plane), with its normal solved from the chord.
 *
 * Assumptions: oracle_accept_sphere_plane, and both materials with Ks = 0
 * and t = 0 (no secondary rays).  Ambiguous: the sphere's outline, the
 * shadow boundary, the terminator, the horizon.
 */
#include <math.h>
#include "oracle/oracle.h"
#include "oracle/oracle_util.h"

#define FAMILY "sphere_shadow"

static int accepts(const oracle_view *v, char *why, size_t n)
{
    const scene_model *s = v->scene;
    int sphere, plane;
    return oracle_accept_sphere_plane(s, FAMILY, &sphere, &plane, why, n) &&
           oracle_accept_matte(oracle_material(s, sphere), FAMILY, "sphere's material", why, n) &&
           oracle_accept_matte(oracle_material(s, plane), FAMILY, "plane's material", why, n);
}

/* 0 inside the shadow, 1 outside (oracle_shadow_fn; ctx: the sphere). */
static double blocked(const void *ctx, vec3 p, const oracle_light_at *la, int *ambiguous)
{
    const scene_prim *sphere = ctx;
    double r = sphere->u.sphere.radius, gap = oracle_path_distance(p, la, sphere->u.sphere.center) - r;
    if (fabs(gap) <= ORACLE_EDGE_MARGIN * r)
        *ambiguous = 1;
    return gap > 0 ? 1 : 0;
}

static oracle_status radiance(const oracle_view *v, double x, double y, rgb *out)
{
    const scene_model *s = v->scene;
    int si = s->prims[0].kind == PRIM_SPHERE ? 0 : 1, pi = 1 - si;
    const scene_prim *sphere = &s->prims[si], *plane = &s->prims[pi];
    oracle_pair_view pv;
    oracle_sees sees = oracle_view_sphere_plane(v, x, y, sphere, plane, &pv);
    vec3 p, normal, toward = vec_neg(pv.ray.dir);
    oracle_shading sh;
    oracle_status status = ORACLE_EXACT;
    if (sees == ORACLE_SEES_AMBIGUOUS)
        return ORACLE_AMBIGUOUS;
    if (sees == ORACLE_SEES_NOTHING) {
        *out = s->image.background;
        return ORACLE_EXACT;
    }
    if (sees == ORACLE_SEES_SPHERE) {
        normal = oracle_chord_normal(&pv.chord, pv.ray.dir, sphere->u.sphere.radius, 0);
        p = vec_add(sphere->u.sphere.center, vec_scale(normal, sphere->u.sphere.radius));
        status = oracle_shade_direct(s, oracle_material(s, si), p, normal, toward, NULL, NULL, &sh);
    } else {
        oracle_plane_hit(plane, &pv.ray, pv.plane_s, &p, &normal);
        status = oracle_shade_direct(s, oracle_material(s, pi), p, normal, toward, blocked, sphere, &sh);
    }
    *out = sh.body;
    return status;
}

const oracle_family oracle_sphere_shadow = {
    "sphere_shadow", "an opaque sphere's shadow on a plane: lit Kd (Ia + I cos), shadowed Kd Ia (slide 47)", 0,
    accepts, radiance, oracle_tolerance_exact,
};
