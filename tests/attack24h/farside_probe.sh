#!/bin/sh
# farside_probe.sh - attack 24h: the scenes that tell the `farside` mutant
# of mutants.py (highlight_above's falloff taken at the ball's far side)
# from the real bound: a Kd 0 Ks 1 n 1 mirror floor over a white
# background under a disk of radius 1 0.01 above it (16 samples,
# inverse_square, powers 1e-17 .. 3.2e-17) and under a 4 x 0.001 rectangle
# 0.02 above it (power 1.8e-16): rendered in double through the API
# (dbl_cmp.c) with the shortcuts on and off.  LIB: the library (default
# build/librefray-internal.a).  Exit 1 when on and off differ (the mutant:
# 2 of the 4 scenes differ (s3, s4); the real code: none).  A Check test made
# of these would pin the intensity bound, which no test in make check does.
set -u
LIB=${LIB:-build/librefray-internal.a}
D=$(mktemp -d)
cc -std=c99 -O2 -Iinclude -o $D/dbl tests/attack24h/dbl_cmp.c "$LIB" -ljansson -lm 2>/dev/null || exit 2
i=0
for l in "disk [0, 0.01, -0.5] [0, -1, 0] 1 power 1e-17 samples 16 falloff inverse_square" \
         "disk [0, 0.01, -0.5] [0, -1, 0] 1 power 1.8e-17 samples 16 falloff inverse_square" \
         "disk [0, 0.01, -0.5] [0, -1, 0] 1 power 3.2e-17 samples 16 falloff inverse_square" \
         "rectangle [-2, 0.02, -0.5] [4, 0, 0] [0, 0, 0.001] power 1.8e-16 samples 16 falloff inverse_square"; do
    i=$((i + 1))
    cat > $D/s$i.scene <<EOS
image { width 32 height 24 max_depth 2 background [1, 1, 1] }
camera { perspective eye [0, 1.5, 3] look_at [0, 0, -0.5] up [0, 1, 0] fov 60 }
plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0 Ks 1 n 1 t 0 } }
sphere { center [-5, 0.5, -8] radius 0.3 material { Kd 0.5 } }
distributed_light { $l }
EOS
done
$D/dbl 0 0 $D/s1.scene $D/s2.scene $D/s3.scene $D/s4.scene > $D/out.txt; e=$?
sed "s#$D/##" $D/out.txt
rm -rf $D
exit $e
