# gen.awk - a random glass-heavy scene for the shortcut on/off comparison
# (attack 18): touching and coincident transparent parts, frames, far
# translations, many samples.  awk -v seed=N -f common.awk -f gen.awk
function mat() { return material(0.8, "1 1.5 1.33 2.4 1.0001", 0.8, 0.5) }
function frame(   s) {
    s = ""
    if (rand() < 0.3) s = s " scale " (rand() < 0.5 ? pick("2 0.5 1e-3 1e3 1e-6 3") : v(r(0.2, 3), r(0.2, 3), r(0.2, 3)))
    if (rand() < 0.3) s = s " rotate " v(pick("0 90 45 30 180"), pick("0 90 45 17"), pick("0 90 60"))
    if (rand() < 0.3) s = s " translate " v(pick("0 1 0.5"), pick("0 1 -1"), pick("0 0.25 2"))
    return s
}
BEGIN {
    srand(seed)
    T = pick("0 0 0 1e3 1e6 1e9 1e12 1e-6")
    S = pick("1 1 1 1e-6 1e-3 1e3 1e6")
    printf "image { width 24 height 18 max_depth %d background [0.3, 0.5, 0.8] }\n", pick("2 3 5 8 12")
    ex = r(-4, 4) * S; ey = r(0.2, 5) * S; ez = r(3, 7) * S
    if (rand() < 0.3) printf "camera { orthographic eye %s look_at %s up [0, 1, 0] width %g }\n", v(ex + T, ey, ez), v(T, 0, 0), 5 * S
    else printf "camera { perspective eye %s look_at %s up [0, 1, 0] fov %d }\n", v(ex + T, ey, ez), v(T, 0, 0), ri(20, 80)
    print "ambient { color 0.1 }"
    printf "point_light { position %s power %g }\n", v(r(-3, 3) * S + T, 4 * S, r(-3, 3) * S), 20 * S * S
    if (rand() < 0.5) printf "distributed_light { rectangle %s %s %s power %g samples %d }\n", v(-1 * S + T, 3 * S, -1 * S), v(2 * S, 0, 0), v(0, 0, 2 * S), 10 * S * S, pick("63 64 65 70 1 2 127 128 129")
    if (rand() < 0.5) printf "plane { point %s normal [0, 1, 0] %s }\n", v(T, pick("0 -1 -0.5") * S, 0), mat()
    n = ri(2, 80)
    for (i = 0; i < n; i++) {
        k = pick("tsph tsph tbox tbox nest plane sheet disk tri cyl grid grid touchbox")
        x = ri(-3, 3) * 0.5; y = ri(0, 2) * 0.5; z = ri(-3, 3) * 0.5
        if (k == "tsph") { rad = pick("0.5 0.25 1 0.5"); printf "sphere { center %s radius %.17g %s %s }\n", v(x * S + T, (y + rad) * S, z * S), rad * S, mat(), (S == 1 && T == 0 ? frame() : "") }
        else if (k == "tbox") printf "box { from %s to %s %s %s }\n", v(x * S + T, y * S, z * S), v((x + 0.5) * S + T, (y + 0.5) * S, (z + 0.5) * S), mat(), (S == 1 && T == 0 ? frame() : "")
        else if (k == "nest") { printf "sphere { center %s radius %.17g %s }\n", v(x * S + T, y * S, z * S), 0.5 * S, mat(); printf "sphere { center %s radius %.17g %s }\n", v(x * S + T, y * S, z * S), pick("0.25 0.5 0.4999999") * S, mat() }
        else if (k == "plane") printf "plane { point %s normal %s %s }\n", v(x * S + T, y * S, z * S), pick("[1,0,0] [0,1,0] [0,0,1] [1,1,0] [0,1,1]"), mat()
        else if (k == "sheet") printf "triangle { vertices %s %s %s %s }\n", v(x * S + T, y * S, z * S), v((x + 0.5) * S + T, y * S, z * S), v(x * S + T, y * S, (z + 0.5) * S), mat()
        else if (k == "disk") printf "disk { center %s normal %s radius %.17g %s }\n", v(x * S + T, y * S, z * S), pick("[1,0,0] [0,1,0] [0,0,1] [1,1,0]"), pick("0.5 1e6 0.25") * S, mat()
        else if (k == "tri") { L = pick("1 1e8 1e4"); printf "triangle { vertices %s %s %s %s }\n", v(T - L * S, y * S, -L * S), v(T + L * S, y * S, -L * S), v(T, y * S, L * S), mat() }
        else if (k == "cyl") printf "cylinder { from %s to %s radius %.17g %s }\n", v(x * S + T, y * S, z * S), v(x * S + T, (y + 1) * S, z * S), 0.25 * S, mat()
        else if (k == "grid") { m = ri(2, 4); rad = 0.25; for (a = 0; a < m; a++) for (b = 0; b < m; b++) printf "sphere { center %s radius %.17g %s }\n", v((x + 2 * rad * a) * S + T, (y + rad) * S, (z + 2 * rad * b) * S), rad * S, mat() }
        else if (k == "touchbox") { m = ri(2, 10); for (a = 0; a < m; a++) printf "box { from %s to %s %s }\n", v((x + 0.25 * a) * S + T, y * S, z * S), v((x + 0.25 * (a + 1)) * S + T, (y + 0.5) * S, (z + 0.5) * S), mat() }
    }
}
