#!/bin/sh
# campaign.sh FIRST LAST [OLD] - scenes of gen.awk (GEN=gen2: gen2.awk) for seeds FIRST..LAST,
# each rendered with the shortcuts, with --no-shortcuts and (OLD given)
# by the old binary; prints each seed whose images or exit codes differ.
# Run from the repository root after `make build/refray`.
set -u
B=${B:-build/refray}
D=${OUT:-$(mktemp -d)}
mkdir -p "$D"
bad=0 n=0
s=$1
while [ "$s" -le "$2" ]; do
    cp scenes/stress/glass_cube.obj "$D/"; awk -v seed="$s" -v Tf="${TF:-}" -f tests/attack18/common.awk -f tests/attack18/${GEN:-gen}.awk > "$D/$s.scene"
    timeout 20 nice $B render "$D/$s.scene" -q -o "$D/on.pfm" 2>/dev/null; e1=$?
    timeout 20 nice $B render "$D/$s.scene" -q --no-shortcuts -o "$D/off.pfm" 2>/dev/null; e2=$?
    n=$((n + 1))
    if [ $e1 != $e2 ] || [ $e1 -gt 1 ]; then echo "seed $s: exit $e1 $e2"; bad=1
    elif [ $e1 = 0 ] && ! cmp -s "$D/on.pfm" "$D/off.pfm"; then echo "seed $s: on/off differ"; bad=1
    elif [ $# -ge 3 ] && [ $e1 = 0 ]; then
        timeout 20 nice "$3" render "$D/$s.scene" -q --no-shortcuts -o "$D/old.pfm" 2>/dev/null
        cmp -s "$D/on.pfm" "$D/old.pfm" || { echo "seed $s: old (--no-shortcuts)/new differ"; bad=1; }
    fi
    s=$((s + 1))
done
echo "campaign: $n scenes"
exit $bad
