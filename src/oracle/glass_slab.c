/*
 * glass_slab.c - family `glass_slab` (spec/analytic.md (section `glass_slab`),
 * [ORACLE-SLAB]): a clear plane-parallel slab (an axis-aligned box of
 * thickness h, index n, transparency t, Ks 0) over a lit floor, seen by an
 * orthographic camera at incidence theta.  A ray entering the top face
 * bends to theta_t (sin theta_t = sin theta / n), leaves the bottom face
 * parallel to itself, displaced by
 *     d = h sin(theta - theta_t) / cos(theta_t)
 * perpendicular to its line, i.e. by d / cos(theta) along the floor, back
 * toward the foot of the normal; the floor point F is the undeviated
 * point moved by that much, never found by tracing.  The pixel is
 *     C = L_A + t (L_B + t floor(F)),     L = (1 - t) Kd (Ia + direct)
 * (the slab's own local colour at entry A and exit B, 0 with Kd 0), cut by
 * max_depth: C = L_A at depth 1, L_A + t L_B at depth 2.  With n < 1 and
 * sin theta > n the ray is totally reflected at A and sees the background:
 * C = L_A + t bg.
 * Lights: point lights above the slab or below it (not within its
 * thickness), distant lights; the shadow factor is S = t^2 for the floor
 * under a light above the slab (the segment crosses the bottom face and
 * leaves through another: accepts checks that every visible floor point's
 * segment enters through the bottom face), S = t at B (one face crossed on
 * the way out), S = 1 at A.  No distributed lights.
 * Ambiguous: incidence within 1e-9 of the critical angle (n < 1), and
 * samples whose colour moves by more than OPTICS_SENSITIVITY when B and F
 * slip along the floor by twice what the tracer's self-intersection
 * offsets make them slip (slab_colour).
 */
#include <math.h>
#include "oracle/optics_util.h"
#include "oracle/oracle_geom.h"
#include "oracle/oracle_util.h"

typedef struct slab_setup {
    const scene_prim *box, *floor;
    const scene_material *glass, *ground;
    vec3 up;                  /* the coordinate axis from the floor toward the slab */
    int axis;                 /* its index */
    double top, bottom, ground_z; /* heights z(X) = up . X */
} slab_setup;

/* Where one camera ray goes. */
typedef struct slab_path {
    double cos_theta, sin_theta;
    double cos_t, sin_t;      /* of theta_t, inside */
    vec3 across;              /* unit direction of the ray's part along the floor */
    int tir;                  /* totally reflected at A (n < sin theta) */
    int critical;             /* within the margin of the critical angle */
    vec3 a, b, f;             /* entry, exit, floor point */
    vec3 inside;              /* direction inside the slab */
} slab_path;

static int find_parts(const scene_model *s, slab_setup *g)
{
    if (s->prim_count != 2)
        return 0;
    int box = s->prims[0].kind == PRIM_BOX ? 0 : 1;
    g->box = &s->prims[box];
    g->floor = &s->prims[1 - box];
    if (g->box->kind != PRIM_BOX || g->box->frame || g->floor->kind != PRIM_PLANE)
        return 0;
    g->glass = &s->materials[g->box->material];
    g->ground = &s->materials[g->floor->material];
    return 1;
}

/* The floor normal must be a coordinate axis; up points toward the box. */
static int find_axis(slab_setup *g)
{
    vec3 n = g->floor->u.plane.normal;
    int axis = fabs(n.x) == 1 ? 0 : fabs(n.y) == 1 ? 1 : fabs(n.z) == 1 ? 2 : -1;
    if (axis < 0)
        return 0;
    g->axis = axis;
    double lo = vec_component(g->box->u.box.lo, axis), hi = vec_component(g->box->u.box.hi, axis);
    double ground = vec_component(g->floor->u.plane.point, axis);
    double sign = lo + hi > 2 * ground ? 1 : -1;
    g->up = vec_make(axis == 0 ? sign : 0, axis == 1 ? sign : 0, axis == 2 ? sign : 0);
    g->top = fmax(sign * lo, sign * hi);
    g->bottom = fmin(sign * lo, sign * hi);
    g->ground_z = sign * ground;
    return 1;
}

/* 1 when p lies inside the box's faces across the axis, a margin away from
 * their edges. */
static int within_faces(const slab_setup *g, vec3 p)
{
    for (int i = 0; i < 3; i++) {
        if (i == g->axis)
            continue;
        double lo = vec_component(g->box->u.box.lo, i), hi = vec_component(g->box->u.box.hi, i);
        double margin = OPTICS_MARGIN * (hi - lo), c = vec_component(p, i);
        if (!(c > lo + margin && c < hi - margin))
            return 0;
    }
    return 1;
}

static double height(const slab_setup *g, vec3 p)
{
    return vec_dot(g->up, p);
}

/* The path of one camera ray, by the closed form of the file comment. */
static void slab_trace(const slab_setup *g, oracle_ray r, slab_path *p)
{
    double n = g->glass->ior, h = g->top - g->bottom, z = height(g, r.origin);
    p->cos_theta = -vec_dot(r.dir, g->up);
    vec3 along = vec_madd(r.dir, g->up, p->cos_theta);
    p->sin_theta = vec_length(along);
    p->across = p->sin_theta > 0 ? vec_scale(along, 1 / p->sin_theta) : vec_splat(0);
    p->a = vec_madd(r.origin, r.dir, (z - g->top) / p->cos_theta);
    p->critical = n < 1 && fabs(p->sin_theta - n) <= OPTICS_MARGIN * n;
    p->tir = p->sin_theta > n;
    if (p->tir || p->critical)
        return;
    p->sin_t = p->sin_theta / n;
    p->cos_t = sqrt((1 - p->sin_t) * (1 + p->sin_t));
    p->inside = vec_madd(vec_scale(p->across, p->sin_t), g->up, -p->cos_t);
    p->b = vec_madd(p->a, p->inside, h / p->cos_t);
    double along_floor = optics_slab_shift(h, p->sin_theta, p->cos_theta, n) / p->cos_theta;
    vec3 undeviated = vec_madd(r.origin, r.dir, (z - g->ground_z) / p->cos_theta);
    p->f = vec_madd(undeviated, p->across, -along_floor);
}

static int light_above(const slab_setup *g, const scene_light *l)
{
    if (l->kind == LIGHT_DISTANT)
        return vec_dot(l->direction, g->up) < 0;
    return height(g, l->position) > g->top;
}

/* Where the segment from floor point f to a light above the slab crosses
 * the bottom face's plane. */
static vec3 bottom_crossing(const slab_setup *g, const scene_light *l, vec3 f)
{
    double rise = g->bottom - height(g, f);
    if (l->kind == LIGHT_DISTANT)
        return vec_madd(f, l->direction, -rise / -vec_dot(l->direction, g->up));
    vec3 to = vec_sub(l->position, f);
    return vec_madd(f, to, rise / vec_dot(to, g->up));
}

static int accepts_parts(const scene_model *s, slab_setup *g, char *why, size_t n)
{
    if (!find_parts(s, g))
        return oracle_refuse(why, n, "glass_slab: the scene must be one box (not rotated) and one plane");
    if (!find_axis(g))
        return oracle_refuse(why, n, "glass_slab: the floor's normal must be a coordinate axis");
    /* [NUM-GLASS-3] A slab standing on the floor (ground_z = bottom) is the
     * limit of a gap: the floor seen at the exit point B, lit through both
     * faces; the closed form is the same. */
    if (!(g->ground_z <= g->bottom))
        return oracle_refuse(why, n, "glass_slab: the floor must lie below the slab or touch it");
    if (vec_max_component(g->glass->ks) != 0 || !(g->glass->t > 0))
        return oracle_refuse(why, n, "glass_slab: the slab must have Ks = 0 and t > 0");
    if (vec_max_component(g->ground->ks) != 0 || g->ground->t != 0)
        return oracle_refuse(why, n, "glass_slab: the floor must have Ks = 0 and t = 0");
    if (s->camera.kind != CAMERA_ORTHOGRAPHIC)
        return oracle_refuse(why, n, "glass_slab: the camera must be orthographic");
    return 1;
}

static int accepts_lights(const scene_model *s, const slab_setup *g, char *why, size_t n)
{
    for (int i = 0; i < s->light_count; i++) {
        const scene_light *l = &s->lights[i];
        if (l->kind == LIGHT_RECTANGLE || l->kind == LIGHT_DISK)
            return oracle_refuse(why, n, "glass_slab: light %d is distributed (point or distant only)", i + 1);
        double z = l->kind == LIGHT_POINT ? height(g, l->position) : 0;
        if (l->kind == LIGHT_POINT && z >= g->bottom && z <= g->top)
            return oracle_refuse(why, n, "glass_slab: point light %d lies within the slab's thickness", i + 1);
    }
    return 1;
}

/* Every sample ray enters the top face, leaves the bottom face, and every
 * floor point it sees has its segment to each light above enter the
 * bottom face: all affine in the image point, so the corners decide. */
static int accepts_view(const oracle_view *v, const slab_setup *g, char *why, size_t n)
{
    const scene_model *s = v->scene;
    for (int c = 0; c < 4; c++) {
        oracle_ray r = optics_corner_ray(v, c);
        slab_path p;
        if (!(height(g, r.origin) > g->top) || !(-vec_dot(r.dir, g->up) > 0))
            return oracle_refuse(why, n, "glass_slab: the camera must be above the slab, looking down at it");
        slab_trace(g, r, &p);
        int through = !p.tir && !p.critical;
        if (!within_faces(g, p.a) || (through && !within_faces(g, p.b)))
            return oracle_refuse(why, n, "glass_slab: some camera ray does not cross the top and bottom faces "
                                         "(make the slab wider)");
        for (int i = 0; i < s->light_count && through; i++)
            if (light_above(g, &s->lights[i]) && !within_faces(g, bottom_crossing(g, &s->lights[i], p.f)))
                return oracle_refuse(why, n, "glass_slab: light %d reaches the visible floor past the slab's "
                                             "bottom face (make the slab wider)", i + 1);
    }
    return 1;
}

static int accepts(const oracle_view *v, char *why, size_t n)
{
    slab_setup g;
    return accepts_parts(v->scene, &g, why, n) && accepts_lights(v->scene, &g, why, n) &&
           accepts_view(v, &g, why, n);
}

/* Kd Ia plus every light's direct terms, each through its shadow factor;
 * for the floor the factor is t^2 under lights above the slab. */
static rgb body_at(const scene_model *s, const slab_setup *g, const scene_material *m, vec3 point, vec3 view,
                   double through, int floor)
{
    rgb body = vec_mul(m->kd, s->ambient), highlight = vec_splat(0);
    for (int i = 0; i < s->light_count; i++) {
        const scene_light *l = &s->lights[i];
        double pass = floor ? (light_above(g, l) ? through : 1) : through;
        (void)optics_light_terms(l, m, point, g->up, view, pass, &body, &highlight);
    }
    return body;
}

/*
 * The pixel of the file comment for path p; slip moves B and F along the
 * floor as the tracer's self-intersection offsets do, times slip: the ray
 * inside starts o_A under the top face and reaches the bottom o_A
 * tan(theta_t) early, the exit ray starts o_B under the bottom face and
 * reaches the floor o_B tan(theta) early (0 for the exact value).
 */
static rgb slab_colour(const oracle_view *v, const slab_setup *g, oracle_ray r, const slab_path *p, double slip)
{
    const scene_model *s = v->scene;
    double t = g->glass->t, size = fmax(optics_max_abs(g->box->u.box.lo), optics_max_abs(g->box->u.box.hi));
    rgb c = vec_scale(body_at(s, g, g->glass, p->a, vec_neg(r.dir), 1, 0), 1 - t);
    if (v->max_depth < 2)
        return c;
    if (p->tir)
        return vec_madd(c, s->image.background, t);
    double early_b = slip * optics_spawn_offset(size, p->a) * p->sin_t / p->cos_t;
    double early_f = early_b + slip * optics_spawn_offset(size, p->b) * p->sin_theta / p->cos_theta;
    vec3 b = vec_madd(p->b, p->across, -early_b), f = vec_madd(p->f, p->across, -early_f);
    rgb back = vec_scale(body_at(s, g, g->glass, b, vec_neg(p->inside), t, 0), 1 - t);
    if (v->max_depth >= 3)
        back = vec_madd(back, body_at(s, g, g->ground, f, vec_neg(r.dir), t * t, 1), t);
    return vec_madd(c, back, t);
}

/* Exact, or ambiguous at the critical angle (n < 1) and where twice the
 * tracer's slips, either way, would move the pixel by more than
 * OPTICS_SENSITIVITY. */
static oracle_status radiance(const oracle_view *v, double x, double y, rgb *out)
{
    slab_setup g;
    slab_path p;
    (void)find_parts(v->scene, &g);
    (void)find_axis(&g);
    oracle_ray r = oracle_view_ray(v, x, y);
    slab_trace(&g, r, &p);
    if (p.critical)
        return ORACLE_AMBIGUOUS;
    *out = slab_colour(v, &g, r, &p, 0);
    if (!optics_close(*out, slab_colour(v, &g, r, &p, 2), OPTICS_SENSITIVITY) ||
        !optics_close(*out, slab_colour(v, &g, r, &p, -2), OPTICS_SENSITIVITY))
        return ORACLE_AMBIGUOUS;
    return ORACLE_EXACT;
}

const oracle_family oracle_glass_slab = {
    "glass_slab", "a glass slab's lateral shift d = h sin(theta - theta_t) / cos(theta_t), weight t^2", 0,
    accepts, radiance, oracle_tolerance_exact,
};
