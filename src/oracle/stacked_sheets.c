/*
 * stacked_sheets.c - family `stacked_sheets`: parallel transparent sheets
 * (planes and disks) over an opaque floor (spec/analytic.md (section `stacked_sheets`),
 * [ORACLE-STACKED-SHEETS-1], [ORACLE-STACKED-SHEETS-2]).
 *
 * Every surface is parallel, so each is a height h along the common normal
 * `up` (toward the eye).  A view ray going down crosses the surface of
 * height h at s = (h_eye - h)/(-D.up); a sheet lets through t and keeps
 * (1 - t) of its body (slide 37; sheets pass rays straight on), so the
 * surfaces k = 1, 2, ... the ray meets from the top down give
 *   C = sum_k (prod_{i<k} t_i) (1 - t_k) B_k,   k up to min(floor, max_depth)
 * with the floor (t = 0) closing the sum.  Each body
 *   B_k = Kd_k (Ia + sum_lights I (N.L) S_k),  N = up
 * has S_k the product of t_i over the surfaces the path to the light
 * crosses: the heights between P and the light, each crossed at
 * P + L (h_i - h_k)/(L.up), counted when a plane or inside a disk.
 *
 * Assumptions: only planes and disks, untransformed, all parallel; the
 * lowest a plane with t = 0 (the floor); distinct heights; Ks = 0
 * everywhere; point lights off every surface's height, distant lights not
 * along the sheets; an orthographic camera looking straight down, or a
 * perspective eye above every surface; at most STACK_MAX surfaces; any
 * max_depth.  Ambiguous: a sample or a shadow path within
 * ORACLE_EDGE_MARGIN radii of a disk's rim; the horizon.
 */
#include <math.h>
#include "oracle/oracle.h"
#include "oracle/oracle_geom.h"
#include "oracle/oracle_util.h"

#define FAMILY "stacked_sheets"
#define STACK_MAX 32

typedef struct stack {
    const scene_model *scene;
    vec3 up;                  /* unit, toward the eye */
    double height[STACK_MAX]; /* of each prim, measured from the eye (all < 0) */
    int order[STACK_MAX];     /* prim indices from the top down; order[count-1] the floor */
    int count;
} stack;

static vec3 prim_point(const scene_prim *p)
{
    return p->kind == PRIM_PLANE ? p->u.plane.point : p->u.disk.center;
}

static vec3 prim_normal(const scene_prim *p)
{
    return p->kind == PRIM_PLANE ? p->u.plane.normal : p->u.disk.normal;
}

/* Heights from the eye along up, and the order from the top down
 * (insertion sort: a few surfaces). */
static void stack_build(const scene_model *s, stack *st)
{
    st->scene = s;
    st->count = s->prim_count;
    vec3 n = prim_normal(&s->prims[0]);
    st->up = vec_dot(n, vec_sub(s->camera.eye, prim_point(&s->prims[0]))) < 0 ? vec_neg(n) : n;
    for (int i = 0; i < st->count; i++) {
        st->height[i] = vec_dot(st->up, vec_sub(prim_point(&s->prims[i]), s->camera.eye));
        int j = i;
        for (; j > 0 && st->height[st->order[j - 1]] < st->height[i]; j--)
            st->order[j] = st->order[j - 1];
        st->order[j] = i;
    }
}

static int accept_shapes(const scene_model *s, char *why, size_t n)
{
    if (s->prim_count < 2 || s->prim_count > STACK_MAX)
        return oracle_refuse(why, n, FAMILY ": the scene must have 2 to %d surfaces (sheets and a floor)", STACK_MAX);
    vec3 n0 = prim_normal(&s->prims[0]);
    for (int i = 0; i < s->prim_count; i++) {
        const scene_prim *p = &s->prims[i];
        if (p->kind != PRIM_PLANE && p->kind != PRIM_DISK)
            return oracle_refuse(why, n, FAMILY ": primitive %d is not a plane or a disk", i + 1);
        if (!(fabs(vec_dot(prim_normal(p), n0)) >= 1 - 1e-12))
            return oracle_refuse(why, n, FAMILY ": sheet %d is not parallel to the others", i + 1);
        if (vec_max_component(oracle_material(s, i)->ks) != 0)
            return oracle_refuse(why, n, FAMILY ": primitive %d has Ks > 0 (mirror rays)", i + 1);
    }
    return oracle_accept_untransformed(s, FAMILY, why, n);
}

/* The floor is the lowest surface: an opaque plane; heights distinct. */
static int accept_heights(const stack *st, char *why, size_t n)
{
    const scene_model *s = st->scene;
    double margin = ORACLE_EDGE_MARGIN * oracle_scene_scale(s);
    int floor = st->order[st->count - 1];
    if (s->prims[floor].kind != PRIM_PLANE || oracle_material(s, floor)->t != 0)
        return oracle_refuse(why, n, FAMILY ": the lowest surface must be an opaque plane (t = 0)");
    if (!(st->height[st->order[0]] < -margin))
        return oracle_refuse(why, n, FAMILY ": the eye must be above every sheet");
    for (int k = 1; k < st->count; k++)
        if (!(st->height[st->order[k - 1]] - st->height[st->order[k]] > margin))
            return oracle_refuse(why, n, FAMILY ": primitives %d and %d lie at the same height", st->order[k - 1] + 1,
                                 st->order[k] + 1);
    return 1;
}

static int accept_view(const stack *st, char *why, size_t n)
{
    const scene_camera *c = &st->scene->camera;
    vec3 f, right, up;
    oracle_camera_frame(c, &f, &right, &up);
    if (c->kind == CAMERA_ORTHOGRAPHIC && !(vec_dot(f, st->up) <= -1 + 1e-12))
        return oracle_refuse(why, n, FAMILY ": an orthographic camera must look straight down at the sheets");
    return 1;
}

static int accept_lights(const stack *st, char *why, size_t n)
{
    const scene_model *s = st->scene;
    double margin = ORACLE_EDGE_MARGIN * oracle_scene_scale(s);
    for (int i = 0; i < s->light_count; i++) {
        const scene_light *l = &s->lights[i];
        if (l->kind == LIGHT_DISTANT && !(fabs(vec_dot(l->direction, st->up)) > ORACLE_COS_MARGIN))
            return oracle_refuse(why, n, FAMILY ": distant light %d runs along the sheets", i + 1);
        for (int k = 0; l->kind == LIGHT_POINT && k < st->count; k++)
            if (fabs(vec_dot(st->up, vec_sub(l->position, s->camera.eye)) - st->height[k]) <= margin)
                return oracle_refuse(why, n, FAMILY ": point light %d lies in the plane of primitive %d", i + 1, k + 1);
    }
    return 1;
}

static int accepts(const oracle_view *v, char *why, size_t n)
{
    stack st;
    if (!accept_shapes(v->scene, why, n) || !oracle_accept_lights(v->scene, FAMILY, why, n))
        return 0;
    stack_build(v->scene, &st);
    return accept_heights(&st, why, n) && accept_view(&st, why, n) && accept_lights(&st, why, n);
}

/* Whether point x, at the height of prim i, lies on it: 1, 0, or -1 within
 * ORACLE_EDGE_MARGIN radii of a disk's rim. */
static int covers(const stack *st, int i, vec3 x)
{
    const scene_prim *p = &st->scene->prims[i];
    if (p->kind == PRIM_PLANE)
        return 1;
    vec3 w = vec_sub(x, p->u.disk.center);
    double rho = vec_length(vec_sub(w, vec_scale(st->up, vec_dot(w, st->up)))), r = p->u.disk.radius;
    if (fabs(rho - r) <= ORACLE_EDGE_MARGIN * r)
        return -1;
    return rho < r;
}

typedef struct shadow_ctx {
    const stack *st;
    int self;                 /* the prim the point lies on */
} shadow_ctx;

/* S: the product of t over the surfaces between p and the light. */
static double transmission(const void *ctx, vec3 p, const oracle_light_at *la, int *ambiguous)
{
    const shadow_ctx *sc = ctx;
    const stack *st = sc->st;
    double rise = vec_dot(la->l, st->up), through = 1, top = HUGE_VAL;
    if (la->light->kind == LIGHT_POINT)
        top = vec_dot(st->up, vec_sub(la->light->position, st->scene->camera.eye));
    for (int i = 0; i < st->count; i++) {
        double climb = st->height[i] - st->height[sc->self];
        if (i == sc->self || !(climb > 0) || !(st->height[i] < top))
            continue;
        int on = covers(st, i, vec_add(p, vec_scale(la->l, climb / rise)));
        if (on < 0)
            *ambiguous = 1;
        if (on > 0)
            through *= oracle_material(st->scene, i)->t;
    }
    return through;
}

/* (1 - t) B of prim i at x, seen along d. */
static oracle_status sheet_local(const stack *st, int i, vec3 x, vec3 d, rgb *out)
{
    shadow_ctx sc = {st, i};
    oracle_shading sh;
    const scene_material *m = oracle_material(st->scene, i);
    if (oracle_shade_direct(st->scene, m, x, st->up, vec_neg(d), transmission, &sc, &sh) != ORACLE_EXACT)
        return ORACLE_AMBIGUOUS;
    *out = oracle_shade_local(m, &sh);
    return ORACLE_EXACT;
}

/* The sum from the top down, weight = product of the t passed so far; the
 * walk stops at an opaque surface or at max_depth. */
static oracle_status walk(const oracle_view *v, const stack *st, oracle_ray r, double fall, rgb *out)
{
    double weight = 1, start = vec_dot(st->up, vec_sub(r.origin, v->scene->camera.eye));
    int depth = 1;
    *out = vec_splat(0);
    for (int k = 0; k < st->count; k++) {
        int i = st->order[k];
        vec3 x = vec_add(r.origin, vec_scale(r.dir, (start - st->height[i]) / fall));
        int on = covers(st, i, x);
        rgb local;
        if (on < 0 || (on && sheet_local(st, i, x, r.dir, &local) != ORACLE_EXACT))
            return ORACLE_AMBIGUOUS;
        if (!on)
            continue;
        *out = vec_add(*out, vec_scale(local, weight));
        weight *= oracle_material(v->scene, i)->t;
        if (weight == 0 || depth++ == v->max_depth)
            break;
    }
    return ORACLE_EXACT;
}

static oracle_status radiance(const oracle_view *v, double x, double y, rgb *out)
{
    stack st;
    stack_build(v->scene, &st);
    oracle_ray r = oracle_view_ray(v, x, y);
    double fall = -vec_dot(r.dir, st.up);
    if (fabs(fall) <= ORACLE_COS_MARGIN)
        return ORACLE_AMBIGUOUS;
    if (fall < 0) {
        *out = v->scene->image.background;
        return ORACLE_EXACT;
    }
    return walk(v, &st, r, fall, out);
}

const oracle_family oracle_stacked_sheets = {
    "stacked_sheets", "parallel transparent sheets over a floor: sum of (prod t) (1 - t_k) B_k (slides 37, 47)", 0,
    accepts, radiance, oracle_tolerance_exact,
};
