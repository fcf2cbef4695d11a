#!/bin/sh
# The sweep of spec/numerics.md 2.14: each shape at the origin seen by an
# orthographic eye D away on the x axis (from the side) and on the y axis
# (along a cylinder's or cone's axis), D = 1e2 .. 1e12.  An orthographic
# image does not depend on D (the rays are the same lines, their origins
# exact on an axis), so each is compared with the same view from 10 away
# (pixels that differ, `refray compare`), and with its own render under
# --no-shortcuts (cmp).  tests/attack10, finding 1: the cone from 1e7.
#   sh tests/far_view/sweep.sh [REFRAY] [W H]
set -u
refray=${1:-build/refray} w=${2:-16} h=${3:-12}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
shape() { # NAME: its text
    case $1 in
    cone) echo 'cone { from [0, -1, 0] to [0, 1, 0] radii 1 0.5 material { Kd 0.8 } }' ;;
    cone_open) echo 'cone { from [0, -1, 0] to [0, 1, 0] radii 1 0.5 open material { Kd 0.8 } }' ;;
    cone_apex) echo 'cone { from [0, -1, 0] to [0, 1, 0] radii 1 0 material { Kd 0.8 } }' ;;
    sphere) echo 'sphere { center [0, 0, 0] radius 1 material { Kd 0.8 } }' ;;
    cylinder) echo 'cylinder { from [0, -1, 0] to [0, 1, 0] radius 0.75 material { Kd 0.8 } }' ;;
    torus) echo 'torus { center [0, 0, 0] axis [0, 1, 0] major 0.8 minor 0.3 material { Kd 0.8 } }' ;;
    esac
}
render() { # NAME VIEW D [OPTION]: its PFM
    case $2 in
    side) eye="$3, 0, 0" up="0, 1, 0" ;;
    axis) eye="0, $3, 0" up="0, 0, -1" ;;
    esac
    f="$tmp/$1_$2_$3${4:+_ns}"
    { echo "image { width $w height $h }"
      echo "camera { orthographic eye [$eye] look_at [0, 0, 0] up [$up] width 2.6 }"
      echo "ambient { color 0.2 }"
      echo "point_light { position [3, 10, 2] power 40 falloff none }"
      shape "$1"; } >"$f.scene"
    "$refray" render "$f.scene" -q ${4:-} -o "$f.pfm" 2>/dev/null
}
differ() { "$refray" compare "$1" "$2" | sed -n 's/^differ: *\([0-9]*\).*/\1/p'; }
echo "shape view: pixels differing from D = 10 at D = 1e2 .. 1e12 (* : --no-shortcuts differs)"
for s in cone cone_open cone_apex sphere cylinder torus; do
    for v in side axis; do
        render $s $v 10
        line="$s $v:"
        for d in 1e2 1e4 1e6 1e7 1e8 1e9 1e10 1e12; do
            render $s $v $d && render $s $v $d --no-shortcuts
            n=$(differ "$tmp/${s}_${v}_$d.pfm" "$tmp/${s}_${v}_10.pfm")
            cmp -s "$tmp/${s}_${v}_$d.pfm" "$tmp/${s}_${v}_${d}_ns.pfm" || n="$n*"
            line="$line $n"
        done
        echo "$line"
    done
done
