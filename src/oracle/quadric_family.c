/*
 * quadric_family.c - see quadric_family.h.
 */
#include <math.h>
#include "oracle/quadric_family.h"

int quadric_family_accepts(const oracle_view *v, scene_prim_kind kind, const char *what, vec3 c, double r,
                           int distant_only, const char *family, char *why, size_t n)
{
    const scene_model *s = v->scene;
    vec3 f, right, up;
    if (s->prim_count != 1 || s->prims[0].kind != kind)
        return oracle_refuse(why, n, "%s: the scene must be one %s", family, what);
    if (!oracle_accept_untransformed(s, family, why, n) ||
        !oracle_accept_matte(oracle_material(s, 0), family, "material", why, n) ||
        !oracle_accept_lights(s, family, why, n))
        return 0;
    for (int i = 0; i < s->light_count; i++) {
        const scene_light *l = &s->lights[i];
        if (l->kind == LIGHT_POINT && distant_only)
            return oracle_refuse(why, n, "%s: light %d is a point light (distant lights only)", family, i + 1);
        if (l->kind == LIGHT_POINT && !(vec_length(vec_sub(l->position, c)) > r * (1 + ORACLE_EDGE_MARGIN)))
            return oracle_refuse(why, n, "%s: point light %d is inside the ball around the %s", family, i + 1, what);
    }
    if (s->camera.kind != CAMERA_ORTHOGRAPHIC)
        return oracle_refuse(why, n, "%s: the camera must be orthographic", family);
    oracle_camera_frame(&s->camera, &f, &right, &up);
    if (!(vec_dot(vec_sub(c, s->camera.eye), f) > r * (1 + ORACLE_EDGE_MARGIN)))
        return oracle_refuse(why, n, "%s: the %s must lie wholly in front of the camera's image plane", family,
                             what);
    return 1;
}

oracle_status quadric_family_shade(const oracle_view *v, vec3 p, vec3 n, vec3 d, oracle_shadow_fn shadow,
                                   const void *ctx, rgb *out)
{
    const scene_model *s = v->scene;
    oracle_shading sh;
    if (oracle_shade_direct(s, oracle_material(s, 0), p, n, vec_neg(d), shadow, ctx, &sh) != ORACLE_EXACT)
        return ORACLE_AMBIGUOUS;
    *out = sh.body;
    return ORACLE_EXACT;
}

oracle_status quadric_family_chord(const oracle_view *v, const oracle_ray *ray, oracle_chord_kind kind, double s,
                                   vec3 n, oracle_shadow_fn shadow, const void *ctx, rgb *out)
{
    if (kind == ORACLE_CHORD_GRAZE)
        return ORACLE_AMBIGUOUS;
    if (kind == ORACLE_CHORD_MISS) {
        *out = v->scene->image.background;
        return ORACLE_EXACT;
    }
    return quadric_family_shade(v, vec_add(ray->origin, vec_scale(ray->dir, s)), n, ray->dir, shadow, ctx, out);
}

oracle_status quadric_family_frustum_radiance(const oracle_view *v, double x, double y, rgb *out)
{
    oracle_frustum f = oracle_frustum_of(&v->scene->prims[0]);
    oracle_ray ray = oracle_view_ray(v, x, y);
    double s;
    vec3 nrm;
    oracle_chord_kind kind = oracle_line_frustum(&f, ray.origin, ray.dir, &s, &nrm);
    return quadric_family_chord(v, &ray, kind, s, nrm, NULL, NULL, out);
}
