#!/bin/sh
# stacked_far.sh [T...] - stacked_sheets_cut (perspective, two translucent
# disks and a translucent plane over a floor, a point light between them)
# moved by [T, 0, T] whole: eye, look_at, light, planes' points and disks'
# centres (default T = 1e3 1e4 3e4 1e5).  The picture is the same; the error
# of refray's render against the oracle grows as the coordinates' rounding,
# 1.29e-13 T, but [ORACLE-VIEW-ROUNDING-1]'s floor, K u D / S with S at the
# nearest geometry 5 away, grows as 6.7e-17 T x 256: from T = 1e4 verify
# FAILs refray's render (error / (u D / S) about 1900, K = 256).  Exit 1 when
# verify FAILs at some T.
#   sh tests/attack15/stacked_far.sh [T...]
set -u
B=${B:-build/refray}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
[ $# -gt 0 ] || set -- 1e3 1e4 3e4 1e5
bad=0
for t in "$@"; do
    awk -v t="$t" '
    function move(key,   s, v, a) {
        if (!match($0, key " \\[[^]]*\\]"))
            return
        s = substr($0, RSTART, RLENGTH); v = substr(s, length(key) + 3, length(s) - length(key) - 3)
        split(v, a, ",")
        $0 = substr($0, 1, RSTART - 1) sprintf("%s [%.17g, %.17g, %.17g]", key, a[1] + t, a[2], a[3] + t) \
             substr($0, RSTART + RLENGTH)
    }
    { move("eye"); move("look_at"); move("position"); move("point"); move("center"); print }' \
        scenes/analytic/stacked_sheets_cut.scene > $T/s.scene
    v=$(nice $B verify $T/s.scene)
    echo "T=$t: $(echo "$v" | awk 'NR == 2 {print "max rel " $7 ", over " $9 ", tolerance " $10 ", " $NF}')"
    echo "$v" | awk 'NR == 2 { exit $NF != "FAIL" }' && bad=1
done
exit $bad
