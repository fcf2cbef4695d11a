#!/bin/sh
# api_overflow.sh - attack 24, defect 1 through the public API: the counts
# rf_render_image reports after RF_ERR_DATA (camera, reflection,
# refraction rays, light samples, medium overflows) must be the base's
# (/tmp/base24, 91f0472) and the old library's: band_by_tiles counts the
# band's tiles and then the band again.  Builds tests/attack24/api_overflow.c
# against this tree's build/librefray-internal.a and BASELIB's.
# Exit 1 while they differ.  Run from the repository root after
# `make build/librefray-internal.a`.
BASELIB=${BASELIB:-/tmp/base24/build/librefray-internal.a}
T=$(mktemp -d)
cc -std=c99 -O2 -Iinclude -o $T/new tests/attack24/api_overflow.c build/librefray-internal.a -ljansson -lm 2>/dev/null || exit 2
cc -std=c99 -O2 -Iinclude -o $T/base tests/attack24/api_overflow.c "$BASELIB" -ljansson -lm 2>/dev/null || exit 2
bad=0
for args in "tests/attack24/overflow_right.scene 3" "tests/attack24/overflow_message.scene 30" \
            "tests/attack24/overflow_message.scene 0" "tests/attack24/overflow_right.scene 3 40 24 2" \
            "tests/attack24/overflow_right.scene 3 33 17 3"; do
    a=$($T/new $args) b=$($T/base $args)
    if [ "$a" != "$b" ]; then
        echo "$args"; echo "  new:  $a"; echo "  base: $b"; bad=1
    fi
done
rm -rf $T
exit $bad
