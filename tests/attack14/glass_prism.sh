#!/bin/sh
# glass_prism.sh - a closed glass L prism written twice: once plainly
# (L_prism.obj) and once with two corners of each L face written twice
# (L_prism_repeat.obj), the same solid.  The two pictures must be equal.
#   sh tests/attack14/glass_prism.sh     # exit 1 while they differ
. tests/attack14/lib.sh
for m in L_prism L_prism_repeat; do
    mesh_scene glass_prism.scene $m
    "$R" check "$D/$m.scene" 2>/dev/null | sed -n 2p | sed "s|$D/||"
    "$R" render "$D/$m.scene" -q -o "$D/$m.pfm" 2> "$D/$m.err" || { cat "$D/$m.err"; exit 2; }
done
grep -o 'warning: [^(]*' "$D/L_prism_repeat.err"
"$R" compare "$D/L_prism_repeat.pfm" "$D/L_prism.pfm" | grep '^max abs\|^differ'
"$R" compare "$D/L_prism_repeat.pfm" "$D/L_prism.pfm" | grep -q '^differ: *0 pixels'
