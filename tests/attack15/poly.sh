#!/bin/sh
# poly.sh [N] - judges refray's picture of each face of this directory
# (keyholes with one and two holes in both windings, a diagonal bridge, a
# hole touching the outer edge at a point, an inward slit, collinear runs:
# all held) and of a simple star polygon of N corners (default 32000, radii
# 1 and 1.9 alternating, one corner per equal sector) written by awk, by
# polyjudge.c (the even-odd rule at each pixel's centre).  Exit 1 when a
# face has a wrong pixel.
#   sh tests/attack15/poly.sh [N]
. tests/attack14/lib.sh
B=tests/attack15
cc -std=c99 -O1 $B/polyjudge.c -o $D/polyjudge || exit 2
awk -v n="${1:-32000}" 'BEGIN { for (i = 0; i < n; i++) { a = 6.283185307179586 * i / n; r = (i % 2) ? 1.9 : 1.0
    printf "v %.17g %.17g 0\n", 2 + r * cos(a), 2 + r * sin(a) }
    printf "f"; for (i = 1; i <= n; i++) printf " %d", i; print "" }' > $D/star.obj
bad=0
for f in keyhole_ccw keyhole_cw keyhole_two keyhole_two_cw keyhole_diag touch_hole slit collinear star; do
    [ $f = star ] || cp $B/$f.obj $D/
    sed "s/MESH/$f.obj/" $A/poly.scene > $D/$f.scene
    "$R" render $D/$f.scene -q -o $D/$f.pfm 2>&1 | grep -o 'warning: [^(]*'
    printf '%s: ' $f.obj
    $D/polyjudge $D/$f.obj $D/$f.pfm || bad=1
done
exit $bad
