#!/bin/sh
# hand_planes32.sh - attack 24: [SHADE-SHORTCUT-PLANE-1] at its 32-plane
# edge.  A floor lit by a rectangle light through (or past) a ceiling
# plane; before or after the ceiling, N planes below the floor that every
# bundle passes (N 0, 30, 31, 32, 33, 40), the ceiling at index N or 0;
# also the ceiling moved above the light (passed too: crosses_nothing
# where N + 2 <= 32).  Each image against the old binary and
# --no-shortcuts.  Exit 1 when any differs.
B=${B:-build/refray}
OLD=${OLD:-/tmp/old-main/build/refray}
D=$(mktemp -d)
bad=0 n=0
for N in 0 30 31 32 33 40; do
for where in first last; do
for ceil in 2 4 3; do
    f=$D/s.scene
    {
        echo 'image { width 16 height 12 samples 1 }'
        echo 'camera { perspective eye [0, 1, 6] look_at [0, 0, 0] up [0, 1, 0] fov 60 }'
        echo 'ambient { color 0.05 }'
        echo 'plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0.8 } }'
        [ $where = first ] && echo "plane { point [0, $ceil, 0] normal [0, -1, 0] material { Kd 0.5 } }"
        i=0; while [ $i -lt $N ]; do echo "plane { point [0, -$((i + 1)), 0] normal [0, 1, 0] material { Kd 0.5 } }"; i=$((i + 1)); done
        [ $where = last ] && echo "plane { point [0, $ceil, 0] normal [0, -1, 0] material { Kd 0.5 } }"
        echo 'sphere { center [3, 1, -3] radius 0.3 material { Kd 0.5 } }'
        echo 'distributed_light { rectangle [-0.5, 3, -0.5] [1, 0, 0] [0, 0, 1] power 40 samples 4 }'
    } > $f
    n=$((n + 1))
    $B render $f -q -o $D/on.pfm 2>/dev/null; e1=$?
    $B render $f -q --no-shortcuts -o $D/off.pfm 2>/dev/null; e2=$?
    $OLD render $f -q -o $D/old.pfm 2>/dev/null; e3=$?
    msg=""
    [ $e1 = $e2 ] && [ $e1 = $e3 ] || msg="exit $e1 $e2 $e3"
    cmp -s $D/on.pfm $D/off.pfm || msg="$msg on/off"
    cmp -s $D/on.pfm $D/old.pfm || msg="$msg new/old"
    [ -n "$msg" ] && { echo "N $N ceiling $where at y $ceil: $msg"; bad=1; }
done; done; done
rm -rf $D
echo "hand_planes32: $n scenes"
exit $bad
