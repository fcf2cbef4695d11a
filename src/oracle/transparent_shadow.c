/*
 * transparent_shadow.c - family `transparent_shadow`: the shadow of a
 * transparent sphere (t > 0, ior 1) on a plane, and the sphere itself
 * (spec/analytic.md (section `transparent_shadow`), [ORACLE-TRANSPARENT-SHADOW-1],
 * [ORACLE-TRANSPARENT-SHADOW-2]).
 *
 * Shadow (slide 47): the path from a plane point to a light passes the
 * sphere's centre closer than r -> it crosses the surface twice -> S = t^2;
 * farther -> S = 1.  With ior 1 nothing bends, so a view ray through the
 * sphere goes on along its own line (slide 36 with n1 = n2):
 *   C = local(P1) + [max_depth > 1] t (local(P2) + [max_depth > 2] t C3)
 * P1, P2 the chord's entry and exit (normals solved from the chord), C3
 * what the same line meets next (the plane, or the background);
 * local = (1 - t) body (Ks = 0).  At P1 (outward normal) nothing is in the
 * way of any light with N.L > 0; at P2 the normal faces inward, and a light
 * with N.L > 0 is reached through the sphere's surface once: S = t.
 *
 * Assumptions: oracle_accept_sphere_plane; the sphere's material with
 * t > 0, ior 1 and Ks = 0; the plane's with Ks = 0 and t = 0.
 * Ambiguous: as sphere_shadow, plus the terminators at P1 and P2.
 */
#include <math.h>
#include "oracle/oracle.h"
#include "oracle/optics_util.h"
#include "oracle/oracle_util.h"

#define FAMILY "transparent_shadow"

typedef struct pair {
    const scene_model *scene;
    int sphere, plane;
} pair;

static pair pair_of(const scene_model *s)
{
    pair p = {s, s->prims[0].kind == PRIM_SPHERE ? 0 : 1, 0};
    p.plane = 1 - p.sphere;
    return p;
}

static int accepts(const oracle_view *v, char *why, size_t n)
{
    const scene_model *s = v->scene;
    int sphere, plane;
    if (!oracle_accept_sphere_plane(s, FAMILY, &sphere, &plane, why, n) ||
        !oracle_accept_matte(oracle_material(s, plane), FAMILY, "plane's material", why, n))
        return 0;
    const scene_material *m = oracle_material(s, sphere);
    if (!(m->t > 0) || m->ior != 1 || vec_max_component(m->ks) != 0)
        return oracle_refuse(why, n, FAMILY ": the sphere's material must have t > 0, ior 1 and Ks = 0");
    return 1;
}

/* t^2 through the sphere, 1 past it (oracle_shadow_fn; ctx: the pair). */
static double through_twice(const void *ctx, vec3 p, const oracle_light_at *la, int *ambiguous)
{
    const pair *pr = ctx;
    const scene_prim *sphere = &pr->scene->prims[pr->sphere];
    double r = sphere->u.sphere.radius, gap = oracle_path_distance(p, la, sphere->u.sphere.center) - r;
    double t = oracle_material(pr->scene, pr->sphere)->t;
    if (fabs(gap) <= ORACLE_EDGE_MARGIN * r)
        *ambiguous = 1;
    return gap > 0 ? 1 : t * t;
}

/* From the exit point, inward N.L > 0: out through the surface once. */
static double through_once(const void *ctx, vec3 p, const oracle_light_at *la, int *ambiguous)
{
    const pair *pr = ctx;
    (void)p;
    (void)la;
    (void)ambiguous;
    return oracle_material(pr->scene, pr->sphere)->t;
}

/* The plane at parameter s of the ray (or the background when the ray
 * does not meet it ahead). */
static oracle_status plane_colour(const pair *pr, const oracle_pair_view *pv, double after, rgb *out)
{
    const scene_model *s = pr->scene;
    vec3 p, normal;
    oracle_shading sh;
    if (!pv->plane_ok)
        return ORACLE_AMBIGUOUS;
    if (!(pv->plane_s > after)) {
        *out = s->image.background;
        return ORACLE_EXACT;
    }
    oracle_plane_hit(&s->prims[pr->plane], &pv->ray, pv->plane_s, &p, &normal);
    oracle_status status =
        oracle_shade_direct(s, oracle_material(s, pr->plane), p, normal, vec_neg(pv->ray.dir), through_twice, pr, &sh);
    *out = sh.body;
    return status;
}

/* Entry (far = 0) or exit (far = 1) of the chord, shaded locally. */
static oracle_status sphere_local(const pair *pr, const oracle_pair_view *pv, int far, rgb *out)
{
    const scene_model *s = pr->scene;
    const scene_prim *sphere = &s->prims[pr->sphere];
    const scene_material *m = oracle_material(s, pr->sphere);
    vec3 outward = oracle_chord_normal(&pv->chord, pv->ray.dir, sphere->u.sphere.radius, far);
    vec3 p = vec_add(sphere->u.sphere.center, vec_scale(outward, sphere->u.sphere.radius));
    oracle_shading sh;
    vec3 toward = vec_neg(pv->ray.dir);
    oracle_status status = far ? oracle_shade_direct(s, m, p, vec_neg(outward), toward, through_once, pr, &sh)
                               : oracle_shade_direct(s, m, p, outward, toward, NULL, NULL, &sh);
    *out = oracle_shade_local(m, &sh);
    return status;
}

/* C = local(P1) + [depth 1 < max] t (local(P2) + [depth 2 < max] t C3). */
static oracle_status through_sphere(const oracle_view *v, const pair *pr, const oracle_pair_view *pv, rgb *out)
{
    double t = oracle_material(pr->scene, pr->sphere)->t;
    rgb entry, exit_colour = vec_splat(0), beyond = vec_splat(0);
    if (sphere_local(pr, pv, 0, &entry) != ORACLE_EXACT)
        return ORACLE_AMBIGUOUS;
    if (v->max_depth > 1 && sphere_local(pr, pv, 1, &exit_colour) != ORACLE_EXACT)
        return ORACLE_AMBIGUOUS;
    if (v->max_depth > 2 && plane_colour(pr, pv, pv->chord.along + pv->chord.half, &beyond) != ORACLE_EXACT)
        return ORACLE_AMBIGUOUS;
    *out = vec_add(entry, vec_scale(vec_add(exit_colour, vec_scale(beyond, t)), t));
    return ORACLE_EXACT;
}

/* [ORACLE-VIEW-ROUNDING-4]: the tracer's spawn offsets at P1 and P2
 * (optics_spawn_offset, along the normals) shift the line it follows
 * through the sphere and past it; where the chord or the plane beyond
 * meets that line at a grazing angle the hits slide by offset / cos, which
 * no constant bounds.  The line shifted by twice the offsets, each way
 * along both normals, must keep the pixel within the tolerance, else the
 * pixel is ambiguous. */
static oracle_status stable_under_slip(const oracle_view *v, const pair *pr, const oracle_pair_view *pv, rgb c)
{
    const scene_prim *sphere = &pr->scene->prims[pr->sphere];
    const scene_prim *plane = &pr->scene->prims[pr->plane];
    vec3 centre = sphere->u.sphere.center;
    double r = sphere->u.sphere.radius;
    double slip = 2 * optics_spawn_offset(optics_max_abs(centre) + r, centre);
    double tolerance = oracle_tolerance_exact(v, 0);
    vec3 n1 = oracle_chord_normal(&pv->chord, pv->ray.dir, r, 0);
    vec3 n2 = oracle_chord_normal(&pv->chord, pv->ray.dir, r, 1);
    for (int k = 0; k < 4; k++) {
        vec3 w = vec_add(vec_scale(n1, k & 1 ? slip : -slip), vec_scale(n2, k & 2 ? slip : -slip));
        oracle_pair_view moved = *pv;
        rgb shifted;
        moved.ray.origin = vec_add(pv->ray.origin, w);
        if (oracle_line_sphere(moved.ray.origin, moved.ray.dir, centre, r, &moved.chord) != ORACLE_CHORD_HIT)
            return ORACLE_AMBIGUOUS;
        moved.plane_s = HUGE_VAL;
        moved.plane_ok = oracle_line_plane(moved.ray.origin, moved.ray.dir, plane->u.plane.point,
                                           plane->u.plane.normal, &moved.plane_s);
        if (through_sphere(v, pr, &moved, &shifted) != ORACLE_EXACT || !optics_close(c, shifted, tolerance))
            return ORACLE_AMBIGUOUS;
    }
    return ORACLE_EXACT;
}

static oracle_status radiance(const oracle_view *v, double x, double y, rgb *out)
{
    pair pr = pair_of(v->scene);
    oracle_pair_view pv;
    oracle_sees sees = oracle_view_sphere_plane(v, x, y, &v->scene->prims[pr.sphere], &v->scene->prims[pr.plane], &pv);
    if (sees == ORACLE_SEES_AMBIGUOUS)
        return ORACLE_AMBIGUOUS;
    if (sees == ORACLE_SEES_NOTHING) {
        *out = v->scene->image.background;
        return ORACLE_EXACT;
    }
    if (sees == ORACLE_SEES_PLANE)
        return plane_colour(&pr, &pv, 0, out);
    if (through_sphere(v, &pr, &pv, out) != ORACLE_EXACT)
        return ORACLE_AMBIGUOUS;
    return v->max_depth > 1 ? stable_under_slip(v, &pr, &pv, *out) : ORACLE_EXACT;
}

const oracle_family oracle_transparent_shadow = {
    "transparent_shadow", "a transparent sphere's shadow on a plane: S = t^2 through it (slide 47)", 0,
    accepts, radiance, oracle_tolerance_exact,
};
