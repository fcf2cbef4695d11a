# Sourced by oblique.sh, turned.sh and stretched.sh: refray (the caller's $1),
# a temporary folder, mark (sweep_mark.sh), the lit setting over a shiny floor
# at y = -1.5 seen from EYE, one row of a sweep, and the turned shapes.  The
# light is at $light (set before sourcing; by default above the shape,
# [0.8, 6, 0.5]).
refray=${1:-build/refray}
light=${light:-[0.8, 6, 0.5]}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/../sweep_mark.sh"
head() { # EYE
    echo "image { width 32 height 24 max_depth 3 }"
    echo "camera { eye $1 look_at [0, 0, 0] fov 45 }"
    echo "ambient { color 0.2 }"
    echo "point_light { position $light power 40 falloff none }"
    echo "plane { point [0, -1.5, 0] normal [0, 1, 0] material { Kd 0.5 Ks 0.4 n 20 } }"
}
# row NAME EYE S...: prints "NAME EYE:" and, for each S, the pixels of the
# scene `squashed_of NAME S` writes over 1e-6 relative of `flat_of NAME`'s
# (refray compare --tolerance), starred where --no-shortcuts differs by a
# byte (mark).  The caller defines squashed_of and flat_of.
row() {
    name=$1 eye=$2
    shift 2
    { head "$eye"; flat_of "$name"; } >"$tmp/flat.scene"
    "$refray" render "$tmp/flat.scene" -q -o "$tmp/flat.pfm" || exit 1
    line="$name $eye:"
    for s in "$@"; do
        { head "$eye"; squashed_of "$name" "$s"; } >"$tmp/x.scene"
        "$refray" render "$tmp/x.scene" -q -o "$tmp/x.pfm" || exit 1
        "$refray" render "$tmp/x.scene" -q --no-shortcuts -o "$tmp/xn.pfm" || exit 1
        n=$("$refray" compare "$tmp/x.pfm" "$tmp/flat.pfm" --tolerance 1e-6 | sed -n 's/^over: *\([0-9]*\).*/\1/p')
        mark "${n:-0}" "$tmp/x.pfm" "$tmp/xn.pfm"
    done
    echo "$line"
}
turned() { # NAME: the turned shapes the sweeps share, up to their scale
    case $1 in
    sphere-z) echo 'sphere { center [0, 0, 0] radius 1 rotate [0, 0, 30]' ;;
    sphere-xz) echo 'sphere { center [0, 0, 0] radius 1 rotate [40, 0, 25]' ;;
    cone) echo 'cone { from [0, -1, 0] to [0, 1, 0] radii 1 0.5 rotate [0, 0, 30]' ;;
    torus) echo 'torus { center [0, 0, 0] axis [0, 1, 0] major 0.8 minor 0.4 rotate [20, 0, 30]' ;;
    esac
}
