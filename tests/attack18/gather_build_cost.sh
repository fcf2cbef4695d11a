#!/bin/sh
# gather_build_cost.sh - the cost of [SHADE-SHORTCUT-GATHER-2]'s neighbour
# lists in a scene of few glass parts and many opaque ones (attack 18,
# finding 2).  Two scenes of 300000 opaque balls (a 2x2 image, nothing
# glass in view) with 64 glass balls and with 65: the lists are built only
# for at most 64 (gather_alone_build), by a pass over every primitive for
# each transparent one (neighbours(): 64 x 300000 boxes formed and
# compared), so 64 costs more than 65 by that pass.  The time compared is
# the tracer's build as `--stats` prints it ("built in": tracer_build, the
# lists included), the least of three renders each (the machine is
# shared).  89e4c87: 0.81 s and 0.72 s (ratio about 1); b58baa2: 2.18 s
# and 0.69 s.  Exit 1 while 64 takes over 1.5 times as long as 65.  Run
# from the repository root after `make build/refray`; B=other/refray for
# another binary.
set -u
dir=$(mktemp -d) && trap 'rm -rf "$dir"' EXIT
for n in 64 65; do
    {
        echo "image { width 2 height 2 max_depth 3 }"
        echo "camera { perspective eye [0, 0, 5] look_at [0, 0, 0] up [0, 1, 0] fov 40 }"
        echo "point_light { position [0, 5, 5] power 10 }"
        echo "for i in 0 .. $((n - 1)) { sphere { center [i, 0, -40] radius 0.3 material { Kd 0.1 t 0.8 ior 1.5 } } }"
        echo "for i in 0 .. 299 { for j in 0 .. 999 { sphere { center [i, j + 2, -3] radius 0.3 material { Kd 0.5 } } } }"
    } > "$dir/$n.scene"
    for k in 1 2 3; do
        nice "${B:-build/refray}" render "$dir/$n.scene" --max-loop 10000000 --stats -q -o "$dir/$n.pfm" 2>&1 |
            sed -n 's/.*built in \([0-9.]*\) s.*/\1/p' >> "$dir/$n.times" || exit 2
    done
done
sort -n "$dir/64.times" | head -1 > "$dir/least"
sort -n "$dir/65.times" | head -1 >> "$dir/least"
awk 'NR == 1 {a = $1} NR == 2 {b = $1} END {
    if (a == "" || b == "") exit 2
    printf "tracer build: 64 glass %.3f s, 65 glass %.3f s, ratio %.2f (limit 1.5)\n", a, b, a / b
    exit !(a / b <= 1.5)
}' "$dir/least"
