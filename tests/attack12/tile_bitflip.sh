#!/bin/sh
# tile_bitflip.sh - one byte of a PFM tile's sidecar changed inside its
# pixels (a disk or copy fault; the sidecar's length and header intact, the
# value still finite and >= 0).  A sidecar carries no checksum of its
# pixels, and the tile's own PFM (which holds the same pixels as floats) is
# not compared with it, so `merge` writes the changed value into the image,
# exit 0, no word; the same for a --checkpoint directory on resume.
# Expected ([TILE-FILE-3], [SCALE-RESUME-3]: a damaged tile is refused or
# rendered again, "the output is again the bytes of an uninterrupted
# render"): a refusal, or the one-piece render's bytes.
# Run from the repository root after nice make -j2 build/refray:
#   sh tests/attack12/tile_bitflip.sh    # exit 1 when the damaged merge differs silently
set -u
B=$(pwd)/${B:-build/refray}
S=$(pwd)/tests/attack12/masked_sphere.scene
D=$(mktemp -d)
cd "$D" || exit 2
"$B" render "$S" -q -o whole.pfm || exit 2
"$B" render "$S" -q --tile 0/2 -o t0.pfm && "$B" render "$S" -q --tile 1/2 -o t1.pfm || exit 2
# the header is five lines; the pixels follow: change byte 6 (the high
# mantissa byte) of the 10th double (pixel 3's red, row 0 of tile 1)
H=$(head -5 t1.pfm.tile | wc -c)
AT=$((H + 9 * 8 + 6))
B0=$(od -An -tu1 -j "$AT" -N1 t1.pfm.tile | tr -d ' ')
printf "$(printf '\\%03o' $(( (B0 + 0x10) % 256 )))" | dd of=t1.pfm.tile bs=1 seek="$AT" conv=notrunc 2>/dev/null
"$B" merge t0.pfm t1.pfm -o merged.pfm
rc=$?
cmp -s merged.pfm whole.pfm; same=$?
"$B" compare merged.pfm whole.pfm | grep -E "max abs|differ"
cd / && rm -rf "$D"
echo "merge exit $rc; merged image identical to the one-piece render: $([ $same -eq 0 ] && echo yes || echo no)"
[ $rc -ne 0 ] || [ $same -eq 0 ]
