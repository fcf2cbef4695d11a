#!/bin/sh
# The sweep of spec/numerics.md 2.17 for shapes squashed by a kept frame
# (tests/attack10, finding 2): a sphere, torus, cone, box, cylinder and disk
# with `scale [1, s, 1] rotate [0, 30, 0]` at the origin, seen from 10
# above, s = 1e-10 .. 1e-300.  At s = 1e-10 the sphere, cylinder, cone
# (radius 1 at the bottom) and disk are the flat disk of radius 1 seen from
# above (silhouette, normals vertical to 1e-10): their image must be the
# disk's without a frame.  At every s each shape must give its image at
# 1e-10 (pixels that differ, `refray compare`: the PFM's floats), and the
# same with --no-shortcuts (cmp).  Exits 1 on any departure.
#   sh tests/frame_squash/sweep.sh [REFRAY]
set -u
refray=${1:-build/refray}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/../sweep_mark.sh"
scene() { # SHAPE S: its text
    case $1 in
    sphere) s='sphere { center [0, 0, 0] radius 1' ;;
    torus) s='torus { center [0, 0, 0] axis [0, 1, 0] major 0.8 minor 0.4' ;;
    cone) s='cone { from [0, -1, 0] to [0, 1, 0] radii 1 0.5' ;;
    box) s='box { from [-0.7, -1, -0.7] to [0.7, 1, 0.7]' ;;
    cylinder) s='cylinder { from [0, -1, 0] to [0, 1, 0] radius 1' ;;
    disk) s='disk { center [0, 0, 0] normal [0, 1, 0] radius 1' ;;
    flat) echo 'disk { center [0, 0, 0] normal [0, 1, 0] radius 1 material { Kd 0.8 } }' ;;
    esac
    echo "image { width 16 height 12 }"
    echo "camera { eye [0, 10, 0.001] look_at [0, 0, 0] fov 20 }"
    echo "ambient { color 0.2 }"
    echo "point_light { position [3, 10, 2] power 40 falloff none }"
    [ "$1" = flat ] || echo "$s scale [1, $2, 1] rotate [0, 30, 0] material { Kd 0.8 } }"
}
differ() { "$refray" compare "$1" "$2" | sed -n 's/^differ: *\([0-9]*\).*/\1/p'; }
fail=0
scene flat >"$tmp/flat.scene"
"$refray" render "$tmp/flat.scene" -q -o "$tmp/flat.pfm" || exit 1
echo "shape: pixels differing from s = 1e-10 at s = 1e-12 .. 1e-300 (* : --no-shortcuts differs)"
for sh in sphere torus cone box cylinder disk; do
    scene $sh 1e-10 >"$tmp/ref.scene"
    "$refray" render "$tmp/ref.scene" -q -o "$tmp/ref.pfm" || exit 1
    line="$sh:"
    case $sh in sphere | cone | cylinder | disk)
        n=$(differ "$tmp/ref.pfm" "$tmp/flat.pfm")
        [ "$n" = 0 ] || fail=1
        line="$line (1e-10 against the flat disk: $n)" ;;
    esac
    for s in 1e-12 1e-14 1e-16 1e-20 1e-30 1e-50 1e-100 1e-154 1e-160 1e-200 1e-250 1e-300; do
        scene $sh $s >"$tmp/x.scene"
        "$refray" render "$tmp/x.scene" -q -o "$tmp/x.pfm" || exit 1
        "$refray" render "$tmp/x.scene" -q --no-shortcuts -o "$tmp/xn.pfm" || exit 1
        n=$(differ "$tmp/x.pfm" "$tmp/ref.pfm")
        mark "$n" "$tmp/x.pfm" "$tmp/xn.pfm"
    done
    echo "$line"
done
[ $fail = 0 ] && echo "frame squash sweep: ok" || echo "frame squash sweep: FAIL"
exit $fail
