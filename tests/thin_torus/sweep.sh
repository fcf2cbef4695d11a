#!/bin/sh
# The sweep of spec/numerics.md 2.15 behind [LANG-TORUS-2]'s bound: the thin
# ring of outside.scene (tests/attack9, finding 3) at minor/major 2^-K, against
# the straight tube of cylinder.scene (its only difference the ring's
# curvature, which halves with each K: a break in that law is a wrong hit),
# inside.scene (every pixel Kd Ia = 0.08: against the same view at 2^-8), and
# each with and without --no-shortcuts (cmp).  Below 2^-16 the loader refuses
# the torus: measure those with a refray built before the rule (77aedc7).
#   sh tests/thin_torus/sweep.sh [REFRAY] [W H] [EYE]
# EYE: the eye in minor radii m, "1 + 3*m, m, m" as the scenes have it;
# the spec's other views are "1 + 20*m, 5*m, 3*m" and "1 + 100*m, 30*m, 20*m"
# (cylinder.scene's tube, 64 m each way, is made 512 m for the last).
set -u
refray=${1:-build/refray} w=${2:-16} h=${3:-12} eye=${4:-1 + 3*m, m, m}
dir=$(dirname "$0") tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
scene() { # NAME K: the scene at minor 2^-K
    sed -e "s/pow(2, -28)/pow(2, -$2)/" -e "s/width 16  height 12/width $w  height $h/" \
        -e "s/eye \[1 + 3\*m, m, m\]/eye [$eye]/" -e "s/64\*m/512*m/g" "$dir/$1.scene" >"$tmp/$1_$2.scene"
}
render() { # NAME K [OPTION]: its PFM
    scene "$1" "$2"
    "$refray" render "$tmp/$1_$2.scene" -q ${3:-} -o "$tmp/$1_$2${3:+_ns}.pfm" 2>/dev/null
}
stat() { "$refray" compare "$1" "$2" | sed -n 's/^max abs: *\([^ ]*\).*/\1/p;s/^differ: *\([0-9]*\).*/\1/p' | paste -sd' '; }
render inside 8
echo "K: outside - cylinder (max abs, pixels) | inside - 0.08 (max abs, pixels) | shortcuts (outside, inside)"
for k in 12 14 16 18 19 20 21 22 23 24 25 26 28; do
    if ! render outside $k; then echo "2^-$k: refused"; continue; fi
    render cylinder $k && render inside $k && render outside $k --no-shortcuts && render inside $k --no-shortcuts
    same() { cmp -s "$tmp/$1_$k.pfm" "$tmp/$1_${k}_ns.pfm" && echo same || echo DIFFER; }
    echo "2^-$k: $(stat "$tmp/outside_$k.pfm" "$tmp/cylinder_$k.pfm") | $(stat "$tmp/inside_$k.pfm" "$tmp/inside_8.pfm") | $(same outside), $(same inside)"
done
