#!/bin/sh
# stack_figures.sh - spec/reliability.md [REL-STACK-1] states that 1000
# mirror bounces render in a 1284 KiB stack ("(ulimit -s 1284; build/refray
# render /tmp/mc.scene ...)  # 0") and 999 total reflections in a glass cube
# in 1870 KiB, "178 KiB to spare" under 2 MiB.  At ae0ba50 the mirror chain
# needs 1392 KiB and the glass chain 1948 KiB (89e4c87: 1284 and 1861):
# shade's frame grew by the mirror_trace of [SHADE-SHORTCUT-TIR-1] (about
# 110 bytes a bounce), on every bounce, opaque mirrors too.  Exits 1 while
# the spec's own command dies (SIGSEGV, 139).  B: the binary (build/refray).
# Run from the repository root.
B=${B:-build/refray}
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
printf 'image { width 1 height 1 max_depth 1000 }\ncamera { eye [0, 0, 0] look_at [0, 0, -1] fov 1 }\nambient { color 1 }\nplane { point [0, 0, -1] normal [0, 0, 1] material { Kd 0.001 Ks 0.999 } }\nplane { point [0, 0, 1] normal [0, 0, -1] material { Kd 0.001 Ks 0.999 } }\n' > "$D/mc.scene"
printf 'image { width 1 height 1 max_depth 1000 }\ncamera { eye [0, 0, 0] look_at [1, 1, 1] fov 0.001 }\nambient { color 1 }\nbox { from [-1, -1, -1] to [1, 1, 1] material { Kd 0.001 Ks 0 t 0.999 ior 1.5 } }\n' > "$D/tir.scene"
(ulimit -s 1310; "$B" render "$D/mc.scene" -q -o "$D/mc.pfm" >/dev/null 2>&1); a=$?
(ulimit -s 1890; "$B" render "$D/tir.scene" -q -o "$D/tir.pfm" >/dev/null 2>&1); b=$?
echo "mirror chain in 1310 KiB: exit $a; glass chain in 1890 KiB: exit $b (0 and 0 expected)"
[ "$a" = 0 ] && [ "$b" = 0 ]
