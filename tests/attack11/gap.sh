#!/bin/sh
# gap.sh SCENE [GAP] [extra render args]: renders SCENE as written (its
# first line `let g = 0`: touching) and with g = GAP (default 1e-9), and
# with --no-shortcuts; prints the compare lines and whether the shortcut
# render is byte-identical.
B=${B:-build/refray}
S=$1; G=${2:-1e-9}; shift; shift 2>/dev/null
T=${TMPDIR:-/tmp}/gap.$$
sed "1s/^let g = 0\$/let g = $G/" "$S" > $T.gap.scene
$B render "$S" -q -o $T.t.pfm "$@" || echo "render exit $?"
$B render $T.gap.scene -q -o $T.g.pfm "$@" || echo "render gap exit $?"
$B render "$S" --no-shortcuts -q -o $T.n.pfm "$@" || echo "render ns exit $?"
echo "touch vs gap $G:"; $B compare $T.t.pfm $T.g.pfm | grep -v "^A:\|^B:\|^size:"
cmp -s $T.t.pfm $T.n.pfm && echo "shortcuts: identical" || { echo "shortcuts: DIFFER"; $B compare $T.t.pfm $T.n.pfm | grep -i "differ\|max"; }
rm -f $T.*
