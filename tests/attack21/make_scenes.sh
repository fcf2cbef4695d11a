#!/bin/sh
# make_scenes.sh DIR - writes attack 21's hand scenes into DIR: spheres
# whose shadow-ray counts take [NUM-SPHERE-3]'s unrefined roots (far,
# tiny, grazed, with a light on or just off a sphere's surface so that a
# root lies at the shadow ray's tmax, transparent so that the counts feed
# the transmission), at scales 1e-6 .. 1e6 moved to 1e8; and glass, mirrors
# and distributed lights at depth (glass19's child_key).  Compared by
# cmp_hand.sh.
set -u
D=$1
mkdir -p "$D"
for S in 1 1e-6 1e6; do
for T in 0 1e8; do
for L in on off graze; do
    awk -v S="$S" -v T="$T" -v L="$L" 'function W(x) { return sprintf("%.17g", T + S * x) }
    function N(x) { return sprintf("%.17g", S * x) }
    BEGIN {
        print "image { width 64 height 48 samples 1 max_depth 6 background [0.1, 0.1, 0.1] }"
        printf "camera { perspective eye [%s, %s, %s] look_at [%s, %s, %s] up [0, 1, 0] fov 50 }\n", W(0), W(3), W(8), W(0), W(0.5), W(0)
        print "material floor { Kd 0.8 }"
        print "material clear { Kd 0.1 t 0.8 ior 1 }"
        print "material glass { Kd 0 Ks 0.05 n 200 t 0.95 ior 1.5 }"
        print "material opaque { Kd 0.5 }"
        printf "plane { point [%s, %s, %s] normal [0, 1, 0] material floor }\n", W(0), W(0), W(0)
        # the light on the surface of sphere 0 (a root at every shadow ray tmax), just off it, or at a graze height
        lx = 0.3; ly = 4; lz = 0.2; r0 = 0.25
        if (L == "on") cy = ly - r0; else if (L == "off") cy = ly - r0 * (1 + 1e-12); else cy = ly - 1.7
        printf "point_light { position [%s, %s, %s] power 30 }\n", W(lx), W(ly), W(lz)
        printf "sphere { center [%s, %s, %s] radius %s material clear }\n", W(lx), W(cy), W(lz), N(r0)
        # tiny spheres far up a line to the light, and a row of grazed ones
        for (i = 1; i <= 12; i++) {
            r = 10 ^ (-i / 2)
            printf "sphere { center [%s, %s, %s] radius %s material %s }\n", W(lx * (1 - i / 13)), W(ly * (1 - i / 13) + r * 0.999999999), W(lz * (1 - i / 13)), N(r), (i % 2 ? "clear" : "opaque")
        }
        for (i = 0; i < 8; i++)
            printf "sphere { center [%s, %s, %s] radius %s material clear }\n", W(-2 + 0.5 * i), W(0.6), W(-1), N(0.3)
        # nested glass
        printf "sphere { center [%s, %s, %s] radius %s material glass }\n", W(1.5), W(1), W(1), N(0.9)
        printf "sphere { center [%s, %s, %s] radius %s material clear }\n", W(1.6), W(1.1), W(1.1), N(0.4)
    }' > "$D/sphere_${L}_S${S}_T${T}.scene"
done
done
done
# glass19: glass and mirrors at depth under distributed lights (keys mixed) and without (keys passed on)
for K in rect disk point; do
for DEP in 3 12; do
    awk -v K="$K" -v DEP="$DEP" 'BEGIN {
        printf "image { width 64 height 48 samples 2 max_depth %d background [0.2, 0.25, 0.35] }\n", DEP
        print "camera { perspective eye [0, 2.2, 6] look_at [0, 1, 0] up [0, 1, 0] fov 45 }"
        print "material light { Kd 0.85 }"
        print "material mirror { Kd 0 Ks 0.9 n 1000 }"
        print "material glass { Kd 0 Ks 0.05 n 300 t 0.95 ior 1.5 }"
        print "material air { Kd 0 Ks 0 t 1 ior 1.0 }"
        print "plane { point [0, 0, 0] normal [0, 1, 0] material light }"
        print "sphere { center [0, 1.2, 0] radius 1.2 material glass }"
        print "sphere { center [0.45, 1.45, 0.3] radius 0.35 material air }"
        print "sphere { center [-2.5, 1, -1] radius 1 material mirror }"
        print "box { from [1.8, 0, -2] to [2.2, 3, 2] material mirror }"
        if (K == "rect") print "distributed_light { rectangle [-1, 5, -1] [2, 0, 0] [0, 0, 2] power 30 samples 5 }"
        else if (K == "disk") print "distributed_light { disk [0, 5, 1] [0, -1, 0] 0.7 power 30 samples 7 }"
        print "point_light { position [3, 6, 4] power 20 }"
    }' > "$D/glass_${K}_d${DEP}.scene"
done
done
