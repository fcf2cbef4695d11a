#!/bin/sh
# checkpoint_bitflip.sh - finding 3 on the --checkpoint path: a render of
# two_spheres.scene killed with SIGKILL after KILL_AFTER seconds (default
# 3), two bytes of the first kept tile's sidecar changed inside its pixels
# (one double's top bytes set to 0x3f 0xf0: a finite value >= 0), and the
# same command run again.  It resumes, exits 0 and writes the changed value.
# Expected ([SCALE-RESUME-3]): the damaged tile rendered again and the bytes
# of an uninterrupted render.
# Run from the repository root after nice make -j2 build/refray:
#   sh tests/attack12/checkpoint_bitflip.sh   # exit 1 when the resumed image differs
set -u
B=$(pwd)/${B:-build/refray}
S=$(pwd)/tests/attack12/two_spheres.scene
D=$(mktemp -d)
cd "$D" || exit 2
"$B" render "$S" -W -q -o whole.pfm || exit 2
timeout -s KILL "${KILL_AFTER:-3}" "$B" render "$S" -W -q --checkpoint ck -o out.pfm
f=$(ls ck/tile-*.pfm.tile 2>/dev/null | head -1)
[ -n "$f" ] || { echo "no tile kept: raise KILL_AFTER"; cd / && rm -rf "$D"; exit 2; }
H=$(head -5 "$f" | wc -c)
AT=$((H + 30 * 8 + 6))
printf '\360\077' | dd of="$f" bs=1 seek="$AT" conv=notrunc 2>/dev/null
"$B" render "$S" -W --checkpoint ck -o out.pfm
rc=$?
cmp -s out.pfm whole.pfm; same=$?
"$B" compare out.pfm whole.pfm | grep -E "max abs|differ"
cd / && rm -rf "$D"
echo "changed $f; resumed render exit $rc; identical to the uninterrupted render: $([ $same -eq 0 ] && echo yes || echo no)"
[ $rc -ne 0 ] || [ $same -eq 0 ]
