#!/bin/sh
# squash_oblique.sh - [NUM-FRAME-2]/[NUM-FRAME-3] beyond tests/frame_squash:
# a sphere, cylinder and disk squashed by `scale [1, s, 1]`, turned, lifted
# to y = 1 above a shiny floor, seen obliquely, lit from above: the floor's
# shadow rays and mirror rays cross the squashed shape.  At every s the
# image must be the flat disk's (radius 1 at y = 1, no frame): the squashed
# shapes' silhouettes from every direction are that disk to s, their
# normals vertical to s (independent of refray: geometry).  Prints the
# pixels that differ and whether --no-shortcuts is byte-identical; exits 1
# on any departure.
#   sh tests/attack13/squash_oblique.sh
set -u
B=${B:-build/refray}
T=$(mktemp -d)
head() {
    echo "image { width 32 height 24 max_depth 3 }"
    echo "camera { eye [2.5, 3.2, -4] look_at [0, 0.6, 0] fov 50 }"
    echo "ambient { color 0.2 }"
    echo "point_light { position [0.8, 6, 0.5] power 40 falloff none }"
    echo "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0.5 Ks 0.4 n 20 } }"
}
head > $T/flat.scene
echo 'disk { center [0, 1, 0] normal [0, 1, 0] radius 1 material { Kd 0.8 } }' >> $T/flat.scene
nice $B render $T/flat.scene -q -o $T/flat.pfm || exit 2
fail=0
for sh in sphere cylinder disk; do
    case $sh in
    sphere) s='sphere { center [0, 0, 0] radius 1' ;;
    cylinder) s='cylinder { from [0, -1, 0] to [0, 1, 0] radius 1' ;;
    disk) s='disk { center [0, 0, 0] normal [0, 1, 0] radius 1' ;;
    esac
    line="$sh:"
    for e in ${ES:-1e-7 1e-10 1e-14 1e-20 1e-50 1e-100 1e-160 1e-300}; do
        { head; echo "$s scale [1, $e, 1] rotate [0, 30, 0] translate [0, 1, 0] material { Kd 0.8 } }"; } > $T/x.scene
        nice $B render $T/x.scene -q -o $T/x.pfm || exit 2
        nice $B render $T/x.scene -q --no-shortcuts -o $T/n.pfm || exit 2
        n=$($B compare $T/x.pfm $T/flat.pfm --tolerance 1e-6 | sed -n 's/^over: *\([0-9]*\).*/\1/p')
        [ -n "$n" ] || n=0
        cmp -s $T/x.pfm $T/n.pfm && m="" || { m="*"; fail=1; }
        [ "$n" = 0 ] || fail=1
        line="$line $e:$n$m"
    done
    echo "$line"
done
rm -rf $T
exit $fail
