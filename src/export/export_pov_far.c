/*
 * export_pov_far.c - see export_pov_far.h.
 *
 * Camera rays are enumerated exactly as refray makes them (camera_ray at
 * the centres of POV-Ray's pixels, which are refray's sub-pixel cells);
 * POV-Ray's own rays differ from them by rounding only.  Occlusion is
 * ignored throughout, so every reach is an upper bound of what a render
 * can meet.
 */
#include <math.h>
#include "export/export_pov_far.h"
#include "render/camera.h"
#include "render/intersect.h"

int pov_render_size(const scene_model *s, int *width, int *height)
{
    int k = s->image.samples;
    *width = s->image.width * k;
    *height = s->image.height * k;
    return k;
}

typedef struct extent {
    vec3 lo, hi;
    int any;
} extent;

static void extent_add(extent *e, vec3 p)
{
    e->lo = e->any ? vec_min(e->lo, p) : p;
    e->hi = e->any ? vec_max(e->hi, p) : p;
    e->any = 1;
}

/* The 8 corners of the local box lo..hi, taken to the world. */
static void extent_add_box(extent *e, const scene_prim *p, vec3 lo, vec3 hi)
{
    for (int i = 0; i < 8; i++) {
        vec3 c = vec_make(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
        extent_add(e, p->frame ? xform_point(&p->frame->to_world, c) : c);
    }
}

/* Planes are unbounded and left out. */
static void extent_add_prim(extent *e, const scene_prim *p)
{
    switch (p->kind) {
    case PRIM_SPHERE: {
        vec3 r = vec_splat(p->u.sphere.radius);
        extent_add_box(e, p, vec_sub(p->u.sphere.center, r), vec_add(p->u.sphere.center, r));
        break;
    }
    case PRIM_DISK: {
        vec3 r = vec_splat(p->u.disk.radius);
        extent_add_box(e, p, vec_sub(p->u.disk.center, r), vec_add(p->u.disk.center, r));
        break;
    }
    case PRIM_BOX:
        extent_add_box(e, p, p->u.box.lo, p->u.box.hi);
        break;
    case PRIM_TRIANGLE:
        for (int i = 0; i < 3; i++)
            extent_add(e, p->u.triangle.p[i]);
        break;
    case PRIM_CYLINDER:
    case PRIM_CONE: {
        vec3 a = p->kind == PRIM_CONE ? p->u.cone.from : p->u.cylinder.from;
        vec3 b = p->kind == PRIM_CONE ? p->u.cone.to : p->u.cylinder.to;
        vec3 r = vec_splat(p->kind == PRIM_CONE ? fmax(p->u.cone.radius[0], p->u.cone.radius[1])
                                                : p->u.cylinder.radius);
        extent_add_box(e, p, vec_sub(vec_min(a, b), r), vec_add(vec_max(a, b), r));
        break;
    }
    case PRIM_TORUS: {
        vec3 r = vec_splat(p->u.torus.major + p->u.torus.minor);
        extent_add_box(e, p, vec_sub(p->u.torus.center, r), vec_add(p->u.torus.center, r));
        break;
    }
    case PRIM_MESH:
        for (int i = 0; i < p->u.mesh.position_count; i++)
            extent_add(e, p->u.mesh.positions[i]);
        break;
    case PRIM_PLANE:
        break;
    }
}

pov_bounds pov_far_bounds(const scene_model *s)
{
    extent e = {vec_splat(0), vec_splat(0), 0};
    pov_bounds b;
    extent_add(&e, s->camera.eye);
    for (int i = 0; i < s->prim_count; i++)
        extent_add_prim(&e, &s->prims[i]);
    for (int i = 0; i < s->light_count; i++) {
        const scene_light *l = &s->lights[i];
        if (l->kind == LIGHT_DISTANT)
            continue;
        extent_add(&e, l->position);
        if (l->kind == LIGHT_RECTANGLE)
            extent_add(&e, vec_add(l->position, vec_add(l->edge_u, l->edge_v)));
    }
    b.centre = vec_scale(vec_add(e.lo, e.hi), 0.5);
    b.radius = fmax(1.0, 0.5 * vec_length(vec_sub(e.hi, e.lo)));
    return b;
}

/* How far a camera ray's origin can be from the eye: half the diagonal of
 * an orthographic view, 0 for a perspective camera. */
static double view_radius(const scene_model *s)
{
    if (s->camera.kind != CAMERA_ORTHOGRAPHIC)
        return 0;
    double half = 0.5 * s->camera.width;
    double aspect = (double)s->image.height / (double)s->image.width;
    return half * sqrt(1 + aspect * aspect);
}

double pov_far_spread(const scene_model *s, const pov_bounds *b)
{
    return vec_length(vec_sub(s->camera.eye, b->centre)) + view_radius(s) + b->radius;
}

double pov_far_distant_distance(const scene_model *s, const pov_bounds *b, int trace_levels)
{
    return POV_MAX_DISTANCE * (trace_levels + 1) + pov_far_spread(s, b);
}

/* Distance along (o, d) to plane p, or 0 when it does not meet it ahead. */
static double plane_distance(const scene_prim *p, vec3 o, vec3 d)
{
    double den = vec_dot(p->u.plane.normal, d);
    if (den == 0)
        return 0;
    double t = vec_dot(p->u.plane.normal, vec_sub(p->u.plane.point, o)) / den;
    return t > 0 && isfinite(t) ? t : 0;
}

/* Calls visit for the camera ray through the centre of every pixel of
 * POV-Ray's render. */
static void each_camera_ray(const scene_model *s, void (*visit)(void *ctx, const ray *r), void *ctx)
{
    int width, height, k = pov_render_size(s, &width, &height);
    real half = camera_half(&s->camera);
    for (int j = 0; j < height; j++)
        for (int i = 0; i < width; i++) {
            ray r = camera_ray(&s->camera, half, s->image.width, s->image.height, (i + 0.5) / k, (j + 0.5) / k);
            visit(ctx, &r);
        }
}

typedef struct camera_reach {
    const scene_prim *plane;
    double farthest;
} camera_reach;

static void reach_plane(void *ctx, const ray *r)
{
    camera_reach *c = ctx;
    c->farthest = fmax(c->farthest, plane_distance(c->plane, r->origin, r->dir));
}

double pov_far_camera_reach(const scene_model *s, const scene_prim *p)
{
    camera_reach c = {p, 0};
    each_camera_ray(s, reach_plane, &c);
    return c.farthest;
}

typedef struct shadow_reach {
    const scene_model *scene;
    const scene_prim *w;
    vec3 toward;         /* unit, toward the light */
    double farthest;
} shadow_reach;

/* From every point where the camera ray meets another plane. */
static void reach_from_planes(void *ctx, const ray *r)
{
    shadow_reach *c = ctx;
    for (int i = 0; i < c->scene->prim_count; i++) {
        const scene_prim *f = &c->scene->prims[i];
        if (f->kind != PRIM_PLANE || f == c->w)
            continue;
        double t = plane_distance(f, r->origin, r->dir);
        if (t > 0)
            c->farthest = fmax(c->farthest, plane_distance(c->w, ray_at(r, t), c->toward));
    }
}

/*
 * From a point p within the ball (c, R), the shadow ray p + u L meets the
 * plane N.x = N.q at u = N.(q - p) / N.L, ahead (u > 0) only where
 * N.(q - p) has the sign of N.L, so with sigma that sign
 *   u <= max(0, sigma N.(q - c) + R) / |N.L|
 * for the points of bounded primitives; points on planes are taken from
 * the camera rays one by one.
 */
double pov_far_shadow_reach(const scene_model *s, const pov_bounds *b, const scene_light *l, const scene_prim *w)
{
    shadow_reach c = {s, w, vec_neg(l->direction), 0};
    double cos_w = vec_dot(w->u.plane.normal, c.toward);
    if (cos_w == 0)
        return 0;
    double offset = vec_dot(w->u.plane.normal, vec_sub(w->u.plane.point, b->centre));
    c.farthest = fmax(0, (cos_w > 0 ? offset : -offset) + b->radius) / fabs(cos_w);
    each_camera_ray(s, reach_from_planes, &c);
    return c.farthest;
}

/* ---- Surfaces within a gap of a transparent solid ---- */

static int boxes_near(vec3 alo, vec3 ahi, vec3 blo, vec3 bhi, double gap)
{
    return alo.x - gap <= bhi.x && blo.x <= ahi.x + gap && alo.y - gap <= bhi.y && blo.y <= ahi.y + gap &&
           alo.z - gap <= bhi.z && blo.z <= ahi.z + gap;
}

/* Whether plane p comes within gap of the box lo..hi. */
static int plane_near_box(const scene_prim *p, vec3 lo, vec3 hi, double gap)
{
    vec3 n = p->u.plane.normal, mid = vec_scale(vec_add(lo, hi), 0.5), half = vec_scale(vec_sub(hi, lo), 0.5);
    double reach = fabs(n.x) * half.x + fabs(n.y) * half.y + fabs(n.z) * half.z;
    return fabs(vec_dot(n, vec_sub(mid, p->u.plane.point))) <= reach + gap;
}

/* Whether the surface of the ball (c, r) comes within gap of the box lo..hi:
 * the box reaches the shell between r - gap and r + gap. */
static int ball_near_box(vec3 c, double r, vec3 lo, vec3 hi, double gap)
{
    vec3 nearest = vec_max(lo, vec_min(hi, c));
    vec3 far = vec_make(fabs(lo.x - c.x) > fabs(hi.x - c.x) ? lo.x : hi.x,
                        fabs(lo.y - c.y) > fabs(hi.y - c.y) ? lo.y : hi.y,
                        fabs(lo.z - c.z) > fabs(hi.z - c.z) ? lo.z : hi.z);
    return vec_length(vec_sub(nearest, c)) <= r + gap && vec_length(vec_sub(far, c)) >= r - gap;
}

/* Whether the surface of sphere a (no transform: its own ball) comes within
 * gap of primitive b; for other shapes their bounding boxes stand in, so
 * the answer errs toward yes. */
static int ball_near(const scene_prim *a, const scene_prim *b, double gap)
{
    vec3 c = a->u.sphere.center, lo, hi;
    double r = a->u.sphere.radius;
    if (b->kind == PRIM_PLANE)
        return fabs(vec_dot(b->u.plane.normal, vec_sub(c, b->u.plane.point))) <= r + gap;
    if (b->kind == PRIM_SPHERE && !b->frame) {
        double d = vec_length(vec_sub(b->u.sphere.center, c));
        return d <= r + b->u.sphere.radius + gap && d >= fabs(r - b->u.sphere.radius) - gap;
    }
    return isect_prim_bounds(b, &lo, &hi) && ball_near_box(c, r, lo, hi, gap);
}

/* Whether plane a comes within gap of primitive b: another plane unless
 * they are parallel and farther apart, a bounded one by its box. */
static int plane_near(const scene_prim *a, const scene_prim *b, double gap)
{
    vec3 lo, hi, n = a->u.plane.normal;
    if (b->kind != PRIM_PLANE)
        return isect_prim_bounds(b, &lo, &hi) && plane_near_box(a, lo, hi, gap);
    vec3 cross = vec_cross(n, b->u.plane.normal);
    return vec_dot(cross, cross) > 0 || fabs(vec_dot(n, vec_sub(b->u.plane.point, a->u.plane.point))) <= gap;
}

int pov_far_near_solid(const scene_model *s, int solid, double gap, int opaque_only)
{
    const scene_prim *a = &s->prims[solid];
    vec3 alo, ahi, blo, bhi;
    int bounded = isect_prim_bounds(a, &alo, &ahi);
    if (!bounded && a->kind != PRIM_PLANE)
        return -1;
    for (int i = 0; i < s->prim_count; i++) {
        const scene_prim *b = &s->prims[i];
        int near;
        if (i == solid || (opaque_only && s->materials[b->material].t > 0))
            continue;
        if (!bounded)
            near = plane_near(a, b, gap);
        else if (a->kind == PRIM_SPHERE && !a->frame)
            near = ball_near(a, b, gap);
        else if (b->kind == PRIM_PLANE)
            near = plane_near_box(b, alo, ahi, gap);
        else
            near = isect_prim_bounds(b, &blo, &bhi) && boxes_near(alo, ahi, blo, bhi, gap);
        if (near)
            return i;
    }
    return -1;
}
