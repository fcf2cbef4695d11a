#!/bin/sh
# checkpoint_output_inside.sh - the output named tile-* inside the
# checkpoint directory: `--checkpoint ck -o ck/tile-result.png` (ck made
# first) and `--checkpoint . -o tile-final.pfm` exit 0, and the image is
# not there: the clean-up after the write removes every "tile-*" name
# (src/cli/cli_checkpoint.c, ours()), the output among them, then ck.
# Expected: the image written (exit 0) and kept, or a refusal before
# rendering; a render that says it succeeded has its output.
# (With ck missing, `-o ck/result.pfm` is refused at once, exit 74: held.)
# Run from the repository root after nice make -j2 build/refray:
#   sh tests/attack12/checkpoint_output_inside.sh   # exit 1 when the output is gone
set -u
B=$(pwd)/${B:-build/refray}
S=$(pwd)/tests/attack12/masked_sphere.scene
D=$(mktemp -d)
cd "$D" || exit 2
mkdir one two two/ck
(cd one && "$B" render "$S" -q --checkpoint . -o tile-final.pfm; echo "1: exit $?; left in .: $(ls)")
(cd two && "$B" render "$S" -q --checkpoint ck -o ck/tile-result.png; echo "2: exit $?; left: $(ls)")
ok=0
[ -f one/tile-final.pfm ] || ok=1
[ -f two/ck/tile-result.png ] || ok=1
cd / && rm -rf "$D"
exit $ok
