#!/bin/sh
# campaign.sh GEN FIRST LAST [OPTION...] - tests/attack19/campaign.sh for
# this folder's generators (gen8), with their mesh files copied next to
# the scenes.  Run from the repository root after `make build/refray`.
set -u
D=${OUT:-$(mktemp -d)}
mkdir -p "$D"
cp tests/attack20/*.obj scenes/stress/geosphere.obj "$D/"
gen=$1
shift
if [ ! -f "tests/attack19/$gen.awk" ]; then
    # campaign.sh reads tests/attack19/GEN.awk: this folder's, by a link in a copy of it
    T=$(mktemp -d)
    mkdir -p "$T/tests/attack19" "$T/tests/attack18"
    cp tests/attack18/common.awk "$T/tests/attack18/"
    cp tests/attack19/common19.awk "tests/attack20/$gen.awk" "$T/tests/attack19/"
    mkdir -p "$T/scenes/stress" && cp scenes/stress/glass_cube.obj "$T/scenes/stress/"
    R=$(pwd)
    cd "$T" && OUT="$D" B="${B:-$R/build/refray}" sh "$R/tests/attack19/campaign.sh" "$gen" "$@"
    rc=$?
    rm -rf "$T"
    exit $rc
fi
OUT="$D" sh tests/attack19/campaign.sh "$gen" "$@"
