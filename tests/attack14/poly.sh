#!/bin/sh
# poly.sh - polygons cut by ear clipping ([MESH-POLY-1]) against the same
# region cut into triangles by hand (the *_ref.obj files), ambient light
# only: the two pictures must be equal pixel for pixel (no pixel centre lies
# on an edge: the centres are at odd multiples of 3/64 from 2).
#   sh tests/attack14/poly.sh      # exit 1 when a polygon's picture differs
. tests/attack14/lib.sh
status=0
for pair in L_repeat:L_ref comb_repeat:comb_ref spike:square_ref pinch:pinch_ref keyhole:keyhole_ref keyhole2:keyhole_ref star:star_ref uu:uu_ref; do
    m=${pair%%:*} ref=${pair#*:}
    for x in $m $ref; do
        mesh_scene poly.scene $x
        "$R" render "$D/$x.scene" -q -o "$D/$x.pfm" 2> "$D/$x.err" || { cat "$D/$x.err"; exit 2; }
    done
    n=$("$R" compare "$D/$m.pfm" "$D/$ref.pfm" | sed -n 's/^differ: *\([0-9]*\) pixels.*/\1/p')
    w=$(grep -o 'warning: [^;(]*' "$D/$m.err" | head -1)
    echo "$m.obj against $ref.obj: $n pixels differ${w:+; $w}"
    [ "$n" = 0 ] || status=1
done
exit $status
