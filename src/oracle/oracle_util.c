/*
 * oracle_util.c - see oracle_util.h.
 */
#include <float.h>
#include <math.h>
#include "oracle/oracle_geom.h"
#include "oracle/oracle_surface.h"
#include "oracle/oracle_util.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

rgb oracle_falloff(rgb power, double d, double d0, scene_falloff falloff)
{
    double s = d + d0;
    if (falloff == FALLOFF_LINEAR)
        return vec_scale(power, 1 / s);
    if (falloff == FALLOFF_INVERSE_SQUARE)
        return vec_scale(power, 1 / (s * s));
    return power;
}

int oracle_light_toward(const scene_light *light, vec3 p, oracle_light_at *out)
{
    out->light = light;
    if (light->kind == LIGHT_DISTANT) {
        out->l = vec_neg(light->direction);
        out->dist = HUGE_VAL;
        out->intensity = light->power;
        return 1;
    }
    if (light->kind != LIGHT_POINT)
        return 0;
    vec3 to = vec_sub(light->position, p);
    out->dist = vec_length(to);
    if (!(out->dist > 0))
        return 0;
    out->l = vec_scale(to, 1 / out->dist);
    out->intensity = oracle_falloff(light->power, out->dist, light->d0, light->falloff);
    return 1;
}

double oracle_phong_lobe(double c, double n, int *ambiguous)
{
    if (n < 1 && fabs(c) <= ORACLE_COS_MARGIN) {
        *ambiguous = 1;
        return 0;
    }
    if (!(c > 0))
        return 0;
    return c >= 1 ? 1 : pow(c, n);
}

/*
 * One light's share, added to *out.  V.R is expanded rather than R formed:
 * with R = 2(N.L)N - L, V.R = 2(N.L)(N.V) - L.V (slides 24-28).
 */
static oracle_status add_light(const scene_material *m, vec3 p, vec3 n, vec3 v, const oracle_light_at *la,
                               oracle_shadow_fn shadow, const void *ctx, oracle_shading *out)
{
    double cos_nl = vec_dot(n, la->l);
    if (vec_max_component(la->intensity) == 0)
        return ORACLE_EXACT;
    if (fabs(cos_nl) <= ORACLE_COS_MARGIN)
        return ORACLE_AMBIGUOUS;
    if (cos_nl < 0)
        return ORACLE_EXACT;
    int ambiguous = 0;
    double through = shadow ? shadow(ctx, p, la, &ambiguous) : 1;
    double vr = 2 * cos_nl * vec_dot(n, v) - vec_dot(la->l, v);
    double lobe = vec_max_component(m->ks) > 0 ? oracle_phong_lobe(vr, m->n, &ambiguous) : 0;
    if (ambiguous)
        return ORACLE_AMBIGUOUS;
    rgb received = vec_scale(la->intensity, through);
    out->body = vec_add(out->body, vec_scale(vec_mul(m->kd, received), cos_nl));
    out->highlight = vec_add(out->highlight, vec_scale(vec_mul(m->ks, received), lobe));
    return ORACLE_EXACT;
}

oracle_status oracle_shade_direct(const scene_model *s, const scene_material *m, vec3 p, vec3 n, vec3 v,
                                  oracle_shadow_fn shadow, const void *ctx, oracle_shading *out)
{
    out->body = vec_mul(m->kd, s->ambient);
    out->highlight = vec_splat(0);
    for (int i = 0; i < s->light_count; i++) {
        oracle_light_at la;
        if (!oracle_light_toward(&s->lights[i], p, &la))
            return ORACLE_AMBIGUOUS;
        if (add_light(m, p, n, v, &la, shadow, ctx, out) != ORACLE_EXACT)
            return ORACLE_AMBIGUOUS;
    }
    return ORACLE_EXACT;
}

rgb oracle_shade_local(const scene_material *m, const oracle_shading *sh)
{
    return vec_add(vec_scale(sh->body, 1 - m->t), sh->highlight);
}

oracle_chord_kind oracle_line_sphere(vec3 o, vec3 d, vec3 c, double r, oracle_chord *out)
{
    vec3 w = vec_sub(c, o);
    out->along = vec_dot(w, d);
    out->q = vec_sub(w, vec_scale(d, out->along));
    out->off = vec_length(out->q);
    out->half = 0;
    if (fabs(out->off - r) <= ORACLE_EDGE_MARGIN * r)
        return ORACLE_CHORD_GRAZE;
    if (out->off > r)
        return ORACLE_CHORD_MISS;
    out->half = sqrt((r - out->off) * (r + out->off));
    return ORACLE_CHORD_HIT;
}

/* The crossing is o + (along -/+ half) d, and o + along d = c - q, so the
 * crossing minus the centre is -q -/+ half d, of length sqrt(off^2 + half^2) = r. */
vec3 oracle_chord_normal(const oracle_chord *ch, vec3 d, double r, int far)
{
    vec3 radial = vec_add(vec_neg(ch->q), vec_scale(d, far ? ch->half : -ch->half));
    return vec_scale(radial, 1 / r);
}

oracle_chord_kind oracle_view_sphere(const oracle_view *v, double x, double y, const scene_prim *sphere, vec3 *p,
                                     vec3 *n, vec3 *toward_viewer)
{
    double r = sphere->u.sphere.radius;
    oracle_ray ray = oracle_view_ray(v, x, y);
    oracle_chord ch;
    oracle_chord_kind kind = oracle_line_sphere(ray.origin, ray.dir, sphere->u.sphere.center, r, &ch);
    if (kind != ORACLE_CHORD_HIT)
        return kind;
    *n = oracle_chord_normal(&ch, ray.dir, r, 0);
    *p = vec_add(sphere->u.sphere.center, vec_scale(*n, r));
    *toward_viewer = vec_neg(ray.dir);
    return kind;
}

int oracle_view_plane(const oracle_view *v, double x, double y, const scene_prim *plane, vec3 *p, vec3 *n,
                      vec3 *toward_viewer)
{
    vec3 p0 = plane->u.plane.point, normal = plane->u.plane.normal;
    oracle_ray ray = oracle_view_ray(v, x, y);
    double s;
    if (!oracle_line_plane(ray.origin, ray.dir, p0, normal, &s))
        return -1;
    if (fabs(vec_dot(normal, vec_sub(p0, ray.origin))) <= ORACLE_EDGE_MARGIN * oracle_scene_scale(v->scene))
        return -1;
    if (!(s > 0))
        return 0;
    *p = vec_add(ray.origin, vec_scale(ray.dir, s));
    *n = vec_dot(normal, ray.dir) < 0 ? normal : vec_neg(normal);
    *toward_viewer = vec_neg(ray.dir);
    return 1;
}

oracle_status oracle_view_shade(const oracle_view *v, double x, double y, oracle_shading *sh, rgb *out, int *seen)
{
    const scene_model *s = v->scene;
    vec3 p, n, toward;
    int met;
    if (s->prims[0].kind == PRIM_SPHERE) {
        oracle_chord_kind kind = oracle_view_sphere(v, x, y, &s->prims[0], &p, &n, &toward);
        met = kind == ORACLE_CHORD_GRAZE ? -1 : kind == ORACLE_CHORD_HIT;
    } else {
        met = oracle_view_plane(v, x, y, &s->prims[0], &p, &n, &toward);
    }
    *seen = met > 0;
    if (met < 0)
        return ORACLE_AMBIGUOUS;
    if (met == 0) {
        *out = s->image.background;
        return ORACLE_EXACT;
    }
    if (oracle_shade_direct(s, oracle_material(s, 0), p, n, toward, NULL, NULL, sh) != ORACLE_EXACT)
        return ORACLE_AMBIGUOUS;
    return ORACLE_EXACT;
}

oracle_status oracle_view_lambert(const oracle_view *v, double x, double y, rgb *out)
{
    oracle_shading sh;
    int seen;
    oracle_status status = oracle_view_shade(v, x, y, &sh, out, &seen);
    if (status == ORACLE_EXACT && seen)
        *out = sh.body;
    return status;
}

oracle_status oracle_view_phong(const oracle_view *v, double x, double y, rgb *out)
{
    oracle_shading sh;
    int seen;
    oracle_status status = oracle_view_shade(v, x, y, &sh, out, &seen);
    if (status != ORACLE_EXACT || !seen)
        return status;
    *out = vec_add(sh.body, sh.highlight);
    if (v->max_depth > 1)
        *out = vec_add(*out, vec_mul(oracle_material(v->scene, 0)->ks, v->scene->image.background));
    return ORACLE_EXACT;
}

vec3 oracle_phong_sphere_peak(vec3 c, double r, vec3 l, vec3 v)
{
    return vec_add(c, vec_scale(vec_normalize(vec_add(l, v)), r));
}

double oracle_path_distance(vec3 p, const oracle_light_at *la, vec3 c)
{
    vec3 w = vec_sub(c, p);
    double s = vec_dot(w, la->l);
    if (s < 0)
        s = 0;
    if (s > la->dist)
        s = la->dist;
    return vec_length(vec_sub(w, vec_scale(la->l, s)));
}

int oracle_line_plane(vec3 o, vec3 d, vec3 p0, vec3 n, double *s)
{
    double dn = vec_dot(n, d);
    if (fabs(dn) <= ORACLE_COS_MARGIN * vec_length(n) * vec_length(d))
        return 0;
    *s = vec_dot(n, vec_sub(p0, o)) / dn;
    return 1;
}

/*
 * Inverse of oracle_view_ray.  Orthographic: p - eye = a*right + b*up +
 * depth*forward with a = sx*width/2, b = sy*width/2*H/W.  Perspective: the
 * ray through (sx, sy) has direction forward + sx*h*right + sy*h*(H/W)*up
 * with h = tan(fov/2), so sx = (p.right)/(p.forward)/h and likewise sy.
 */
int oracle_image_point(const oracle_view *v, vec3 p, double *x, double *y)
{
    const scene_camera *c = &v->scene->camera;
    vec3 f, r, u, w = vec_sub(p, c->eye);
    oracle_camera_frame(c, &f, &r, &u);
    double aspect = (double)v->height / v->width, a = vec_dot(w, r), b = vec_dot(w, u), half;
    if (c->kind == CAMERA_ORTHOGRAPHIC) {
        half = c->width / 2;
    } else {
        double depth = vec_dot(w, f);
        if (!(depth > 0))
            return 0;
        a /= depth;
        b /= depth;
        half = tan(c->fov * M_PI / 360);
    }
    *x = (a / half + 1) * v->width / 2;
    *y = (1 - b / (half * aspect)) * v->height / 2;
    return 1;
}

vec3 oracle_mirror_point(vec3 p0, vec3 n, vec3 eye, vec3 light)
{
    vec3 image = vec_sub(light, vec_scale(n, 2 * vec_dot(n, vec_sub(light, p0)) / vec_dot(n, n)));
    vec3 toward = vec_sub(image, eye);
    double s = vec_dot(n, vec_sub(p0, eye)) / vec_dot(n, toward);
    return vec_add(eye, vec_scale(toward, s));
}

vec3 oracle_mirror_point_ortho(vec3 p0, vec3 n, vec3 f, vec3 light)
{
    vec3 view = vec_neg(f);
    vec3 m = vec_sub(vec_scale(n, 2 * vec_dot(n, view) / vec_dot(n, n)), view);
    return vec_sub(light, vec_scale(m, vec_dot(n, vec_sub(light, p0)) / vec_dot(n, m)));
}

static double grow(double scale, vec3 p, double extra)
{
    return fmax(scale, fmax(fabs(p.x), fmax(fabs(p.y), fabs(p.z))) + extra);
}

/* What the view's rays reach (spec/verify.md, [ORACLE-VIEW-ROUNDING-1]):
 * the largest |coordinate| of a hit (*coord), the farthest and the nearest
 * distance from the eye to a hit (*far, *near), read from the world boxes
 * of the bounded primitives and from the planes, never from look_at.  An
 * eye inside the boxes' union sees its nearest hit no nearer than the
 * union's nearest face, as far as this bound goes; a plane contributes its
 * distance from the eye and its point nearest the origin. */
static void view_reach(const scene_model *s, double *coord, double *far, double *near)
{
    vec3 eye = s->camera.eye, lo = vec_splat(HUGE_VAL), hi = vec_splat(-HUGE_VAL);
    int bounded = 0;
    *coord = 0;
    *far = 0;
    *near = HUGE_VAL;
    for (int i = 0; i < s->prim_count; i++) {
        const scene_prim *p = &s->prims[i];
        vec3 plo, phi;
        if (p->kind == PRIM_PLANE) {
            vec3 n = vec_normalize(p->u.plane.normal);
            double off = vec_dot(n, p->u.plane.point), d = fabs(vec_dot(n, vec_sub(eye, p->u.plane.point)));
            *coord = grow(*coord, vec_scale(n, off), 0);
            *far = fmax(*far, d);
            *near = fmin(*near, d);
        } else if (scene_prim_world_box(p, &plo, &phi)) {
            lo = vec_min(lo, plo);
            hi = vec_max(hi, phi);
            bounded = 1;
        }
    }
    if (!bounded)
        return;
    *coord = grow(grow(*coord, lo, 0), hi, 0);
    for (int c = 0; c < 8; c++) {
        vec3 corner = vec_make(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z);
        *far = fmax(*far, vec_length(vec_sub(corner, eye)));
    }
    *near = fmin(*near, oracle_box_distance(eye, lo, hi));
}

/* 1 when some ray leaves a surface for another surface: a reflective or
 * transparent material and a depth that traces it. */
static int traces_onward(const scene_model *s)
{
    if (s->image.max_depth < 2)
        return 0;
    for (int i = 0; i < s->material_count; i++) {
        const scene_material *m = &s->materials[i];
        if (m->t > 0 || vec_max_component(m->ks) > 0)
            return 1;
    }
    return 0;
}

/* The shortest way a secondary ray travels to what it samples
 * ([ORACLE-VIEW-ROUNDING-3]): from the geometry to a point light (a lower
 * bound of the distance to each surface: a world box's nearest face is no
 * bound from inside the box, where a light may lie just off a sphere)
 * and, when rays go on to other surfaces, the size of the bounded
 * primitives' union.  A shadow ray to a distant light samples a
 * direction, which the offset does not turn.  HUGE_VAL when nothing is
 * sampled at a finite distance. */
static double spawn_reach(const scene_model *s)
{
    vec3 lo = vec_splat(HUGE_VAL), hi = vec_splat(-HUGE_VAL);
    double reach = HUGE_VAL;
    int bounded = 0;
    for (int i = 0; i < s->prim_count; i++) {
        const scene_prim *p = &s->prims[i];
        vec3 plo, phi;
        int box = p->kind != PRIM_PLANE && scene_prim_world_box(p, &plo, &phi);
        if (box) {
            lo = vec_min(lo, plo);
            hi = vec_max(hi, phi);
            bounded = 1;
        }
        for (int j = 0; j < s->light_count; j++)
            if (s->lights[j].kind == LIGHT_POINT)
                reach = fmin(reach, oracle_surface_distance(p, s->lights[j].position));
    }
    if (bounded && traces_onward(s))
        reach = fmin(reach, vec_length(vec_sub(hi, lo)));
    return reach;
}

/* The smallest radius of curvature a secondary ray can meet
 * ([ORACLE-VIEW-ROUNDING-4]); HUGE_VAL when no ray goes on to a surface or
 * every surface is flat. */
static double spawn_curvature_radius(const scene_model *s)
{
    double radius = HUGE_VAL;
    if (traces_onward(s))
        for (int i = 0; i < s->prim_count; i++)
            radius = fmin(radius, oracle_curvature_radius(&s->prims[i]));
    return radius;
}

/* [ORACLE-VIEW-ROUNDING-1] (spec/verify.md): the two codes round a ray's
 * origin and its hit differently, by a few units u = 2^-53 of the sizes
 * the hit is made of, D = |eye| + the hit's coordinates + its distance;
 * a hit moved sideways by delta changes a pixel by at most G delta
 * relative, G the largest relative slope of the picture, which for a
 * picture of world width S at the hit is a small multiple of 1/S.  Hence
 * the floor K u D / S; K is spec/verify.md's constant, 8 times the largest
 * ratio measured.  Orthographic: S is the width at every distance, so the
 * farthest hit and the largest coordinate bound D / S; perspective: D / S
 * falls with the hit's distance, so the nearest hit bounds it. */
double oracle_tolerance_exact(const oracle_view *v, int light_samples)
{
    const scene_camera *c = &v->scene->camera;
    double coord, far, near;
    view_reach(v->scene, &coord, &far, &near);
    double eye = vec_length(c->eye), span, d;
    if (c->kind == CAMERA_ORTHOGRAPHIC) {
        span = c->width;
        d = eye + coord + far;
    } else { /* at the nearest hit, whose coordinates are within eye + near */
        span = 2 * near * tan(c->fov * M_PI / 360);
        d = eye + fmin(coord, eye + near) + near;
    }
    double floor = ORACLE_VIEW_ROUNDING_K * DBL_EPSILON / 2 * d / span;
    (void)light_samples;
    if (!(span > 0 && span < HUGE_VAL))
        floor = 0;
    /* [ORACLE-VIEW-ROUNDING-3]: the render's secondary rays leave a hit
     * ORACLE_SPAWN_REL of its coordinates (at most coord) off it, which
     * moves what they sample, reach away, by that much. */
    floor += ORACLE_SPAWN_K * ORACLE_SPAWN_REL * coord / spawn_reach(v->scene);
    /* [ORACLE-VIEW-ROUNDING-4]: that offset slides a secondary hit on a
     * curved surface, turning its normal by offset / radius. */
    floor += ORACLE_SPAWN_CURVE_K * ORACLE_SPAWN_REL * coord / spawn_curvature_radius(v->scene);
    if (!(floor > ORACLE_EXACT_TOLERANCE))
        return ORACLE_EXACT_TOLERANCE;
    return floor < ORACLE_VIEW_ROUNDING_MAX ? floor : ORACLE_VIEW_ROUNDING_MAX;
}

double oracle_scene_scale(const scene_model *s)
{
    double scale = grow(1, s->camera.eye, 0);
    for (int i = 0; i < s->prim_count; i++) {
        const scene_prim *p = &s->prims[i];
        if (p->kind == PRIM_SPHERE)
            scale = grow(scale, p->u.sphere.center, p->u.sphere.radius);
        else if (p->kind == PRIM_PLANE)
            scale = grow(scale, p->u.plane.point, 0);
        else if (p->kind == PRIM_DISK)
            scale = grow(scale, p->u.disk.center, p->u.disk.radius);
    }
    for (int i = 0; i < s->light_count; i++)
        if (s->lights[i].kind == LIGHT_POINT)
            scale = grow(scale, s->lights[i].position, 0);
    return scale;
}

const scene_material *oracle_material(const scene_model *s, int prim)
{
    return &s->materials[s->prims[prim].material];
}

int oracle_accept_lights(const scene_model *s, const char *family, char *why, size_t n)
{
    for (int i = 0; i < s->light_count; i++) {
        scene_light_kind k = s->lights[i].kind;
        if (k != LIGHT_POINT && k != LIGHT_DISTANT)
            return oracle_refuse(why, n,
                                 "%s: light %d is distributed (only point and distant lights have an exact image here)",
                                 family, i + 1);
    }
    return 1;
}

int oracle_accept_untransformed(const scene_model *s, const char *family, char *why, size_t n)
{
    for (int i = 0; i < s->prim_count; i++)
        if (s->prims[i].frame)
            return oracle_refuse(why, n,
                                 "%s: primitive %d keeps a transform (an ellipsoid, a mirrored or turned shape)",
                                 family, i + 1);
    return 1;
}

int oracle_accept_matte(const scene_material *m, const char *family, const char *what, char *why, size_t n)
{
    if (vec_max_component(m->ks) != 0 || m->t != 0)
        return oracle_refuse(why, n, "%s: the %s must have Ks = 0 and t = 0", family, what);
    return 1;
}

int oracle_accept_lights_outside(const scene_model *s, vec3 c, double r, const char *family, char *why, size_t n)
{
    for (int i = 0; i < s->light_count; i++) {
        const scene_light *l = &s->lights[i];
        if (l->kind == LIGHT_POINT && !(vec_length(vec_sub(l->position, c)) > r * (1 + ORACLE_EDGE_MARGIN)))
            return oracle_refuse(why, n, "%s: point light %d is inside or on the sphere", family, i + 1);
    }
    return 1;
}

int oracle_accept_ortho_in_front(const scene_model *s, vec3 c, double r, const char *family, char *why, size_t n)
{
    vec3 f, right, up;
    if (s->camera.kind != CAMERA_ORTHOGRAPHIC)
        return oracle_refuse(why, n, "%s: the camera must be orthographic", family);
    oracle_camera_frame(&s->camera, &f, &right, &up);
    if (!(vec_dot(vec_sub(c, s->camera.eye), f) > r * (1 + ORACLE_EDGE_MARGIN)))
        return oracle_refuse(why, n, "%s: the sphere must lie wholly in front of the camera's image plane", family);
    return 1;
}

int oracle_accept_off_plane(const scene_model *s, const scene_prim *plane, const char *family, char *why, size_t n)
{
    double margin = ORACLE_EDGE_MARGIN * oracle_scene_scale(s);
    vec3 p0 = plane->u.plane.point, normal = plane->u.plane.normal;
    for (int i = 0; i < s->light_count; i++)
        if (s->lights[i].kind == LIGHT_POINT && fabs(vec_dot(normal, vec_sub(s->lights[i].position, p0))) <= margin)
            return oracle_refuse(why, n, "%s: point light %d lies in the plane", family, i + 1);
    if (fabs(vec_dot(normal, vec_sub(s->camera.eye, p0))) <= margin)
        return oracle_refuse(why, n, "%s: the eye lies in the plane", family);
    return 1;
}

/* The sphere is met first when its entry lies ahead and before the plane;
 * an outline graze matters only where the sphere would be met first. */
oracle_sees oracle_view_sphere_plane(const oracle_view *v, double x, double y, const scene_prim *sphere,
                                     const scene_prim *plane, oracle_pair_view *out)
{
    vec3 p0 = plane->u.plane.point, normal = plane->u.plane.normal;
    out->ray = oracle_view_ray(v, x, y);
    oracle_chord_kind kind = oracle_line_sphere(out->ray.origin, out->ray.dir, sphere->u.sphere.center,
                                                sphere->u.sphere.radius, &out->chord);
    out->plane_s = HUGE_VAL;
    out->plane_ok = oracle_line_plane(out->ray.origin, out->ray.dir, p0, normal, &out->plane_s);
    int plane_ahead = out->plane_ok && out->plane_s > 0;
    double entry = out->chord.along - out->chord.half;
    if (kind != ORACLE_CHORD_MISS && entry > 0 && (!plane_ahead || entry < out->plane_s))
        return kind == ORACLE_CHORD_HIT ? ORACLE_SEES_SPHERE : ORACLE_SEES_AMBIGUOUS;
    if (!out->plane_ok)
        return ORACLE_SEES_AMBIGUOUS;
    if (fabs(vec_dot(normal, vec_sub(p0, out->ray.origin))) <= ORACLE_EDGE_MARGIN * oracle_scene_scale(v->scene))
        return ORACLE_SEES_AMBIGUOUS;
    return plane_ahead ? ORACLE_SEES_PLANE : ORACLE_SEES_NOTHING;
}

void oracle_plane_hit(const scene_prim *plane, const oracle_ray *ray, double s, vec3 *p, vec3 *n)
{
    vec3 normal = plane->u.plane.normal;
    *p = vec_add(ray->origin, vec_scale(ray->dir, s));
    *n = vec_dot(normal, ray->dir) < 0 ? normal : vec_neg(normal);
}

static int find_pair(const scene_model *s, int *sphere, int *plane)
{
    *sphere = *plane = -1;
    for (int i = 0; i < s->prim_count; i++) {
        if (s->prims[i].kind == PRIM_SPHERE && *sphere < 0)
            *sphere = i;
        else if (s->prims[i].kind == PRIM_PLANE && *plane < 0)
            *plane = i;
    }
    return s->prim_count == 2 && *sphere >= 0 && *plane >= 0;
}

/* The signed height of p over the plane, positive on the sphere's side. */
static double height(const scene_prim *plane, double side, vec3 p)
{
    return side * vec_dot(plane->u.plane.normal, vec_sub(p, plane->u.plane.point));
}

static int pair_lights(const scene_model *s, const scene_prim *plane, double side, const char *family, char *why,
                       size_t n)
{
    for (int i = 0; i < s->light_count; i++) {
        const scene_light *l = &s->lights[i];
        if (l->kind == LIGHT_DISTANT && !(-side * vec_dot(plane->u.plane.normal, l->direction) > ORACLE_COS_MARGIN))
            return oracle_refuse(why, n, "%s: distant light %d does not shine from the sphere's side of the plane",
                                 family, i + 1);
        if (l->kind == LIGHT_POINT && !(height(plane, side, l->position) > ORACLE_EDGE_MARGIN * oracle_scene_scale(s)))
            return oracle_refuse(why, n, "%s: point light %d is not on the sphere's side of the plane", family, i + 1);
    }
    return 1;
}

static int pair_eye(const scene_model *s, const scene_prim *sphere, const scene_prim *plane, double side,
                    const char *family, char *why, size_t n)
{
    vec3 c = sphere->u.sphere.center, f, right, up;
    double r = sphere->u.sphere.radius, clear = r * (1 + ORACLE_EDGE_MARGIN);
    oracle_camera_frame(&s->camera, &f, &right, &up);
    if (!(height(plane, side, s->camera.eye) > ORACLE_EDGE_MARGIN * oracle_scene_scale(s)))
        return oracle_refuse(why, n, "%s: the eye is not on the sphere's side of the plane", family);
    if (s->camera.kind == CAMERA_ORTHOGRAPHIC && !(fabs(vec_dot(vec_sub(c, s->camera.eye), f)) > clear))
        return oracle_refuse(why, n, "%s: the camera's image plane cuts the sphere", family);
    if (s->camera.kind == CAMERA_PERSPECTIVE && !(vec_length(vec_sub(c, s->camera.eye)) > clear))
        return oracle_refuse(why, n, "%s: the eye is inside the sphere", family);
    return 1;
}

int oracle_accept_sphere_plane(const scene_model *s, const char *family, int *sphere, int *plane, char *why,
                               size_t n)
{
    if (!find_pair(s, sphere, plane))
        return oracle_refuse(why, n, "%s: the scene must be one sphere and one plane", family);
    if (!oracle_accept_untransformed(s, family, why, n) || !oracle_accept_lights(s, family, why, n))
        return 0;
    const scene_prim *sp = &s->prims[*sphere], *pl = &s->prims[*plane];
    double above = vec_dot(pl->u.plane.normal, vec_sub(sp->u.sphere.center, pl->u.plane.point));
    double side = above < 0 ? -1 : 1;
    if (!(fabs(above) > sp->u.sphere.radius * (1 + ORACLE_EDGE_MARGIN)))
        return oracle_refuse(why, n, "%s: the sphere touches or cuts the plane", family);
    return pair_lights(s, pl, side, family, why, n) &&
           oracle_accept_lights_outside(s, sp->u.sphere.center, sp->u.sphere.radius, family, why, n) &&
           pair_eye(s, sp, pl, side, family, why, n);
}
