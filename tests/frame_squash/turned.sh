#!/bin/sh
# The squash across a frame's axes ([NUM-FRAME-5], spec/numerics.md 2.17a):
# a shape turned first and then squashed, `rotate R scale [1, S, 1]`, so
# that the squash is along no axis of the shape's own frame, at the origin
# over a shiny floor at y = -1.5, lit from above, from three eyes.
# Expected (geometry, not refray's render of the shape): to S, the shape is
# its own outline seen along y, flat in y = 0, with normals vertical: the
# sphere (turned two ways) the unit disk; the box [-0.7, 0.7] x [-1, 1] x
# [-0.7, 0.7] turned 30 degrees about z the rectangle |x| <= 0.7 cos 30 +
# sin 30 = 1.1062177826491071, |z| <= 0.7 (two triangles); the cylinder
# from y = -1 to 1 of radius 1 turned 90 degrees about z (lying along x)
# the square |x|, |z| <= 1; the cone and the torus, turned, their own image at
# S = 1e-10 (outlines not written out here).  Each image is compared with the flat shape's
# (no frame) to 1e-6 relative, and with --no-shortcuts byte for byte.  S
# from 1e-10 to 1e-300.  Exits 1 on any departure.
#   sh tests/frame_squash/turned.sh [REFRAY]
set -u
. "$(dirname "$0")/lit.sh"
quad() { # X Z: the rectangle |x| <= X, |z| <= Z in y = 0, two triangles
    echo "triangle { vertices [-$1, 0, -$2] [$1, 0, -$2] [$1, 0, $2] material { Kd 0.8 } }"
    echo "triangle { vertices [-$1, 0, -$2] [$1, 0, $2] [-$1, 0, $2] material { Kd 0.8 } }"
}
shape() { # NAME: the shape's text with its turn
    case $1 in
    box) echo 'box { from [-0.7, -1, -0.7] to [0.7, 1, 0.7] rotate [0, 0, 30]' ;;
    cylinder) echo 'cylinder { from [0, -1, 0] to [0, 1, 0] radius 1 rotate [0, 0, 90]' ;;
    *) turned "$1" ;;
    esac
}
squashed_of() { echo "$(shape "$1") scale [1, $2, 1] material { Kd 0.8 } }"; }
flat_of() { # NAME
    case $1 in
    sphere-*) echo 'disk { center [0, 0, 0] normal [0, 1, 0] radius 1 material { Kd 0.8 } }' ;;
    box) quad 1.1062177826491071 0.7 ;;
    cylinder) quad 1 1 ;;
    *) squashed_of "$1" 1e-10 ;;
    esac
}
fail=0
echo "shape, eye: pixels over 1e-6 of the flat shape at s = S..., * : --no-shortcuts differs"
for eye in "[2.5, 3.2, -4]" "[-3, 1.2, 2.5]" "[0.6, 7, -1.5]"; do
    for sh in sphere-z sphere-xz box cylinder cone torus; do
        row $sh "$eye" 1e-10 1e-12 1e-14 1e-16 1e-20 1e-50 1e-100 1e-150 1e-160 1e-162 1e-200 1e-300
    done
done
[ $fail = 0 ] && echo "frame squash turned sweep: ok" || echo "frame squash turned sweep: FAIL"
exit $fail
