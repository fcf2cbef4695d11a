#!/bin/sh
# mask_gray.sh - a kit mask byte that is neither 0 nor 255: the manifest's
# rule says the mask marks pixels with 255; conform and compare --manifest
# take a byte as a mark when it is over half the maxval, the kit's own
# kit_check.c when it is non-zero.  The lambert_sphere kit with mask byte
# 100 at pixel (48, 36) (masked_pixels stays 0: conform counts no mark)
# and the exact image with NaN in that pixel: kit_check passes (0),
# conform and compare --manifest fail (1).  Exits 1 when the judges
# disagree (a refusal, kit_check's 2 and refray's 65, is one verdict).
#   sh tests/attack13/mask_gray.sh
set -u
B=$(pwd)/${B:-build/refray}
D=$(mktemp -d)
cc -std=c99 -O2 -o $D/kit_check tests/conform/kit_check.c -lm || exit 2
cc -std=c99 -O2 -o $D/pfmtool tests/attack12/pfmtool.c -lm || exit 2
nice "$B" kit -q -o $D/kit scenes/analytic/lambert_sphere.scene || exit 2
S=$D/kit/scenes/lambert_sphere/lambert_sphere
# the PGM header is "P5\n96 72\n255\n" (13 bytes); pixel (48, 36) is byte 13 + 36*96 + 48
hdr=$(head -c 13 $S.mask.pgm | od -An -c | tr -d ' ')
[ "$hdr" = 'P5\n9672\n255\n' ] || { echo "unexpected mask header: $hdr"; exit 2; }
printf '\144' | dd of=$S.mask.pgm bs=1 seek=$((13 + 36 * 96 + 48)) conv=notrunc 2>/dev/null
"$D/pfmtool" set $S.exact.pfm $D/nan.pfm 48 36 nan
rel=$(jq '.scenes[0].tolerance.relative' $D/kit/manifest.json)
abs=$(jq '.scenes[0].tolerance.absolute' $D/kit/manifest.json)
"$D/kit_check" $S.exact.pfm $S.mask.pgm $rel $abs $D/nan.pfm >/dev/null; kc=$?
nice "$B" compare $D/nan.pfm --manifest $D/kit/manifest.json --scene lambert_sphere >/dev/null 2>&1; cm=$?
nice "$B" conform --kit $D/kit --format pfm --cmd "cp $D/nan.pfm {out}" >/dev/null 2>&1; cf=$?
echo "kit_check $kc, compare --manifest $cm, conform $cf"
rm -rf $D
# A refusal is kit_check's 2 and refray's 65: the same verdict.
v() { case $1 in 2|65) echo refused ;; *) echo $1 ;; esac; }
[ "$(v $kc)" = "$(v $cm)" ] && [ "$(v $cm)" = "$(v $cf)" ] && exit 0
exit 1
