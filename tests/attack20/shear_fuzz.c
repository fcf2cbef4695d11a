/*
 * shear_fuzz.c - attack 20: shear_bounds (bvh_bundle.c) against the shears
 * the rays really have.  For an exact origin O and a target box [L, H]
 * (flat on an axis, point-like, |D_x| within ulps of |D_z| or |D_y| at
 * the box's corners: the dominant axis at its tie; magnitudes 2^-400 ..
 * 2^400), every shadow ray from O (ray_shadow_to) toward a point of the
 * box (its corners, points nudged in from them, random ones) must have
 * its isect_shear_make among the bundle's: kz one of the kept axes, kx
 * and ky as kept, sx and sy within their bounds.  The claim the triangles
 * left out rest on, tested directly rather than through a triangle's
 * rare coincidence.  It includes bvh_bundle.c for its static functions.
 *   cc -std=c99 -O2 -ffp-contract=off -Isrc -Ibuild/gen -o /tmp/sf tests/attack20/shear_fuzz.c \
 *      build/librefray-internal.a -ljansson -lm && /tmp/sf 1000000
 */
#include "render/bvh_bundle.c"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#define FUZZ_SEED 0x853C49E6748FEA9Bu
#include "fuzz_common.h"

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 100000, bad = 0, rays_n = 0, known = 0, ties = 0;
    long subn = 0;
    if (argc > 2)
        st = strtoull(argv[2], NULL, 10);
    for (long it = 0; it < n; it++) {
        double S = ldexp(1.0, RI(-390, 390) * (U() < 0.7 ? 0 : 1)) * (U() < 0.5 ? 1 : 0.75);
        shadow_start from;
        from.point = vec_make(S * RI(-8, 8) * 0.25, S * RI(-8, 8) * 0.25, S * RI(-8, 8) * 0.25);
        int na = RI(0, 3);
        from.normal = na == 0 ? vec_make(0, 1, 0) : na == 1 ? vec_make(1, 0, 0) : na == 2 ? vec_make(0, 0, -1) : vec_make(0.6, 0, 0.8);
        from.offset = S * ldexp(1.0, -RI(10, 40));
        int sub = U() < 0.15 && from.normal.x == 0;
        if (sub)
            from.point.x = 0;
        vec3 O = ray_shadow_origin(&from, from.normal);
        double o[3] = {O.x, O.y, O.z}, D[3], w[3], lo[3], hi[3];
        for (int a = 0; a < 3; a++) {
            D[a] = S * (RI(-16, 16) * 0.25 + (U() < 0.3 ? U() : 0));
            w[a] = U() < 0.3 ? 0 : U() < 0.3 ? S * 1e-12 : S * RI(1, 8) * 0.25;
        }
        int tie = U() < 0.6;
        if (tie) {   /* |D_b| within ulps of |D_a| at the corner of least |D_a|, greatest |D_b| */
            int a = RI(0, 2), b = (a + RI(1, 2)) % 3;
            if (D[a] == 0) D[a] = S;
            D[b] = nudge(D[a] * (U() < 0.5 ? 1 : -1), RI(-4, 4));
            if (U() < 0.3) w[a] = w[b] = 0;
        }
        if (sub) {   /* x: O_x = 0, the box subnormal on x: the rays' dir_x subnormal or 0 */
            o[0] = 0;
            D[0] = RI(-8, 8) * 0x1p-1074;
            w[0] = RI(0, 3) * 0x1p-1074;
        }
        for (int a = 0; a < 3; a++) {
            /* the corner o + D is the box's least corner where D > 0 (least |D|), its greatest below */
            double c = o[a] + D[a];
            lo[a] = D[a] >= 0 ? c : c - w[a];
            hi[a] = D[a] >= 0 ? c + w[a] : c;
        }
        bvh_bundle_rays rays;
        memset(&rays, 0, sizeof rays);
        rays.apex = from.point;
        rays.slack = from.offset * 2;
        rays.lo = vec_make(lo[0], lo[1], lo[2]);
        rays.hi = vec_make(hi[0], hi[1], hi[2]);
        rays.exact = 1;
        rays.origin = O;
        bundle_cone c;
        memset(&c, 0, sizeof c);
        shear_bounds(&rays, &c);
        if (!c.tri)
            continue;
        known++;
        ties += tie;
        for (int j = 0; j < 24; j++) {
            double q[3];
            for (int a = 0; a < 3; a++) {
                int k = j < 8 ? (j >> a & 1) : RI(0, 2);
                q[a] = k == 0 ? lo[a] : k == 1 ? hi[a] : lo[a] + (hi[a] - lo[a]) * U();
                if (j >= 16) q[a] = k == 0 ? nudge(lo[a], RI(0, 2)) : k == 1 ? nudge(hi[a], -RI(0, 2)) : q[a];
                if (q[a] < lo[a]) q[a] = lo[a];
                if (q[a] > hi[a]) q[a] = hi[a];
            }
            vec3 qv = vec_make(q[0], q[1], q[2]);
            ray r = ray_shadow_to(&from, qv);
            if (r.origin.x != O.x || r.origin.y != O.y || r.origin.z != O.z || !(r.tmax > 0))
                continue;
            isect_shear sh;
            isect_shear_make(&r, &sh);
            rays_n++;
            subn += fabs(r.dir.x) < 0x1p-1022 && r.dir.x != 0;
            int ok = 0;
            for (int p = 0; p < c.perms && !ok; p++) {
                const isect_shear *b = c.perm[p];
                ok = b[0].kz == sh.kz && b[0].kx == sh.kx && b[0].ky == sh.ky && b[0].sx <= sh.sx && sh.sx <= b[1].sx &&
                     b[0].sy <= sh.sy && sh.sy <= b[1].sy;
            }
            if (!ok) {
                if (bad < 5) {
                    printf("OUTSIDE it %ld ray %d: kz %d sx %a sy %a; kept:", it, j, sh.kz, sh.sx, sh.sy);
                    for (int p = 0; p < c.perms; p++)
                        printf(" [kz %d sx %a..%a sy %a..%a]", c.perm[p][0].kz, c.perm[p][0].sx, c.perm[p][1].sx,
                               c.perm[p][0].sy, c.perm[p][1].sy);
                    printf("\n");
                }
                bad++;
            }
        }
    }
    printf("shear_fuzz: %ld bundles, %ld with shears known (%ld at a tie), %ld rays, %ld outside\n", n, known, ties, rays_n,
           bad);
    printf("  rays with a subnormal dir.x: %ld\n", subn);
    return bad != 0;
}
