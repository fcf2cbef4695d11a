#!/bin/sh
# conform_abs_unbounded.sh - a manifest whose tolerance.absolute is 10 (the
# peak of lambert_sphere is 0.88) loads, and conform passes an all-black
# picture with "max rel 1.000".  [VERIFY-UNBOUNDED-1] refuses a relative
# bound of 1 or more as no verdict (manifest_read says so), but an absolute
# bound of the peak or more is the same non-verdict and is taken; nor is it
# checked against png16_scale (spec: absolute = 1 / (65535 png16_scale)),
# and png16_scale 3 (spec: a power of two) loads too.
# Run from the repository root after nice make -j2 build/refray:
#   sh tests/attack12/conform_abs_unbounded.sh   # exit 1 when black passes
set -u
B=$(pwd)/${B:-build/refray}
D=$(mktemp -d)
cc -std=c99 -O2 -o "$D/pfmtool" tests/attack12/pfmtool.c -lm || exit 2
"$B" kit -q -o "$D/kit" scenes/analytic/lambert_sphere.scene || exit 2
jq '.scenes[0].tolerance.absolute = 10 | .scenes[0].png16_scale = 3' "$D/kit/manifest.json" > "$D/m" &&
    mv "$D/m" "$D/kit/manifest.json" || exit 2
"$B" conform --kit "$D/kit" --format pfm --cmd "$B render {scene} -q -o {out}.pfm && $D/pfmtool scale {out}.pfm {out} 0"
rc=$?
rm -rf "$D"
[ $rc -ne 0 ] && exit 0
echo "an all-black picture passed under an edited absolute tolerance (exit $rc)"
exit 1
