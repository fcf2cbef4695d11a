#!/bin/sh
# pfm_trailing_newline.sh - [KIT-PFM-1] takes a PFM's pixel data as the
# file's last bytes and accepts white space between the header and them.
# A picture with one byte after its raster (a writer that ends the file
# with a new line) is refused with the reason "... bytes longer than its
# header ..." when its first raster byte is not a white-space byte; when
# it is (the low byte of the bottom-left red float: 6 of 256 values), the
# file is taken, read one byte off, and judged as another picture.  The
# script sets that byte to 0x0a (the value moves by under 3e-5 relative,
# inside the 1e-4 bound) and appends a new line, and prints conform's
# verdicts with and without the byte set.  Exits 1 when the two are not
# the same refusal.
#   sh tests/attack13/pfm_trailing_newline.sh
set -u
B=$(pwd)/${B:-build/refray}
D=$(mktemp -d)
nice "$B" kit -q -o $D/kit scenes/analytic/lambert_sphere.scene || exit 2
# $1: the picture refray wrote; $2: set its first raster byte (after the
# 14-byte header "PF\n96 72\n-1.0\n") to a new line first
cat > $D/nl.sh <<'EOS'
[ "$2" = white ] && printf '\n' | dd of="$1" bs=1 seek=14 conv=notrunc 2>/dev/null
printf '\n' >> "$1"
EOS
r=""
for v in plain white; do
    out=$(nice "$B" conform --kit $D/kit --format pfm \
        --cmd "$B render {scene} -q -o {out} && sh $D/nl.sh {out} $v" | sed -n '3p' | cut -c1-160)
    echo "$v: $out"
    r="$r|${out%%:*}"
done
rm -rf $D
case $r in *"is not a readable image"*"|"*"is not a readable image"*) exit 0 ;; esac
exit 1
