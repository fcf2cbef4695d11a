/*
 * ambient.c - family `ambient`: a scene lit by ambient light alone
 * (spec/analytic.md, [ORACLE-AMBIENT]).  Every pixel whose ray meets a
 * primitive shows Kd * Ia of that primitive's material (slide 11); the rest
 * show the background.  Assumptions: no lights, every material opaque
 * (t = 0) with Ks = 0 (nothing reflects or transmits), one sphere seen by an
 * orthographic camera, so that coverage is decided by the distance of the
 * sample point's ray from the sphere's centre, not by a ray intersection.
 */
#include <math.h>
#include "oracle.h"
#include "oracle_geom.h"

static int accepts(const oracle_view *v, char *why, size_t n)
{
    const rf_scene *s = v->scene;
    if (s->light_count != 0)
        return oracle_refuse(why, n, "ambient: the scene must have no lights (it has %d)", s->light_count);
    if (s->prim_count != 1 || s->prims[0].kind != PRIM_SPHERE || s->prims[0].has_xform)
        return oracle_refuse(why, n, "ambient: the scene must be one sphere");
    if (s->camera.kind != CAMERA_ORTHOGRAPHIC)
        return oracle_refuse(why, n, "ambient: the camera must be orthographic");
    const rf_material *m = &s->materials[s->prims[0].material];
    if (m->t != 0 || vec_max_component(m->ks) != 0)
        return oracle_refuse(why, n, "ambient: the material must have t = 0 and Ks = 0");
    return 1;
}

/* The orthographic ray through (x, y) is the line eye' + s*forward; it meets
 * the sphere iff its distance from the centre is at most the radius.  A
 * sample within 1e-9 radii of the outline is ambiguous. */
static oracle_status radiance(const oracle_view *v, double x, double y, rgb *out)
{
    const rf_scene *s = v->scene;
    const rf_prim *sphere = &s->prims[0];
    oracle_ray r = oracle_view_ray(v, x, y);
    vec3 to_center = vec_sub(sphere->u.sphere.center, r.origin);
    double along = vec_dot(to_center, r.dir);
    double off = vec_length(vec_sub(to_center, vec_scale(r.dir, along)));
    double radius = sphere->u.sphere.radius;
    if (fabs(off - radius) <= 1e-9 * radius)
        return ORACLE_AMBIGUOUS;
    int covered = off < radius && along > -radius;
    *out = covered ? vec_mul(s->materials[sphere->material].kd, s->ambient) : s->image.background;
    return ORACLE_EXACT;
}

static double tolerance(const oracle_view *v, int light_samples)
{
    (void)v;
    (void)light_samples;
    return 1e-9;
}

const oracle_family oracle_ambient = {
    "ambient", "ambient light alone: Kd * Ia (slide 11)", 0, accepts, radiance, tolerance,
};
