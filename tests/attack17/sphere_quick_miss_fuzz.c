/*
 * sphere_quick_miss_fuzz.c - attack 17, a check that held: isect_hot_crossings
 * of a sphere record (with isect_sphere_moving_away first) against
 * isect_part_crossings (the full test) on adversarial rays: radii 1e-150 ..
 * 1e150, centres up to 1e12 R off the origin, origins on the surface, an ulp
 * off, 1e-12 .. 1e3 R off, at 2R, just inside; directions along the normal,
 * tangent, tangent tipped by 1e-16 .. 0.1 either way, random, scaled by
 * 1e-100 .. 1e100; tmin 0 or up to 1e-3 R.  Exit 1 on a count that differs.
 * Build and run from the repository root after `make build/refray`:
 *   cc -std=c99 -O2 -ffp-contract=off -Isrc -Ibuild/gen -o /tmp/fz \
 *      tests/attack17/sphere_quick_miss_fuzz.c build/librefray-internal.a -lm && /tmp/fz 2000000
 * 4961d02: 2000000 rays, 0 differ (1016541 with no crossing).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <stdint.h>
#include "render/intersect.h"
static uint64_t s = 88172645463325252ull;
static double U(void) { s ^= s << 13; s ^= s >> 7; s ^= s << 17; return (double)(s >> 11) * 0x1p-53; }
static double L(double lo, double hi) { return exp(log(lo) + (log(hi) - log(lo)) * U()); }
static vec3 rdir(void) { double z = 2 * U() - 1, a = 6.283185307179586 * U(), r = sqrt(1 - z * z); return vec_make(r * cos(a), r * sin(a), z); }
int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 1000000, bad = 0, told = 0;
    for (long i = 0; i < n; i++) {
        scene_prim p;
        memset(&p, 0, sizeof p);
        p.kind = PRIM_SPHERE;
        p.mesh = -1;
        double R = L(1e-150, 1e150);
        double off = U() < 0.3 ? 0 : L(1e-3, 1e12) * R;
        vec3 c = vec_scale(rdir(), U() < 0.5 ? off : L(1e-6, 1e6));
        p.u.sphere.center = c;
        p.u.sphere.radius = R;
        vec3 nrm = rdir();
        int mode = (int)(U() * 6);
        double dist = mode == 0 ? 0 : mode == 1 ? R * 0x1p-52 * (U() - 0.3) : mode == 2 ? R * L(1e-12, 1e-6) : mode == 3 ? R * L(1e-3, 1e3) : mode == 4 ? R * 2.0000000001 : -R * 1e-9;
        vec3 o = vec_add(c, vec_scale(nrm, R + dist));
        vec3 d;
        int dm = (int)(U() * 4);
        if (dm == 0) d = nrm;
        else if (dm == 1) { vec3 t = vec_normalize(vec_cross(nrm, rdir())); d = vec_normalize(vec_add(t, vec_scale(nrm, L(1e-16, 1e-1) * (U() < 0.5 ? 1 : -1)))); }
        else if (dm == 2) d = rdir();
        else { vec3 t = vec_normalize(vec_cross(nrm, rdir())); d = t; }
        d = vec_scale(d, L(1e-100, 1e100));
        ray r = {o, d, U() < 0.5 ? 0.0 : L(1e-300, 1e-3) * R / vec_length(d), INFINITY};
        if (!(vec_max_abs(o) < 1e150)) continue;
        real g[ISECT_HOT_REALS];
        int reals, code = isect_hot_make(&p, 0, g, &reals);
        int full = isect_part_crossings(&p, 0, &r);
        int hot = isect_hot_crossings(code, g, &r, NULL);
        if (full != hot) {
            if (bad++ < 10)
                printf("R=%.17g c=[%.17g,%.17g,%.17g] o=[%.17g,%.17g,%.17g] d=[%.17g,%.17g,%.17g] tmin=%.17g full=%d hot=%d\n", R, c.x, c.y, c.z, o.x, o.y, o.z, d.x, d.y, d.z, r.tmin, full, hot);
        }
        told += full == 0;
    }
    printf("%ld rays, %ld differ, %ld with no crossing\n", n, bad, told);
    return bad != 0;
}
