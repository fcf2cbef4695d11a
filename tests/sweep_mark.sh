# Sourced by the sweeps (tests/flat_cone, tests/frame_squash): mark N A B
# appends N (pixels off the reference) to $line, starred when the renders A
# and B (with and without the shortcuts) differ by a byte; either sets fail=1.
mark() {
    n=$1
    [ "$n" = 0 ] || fail=1
    cmp -s "$2" "$3" || { n="$n*"; fail=1; }
    line="$line $n"
}
