#!/bin/sh
# pfm_scale_agree.sh - [KIT-PFM-1] says refray (img_read: compare, conform,
# compare --manifest) and kit_check.c read a PFM the same way.  The scale
# token: refray refuses one that is not finite, zero or followed by other
# characters ("bad scale in the PFM header", exit 65); kit_check.c takes
# only its sign (strtod < 0), so it judges those files, and passes refray's
# own right picture written with the scale -inf, -1e999 or -1.0x.  Exit 1
# when the two judges part (one refuses, the other passes).
#   sh tests/attack15/pfm_scale_agree.sh
set -u
R=${B:-build/refray}
KC=${KIT_CHECK:-build/kit_check}
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
S=scenes/analytic/plane_point_inverse_square.scene
nice $R kit -q -o $D/kit $S && nice $R render $S -q -o $D/r.pfm || exit 2
E=$D/kit/scenes/plane_point_inverse_square/plane_point_inverse_square
rel=$(jq '.scenes[0].tolerance.relative' $D/kit/manifest.json)
abs=$(jq '.scenes[0].tolerance.absolute' $D/kit/manifest.json)
tail -c $((80 * 60 * 12)) $D/r.pfm > $D/raw
bad=0
for sc in -1.0 -inf -1e999 -1.0x -nan; do
    printf 'PF\n80 60\n%s\n' "$sc" > $D/m.pfm && cat $D/raw >> $D/m.pfm
    $R compare $D/m.pfm --manifest $D/kit/manifest.json > $D/c.txt 2>&1; c=$?
    $KC $E.exact.pfm $E.mask.pgm "$rel" "$abs" $D/m.pfm > $D/k.txt 2>&1; k=$?
    echo "scale $sc: compare --manifest exit $c ($(grep -o 'bad scale[^;]*\|[0-9]* pixels over' $D/c.txt | head -1)), kit_check exit $k ($(tail -1 $D/k.txt))"
    [ $c = 65 ] && [ $k = 0 ] && bad=1
    [ $c = 0 ] && [ $k != 0 ] && bad=1
done
exit $bad
