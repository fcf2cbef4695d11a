#!/bin/sh
# view_rounding_look_at.sh - [ORACLE-VIEW-ROUNDING-1]'s tolerance
# max(1e-9, 256 u D / S), D = |eye| + |eye - look_at|, depends on where
# look_at lies on the line of sight, which changes no ray and no pixel:
#  1. sphere_far_look_near / _far: the same image byte for byte; verify
#     FAILs the first (tolerance 1e-9) and passes the second (8.9e-7);
#  2. lambert_sphere_far_look_at (the stock scene, look_at moved to
#     [0, 0, -5e13]): the same image as the stock scene byte for byte;
#     `kit` writes relative 0.444 into the manifest, and conform passes a
#     picture of 0.6 times the right one (the stock kit fails it); the same
#     for perspective: phong_plane_near_look_at (look_at 2^-43 of the way),
#     relative 0.268, a picture of 0.75 times the right one passes.
# Exits 1 when either happens.
#   sh tests/attack13/view_rounding_look_at.sh
set -u
B=$(pwd)/${B:-build/refray}
D=$(mktemp -d)
A=tests/attack13
bad=0
nice "$B" render $A/sphere_far_look_near.scene -q -o $D/n.pfm && nice "$B" render $A/sphere_far_look_far.scene -q -o $D/f.pfm || exit 2
cmp -s $D/n.pfm $D/f.pfm && echo "1: the two images are byte-identical" || echo "1: the two images differ"
vn=$(nice "$B" verify $A/sphere_far_look_near.scene | awk 'NR == 2 {print "max rel " $7 ", tolerance " $10 ": " $NF}')
vf=$(nice "$B" verify $A/sphere_far_look_far.scene | awk 'NR == 2 {print "max rel " $7 ", tolerance " $10 ": " $NF}')
echo "   look_at near: $vn; look_at at the sphere: $vf"
[ "${vn##*: }" = "${vf##*: }" ] || bad=1
cc -std=c99 -O2 -o $D/pfmtool tests/attack12/pfmtool.c -lm || exit 2
for p in scenes/analytic/lambert_sphere.scene:0.6 $A/lambert_sphere_far_look_at.scene:0.6 \
         scenes/analytic/phong_plane_perspective.scene:0.75 $A/phong_plane_near_look_at.scene:0.75; do
    s=${p%:*} k=${p##*:}
    rm -rf $D/kit
    nice "$B" kit -q -o $D/kit $s || { echo "kit refused $s"; continue; }
    rel=$(jq '.scenes[0].tolerance.relative' $D/kit/manifest.json)
    v=$(nice "$B" conform --kit $D/kit --format pfm \
        --cmd "$B render {scene} -q -o {out}.pfm && $D/pfmtool scale {out}.pfm {out} $k" | awk 'NR == 2 {print $NF}')
    echo "2: $(basename $s): relative $rel; a picture of $k x the right one: $v"
    case $s in *attack13*) [ "$v" = pass ] && bad=1 ;; esac
done
rm -rf $D
exit $bad
