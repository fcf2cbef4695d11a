#!/bin/sh
# hand_ties.sh - attack 23: [BVH-BEAM-1] on tied hits by hand.  1 .. 12
# exact copies of one part (disk, box, triangle, ball, mesh octahedron;
# past 8 the nearest walk's second pass) with a plane and a box top in the
# same plane, seen by a camera looking straight down (-y) or along -z (a
# direction component 0 in the centre column when the width is odd),
# widths 33 and 65, 1 and 3 x 3 samples, at scale 1 and 1e6 moved 1e9;
# and a ball grid behind them (pruned trees near the cap).  Each by the new
# binary on and off, the old and the base: images and exit codes.  Exit 1
# on a difference.  From the repository root after `make build/refray`.
set -u
B=${B:-$PWD/build/refray}
OLD=${OLD:-/tmp/old-main/build/refray}
BASE=${BASE:-/tmp/attack23-base/build/refray}
D=$(mktemp -d)
cp tests/attack20/octa.obj "$D/"
n=0 bad=0
for kind in disk box tri ball mesh; do
for copies in 1 8 9 12; do
for view in down z; do
for w in 33 65; do
for k in 1 3; do
for S in 1 1e6; do
    T=0; [ "$S" = 1 ] || T=1e9
    f=$D/s.scene
    awk -v kind=$kind -v copies=$copies -v view=$view -v w=$w -v k=$k -v S=$S -v T=$T '
    function P(x, y, z) { return sprintf("[%.17g, %.17g, %.17g]", T + x * S, y * S, z * S) }
    BEGIN {
        printf "image { width %d height 9 samples %d max_depth 2 }\n", w, k
        if (view == "down") printf "camera { perspective eye %s look_at %s up [0, 0, -1] fov 60 }\n", P(0, 5, 0), P(0, 0, 0)
        else printf "camera { perspective eye %s look_at %s up [0, 1, 0] fov 60 }\n", P(0, 0.5, 5), P(0, 0.5, 0)
        printf "point_light { position %s power %g }\n", P(1, 4, 2), 20 * S * S
        printf "plane { point %s normal [0, 1, 0] material { Kd 0.5 } }\n", P(0, 0, 0)
        printf "box { from %s to %s material { Kd [0.2, 0.7, 0.2] } }\n", P(-2, -1, -2), P(-0.5, 0, 2)
        for (i = 0; i < copies; i++) {
            m = sprintf("material { Kd [%g, 0.3, 0.3] Ks 0.2 n 20 }", 0.1 + i / 20)
            if (kind == "disk") printf "disk { center %s normal [0, 1, 0] radius %g %s }\n", P(0.5, 0, 0), 0.8 * S, m
            else if (kind == "box") printf "box { from %s to %s %s }\n", P(0, -0.5, -0.5), P(1, 0, 0.5), m
            else if (kind == "tri") printf "triangle { vertices %s %s %s %s }\n", P(0, 0, -1), P(1.5, 0, 0), P(0, 0, 1), m
            else if (kind == "ball") printf "sphere { center %s radius %g %s }\n", P(0.5, 0.5, 0), 0.5 * S, m
            else printf "mesh { file \"octa.obj\" %s scale %g translate %s }\n", m, 0.5 * S, P(0.5, 0.5, 0)
        }
        for (a = 0; a < 8; a++) for (b = 0; b < 8; b++)
            printf "sphere { center %s radius %g material { Kd 0.6 } }\n", P(a - 4, 0.2, b - 12), 0.2 * S
    }' > "$f"
    cp "$f" "$D/last.scene"
    ( cd "$D" && $B render s.scene -q -o on.pfm >/dev/null 2>&1 ); e1=$?
    ( cd "$D" && $B render s.scene -q --no-shortcuts -o off.pfm >/dev/null 2>&1 ); e2=$?
    ( cd "$D" && $OLD render s.scene -q -o old.pfm >/dev/null 2>&1 ); e3=$?
    ( cd "$D" && $BASE render s.scene -q -o base.pfm >/dev/null 2>&1 ); e4=$?
    n=$((n + 1)); msg=""
    [ $e1 = $e2 ] && [ $e1 = $e3 ] && [ $e1 = $e4 ] || msg="exit $e1 $e2 $e3 $e4"
    if [ $e1 = 0 ]; then
        cmp -s $D/on.pfm $D/off.pfm || msg="$msg on/off"
        cmp -s $D/on.pfm $D/old.pfm || msg="$msg new/old"
        cmp -s $D/on.pfm $D/base.pfm || msg="$msg new/base"
    fi
    [ -z "$msg" ] || { echo "hand_ties: $kind x$copies $view w $w k $k S $S: $msg"; bad=1; cp "$f" "$D/bad-$n.scene"; }
done; done; done; done; done; done
echo "hand_ties: $n scenes ($D)"
exit $bad
