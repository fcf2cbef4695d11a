/*
 * ambient_only.c - family `ambient_only`: a sphere lit by ambient light
 * alone (spec/analytic.md (section `ambient_only`), [ORACLE-AMBIENT-1]).  Every sample
 * point whose ray meets the sphere shows Kd * Ia of its material (slide
 * 11); the rest show the background.  (Not `ambient`: a reserved word,
 * which `oracle NAME` cannot take.)
 *
 * Assumptions: no lights; one untransformed sphere whose material is opaque
 * (t = 0) with Ks = 0, so nothing reflects or transmits and max_depth plays
 * no part; any camera.  Coverage is decided by the distance of the view ray
 * from the centre (oracle_line_sphere), not by a ray intersection: the ray
 * o + s d, s > 0, meets the sphere iff that distance is below the radius and
 * the far crossing along + half lies ahead of the origin.
 */
#include <math.h>
#include "oracle/oracle.h"
#include "oracle/oracle_geom.h"
#include "oracle/oracle_util.h"

static int accepts(const oracle_view *v, char *why, size_t n)
{
    const scene_model *s = v->scene;
    if (s->light_count != 0)
        return oracle_refuse(why, n, "ambient_only: the scene must have no lights (it has %d)", s->light_count);
    if (s->prim_count != 1 || s->prims[0].kind != PRIM_SPHERE)
        return oracle_refuse(why, n, "ambient_only: the scene must be one sphere");
    if (!oracle_accept_untransformed(s, "ambient_only", why, n))
        return 0;
    return oracle_accept_matte(oracle_material(s, 0), "ambient_only", "sphere's material", why, n);
}

/* Ambiguous within ORACLE_EDGE_MARGIN radii of the outline, or when the far
 * crossing is that close to the ray's origin (an orthographic image plane
 * through the sphere's back). */
static oracle_status radiance(const oracle_view *v, double x, double y, rgb *out)
{
    const scene_model *s = v->scene;
    const scene_prim *sphere = &s->prims[0];
    double radius = sphere->u.sphere.radius;
    oracle_ray r = oracle_view_ray(v, x, y);
    oracle_chord ch;
    oracle_chord_kind kind = oracle_line_sphere(r.origin, r.dir, sphere->u.sphere.center, radius, &ch);
    if (kind == ORACLE_CHORD_GRAZE)
        return ORACLE_AMBIGUOUS;
    double far = ch.along + ch.half;
    if (kind == ORACLE_CHORD_HIT && fabs(far) <= ORACLE_EDGE_MARGIN * radius)
        return ORACLE_AMBIGUOUS;
    int covered = kind == ORACLE_CHORD_HIT && far > 0;
    *out = covered ? vec_mul(oracle_material(s, 0)->kd, s->ambient) : s->image.background;
    return ORACLE_EXACT;
}

const oracle_family oracle_ambient_only = {
    "ambient_only", "ambient light alone: Kd * Ia (slide 11)", 0, accepts, radiance, oracle_tolerance_exact,
};
