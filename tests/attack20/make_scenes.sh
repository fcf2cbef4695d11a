#!/bin/sh
# make_scenes.sh - writes attack 20's hand scenes into tests/attack20/scenes
# (kept in the repository; run again after editing this): shadow rays of
# point-like and flat area lights through the shared edges and corners of
# lattice meshes, at scales 1e-6 .. 1e6 and moved to 1e8; pixel centres,
# mesh edges and light corners on one 0.25 lattice.  Run from tests/attack20.
set -eu
d=scenes
for S in 1 0.001 1000 1e-6 1e6; do
for T in 0 1e8; do
for L in point flat slant disk; do
for t in 0 0.5; do
    f="$d/edge_${L}_t${t}_S${S}_T${T}.scene"
    w=$(awk -v S=$S 'BEGIN{printf "%.17g", 4 * S}')
    c=$(awk -v S=$S -v T=$T 'BEGIN{printf "%.17g", T + 0.125 * S}')
    e=$(awk -v S=$S -v T=$T 'BEGIN{printf "%.17g", T + 5 * S}')
    o=$(awk -v T=$T 'BEGIN{printf "%.17g", T}')
    lx=$(awk -v S=$S -v T=$T 'BEGIN{printf "%.17g", T}')
    ly=$(awk -v S=$S -v T=$T 'BEGIN{printf "%.17g", T + 2 * S}')
    p=$(awk -v S=$S 'BEGIN{printf "%.17g", 10 * S * S}')
    case $L in
    point) light="distributed_light { rectangle [$lx, $ly, $lx] [$(awk -v S=$S 'BEGIN{printf "%.17g", 1e-12 * S}'), 0, 0] [0, 0, $(awk -v S=$S 'BEGIN{printf "%.17g", 1e-12 * S}')] power $p samples 4 }" ;;
    flat) light="distributed_light { rectangle [$lx, $ly, $lx] [$(awk -v S=$S 'BEGIN{printf "%.17g", 0.5 * S}'), 0, 0] [0, 0, $(awk -v S=$S 'BEGIN{printf "%.17g", 0.25 * S}')] power $p samples 9 }" ;;
    slant) light="distributed_light { rectangle [$lx, $ly, $lx] [$(awk -v S=$S 'BEGIN{printf "%.17g, 0, %.17g", S, S}')] [0, $(awk -v S=$S 'BEGIN{printf "%.17g", 0.5 * S}'), 0] power $p samples 9 }" ;;
    disk) light="distributed_light { disk [$lx, $ly, $lx] [1, -1, 0.5] $(awk -v S=$S 'BEGIN{printf "%.17g", 1e-9 * S}') power $p samples 4 }" ;;
    esac
    {
        echo "# attack 20: shadow rays from lattice pixel centres through a lattice mesh's shared edges"
        echo "image { width 16 height 16 max_depth 2 background 0.2 }"
        echo "camera { orthographic eye [$c, $e, $c] look_at [$c, $o, $c] up [0, 0, -1] width $w }"
        echo "$light"
        echo "plane { point [$o, $o, $o] normal [0, 1, 0] material { Kd 0.8 } }"
        echo "mesh { file \"sheet.obj\" material { Kd 0.3 t $t ior 1 } scale $S translate [$o, $(awk -v S=$S -v T=$T 'BEGIN{printf "%.17g", T + S}'), $o] }"
        echo "mesh { file \"octa.obj\" material { Kd 0.3 t $t ior 1 } scale $S translate [$(awk -v S=$S -v T=$T 'BEGIN{printf "%.17g, %.17g, %.17g", T + S, T + 0.5 * S, T}')] }"
        echo "mesh { file \"fan.obj\" material { Kd 0.3 t $t ior 1 } scale $S rotate [0, 45, 0] translate [$(awk -v S=$S -v T=$T 'BEGIN{printf "%.17g, %.17g, %.17g", T - S, T + 0.5 * S, T + S}')] }"
    } > "$f"
done
done
done
done
# The shading points on a mesh floor (sheet.obj, twice as dense as the
# pixels), lights at the horizon: the rays graze the floor's own triangles,
# the origin just above their plane.
for S in 1 1e-6 1e6; do
for h in 0.01 1e-9 0.5; do
for t in 0 0.5; do
    f="$d/floor_h${h}_t${t}_S${S}.scene"
    a() { awk -v S=$S -v h=$h "BEGIN{printf $1}"; }
    {
        echo "# attack 20: shadow rays grazing a lattice mesh floor toward lights at the horizon"
        echo "image { width 16 height 16 max_depth 2 background 0.2 }"
        echo "camera { orthographic eye [$(a '"%.17g, %.17g, %.17g", 0.125 * S, 5 * S, 0.125 * S')] look_at [$(a '"%.17g, 0, %.17g", 0.125 * S, 0.125 * S')] up [0, 0, -1] width $(a '"%.17g", 4 * S')}"
        echo "distributed_light { rectangle [$(a '"%.17g, %.17g, %.17g", 3 * S, h * S, -1 * S')] [0, 0, $(a '"%.17g", 2 * S')] [0, $(a '"%.17g", h * S')] , 0] power $(a '"%.17g", 10 * S * S')] samples 9 }" | sed 's/\] , 0\]/, 0]/; s/power \([^]]*\)\] samples/power \1 samples/'
        echo "distributed_light { disk [$(a '"%.17g, %.17g, %.17g", -3 * S, h * S, 3 * S')] [1, 0, -1] $(a '"%.17g", 0.25 * S')] power $(a '"%.17g", 10 * S * S')] samples 4 }" | sed 's/\] power/ power/; s/power \([^]]*\)\] samples/power \1 samples/'
        echo "mesh { file \"sheet.obj\" material { Kd 0.8 t $t ior 1 } scale $(a '"%.17g", 4 * S') }"
        echo "mesh { file \"octa.obj\" material { Kd 0.3 t $t ior 1 } scale $S translate [$(a '"%.17g, %.17g, %.17g", S, 0.25 * S, 0')] }"
    } > "$f"
done
done
done
