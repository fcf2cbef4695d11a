#!/bin/sh
# poly.sh - builds polyjudge.c and judges, pixel by pixel against the
# even-odd rule at each centre, the faces of this directory (keyholes with
# one and two holes in both windings, a diagonal bridge, a hole touching
# the outer edge at a point, an inward slit, collinear runs: all held) and
# a simple star polygon of N corners (default 32000, radii 1 and 1.9
# alternating) written by awk.  Exit 1 when a face has a wrong pixel.
#   sh tests/attack15/poly.sh [N]
set -u
R=$(pwd)/${REFRAY:-build/refray}
A=$(pwd)/tests/attack15
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
cc -std=c99 -O1 "$A/polyjudge.c" -o "$D/polyjudge" || exit 2
awk -v n="${1:-32000}" 'BEGIN { for (i = 0; i < n; i++) { a = 6.283185307179586 * i / n; r = (i % 2) ? 1.9 : 1.0
    printf "v %.17g %.17g 0\n", 2 + r * cos(a), 2 + r * sin(a) }
    printf "f"; for (i = 1; i <= n; i++) printf " %d", i; print "" }' > "$D/star.obj"
"$D/polyjudge" "$R" "$D" "$A"/keyhole_ccw.obj "$A"/keyhole_cw.obj "$A"/keyhole_two.obj "$A"/keyhole_two_cw.obj \
    "$A"/keyhole_diag.obj "$A"/touch_hole.obj "$A"/slit.obj "$A"/collinear.obj "$D/star.obj" > "$D/out" 2>&1; rc=$?; grep -v "^ " "$D/out"; exit $rc
