#!/bin/sh
# tile_damaged.sh [REFRAY] - renders scenes/demo.scene at 16 x 12 in two
# tiles, writes NaN, +Inf or -1 over the first double of tile 0's sidecar
# (its pixel (0, 0), red; a render never makes any of the three), and merges.
# refray merge accepts each with exit 0 and no message, and writes 0, 0 and
# -1 where the tile held 0.35.  Run from the repository root.
set -e
B=${1:-build/refray}
D=$(mktemp -d)
"$B" render scenes/demo.scene --width 16 --height 12 --tile 0/2 -q -o "$D/t0.pfm"
"$B" render scenes/demo.scene --width 16 --height 12 --tile 1/2 -q -o "$D/t1.pfm"
cp "$D/t0.pfm.tile" "$D/good.tile"
for v in nan inf -1; do
    python3 - "$D/good.tile" "$D/t0.pfm.tile" "$v" <<'PY'
import struct, sys
t = open(sys.argv[1], 'rb').read()
at = t.index(b'pixels f64le\n') + len(b'pixels f64le\n')
open(sys.argv[2], 'wb').write(t[:at] + struct.pack('<d', float(sys.argv[3])) + t[at + 8:])
PY
    rc=0
    "$B" merge "$D/t0.pfm" "$D/t1.pfm" -o "$D/out.pfm" || rc=$?
    python3 - "$D/out.pfm" "$v" "$rc" <<'PY'
import struct, sys
d = open(sys.argv[1], 'rb').read(); q = d.split(b'\n', 3); w, h = map(int, q[1].split())
v = struct.unpack('<%df' % (3 * w * h), q[3])
print('tile pixel (0, 0) red = %s: merge exit %s, merged image (0, 0) red = %r' % (sys.argv[2], sys.argv[3], v[3 * (h - 1) * w]))
PY
done
rm -rf "$D"
