/*
 * torus_diff.c - a differential check of intersect_torus.c against an
 * earlier version (spec/proofs.md, "Round 9"): isect_torus_hits on a fixed
 * set of rays at random sizes 2^-499 to 2^500, distances, centres and
 * axes (one ray in 7 with its direction shortened by up to 2^-600, as a
 * local frame can), one line a ray: its inputs' scales (the distance in
 * bounding radii, log2), whether a floating-point exception was raised
 * (fetestexcept), and the hits' t, normal and point bit for bit.  Not part
 * of make check; built twice, against each version:
 *   mkdir -p /tmp/old/render && git show fa70aa1:src/render/intersect_torus.c >/tmp/old/render/intersect_torus.c
 *   cc -std=c99 -O2 -ffp-contract=off -frounding-math -DNDEBUG -I/tmp/old -Isrc tests/prove/torus_diff.c -lm -o /tmp/old/diff
 *   cc -std=c99 -O2 -ffp-contract=off -frounding-math -DNDEBUG -Isrc tests/prove/torus_diff.c -lm -o /tmp/new-diff
 *   /tmp/old/diff 1000000 >/tmp/old.txt; /tmp/new-diff 1000000 >/tmp/new.txt; diff /tmp/old.txt /tmp/new.txt
 * FAR (any argument after the count): distances up to 2^1000 radii.
 */
#include <fenv.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "render/isect_common.c"
#include "render/intersect_torus.c"

static double uniform(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return (double)(*s >> 11) * 0x1p-53;
}

static unsigned long long bits(double x)
{
    uint64_t b;
    memcpy(&b, &x, sizeof b);
    return (unsigned long long)b;
}

int main(int argc, char **argv)
{
    long count = argc > 1 ? atol(argv[1]) : 100000;
    int far = argc > 2;
    uint64_t s = 88172645463325252ull;
    for (long k = 0; k < count; k++) {
        int a = (int)(uniform(&s) * 1000) - 499;
        int b = far ? (int)(uniform(&s) * 999) - 499 : a + (int)(uniform(&s) * 200) - 20;
        int ce = (int)(uniform(&s) * 1000) - 500;
        if (b > 499)
            b = 499;
        if (k % 3 == 0) {
            a = (int)(uniform(&s) * 20) - 10;
            b = a + (int)(uniform(&s) * 10);
            ce = (int)(uniform(&s) * 10) - 5;
        }
        double major = ldexp(0.5 + uniform(&s), a);
        double minor = major * (k % 5 == 0 ? 1 - ldexp(1, -(int)(uniform(&s) * 52)) : uniform(&s) * 0.9 + 1e-3);
        if (!(minor < major) || !(minor > 0))
            continue;
        vec3 c = vec_make(ldexp(uniform(&s) - 0.5, ce), ldexp(uniform(&s) - 0.5, ce), ldexp(uniform(&s) - 0.5, ce));
        vec3 axis = vec_normalize(vec_make(uniform(&s) - 0.5, uniform(&s) - 0.5, uniform(&s) - 0.5));
        if (k % 4 == 0)
            axis = vec_make(0, 0, 1);
        /* aimed at a point near the torus */
        vec3 target = vec_add(c, vec_scale(vec_make(uniform(&s) * 2.4 - 1.2, uniform(&s) * 2.4 - 1.2,
                                                    uniform(&s) * 0.6 - 0.3), major));
        vec3 away = vec_make(ldexp(uniform(&s) - 0.5, b), ldexp(uniform(&s) - 0.5, b), ldexp(uniform(&s) - 0.5, b));
        ray r;
        r.origin = vec_add(target, away);
        r.dir = vec_normalize(vec_sub(target, r.origin));
        int shorter = 0;
        if (k % 7 == 0) {
            shorter = (int)(uniform(&s) * 600);
            r.dir = vec_scale(r.dir, ldexp(1, -shorter));
        }
        r.tmin = 0;
        r.tmax = INFINITY;
        hit out[4];
        feclearexcept(FE_ALL_EXCEPT);
        int n = isect_torus_hits(c, axis, major, minor, &r, out, 4);
        int raised = fetestexcept(FE_OVERFLOW | FE_INVALID | FE_DIVBYZERO) != 0;
        printf("%ld radii=%.1f shorter=%d raised=%d %d", k, log2(vec_length(vec_sub(r.origin, c)) / (major + minor)),
               shorter, raised, n);
        for (int i = 0; i < n; i++)
            printf(" %016llx %016llx %016llx %016llx %016llx %016llx %016llx", bits(out[i].t), bits(out[i].normal.x),
                   bits(out[i].normal.y), bits(out[i].normal.z), bits(out[i].point.x), bits(out[i].point.y),
                   bits(out[i].point.z));
        printf("\n");
    }
    return 0;
}
