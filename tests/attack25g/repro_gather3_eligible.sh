#!/bin/sh
# repro_gather3_eligible.sh - attack 25g finding 3: gather3_eligible.scene
# rendered by the new binary (B) with and without --no-shortcuts, by the
# round's base (BASE, 34a5772: the old image) and the old one (OLD).
# Exits 1 when B's image differs from OLD's (it does from 19fd7b6 on).
# Run from the repository root.
B=${B:-build/refray}
OLD=${OLD:-/tmp/old-main/build/refray}
BASE=${BASE:-/tmp/base25/build/refray}
f=tests/attack25g/gather3_eligible.scene
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
$B render "$f" -q -o "$D/on.pfm" && $B render "$f" -q --no-shortcuts -o "$D/off.pfm" &&
    $OLD render "$f" -q -o "$D/old.pfm" || exit 1
bad=0
cmp -s "$D/off.pfm" "$D/old.pfm" || { echo "--no-shortcuts differs from the old image"; bad=1; }
cmp -s "$D/on.pfm" "$D/old.pfm" || { echo "the shortcuts change the image (new != old)"; bad=1; }
if [ -x "$BASE" ]; then
    $BASE render "$f" -q -o "$D/base.pfm" && cmp -s "$D/base.pfm" "$D/old.pfm" &&
        echo "(the base's image is the old one)"
fi
[ $bad = 0 ] && echo "gather3_eligible: same images"
exit $bad
