/*
 * snell_window.c - family `snell_window` (spec/analytic.md (section `snell_window`),
 * [ORACLE-SNELL]): the camera inside a large glass box (index n > 1,
 * transparency t) looks at one pair of its faces.  At a face met from
 * inside the tracer goes from n to 1 (the box leaves the medium stack,
 * leaving air, whether or not the camera ray started with it): a ray at
 * incidence theta leaves when sin theta < 1/n (weight t, it sees the
 * background) and is totally reflected beyond the critical angle
 * theta_c = asin(1/n) (weight t, on to the opposite face, where the angle
 * is the same, and so on until max_depth D).  The image is Snell's window:
 * a disk of background of angular radius theta_c.  With L = (1 - t) Kd Ia
 * (no lights) and G(q, m) = sum_{k<m} q^k:
 *     beyond theta_c:  C = G(Ks + t, D) L            (the mirror ray and the
 *                                                     TIR ray are one ray)
 *     inside:          C = G(Ks, D) L + t bg G(Ks, D - 1)
 * With point lights inside the box the local colour of each hit depends on
 * where it is; the hits come from unfolding (optics_slab_hit) and the same
 * weights are summed term by term.  Assumptions (refused otherwise): one
 * box, not rotated, t > 0; every camera ray origin and every point light
 * strictly inside it; no other lights; no horizon in the view (every ray
 * heads for the same face), and every ray's first D hits lie on the two
 * faces it looks at, not on the sides (the box is wide enough).
 * Ambiguous: incidence within 1e-9 (relative) of the critical angle, and
 * lit samples whose series moves by more than OPTICS_SENSITIVITY when the
 * hits slip along the faces by twice the tracer's self-intersection
 * offsets.
 */
#include <math.h>
#include "oracle/optics_util.h"
#include "oracle/oracle_geom.h"
#include "oracle/oracle_util.h"

/* The box, its material and the pair of faces the camera looks at. */
typedef struct window_setup {
    const scene_prim *box;
    const scene_material *glass;
    optics_slab slab;
    int axis;
} window_setup;

/* The faces across the camera's forward axis (its largest component). */
static void window_setup_of(const scene_model *s, window_setup *w)
{
    w->box = &s->prims[0];
    w->glass = &s->materials[w->box->material];
    vec3 f, r, u;
    oracle_camera_frame(&s->camera, &f, &r, &u);
    double ax = fabs(f.x), ay = fabs(f.y), az = fabs(f.z);
    w->axis = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
    w->slab.axis = vec_make(w->axis == 0, w->axis == 1, w->axis == 2);
    w->slab.lo = vec_component(w->box->u.box.lo, w->axis);
    w->slab.hi = vec_component(w->box->u.box.hi, w->axis);
}

/* Strictly inside the box along the axes in mask (bit i: axis i), a margin
 * of each extent away from the faces. */
static int inside_box(const scene_prim *box, vec3 p, int mask)
{
    for (int i = 0; i < 3; i++) {
        double lo = vec_component(box->u.box.lo, i), hi = vec_component(box->u.box.hi, i);
        double margin = OPTICS_MARGIN * (hi - lo), c = vec_component(p, i);
        if ((mask >> i & 1) && !(c > lo + margin && c < hi - margin))
            return 0;
    }
    return 1;
}

static int accepts_scene(const scene_model *s, char *why, size_t n)
{
    if (s->prim_count != 1 || s->prims[0].kind != PRIM_BOX || s->prims[0].frame)
        return oracle_refuse(why, n, "snell_window: the scene must be one box (not rotated)");
    const scene_material *m = &s->materials[s->prims[0].material];
    if (!(m->t > 0))
        return oracle_refuse(why, n, "snell_window: the box must be transparent (t > 0)");
    for (int i = 0; i < s->light_count; i++) {
        const scene_light *l = &s->lights[i];
        if (l->kind != LIGHT_POINT)
            return oracle_refuse(why, n, "snell_window: light %d is not a point light", i + 1);
        if (!inside_box(&s->prims[0], l->position, 7))
            return oracle_refuse(why, n, "snell_window: point light %d is not strictly inside the box", i + 1);
    }
    return 1;
}

/* Per corner: the origin inside, the ray heading for the same face as the
 * others, its last hit (k = D - 1) on the face.  The hits of every sample
 * ray lie in the hull of the corners' (a central projection of the image
 * rectangle from the eye when no ray is parallel to the faces). */
static int accepts(const oracle_view *v, char *why, size_t n)
{
    const scene_model *s = v->scene;
    if (!accepts_scene(s, why, n))
        return 0;
    window_setup w;
    window_setup_of(s, &w);
    int across = 7 & ~(1 << w.axis), sign = 0;
    for (int c = 0; c < 4; c++) {
        oracle_ray r = optics_corner_ray(v, c);
        double dz = vec_dot(w.slab.axis, r.dir);
        if (!inside_box(w.box, r.origin, 7))
            return oracle_refuse(why, n, "snell_window: the camera is not strictly inside the box");
        if (dz == 0 || (sign && (dz > 0) != (sign > 0)))
            return oracle_refuse(why, n, "snell_window: the view must not contain directions parallel to the faces");
        sign = dz > 0 ? 1 : -1;
    }
    for (int c = 0; c < 4; c++) {
        oracle_ray r = optics_corner_ray(v, c);
        optics_bounce b;
        optics_slab_hit(&w.slab, r.origin, r.dir, v->max_depth - 1, &b);
        if (!inside_box(w.box, b.point, across))
            return oracle_refuse(why, n, "snell_window: within max_depth some ray reaches a side of the box "
                                         "(make the box wider)");
    }
    return 1;
}

/*
 * Term by term at the unfolded hits: each adds its local colour; a ray
 * inside the window also leaves with weight t to the background, and goes
 * on only by the mirror ray (Ks); beyond it the TIR ray joins (Ks + t).
 * slip moves the hits along the faces as the tracer's self-intersection
 * offsets do, times slip: each reflected ray starts o_k off its face, so
 * every later hit comes o_k tan(theta) early (0 for the exact value).
 */
static oracle_status unfolded_series(const scene_model *s, const window_setup *w, oracle_ray r, int tir, int depth,
                                     double slip, rgb *out)
{
    const scene_material *m = w->glass;
    rgb sum = vec_splat(0), weight = vec_splat(1);
    rgb next = tir ? vec_add(m->ks, vec_splat(m->t)) : m->ks;
    double dz = vec_dot(w->slab.axis, r.dir), early = 0;
    double size = fmax(optics_max_abs(w->box->u.box.lo), optics_max_abs(w->box->u.box.hi));
    vec3 across = vec_sub(r.dir, vec_scale(w->slab.axis, dz));
    double tan_theta = vec_length(across) / fabs(dz);
    across = tan_theta > 0 ? vec_normalize(across) : across;
    for (int k = 0; k < depth; k++) {
        optics_bounce b;
        optics_slab_hit(&w->slab, r.origin, r.dir, k, &b);
        vec3 point = vec_madd(b.point, across, -slip * early);
        rgb body = vec_mul(m->kd, s->ambient), highlight = vec_splat(0);
        for (int i = 0; i < s->light_count; i++)
            if (!optics_light_terms(&s->lights[i], m, point, b.inward, vec_neg(b.dir), 1, &body, &highlight))
                return ORACLE_AMBIGUOUS;
        sum = vec_add(sum, vec_mul(weight, vec_madd(highlight, body, 1 - m->t)));
        if (k < depth - 1 && !tir)
            sum = vec_add(sum, vec_scale(vec_mul(weight, s->image.background), m->t));
        weight = vec_mul(weight, next);
        early += optics_spawn_offset(size, b.point) * tan_theta;
    }
    *out = sum;
    return ORACLE_EXACT;
}

/* The exact series, ambiguous when twice the tracer's slips (either way)
 * would move it by more than OPTICS_SENSITIVITY. */
static oracle_status lit_series(const scene_model *s, const window_setup *w, oracle_ray r, int tir, int depth, rgb *out)
{
    rgb early, late;
    if (unfolded_series(s, w, r, tir, depth, 0, out) != ORACLE_EXACT ||
        unfolded_series(s, w, r, tir, depth, 2, &early) != ORACLE_EXACT ||
        unfolded_series(s, w, r, tir, depth, -2, &late) != ORACLE_EXACT)
        return ORACLE_AMBIGUOUS;
    if (!optics_close(*out, early, OPTICS_SENSITIVITY) || !optics_close(*out, late, OPTICS_SENSITIVITY))
        return ORACLE_AMBIGUOUS;
    return ORACLE_EXACT;
}

/* The closed forms of the file comment. */
static rgb closed_series(const scene_model *s, const scene_material *m, int tir, int depth)
{
    rgb local = vec_scale(vec_mul(m->kd, s->ambient), 1 - m->t);
    if (tir)
        return vec_mul(optics_geometric_sum_rgb(vec_add(m->ks, vec_splat(m->t)), depth), local);
    rgb out = vec_mul(optics_geometric_sum_rgb(m->ks, depth), local);
    return vec_add(out, vec_scale(vec_mul(optics_geometric_sum_rgb(m->ks, depth - 1), s->image.background), m->t));
}

static oracle_status radiance(const oracle_view *v, double x, double y, rgb *out)
{
    const scene_model *s = v->scene;
    window_setup w;
    window_setup_of(s, &w);
    oracle_ray r = oracle_view_ray(v, x, y);
    double dz = vec_dot(w.slab.axis, r.dir);
    double sin_theta = vec_length(vec_sub(r.dir, vec_scale(w.slab.axis, dz)));
    double critical = optics_critical_sin(w.glass->ior, 1);
    if (critical < 1 && fabs(sin_theta - critical) <= OPTICS_MARGIN * critical)
        return ORACLE_AMBIGUOUS;
    int tir = sin_theta > critical;
    if (s->light_count == 0) {
        *out = closed_series(s, w.glass, tir, v->max_depth);
        return ORACLE_EXACT;
    }
    return lit_series(s, &w, r, tir, v->max_depth, out);
}

const oracle_family oracle_snell_window = {
    "snell_window", "total internal reflection past the critical angle: Snell's window, a series of TIR", 0,
    accepts, radiance, oracle_tolerance_exact,
};
