#!/bin/sh
# Shapes turned and then stretched, `rotate R scale [..S..]`, so that the
# stretch is along no axis of the shape's own frame ([NUM-FRAME-6],
# spec/numerics.md 2.17c), over a shiny floor at y = -1.5, lit from
# [3, 6, -2], from three eyes.  Expected (geometry, not refray's render of the
# shape): the unit sphere turned two ways and stretched along x is the
# ellipsoid x^2 / S^2 + y^2 + z^2 = 1, which within the |x| < 50 the
# views reach is the cylinder of radius 1 along x to (50 / S)^2 / 2 (1.3e-9
# at S = 1e6) in position and 50 / S^2 in its normals; the cylinder along x
# (|x| <= 1, radius 1) turned about x and stretched along z is, where seen,
# the plank |x| <= 1, |y| <= 1 to the same.  Their references are that
# cylinder from x = -1e4 to 1e4 and that box, no frame, their ends out of
# every view.  The cone and the torus, turned and stretched along x, are
# where seen their section across x swept along it, the same for every S
# to 50 / S (5e-9 at 1e10): their reference is their own image at S = 1e10.
# Each image is compared with its reference to 1e-6 relative, and with
# --no-shortcuts byte for byte.  The torus is shown, not judged: at S =
# 1e12 and 3e12 up to 14 pixels differ, its quartic's roots (the same with
# the points as they came before [NUM-FRAME-6]).  Exits 1 on any other
# departure.
#   sh tests/frame_squash/stretched.sh [REFRAY]
set -u
light="[3, 6, -2]"
. "$(dirname "$0")/lit.sh"
shape() { # NAME: the shape's text with its turn, "|", its stretch
    case $1 in
    cylinder) echo 'cylinder { from [-1, 0, 0] to [1, 0, 0] radius 1 rotate [30, 0, 0]|[1, 1, S]' ;;
    *) echo "$(turned "$1")|[S, 1, 1]" ;;
    esac
}
squashed_of() { # NAME S
    t=$(shape "$1")
    echo "${t%%|*} scale $(echo "${t#*|}" | sed "s/S/$2/") material { Kd 0.8 } }"
}
flat_of() { # NAME
    case $1 in
    sphere-*) echo 'cylinder { from [-1e4, 0, 0] to [1e4, 0, 0] radius 1 material { Kd 0.8 } }' ;;
    cylinder) echo 'box { from [-1, -1, -1e4] to [1, 1, 1e4] material { Kd 0.8 } }' ;;
    *) squashed_of "$1" 1e10 ;;
    esac
}
fail=0
echo "shape, eye: pixels over 1e-6 of the reference at S = ..., * : --no-shortcuts differs"
for eye in "[2.5, 3.2, -4]" "[-3, 1.2, 2.5]" "[0.6, 7, -1.5]"; do
    for sh in sphere-z sphere-xz cylinder; do
        row $sh "$eye" 1e6 1e8 1e10 1e12 1e13 1e14
    done
    row cone "$eye" 1e11 3e11 1e12 3e12 1e13 1e14
    judged=$fail
    row torus "$eye" 1e11 3e11 1e12 3e12 1e13 1e14
    fail=$judged
done
[ $fail = 0 ] && echo "frame stretched sweep: ok" || echo "frame stretched sweep: FAIL"
exit $fail
