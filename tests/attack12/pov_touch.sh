#!/bin/sh
# pov_touch.sh - pov_glass_on_floor.scene with the floor g below the glass
# box, g = 0 (touching), 1e-6, 1e-3: `export --to pov --scale 0.5` (the
# header lists "approximations: 0"), POV-Ray 3.7 at 48 x 36 (one ray per
# pixel, 16-bit linear PNG), compared with refray's render (times 2).
# Also refray touching against refray at each gap (the [NUM-GLASS-3] limit).
# Run from the repository root after nice make -j2 build/refray:
#   sh tests/attack12/pov_touch.sh   # exit 1 when POV-Ray differs at g = 0 with nothing listed
set -u
B=$(pwd)/${B:-build/refray}
S=$(pwd)/tests/attack12/pov_glass_on_floor.scene
D=$(mktemp -d)
cd "$D" || exit 2
over0=
for g in 0 1e-6 1e-3; do
    sed "s/^let g = 0\$/let g = $g/" "$S" > s.scene
    "$B" render s.scene -q -o r.pfm || exit 2
    [ "$g" = 0 ] && cp r.pfm r0.pfm
    "$B" export s.scene --to pov --scale 0.5 -o s.pov || exit 2
    povray +Is.pov +Op.png +W48 +H36 -A -D -V +WT1 +FN16 File_Gamma=1.0 Output_Alpha=off > pov.log 2>&1 ||
        { echo "povray failed"; cat pov.log; exit 2; }
    over=$("$B" compare p.png r.pfm --scale 2 --tolerance 1e-3 | sed -n 's/^over: *\([0-9]*\) .*/\1/p')
    echo "g = $g: $(grep '^// approximations' s.pov); POV-Ray against refray: $over of 1728 pixels over 1e-3," \
         "$("$B" compare p.png r.pfm --scale 2 | grep 'max abs')"
    echo "        refray touching against refray at g: $("$B" compare r0.pfm r.pfm | grep 'max abs')"
    [ "$g" = 0 ] && over0=$over
done
cd / && rm -rf "$D"
[ "${over0:-1}" -eq 0 ]
