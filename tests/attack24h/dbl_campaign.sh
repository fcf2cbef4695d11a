#!/bin/sh
# dbl_campaign.sh FIRST LAST - attack 24h: the scenes of hand_hidden.sh
# (also over a background of 1 + 2^-24, a float tie) and gen15 seeds
# FIRST..LAST, rendered in double through the API (dbl_cmp.c) by this
# tree's library (on and off) and by the base's (BASELIB); exit 1 when on
# and off differ, or this tree's hashes or counts (all but the shadow rays)
# differ from the base's.  LIB: the library under test (default
# build/librefray-internal.a).  W H: the size (default 32 24).  HAND=0:
# gen15 alone.
set -u
. tests/attack24h/lights.sh
LIB=${LIB:-build/librefray-internal.a}
BASELIB=${BASELIB:-/tmp/base24/build/librefray-internal.a}
D=${OUT:-$(mktemp -d)}
mkdir -p $D/s
cp scenes/models/sphere_12x8.obj scenes/stress/glass_cube.obj tests/attack20/*.obj scenes/stress/geosphere.obj $D/s/
cc -std=c99 -O2 -Iinclude -o $D/new tests/attack24h/dbl_cmp.c "$LIB" -ljansson -lm 2>/dev/null || exit 2
[ -x $D/base ] || cc -std=c99 -O2 -Iinclude -o $D/base tests/attack24h/dbl_cmp.c "$BASELIB" -ljansson -lm 2>/dev/null || exit 2
k=0
[ "${HAND:-1}" = 1 ] || set -- "$1" "$2" nohand
for bg in "1, 1, 1" "1.000000059604644775390625, 1, 0"; do
for lt in point pointlin pointinv pointd0 disk tiny rect distant; do
for nn in 1 30 1000000; do
for mat in mirror glass; do
for p in 1e-18 3.2e-18 1e-17 3.2e-17 1e-16 1.8e-16 3.2e-16 1e-15 3.2e-15 1e-13 1e-9; do
    case $mat in mirror) m="Kd 0 Ks 1 n $nn t 0" ;; glass) m="Kd 0 Ks 1 n $nn t 1 ior 1" ;; esac
    hidden_light "$lt" "$p"
    k=$((k + 1))
    [ "${3:-}" = nohand ] && continue
    {
        echo "image { width 32 height 24 max_depth 2 background [$bg] }"
        echo "camera { perspective eye [0, 1.5, 3] look_at [0, 0, -0.5] up [0, 1, 0] fov 60 }"
        echo "plane { point [0, 0, 0] normal [0, 1, 0] material { $m } }"
        echo "sphere { center [-5, 0.5, -8] radius 0.3 material { Kd 0.5 } }"
        echo "$l"
    } > $D/s/hand-$k.scene
done; done; done; done; done
s=$1
while [ $s -le $2 ]; do
    awk -v seed=$s -f tests/attack18/common.awk -f tests/attack19/common19.awk -f tests/attack24h/gen15.awk > $D/s/gen15-$s.scene
    s=$((s + 1))
done
cd $D/s
$D/new ${W:-32} ${H:-24} *.scene > $D/new.txt; e=$?
[ -n "${ONLYNEW:-}" ] || $D/base ${W:-32} ${H:-24} *.scene > $D/base.txt
strip() { sed 's/ shadow [0-9]*$//' "$1"; }
bad=0
[ $e = 0 ] || { grep DIFF $D/new.txt | head; echo "dbl_campaign: $(grep -c DIFF $D/new.txt) scenes differ on/off"; bad=1; }
if [ -z "${ONLYNEW:-}" ]; then
    strip $D/new.txt > $D/n.txt; strip $D/base.txt > $D/b.txt
    cmp -s $D/n.txt $D/b.txt || { diff $D/b.txt $D/n.txt | head; echo "dbl_campaign: $(diff $D/b.txt $D/n.txt | grep -c '^>') lines differ from the base"; bad=1; }
    fewer=$(paste -d' ' $D/new.txt $D/base.txt | awk '{ if ($NF != $(NF/2)) f++ } END { print f + 0 }')
fi
echo "dbl_campaign: $(grep -c . $D/new.txt) scenes ($(grep -c ': 0 ' $D/new.txt) rendered), ${fewer:-?} with other shadow-ray counts than the base"
exit $bad
