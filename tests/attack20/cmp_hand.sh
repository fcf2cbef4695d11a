#!/bin/sh
# cmp_hand.sh [OPTION...] - renders each scene of tests/attack20/scenes at
# its own size with the new binary (default and --no-shortcuts) and the old
# one (OLD, default /tmp/old-main/build/refray), OPTIONs to all; prints each
# scene whose images or exit codes differ; exits 1 if any.  From the
# repository root after `make build/refray`.
set -u
B=${B:-build/refray}
OLD=${OLD:-/tmp/old-main/build/refray}
D=$(mktemp -d)
n=0 bad=0
for f in tests/attack20/scenes/*.scene; do
    n=$((n + 1))
    nice $B render "$f" -q "$@" -o "$D/on.pfm" >/dev/null 2>&1; e1=$?
    nice $B render "$f" -q --no-shortcuts "$@" -o "$D/off.pfm" >/dev/null 2>&1; e2=$?
    nice $OLD render "$f" -q "$@" -o "$D/old.pfm" >/dev/null 2>&1; e3=$?
    msg=""
    [ $e1 = $e2 ] && [ $e1 = $e3 ] || msg="exit $e1 $e2 old $e3"
    if [ $e1 = 0 ] && [ $e2 = 0 ]; then cmp -s "$D/on.pfm" "$D/off.pfm" || msg="$msg on/off differ"; fi
    if [ $e1 = 0 ] && [ $e3 = 0 ]; then cmp -s "$D/on.pfm" "$D/old.pfm" || msg="$msg new/old differ"; fi
    [ -z "$msg" ] || { echo "$f: $msg"; bad=1; }
done
rm -rf "$D"
echo "cmp_hand: $n scenes $*"
exit $bad
