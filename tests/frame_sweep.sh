#!/bin/sh
# frame_sweep.sh BIN DIR - [NUM-FRAME-1] (spec/numerics.md 2.17): every
# kind of shape that keeps its frame (scale [1, 0.5, 1] rotate [80, 62, 0]),
# of half size S in 1e-9, 1e-6, 1e-3, 1, rendered at 20x15 in two
# placements, each with and without --no-shortcuts (the two files must be
# the same to the byte):
#  - near: the shape at x = X and the eye 7.2 S from it at the same x, for
#    X in 0, -1e7, -1e11, -1e13, 1e15, -2^100.  The eye's x and the
#    shape's are the same double, so o - T is the same at every X, and the
#    image must be the one at X = 0, byte for byte (tests/attack9b,
#    finding 1: before, 1e13 / S >= 2^40 or so hit every ray);
#  - far: the shape at the origin and an orthographic camera (width 6 S)
#    D = S 10^k away, k in 4, 8, 12, 16, 17: past about 2^40 the local
#    ray is off by more than the shape, and only the box gate keeps the
#    walks the same.
# Prints each difference and "frame_sweep: N scenes, D differ (shortcuts),
# M differ (from X = 0)"; exits 1 when D or M is not 0.  Run from the
# repository root: sh tests/frame_sweep.sh build/refray /tmp/frame_sweep
bin=$1 out=$2
[ -x "$bin" ] && [ -n "$out" ] || { echo "usage: $0 BIN DIR" >&2; exit 64; }
mkdir -p "$out"
n=0 d=0 m=0
# both NAME TEXT: writes NAME.scene, renders it both ways; 0 when the same.
both() {
    printf '%s\n' "$2" > "$out/$1.scene"
    "$bin" render "$out/$1.scene" -q -o "$out/$1.a.pfm" >/dev/null 2>&1 &&
        "$bin" render "$out/$1.scene" -q --no-shortcuts -o "$out/$1.b.pfm" >/dev/null 2>&1 &&
        cmp -s "$out/$1.a.pfm" "$out/$1.b.pfm"
}
head='image { width 20 height 15 samples 1 max_depth 1 background 0.1 }'
tail='scale [1, 0.5, 1] rotate [80, 62, 0]'
for s in 1e-9 1e-6 1e-3 1; do
    for k in sphere box cylinder cone torus; do
        shape=$(awk -v s="$s" -v k="$k" 'BEGIN {
            if (k == "sphere") printf "sphere { radius %.17g", s;
            if (k == "box") printf "box { from [%.17g, %.17g, %.17g] to [%.17g, %.17g, %.17g]", -s, -s, -s, s, s, s;
            if (k == "cylinder") printf "cylinder { from [0, %.17g, 0] to [0, %.17g, 0] radius %.17g", -s, s, s;
            if (k == "cone") printf "cone { from [0, %.17g, 0] to [0, %.17g, 0] radii %.17g %.17g", -s, s, s, s / 2;
            if (k == "torus") printf "torus { major %.17g minor %.17g", s, 0.3 * s }')
        eye=$(awk -v s="$s" 'BEGIN { printf "%.17g, %.17g", 3.977874551863094 * s, -5.80152477284702 * s }')
        at=$(awk -v s="$s" 'BEGIN { printf "%.17g, 0", 0.5 * s }')
        move=$(awk -v s="$s" 'BEGIN { printf "%.17g, %.17g", 1.75 * s, s }')
        for x in 0 -1e7 -1e11 -1e13 1e15 -1267650600228229401496703205376; do
            name="near_${k}_${s}_$x" n=$((n + 1))
            both "$name" "$head
camera { perspective eye [$x, $eye] look_at [$x, $at] up [0, 1, 0] fov 60 }
ambient { color 0.05 }
$shape $tail translate [$x, $move] material { Kd 0.77 } }" || { d=$((d + 1)); echo "differs (shortcuts): $name"; }
            if [ "$x" != 0 ] && ! cmp -s "$out/$name.a.pfm" "$out/near_${k}_${s}_0.a.pfm"; then
                m=$((m + 1)); echo "differs (from x = 0): $name"
            fi
        done
        for e in 4 8 12 16 17; do
            name="far_${k}_${s}_1e$e" n=$((n + 1))
            cam=$(awk -v s="$s" -v e="$e" 'BEGIN { printf "eye [%.17g, %.17g, %.17g] look_at [0, %.17g, %.17g] up [0, 1, 0] width %.17g", -s * 10 ^ e, 0.1 * s, 0.2 * s, 0.1 * s, 0.2 * s, 6 * s }')
            both "$name" "$head
camera { orthographic $cam }
ambient { color 0.05 }
$shape $tail material { Kd 0.77 } }" || { d=$((d + 1)); echo "differs (shortcuts): $name"; }
        done
    done
done
echo "frame_sweep: $n scenes, $d differ (shortcuts), $m differ (from x = 0)"
[ "$d" = 0 ] && [ "$m" = 0 ]
