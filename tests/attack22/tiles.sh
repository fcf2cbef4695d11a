#!/bin/sh
# tiles.sh - attack 22's hand scenes (make_scenes.sh, the 64-sample ones)
# rendered whole, as 3 tiles merged (render --tile I/3, refray merge),
# with --jobs 2 and through --checkpoint DIR: every image the same bits as
# the whole one, and that the same as the old binary's.  Exit 1 on a
# difference.
# From the repository root after `make build/refray`.
set -u
B=${B:-build/refray}
OLD=${OLD:-/tmp/old-main/build/refray}
D=$(mktemp -d)
sh tests/attack22/make_scenes.sh "$D/s"
n=0 bad=0
for f in "$D"/s/dark_*_n64_*.scene; do
    n=$((n + 1))
    msg=""
    $B render "$f" -q -o "$D/whole.pfm" >/dev/null 2>&1 || msg="$msg whole failed"
    $OLD render "$f" -q -o "$D/old.pfm" >/dev/null 2>&1
    cmp -s "$D/whole.pfm" "$D/old.pfm" || msg="$msg old differs"
    for i in 0 1 2; do $B render "$f" -q --tile $i/3 -o "$D/t$i.pfm" >/dev/null 2>&1; done
    $B merge "$D/t0.pfm" "$D/t1.pfm" "$D/t2.pfm" -o "$D/merged.pfm" >/dev/null 2>&1
    cmp -s "$D/whole.pfm" "$D/merged.pfm" || msg="$msg tiles differ"
    $B render "$f" -q --jobs 2 -o "$D/jobs.pfm" >/dev/null 2>&1
    cmp -s "$D/whole.pfm" "$D/jobs.pfm" || msg="$msg jobs differ"
    rm -rf "$D/ck"
    $B render "$f" -q --checkpoint "$D/ck" -o "$D/ck.pfm" >/dev/null 2>&1
    cmp -s "$D/whole.pfm" "$D/ck.pfm" || msg="$msg checkpoint differs"
    [ -n "$msg" ] && { echo "$(basename "$f"):$msg"; bad=1; }
done
echo "tiles: $n scenes"
rm -rf "$D"
exit $bad
