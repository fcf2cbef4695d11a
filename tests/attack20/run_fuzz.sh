#!/bin/sh
# run_fuzz.sh [SCALE] - builds attack 20's fuzz programs against
# build/librefray-internal.a and runs each for SCALE (default 1) times its
# base count; exits 1 if any reports a difference.  From the repository
# root after `make build/refray`.
set -u
k=${1:-1}
T=$(mktemp -d)
bad=0
for p in pair_fuzz tri_fuzz nest_fuzz shear_fuzz; do
    cc -std=c99 -O2 -ffp-contract=off -Isrc -Ibuild/gen -o "$T/$p" "tests/attack20/$p.c" build/librefray-internal.a \
        -ljansson -lm 2>/dev/null || { echo "run_fuzz: $p does not build"; exit 2; }
done
TF_DIR="$T/t" "$T/pair_fuzz" $((1000000 * k)) || bad=1
TF_DIR="$T/t" "$T/tri_fuzz" $((1000 * k)) || bad=1
TF_DIR="$T/t" "$T/tri_fuzz" $((2000 * k)) 5 tangent || bad=1
NF_DIR="$T/n" "$T/nest_fuzz" $((1000 * k)) || bad=1
"$T/shear_fuzz" $((200000 * k)) || bad=1
rm -rf "$T"
exit $bad
