#!/bin/sh
# moved_far.sh [SCENE:T...] - a scene of scenes/analytic moved by [T, 0, T]
# whole (eye, look_at, lights, planes' points, centres, from and to), so its
# picture is the same; default stacked_sheets_cut at T = 1e3, 1e4, 3e4, 1e5
# and transparent_shadow at 1e4, 1e5 (perspective; translucent sheets or a
# glass ball between a point light and a floor).  The error of refray's
# render against the oracle grows as the coordinates' rounding (1.29e-13 T
# for stacked_sheets_cut, 6e-14 T for transparent_shadow), faster than
# [ORACLE-VIEW-ROUNDING-1]'s floor K u D / S (S at the nearest geometry,
# about 5 away): verify FAILs refray's render, the error about 1900 and 700
# times u D / S against K = 256.  Exit 1 when verify FAILs at some T.
#   sh tests/attack15/moved_far.sh [SCENE:T...]
set -u
B=${B:-build/refray}
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
[ $# -gt 0 ] || set -- stacked_sheets_cut:1e3 stacked_sheets_cut:1e4 stacked_sheets_cut:3e4 stacked_sheets_cut:1e5 \
    transparent_shadow:1e4 transparent_shadow:1e5
bad=0
for p in "$@"; do
    s=${p%:*} t=${p##*:}
    awk -v t="$t" '
    function move(key,   s, v, a) {
        if (!match($0, key " \\[[^]]*\\]"))
            return
        s = substr($0, RSTART, RLENGTH); v = substr(s, length(key) + 3, length(s) - length(key) - 3)
        split(v, a, ",")
        $0 = substr($0, 1, RSTART - 1) sprintf("%s [%.17g, %.17g, %.17g]", key, a[1] + t, a[2], a[3] + t) \
             substr($0, RSTART + RLENGTH)
    }
    { move("eye"); move("look_at"); move("position"); move("point"); move("center"); move("from"); move("to")
      print }' scenes/analytic/$s.scene > $D/s.scene
    v=$(nice $B verify $D/s.scene)
    echo "$s T=$t: $(echo "$v" | awk 'NR == 2 {print "max rel " $7 ", over " $9 ", tolerance " $10 ", " $NF}')"
    echo "$v" | awk 'NR == 2 { exit $NF != "FAIL" }' && bad=1
done
exit $bad
