#!/bin/sh
# spawn_grazing.sh [EYE_Y:T...] - scenes/analytic/transparent_shadow.scene (a
# glass ball, ior 1, over a floor, a point light, max_depth 4) with its eye
# lowered to [0, EYE_Y, 9] (looking at [0, 0.6, 0], the ball and the floor
# behind it at a grazing angle), the whole scene then moved by [T, 0, T].
# refray's render against the oracle at 400x300:
#   EYE_Y 0.1, T = 0:   2.8e-11, pass;   T = 1e3: 1.540e-8 (8 pixels over
#   1.32e-9), FAIL; at --max-depth 2: 5.3e-8, 72 pixels; --max-depth 1: 2.8e-12.
#   EYE_Y 0.4, T = 1e3: 5.1e-9 (21 pixels over 1e-9), FAIL; EYE_Y 3, T = 1e3: pass.
# The long double build gives the same 1.540e-8: the spawn offset
# ([NUM-SPAWN-1]), not double rounding; 23aaeed FAILs too (7 pixels, its
# tolerance 1.36e-9).  [ORACLE-VIEW-ROUNDING-3] assumes a secondary ray
# started delta off "meets the next surface about delta aside"; a ray through
# the ball meeting the floor at a grazing angle meets it delta / sin(angle)
# aside (likely the mechanism: the failures need the low eye), so the lit
# point moves far more than the term allows.
# Status: fixed ([ORACLE-VIEW-ROUNDING-4], spec/verify.md): exits 0.
# Exit 1 while verify FAILs at some case (default 0.1:1e3 and 0.4:1e3).
#   sh tests/attack17/spawn_grazing.sh [EYE_Y:T...]
set -u
B=${B:-build/refray}
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
[ $# -gt 0 ] || set -- 0.1:1e3 0.4:1e3
bad=0
for p in "$@"; do
    y=${p%%:*} t=${p#*:}
    sed "s/eye \[0, 3, 5\]/eye [0, $y, 9]/" scenes/analytic/transparent_shadow.scene |
        awk -v t="$t" -f tests/attack17/shift.awk > "$D/s.scene"
    grep -q "eye \[" "$D/s.scene" || { echo "scene not as expected"; exit 2; }
    v=$(nice $B verify "$D/s.scene" --width 400 --height 300)
    echo "eye y $y, T=$t: $(echo "$v" | awk 'NR == 2 {print "max rel " $7 ", over " $9 ", tolerance " $10 ", " $NF}')"
    echo "$v" | awk 'NR == 2 { exit $NF != "FAIL" }' && bad=1
done
exit $bad
