#!/bin/sh
# The JSON Schema of the scene format (spec/scene.schema.json) against
# refray's exports [JSON-SCHEMA-1], with a validator refray did not write:
# the `jsonschema` command of Debian's python3-jsonschema.
#   1. the export of every scene under scenes/ (and one with --mesh-files)
#      is valid;
#   2. each of a set of broken exports is rejected, so this test can fail.
# Run by `make test` in builds with JSON; usage:
#   tests/json_schema.sh REFRAY OUTDIR
set -eu

REFRAY=${1:-build/refray}
OUT=${2:-build/json-schema}
SCHEMA=spec/scene.schema.json
JSONSCHEMA=${JSONSCHEMA:-/usr/bin/jsonschema}

die() { echo "json_schema.sh: $*" >&2; exit 1; }

[ -x "$JSONSCHEMA" ] || die "no $JSONSCHEMA (Debian python3-jsonschema; make deps installs it)"
rm -rf "$OUT"
mkdir -p "$OUT/good" "$OUT/broken"

# 1. Every scene, exported, in one run of the validator.
count=0
set --
for scene in scenes/*.scene scenes/*/*.scene; do
    name=$(echo "$scene" | sed 's|^scenes/||; s|\.scene$||; s|/|-|g')
    "$REFRAY" export -W "$scene" --to json -o "$OUT/good/$name.json" || die "export of $scene failed"
    set -- "$@" -i "$OUT/good/$name.json"
    count=$((count + 1))
done
"$REFRAY" export -W scenes/mesh.scene --to json -o "$OUT/good/mesh-files.json" --mesh-files meshes ||
    die "export of scenes/mesh.scene with --mesh-files failed"
set -- "$@" -i "$OUT/good/mesh-files.json"
# Meshes outside scenes/: PLY (ASCII and both binary orders, inline and as
# mesh files) and the closed glass prism.
"$REFRAY" export -W tests/ply/encodings.scene --to json -o "$OUT/good/ply.json" || die "export of the PLY scene failed"
"$REFRAY" export -W tests/ply/encodings.scene --to json -o "$OUT/good/ply-files.json" --mesh-files meshes ||
    die "export of the PLY scene with --mesh-files failed"
"$REFRAY" export -W tests/obj/prism_head_on.scene --to json -o "$OUT/good/prism.json" ||
    die "export of tests/obj/prism_head_on.scene failed"
set -- "$@" -i "$OUT/good/ply.json" -i "$OUT/good/ply-files.json" -i "$OUT/good/prism.json"
[ "$count" -ge 70 ] || die "only $count scenes under scenes/"
"$JSONSCHEMA" "$@" "$SCHEMA" || die "an export does not follow $SCHEMA"

# 2. Broken exports: each edit (a sed script on one export) must change the
# file and make the validator say no.
break_one() {
    from=$1 edit=$2 what=$3
    to="$OUT/broken/$(echo "$what" | tr ' ' '-').json"
    sed "$edit" "$OUT/good/$from.json" > "$to"
    cmp -s "$OUT/good/$from.json" "$to" && die "the edit for '$what' changed nothing"
    if "$JSONSCHEMA" -i "$to" "$SCHEMA" >/dev/null 2>&1; then
        die "$SCHEMA accepts an export with $what ($to)"
    fi
    broken=$((broken + 1))
}
broken=0
break_one stress-scale_1 '0,/"radius": 1.0/s//"radius": -1.0/' "a negative radius"
break_one stress-scale_1 '0,/"Kd": \[0.69999999999999996/s//"Kd": [1.5/' "Kd above 1"
break_one stress-scale_1 '0,/"kind": "sphere"/s//"kind": "sphre"/' "an unknown kind"
break_one stress-scale_1 '/^  "source"/a\
  "extra": 1,' "an unknown member"
break_one stress-scale_1 '/^  "ambient"/d' "no ambient"
break_one stress-scale_1 's/"version": 1/"version": 2/' "format version 2"
break_one stress-scale_1 '0,/"width": 16/s//"width": 16.5/' "a fractional width"
break_one stress-scale_1 '0,/\[0.0, 0.0, 0.0, 1.0\]/s//[0.0, 0.0, 1.0, 1.0]/' "a matrix whose last row is not 0 0 0 1"
break_one stress-scale_1 '0,/"t": 0.0,/s//"t": 1.5,/' "transparency above 1"
break_one analytic-disk_light 's/"falloff": "inverse_square"/"falloff": "square"/' "an unknown falloff"
break_one analytic-disk_light 's/"gamma": "0x/"gamma": "/' "a constant not in hex"
break_one analytic-disk_light '/"frame": {/d' "a disk light without its frame"
break_one mesh '0,/"triangles": \[/s//"triangles": [[0, 1],/' "a triangle of two corners"
break_one analytic-lambert_cone 's/"radii": \[1.0, /"radii": [/' "a cone with one radius"
break_one analytic-lambert_cone 's/"open": false/"open": 0/' "open as a number"
break_one analytic-lambert_torus 's/"minor": 0.34999999999999998/"minor": -0.35/' "a negative minor radius"
break_one mesh-files 's/"file": "[^"]*"/"file": ""/' "an empty mesh file name"
echo "json_schema.sh: $count exported scenes (and 1 with mesh files, 3 of PLY and glass meshes) follow $SCHEMA; $broken broken exports are rejected"
