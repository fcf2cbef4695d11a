#!/bin/sh
# hand_tiles.sh - attack 24: [BVH-BEAM-1]'s tiles at the image's edges.
# scenes/demo.scene and scenes/mesh.scene (perspective) at sizes 1x1, 1x17,
# 17x1, 15x15, 16x16, 17x17, 31x33, 47x5 with 1, 2, 3, 5, 16 and 17 samples
# a pixel (tiles 16x16, 16x4, 16x1, 10x1, 1x1, none), rendered whole, with
# --no-shortcuts, by the old binary (16 and 17 samples at 1x1, 1x17 and
# 17x1 only), with --jobs 2, and as --region bands
# (one row, one column, a 7-pixel offset) merged by refray merge: all the
# same bytes.  Exit 1 when any differ.  From the repository root after
# `make build/refray`.
B=${B:-build/refray}
OLD=${OLD:-/tmp/old-main/build/refray}
D=$(mktemp -d)
bad=0 n=0
for s in scenes/demo.scene scenes/mesh.scene; do
for wh in "1 1" "1 17" "17 1" "15 15" "16 16" "17 17" "31 33" "47 5"; do
for k in 1 2 3 5 16 17; do
    set -- $wh; W=$1 H=$2
    # 16 and 17 samples only on the small images (time)
    [ $k -ge 16 ] && [ $((W * H)) -gt 17 ] && continue
    o="--width $W --height $H --samples $k"
    n=$((n + 1))
    $B render $s $o -q -o $D/on.pfm 2>/dev/null; e1=$?
    $B render $s $o --no-shortcuts -q -o $D/off.pfm 2>/dev/null; e2=$?
    $OLD render $s $o -q -o $D/old.pfm 2>/dev/null; e3=$?
    $B render $s $o --jobs 2 -q -o $D/jobs.pfm 2>/dev/null
    rm -f $D/r*.pfm
    x=7; [ $x -lt $W ] || x=0
    $B render $s $o --region 0 0 $W 1 -q -o $D/r0.pfm 2>/dev/null
    if [ $H -gt 1 ]; then
        $B render $s $o --region 0 1 1 $H -q -o $D/r1.pfm 2>/dev/null
        [ $W -gt 1 ] && $B render $s $o --region 1 1 $W $H -q -o $D/r2.pfm 2>/dev/null
    fi
    $B merge $D/r*.pfm -o $D/merged.pfm >/dev/null 2>&1
    msg=""
    [ $e1 = $e2 ] && [ $e1 = $e3 ] || msg="exit $e1 $e2 $e3"
    cmp -s $D/on.pfm $D/off.pfm || msg="$msg on/off"
    cmp -s $D/on.pfm $D/old.pfm || msg="$msg new/old"
    cmp -s $D/on.pfm $D/jobs.pfm || msg="$msg jobs"
    cmp -s $D/on.pfm $D/merged.pfm || msg="$msg regions"
    [ -n "$msg" ] && { echo "$s $o: $msg"; bad=1; }
done; done; done
rm -rf $D
echo "hand_tiles: $n cases"
exit $bad
