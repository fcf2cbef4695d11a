#!/bin/sh
# crosscheck.sh - other renderers measured by refray's oracle through the
# conformance kit; the script behind `make crosscheck` (spec/crosscheck.md).
#
# Each renderer is one `refray conform` run over the kit with the command
# line and options that renderer needs (run_renderer below): its table is
# conform's --markdown, its JUnit XML and text table stay in $OUT.  Mitsuba
# 3 reads the kit's .json through tests/conform/mitsuba3.py; the scenes
# whose model it does not share exit 69, and their rows get the adapter's
# reason (its --dry-run says it without rendering).  A scene that is not
# analytic, tests/conform/axes.scene, checks Mitsuba's camera and image
# orientation against refray's own render.  After the tables come the
# kit's notes on what the POV-Ray export could not match, read from the
# header of each .pov file.
#
# Environment: REFRAY (the program), KIT (a kit made by `refray kit`), OUT
# (the work directory), UPDATE_SPEC=1 to write the result into
# spec/crosscheck.md between its crosscheck-table markers, ONLY="NAME ..."
# for some scenes only, MITSUBA_PYTHON (a Python with mitsuba and numpy:
# `make mitsuba-venv`).  POV-Ray is installed from Debian (`povray`) when
# it is missing.
set -u

REFRAY=${REFRAY:-build/refray}
KIT=${KIT:-build/kit}
OUT=${OUT:-build/crosscheck}
UPDATE_SPEC=${UPDATE_SPEC:-0}
ONLY=${ONLY:-}
MITSUBA_PYTHON=${MITSUBA_PYTHON:-build/mitsuba-venv/bin/python}
MITSUBA_NOT_EXPRESSIBLE=69
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
    [ "$stem" != mitsuba ] || mitsuba_reasons "$OUT/$stem.md"
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

# Puts the adapter's reason into the rows of the scenes it refused (exit 69)
# of the Markdown table $1, and adds a line that counts them.
mitsuba_reasons() {
    reasons=$OUT/mitsuba-reasons.tsv
    : >"$reasons"
    for json in "$KIT"/scenes/*/*.json; do
        why=$("$MITSUBA_PYTHON" "$ROOT/tests/conform/mitsuba3.py" --dry-run "$json" 2>&1 >/dev/null |
            sed -n 's/^mitsuba3.py: model not expressible: //p')
        [ -z "$why" ] || printf '%s\t%s\n' "$(basename "$json" .json)" "$why" >>"$reasons"
    done
    awk -F '\t' -v code="$MITSUBA_NOT_EXPRESSIBLE" '
        NR == FNR { why[$1] = $2; next }
        {
            at = index($0, "| the renderer exited with status " code " |")
            if (at > 0) {
                name = substr($0, 3, index(substr($0, 3), " ") - 1)
                $0 = substr($0, 1, at + 1) "not expressible: " why[name] " |"
                refused++
            }
            print
        }
        END { printf "\nNot expressible in Mitsuba 3 (the adapter exits %d with the reason): %d scenes.\n", code, refused }
    ' "$reasons" "$1" >"$1.tmp" && mv "$1.tmp" "$1"
}

# [XCHK-MITSUBA-AXES-1] tests/conform/axes.scene (asymmetric: perspective,
# two lights, every shape the adapter maps but the cylinder) by Mitsuba
# against refray's own render of it, into the Mitsuba section.
mitsuba_axes() {
    scene=tests/conform/axes.scene
    "$REFRAY" export -W "$scene" --to json -o "$OUT/axes.json" &&
        "$REFRAY" render -q "$scene" -o "$OUT/axes.pfm" &&
        "$MITSUBA_PYTHON" tests/conform/mitsuba3.py "$OUT/axes.json" "$OUT/axes.exr" ||
        die "the axes check could not run"
    "$REFRAY" compare "$OUT/axes.exr" "$OUT/axes.pfm" --downsample 2 --tolerance 1e-4 >"$OUT/axes.txt"
    [ $? -le 1 ] || die "the axes check's compare failed"
    {
        echo
        echo "The axes check ([XCHK-MITSUBA-AXES-1]): \`$scene\` rendered by refray (PFM) and by the adapter"
        echo "(its 2 x 2 samples as a 192 x 144 EXR), then"
        echo
        echo "    refray compare axes.exr axes.pfm --downsample 2 --tolerance 1e-4"
        echo
        grep -E '^(size|max abs|max rel|over):' "$OUT/axes.txt" | sed 's/^/    /'
    } >>"$sections"
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

case $MITSUBA_PYTHON in /*) mitsuba_abs=$MITSUBA_PYTHON ;; *) mitsuba_abs=$ROOT/$MITSUBA_PYTHON ;; esac
versions=$("$MITSUBA_PYTHON" -c 'import mitsuba, drjit, numpy; print(mitsuba.__version__, drjit.__version__, numpy.__version__)') ||
    die "no Mitsuba 3 at $MITSUBA_PYTHON (make mitsuba-venv)"
# shellcheck disable=SC2086 # three words
set -- $versions
run_renderer "Mitsuba $1 (scalar_rgb; drjit $2, numpy $3; 32-bit float EXR)" mitsuba \
    "refray conform --kit $KIT --format exr --downsample manifest --timeout 300 --cmd '$MITSUBA_PYTHON tests/conform/mitsuba3.py {json} {out}'" \
    --format exr --downsample manifest --timeout 300 \
    --cmd "'$mitsuba_abs' '$ROOT/tests/conform/mitsuba3.py' {json} {out}"
mitsuba_axes

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
    echo "0.6 s, Mitsuba's its import of about 0.4 s and one render per light); the verdict and its reason."
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
