# gen2.awk - a random scene of touching transparent parts in kept frames
# (uneven scale, turns), meshes, planes and disks on faces along x, y, z
# and tilted, opaque floors; everything moved by T.  awk -v seed=N -v
# Tf=T -f common.awk -f gen2.awk (Tf: T fixed)
function mat() { return material(0.75, "1 1.5 1.33 2.4", 0.6, 0.4) }
function tr(x, y, z) { return sprintf(" translate %s", v(x * S + T, y * S, z * S)) }
BEGIN {
    srand(seed)
    T = pick("0 0 0 1e2 1e4 1e6 1e8")
    if (Tf != "") T = Tf
    S = pick("1 1 1 1e-3 1e3 0.1 10")
    sc = (S == 1 ? "" : " scale " S)
    printf "image { width 20 height 15 max_depth %d background [0.3, 0.5, 0.8] }\n", pick("3 5 8 16")
    ex = r(-4, 4) * S; ey = r(-2, 5) * S; ez = r(3, 7) * S * pick("1 -1")
    if (rand() < 0.3) printf "camera { orthographic eye %s look_at %s up [0, 1, 0] width %g }\n", v(ex + T, ey, ez), v(T, 0.5 * S, 0), 4 * S
    else printf "camera { perspective eye %s look_at %s up [0, 1, 0] fov %d }\n", v(ex + T, ey, ez), v(T, 0.5 * S, 0), ri(20, 70)
    print "ambient { color 0.1 }"
    printf "point_light { position %s power %g }\n", v(r(-3, 3) * S + T, 4 * S, r(-3, 3) * S), 20 * S * S
    if (rand() < 0.5) printf "distributed_light { disk %s [0, -1, 0] %g power %g samples %d }\n", v(T, 3 * S, 0), S, 10 * S * S, pick("63 64 65 70 3")
    n = ri(1, 30)
    for (i = 0; i < n; i++) {
        k = pick("kbox ksph kcyl ktor mesh face xplane tdisk cube cube sph")
        x = ri(-2, 2) * 0.5; y = ri(0, 2) * 0.5; z = ri(-2, 2) * 0.5
        rot = sprintf(" rotate %s", v(pick("0 90 30 45"), pick("0 90 30 45 180"), pick("0 90 60")))
        if (k == "cube") printf "box { from [0, 0, 0] to [0.5, 0.5, 0.5] %s%s%s }\n", mat(), sc, tr(x, y, z)
        else if (k == "sph") printf "sphere { center [0, 0, 0] radius 0.25 %s%s%s }\n", mat(), sc, tr(x + 0.25, y + 0.25 + pick("0 0.5 -0.5"), z + 0.25)
        else if (k == "kbox") printf "box { from [-0.25, -0.25, -0.25] to [0.25, 0.25, 0.25] %s scale %s%s%s%s }\n", mat(), v(pick("1 2 0.5"), pick("1 0.5 3"), 1), rot, sc, tr(x + 0.25, y + 0.25, z + 0.25)
        else if (k == "ksph") printf "sphere { center [0, 0, 0] radius 0.25 %s scale %s%s%s%s }\n", mat(), v(pick("1 2 0.5"), 1, pick("1 0.5")), (rand() < 0.5 ? rot : ""), sc, tr(x + 0.25, y + pick("0.25 0.5 0.125"), z + 0.25)
        else if (k == "kcyl") printf "cylinder { from [0, -0.25, 0] to [0, 0.25, 0] radius 0.25 %s scale %s%s%s }\n", mat(), v(pick("1 2"), 1, pick("1 0.5")), sc, tr(x + 0.25, y + 0.25, z + 0.25)
        else if (k == "ktor") printf "torus { major 0.2 minor 0.05 %s scale %s%s%s%s }\n", mat(), v(1, pick("1 0.5"), 1), rot, sc, tr(x + 0.25, y + 0.05, z + 0.25)
        else if (k == "mesh") printf "mesh { file \"glass_cube.obj\" %s scale 0.25%s%s }\n", mat(), sc, tr(x + 0.25, y + 0.25, z + 0.25)
        else if (k == "face") printf "disk { center %s normal %s radius 0.25 %s%s }\n", v((x + 0.25) * S + T, (y + pick("0 0.5")) * S, (z + 0.25) * S), pick("[0,1,0] [0,-1,0] [0,1,1e-9]"), mat(), ""
        else if (k == "xplane") printf "plane { point %s normal %s %s }\n", v((x + pick("0 0.5")) * S + T, y * S, z * S), pick("[1,0,0] [0,0,1] [0,1,0] [-1,0,0]"), mat()
        else if (k == "tdisk") printf "disk { center [0, 0, 0] normal [0, 0, 1] radius 0.25 %s%s%s%s }\n", mat(), rot, sc, tr(x + 0.25, y + 0.25, z + pick("0 0.5"))
    }
}
