/*
 * lightsample.c - see lightsample.h.
 */
#include <math.h>
#include "render/lightsample.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

light_grid light_grid_for(int samples)
{
    light_grid g;
    int rows = (int)floor(sqrt((double)samples));
    while (rows > 1 && samples % rows != 0)
        rows--;
    g.rows = rows < 1 ? 1 : rows;
    g.cols = samples / g.rows;
    return g;
}

void light_cell_point(light_grid g, int index, double u1, double u2, double *s, double *t)
{
    int row = index / g.cols, col = index % g.cols;
    *s = (col + u1) / g.cols;
    *t = (row + u2) / g.rows;
}

void light_concentric(double s, double t, double *x, double *y)
{
    double a = 2 * s - 1, b = 2 * t - 1, r, phi;
    if (a == 0 && b == 0) {
        *x = *y = 0;
        return;
    }
    if (fabs(a) > fabs(b)) {
        r = a;
        phi = (M_PI / 4) * (b / a);
    } else {
        r = b;
        phi = M_PI / 2 - (M_PI / 4) * (a / b);
    }
    *x = r * cos(phi);
    *y = r * sin(phi);
}

void light_frame(vec3 n, vec3 *t1, vec3 *t2)
{
    real sign = copysign((real)1, n.z);
    real a = -1 / (sign + n.z);
    real b = n.x * n.y * a;
    *t1 = vec_make(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    *t2 = vec_make(b, sign + n.y * n.y * a, -n.y);
}

vec3 light_point(const scene_light *light, vec3 t1, vec3 t2, double s, double t)
{
    if (light->kind == LIGHT_RECTANGLE)
        return vec_add(light->position, vec_add(vec_scale(light->edge_u, s), vec_scale(light->edge_v, t)));
    double x, y;
    light_concentric(s, t, &x, &y);   /* the sample's place on the unit disk: model data, in double */
    return vec_add(light->position, vec_add(vec_scale(t1, x * light->radius), vec_scale(t2, y * light->radius)));
}
