# gen4.awk - a random scene for [SHADE-SHORTCUT-BUNDLE-1]'s box parts
# (attack 19): rectangle and disk lights near, inside and touching boxes,
# boxes grazing the light, turned and scaled boxes (kept frames), huge and
# tiny boxes, far lights, transparent boxes, leaves full of boxes.
# awk -v seed=N -f ../attack18/common.awk -f common19.awk -f gen4.awk
function bm() { return mixed_material(0.25, "0 0.3", "0.5 1 0.9", "1 1.5", "0.8 0.5 0", "0 0.2", "20 1 1e4") }
BEGIN {
    srand(seed)
    S = pick("1 1 1 1 1e-3 1e3 1e6 1e-6")
    printf "image { width %d height %d max_depth %d background [0.3, 0.5, 0.8] }\n", pick("16 17 12"), pick("12 13 9"), pick("1 2 3 4")
    ex = r(-3, 3) * S; ey = r(0.5, 4) * S; ez = r(3, 7) * S
    if (rand() < 0.2) printf "camera { orthographic eye %s look_at %s up [0, 1, 0] width %g }\n", v(ex, ey, ez), v(0, 0.5 * S, 0), 5 * S
    else printf "camera { perspective eye %s look_at %s up [0, 1, 0] fov %s }\n", v(ex, ey, ez), v(0, 0.5 * S, 0), pick("40 60 90")
    print "ambient { color 0.05 }"
    nl = ri(1, 3)
    for (i = 0; i < nl; i++) {
        L = pick("1 1 1 1e6 1e-3 0.5")
        px = pick("0 0.5 1 -1 0.25") * S; py = pick("0.5 1 2 3 0 0.75") * S * (L == 1e6 ? L : 1); pz = pick("0 0.5 -0.5 0.25") * S
        eu = pick("1 0.5 1e-6 2") * S * L
        if (rand() < 0.5) printf "distributed_light { rectangle %s %s %s power %g samples %s }\n", v(px, py, pz), pick("[" eu ",0,0] [0," eu ",0] [" eu "," eu ",0]"), v(0, 0, pick("1 0.5 1e-6") * S * L), 10 * S * S * L * L, pick("1 4 9 16 17")
        else printf "distributed_light { disk %s %s %g power %g samples %s }\n", v(px, py, pz), pick("[0,-1,0] [0,1,0] [1,0,0] [1,-1,0.3] [0,0,1]"), eu, 10 * S * S * L * L, pick("1 4 9 16 17")
    }
    if (rand() < 0.5) printf "point_light { position %s power %g }\n", v(r(-3, 3) * S, 4 * S, r(-3, 3) * S), 10 * S * S
    if (rand() < 0.6) printf "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0.8 } }\n"
    n = ri(1, 40)
    for (i = 0; i < n; i++) {
        k = pick("box box box fbox huge tiny around touch row sph")
        x = ri(-4, 4) * 0.25; y = ri(0, 8) * 0.25; z = ri(-4, 4) * 0.25
        w = pick("0.25 0.5 1 0.125")
        if (k == "box") printf "box { from %s to %s %s }\n", v(x * S, y * S, z * S), v((x + w) * S, (y + w) * S, (z + w) * S), bm()
        else if (k == "fbox") printf "box { from %s to %s %s %s translate %s }\n", v(-w / 2, -w / 2, -w / 2), v(w / 2, w / 2, w / 2), bm(), frame(0), v(x * S, y * S, z * S)
        else if (k == "huge") printf "box { from %s to %s %s }\n", v(-1e6 * S, y * S - pick("1 1e6 0.25") * S, -1e6 * S), v(1e6 * S, y * S, 1e6 * S), bm()
        else if (k == "tiny") printf "box { from %s to %s %s }\n", v(x * S, y * S, z * S), v(x * S + 1e-9 * S, y * S + 1e-9 * S, z * S + 1e-9 * S), bm()
        else if (k == "around") printf "box { from %s to %s %s }\n", v(-2 * S, -0.5 * S, -2 * S), v(2 * S, pick("3 1 0.75 4") * S, 2 * S), bm()
        else if (k == "touch") printf "box { from %s to %s %s }\n", v(x * S, y * S, z * S), v((x + w) * S, pick("0.5 1 2 3 0.75") * S, (z + w) * S), bm()
        else if (k == "row") { m = ri(2, 20); for (a = 0; a < m; a++) printf "box { from %s to %s %s }\n", v((x + 0.1 * a) * S, y * S, z * S), v((x + 0.1 * a + 0.05) * S, (y + 0.3) * S, (z + 0.2) * S), bm() }
        else if (k == "sph") printf "sphere { center %s radius %g %s }\n", v(x * S, y * S, z * S), 0.2 * S, bm()
    }
}
