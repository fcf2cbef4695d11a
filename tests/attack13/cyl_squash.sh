#!/bin/sh
# cyl_squash.sh - a closed cylinder squashed by its frame to heights near
# 1e-161 ([NUM-FRAME-2], spec/numerics.md 2.17a, which measures s down to
# 1e-300 from straight above only), seen obliquely with ambient light only:
# must be the flat unit disk's image (cyl_flat.scene) at every s (geometry:
# the silhouette is the unit disk to s, every visible point Kd Ia).  The
# sphere, cone (radii 1, 1.0000001) and the same view are checked alongside.
# Prints the pixels that differ per s; exits 1 when any does.
#   sh tests/attack13/cyl_squash.sh
set -u
B=${B:-build/refray}
T=$(mktemp -d)
D=tests/attack13
nice $B render $D/cyl_flat.scene -q -o $T/flat.pfm || exit 2
fail=0
for sh in "sphere { center [0, 0, 0] radius 1" "cone { from [0, -1, 0] to [0, 1, 0] radii 1 1.0000001" \
          "cylinder { from [0, -1, 0] to [0, 1, 0] radius 1"; do
    line="${sh%% *}:"
    for e in 1e-150 1e-160 1.5e-162 2e-162 3e-162 5e-162 1e-170 1e-300; do
        sed "s/^cylinder.*/$sh scale [1, $e, 1] material { Kd 0.8 } }/" $D/cyl_squash.scene > $T/x.scene
        nice $B render $T/x.scene -q -o $T/x.pfm || exit 2
        nice $B render $T/x.scene -q --no-shortcuts -o $T/n.pfm || exit 2
        n=$($B compare $T/x.pfm $T/flat.pfm | sed -n 's/^differ: *\([0-9]*\).*/\1/p')
        [ "${n:-0}" = 0 ] || fail=1
        cmp -s $T/x.pfm $T/n.pfm && m="" || { m="*"; fail=1; }
        line="$line $e:${n:-0}$m"
    done
    echo "$line"
done
echo "(pixels differing from the flat disk; * --no-shortcuts differs)"
rm -rf $T
exit $fail
