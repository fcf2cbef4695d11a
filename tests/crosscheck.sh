#!/bin/sh
# crosscheck.sh - other renderers measured by refray's oracle through the
# conformance kit; the script behind `make crosscheck` (spec/crosscheck.md).
#
# Each renderer is one `refray conform` run over the kit with the command
# line and options that renderer needs (run_renderer below): its table is
# conform's --markdown, its JUnit XML and text table stay in $OUT.  After
# the tables come the kit's notes on what the POV-Ray export could not
# match, read from the header of each .pov file.
#
# Environment: REFRAY (the program), KIT (a kit made by `refray kit`), OUT
# (the work directory), UPDATE_SPEC=1 to write the result into
# spec/crosscheck.md between its crosscheck-table markers, ONLY="NAME ..."
# for some scenes only.  POV-Ray is installed from Debian (`povray`) when
# it is missing.
set -u

REFRAY=${REFRAY:-build/refray}
KIT=${KIT:-build/kit}
OUT=${OUT:-build/crosscheck}
UPDATE_SPEC=${UPDATE_SPEC:-0}
ONLY=${ONLY:-}
SPEC=spec/crosscheck.md
ROOT=$(pwd)

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

# Runs conform for one renderer: $1 its heading, $2 the file stem, $3 the
# command as shown in the spec (paths relative to the repository), then
# conform's options.  Appends its section to $sections.
run_renderer() {
    heading=$1
    stem=$2
    shown=$3
    shift 3
    echo "crosscheck: $heading" >&2
    # shellcheck disable=SC2086 # ONLY is a list of names
    "$REFRAY" conform --kit "$KIT" --markdown "$OUT/$stem.md" --junit "$OUT/$stem.xml" \
        ${ONLY:+--only $ONLY} "$@" >"$OUT/$stem.txt" 2>"$OUT/$stem.err"
    status=$?
    # 0: every scene passed, 1: some failed; both are a measurement.
    [ "$status" -le 1 ] || die "conform for $heading stopped with exit $status: $(cat "$OUT/$stem.err")"
    {
        echo
        echo "### $heading"
        echo
        echo "    $shown"
        echo
        cat "$OUT/$stem.md"
        echo
        tail -n 1 "$OUT/$stem.txt" | sed 's/^/Summary: /'
    } >>"$sections"
}

# The approximations listed in the header of each of the kit's .pov files
# (`//   - ...` lines after `// approximations:`), per scene.
pov_notes() {
    for dir in "$KIT"/scenes/*/; do
        name=$(basename "$dir")
        if [ -n "$ONLY" ] && ! echo " $ONLY " | grep -q " $name "; then
            continue
        fi
        echo
        echo "#### $name"
        echo
        pov="$dir$name.pov"
        if [ ! -f "$pov" ]; then
            echo "- no .pov: the export refused the scene (the reason is in the table and in manifest.json)"
        elif grep -q '^//   - ' "$pov"; then
            sed -n '/^#version/q; s,^//   - \(.*\),- \1,p' "$pov"
        else
            echo "- nothing: the export is exact for this scene"
        fi
    done
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

[ -x "$REFRAY" ] || die "no refray at $REFRAY"
[ -f "$KIT/manifest.json" ] || die "no kit at $KIT (make kit)"
install_povray
mkdir -p "$OUT" || die "cannot create $OUT"
sections=$OUT/sections.md
: >"$sections"

pov_version=$(povray --version 2>&1 | sed -n 's/^POV-Ray \(3[^ ]*\).*/\1/p' | head -n 1)
run_renderer "POV-Ray ${pov_version:-3.7} (one thread, no anti-aliasing, 16-bit linear PNG)" povray \
    "refray conform --kit $KIT --format png --downsample manifest --scale manifest --timeout 120 --cmd 'sh tests/conform/povray.sh {pov} {out} {width} {height}'" \
    --format png --downsample manifest --scale manifest --timeout 120 \
    --cmd "sh '$ROOT/tests/conform/povray.sh' {pov} {out} {width} {height}"

# Mitsuba 3 (issue 10, 4b) goes here: one more run_renderer, with the
# adapter that reads the kit's .json, e.g.
#   run_renderer "Mitsuba 3 (scalar_rgb)" mitsuba "refray conform ... --cmd '...'" \
#       --format exr --cmd "'$ROOT/build/mitsuba-venv/bin/python' '$ROOT/tests/conform/mitsuba.py' {json} {out}"

case $REFRAY in /*) refray_abs=$REFRAY ;; *) refray_abs=$ROOT/$REFRAY ;; esac
run_renderer "refray $("$REFRAY" --version | sed 's/^refray //') itself, through the same runner" refray \
    "refray conform --kit $KIT --format pfm --cmd '$REFRAY render -q {scene} -o {out}'" \
    --format pfm --cmd "'$refray_abs' render -q {scene} -o {out}"

table=$OUT/table.md
{
    echo "Made by \`make crosscheck\` on $(date -u +%Y-%m-%d), $(uname -m), with the kit of \`make kit\`"
    echo "($(ls -d "$KIT"/scenes/*/ | wc -l | tr -d ' ') scenes).  Columns: the exact image's peak; max abs, RMS and max rel error"
    echo "over the compared pixels; pixels over the tolerance |out - exact| <= relative |exact| + absolute"
    echo "of the manifest; the renderer's wall time in seconds (POV-Ray's includes its start-up of about"
    echo "0.6 s); the verdict and its reason."
    cat "$sections"
    echo
    echo "### What the POV-Ray export could not match, per scene"
    pov_notes
} >"$table"
cat "$table"
if [ "$UPDATE_SPEC" = 1 ]; then
    update_spec "$table"
    echo "crosscheck: table written into $SPEC" >&2
fi
