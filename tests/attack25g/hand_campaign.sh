#!/bin/sh
# hand_campaign.sh GEN FIRST LAST [OPTION...] - attack 25g: scenes of this
# folder's GEN.awk for seeds FIRST..LAST, rendered by the new binary (B)
# with and without --no-shortcuts, by the old one (OLD) and this round's
# base (BASE); a seed is printed when images or exit codes differ.
# Run from the repository root.  Exits 1 when some seed differed.
set -u
B=${B:-build/refray}
OLD=${OLD:-/tmp/old-main/build/refray}
BASE=${BASE:-/tmp/base25/build/refray}
D=${OUT:-$(mktemp -d)}
gen=$1 s=$2 last=$3
shift 3
mkdir -p "$D"
bad=0 n=0
while [ "$s" -le "$last" ]; do
    f="$D/$gen-$s.scene"
    awk -v seed="$s" -f tests/attack18/common.awk -f tests/attack19/common19.awk -f "tests/attack25g/$gen.awk" > "$f"
    timeout 120 $B render "$f" -q "$@" -o "$D/on.pfm" >/dev/null 2>&1; e1=$?
    timeout 120 $B render "$f" -q --no-shortcuts "$@" -o "$D/off.pfm" >/dev/null 2>&1; e2=$?
    timeout 120 $OLD render "$f" -q "$@" -o "$D/old.pfm" >/dev/null 2>&1; e3=$?
    timeout 120 $BASE render "$f" -q "$@" -o "$D/base.pfm" >/dev/null 2>&1; e4=$?
    n=$((n + 1))
    msg=""
    [ $e1 = $e2 ] && [ $e1 = $e3 ] && [ $e1 = $e4 ] || msg="exit $e1 off $e2 old $e3 base $e4"
    if [ $e1 = 0 ]; then
        cmp -s "$D/on.pfm" "$D/off.pfm" || msg="$msg on/off differ"
        cmp -s "$D/on.pfm" "$D/old.pfm" || msg="$msg new/old differ"
        cmp -s "$D/on.pfm" "$D/base.pfm" || msg="$msg new/base differ"
    fi
    if [ -n "$msg" ]; then
        echo "$gen seed $s: $msg"; cp "$f" "$D/bad-$gen-$s.scene"; bad=1
    fi
    s=$((s + 1))
done
echo "hand campaign $gen: $n scenes $*"
exit $bad
