#!/bin/sh
# conform_masked_nan.sh - a picture equal to refray's own render except for
# NaN in one pixel the kit's mask excludes (masked_sphere.scene: 4 of 63
# pixels excluded).  [KIT-RULE-1] compares only unmasked pixels, and the
# rule's own C file (tests/conform/kit_check.c) and `compare --manifest`
# pass it; `conform` fails it as "nonfinite".
# Run from the repository root after nice make -j2 build/refray:
#   sh tests/attack12/conform_masked_nan.sh   # exit 1 when the verdicts disagree
set -u
B=$(pwd)/${B:-build/refray}
D=$(mktemp -d)
cc -std=c99 -O2 -o "$D/pfmtool" tests/attack12/pfmtool.c -lm || exit 2
cc -std=c99 -O2 -o "$D/kit_check" tests/conform/kit_check.c -lm || exit 2
"$B" kit -q -o "$D/kit" tests/attack12/masked_sphere.scene || exit 2
S=$D/kit/scenes/masked_sphere/masked_sphere
"$B" render "$S.scene" -q -o "$D/r.pfm" || exit 2
"$D/pfmtool" set "$D/r.pfm" "$D/nan.pfm" 4 0 nan || exit 2   # pixel (4, 0): masked
"$D/kit_check" "$S.exact.pfm" "$S.mask.pgm" 0.0001 3.0518043793392844e-05 "$D/nan.pfm"; kc=$?
"$B" compare "$D/nan.pfm" --manifest "$D/kit/manifest.json" > /dev/null; cm=$?
"$B" conform --kit "$D/kit" --format pfm --cmd "$D/pfmtool set $S.exact.pfm {out} 4 0 nan"; cf=$?
"$B" conform --kit "$D/kit" --format pfm --cmd "$B render {scene} -q -o {out}.pfm && $D/pfmtool set {out}.pfm {out} 4 0 nan"; cr=$?
rm -rf "$D"
echo "kit_check $kc, compare --manifest $cm, conform (exact image + masked NaN) $cf, conform (render + masked NaN) $cr"
[ $kc -eq $cf ] && [ $cm -eq $cf ] && [ $cr -eq $cf ] && exit 0
exit 1
