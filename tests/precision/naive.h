/*
 * naive.h - the textbook methods refray does NOT use, kept to show where
 * they fail: the "before" of every robust method in spec/numerics.md.  Used
 * by tests/test_stability.c (which asserts that each fails on its stress
 * case) and by tests/precision/precision.c (which measures by how much).
 * Never linked into the renderer.
 */
#ifndef REFRAY_NAIVE_H
#define REFRAY_NAIVE_H

#include "render/ray.h"
#include "scene/scene.h"

/* Ray/sphere by the quadratic formula as printed in most textbooks:
 * a t^2 + b t + c = 0 with b = 2 f.d, c = f.f - R^2, disc = b^2 - 4ac,
 * t = (-b -+ sqrt(disc)) / 2a.  Returns 1 and the nearest t in
 * (tmin, tmax).  Fails for a small sphere far away (b^2 and 4ac agree in
 * every digit) and loses the near root of a huge sphere close up. */
static inline int naive_sphere(vec3 center, real radius, const ray *r, real *t)
{
    vec3 f = vec_sub(r->origin, center);
    real a = vec_dot(r->dir, r->dir), b = 2 * vec_dot(f, r->dir);
    real c = vec_dot(f, f) - radius * radius;
    real disc = b * b - 4 * a * c;
    if (disc < 0)
        return 0;
    real sq = sqrt(disc), t0 = (-b - sq) / (2 * a), t1 = (-b + sq) / (2 * a);
    if (t0 > r->tmin && t0 < r->tmax) {
        *t = t0;
        return 1;
    }
    if (t1 > r->tmin && t1 < r->tmax) {
        *t = t1;
        return 1;
    }
    return 0;
}

/* Moller and Trumbore, "Fast, Minimum Storage Ray/Triangle Intersection"
 * (1997), in double: barycentrics u, v from two different cross products,
 * tested against [0, 1] with rounding of their own, so two triangles that
 * share an edge can both reject a ray through it. */
static inline int naive_triangle(const vec3 p[3], const ray *r, real *t)
{
    vec3 e1 = vec_sub(p[1], p[0]), e2 = vec_sub(p[2], p[0]);
    vec3 pv = vec_cross(r->dir, e2);
    real det = vec_dot(e1, pv);
    if (det == 0)
        return 0;
    real inv = 1 / det;
    vec3 s = vec_sub(r->origin, p[0]);
    real u = vec_dot(s, pv) * inv;
    if (u < 0 || u > 1)
        return 0;
    vec3 q = vec_cross(s, e1);
    real v = vec_dot(r->dir, q) * inv;
    if (v < 0 || u + v > 1)
        return 0;
    real tt = vec_dot(e2, q) * inv;
    if (!(tt > r->tmin && tt < r->tmax))
        return 0;
    *t = tt;
    return 1;
}

/* Woop, Benthin and Wald's test as the paper states it, refray's before
 * issue 13: an edge function of exactly 0 counts as inside for both
 * triangles that share the edge, so a ray through a shared edge or vertex
 * hits two (or more) of them: a glass mesh is crossed twice there, and the
 * light is attenuated twice.  Returns 1 for a hit with t in (tmin, tmax). */
static inline int naive_woop_inclusive(const vec3 p[3], const ray *r)
{
    vec3 d = r->dir;
    real ad[3] = {fabs(d.x), fabs(d.y), fabs(d.z)};
    int kz = ad[0] >= ad[1] ? (ad[0] >= ad[2] ? 0 : 2) : (ad[1] >= ad[2] ? 1 : 2);
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    real dz = vec_component(d, kz);
    if (dz < 0) {
        int s = kx;
        kx = ky;
        ky = s;
    }
    if (dz == 0)
        return 0;
    real sx = vec_component(d, kx) / dz, sy = vec_component(d, ky) / dz, px[3], py[3], pz[3], e[3];
    for (int i = 0; i < 3; i++) {
        vec3 a = vec_sub(p[i], r->origin);
        pz[i] = vec_component(a, kz);
        px[i] = vec_component(a, kx) - sx * pz[i];
        py[i] = vec_component(a, ky) - sy * pz[i];
    }
    for (int i = 0; i < 3; i++)
        e[i] = px[(i + 2) % 3] * py[(i + 1) % 3] - py[(i + 2) % 3] * px[(i + 1) % 3];
    if ((e[0] < 0 || e[1] < 0 || e[2] < 0) && (e[0] > 0 || e[1] > 0 || e[2] > 0))
        return 0;
    real det = e[0] + e[1] + e[2];
    if (det == 0)
        return 0;
    real t = (e[0] / det * pz[0] + e[1] / det * pz[1] + e[2] / det * pz[2]) / dz;
    return t > r->tmin && t < r->tmax;
}

/* For the mesh sweeps of both users: the corner positions of triangle k of
 * a mesh, and a bvh_visit callback that counts the crossings. */
static inline void mesh_triangle(const scene_trimesh *g, int k, vec3 p[3])
{
    for (int i = 0; i < 3; i++)
        p[i] = g->positions[g->tri[k][i]];
}

static inline int count_crossing(void *ctx, const hit *h)
{
    (void)h;
    ++*(int *)ctx;
    return 0;
}

/* A secondary ray pushed off the surface by a fixed distance eps along the
 * normal, to the side dir goes: too far at small scales (it jumps thin
 * gaps), too short at large ones (the hit point's own error is larger). */
static inline ray naive_spawn(vec3 point, vec3 normal, vec3 dir, real eps)
{
    ray r;
    r.origin = vec_madd(point, normal, vec_dot(dir, normal) >= 0 ? eps : -eps);
    r.dir = dir;
    r.tmin = 0;
    r.tmax = HUGE_VAL;
    return r;
}

/* The Phong lobe as exp(n log c): the exponent n log c carries the relative
 * error of log c, multiplied by |n log c| in the result (up to 745 ulps). */
static inline real naive_phong_lobe(real c, real n)
{
    return c > 0 ? exp(n * log(c)) : 0;
}

/* Snell's law as in most textbooks: k = 1 - eta^2 (1 - c^2), total internal
 * reflection when k < 0, t = eta d + (eta c - sqrt k) n.  Near the critical
 * angle k is the difference of two numbers equal to about 16 digits: the
 * refract-or-reflect decision is wrong for cosines a few ulps from it. */
static inline int naive_refract(vec3 d, vec3 n, real n1, real n2, vec3 *t)
{
    real c = -vec_dot(n, d), eta = n1 / n2;
    real k = 1 - eta * eta * (1 - c * c);
    if (k < 0)
        return 0;
    *t = vec_madd(vec_scale(d, eta), n, eta * c - sqrt(k));
    return 1;
}

/* A closed cylinder by the textbook quadratic: the side as
 * a t^2 + b t + c = 0 across the axis with c = |fp|^2 - R^2 and
 * disc = b^2 - 4ac, the caps as planes; the nearest hit in (tmin, tmax) and
 * the point o + t d.  For a far origin c is the difference of two huge
 * squares and the point carries the error of o. */
static inline int naive_cylinder(vec3 from, vec3 to, real radius, const ray *r, real *t)
{
    vec3 w = vec_sub(to, from), a = vec_normalize(w), f = vec_sub(r->origin, from);
    real len = vec_length(w), z0 = vec_dot(f, a), dz = vec_dot(r->dir, a), best = HUGE_VAL;
    vec3 fp = vec_sub(f, vec_scale(a, z0)), dp = vec_sub(r->dir, vec_scale(a, dz));
    real qa = vec_dot(dp, dp), qb = 2 * vec_dot(fp, dp), qc = vec_dot(fp, fp) - radius * radius;
    real disc = qb * qb - 4 * qa * qc;
    if (qa > 0 && disc >= 0)
        for (int k = -1; k <= 1; k += 2) {
            real tt = (-qb + k * sqrt(disc)) / (2 * qa), z = z0 + tt * dz;
            if (z >= 0 && z <= len && tt > r->tmin && tt < r->tmax && tt < best)
                best = tt;
        }
    for (int e = 0; e < 2 && dz != 0; e++) {
        real tt = ((e ? len : 0) - z0) / dz;
        vec3 q = vec_add(fp, vec_scale(dp, tt));
        if (vec_dot(q, q) <= radius * radius && tt > r->tmin && tt < r->tmax && tt < best)
            best = tt;
    }
    *t = best;
    return best < HUGE_VAL;
}

/* A torus by its quartic in t written from the ray as given (no shift of
 * the origin, no scaling), (|q|^2 + R^2 - r^2)^2 - 4 R^2 rho^2 with
 * q = o - c + t d expanded in powers of t, its first root found by
 * stepping t over the bounding sphere's chord in 256 steps and bisecting a
 * sign change; the point o + t d.  The coefficients of a far ray are huge
 * and nearly cancel: the quartic's value near a thin tube is noise. */
static inline real naive_torus_quartic(const real c[5], real t)
{
    return (((c[4] * t + c[3]) * t + c[2]) * t + c[1]) * t + c[0];
}

static inline int naive_torus(vec3 center, vec3 axis, real major, real minor, const ray *r, real *t)
{
    vec3 f = vec_sub(r->origin, center), d = r->dir;
    real fz = vec_dot(f, axis), dz = vec_dot(d, axis);
    real dd = vec_dot(d, d), fd = vec_dot(f, d), ff = vec_dot(f, f);
    real k = ff + major * major - minor * minor, R2 = 4 * major * major, c[5];
    c[4] = dd * dd;
    c[3] = 4 * dd * fd;
    c[2] = 2 * dd * k + 4 * fd * fd - R2 * (dd - dz * dz);
    c[1] = 4 * fd * k - 2 * R2 * (fd - fz * dz);
    c[0] = k * k - R2 * (ff - fz * fz);
    real bound = major + minor, disc = fd * fd - dd * (ff - bound * bound);
    if (disc < 0)
        return 0;
    real lo = (-fd - sqrt(disc)) / dd, hi = (-fd + sqrt(disc)) / dd;
    lo = lo > r->tmin ? lo : r->tmin;
    hi = hi < r->tmax ? hi : r->tmax;
    real step = (hi - lo) / 256, a = lo, fa = naive_torus_quartic(c, a);
    for (int i = 1; i <= 256 && step > 0; i++) {
        real b = lo + i * step, fb = naive_torus_quartic(c, b);
        if ((fa < 0) != (fb < 0)) {
            for (int j = 0; j < 100; j++) {
                real m = 0.5 * (a + b), fm = naive_torus_quartic(c, m);
                if ((fm < 0) == (fa < 0))
                    a = m;
                else
                    b = m;
            }
            *t = 0.5 * (a + b);
            return *t > r->tmin;
        }
        a = b;
        fa = fb;
    }
    return 0;
}

#endif
