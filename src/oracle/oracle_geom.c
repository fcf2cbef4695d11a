/*
 * oracle_geom.c - see oracle_geom.h.
 *
 * With sx = 2x/W - 1 and sy = 1 - 2y/H, the screen point of a perspective
 * camera at distance 1 is forward + a*right + b*up with a = sx tan(fov/2),
 * b = sy tan(fov/2) H/W; its length is sqrt(1 + a^2 + b^2) because the frame
 * is orthonormal, so the unit direction is that point over that length.
 * An orthographic camera moves the origin by (sx*width/2) right and
 * (sy*width/2 * H/W) up and keeps forward.
 *
 * up is any non-zero finite vector ([LANG-VALID-2]): 1e200 long, v.v is
 * +Inf and v/sqrt(v.v) is 0 (attack 9, finding 5).  oracle_tame scales a
 * vector by its largest component first; within 2^+-511 it returns v
 * itself, so every frame the old unit could form keeps its bits.
 */
#include <math.h>
#include "oracle/oracle_geom.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

vec3 oracle_tame(vec3 v)
{
    double m = fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
    if (m >= 0x1p-511 && m < 0x1p511)
        return v;
    return vec_make(v.x / m, v.y / m, v.z / m);
}

static vec3 unit(vec3 v)
{
    v = oracle_tame(v);
    double len = sqrt(vec_dot(v, v));
    return vec_make(v.x / len, v.y / len, v.z / len);
}

void oracle_camera_frame(const scene_camera *c, vec3 *forward, vec3 *right, vec3 *up)
{
    *forward = unit(vec_sub(c->look_at, c->eye));
    vec3 u = oracle_tame(c->up);
    *up = unit(vec_sub(u, vec_scale(*forward, vec_dot(u, *forward))));
    *right = vec_cross(*forward, *up);
}

oracle_ray oracle_view_ray(const oracle_view *v, double x, double y)
{
    const scene_camera *c = &v->scene->camera;
    vec3 f, r, u;
    oracle_camera_frame(c, &f, &r, &u);
    double sx = 2 * x / v->width - 1, sy = 1 - 2 * y / v->height, aspect = (double)v->height / v->width;
    oracle_ray ray;
    if (c->kind == CAMERA_ORTHOGRAPHIC) {
        double half = c->width / 2;
        ray.origin = vec_add(c->eye, vec_add(vec_scale(r, sx * half), vec_scale(u, sy * half * aspect)));
        ray.dir = f;
    } else {
        double half = tan(c->fov * M_PI / 360);
        double a = sx * half, b = sy * half * aspect, len = sqrt(1 + a * a + b * b);
        ray.origin = c->eye;
        ray.dir = vec_scale(vec_add(f, vec_add(vec_scale(r, a), vec_scale(u, b))), 1 / len);
    }
    return ray;
}
