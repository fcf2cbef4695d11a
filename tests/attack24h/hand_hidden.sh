#!/bin/sh
# hand_hidden.sh - attack 24h: [SHADE-SHORTCUT-HIDDEN-1] at its threshold.
# A Kd 0 mirror floor (t 0, or glass t 1 ior 1) of Ks 1 over a white
# background: its colour is 1 + H, and H passes half an ulp of 1 (2^-53)
# somewhere on the floor for one of the light powers swept (1e-18 .. 1e-13
# by 10^0.25): the shortcut is right only if it never leaves out a loop
# whose highlight reaches 2^-53.  Lights: a point light 1 over the floor
# (falloffs none, linear, inverse_square, d0 0 and 1), a disk of radius 1
# 0.01 over it with 16 samples, a disk of radius 1e-3 with 64, a long thin
# rectangle 0.02 over it, a grazing distant light; n 1, 30, 1e6.  Each scene
# by B on and off, and (unless ONLYB=1) by OLD and BASE with the counts.
# Exit 1 on a difference.  From the repository root.
set -u
. tests/attack24h/lights.sh
B=${B:-build/refray}
OLD=${OLD:-/tmp/old-main/build/refray}
BASE=${BASE:-/tmp/base24/build/refray}
D=$(mktemp -d)
counts() { sed -n 's/^  rays: \([0-9]*\) camera, [0-9]* shadow, \(.*\); [0-9]* in all/\1 \2/p; /^  light samples:/p' "$1"; }
shadows() { sed -n "s/.*camera, \([0-9]*\) shadow.*/\1/p" "$1"; }
n=0 bad=0 fewer=0
for lt in point pointlin pointinv pointd0 disk tiny rect distant; do
for nn in 1 30 1000000; do
for mat in mirror glass; do
for p in 1e-18 1.8e-18 3.2e-18 5.6e-18 1e-17 1.8e-17 3.2e-17 5.6e-17 1e-16 1.8e-16 3.2e-16 5.6e-16 1e-15 1.8e-15 3.2e-15 1e-14 1e-13; do
    f=$D/s.scene
    case $mat in
    mirror) m="Kd 0 Ks 1 n $nn t 0" ;;
    glass) m="Kd 0 Ks 1 n $nn t 1 ior 1" ;;
    esac
    hidden_light "$lt" "$p"
    {
        echo "image { width 32 height 24 max_depth 2 background [1, 1, 1] }"
        echo "camera { perspective eye [0, 1.5, 3] look_at [0, 0, -0.5] up [0, 1, 0] fov 60 }"
        echo "plane { point [0, 0, 0] normal [0, 1, 0] material { $m } }"
        echo "sphere { center [-5, 0.5, -8] radius 0.3 material { Kd 0.5 } }"
        echo "$l"
    } > "$f"
    $B render "$f" -q --stats -o $D/on.pfm >/dev/null 2>$D/on.st; e1=$?
    $B render "$f" -q --no-shortcuts -o $D/off.pfm >/dev/null 2>&1; e2=$?
    n=$((n + 1)); msg=""
    [ $e1 = $e2 ] || msg="exit $e1 $e2"
    [ $e1 = 0 ] && { cmp -s $D/on.pfm $D/off.pfm || msg="$msg on/off"; }
    if [ "${ONLYB:-0}" != 1 ]; then
        $OLD render "$f" -q -o $D/old.pfm >/dev/null 2>&1; e3=$?
        $BASE render "$f" -q --stats -o $D/base.pfm >/dev/null 2>$D/base.st; e4=$?
        [ $e1 = $e3 ] && [ $e1 = $e4 ] || msg="$msg exit old $e3 base $e4"
        if [ $e1 = 0 ]; then
            cmp -s $D/on.pfm $D/old.pfm || msg="$msg new/old"
            [ "$(counts $D/on.st)" = "$(counts $D/base.st)" ] || msg="$msg counts"
            [ "$(shadows $D/on.st)" = "$(shadows $D/base.st)" ] || fewer=$((fewer + 1))
        fi
    fi
    [ -z "$msg" ] || { echo "hand_hidden: $lt n $nn $mat power $p: $msg"; bad=1; [ -n "${FIRST:-}" ] && break 4; }
done; done; done; done
echo "hand_hidden: $n scenes, $fewer with other shadow-ray counts than BASE"
rm -rf "$D"
exit $bad
