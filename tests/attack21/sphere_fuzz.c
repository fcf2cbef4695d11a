/*
 * sphere_fuzz.c - attack 21: [NUM-SPHERE-3] (sphere_root_clear: a far
 * origin's root clear of the interval's ends counted unrefined, the count
 * of isect_part_crossings and isect_hot_crossings) against the refined
 * roots' count, isect_part_all (every hit it writes is accepted, so its
 * return is the count the tracer had before).  Cases: spheres of radius
 * 2^-300 .. 2^300, centres up to 1e17 radii from the origin and moved up to
 * 1e8 of the scale, origins at 2R (1 + tiny) .. 1e12 R from the centre,
 * aims over the silhouette disk, at its rim to 1e-16 and past it by ulps
 * (grazes), directions of magnitude 1e-30 .. 1e30 with components zeroed
 * at random (axis rays), and the interval's ends put at the unrefined or
 * refined roots nudged by -3..3 ulps, at the edge of the clear margin
 * (sphere_root_clear's m, copied here only to place the ends), at random,
 * tmin negative or -inf, tmax +inf.  Exit 1 on a difference.  From the
 * repository root after `make build/refray`:
 *   cc -std=c99 -O2 -ffp-contract=off -Isrc -Ibuild/gen -o /tmp/sf \
 *      tests/attack21/sphere_fuzz.c build/librefray-internal.a -ljansson -lm && /tmp/sf 1000000 [SEED [SPAN [DSPAN]]]
 * (SPAN: scales 2^-SPAN .. 2^SPAN, default 300; 480 reaches overflow and
 * the radius floor 2^-400 of sphere_root_clear; DSPAN: |d| 10^-DSPAN ..
 * 10^DSPAN, default 30)
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "render/intersect.h"
#include "render/isect_common.h"
#include "scene/scene.h"
#include "../attack20/fuzz_common.h"

static vec3 unit(void)
{
    for (;;) {
        vec3 v = vec_make(2 * U() - 1, 2 * U() - 1, 2 * U() - 1);
        double l2 = vec_length2(v);
        if (l2 > 0.01 && l2 <= 1.0)
            return vec_normalize(v);
    }
}

/* Where sphere_root_clear's margin puts an end for root t (the place the
 * shortcut's answer flips), so that ends can be set around it. */
static double margin_end(vec3 c, double radius, const ray *r, double t, int lower)
{
    vec3 f2 = vec_sub(vec_madd(r->origin, r->dir, t), c);
    double n1 = fabs(f2.x) + fabs(f2.y) + fabs(f2.z);
    double dm = fmax(fabs(r->dir.x), fmax(fabs(r->dir.y), fabs(r->dir.z)));
    double m = (n1 + radius) * (1.0 + 0x1p-14) + 0x1p-40 * fabs(t) * dm;
    return lower ? t - m / dm : t + m / dm;
}

static double place(double u, double full, vec3 c, double radius, const ray *r, int lower)
{
    int k = RI(0, 5);
    double base = k == 0 ? u : k == 1 ? full : k == 2 ? fmax(u, full) : k == 3 ? fmin(u, full)
                                                                       : margin_end(c, radius, r, u, lower);
    return nudge(base, RI(-3, 3));
}

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 100000;
    if (argc > 2)
        st = strtoull(argv[2], NULL, 10) * 0x9E3779B97F4A7C15u + 1;
    int span = argc > 3 ? atoi(argv[3]) : 300;   /* scales 2^-span .. 2^span */
    double dspan = argc > 4 ? atof(argv[4]) : 30;   /* |d| 10^-dspan .. 10^dspan */
    long cases = 0, two = 0, between = 0, bad_part = 0, bad_hot = 0, graze = 0;
    for (long i = 0; i < n; i++) {
        double s = ldexp(1.0, RI(-span, span));
        double spread = pow(10.0, (U() < 0.2 ? 17 : 15) * U());
        vec3 c = vec_scale(unit(), spread * s);
        if (U() < 0.2)
            c = vec_add(c, vec_make(1e8 * s, -3e7 * s, 0.5e8 * s));
        double radius = s * (U() < 0.8 ? 0.05 + U() : pow(10.0, -6 * U()));
        scene_prim p;
        memset(&p, 0, sizeof p);
        p.kind = PRIM_SPHERE;
        p.mesh = -1;
        p.u.sphere.center = c;
        p.u.sphere.radius = radius;
        vec3 nrm = unit(), side = vec_normalize(vec_cross(nrm, unit()));
        double w = U();
        double away = radius * (w < 0.1 ? 2.0 * (1 + pow(10.0, -15 * U())) : w < 0.15 ? 0.5 + 1.5 * U()
                                                                           : 2.5 + pow(10.0, 12 * U()));
        w = U();
        double off = w < 0.4 ? sqrt(U()) : w < 0.8 ? 1 - pow(10.0, -16 * U()) : nudge(1.0, RI(-4, 4));
        if (w >= 0.4)
            graze++;
        vec3 o = vec_madd(c, nrm, away), aim = vec_madd(c, side, radius * off);
        vec3 d = vec_scale(vec_normalize(vec_sub(aim, o)), pow(10.0, dspan * (2 * U() - 1)));
        if (U() < 0.1) {
            /* an axis ray: the sphere put on it */
            int ax = RI(0, 2);
            d = vec_make(ax == 0 ? 1.0 : 0.0, ax == 1 ? 1.0 : 0.0, ax == 2 ? -1.0 : 0.0);
            d = vec_scale(d, pow(10.0, 10 * U() - 5));
            o = vec_madd(c, d, -away / vec_length(d));
            if (ax != 0)
                o.x = nudge(c.x + radius * off, RI(-2, 2));
            else
                o.y = nudge(c.y + radius * off, RI(-2, 2));
        }
        ray r;
        r.origin = o;
        r.dir = d;
        r.tmin = 0.0;
        r.tmax = HUGE_VAL;
        real u[2];
        hit full[ISECT_MAX_CROSSINGS];
        int nu = isect_sphere_roots(vec_sub(o, c), d, radius, u);
        int nf = isect_part_all(&p, 0, &r, full);
        double f0 = nf > 0 ? full[0].t : u[0], f1 = nf > 1 ? full[1].t : nf > 0 ? full[0].t : u[1];
        int k = RI(0, 7);
        if (k == 1 || k == 3)
            r.tmax = place(nu == 2 ? u[1] : u[0], f1, c, radius, &r, 0);
        if (k == 2 || k == 3)
            r.tmin = place(u[0], f0, c, radius, &r, 1);
        if (k == 4) {
            r.tmin = place(u[1], f1, c, radius, &r, 1);
            r.tmax = place(u[1], f1, c, radius, &r, 0);
        }
        if (k == 5) {
            r.tmin = place(u[0], f0, c, radius, &r, 0);
            r.tmax = place(u[1], f1, c, radius, &r, 1);
        }
        if (k == 6) {
            r.tmin = U() < 0.3 ? -HUGE_VAL : f0 * (2 * U() - 0.5);
            r.tmax = f0 + (f1 - f0) * 3 * U();
        }
        if (k == 7)
            r.tmin = -HUGE_VAL;
        if (!(r.tmin == r.tmin) || !(r.tmax == r.tmax))
            continue;
        cases++;
        two += nu == 2;
        int expect = isect_part_all(&p, 0, &r, full);
        int unref = nu == 2 ? (u[0] > r.tmin && u[0] < r.tmax) + (u[1] > r.tmin && u[1] < r.tmax) : expect;
        between += unref != expect;
        int got = isect_part_crossings(&p, 0, &r);
        real g[ISECT_HOT_REALS];
        int reals, code = isect_hot_make(&p, 0, g, &reals);
        int hot = isect_hot_crossings(code, g, &r, NULL);
        /* the hot record tells a sphere the ray moves away from first
         * (isect_sphere_moving_away, older than this round): only for
         * tmin >= 0, the tracer's rays */
        int hot_bad = r.tmin >= 0.0 && hot != expect;
        if (got != expect || hot_bad) {
            bad_part += got != expect;
            bad_hot += hot_bad;
            if (bad_part + bad_hot <= 10)
                printf("diff: c %a %a %a R %a o %a %a %a d %a %a %a tmin %a tmax %a: full %d count %d hot %d\n",
                       c.x, c.y, c.z, radius, o.x, o.y, o.z, d.x, d.y, d.z, r.tmin, r.tmax, expect, got, hot);
        }
    }
    printf("sphere_fuzz: %ld cases (%ld with two roots, %ld grazing aims, %ld where the unrefined count differs): "
           "%ld count differences, %ld hot differences\n",
           cases, two, graze, between, bad_part, bad_hot);
    return bad_part || bad_hot;
}
