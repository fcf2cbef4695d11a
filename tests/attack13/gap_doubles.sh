#!/bin/sh
# gap_doubles.sh SCENE...: gap2.sh in the exact doubles of the tile sidecar
# (`--tile 0/1`): for each scene (first line `let g = 0`) prints
# |v(0) - v(1e-9)| and the bound 2 |v(2e-9) - v(1e-9)| + 1e-12 of
# spec/numerics.md 2.8a, and exits 1 when some scene exceeds it.
set -u
B=${B:-build/refray}
T=$(mktemp -d)
cc -std=c99 -O2 -o $T/tilediff tests/attack13/tilediff.c -lm || exit 2
bad=0
for S in "$@"; do
    d=$(dirname "$S")
    for g in 0 1e-9 2e-9; do
        sed "1s/^let g = 0\$/let g = $g/" "$S" > "$d/.gd$$.$g.scene"
        nice $B render "$d/.gd$$.$g.scene" --tile 0/1 -q -o $T/r$g.pfm 2>/dev/null || echo "$S g=$g: render failed"
        rm -f "$d/.gd$$.$g.scene"
    done
    a=$($T/tilediff $T/r0.pfm.tile $T/r1e-9.pfm.tile | sed 's/.*max abs \([^ ]*\).*/\1/')
    b=$($T/tilediff $T/r2e-9.pfm.tile $T/r1e-9.pfm.tile | sed 's/.*max abs \([^ ]*\).*/\1/')
    ok=$(awk -v a="$a" -v b="$b" 'BEGIN { print (a <= 2 * b + 1e-12) ? "within" : "OVER" }')
    [ "$ok" = within ] || bad=1
    echo "$(basename $S): touch-gap $a, bound $(awk -v b="$b" 'BEGIN { printf "%.3e", 2 * b + 1e-12 }'): $ok"
done
rm -rf $T
exit $bad
