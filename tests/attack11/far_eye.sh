#!/bin/sh
# far_eye.sh [SCENE...] - each orthographic scene with its eye K times as far
# from look_at along the same line (K = 1, 1e3, 1e5, 1e7, 1e9), checked by
# `refray verify`: its verdict, max rel, tolerance, and the error in units of
# u D / S (u = 2^-53, D = |eye| + |eye - look_at|, S = the view's width), the
# ratio that sets [ORACLE-VIEW-ROUNDING-1]'s constant (spec/verify.md).
# Default: every orthographic scene of scenes/analytic.
# Run from the repository root after nice make -j2 build/refray:
#   sh tests/attack11/far_eye.sh
set -u
B=${B:-build/refray}
D=$(mktemp -d)
[ $# -gt 0 ] || set -- $(grep -l 'camera.*orthographic' scenes/analytic/*.scene)
printf '%-28s %5s %8s %10s %10s %7s\n' scene K verdict "max rel" tolerance "err/uDS"
for s in "$@"; do
    for k in 1 1e3 1e5 1e7 1e9; do
        f=$D/$(basename "$s" .scene)_$k.scene
        awk -v k="$k" '/^camera/ && /orthographic/ {
            match($0, /eye \[[^]]*\]/); split(substr($0, RSTART + 5, RLENGTH - 6), E, ",")
            match($0, /look_at \[[^]]*\]/); split(substr($0, RSTART + 9, RLENGTH - 10), L, ",")
            sub(/eye \[[^]]*\]/, sprintf("eye [%.17g, %.17g, %.17g]", L[1] + k * (E[1] - L[1]),
                L[2] + k * (E[2] - L[2]), L[3] + k * (E[3] - L[3]))) } { print }' "$s" > "$f"
        "$B" verify --json "$f" 2>/dev/null | awk -v s="$(basename "$s" .scene)" -v k="$k" -v f="$f" '
            { for (i = 1; i <= NF; i++) t = t $i " " }
            END {
                v = t; sub(/.*"verdict": "/, "", v); sub(/".*/, "", v)
                if (v == "refused" || v == "error") { printf "%-28s %5s %8s\n", s, k, v; exit }
                m = t; sub(/.*"max_rel": /, "", m); sub(/,.*/, "", m)
                o = t; sub(/.*"tolerance": /, "", o); sub(/,.*/, "", o)
                while ((getline line < f) > 0)
                    if (line ~ /^camera/) cam = line
                match(cam, /eye \[[^]]*\]/); split(substr(cam, RSTART + 5, RLENGTH - 6), E, ",")
                match(cam, /look_at \[[^]]*\]/); split(substr(cam, RSTART + 9, RLENGTH - 10), L, ",")
                match(cam, /width [0-9.e+-]*/); w = substr(cam, RSTART + 6, RLENGTH - 6)
                de = sqrt(E[1] ^ 2 + E[2] ^ 2 + E[3] ^ 2)
                dl = sqrt((E[1] - L[1]) ^ 2 + (E[2] - L[2]) ^ 2 + (E[3] - L[3]) ^ 2)
                uds = 2 ^ -53 * (de + dl) / w
                printf "%-28s %5s %8s %10.3e %10.3e %7.2f\n", s, k, v, m, o, m / uds }'
    done
done
rm -rf "$D"
