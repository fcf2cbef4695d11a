/*
 * parallel_mirrors.c - family `parallel_mirrors` (spec/analytic.md, section
 * parallel_mirrors, [ORACLE-MIRRORS]): two parallel opaque planes facing
 * each other, the camera between them.  Every camera ray not parallel to
 * the planes bounces between them forever; the tracer follows it for
 * max_depth D hits, so the pixel is the series
 *     C = sum_{k=0}^{D-1} W_k (Kd_k Ia + direct_k),   W_k = prod_{j<k} Ks_j
 * over the hits k.  The hit points come from unfolding the path
 * (optics_slab_hit), never from reflecting a ray step by step.  With no
 * point light the terms do not depend on where the hits are and the series
 * is summed in closed form (alternating walls A, B, q = Ks_A Ks_B):
 *     C = G(q, ceil(D/2)) Kd_A Ia + Ks_A G(q, floor(D/2)) Kd_B Ia,
 *     G(q, m) = sum_{j<m} q^j = (1 - q^m)/(1 - q).
 * Assumptions (refused otherwise): exactly two planes, parallel, apart;
 * both opaque (t = 0); the camera (every ray origin) strictly between them;
 * point lights strictly between them (they see both inner faces unshadowed:
 * the segment from a wall to the light stays between the walls), distant
 * lights allowed (they add nothing: the light that reaches one wall's inner
 * face must cross the other, opaque wall); no distributed light.
 * Ambiguous: rays within 1e-9 of parallel to the walls (the horizon, where
 * a ray escapes to the background), and lit samples whose series moves by
 * more than OPTICS_SENSITIVITY when the hits slip along the walls by twice
 * the tracer's self-intersection offsets (near the horizon the path runs
 * far, the offsets grow with the coordinates and tan(theta) turns each
 * into a long slip).
 */
#include <math.h>
#include "oracle/optics_util.h"
#include "oracle/oracle_geom.h"
#include "oracle/oracle_util.h"

/* The two walls as a slab whose lo wall (wall 0) is the first plane: the
 * axis is the first plane's normal, turned toward the second plane. */
static void mirror_slab(const scene_model *s, optics_slab *slab)
{
    const scene_prim *a = &s->prims[0], *b = &s->prims[1];
    slab->axis = a->u.plane.normal;
    double za = vec_dot(slab->axis, a->u.plane.point), zb = vec_dot(slab->axis, b->u.plane.point);
    if (zb < za) {
        slab->axis = vec_neg(slab->axis);
        za = -za;
        zb = -zb;
    }
    slab->lo = za;
    slab->hi = zb;
}

static int strictly_between(const optics_slab *slab, vec3 p)
{
    double z = vec_dot(slab->axis, p), margin = OPTICS_MARGIN * (slab->hi - slab->lo);
    return z > slab->lo + margin && z < slab->hi - margin;
}

static int accepts_walls(const scene_model *s, char *why, size_t n)
{
    if (s->prim_count != 2 || s->prims[0].kind != PRIM_PLANE || s->prims[1].kind != PRIM_PLANE)
        return oracle_refuse(why, n, "parallel_mirrors: the scene must be exactly two planes");
    if (vec_length(vec_cross(s->prims[0].u.plane.normal, s->prims[1].u.plane.normal)) > 1e-12)
        return oracle_refuse(why, n, "parallel_mirrors: the two planes are not parallel");
    for (int i = 0; i < 2; i++)
        if (s->materials[s->prims[i].material].t != 0)
            return oracle_refuse(why, n, "parallel_mirrors: plane %d is transparent (t must be 0)", i + 1);
    optics_slab slab;
    mirror_slab(s, &slab);
    double scale = fmax(vec_length(s->prims[0].u.plane.point), vec_length(s->prims[1].u.plane.point));
    if (!(slab.hi - slab.lo > 1e-9 * fmax(scale, 1)))
        return oracle_refuse(why, n, "parallel_mirrors: the two planes coincide");
    return 1;
}

static int accepts(const oracle_view *v, char *why, size_t n)
{
    const scene_model *s = v->scene;
    if (!accepts_walls(s, why, n))
        return 0;
    optics_slab slab;
    mirror_slab(s, &slab);
    for (int c = 0; c < 4; c++)
        if (!strictly_between(&slab, optics_corner_ray(v, c).origin))
            return oracle_refuse(why, n, "parallel_mirrors: the camera is not strictly between the mirrors");
    for (int i = 0; i < s->light_count; i++) {
        const scene_light *l = &s->lights[i];
        if (l->kind == LIGHT_RECTANGLE || l->kind == LIGHT_DISK)
            return oracle_refuse(why, n, "parallel_mirrors: light %d is distributed (point or distant only)", i + 1);
        if (l->kind == LIGHT_POINT && !strictly_between(&slab, l->position))
            return oracle_refuse(why, n, "parallel_mirrors: point light %d is not strictly between the mirrors",
                                 i + 1);
    }
    return 1;
}

/* Wall 0 is the first plane (mirror_slab), wall 1 the second. */
static const scene_material *wall_material(const scene_model *s, int wall)
{
    return &s->materials[s->prims[wall].material];
}

static int has_point_light(const scene_model *s)
{
    for (int i = 0; i < s->light_count; i++)
        if (s->lights[i].kind == LIGHT_POINT)
            return 1;
    return 0;
}

/* The closed form: the walls alternate from the first one, A. */
static rgb closed_series(const scene_model *s, int first_wall, int depth)
{
    const scene_material *a = wall_material(s, first_wall), *b = wall_material(s, !first_wall);
    rgb q = vec_mul(a->ks, b->ks);
    rgb even = vec_mul(optics_geometric_sum_rgb(q, (depth + 1) / 2), vec_mul(a->kd, s->ambient));
    rgb odd = vec_mul(vec_mul(a->ks, optics_geometric_sum_rgb(q, depth / 2)), vec_mul(b->kd, s->ambient));
    return vec_add(even, odd);
}

/*
 * The series term by term at the unfolded hit points.  Distant lights are
 * left out: the other wall blocks them (see the file comment).  slip moves
 * the hits along the walls as the tracer's self-intersection offsets do,
 * times slip: each mirror ray starts o_j off its wall, so every later hit
 * comes o_j tan(theta) early along the wall (0 for the exact value).
 */
static oracle_status unfolded_series(const scene_model *s, const optics_slab *slab, oracle_ray r, int depth, double slip,
                                     rgb *out)
{
    rgb sum = vec_splat(0), weight = vec_splat(1);
    double dz = vec_dot(slab->axis, r.dir), early = 0;
    vec3 across = vec_sub(r.dir, vec_scale(slab->axis, dz));
    double tan_theta = vec_length(across) / fabs(dz);
    across = tan_theta > 0 ? vec_normalize(across) : across;
    for (int k = 0; k < depth; k++) {
        optics_bounce b;
        optics_slab_hit(slab, r.origin, r.dir, k, &b);
        const scene_material *m = wall_material(s, b.wall);
        vec3 point = vec_madd(b.point, across, -slip * early);
        rgb body = vec_mul(m->kd, s->ambient), highlight = vec_splat(0);
        for (int i = 0; i < s->light_count; i++)
            if (s->lights[i].kind == LIGHT_POINT &&
                !optics_light_terms(&s->lights[i], m, point, b.inward, vec_neg(b.dir), 1, &body, &highlight))
                return ORACLE_AMBIGUOUS;
        sum = vec_add(sum, vec_mul(weight, vec_add(body, highlight)));
        weight = vec_mul(weight, m->ks);
        const scene_prim *wall = &s->prims[b.wall];
        early += optics_spawn_offset(optics_max_abs(wall->u.plane.point), b.point) * tan_theta;
    }
    *out = sum;
    return ORACLE_EXACT;
}

/* The exact series, ambiguous when twice the tracer's slips (either way)
 * would move it by more than OPTICS_SENSITIVITY. */
static oracle_status lit_series(const scene_model *s, const optics_slab *slab, oracle_ray r, int depth, rgb *out)
{
    rgb early, late;
    if (unfolded_series(s, slab, r, depth, 0, out) != ORACLE_EXACT ||
        unfolded_series(s, slab, r, depth, 2, &early) != ORACLE_EXACT ||
        unfolded_series(s, slab, r, depth, -2, &late) != ORACLE_EXACT)
        return ORACLE_AMBIGUOUS;
    if (!optics_close(*out, early, OPTICS_SENSITIVITY) || !optics_close(*out, late, OPTICS_SENSITIVITY))
        return ORACLE_AMBIGUOUS;
    return ORACLE_EXACT;
}

static oracle_status radiance(const oracle_view *v, double x, double y, rgb *out)
{
    const scene_model *s = v->scene;
    optics_slab slab;
    mirror_slab(s, &slab);
    oracle_ray r = oracle_view_ray(v, x, y);
    double dz = vec_dot(slab.axis, r.dir);
    if (fabs(dz) <= OPTICS_MARGIN)
        return ORACLE_AMBIGUOUS;
    if (!has_point_light(s)) {
        *out = closed_series(s, dz > 0, v->max_depth);
        return ORACLE_EXACT;
    }
    return lit_series(s, &slab, r, v->max_depth, out);
}

const oracle_family oracle_parallel_mirrors = {
    "parallel_mirrors", "two facing mirrors: the reflection series cut by max_depth, hits by unfolding", 0,
    accepts, radiance, oracle_tolerance_exact,
};
