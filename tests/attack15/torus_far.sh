#!/bin/sh
# torus_far.sh [K...] - lambert_torus and lambert_torus_edge with the
# orthographic eye K times as far from look_at on the same line (default
# K = 1e10; the eye then about 1e11 away).  The oracle's far image equals
# its stock one to ~1e-4; refray's far render is compared with its own
# stock render.  Exit 1 when refray's far render is more than 1e-3 off its
# own stock one (a torus missed, not the view's rounding) while the
# oracle's is within 1e-3.
#   sh tests/attack15/torus_far.sh [K...]
set -u
B=${B:-build/refray}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
[ $# -gt 0 ] || set -- 1e10
bad=0
for s in lambert_torus lambert_torus_edge; do
    nice $B render scenes/analytic/$s.scene -q -o $T/rn.pfm && nice $B oracle scenes/analytic/$s.scene -o $T/on.pfm > /dev/null || exit 2
    for k in "$@"; do
        awk -v k="$k" '/^camera/ && /orthographic/ {
            match($0, /eye \[[^]]*\]/); split(substr($0, RSTART + 5, RLENGTH - 6), E, ",")
            match($0, /look_at \[[^]]*\]/); split(substr($0, RSTART + 9, RLENGTH - 10), L, ",")
            sub(/eye \[[^]]*\]/, sprintf("eye [%.17g, %.17g, %.17g]", L[1] + k * (E[1] - L[1]),
                L[2] + k * (E[2] - L[2]), L[3] + k * (E[3] - L[3]))) } { print }' scenes/analytic/$s.scene > $T/f.scene
        nice $B render $T/f.scene -q -o $T/rf.pfm && nice $B oracle $T/f.scene -o $T/of.pfm > /dev/null || exit 2
        r=$($B compare $T/rn.pfm $T/rf.pfm | awk '/^max abs/ {print $3, $6}')
        o=$($B compare $T/on.pfm $T/of.pfm | awk '/^max abs/ {print $3}')
        v=$(nice $B verify $T/f.scene | awk 'NR == 2 {print "max rel " $7 ", tolerance " $10 ", " $NF}')
        echo "$s K=$k: refray far vs near max abs ${r% *} at ${r#* }; oracle far vs near $o; verify: $v"
        awk -v r="${r% *}" -v o="$o" 'BEGIN { exit !(r > 1e-3 && o < 1e-3) }' && bad=1
    done
done
exit $bad
