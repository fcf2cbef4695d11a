#!/bin/sh
# merge_sidecar_name.sh - `refray merge` given the tiles' sidecars
# (NAME.pfm.tile, what `ls` and a glob such as tiles/tile-* list beside the
# PFMs) refuses them as display-code images: "PNG and PPM hold display
# codes".  The file is neither PNG nor PPM; it is the tile's own sidecar.
#   sh tests/attack14/merge_sidecar_name.sh   # exit 1 while the reason names PNG and PPM
set -u
R=${REFRAY:-build/refray}
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
for i in 0 1; do
    "$R" render scenes/demo.scene --width 32 --height 24 --tile $i/2 -q -o "$D/tile-$i.pfm" || exit 2
done
"$R" merge "$D"/tile-*.pfm -o "$D/ok.pfm" || exit 2
"$R" merge "$D"/tile-* -o "$D/out.pfm" 2> "$D/err"
echo "merge tile-*: exit $?: $(cat "$D/err")"
! grep -q 'PNG and PPM' "$D/err"
