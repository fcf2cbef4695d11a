#!/bin/sh
# polyfuzz.sh [SEED COUNT [EXTRA]] - builds polyfuzz.c and runs it (defaults:
# seed 3, 100 polygons, repeated corners only).  Exit 1 when a polygon's
# picture has a pixel the point-in-polygon test of its centre disagrees with.
set -u
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
cc -std=c99 -O1 tests/attack14/polyfuzz.c -lm -o "$D/polyfuzz" || exit 2
"$D/polyfuzz" "$PWD/${REFRAY:-build/refray}" "$D" "${1:-3}" "${2:-100}" "${3:-1}"
