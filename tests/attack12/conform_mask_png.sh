#!/bin/sh
# conform_mask_png.sh - a kit manifest that lists the mask as PNG only
# (files.mask_pgm null with its reason under missing, files.mask_png kept;
# spec/conformance.md 2 lets any file be null) and says masked_pixels 4.
# conform (and compare --manifest) read only mask_pgm: with it null they
# compare every pixel, the excluded ones against the exact image's 0
# placeholders, and fail refray's own render ("4 of 63 pixels over ...
# exact (0, 0, 0)").  The exact image falls back from EXR to PFM; the mask
# does not fall back to PNG, and masked_pixels is not checked against the
# mask that is used.
# Run from the repository root after nice make -j2 build/refray:
#   sh tests/attack12/conform_mask_png.sh   # exit 1 when the right render fails
set -u
B=$(pwd)/${B:-build/refray}
D=$(mktemp -d)
"$B" kit -q -o "$D/kit" tests/attack12/masked_sphere.scene || exit 2
jq '.scenes[0].files.mask_pgm = null | .scenes[0].missing.mask_pgm = "not written: this kit has PNG masks"' \
    "$D/kit/manifest.json" > "$D/m" && mv "$D/m" "$D/kit/manifest.json" || exit 2
"$B" conform --kit "$D/kit" --format pfm --cmd "$B render {scene} -q -o {out}"
rc=$?
rm -rf "$D"
exit $rc
