#!/bin/sh
# arena_disk.sh [SCENE...] - figures, not a reproducer: the smallest fixed
# arena tests/embed/render_string renders each SCENE in ([EMBED-API-6],
# tests/bench/arena_min.sh), with the old main's library (OLDLIB, default
# /tmp/old-main/build/librefray-internal.a), this round's base's (BASELIB,
# optional) and build/librefray-internal.a; and the new library's exit
# status in the old library's smallest arena (3: RF_ERR_NO_MEMORY).
# Default scenes: scenes/analytic/disk_light.scene (a disk light of 256
# samples: [SHADE-SHORTCUT-DARK-2]'s cell centres take 16 bytes a sample)
# and scenes/demo.scene (the figure spec/embedding.md quotes).  From the
# repository root after `make build/librefray-internal.a`.
set -u
OLDLIB=${OLDLIB:-/tmp/old-main/build/librefray-internal.a}
BASELIB=${BASELIB:-}
[ $# -gt 0 ] || set -- scenes/analytic/disk_light.scene scenes/demo.scene
D=$(mktemp -d)
build() { cc -std=c99 -O2 -Iinclude -o "$D/$1" tests/embed/render_string.c "$2" -ljansson -lm 2>/dev/null || { echo "arena_disk: build of $1 failed"; exit 2; }; }
least() { sh tests/bench/arena_min.sh "$D/$1" "$2" | sed -n 's/.* arena of \([0-9]*\) bytes.*/\1/p'; }
build old "$OLDLIB"
build new build/librefray-internal.a
[ -n "$BASELIB" ] && build base "$BASELIB"
for S in "$@"; do
    old=$(least old "$S") new=$(least new "$S") base=-
    [ -n "$BASELIB" ] && base=$(least base "$S")
    "$D/new" "$old" "$S" >/dev/null 2>&1; e=$?
    echo "arena_disk: $S: smallest arena old $old, base $base, new $new bytes; new in $old bytes: exit $e"
done
rm -rf "$D"
