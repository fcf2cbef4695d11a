#!/bin/sh
# quad_far.sh - one square written as a quad and as its two triangles, in
# file units of 1e160 scaled back to size 2 by the mesh's `scale 1e-160`.
# The two files describe the same surface, so the two pictures must agree
# (or both be refused for the same reason).
#   sh tests/attack14/quad_far.sh     # exit 1 while the quad alone is refused
. tests/attack14/lib.sh
for m in quad_far quad_far_tris; do
    mesh_scene quad_far.scene $m
    if "$R" render "$D/$m.scene" -q -o "$D/$m.pfm" 2> "$D/$m.err"; then
        echo "$m.obj: rendered"
    else
        echo "$m.obj: exit $?: $(grep -o 'error: .*' "$D/$m.err" | head -1)"
    fi
done
[ -f "$D/quad_far.pfm" ] && [ -f "$D/quad_far_tris.pfm" ] || exit 1
"$R" compare "$D/quad_far.pfm" "$D/quad_far_tris.pfm" | grep '^differ'
"$R" compare "$D/quad_far.pfm" "$D/quad_far_tris.pfm" | grep -q '^differ: *0 pixels'
