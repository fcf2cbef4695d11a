#!/bin/sh
# hand_absorb.sh - attack 23: [SHADE-SHORTCUT-ABSORB-1] at its extremes, by
# hand.  Kd = 0 balls (opaque, and glass inside glass) of n 1, 1.5, 7.25,
# 1000, 1e5, 1048575, 1048576 under point lights of powers from 1e-300 to
# 1.7e308 (a highlight sum at DBL_MAX, saturated), one bright light with
# many dim ones, d0 1e-300 and inverse_square falloff, a distant light of
# 1e308, Ks 1e-300 .. 1 per channel: each scene rendered by the new binary
# (B) with and without --no-shortcuts, by the old one (OLD) and by the base
# (BASE); images and exit codes compared, and the counts (camera,
# reflection, refraction rays, light samples) against BASE.  Exit 1 on a
# difference.  From the repository root after `make build/refray`.
set -u
B=${B:-build/refray}
OLD=${OLD:-/tmp/old-main/build/refray}
BASE=${BASE:-/tmp/attack23-base/build/refray}
D=$(mktemp -d)
counts() { sed -n 's/^  rays: \([0-9]*\) camera, [0-9]* shadow, \(.*\); [0-9]* in all/\1 \2/p; /^  light samples:/p' "$1"; }
n=0 bad=0 ok=0 fewer=0
for nn in 1 1.5 7.25 1000 100000 1048575 1048576; do
for p in 1e-300 1 1e200 1e300 1.7e308; do
for glass in 0 1; do
    f=$D/s.scene
    {
        echo "image { width 24 height 16 max_depth 4 background [0.1, 0.1, 0.1] }"
        echo "camera { perspective eye [0, 1, 5] look_at [0, 0.5, 0] up [0, 1, 0] fov 50 }"
        echo "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0 Ks [1, 1e-300, 0.5] n $nn } }"
        if [ $glass = 1 ]; then
            echo "sphere { center [0, 0.8, 0] radius 0.8 material { Kd 0 Ks 0.5 n $nn t 0.9 ior 1.5 } }"
            echo "sphere { center [0, 0.8, 0] radius 0.4 material { Kd 0 Ks 1 n $nn t 0.5 ior 1.3 } }"
        else
            echo "sphere { center [0, 0.8, 0] radius 0.8 material { Kd 0 Ks [0.5, 1, 1e-9] n $nn } }"
            echo "sphere { center [1.5, 0.4, 0] radius 0.4 material { Kd 0 Ks 1 n $nn } }"
        fi
        echo "point_light { position [2, 3, 2] power $p }"
        echo "point_light { position [-2, 3, 1] power 1e-12 }"
        echo "point_light { position [0, 3, -2] power 1e-300 d0 1e-300 falloff inverse_square }"
        echo "point_light { position [1, 0.5, 3] power [1e-9, 1, 1e-20] falloff none }"
        echo "distant_light { direction [0.3, -1, 0.2] power 1e-200 }"
    } > "$f"
    $B render "$f" -q --stats -o $D/on.pfm >/dev/null 2>$D/on.st; e1=$?
    $B render "$f" -q --no-shortcuts -o $D/off.pfm >/dev/null 2>&1; e2=$?
    $OLD render "$f" -q -o $D/old.pfm >/dev/null 2>&1; e3=$?
    $BASE render "$f" -q --stats -o $D/base.pfm >/dev/null 2>$D/base.st; e4=$?
    n=$((n + 1)); msg=""; [ $e1 = 0 ] && ok=$((ok + 1)); s1=$(sed -n "s/.*camera, \([0-9]*\) shadow.*/\1/p" $D/on.st); s4=$(sed -n "s/.*camera, \([0-9]*\) shadow.*/\1/p" $D/base.st); [ "$s1" = "$s4" ] || fewer=$((fewer + 1))
    [ $e1 = $e2 ] && [ $e1 = $e3 ] && [ $e1 = $e4 ] || msg="exit $e1 $e2 $e3 $e4"
    if [ $e1 = 0 ]; then
        cmp -s $D/on.pfm $D/off.pfm || msg="$msg on/off"
        cmp -s $D/on.pfm $D/old.pfm || msg="$msg new/old"
        cmp -s $D/on.pfm $D/base.pfm || msg="$msg new/base"
        [ "$(counts $D/on.st)" = "$(counts $D/base.st)" ] || msg="$msg counts"
    fi
    [ -z "$msg" ] || { echo "hand_absorb: n $nn power $p glass $glass: $msg"; bad=1; }
done; done; done
echo "hand_absorb: $n scenes, $ok rendered, $fewer with fewer shadow rays than BASE"
[ -n "${KEEP:-}" ] || rm -rf "$D"
exit $bad
