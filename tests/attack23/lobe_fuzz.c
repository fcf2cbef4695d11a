/*
 * lobe_fuzz.c - attack 23: [SHADE-SHORTCUT-ABSORB-1]'s bound
 * trace_lobe_above(c, n) against libm's lobe shade_phong_lobe(V, R, n)
 * (pow and exp), with c = V.R formed as add_source forms it.  Each case:
 * unit N and L (vec_normalize of random vectors), R = shade_reflect_about(L,
 * N), and V = normalize(c* R + s W) for a target c* (W unit, across R),
 * or, in the "skew" mode (argv[3] = 1), V and R each scaled by 1 + e with
 * |e| up to 2^-21 (|a|^2 within the proofs' vunit 2^-20 of 1).  n: an
 * integer 1 .. 2^20, a fractional n, or n near 1, 2^k and 2^20; the target
 * c puts z = n (-ln c) log2(e) near an integer k (the bound 2^-floor(z)
 * at its tightest) or anywhere in (0, 1), near 0, 1/2 and 1.
 * A case where shade_phong_lobe > trace_lobe_above is a defect: printed,
 * exit 1.  Also prints the least ratio bound / lobe seen (how much room).
 *   cc -std=c99 -O2 -ffp-contract=off -Isrc -Ibuild/gen -o /tmp/lobef \
 *      tests/attack23/lobe_fuzz.c build/librefray-internal.a -ljansson -lm
 *   /tmp/lobef CASES [SEED [SKEW [MUTANT]]]
 * MUTANT (default 0: trace_lobe_above itself) takes a copy of it with one
 * change, to see that the fuzzer catches it: 1 2^-(floor(z) + 1), 2 no
 * n 2^-18 term, 3 no factor 1 - 2^-40, 4 the n 2^-18 term as n 2^-30.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include "base/vec.h"
#include "render/shade.h"
#include "render/trace.h"

#include "../fuzz_rng.h"
static vec3 rnd_unit(void)
{
    for (;;) {
        vec3 a = vec_make(2 * U() - 1, 2 * U() - 1, 2 * U() - 1);
        if (vec_length2(a) > 0.01 && vec_length2(a) <= 1)
            return vec_normalize(a);
    }
}

static int mutant;
static double lobe_mut(double c, double n)
{
    if (!(c > 0))
        return 0;
    if (!(c < 1 && n >= 1 && n < 0x1p20))
        return 1;
    double x = 1 - c, sum = x * (1 + x * (0.5 + x * 0.33333333333333));
    double z = n * sum * 1.44269504088896 * (mutant == 3 ? 1 : 1 - 0x1p-40) -
               (mutant == 2 ? 0 : n * (mutant == 4 ? 0x1p-30 : 0x1p-18));
    if (!(z >= 1))
        return 1;
    int e = (z < 1000 ? (int)z : 1000) + (mutant == 1);
    return ldexp(1, -e);
}

static double pick_n(void)
{
    switch (R64() % 8) {
    case 0: return (double)(1 + R64() % 64);
    case 1: return (double)(1 + R64() % (1u << 20));
    case 2: return 1 + U() * 100;                       /* fractional */
    case 3: return ldexp(1, (int)(R64() % 21)) + (R64() % 3) - 1.0;
    case 4: return nextafter(0x1p20, 0) - U() * 10;
    case 5: return 1 + U() * 1e-9;
    case 6: return exp(U() * log(0x1p20));
    default: return 1e5 * U() + 1;
    }
}

static double pick_c(double n)
{
    switch (R64() % 6) {
    case 0: {                                          /* z near an integer */
        double k = 1 + (double)(R64() % 1000);
        double zj = k + (U() - 0.5) * ldexp(1, -(int)(R64() % 40));
        return exp(-zj * log(2) / n);
    }
    case 1: return U();
    case 2: return 1 - ldexp(U(), -(int)(R64() % 53));
    case 3: return 0.5 + (U() - 0.5) * ldexp(1, -(int)(R64() % 50));
    case 4: return ldexp(U(), -(int)(R64() % 1000));
    default: return 0.75 + (U() - 0.5) * ldexp(1, -(int)(R64() % 50));
    }
}

int main(int argc, char **argv)
{
    long cases = argc > 1 ? atol(argv[1]) : 100000;
    rng = argc > 2 ? strtoull(argv[2], NULL, 10) : 1;
    int skew = argc > 3 ? atoi(argv[3]) : 0;
    mutant = argc > 4 ? atoi(argv[4]) : 0;
    double least_room = INFINITY;
    long tested = 0, bounded = 0, bad = 0;
    for (long i = 0; i < cases; i++) {
        vec3 nn = rnd_unit(), l = rnd_unit();
        if (vec_dot(nn, l) <= 0)
            l = vec_neg(l);
        vec3 r = shade_reflect_about(l, nn);
        double n = pick_n(), cs = pick_c(n);
        if (!(cs > 0 && cs < 1))
            continue;
        vec3 w = vec_normalize(vec_cross(r, rnd_unit()));
        vec3 v = vec_normalize(vec_add(vec_scale(r, cs), vec_scale(w, sqrt(1 - cs * cs))));
        if (skew) {
            v = vec_scale(v, 1 + (2 * U() - 1) * 0x1p-21);
            r = vec_scale(r, 1 + (2 * U() - 1) * 0x1p-21);
        }
        double c = vec_dot(v, r);
        if (!(c > 0))
            continue;
        double lobe = shade_phong_lobe(v, r, n), bound = mutant ? lobe_mut(c, n) : trace_lobe_above(c, n);
        tested++;
        if (bound < 1)
            bounded++;
        if (lobe > bound) {
            bad++;
            if (bad <= 10)
                printf("DEFECT: n %.17g c %.17g lobe %.17g > bound %.17g\n", n, c, lobe, bound);
        } else if (lobe > 0 && bound < 1 && bound / lobe < least_room)
            least_room = bound / lobe;
    }
    printf("lobe_fuzz: %ld cases, %ld with a bound below 1, %ld defects; least bound/lobe %.9g\n", tested, bounded,
           bad, least_room);
    return bad != 0;
}
