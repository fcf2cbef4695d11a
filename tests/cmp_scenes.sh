#!/bin/sh
# cmp_scenes.sh OLD NEW DIR [OPTION...] - renders every scene under scenes/
# (find scenes -name '*.scene' | sort) at 64x48 to PFM with two refray
# binaries and compares the files byte for byte, and the exit codes: the
# check that a change (a shortcut, a speed step, a mend) leaves every image
# the same.  OPTIONs go to both renders (e.g. --no-shortcuts).  Prints each
# difference and a last line "cmp_scenes: N scenes, D differ, F exit-code
# differences"; exits 1 when D or F is not 0.  Run from the repository root.
old=$1 new=$2 out=$3
[ -x "$old" ] && [ -x "$new" ] && [ -n "$out" ] || { echo "usage: $0 OLD NEW DIR [OPTION...]" >&2; exit 64; }
shift 3
mkdir -p "$out"
n=0 d=0 f=0
for s in $(find scenes -name '*.scene' | sort); do
    n=$((n + 1))
    b=$(echo "$s" | tr / _)
    "$old" render "$s" --width 64 --height 48 -q "$@" -o "$out/$b.old.pfm" >/dev/null 2>&1; e1=$?
    "$new" render "$s" --width 64 --height 48 -q "$@" -o "$out/$b.new.pfm" >/dev/null 2>&1; e2=$?
    if [ "$e1" != "$e2" ]; then
        f=$((f + 1)); echo "exit code differs: $s: $e1 against $e2"
    elif [ -f "$out/$b.old.pfm" ] && ! cmp -s "$out/$b.old.pfm" "$out/$b.new.pfm"; then
        d=$((d + 1)); echo "differs: $s"
    fi
done
echo "cmp_scenes: $n scenes, $d differ, $f exit-code differences"
[ "$d" = 0 ] && [ "$f" = 0 ]
