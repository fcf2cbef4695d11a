# gen3.awk - a random scene for [SHADE-SHORTCUT-TIR-1] and the nearest
# walk's deferred plane (attack 19): dense glass (total reflection) with
# Ks 0 or > 0, nested solids and air bubbles, touching and coincident
# faces, glass meshes and framed glass, planes on faces and through
# solids, small depths, point and distant lights only (or, rarely, a
# distributed one), odd cameras.  awk -v seed=N -f ../attack18/common.awk -f common19.awk -f gen3.awk
function gm() {
    if (rand() < 0.15) return "material { Kd 0.5 Ks 0.3 n 20 }"
    return glassy(pick("0 0 0.1 0.3"), pick("0 0.05 0.3 1 0.5"), pick("1 20 300 1e-3 1e5 0.5"), pick("1 1 0.9 0.5 0.999"),
                  pick("1.5 2.4 1.33 1 0.7 3 1.0001"))
}
BEGIN {
    srand(seed)
    S = pick("1 1 1 1 1e-3 1e3 1e6")
    image(pick("16 17 9 20"), pick("12 13 7 15"), pick("1 2 3 3 4 5 8"))
    ex = r(-3, 3) * S; ey = r(-1, 4) * S; ez = r(2, 6) * S * pick("1 1 -1")
    c = rand()
    if (c < 0.25) printf "camera { orthographic eye %s look_at %s up [0, 1, 0] width %g }\n", v(ex, ey, ez), v(0, 0.5 * S, 0), pick("4 0.5 1e-6 40") * S
    else if (c < 0.35) printf "camera { perspective eye %s look_at %s up [0, 1, 0] fov %s }\n", v(0.1 * S, 0.4 * S, 0.05 * S), v(ex, ey, ez), pick("90 170 120")
    else printf "camera { perspective eye %s look_at %s up [0, 1, 0] fov %s }\n", v(ex, ey, ez), v(0, 0.5 * S, 0), pick("30 45 60 179.9 0.5 1e-6 170")
    if (rand() < 0.7) print "ambient { color 0.1 }"
    printf "point_light { position %s power %g }\n", v(r(-3, 3) * S, 4 * S, r(-3, 3) * S), 20 * S * S
    if (rand() < 0.4) printf "distant_light { direction %s power 0.5 }\n", v(r(-1, 1), -1, r(-1, 1))
    if (rand() < 0.3) printf "point_light { position %s power %g }\n", v(0.1 * S, 0.3 * S, 0.2 * S), 5 * S * S
    if (rand() < 0.08) printf "distributed_light { disk %s [0, -1, 0] %g power %g samples %s }\n", v(0, 3 * S, 0), S, 10 * S * S, pick("1 4 9")
    if (rand() < 0.5) printf "plane { point %s normal %s %s }\n", v(0, pick("0 -1 -0.5 0") * S, 0), pick("[0,1,0] [0,1,0] [0,-1,0] [0,1,1e-9]"), (rand() < 0.5 ? "material { Kd 0.8 }" : gm())
    n = ri(1, 25)
    for (i = 0; i < n; i++) {
        k = pick("gsph gsph gbox gbox nest bubble mesh plane fplane tri cyl touch coin")
        x = ri(-2, 2) * 0.5; y = ri(0, 2) * 0.5; z = ri(-2, 2) * 0.5
        if (k == "gsph") printf "sphere { center %s radius %.17g %s %s }\n", v(x * S, (y + 0.5) * S, z * S), pick("0.5 0.25 1 2") * S, gm(), (S == 1 ? frame(1) : "")
        else if (k == "gbox") printf "box { from %s to %s %s %s }\n", v(x * S, y * S, z * S), v((x + pick("0.5 1 2")) * S, (y + 0.5) * S, (z + 0.5) * S), gm(), (S == 1 ? frame(1) : "")
        else if (k == "nest") { m = ri(2, 4); for (a = 0; a < m; a++) printf "sphere { center %s radius %.17g %s }\n", v(x * S, y * S, z * S), (1 - a * pick("0.25 0.2 1e-9 0")) * S, gm() }
        else if (k == "bubble") { printf "box { from %s to %s %s }\n", v((x - 1) * S, (y - 1) * S, (z - 1) * S), v((x + 1) * S, (y + 1) * S, (z + 1) * S), gm(); printf "sphere { center %s radius %.17g material { Kd 0 Ks %s t 1 ior 1 } }\n", v(x * S, y * S, z * S), pick("0.5 0.25 1") * S, pick("0 0.1") }
        else if (k == "mesh") printf "mesh { file \"glass_cube.obj\" %s scale %s translate %s }\n", gm(), pick("0.5 1 2"), v(x * S, y * S, z * S)
        else if (k == "plane") printf "plane { point %s normal %s %s }\n", v(x * S, y * S, z * S), pick("[1,0,0] [0,1,0] [0,0,1] [1,1,0] [0,-1,0] [-1,0,0]"), gm()
        else if (k == "fplane") printf "plane { point %s normal %s %s }\n", v(pick("0 3e150 -3e150 1e15"), pick("0 1e150 -1e150 0.5"), 0), pick("[1,0,0] [0,1,0] [0,0,-1]"), gm()
        else if (k == "tri") printf "triangle { vertices %s %s %s %s }\n", v(x * S, y * S, z * S), v((x + 1) * S, y * S, z * S), v(x * S, y * S, (z + 1) * S), gm()
        else if (k == "cyl") printf "cylinder { from %s to %s radius %.17g %s %s }\n", v(x * S, y * S, z * S), v(x * S, (y + 1) * S, z * S), 0.5 * S, gm(), (S == 1 ? frame(1) : "")
        else if (k == "touch") { m = ri(2, 5); for (a = 0; a < m; a++) printf "box { from %s to %s %s }\n", v((x + 0.5 * a) * S, y * S, z * S), v((x + 0.5 * (a + 1)) * S, (y + 0.5) * S, (z + 0.5) * S), gm() }
        else if (k == "coin") { printf "box { from %s to %s %s }\n", v(x * S, y * S, z * S), v((x + 1) * S, (y + 1) * S, (z + 1) * S), gm(); printf "plane { point %s normal %s %s }\n", v(x * S, pick("0 1") * y * S + pick("0 1") * S, z * S), pick("[0,1,0] [0,-1,0]"), gm() }
    }
}
