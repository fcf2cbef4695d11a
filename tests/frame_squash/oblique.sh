#!/bin/sh
# The squash sweep of spec/numerics.md 2.17a seen obliquely, through the
# window s = 1e-150 .. 1e-163 where a cylinder's |dp|^2 is subnormal
# ([NUM-FRAME-4]; tests/attack13, finding 3): the shapes with flat ends or
# faces and the sphere, `scale S rotate [0, 30, 0]` at the origin over a
# shiny floor at y = -1.5, lit from above, from three eyes (oblique, low from
# the other side, steep), with shadow and mirror rays through the shape.
# Expected (geometry, not refray's render of the shape): squashed along y,
# the cylinder, the cones (radius 1 at the bottom, 0.5, 1.0000001 or 1 at
# the top), the sphere and the disk are the unit disk in y = 0 to s (silhouette
# from every direction, normals vertical to s), the box the square of its
# section (two triangles); the cylinder along x squashed along x the unit
# disk across x (`x-cylinder`, turned about x: turned about y after that
# squash its matrix is refused as singular, check_invert).  Each image is
# compared with the flat shape's (no frame) to 1e-6 relative (`refray
# compare --tolerance`: the world points come back through the frame), and
# with --no-shortcuts byte for byte.  Exits 1 on any departure.
#   sh tests/frame_squash/oblique.sh [REFRAY]
set -u
refray=${1:-build/refray}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/../sweep_mark.sh"
head() { # EYE
    echo "image { width 32 height 24 max_depth 3 }"
    echo "camera { eye $1 look_at [0, 0, 0] fov 45 }"
    echo "ambient { color 0.2 }"
    echo "point_light { position [0.8, 6, 0.5] power 40 falloff none }"
    echo "plane { point [0, -1.5, 0] normal [0, 1, 0] material { Kd 0.5 Ks 0.4 n 20 } }"
}
shape() { # NAME: the squashed shape's text up to its transform, "|", the flat one's
    case $1 in
    cylinder) echo 'cylinder { from [0, -1, 0] to [0, 1, 0] radius 1|disk { center [0, 0, 0] normal [0, 1, 0] radius 1' ;;
    cone) echo 'cone { from [0, -1, 0] to [0, 1, 0] radii 1 0.5|disk { center [0, 0, 0] normal [0, 1, 0] radius 1' ;;
    cone-equal) echo 'cone { from [0, -1, 0] to [0, 1, 0] radii 1 1|disk { center [0, 0, 0] normal [0, 1, 0] radius 1' ;;
    cone-upright) echo 'cone { from [0, -1, 0] to [0, 1, 0] radii 1 1.0000001|disk { center [0, 0, 0] normal [0, 1, 0] radius 1.0000001' ;;
    sphere) echo 'sphere { center [0, 0, 0] radius 1|disk { center [0, 0, 0] normal [0, 1, 0] radius 1' ;;
    disk) echo 'disk { center [0, 0, 0] normal [0, 1, 0] radius 1|disk { center [0, 0, 0] normal [0, 1, 0] radius 1' ;;
    box) echo 'box { from [-0.7, -1, -0.7] to [0.7, 1, 0.7]|triangle { vertices [-0.7, 0, -0.7] [0.7, 0, -0.7] [0.7, 0, 0.7]' ;;
    x-cylinder) echo 'cylinder { from [-1, 0, 0] to [1, 0, 0] radius 1|disk { center [0, 0, 0] normal [1, 0, 0] radius 1' ;;
    esac
}
fail=0
echo "shape, eye: pixels over 1e-6 of the flat shape at s = S..., * : --no-shortcuts differs"
for eye in "[2.5, 3.2, -4]" "[-3, 1.2, 2.5]" "[0.6, 7, -1.5]"; do
    for sh in cylinder cone cone-upright cone-equal sphere disk box x-cylinder; do
        t=$(shape $sh)
        squashed=${t%%|*} flat=${t#*|} turn="rotate [0, 30, 0]"
        [ $sh = x-cylinder ] && turn="rotate [30, 0, 0]"
        { head "$eye"; echo "$flat $turn material { Kd 0.8 } }"
          [ $sh = box ] && echo "triangle { vertices [-0.7, 0, -0.7] [0.7, 0, 0.7] [-0.7, 0, 0.7] rotate [0, 30, 0] material { Kd 0.8 } }"
        } >"$tmp/flat.scene"
        "$refray" render "$tmp/flat.scene" -q -o "$tmp/flat.pfm" || exit 1
        line="$sh $eye:"
        for s in 1e-10 1e-150 1e-155 1e-160 1e-161 3e-161 1e-162 1.5e-162 2e-162 3e-162 5e-162 1e-163 1e-170 1e-300; do
            scale="[1, $s, 1]"
            [ $sh = x-cylinder ] && scale="[$s, 1, 1]"
            { head "$eye"; echo "$squashed scale $scale $turn material { Kd 0.8 } }"; } >"$tmp/x.scene"
            "$refray" render "$tmp/x.scene" -q -o "$tmp/x.pfm" || exit 1
            "$refray" render "$tmp/x.scene" -q --no-shortcuts -o "$tmp/xn.pfm" || exit 1
            n=$("$refray" compare "$tmp/x.pfm" "$tmp/flat.pfm" --tolerance 1e-6 | sed -n 's/^over: *\([0-9]*\).*/\1/p')
            mark "${n:-0}" "$tmp/x.pfm" "$tmp/xn.pfm"
        done
        echo "$line"
    done
done
[ $fail = 0 ] && echo "frame squash oblique sweep: ok" || echo "frame squash oblique sweep: FAIL"
exit $fail
