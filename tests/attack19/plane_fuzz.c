/*
 * plane_fuzz.c - attack 19: isect_plane_crossings' early "moving away"
 * answer against plane_t itself (isect_plane_nearest, the nearest walk's
 * deferred plane test) on adversarial rays: unit normals along the axes
 * with -0 components, tilted, random; plane points up to 1e150; origins on
 * the plane (exactly, its own point), an ulp off, far off, at 1e150;
 * directions parallel (exact and -0), nearly parallel (1e-300 .. 1e-8 off),
 * along the normal, random; tmin 0, -0, 1e-300 .. 1; tmax finite or
 * infinite.  Exit 1 on a ray whose answers differ.  Build and run from the
 * repository root after `make build/refray`:
 *   cc -std=c99 -O2 -ffp-contract=off -Isrc -Ibuild/gen -o /tmp/pf \
 *      tests/attack19/plane_fuzz.c build/librefray-internal.a -ljansson -lm && /tmp/pf 10000000
 * ae0ba50: 20000000 rays (2697475 hits), 0 differ; a mutant that also answers 0
 * for |n.d| < 1e-9 differs on 68064 of 2000000: it can fail.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include "render/intersect.h"

static uint64_t st = 88172645463325252ull;
static double U(void) { st ^= st << 13; st ^= st >> 7; st ^= st << 17; return (double)(st >> 11) * 0x1p-53; }
static double L(double lo, double hi) { return exp(log(lo) + (log(hi) - log(lo)) * U()); }
static int RI(int n) { return (int)(n * U()); }
static vec3 rdir(void) { double z = 2 * U() - 1, a = 6.283185307179586 * U(), r = sqrt(1 - z * z); return vec_make(r * cos(a), r * sin(a), z); }

static vec3 normal(void)
{
    double s = U() < 0.5 ? -1 : 1, z0 = U() < 0.5 ? 0.0 : -0.0, z1 = U() < 0.5 ? 0.0 : -0.0;
    switch (RI(4)) {
    case 0: return vec_make(s, z0, z1);
    case 1: return vec_make(z0, s, z1);
    case 2: return vec_make(z0, z1, s);
    default: return vec_normalize(rdir());
    }
}

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 1000000, bad = 0, hits = 0;
    for (long i = 0; i < n; i++) {
        vec3 nn = normal();
        double mag = RI(3) == 0 ? 0 : L(1e-300, 1e150);
        vec3 p = vec_scale(rdir(), mag);
        ray r;
        double off = RI(4) == 0 ? 0 : L(1e-300, 1e150) * (U() < 0.5 ? -1 : 1);
        r.origin = vec_add(p, vec_add(vec_scale(nn, off), vec_scale(rdir(), RI(2) ? 0 : L(1e-300, 1e150))));
        if (RI(6) == 0)
            r.origin = p;
        if (RI(8) == 0)
            r.origin = vec_make(nextafter(p.x, INFINITY), p.y, nextafter(p.z, -INFINITY));
        vec3 d = rdir();
        switch (RI(5)) {
        case 0: d = vec_sub(d, vec_scale(nn, vec_dot(d, nn))); break;                       /* parallel */
        case 1: d = vec_add(vec_sub(d, vec_scale(nn, vec_dot(d, nn))), vec_scale(nn, L(1e-300, 1e-8) * (U() < 0.5 ? -1 : 1))); break;
        case 2: d = vec_scale(nn, U() < 0.5 ? -1 : 1); break;
        case 3: d = vec_make(nn.x == 0 ? (U() < 0.5 ? 0.0 : -0.0) : d.x, nn.y == 0 ? -0.0 : d.y, d.z); break;
        default: break;
        }
        if (vec_length2(d) > 0 && RI(2))
            d = vec_normalize(d);
        if (!(vec_length2(d) > 0))
            d = vec_make(U() < 0.5 ? 0.0 : -0.0, 1, 0);
        r.dir = d;
        switch (RI(4)) {
        case 0: r.tmin = 0; break;
        case 1: r.tmin = -0.0; break;
        default: r.tmin = L(1e-300, 1); break;
        }
        r.tmax = RI(3) == 0 ? HUGE_VAL : L(1e-300, 1e300);
        if (!(r.tmax > r.tmin))
            continue;
        real t;
        int a = isect_plane_crossings(p, nn, &r), b = isect_plane_nearest(p, nn, &r, &t);
        hits += b;
        if (a != b) {
            if (bad < 5)
                printf("DIFFER: point %a %a %a normal %a %a %a origin %a %a %a dir %a %a %a tmin %a tmax %a: %d %d\n", p.x,
                       p.y, p.z, nn.x, nn.y, nn.z, r.origin.x, r.origin.y, r.origin.z, r.dir.x, r.dir.y, r.dir.z, r.tmin,
                       r.tmax, a, b);
            bad++;
        }
    }
    printf("plane_fuzz: %ld rays, %ld hits, %ld differ\n", n, hits, bad);
    return bad != 0;
}
