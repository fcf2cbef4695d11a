#!/bin/sh
# conform_pfm_variants.sh - refray's own render of two kit scenes
# (lambert_sphere, ambient_only), rewritten by pfmtool.c as other programs
# write PFM, judged by conform: big-endian (scale +1.0), a scale magnitude
# of 2 and of 1e-30, 12 and 100000 bytes after the raster, values times
# 1 +- 5e-5 (inside the 1e-4 bound), a one-channel Pf of the red channel,
# and CR LF header lines.  Prints one verdict line per variant.
# Run from the repository root after nice make -j2 build/refray:
#   sh tests/attack12/conform_pfm_variants.sh
set -u
B=$(pwd)/${B:-build/refray}
D=$(mktemp -d)
cc -std=c99 -O2 -o "$D/pfmtool" tests/attack12/pfmtool.c -lm || exit 2
"$B" kit -q -o "$D/kit" scenes/analytic/lambert_sphere.scene scenes/analytic/ambient_only.scene || exit 2
for v in be: mag:2.0 mag:1e-30 tail:12 tail:100000 scale:1.00005 scale:0.99995 gray: crlf:; do
    op=${v%%:*}
    arg=${v#*:}
    line=$("$B" conform --kit "$D/kit" --format pfm \
        --cmd "$B render {scene} -q -o {out}.pfm && $D/pfmtool $op {out}.pfm {out} $arg" | tail -1)
    reason=$("$B" conform --kit "$D/kit" --format pfm --only lambert_sphere \
        --cmd "$B render {scene} -q -o {out}.pfm && $D/pfmtool $op {out}.pfm {out} $arg" | sed -n 3p | cut -c1-90)
    echo "$op $arg: $line ${reason:+| lambert_sphere: $reason}"
done
rm -rf "$D"
