#!/bin/sh
# gap2.sh SCENE: renders SCENE (first line `let g = 0`) at g = 0, 1e-9, 2e-9
# and with --no-shortcuts; prints max abs touch-gap, gap-gap2 (the smoothness
# bound: touching must lie within 2|v(2g)-v(g)| + 1e-12 of v(g), spec 2.8a) and
# whether --no-shortcuts is byte-identical.
B=${B:-build/refray}
S=$1; shift
T=$(dirname "$S")/.gap2.$$
sed "1s/^let g = 0\$/let g = 1e-9/" "$S" > $T.g1.scene
sed "1s/^let g = 0\$/let g = 2e-9/" "$S" > $T.g2.scene
nice $B render "$S" -q -o $T.t.pfm "$@" || echo "render exit $?"
nice $B render $T.g1.scene -q -o $T.g1.pfm "$@" || echo "render g1 exit $?"
nice $B render $T.g2.scene -q -o $T.g2.pfm "$@" || echo "render g2 exit $?"
nice $B render "$S" --no-shortcuts -q -o $T.n.pfm "$@" || echo "render ns exit $?"
a=$($B compare $T.t.pfm $T.g1.pfm | grep -i "max abs" | head -1)
b=$($B compare $T.g1.pfm $T.g2.pfm | grep -i "max abs" | head -1)
echo "$(basename $S): touch vs 1e-9: $a | 1e-9 vs 2e-9: $b"
cmp -s $T.t.pfm $T.n.pfm && echo "  shortcuts: identical" || echo "  shortcuts: DIFFER"
rm -f $T.*
