#!/bin/sh
# tests/bench/arena_min.sh - `make arena-min`: the smallest fixed arena in
# which tests/embed/render_string renders SCENE (spec/embedding.md), by
# bisection over the arena's size.  Each probe renders one row (what a
# render allocates does not depend on how many rows it renders); the size
# found is then confirmed by a whole render, and one byte less must fail.
#
# usage: arena_min.sh RENDER_STRING SCENE
set -eu
prog=$1 scene=$2
fits() { "$prog" "$1" "$scene" ${2:-1} >/dev/null 2>&1; }
lo=0 hi=1024
while ! fits $hi; do lo=$hi hi=$((hi * 2)); done
while [ $((hi - lo)) -gt 1 ]; do
    mid=$(((lo + hi) / 2))
    if fits $mid; then hi=$mid; else lo=$mid; fi
done
fits $hi 0 || { echo "arena-min: $hi bytes render one row of $scene but not all of it" >&2; exit 1; }
! fits $((hi - 1)) 0 || { echo "arena-min: $((hi - 1)) bytes suffice too" >&2; exit 1; }
echo "arena-min: $scene renders in an arena of $hi bytes, not in $((hi - 1))"
