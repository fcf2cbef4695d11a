#!/bin/sh
# make_scenes.sh DIR - writes attack 22's hand scenes into DIR.
# dark_*: [SHADE-SHORTCUT-DARK-2]: a disk light standing across the floor
# (its lower cells below the floor's plane, dark at every floor point, its
# upper ones lit), nearly in the floor's plane (tilted 1e-9 .. 0.01), tilted
# over Kd = 0 spheres and boxes with lobes n 1 .. 1e6, 4, 7 (one row),
# 64 and 4096 samples (two disks of 4096: the second past TRACE_CELLS_MAX),
# at scales 1e-6, 1, 1e6, moved by 0, 1e9 and 1e12 (not 1e-6 at 1e12).  Compared by
# cmp_hand.sh.
set -u
D=$1
mkdir -p "$D"
for S in 1 1e-6 1e6; do
for T in 0 1e9 1e12; do
for L in across flat tilt; do
for N in 4 7 64 4096; do
    # 1e-6 across at 1e12 is below the doubles' spacing there (refused, 65)
    [ "$S" = 1e-6 ] && [ "$T" = 1e12 ] && continue
    awk -v S="$S" -v T="$T" -v L="$L" -v NS="$N" 'function W(x, y, z) { return sprintf("[%.17g, %.17g, %.17g]", T + S * x, T + S * y, T + S * z) }
    BEGIN {
        print "image { width 32 height 24 samples 1 max_depth 3 background [0.1, 0.1, 0.1] }"
        printf "camera { perspective eye %s look_at %s up [0, 1, 0] fov 60 }\n", W(0, 3, 6), W(0, 0.3, 0)
        print "ambient { color 0.02 }"
        print "material floor { Kd 0.8 }"
        print "material shiny { Kd 0 Ks 0.9 n 1000000 }"
        print "material soft { Kd 0 Ks 0.7 n 1 }"
        print "material mid { Kd 0 Ks 0.8 n 30 }"
        print "material lam { Kd 0.5 Ks 0.3 n 5 }"
        printf "plane { point %s normal [0, 1, 0] material floor }\n", W(0, 0, 0)
        printf "sphere { center %s radius %.17g material shiny }\n", W(-1.2, 0.5, 0), 0.5 * S
        printf "sphere { center %s radius %.17g material soft }\n", W(1.2, 0.5, 0), 0.5 * S
        printf "sphere { center %s radius %.17g material lam }\n", W(0, 0.4, 1.2), 0.4 * S
        printf "box { from %s to %s material mid }\n", W(-0.4, 0, -1.6), W(0.4, 0.8, -0.8)
        if (L == "across") {
            printf "distributed_light { disk %s [1, 0, 0] %.17g power %.17g samples %d }\n", W(2.2, 0.3, -0.5), 1 * S, 40 * S * S, NS
            printf "distributed_light { disk %s [0.3, -1, -0.7] %.17g power %.17g samples %d }\n", W(-2, 0.5, 1), 0.9 * S, 30 * S * S, NS
        } else if (L == "flat") {
            printf "distributed_light { disk %s [0.01, -1, 0] %.17g power %.17g samples %d }\n", W(0, 0.02, -2.5), 2 * S, 40 * S * S, NS
            printf "distributed_light { disk %s [1e-9, 1, 0] %.17g power %.17g samples %d }\n", W(0, 1e-6, 2.5), 1.5 * S, 30 * S * S, NS
        } else {
            printf "distributed_light { disk %s [1, -1, 0.3] %.17g power %.17g samples %d }\n", W(-1.5, 2.5, 1), 1 * S, 40 * S * S, NS
            printf "distributed_light { disk %s [-1, -1e-9, 0] %.17g power %.17g samples %d }\n", W(0.5, 1, 0), 0.6 * S, 30 * S * S, NS
        }
    }' > "$D/dark_${L}_n${N}_S${S}_T${T}.scene"
done
done
done
done
