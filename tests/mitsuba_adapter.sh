#!/bin/sh
# The Mitsuba 3 adapter (tests/conform/mitsuba3.py) without Mitsuba: its
# --dry-run decides, for the export of every analytic scene, whether
# Mitsuba shares the scene's model, and prints the Mitsuba scenes it would
# render (spec/crosscheck.md, section 5).  Checked here:
#   1. the scenes it accepts are exactly EXPRESSIBLE below, and each other
#      one exits 69 with "model not expressible: " and the expected reason
#      [XCHK-MITSUBA-EXPRESS-1];
#   2. the numbers of some plans, worked out by hand from the .scene files
#      (camera frame, light intensities pi E, grid points, emission Kd Ia,
#      mirror reflectance Ks, depth);
#   3. usage (64), a missing file (66) and a JSON file that is not a scene (65).
# Run by `make test` in builds with JSON (the export needs it); the renders
# themselves need Mitsuba and run in `make crosscheck`.  Usage:
#   tests/mitsuba_adapter.sh REFRAY OUTDIR
set -eu

REFRAY=${1:-build/refray}
OUT=${2:-build/mitsuba-dry}
PYTHON=${PYTHON:-python3}
ADAPTER=tests/conform/mitsuba3.py
EXPRESSIBLE="ambient_only disk_light disk_occluded lambert_sphere parallel_mirrors_ambient
plane_point_inverse_square rect_light"

die() { echo "mitsuba_adapter.sh: $*" >&2; exit 1; }

command -v "$PYTHON" >/dev/null 2>&1 || die "no $PYTHON (Debian python3; make deps installs it with python3-jsonschema)"
rm -rf "$OUT"
mkdir -p "$OUT"

# The reason a refused scene must give (a fragment of it).
reason_for() {
    case $1 in
    lambert_cone_apex) echo "primitive 0: Mitsuba 3 has no cone shape" ;;
    lambert_cone | lambert_cylinder) echo "light 1: falloff linear" ;;
    lambert_torus*) echo "primitive 0: Mitsuba 3 has no torus shape" ;;
    sphere_shadow_two_lights) echo "light 1: falloff E/(d + d0)^2 with d0 > 0" ;;
    phong_sphere | phong_plane_perspective) echo "material 0: Phong highlight" ;;
    glass_slab_above | glass_slab_on_floor | snell_window) echo "material 0: transparency t" ;;
    stacked_sheets) echo "materials 1, 2, 3: transparency t" ;;
    transparent_shadow_depth2) echo "material 1: transparency t" ;;
    ball_lens) echo "lights 0, 1: falloff linear" ;;
    parallel_mirrors) echo "materials 0, 1: Phong highlight" ;;
    *) echo "light 0: falloff linear" ;;
    esac
}

# 1. The decision for every analytic scene.
accepted=0 refused=0
for scene in scenes/analytic/*.scene tests/conform/axes.scene; do
    name=$(basename "$scene" .scene)
    "$REFRAY" export -W "$scene" --to json -o "$OUT/$name.json" || die "export of $scene failed"
    status=0
    "$PYTHON" "$ADAPTER" --dry-run "$OUT/$name.json" >"$OUT/$name.plan" 2>"$OUT/$name.err" || status=$?
    if echo " $EXPRESSIBLE axes " | tr '\n' ' ' | grep -q " $name "; then
        [ "$status" = 0 ] || die "$name: expressible, but the adapter exited $status: $(cat "$OUT/$name.err")"
        accepted=$((accepted + 1))
    else
        [ "$status" = 69 ] || die "$name: not expressible, but the adapter exited $status"
        grep -q "^mitsuba3.py: model not expressible: .*$(reason_for "$name")" "$OUT/$name.err" ||
            die "$name: expected the reason '$(reason_for "$name")', got: $(cat "$OUT/$name.err")"
        refused=$((refused + 1))
    fi
done
[ "$accepted" = 8 ] || die "accepted $accepted scenes, expected 8"

# 2. Plans against numbers worked out from the scenes.
"$PYTHON" - "$OUT" <<'EOF' || die "a plan differs from the numbers worked out by hand"
import json, math, sys
out = sys.argv[1]

def plan(name):
    return json.load(open("%s/%s.plan" % (out, name)))['plan']

def near(a, b, what):
    a, b = (a, b) if isinstance(a, list) else ([a], [b])
    assert len(a) == len(b) and all(abs(x - y) <= 1e-12 * max(1.0, abs(y)) for x, y in zip(a, b)), (what, a, b)

def column(m, j):
    return [m[i][j] for i in range(3)]

# plane_point_inverse_square: orthographic from [0, 5, 0] down, up -z, width 6, 80 x 60, 2 x 2 samples;
# forward (0, -1, 0), right = forward x up = (1, 0, 0), up' = right x forward = (0, 0, -1).
p = plan('plane_point_inverse_square')
s = p['lit']['sensor']
assert s['type'] == 'orthographic' and s['film']['width'] == 160 and s['film']['height'] == 120, s
near(column(s['to_world'], 0), [-3, 0, 0], 'left * half width')
near(column(s['to_world'], 1), [0, 0, -3], 'up * half width')
near(column(s['to_world'], 2), [0, -1, 0], 'forward')
near(column(s['to_world'], 3), [0, 5, 0], 'eye')
assert p['lights'] == [{'type': 'point', 'position': [0.5, 1.5, 0.3],
                        'intensity': {'type': 'rgb', 'value': [4 * math.pi] * 3}}], p['lights']
assert p['lit']['integrator'] == {'type': 'direct', 'emitter_samples': 1, 'bsdf_samples': 0}
assert p['ambient']['integrator'] == {'type': 'path', 'max_depth': 1, 'rr_depth': 2}

# lambert_sphere: distant light along [1, -1, -2] of power [1, 0.9, 0.8]; Kd [0.8, 0.5, 0.3], Ia 0.1.
p = plan('lambert_sphere')
(light,) = p['lights']
near(light['direction'], [1 / math.sqrt(6), -1 / math.sqrt(6), -2 / math.sqrt(6)], 'direction')
near(light['irradiance']['value'], [math.pi, 0.9 * math.pi, 0.8 * math.pi], 'irradiance pi E')
near(p['ambient']['shape0_0']['emitter']['radiance']['value'], [0.08, 0.05, 0.03], 'Kd Ia')
near(p['ambient']['background']['radiance']['value'], [0.05, 0.05, 0.1], 'background')
assert p['lit']['shape0_0']['bsdf']['side']['reflectance']['value'] == [0.8, 0.5, 0.3]

# rect_light: corner [-1, 2, -0.75], edges [2, 0, 0] and [0, 0, 1.5], 256 samples: 16 x 16 cells.
p = plan('rect_light')
assert len(p['lights']) == 256
near(p['lights'][0]['position'], [-1 + 2 / 32, 2, -0.75 + 1.5 / 32], 'first cell centre')
near(p['lights'][255]['position'], [1 - 2 / 32, 2, 0.75 - 1.5 / 32], 'last cell centre')
near(p['lights'][0]['intensity']['value'], [12 * math.pi / 256] * 3, 'intensity pi E / N')

# disk_light: radius 1 at [0, 1.5, 0] facing down; the concentric map keeps every point inside,
# and the grid's centre cells straddle the centre symmetrically.
p = plan('disk_light')
assert len(p['lights']) == 256 and p['lit']['sensor']['fov'] == 70 and p['lit']['sensor']['fov_axis'] == 'x'
for light in p['lights']:
    x, y, z = light['position']
    assert abs(y - 1.5) < 1e-15 and x * x + z * z < 1, light
near(sum(l['position'][0] for l in p['lights']), 0, 'grid centred in x')

# parallel_mirrors_ambient: no lights, depth 7; floor Kd 0.1 Ks 0.8, ceiling Kd [0.3, 0.2, 0.1]
# Ks [0.5, 0.6, 0.9]; Ia [0.5, 0.45, 0.4].
p = plan('parallel_mirrors_ambient')
assert p['lights'] == [] and p['ambient']['integrator']['max_depth'] == 7
floor, ceiling = p['ambient']['shape0_0'], p['ambient']['shape1_0']
near(floor['bsdf']['side']['specular_reflectance']['value'], [0.8] * 3, 'floor Ks')
near(ceiling['bsdf']['side']['specular_reflectance']['value'], [0.5, 0.6, 0.9], 'ceiling Ks')
near(floor['emitter']['radiance']['value'], [0.05, 0.045, 0.04], 'floor Kd Ia')
near(ceiling['emitter']['radiance']['value'], [0.15, 0.09, 0.04], 'ceiling Kd Ia')
near(column(ceiling['to_world'], 2), [0, -1, 0], 'the ceiling faces the eye')
EOF

# 3. Usage and bad input.
expect_status() {
    want=$1
    shift
    status=0
    "$PYTHON" "$ADAPTER" "$@" >/dev/null 2>&1 || status=$?
    [ "$status" = "$want" ] || die "mitsuba3.py $*: exit $status, expected $want"
}
expect_status 64
expect_status 64 --dry-run
expect_status 66 --dry-run "$OUT/no-such-scene.json"
echo '{"format": {"name": "something-else"}}' >"$OUT/other.json"
expect_status 65 --dry-run "$OUT/other.json"
echo "mitsuba_adapter.sh: $accepted scenes expressible in Mitsuba 3, $refused refused with their reasons; plans and exit codes as expected"
