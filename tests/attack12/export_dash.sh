#!/bin/sh
# export_dash.sh - `refray export S --to json -o -` (and --to pov) writes a
# file named "-" in the current directory and nothing to standard output,
# exit 0; with --mesh-files m the mesh goes to m/-.mesh0.obj.  `render`
# takes '-' as standard output (with --format), `oracle` and `merge`
# refuse it (64, spec/scaling.md); `export --help` says "-o OUT ...
# (default: stdout)", so `refray export s.scene --to json -o - | jq .`
# reads nothing and leaves a stray file.
# Run from the repository root after nice make -j2 build/refray:
#   sh tests/attack12/export_dash.sh   # exit 1 when stdout is empty and '-' was written
set -u
B=$(pwd)/${B:-build/refray}
S=$(pwd)/tests/attack12/json_ellipsoid.scene
P=$(pwd)/tests/attack12/pov_shapes.scene
D=$(mktemp -d)
cd "$D" || exit 2
"$B" export "$S" --to json -o - > out.txt
rc=$?
bytes=$(wc -c < out.txt)
made=$([ -f ./- ] && wc -c < ./- || echo none)
rm -f ./-; "$B" export "$P" --to pov -o - > outp.txt; pmade=$([ -f ./- ] && wc -c < ./- || echo none)
pbytes=$(wc -c < outp.txt)
cd / && rm -rf "$D"
echo "export --to json -o -: exit $rc, $bytes bytes on stdout, file '-': $made bytes; --to pov: $pbytes bytes on stdout, file '-': $pmade bytes"
[ "$bytes" -gt 0 ] && [ "$made" = none ]
