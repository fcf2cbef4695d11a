#!/bin/sh
# conform_abs_dark.sh - [VERIFY-UNBOUNDED-3] bounds a manifest's tolerance
# by uniform scaling only (relative * peak + absolute < peak / 2).  A
# manifest that meets every rule of the spec (png16_scale 2^-15, a power of
# two; absolute 0.4 <= 1 / (65535 * 2^-15) = 0.50001; 0.0001 * 0.88 + 0.4 <
# 0.44) lets conform pass lambert_sphere's picture with every channel value
# below 0.4 set to 0 (the shadowed half and the dim rim black), while the
# picture shifted 10 pixels fails.
# Run from the repository root after nice make -j2 build/refray:
#   sh tests/attack13/conform_abs_dark.sh   # exit 1 when the dark picture passes
set -u
B=$(pwd)/${B:-build/refray}
D=$(mktemp -d)
cc -std=c99 -O2 -o "$D/pfmclip" tests/attack13/pfmclip.c || exit 2
nice "$B" kit -q -o "$D/kit" scenes/analytic/lambert_sphere.scene || exit 2
jq '.scenes[0].tolerance.absolute = 0.4 | .scenes[0].png16_scale = 0.000030517578125' \
    "$D/kit/manifest.json" > "$D/m" && mv "$D/m" "$D/kit/manifest.json" || exit 2
nice "$B" conform --kit "$D/kit" --format pfm \
    --cmd "$B render {scene} -q -o {out}.pfm && $D/pfmclip low {out}.pfm {out} 0.4"
rc=$?
nice "$B" render "$D/kit/scenes/lambert_sphere/lambert_sphere.scene" -q -o "$D/r.pfm"
"$D/pfmclip" low "$D/r.pfm" "$D/dark.pfm" 0.4
nice "$B" compare "$D/dark.pfm" "$D/kit/scenes/lambert_sphere/lambert_sphere.exact.pfm" --tolerance 0.01 | grep -i "pixels\|rms"
rm -rf "$D"
[ $rc -ne 0 ] && exit 0
echo "a picture black below 0.4 (peak 0.88) passed under a manifest that meets every rule (exit $rc)"
exit 1
