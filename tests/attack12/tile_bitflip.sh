#!/bin/sh
# tile_bitflip.sh - changed bytes inside a PFM tile sidecar's pixels (a disk
# or copy fault; the sidecar's length and header intact, the value still
# finite and >= 0).  A sidecar carries no checksum of its pixels, and the
# tile's own PFM (the same pixels as floats) is not compared with it:
#  1. merge: tiles 0/2 and 1/2 of masked_sphere.scene, one byte of tile 1's
#     sidecar changed (the high mantissa byte of its 10th double): `merge`
#     writes the changed value, exit 0, no word;
#  2. resume: two_spheres.scene rendered with --checkpoint and killed with
#     SIGKILL after KILL_AFTER seconds (default 3), two bytes of the first
#     kept tile's sidecar set to 0x3f 0xf0 (one double's top bytes), the
#     same command run again: it resumes, exits 0, and writes the value.
# Expected ([TILE-FILE-3], [SCALE-RESUME-3]: a damaged tile is refused or
# rendered again, "the output is again the bytes of an uninterrupted
# render"): a refusal, or the one-piece render's bytes.
# Run from the repository root after nice make -j2 build/refray:
#   sh tests/attack12/tile_bitflip.sh    # exit 1 when a damaged tile changes an image silently
set -u
B=$(pwd)/${B:-build/refray}
T=$(pwd)/tests/attack12
D=$(mktemp -d)
cd "$D" || exit 2
bad=0

# verdict WHAT EXIT OUT REF: prints the comparison; bad=1 on a silent change
verdict() {
    cmp -s "$3" "$4" && same=yes || same=no
    "$B" compare "$3" "$4" | grep -E "max abs|differ"
    echo "$1: exit $2; identical to the one-piece render: $same"
    [ "$2" -ne 0 ] || [ $same = yes ] || bad=1
}

# put FILE AT BYTES: writes the octal-escaped BYTES into FILE at offset AT
put() {
    printf "$3" | dd of="$1" bs=1 seek="$2" conv=notrunc 2>/dev/null
}

"$B" render "$T/masked_sphere.scene" -q -o whole.pfm || exit 2
"$B" render "$T/masked_sphere.scene" -q --tile 0/2 -o t0.pfm || exit 2
"$B" render "$T/masked_sphere.scene" -q --tile 1/2 -o t1.pfm || exit 2
AT=$(($(head -5 t1.pfm.tile | wc -c) + 9 * 8 + 6))
B0=$(od -An -tu1 -j "$AT" -N1 t1.pfm.tile | tr -d ' ')
put t1.pfm.tile "$AT" "$(printf '\\%03o' $(((B0 + 0x10) % 256)))"
"$B" merge t0.pfm t1.pfm -o merged.pfm
verdict "merge" $? merged.pfm whole.pfm

"$B" render "$T/two_spheres.scene" -W -q -o whole2.pfm || exit 2
timeout -s KILL "${KILL_AFTER:-3}" "$B" render "$T/two_spheres.scene" -W -q --checkpoint ck -o out.pfm
f=$(ls ck/tile-*.pfm.tile 2>/dev/null | head -1)
if [ -n "$f" ]; then
    put "$f" $(($(head -5 "$f" | wc -c) + 30 * 8 + 6)) '\360\077'
    "$B" render "$T/two_spheres.scene" -W --checkpoint ck -o out.pfm
    verdict "resume after changing $f" $? out.pfm whole2.pfm
else
    echo "resume: no tile kept after ${KILL_AFTER:-3} s: raise KILL_AFTER"
fi
cd / && rm -rf "$D"
exit $bad
