#!/bin/sh
# campaign.sh GEN FIRST LAST [OPTION...] - scenes of GEN.awk (gen3, gen4)
# for seeds FIRST..LAST, each rendered by the new binary with and without
# --no-shortcuts and by the old one (OLD, default /tmp/old-main/build/refray)
# with the same OPTIONs; prints each seed whose images or exit codes
# differ (and, then, the old binary's --no-shortcuts verdict).  Run from the
# repository root after `make build/refray`.  OUT: the directory kept.
set -u
B=${B:-build/refray}
OLD=${OLD:-/tmp/old-main/build/refray}
D=${OUT:-$(mktemp -d)}
gen=$1 s=$2 last=$3
shift 3
mkdir -p "$D"
cp scenes/stress/glass_cube.obj "$D/"
bad=0 n=0
while [ "$s" -le "$last" ]; do
    f="$D/$gen-$s.scene"
    awk -v seed="$s" -f tests/attack18/common.awk -f tests/attack19/common19.awk -f "tests/attack19/$gen.awk" > "$f"
    timeout 60 nice $B render "$f" -q "$@" -o "$D/on.pfm" >/dev/null 2>&1; e1=$?
    timeout 60 nice $B render "$f" -q --no-shortcuts "$@" -o "$D/off.pfm" >/dev/null 2>&1; e2=$?
    timeout 60 nice $OLD render "$f" -q "$@" -o "$D/old.pfm" >/dev/null 2>&1; e3=$?
    n=$((n + 1))
    msg=""
    [ $e1 = $e2 ] && [ $e1 = $e3 ] || msg="exit $e1 $e2 old $e3"
    if [ $e1 = 0 ] && [ $e2 = 0 ]; then cmp -s "$D/on.pfm" "$D/off.pfm" || msg="$msg on/off differ"; fi
    if [ $e1 = 0 ] && [ $e3 = 0 ]; then cmp -s "$D/on.pfm" "$D/old.pfm" || msg="$msg new/old differ"; fi
    if [ -n "$msg" ]; then
        timeout 60 nice $OLD render "$f" -q --no-shortcuts "$@" -o "$D/oldoff.pfm" >/dev/null 2>&1; e4=$?
        o=same; [ $e4 = $e3 ] && cmp -s "$D/old.pfm" "$D/oldoff.pfm" || o="differ (exit $e4)"
        echo "$gen seed $s: $msg; old on/off $o"; cp "$f" "$D/bad-$gen-$s.scene"; bad=1
    fi
    s=$((s + 1))
done
echo "campaign $gen: $n scenes $*"
exit $bad
