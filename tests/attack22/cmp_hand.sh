#!/bin/sh
# cmp_hand.sh [OPTION...] - renders attack 22's hand scenes (make_scenes.sh)
# with build/refray (B), with and without --no-shortcuts, and with the old
# binary (OLD, default /tmp/old-main/build/refray), the OPTIONs given to
# all three; prints each scene whose images or exit codes differ, or whose
# "rays:" and "light samples:" lines of --stats differ from the old
# binary's, and exits 1 if any does.  Run from the repository root after
# `make build/refray`.
set -u
B=${B:-build/refray}
OLD=${OLD:-/tmp/old-main/build/refray}
D=$(mktemp -d)
sh tests/attack22/make_scenes.sh "$D/s"
# The shadow rays are left out since the twenty-first round:
# [SHADE-SHORTCUT-ABSORB-1] sends fewer of them by design.
counts() { sed -n 's/^  rays: \([0-9]*\) camera, [0-9]* shadow, \(.*\); [0-9]* in all/\1 \2/p; /^  light samples:/p' "$1"; }
n=0 bad=0
for f in "$D"/s/*.scene; do
    n=$((n + 1))
    timeout 300 nice $B render "$f" -q --stats "$@" -o "$D/on.pfm" >/dev/null 2>"$D/on.st"; e1=$?
    timeout 300 nice $B render "$f" -q --no-shortcuts "$@" -o "$D/off.pfm" >/dev/null 2>&1; e2=$?
    timeout 300 nice $OLD render "$f" -q --stats "$@" -o "$D/old.pfm" >/dev/null 2>"$D/old.st"; e3=$?
    msg=""
    [ $e1 = $e2 ] && [ $e1 = $e3 ] || msg="exit $e1 $e2 old $e3"
    if [ $e1 = 0 ] && [ $e2 = 0 ]; then cmp -s "$D/on.pfm" "$D/off.pfm" || msg="$msg on/off differ"; fi
    if [ $e1 = 0 ] && [ $e3 = 0 ]; then
        cmp -s "$D/on.pfm" "$D/old.pfm" || msg="$msg new/old differ"
        [ "$(counts "$D/on.st")" = "$(counts "$D/old.st")" ] || msg="$msg counts differ"
    fi
    [ -n "$msg" ] && { echo "$(basename "$f"): $msg"; bad=1; }
done
echo "cmp_hand: $n scenes $*"
rm -rf "$D"
exit $bad
