#!/bin/sh
# The sweep of spec/numerics.md 2.14 for flat cones (tests/attack11, finding
# 3): a closed and an open cone of height 1 and radius R (the aspect R),
# R = 1e2 .. 1e12, seen by an orthographic eye F R away, F = 10, 1e3, 1e5,
# against its base disk alone from the same eye.  From above the cone
# covers exactly what the disk covers (the apex projects inside the disk),
# and its side's normal is within atan(1/R) of the disk's, so a channel
# differs by at most Kd power atan(1/R) <= 2.1/R (Kd <= 0.7, power 3), at
# most 2.5/R of its value (every lit channel is at least 0.85): the bound
# is 4/R relative, plus 2^-22 for the PFM's float (a pixel drawn outside
# the disk, or a hole, is 18 times its value off).  Each render is also
# compared with its own --no-shortcuts render (cmp).  Exits 1 on any
# departure.
#   sh tests/flat_cone/sweep.sh [REFRAY]
set -u
refray=${1:-build/refray}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/../sweep_mark.sh"
scene() { # FILE R F SHAPE
    d=$(awk -v r="$2" -v f="$3" 'BEGIN { printf "%.17g %.17g", 0.6 * f * r, 0.8 * f * r }')
    w=$(awk -v r="$2" 'BEGIN { printf "%.17g", 3 * r }')
    { echo "image { width 16 height 12 max_depth 2 background [0.1, 0.1, 0.2] }"
      echo "camera { orthographic eye [${d% *}, ${d#* }, 0] look_at [0, 0, 0] up [0, 1, 0] width $w }"
      echo "ambient { color 0.2 }"
      echo "distant_light { direction [-0.5, -1, 0.2] power 3 }"
      case $4 in
      disk) echo "disk { center [0, -0.5, 0] normal [0, 1, 0] radius $2 material { Kd [0.7, 0.5, 0.3] } }" ;;
      cone) echo "cone { from [0, -0.5, 0] to [0, 0.5, 0] radii $2 0 material { Kd [0.7, 0.5, 0.3] } }" ;;
      open) echo "cone { from [0, -0.5, 0] to [0, 0.5, 0] radii $2 0 open material { Kd [0.7, 0.5, 0.3] } }" ;;
      esac; } >"$1"
}
fail=0
echo "R F shape: pixels over 4/R + 2^-22 against the disk (* : --no-shortcuts differs)"
for r in 1e2 1e3 1e4 1e5 1e6 1e7 3e7 5e7 1e8 1e9 1e10 1e11 1e12; do
    tol=$(awk -v r="$r" 'BEGIN { printf "%.17g", 4 / r + 2 ^ -22 }')
    for f in 10 1e3 1e5; do
        scene "$tmp/disk.scene" "$r" "$f" disk
        "$refray" render "$tmp/disk.scene" -q -o "$tmp/disk.pfm" || exit 1
        line="$r $f:"
        for s in cone open; do
            scene "$tmp/$s.scene" "$r" "$f" $s
            "$refray" render "$tmp/$s.scene" -q -o "$tmp/$s.pfm" || exit 1
            "$refray" render "$tmp/$s.scene" -q --no-shortcuts -o "$tmp/${s}_ns.pfm" || exit 1
            n=$("$refray" compare "$tmp/$s.pfm" "$tmp/disk.pfm" --tolerance "$tol" --json |
                sed -n 's/.*"over": *\([0-9]*\).*/\1/p')
            line="$line $s"
            mark "$n" "$tmp/$s.pfm" "$tmp/${s}_ns.pfm"
        done
        echo "$line"
    done
done
[ $fail = 0 ] && echo "flat cone sweep: ok" || echo "flat cone sweep: FAIL"
exit $fail
