#!/bin/sh
# povray.sh POV OUT WIDTH HEIGHT - a kit's .pov rendered by POV-Ray 3.7 for
# `refray conform` (spec/crosscheck.md, spec/conformance.md):
#
#   refray conform --kit build/kit --format png --downsample manifest \
#       --scale manifest --cmd 'sh tests/conform/povray.sh {pov} {out} {width} {height}'
#
# One thread, no anti-aliasing, linear 16-bit PNG (the SDL says
# assumed_gamma 1.0).  The kit's SDL has its lights scaled by the scene's
# png16_scale (--scale manifest divides it back) and WIDTH x HEIGHT is k
# times the scene's size for a k x k pixel grid (--downsample manifest
# averages the blocks).  Debian's povray.conf lets POV-Ray read and write
# only the current directory, /tmp and $HOME, so the SDL is copied into the
# working directory conform runs this in.
set -eu
[ $# -eq 4 ] || { echo "usage: povray.sh POV OUT WIDTH HEIGHT" >&2; exit 64; }
cp "$1" scene.pov
povray +Iscene.pov +Oimage.png +W"$3" +H"$4" -A -D -V +WT1 +FN16 File_Gamma=1.0 Output_Alpha=off
mv image.png "$2"
