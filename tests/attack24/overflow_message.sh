#!/bin/sh
# overflow_message.sh - attack 24, defect 1: after [BVH-BEAM-1]'s tiles met
# an overflow, band_by_tiles (src/render/render.c) makes the band again by
# rows_by_pixel without taking back the counts the tiles added: a medium
# overflow of a later tile (pixel (7, 13), 17 nested glass balls) stays in
# medium_overflows while the row-major first overflow is a ray tree's
# (pixel (25, 2)), so the CLI prints the nested-solids message for a tree
# overflow.  Exit 1 while the message differs from the old binary's.
# Run from the repository root after `make build/refray`.
B=${B:-build/refray}
OLD=${OLD:-/tmp/old-main/build/refray}
S=tests/attack24/overflow_message.scene
new=$($B render $S --max-ray-tree 30 -q -o /tmp/overflow_message_$$.pfm 2>&1 | grep '^refray: error')
old=$($OLD render $S --max-ray-tree 30 -q -o /tmp/overflow_message_$$.pfm 2>&1 | grep '^refray: error')
rm -f /tmp/overflow_message_$$.pfm
[ "$new" = "$old" ] && exit 0
echo "new: $new"
echo "old: $old"
exit 1
