#!/bin/sh
# conform_hdr_dark.sh - refray's own kit of a scene with a bright spot
# (plane_point_hdr.scene: peak 1084, the rest of the plane 0.012 .. 0.04)
# gets png16_scale 2^-11 and absolute 0.03125, one 16-bit step at that
# scale ([KIT-TOL-1]), within [VERIFY-UNBOUNDED-4]'s 2^-14 of the peak
# (0.066).  The same absolute judges PFM and EXR, which hold those values:
# a renderer writing every value below 0.031 as 0 (87 % of the pixels
# black) passes conform --format pfm, kit_check.c and compare --manifest.  No manifest edited.
# Exit 1 when the black picture passes either judge.
#   sh tests/attack15/conform_hdr_dark.sh
set -u
R=${B:-$(pwd)/build/refray}
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
cc -std=c99 -O2 -o $D/clip tests/attack13/pfmclip.c || exit 2
nice $R kit -q -o $D/kit tests/attack15/plane_point_hdr.scene || exit 2
rel=$(jq '.scenes[0].tolerance.relative' $D/kit/manifest.json)
abs=$(jq '.scenes[0].tolerance.absolute' $D/kit/manifest.json)
echo "kit: peak $(jq '.scenes[0].peak' $D/kit/manifest.json), png16_scale $(jq '.scenes[0].png16_scale' $D/kit/manifest.json), relative $rel, absolute $abs"
nice $R render tests/attack15/plane_point_hdr.scene -q -o $D/right.pfm && $D/clip low $D/right.pfm $D/dark.pfm 0.031 || exit 2
echo "the dark picture: $(cmp -l $D/right.pfm $D/dark.pfm | wc -l) bytes changed of $(wc -c < $D/right.pfm)"
v=$(nice $R conform --kit $D/kit --format pfm --cmd "$R render {scene} -q -o {out}.pfm && $D/clip low {out}.pfm {out} 0.031")
echo "$v" | sed -n 2p
bad=0
echo "$v" | awk 'NR == 2 { exit $NF != "pass" }' && bad=1
E=$D/kit/scenes/plane_point_hdr
nice ${KIT_CHECK:-build/kit_check} $E/plane_point_hdr.exact.pfm $E/plane_point_hdr.mask.pgm "$rel" "$abs" $D/dark.pfm; k=$?
echo "kit_check exit $k"
[ $k = 0 ] && bad=1
nice $R compare $D/dark.pfm --manifest $D/kit/manifest.json --scene plane_point_hdr > $D/cmp.txt; c=$?
echo "compare --manifest exit $c: $(grep "^over\|pixels over" $D/cmp.txt | head -1)"
[ $c = 0 ] && bad=1
exit $bad
