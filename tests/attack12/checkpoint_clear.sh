#!/bin/sh
# checkpoint_clear.sh - `refray render S --checkpoint . -o out.pfm` in a
# directory that already holds the user's own files named tile-* (tiles of
# an earlier `--tile` run, tile-notes.txt) and refray-checkpoint-notes.md:
# the render succeeds and then deletes every one of them.
# cli_tiles_checkpoint_clear (src/cli/cli_checkpoint.c) unlinks every name
# that starts with "tile-" or "refray-checkpoint", whoever made it;
# [SCALE-RESUME-1] says "refray removes what it put in DIR".
# Expected: only the checkpoint's own tile-NNNNN.pfm(.tile) of its bands and
# its manifest are removed (or a non-empty DIR without a checkpoint
# manifest is refused, as kit -o refuses a directory that is not a kit).
# Run from the repository root after nice make -j2 build/refray:
#   sh tests/attack12/checkpoint_clear.sh   # exit 1 when the user's files are gone
set -u
B=$(pwd)/${B:-build/refray}
S=$(pwd)/tests/attack12/masked_sphere.scene
D=$(mktemp -d)
cd "$D" || exit 2
"$B" render "$S" -q --tile 0/2 -o tile-0.exr && "$B" render "$S" -q --tile 1/2 -o tile-1.pfm || exit 2
echo "my notes" > tile-notes.txt
echo "my notes" > refray-checkpoint-notes.md
echo "before: $(ls | tr '\n' ' ')"
"$B" render "$S" -q --checkpoint . -o out.pfm
rc=$?
echo "render exit $rc; after: $(ls | tr '\n' ' ')"
left=$(ls tile-0.exr tile-1.pfm tile-1.pfm.tile tile-notes.txt refray-checkpoint-notes.md 2>/dev/null | wc -l)
cd / && rm -rf "$D"
[ "$left" -eq 5 ]
