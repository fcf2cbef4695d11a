#!/bin/sh
# path_hash.sh [SCENE...] - path_hash.c built against this tree and against
# the old main (OLDSRC, default /tmp/old-main: its src, build/gen and
# build/librefray-internal.a), run on the SCENEs (default: attack 22's
# hand scenes, make_scenes.sh); exit 1 when a ray-tree hash differs.  From
# the repository root after `make build/librefray-internal.a`.
set -u
OLDSRC=${OLDSRC:-/tmp/old-main}
D=$(mktemp -d)
cc -std=c99 -O2 -ffp-contract=off -Isrc -Ibuild/gen -o "$D/new" tests/attack22/path_hash.c build/librefray-internal.a -ljansson -lm 2>/dev/null &&
cc -std=c99 -O2 -ffp-contract=off -DPATH_HASH_OLD_CAMERA -I"$OLDSRC/src" -I"$OLDSRC/build/gen" -o "$D/old" tests/attack22/path_hash.c \
   "$OLDSRC/build/librefray-internal.a" -ljansson -lm 2>/dev/null || { echo "path_hash: build failed"; exit 2; }
if [ $# = 0 ]; then sh tests/attack22/make_scenes.sh "$D/s"; set -- "$D"/s/*.scene; fi
"$D/new" "$@" > "$D/new.txt"
"$D/old" "$@" > "$D/old.txt"
bad=0
diff "$D/old.txt" "$D/new.txt" || bad=1
echo "path_hash: $(grep -c . "$D/new.txt") hashes (shortcuts on and off), $([ $bad = 0 ] && echo same || echo DIFFER)"
rm -rf "$D"
exit $bad
