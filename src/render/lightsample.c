/*
 * lightsample.c - see lightsample.h.
 */
#include <math.h>
#include "render/lightsample.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/*
 * Contracts (make prove, spec/proofs.md).  samples >= 1: [LANG-DIST-1]
 * (1 .. --max-light-samples, distributed_shape) or the --light-samples of
 * cli_check_sizes; index in 0 .. samples - 1 (add_distributed); u1, u2 in
 * [0, 1) (sampler_uniform, base/sampler.h).
 */
/*@ requires 1 <= samples <= 1000000000;
    assigns \nothing;
    ensures \result.rows >= 1 && EXACT(\result.cols >= 1);
    ensures EXACT(\result.rows * \result.cols == samples); */
light_grid light_grid_for(int samples)
{
    light_grid g;
    int rows = (int)floor(sqrt((double)samples));
    /*@ loop invariant EXACT(rows <= \at(rows, LoopEntry));
        loop assigns rows;
        loop variant rows; */
    while (rows > 1 && samples % rows != 0)
        rows--;
    g.rows = rows < 1 ? 1 : rows;
    g.cols = samples / g.rows;
    return g;
}

/*@ requires 1 <= g.rows <= 1000000000 && 1 <= g.cols <= 1000000000;
    requires 0 <= index <= 1000000000 && EXACT(index / g.cols < g.rows);   // index < rows * cols = samples
    requires \is_finite(u1) && 0 <= u1 < 1 && \is_finite(u2) && 0 <= u2 < 1;
    requires \valid(s) && \valid(t) && \separated(s, t);
    assigns *s, *t;
    ensures \is_finite(*s) && \is_finite(*t) && *s >= 0 && *t >= 0;
    ensures EXACT(*s < 1 && *t < 1);
    ensures EXACT(*s == (index % g.cols + u1) / g.cols && *t == (index / g.cols + u2) / g.rows); */
void light_cell_point(light_grid g, int index, double u1, double u2, double *s, double *t)
{
    int row = index / g.cols, col = index % g.cols;
    *s = (col + u1) / g.cols;
    *t = (row + u2) / g.rows;
}

/*@ requires \is_finite(s) && 0 <= s <= 1 && \is_finite(t) && 0 <= t <= 1;  // light_cell_point
    requires \valid(x) && \valid(y) && \separated(x, y);
    assigns *x, *y;
    ensures \is_finite(*x) && \is_finite(*y) && DOUBLES(-1 <= *x <= 1 && -1 <= *y <= 1);
    ensures EXACT(s == 0.5 && t == 0.5 ==> *x == 0 && *y == 0); */
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

/*
 * The frame of Duff et al., "Building an Orthonormal Basis, Revisited"
 * (JCGT 6(1), 2017).  n is a disk or rectangle light's normal, loader_unit's
 * vec_normalize result (disk_light, check_rectangle: [LANG-VALID-2]): finite,
 * every component within 4 (vec_normalize's bound), of unit length within
 * 2^-20 (vunit).  |sign + n.z| = 1 + |n.z| >= 1, so |a| <= 1.  For
 * e = |n|^2 - 1 the frame is off by e alone (exact arithmetic):
 * t1.n = -n.x e / (1 + |n.z|), t2.n = -sign n.y e / (1 + |n.z|),
 * |t1|^2 - 1 = n.x^2 e / (1 + |n.z|)^2, |t2|^2 - 1 = n.y^2 e / (1 + |n.z|)^2,
 * t1.t2 = sign n.x n.y e / (1 + |n.z|)^2: exactly orthonormal for e = 0,
 * within 2^-19 for vunit's |e| <= 2^-20 (n.x^2, n.y^2 <= |n|^2 <= 2).
 * The contract states what Eva shows (finite, each component within 17);
 * the frame identities are not clauses: WP's provers do not close them
 * (spec/proofs.md, "light_frame"); tests/check_lightsample.c checks them.
 */
/*@ requires vfinite(n) && DOUBLES(vbounded(n, 4));   // loader_unit (vec_normalize's bound): [LANG-VALID-2]
    requires \valid(t1) && \valid(t2) && \separated(t1, t2);
    assigns *t1 \from n;
    assigns *t2 \from n;
    ensures DOUBLES(vfinite(*t1) && vfinite(*t2));
    ensures DOUBLES(vbounded(*t1, 17) && vbounded(*t2, 17)); */
void light_frame(vec3 n, vec3 *t1, vec3 *t2)
{
    real sign = copysign((real)1, n.z);
    /*@ assert EXACT(sign * sign == 1 && sign * n.z == \abs(n.z)); */
    /* -1 / (sign + n.z), the same double: sign + n.z is sign (1 + |n.z|),
     * rounded alike; a divisor of at least 1 to a box analysis (Eva). */
    real a = -sign / (1 + fabs(n.z));
    /*@ assert EXACT(a * (1 + \abs(n.z)) == -sign); */
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
