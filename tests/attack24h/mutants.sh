#!/bin/sh
# mutants.sh [NAME...] - attack 24h: each [SHADE-SHORTCUT-HIDDEN-1] mutant of
# mutants.py built in a clone (M, default /tmp/ah24/mut, a clone of this
# branch built once with `make build/refray build/check_refray`), then: the
# Check suites shortcuts, bundle and random_scenes; hand_hidden.sh (on/off
# of the mutant only); gen15 seeds 1..SEEDS (default 150) at 32x24, on/off
# of the mutant.  Prints one line a mutant: what caught it.
set -u
R=$(pwd)
M=${M:-/tmp/ah24/mut}
SEEDS=${SEEDS:-150}
names=${*:-$(python3 tests/attack24h/mutants.py list)}
git -C "$M" show HEAD:src/render/trace.c > /tmp/ah24/trace.pristine.c
for name in $names; do
    python3 tests/attack24h/mutants.py "$name" /tmp/ah24/trace.pristine.c "$M/src/render/trace.c" || continue
    if ! make -C "$M" -j2 build/refray build/check_refray >/tmp/ah24/mut-build.log 2>&1; then echo "$name: build failed"; continue; fi
    caught=""
    for suite in shortcuts bundle random_scenes; do
        (cd "$M" && REFRAY_BIN=build/refray CK_TIMEOUT_MULTIPLIER=4 build/check_refray $suite >/tmp/ah24/mut-$name-$suite.log 2>&1) || caught="$caught check:$suite($(grep -c ':F:\|:E:' /tmp/ah24/mut-$name-$suite.log))"
    done
    B=$M/build/refray ONLYB=1 FIRST=1 sh tests/attack24h/hand_hidden.sh > /tmp/ah24/mut-$name-hand.log 2>&1 || caught="$caught hand_hidden($(head -1 /tmp/ah24/mut-$name-hand.log))"
    D=/tmp/ah24/mut-$name-gen; mkdir -p $D; cp scenes/models/sphere_12x8.obj scenes/stress/glass_cube.obj tests/attack20/*.obj scenes/stress/geosphere.obj $D/
    g=0 s=1
    while [ $s -le $SEEDS ]; do
        awk -v seed=$s -f tests/attack18/common.awk -f tests/attack19/common19.awk -f tests/attack24h/gen15.awk > $D/s.scene
        timeout 60 $M/build/refray render $D/s.scene -q --width 32 --height 24 -o $D/on.pfm >/dev/null 2>&1; e1=$?
        timeout 60 $M/build/refray render $D/s.scene -q --width 32 --height 24 --no-shortcuts -o $D/off.pfm >/dev/null 2>&1; e2=$?
        if [ $e1 != $e2 ] || { [ $e1 = 0 ] && ! cmp -s $D/on.pfm $D/off.pfm; }; then g=$((g + 1)); fi
        s=$((s + 1))
    done
    [ $g = 0 ] || caught="$caught gen15($g of $SEEDS)"
    echo "$name:${caught:- SURVIVES}"
done
git -C "$M" checkout -q src/render/trace.c
