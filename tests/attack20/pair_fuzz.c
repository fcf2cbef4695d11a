/*
 * pair_fuzz.c - attack 20: slab_pair.h's two-lane test against the scalar
 * slab_box_meets_neg (slab.h), lane by lane, on adversarial values: origins
 * on slab planes with zero and -0 directions (0 * inf = NaN), infinite and
 * huge bounds, subnormal differences and directions, inverted boxes, tmax
 * infinite, tmin negative and NaN-free.  Every answer bit and entry (as
 * bits) must agree.  Exit 1 on a difference.  Build from the repository
 * root after `make build/refray`:
 *   cc -std=c99 -O2 -ffp-contract=off -Isrc -Ibuild/gen -o /tmp/pf tests/attack20/pair_fuzz.c -lm && /tmp/pf 20000000
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "render/slab_pair.h"

static uint64_t st = 0x243F6A8885A308D3u;
static uint64_t R64(void)
{
    uint64_t z = (st += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}
static double U(void) { return (double)(R64() >> 11) * 0x1p-53; }
static int RI(int n) { return (int)(U() * n); }

static const double special[] = {0.0, -0.0, INFINITY, -INFINITY, 1.0, -1.0, 0x1p-1074, -0x1p-1074, 0x1p-1022,
                                 1e300, -1e300, 1.7976931348623157e308, -1.7976931348623157e308, 0.5, 2.0, 1e-300};
static double val(const double *pool, int n)
{
    int k = RI(6);
    if (k == 0)
        return special[RI(16)];
    if (k == 1 && n > 0)
        return pool[RI(n)];
    if (k == 2 && n > 0)
        return nextafter(pool[RI(n)], U() < 0.5 ? INFINITY : -INFINITY);
    if (k == 3) {
        uint64_t b = R64();
        double d;
        memcpy(&d, &b, 8);
        return isnan(d) ? 0.0 : d;
    }
    return (U() * 8 - 4) * pow(2.0, RI(40) - 20);
}
static int same(double a, double b) { return memcmp(&a, &b, 8) == 0; }

int main(int argc, char **argv)
{
#ifndef SLAB_PAIR_SSE2
    puts("no SSE2 pair form here");
    return 0;
#else
    long n = argc > 1 ? atol(argv[1]) : 1000000, bad = 0;
    if (argc > 2)
        st = strtoull(argv[2], NULL, 10);
    static bvh_node nodes[2] __attribute__((aligned(16)));
    for (long it = 0; it < n; it++) {
        double pool[16];
        int np = 0;
        ray r;
        double o[3], d[3];
        for (int a = 0; a < 3; a++) {
            o[a] = val(pool, np);
            if (!isfinite(o[a])) o[a] = 0;
            pool[np++] = o[a];
            int k = RI(5);
            d[a] = k == 0 ? 0.0 : k == 1 ? -0.0 : k == 2 ? (U() < 0.5 ? 0x1p-1074 : -0x1p-1060) : val(pool, 0);
            if (!isfinite(d[a])) d[a] = 1;
        }
        r.origin = vec_make(o[0], o[1], o[2]);
        r.dir = vec_make(d[0], d[1], d[2]);
        for (int c = 0; c < 2; c++) {
            double lo[3], hi[3];
            for (int a = 0; a < 3; a++) {
                lo[a] = val(pool, np);
                hi[a] = U() < 0.8 ? (lo[a] <= INFINITY ? lo[a] + fabs(val(pool, np)) : lo[a]) : val(pool, np);
                if (isnan(hi[a])) hi[a] = lo[a];
                if (U() < 0.3) lo[a] = o[a];
                if (U() < 0.2) hi[a] = o[a];
            }
            memset(&nodes[c], 0, sizeof nodes[c]);
            nodes[c].lo = vec_make(lo[0], lo[1], lo[2]);
            nodes[c].hi = vec_make(hi[0], hi[1], hi[2]);
        }
        slab_ray s = slab_make(&r);
        slab_pair_ray p;
        slab_pair_make(&s, &p);
        double tmin = U() < 0.5 ? 0.0 : U() < 0.5 ? val(pool, np) : 1e-9;
        double tmax = U() < 0.3 ? INFINITY : U() < 0.5 ? fabs(val(pool, np)) : 1.0;
        if (isnan(tmin)) tmin = 0;
        if (isnan(tmax)) tmax = INFINITY;
        double ea, ec, pa, pc, qa, qc;
        int sa = slab_box_meets_neg(nodes[0].lo, nodes[0].hi, &s, s.neg[0], s.neg[1], s.neg[2], tmin, tmax, &ea);
        int sc = slab_box_meets_neg(nodes[1].lo, nodes[1].hi, &s, s.neg[0], s.neg[1], s.neg[2], tmin, tmax, &ec);
        int m1 = slab_pair_meets(nodes, &p, slab_pair_near_at(0, s.neg[0]), slab_pair_far_at(0, s.neg[0]),
                                 slab_pair_near_at(1, s.neg[1]), slab_pair_far_at(1, s.neg[1]),
                                 slab_pair_near_at(2, s.neg[2]), slab_pair_far_at(2, s.neg[2]), tmin, tmax, &pa, &pc);
        int m2 = slab_pair_meets_slab(nodes, &s, tmin, tmax, &qa, &qc);
        int want = sa | sc << 1;
        if (m1 != want || m2 != want || !same(ea, pa) || !same(ec, pc) || !same(ea, qa) || !same(ec, qc)) {
            if (bad < 5)
                printf("DIFFER it %ld: scalar %d (%a %a) pair %d (%a %a) slab %d (%a %a)\n", it, want, ea, ec, m1, pa, pc,
                       m2, qa, qc);
            bad++;
        }
    }
    printf("pair_fuzz: %ld node pairs, %ld differ\n", n, bad);
    return bad != 0;
#endif
}
