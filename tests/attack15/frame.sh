#!/bin/sh
# frame.sh - a closed glass square frame whose two big faces are keyhole
# polygons (frame_keyhole.obj, the bridge's ends on the walls) against the
# same solid with those faces cut by hand into strips (frame_ref.obj):
# refray check must find both closed, and the renders must be the same.
# Exit 1 when they differ.   sh tests/attack15/frame.sh
set -u
R=${REFRAY:-build/refray}
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
for m in frame_keyhole frame_ref; do
    cp tests/attack15/$m.obj $D/ && sed "s/MESH/$m.obj/" tests/attack15/frame.scene > $D/$m.scene
    "$R" check $D/$m.scene 2>&1 | sed -n 2p | sed "s|$D/||"
    "$R" render $D/$m.scene -q -o $D/$m.pfm || exit 2
done
"$R" compare $D/frame_keyhole.pfm $D/frame_ref.pfm | grep '^differ'
cmp -s $D/frame_keyhole.pfm $D/frame_ref.pfm
