#!/bin/sh
# repro_far_graze.sh - attack 25g finding 2: far_graze.scene rendered by the
# new binary (B) with and without --no-shortcuts and by the old one (OLD):
# exits 1 when the images differ (they do at 34a5772 and at this branch:
# [SHADE-SHORTCUT-GATHER-2]'s alone test, whose premise GATHER-3 reuses).
# Run from the repository root.
B=${B:-build/refray}
OLD=${OLD:-/tmp/old-main/build/refray}
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
bad=0
for f in tests/attack25g/far_graze.scene ${EXTRA:-}; do
    $B render "$f" -q -o "$D/on.pfm" || bad=1
    $B render "$f" -q --no-shortcuts -o "$D/off.pfm" || bad=1
    $OLD render "$f" -q -o "$D/old.pfm" || bad=1
    cmp -s "$D/off.pfm" "$D/old.pfm" || { echo "$f: --no-shortcuts differs from the old binary"; bad=1; }
    cmp -s "$D/on.pfm" "$D/old.pfm" || { echo "$f: the shortcuts change the image (on != old)"; bad=1; }
done
[ $bad = 0 ] && echo "far_graze: same images"
exit $bad
