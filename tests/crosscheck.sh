#!/bin/sh
# crosscheck.sh - POV-Ray checked by refray's oracle; the script behind
# `make crosscheck` (spec/crosscheck.md).
#
# For each analytic scene given: export it (`refray export --to pov`),
# render the SDL with POV-Ray 3.7 on one thread with linear output, compare
# the picture with the scene's exact image (`povcheck compare`: the exact
# image and its excluded pixels as `refray verify` builds them), and put
# POV-Ray's error and time next to refray's (`povcheck refray`: the
# verify_scene result that `refray verify --json` prints).
#
# The picture goes through a 16-bit PNG (+FN16, File_Gamma=1.0, with
# assumed_gamma 1.0 in the SDL: linear codes).  So that its step (1/65535
# of full scale) is small against the picture, the export scales every
# light, the ambient light and the background by the power of two that
# puts the exact image's peak in (0.4, 0.8] (`refray export --scale`: the
# image is linear in them, so this is exact), and povcheck divides it back.
# POV_FORMAT=exr uses +FE instead (this povray writes half floats: a
# relative step of 2^-11, coarser than the scaled PNG).
#
# Environment: REFRAY and POVCHECK (the two programs), OUT (the work
# directory; every file of the run stays there), UPDATE_SPEC=1 to write the
# table into spec/crosscheck.md between its crosscheck-table markers.
# POV-Ray is installed from Debian (`povray`) when it is missing.
set -u

REFRAY=${REFRAY:-build/refray}
POVCHECK=${POVCHECK:-build/povcheck}
OUT=${OUT:-build/crosscheck}
UPDATE_SPEC=${UPDATE_SPEC:-0}
POV_FORMAT=${POV_FORMAT:-png16}
SPEC=spec/crosscheck.md

die() {
    echo "crosscheck: $*" >&2
    exit 1
}

install_povray() {
    command -v povray >/dev/null 2>&1 && return 0
    echo "crosscheck: installing povray (Debian package)" >&2
    if [ "$(id -u)" = 0 ]; then SUDO=; else SUDO=sudo; fi
    $SUDO apt-get update -qq &&
        DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq povray >/dev/null ||
        die "cannot install povray"
}

# Seconds since the epoch with nanoseconds (GNU date).
now() {
    date +%s.%N
}

# a - b, printed with 3 decimals.
elapsed() {
    awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", a - b }'
}

# A number in 3 significant digits, for the table.
num() {
    awk -v x="$1" 'BEGIN { if (x == "") print "-"; else if (x == 0) print "0"; else printf "%.2e", x }'
}

# The power of two 2^-m that takes the peak $1 into (0.4, 0.8].
scale_for() {
    awk -v p="$1" 'BEGIN {
        if (!(p > 0)) { print 1; exit }
        m = 0
        while (p * 2 ^ -m > 0.8) m++
        while (p * 2 ^ -m <= 0.4) m--
        printf "%.17g\n", 2 ^ -m }'
}

# Seconds in 3 significant digits.
secs() {
    awk -v x="$1" 'BEGIN { if (x == "") print "-"; else printf "%.3g", x }'
}

# Renders $OUT/$1.pov (POV-Ray reads and writes only in its current
# directory and /tmp under Debian's povray.conf: run it inside $OUT).
# Sets pov_image, pov_wall, pov_trace and pov_ok.
render_pov() {
    name=$1
    args=$(sed -n 's,^// pov-args: ,,p' "$OUT/$name.pov")
    if [ "$POV_FORMAT" = exr ]; then
        pov_image=$name.pov.exr
        fmt="+FE"
    else
        pov_image=$name.pov.png
        fmt="+FN16 File_Gamma=1.0"
    fi
    t0=$(now)
    # shellcheck disable=SC2086 # args and fmt are lists of options
    (cd "$OUT" && povray "+I$name.pov" "+O$pov_image" $args $fmt -D -V +WT1 Output_Alpha=off \
        >"$name.pov.log" 2>&1)
    pov_ok=$?
    t1=$(now)
    pov_wall=$(elapsed "$t1" "$t0")
    pov_trace=$(sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' "$OUT/$name.pov.log" | head -n 1)
}

# Turns povcheck's "key=value ..." line into variables PREFIX_key.
read_values() {
    prefix=$1
    line=$2
    for kv in $line; do
        eval "${prefix}_${kv%%=*}=\${kv#*=}"
    done
}

# Exports, renders and measures one variant of a scene: $1 the scene, $2
# the label in the table, $3 the file stem, then the extra export options.
# Adds a row to $rows and the notes to $notes_md; uses ex_* and rf_*.
pov_row() {
    scene=$1
    label=$2
    stem=$3
    shift 3
    if ! "$REFRAY" export "$scene" --to pov --scale "$scale" "$@" -o "$OUT/$stem.pov" -W 2>"$OUT/$stem.notes"
    then
        reason=$(sed -n 's/^refray: error: //p' "$OUT/$stem.notes" | head -n 1)
        printf '| %s | %s | refused by the export | | | | | %s | %s | %s | %s %s | %s/%s |\n' "$label" \
            "$(num "$ex_peak")" "$(num "$rf_max_abs")" "$(num "$rf_rms")" "$(num "$rf_max_rel")" \
            "$(secs "$rf_seconds")" "${rf_verdict:-}" "$ex_excluded" "$ex_pixels" >>"$rows"
        printf '\n#### %s\n\nRefused by `refray export`: %s\n' "$label" "$reason" >>"$notes_md"
        return
    fi
    render_pov "$stem"
    k=$(sed -n 's,^// pov-downsample: ,,p' "$OUT/$stem.pov")
    pv_max_abs="" pv_rms="" pv_max_rel="" pv_max_rel_bright=""
    if [ "$pov_ok" = 0 ]; then
        pov=$("$POVCHECK" compare "$scene" "$OUT/$pov_image" "$k" "$scale" 2>"$OUT/$stem.compare.err") &&
            read_values pv "$pov"
    fi
    peak="$(num "$ex_peak")"
    [ "$pov_ok" = 0 ] || peak="$peak; POV-Ray failed ($OUT/$stem.pov.log)"
    printf '| %s | %s | %s | %s | %s | %s | %s (%s) | %s | %s | %s | %s %s | %s/%s |\n' \
        "$label" "$peak" "$(num "$pv_max_abs")" "$(num "$pv_rms")" "$(num "$pv_max_rel")" \
        "$(num "$pv_max_rel_bright")" "$pov_wall" "${pov_trace:--}" "$(num "$rf_max_abs")" \
        "$(num "$rf_rms")" "$(num "$rf_max_rel")" "$(secs "$rf_seconds")" "${rf_verdict:-}" \
        "$ex_excluded" "$ex_pixels" >>"$rows"
    printf '\n#### %s\n\n' "$label" >>"$notes_md"
    if grep -q '^refray: approximation: ' "$OUT/$stem.notes"; then
        sed -n 's/^refray: approximation: \(.*\)/- \1/p' "$OUT/$stem.notes" >>"$notes_md"
    else
        echo "- nothing: the export is exact for this scene" >>"$notes_md"
    fi
}

# One scene: its exact image and refray's check, then POV-Ray's rows: the
# default export, and for distributed lights also POV-Ray's own area_light.
check_scene() {
    scene=$1
    name=$(basename "$scene" .scene)
    exact=$("$POVCHECK" exact "$scene" 2>"$OUT/$name.exact.err") || {
        printf '| %s | no exact image | | | | | | | | | | |\n' "$name" >>"$rows"
        printf '\n#### %s\n\nNo exact image: %s\n' "$name" "$(head -n 1 "$OUT/$name.exact.err")" >>"$notes_md"
        return
    }
    read_values ex "$exact"
    scale=$(scale_for "$ex_peak")
    rf_max_abs="" rf_rms="" rf_max_rel="" rf_seconds="" rf_verdict=""
    ref=$("$POVCHECK" refray "$scene" 2>"$OUT/$name.refray.err") && read_values rf "$ref"
    pov_row "$scene" "$name" "$name"
    if grep -q '^distributed_light' "$scene"; then
        pov_row "$scene" "$name (area_light)" "$name.area" --area-lights
    fi
}

# Replaces the lines between the markers in $SPEC with $1 (atomically).
update_spec() {
    [ -f "$SPEC" ] || die "$SPEC is missing"
    grep -q '^<!-- crosscheck-table:begin -->$' "$SPEC" || die "$SPEC has no crosscheck-table markers"
    awk -v table="$1" '
        /^<!-- crosscheck-table:begin -->$/ { print; while ((getline line < table) > 0) print line; skip = 1; next }
        /^<!-- crosscheck-table:end -->$/ { skip = 0 }
        !skip { print }' "$SPEC" >"$SPEC.tmp" && mv "$SPEC.tmp" "$SPEC"
}

[ $# -gt 0 ] || die "no scenes given (scenes/analytic/*.scene)"
[ -x "$REFRAY" ] || die "no refray at $REFRAY"
[ -x "$POVCHECK" ] || die "no povcheck at $POVCHECK"
install_povray
mkdir -p "$OUT" || die "cannot create $OUT"
if [ "$POV_FORMAT" = exr ]; then
    povray --version 2>&1 | grep -q 'openexr' || die "this povray cannot write OpenEXR (+FE)"
fi
rows=$OUT/rows.md
notes_md=$OUT/notes.md
: >"$rows"
: >"$notes_md"
for scene in "$@"; do
    echo "crosscheck: $scene" >&2
    check_scene "$scene"
done

version=$(povray --version 2>&1 | sed -n 's/^POV-Ray \(3[^ ]*\).*/\1/p' | head -n 1)
table=$OUT/table.md
{
    echo "Made by \`make crosscheck\` on $(date -u +%Y-%m-%d) with POV-Ray ${version:-?} (one thread, +WT1)"
    echo "and refray $("$REFRAY" --version | sed 's/^refray //'), $(uname -m); $# scenes."
    echo
    echo "| scene | exact peak | POV max abs | POV RMS | POV max rel | POV max rel (>1% of peak) | POV s: wall (trace) | refray max abs | refray RMS | refray max rel | refray s, verdict | excluded px |"
    echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
    cat "$rows"
    echo
    echo "### What the export could not match, per scene"
    cat "$notes_md"
} >"$table"
cat "$table"
if [ "$UPDATE_SPEC" = 1 ]; then
    update_spec "$table"
    echo "crosscheck: table written into $SPEC" >&2
fi
