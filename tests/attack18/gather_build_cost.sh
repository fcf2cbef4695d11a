#!/bin/sh
# gather_build_cost.sh - the cost of [SHADE-SHORTCUT-GATHER-2]'s neighbour
# lists in a scene of few glass parts and many opaque ones (attack 18,
# finding 2).  Two scenes of 300000 opaque balls (a 2x2 image, nothing
# glass in view) with 64 glass balls and with 65: the lists are built only
# for at most 64 (gather_alone_build), by a pass over every primitive for
# each transparent one (neighbours(): 64 x 300000 boxes formed and
# compared), so 64 costs more than 65 by that pass.  89e4c87 renders both
# in the same time (ratio about 1.0); b58baa2 takes about twice as long
# for 64 (1M balls: 4.3 s against 8.0 s wall).  Each scene is rendered
# three times and the least wall time kept (the machine is shared).
# Exit 1 while 64 takes over 1.3 times as long as 65.  Run from the
# repository root after `make build/refray`; B=other/refray for another.
set -u
B=${B:-build/refray}
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
best() {
    cat > "$D/$1.scene" <<SCENE
image { width 2 height 2 max_depth 3 }
camera { perspective eye [0, 0, 5] look_at [0, 0, 0] up [0, 1, 0] fov 40 }
point_light { position [0, 5, 5] power 10 }
for i in 0 .. $(($1 - 1)) { sphere { center [i, 0, -40] radius 0.3 material { Kd 0.1 t 0.8 ior 1.5 } } }
for i in 0 .. 299 { for j in 0 .. 999 { sphere { center [i, j + 2, -3] radius 0.3 material { Kd 0.5 } } } }
SCENE
    m=
    for k in 1 2 3; do
        s=$(date +%s.%N)
        nice "$B" render "$D/$1.scene" --max-loop 10000000 -q -o "$D/$1.pfm" || exit 2
        e=$(date +%s.%N)
        m=$(echo "$s $e ${m:-1e9}" | awk '{d = $2 - $1; print (d < $3 ? d : $3)}')
    done
    echo "$m"
}
a=$(best 64) b=$(best 65)
echo "$a $b" | awk '{printf "64 glass: %.2f s, 65 glass: %.2f s, ratio %.2f (limit 1.3)\n", $1, $2, $1 / $2; exit !($1 / $2 <= 1.3)}'
