#!/bin/sh
# campaign.sh GEN FIRST LAST [OPTION...] - scenes of GEN.awk (this folder's
# gen9, or attack 19's gen3..gen7, attack 20's gen8) for seeds FIRST..LAST,
# each rendered by the new binary (B) with and without --no-shortcuts and
# by the old one (OLD, default /tmp/old-main/build/refray) with the same
# OPTIONs and --stats.  Prints each seed whose images or exit codes differ,
# or whose counted results differ: the "rays:" and "light samples:" lines
# of --stats against those of BASE (a build of this round's base, a6e27ad:
# a dark cell's sample counts as add_source counts it and sends no ray),
# and its node visits and primitive tests ("bvh:"); without BASE the two
# count lines against the old binary's (which differ from main's in some
# glass scenes, from earlier rounds: README).  Run from the repository
# root after `make build/refray`.  OUT: the directory kept.
set -u
B=${B:-build/refray}
OLD=${OLD:-/tmp/old-main/build/refray}
BASE=${BASE:-}
D=${OUT:-$(mktemp -d)}
gen=$1 s=$2 last=$3
shift 3
mkdir -p "$D"
cp scenes/stress/glass_cube.obj tests/attack20/*.obj scenes/stress/geosphere.obj "$D/"
dir=tests/attack22
[ -f "$dir/$gen.awk" ] || dir=tests/attack19
[ -f "$dir/$gen.awk" ] || dir=tests/attack20
counts() { grep -E '^  (rays|light samples):' "$1"; }
visits() { sed -n 's/^  bvh:.*s; //p' "$1"; }
bad=0 n=0
while [ "$s" -le "$last" ]; do
    f="$D/$gen-$s.scene"
    awk -v seed="$s" -f tests/attack18/common.awk -f tests/attack19/common19.awk -f "$dir/$gen.awk" > "$f"
    timeout 120 nice $B render "$f" -q --stats "$@" -o "$D/on.pfm" >/dev/null 2>"$D/on.st"; e1=$?
    timeout 120 nice $B render "$f" -q --no-shortcuts "$@" -o "$D/off.pfm" >/dev/null 2>&1; e2=$?
    timeout 120 nice $OLD render "$f" -q --stats "$@" -o "$D/old.pfm" >/dev/null 2>"$D/old.st"; e3=$?
    n=$((n + 1))
    msg=""
    [ $e1 = $e2 ] && [ $e1 = $e3 ] || msg="exit $e1 $e2 old $e3"
    if [ $e1 = 0 ] && [ $e2 = 0 ]; then cmp -s "$D/on.pfm" "$D/off.pfm" || msg="$msg on/off differ"; fi
    if [ $e1 = 0 ] && [ $e3 = 0 ]; then
        cmp -s "$D/on.pfm" "$D/old.pfm" || msg="$msg new/old differ"
        [ -n "$BASE" ] || [ "$(counts "$D/on.st")" = "$(counts "$D/old.st")" ] || msg="$msg counts differ from old"
    fi
    if [ -n "$BASE" ] && [ $e1 = 0 ]; then
        timeout 120 nice $BASE render "$f" -q --stats "$@" -o "$D/base.pfm" >/dev/null 2>"$D/base.st"
        [ "$(counts "$D/on.st")" = "$(counts "$D/base.st")" ] || msg="$msg counts differ from BASE"
        [ "$(visits "$D/on.st")" = "$(visits "$D/base.st")" ] || msg="$msg visits differ from BASE"
    fi
    if [ -n "$msg" ]; then
        echo "$gen seed $s: $msg"; cp "$f" "$D/bad-$gen-$s.scene"; bad=1
    fi
    s=$((s + 1))
done
echo "campaign $gen: $n scenes $*"
exit $bad
