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
. "$(dirname "$0")/lit.sh"
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
turn() { [ "$1" = x-cylinder ] && echo "rotate [30, 0, 0]" || echo "rotate [0, 30, 0]"; }
flat_of() { # NAME
    t=$(shape "$1")
    echo "${t#*|} $(turn "$1") material { Kd 0.8 } }"
    [ "$1" = box ] && echo "triangle { vertices [-0.7, 0, -0.7] [0.7, 0, 0.7] [-0.7, 0, 0.7] rotate [0, 30, 0] material { Kd 0.8 } }"
    return 0
}
squashed_of() { # NAME S
    t=$(shape "$1")
    [ "$1" = x-cylinder ] && scale="[$2, 1, 1]" || scale="[1, $2, 1]"
    echo "${t%%|*} scale $scale $(turn "$1") material { Kd 0.8 } }"
}
fail=0
echo "shape, eye: pixels over 1e-6 of the flat shape at s = S..., * : --no-shortcuts differs"
for eye in "[2.5, 3.2, -4]" "[-3, 1.2, 2.5]" "[0.6, 7, -1.5]"; do
    for sh in cylinder cone cone-upright cone-equal sphere disk box x-cylinder; do
        row $sh "$eye" 1e-10 1e-150 1e-155 1e-160 1e-161 3e-161 1e-162 1.5e-162 2e-162 3e-162 5e-162 1e-163 1e-170 1e-300
    done
done
[ $fail = 0 ] && echo "frame squash oblique sweep: ok" || echo "frame squash oblique sweep: FAIL"
exit $fail
