#!/bin/sh
# conform_dim.sh - a "renderer" whose image is 1 % of refray's (pfmscale.c,
# K = 0.01) passes the conformance kit of disk_light_16.scene: the family's
# relative tolerance there is 0.992, under [VERIFY-UNBOUNDED-1]'s 1, and
# |0.01 v - v| = 0.99 |v| is within it.  Expected: a bound that cannot tell
# the image from 1 % of it is no verdict either (the measured error of 16
# light samples is 0.088: the bound is 11 times it).
# Run from the repository root after nice make -j2 build/refray:
#   sh tests/attack11/conform_dim.sh   # exit 1 when the dim image passes
set -u
B=${B:-build/refray}
D=$(mktemp -d)
cc -std=c99 -O2 -o "$D/pfmscale" tests/attack11/pfmscale.c || exit 2
"$B" kit -q -o "$D/kit" "${SCENE:-tests/attack11/disk_light_16.scene}" || exit 2
"$B" conform --kit "$D/kit" --format pfm \
    --cmd "$(pwd)/$B render {scene} -q -o {out}.pfm && $D/pfmscale {out}.pfm {out} ${K:-0.01}"
rc=$?
rm -rf "$D"
[ $rc -ne 0 ] && exit 0
echo "an image of ${K:-0.01} times the right one passed (exit $rc)"
exit 1
