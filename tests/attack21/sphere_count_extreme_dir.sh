#!/bin/sh
# sphere_count_extreme_dir.sh - [NUM-SPHERE-3]: a world-frame sphere's
# count (isect_part_crossings, isect_hot_crossings: sphere_root_clear takes
# a far origin's root unrefined) must equal the refined roots' count
# (isect_part_all).  spec/numerics.md 2.1b's step 1 bounds the second
# solve's roots by (|F| + R)(1 + 2^-18) / |d| for R >= 2^-400 and |F| <= 4R
# only; it takes root = sqrt(a gap) sqrt(R + ll) as rounded normally.  For
# a direction far from unit length a gap leaves the normal range:
#  1. |d| = 2^-401 (a = 2^-802), R = 2^-267: a gap is subnormal, the first
#     solve's roots lie inside the chord (the root's half-width read from a
#     5-bit number), the refine steps by about R / |d| and the count takes
#     2 where the refined roots give 1 (tmin just past the refined entry).
#  2. |d| about 2^455, R = 2^116: a gap overflows, the second solve's far
#     root is +inf, the refined exit is +inf (outside (-inf, inf)): 1
#     refined against 2 counted.
# Not reached by a render: the tracer's shadow rays have unit directions
# (ray_shadow_to) or |dir| in [0.125, 7] (ray_shadow_along), where
# attack 21's sphere_fuzz finds nothing (scales 2^-1018 .. 2^1018).  Exits
# 1 while either case differs, 0 when the count agrees with the refined
# roots (e.g. sphere_root_clear also asking a |d|_max in a range where a gap
# stays normal).  From the repository root after `make build/refray`.
set -u
T=$(mktemp -d)
cat > "$T/r.c" <<'EOC'
#include <math.h>
#include <stdio.h>
#include "render/intersect.h"
#include "scene/scene.h"
static int differs(vec3 c, double radius, vec3 o, vec3 d, double tmin, double tmax)
{
    scene_prim p = {0};
    p.kind = PRIM_SPHERE, p.mesh = -1, p.u.sphere.center = c, p.u.sphere.radius = radius;
    ray r = {o, d, tmin, tmax};
    hit full[ISECT_MAX_CROSSINGS];
    real g[ISECT_HOT_REALS];
    int reals, code = isect_hot_make(&p, 0, g, &reals);
    int refined = isect_part_all(&p, 0, &r, full), count = isect_part_crossings(&p, 0, &r);
    int hot = isect_hot_crossings(code, g, &r, NULL);
    printf("refined %d, count %d, hot %d\n", refined, count, hot);
    return count != refined || (tmin >= 0 && hot != refined);
}
int main(void)
{
    int bad = differs(vec_make(0x1.949dfee56af26p-212, 0x1.05f824ef4fbcdp-212, 0x1.0feca4124e21bp-210),
                      0x1.835201fe39a9ap-267,
                      vec_make(0x1.949dfee56af26p-212, 0x1.05f824ef4fbcep-212, 0x1.0feca4124e21bp-210),
                      vec_make(0, -0x1.4b408044980edp-401, 0), 0x1.ec127f4a9c4bap+135, 0x1.10aa02af846bp+137);
    bad |= differs(vec_make(-0x1.3c5c4f6186a6ap+164, -0x1.f9f3e7ccbc9a7p+169, -0x1.42a530dce2811p+168),
                   0x1.1abe55e61fb61p+116,
                   vec_make(-0x1.3c5c4f6534876p+164, -0x1.f9f3e7cc6bd57p+169, -0x1.42a530dd063d2p+168),
                   vec_make(0x1.44ee5cafaf5edp+453, -0x1.bdd39e366f833p+454, 0x1.8a7dcff56142p+452), -HUGE_VAL, HUGE_VAL);
    return bad;
}
EOC
cc -std=c99 -O2 -ffp-contract=off -Isrc -Ibuild/gen -o "$T/r" "$T/r.c" build/librefray-internal.a -ljansson -lm 2>/dev/null ||
    { echo "sphere_count_extreme_dir: does not build"; rm -rf "$T"; exit 2; }
"$T/r"
rc=$?
rm -rf "$T"
[ $rc = 0 ] && echo "sphere_count_extreme_dir: the counts agree" || echo "sphere_count_extreme_dir: DEFECT: a count differs from the refined roots'"
exit $rc
