# gen9.awk - a random scene for [SHADE-SHORTCUT-DARK-2] (attack 22): disk
# lights with any normal (tilted, nearly in a surface's plane, facing away),
# radius 1e-6 .. 10 of the scale, 4 .. 4096 samples (several disks so that
# TRACE_CELLS_MAX leaves some out), low over the floor or beside spheres;
# Kd = 0 surfaces with a highlight (n 1 .. 1e6) and without, Lambert ones;
# scale 1e-6 .. 1e6, everything moved by up to 1e12; a point light
# sometimes.  awk -v seed=N -f ../attack18/common.awk -f gen9.awk
function W(x, y, z) { return v(TX + x * S, TY + y * S, TZ + z * S) }
function nrm() { return pick("[0,-1,0] [0,1,0] [1,0,0] [1,-1,0.3] [0,0,1] [1,-0.01,0] [1,0.001,0.2] [0.3,-1,-0.7] [-1,-1e-9,0] [0,-1e-5,1] rnd rnd") }
function mat(   k) {
    k = pick("lam lam spec spec spec spec mir none")
    if (k == "lam") return sprintf("material { Kd %s Ks %s n %s }", pick("0.8 0.3 1e-9"), pick("0 0.3"), pick("1 20 1000"))
    if (k == "spec") return sprintf("material { Kd 0 Ks %s n %s }", pick("0.5 1 1e-9"), pick("1 2 5 30 300 1000 1e4 1e6"))
    if (k == "mir") return sprintf("material { Kd 0 Ks 0.9 n %s t %s ior %s }", pick("1000 50"), pick("0 0 0.5"), pick("1 1.5"))
    return "material { Kd 0 Ks 0 }"
}
BEGIN {
    srand(seed)
    S = pick("1 1 1 1e-3 1e3 1e6 1e-6")
    T = pick("0 0 0 1e3 1e6 1e9 1e12")
    TX = T * pick("1 0 -1"); TY = T * pick("0 1"); TZ = T * pick("1 0 0.5")
    image(pick("16 17 12"), pick("12 13 9"), pick("1 2 3 4"))
    printf "camera { perspective eye %s look_at %s up [0, 1, 0] fov %s }\n", W(r(-3, 3), r(0.3, 4), r(3, 7)), W(0, 0.5, 0), pick("40 60 90")
    print "ambient { color 0.05 }"
    nl = ri(1, 4)
    for (i = 0; i < nl; i++) {
        n = nrm()
        if (n == "rnd") n = v(r(-1, 1), r(-1, 1), r(-1, 1))
        h = pick("0.01 0.1 0.5 1 2 3 1e-4")
        printf "distributed_light { disk %s %s %.17g power %g samples %s }\n", W(r(-2, 2), h, r(-2, 2)), n, pick("0.25 0.5 1e-6 1 2 5 10 0.05") * S, 10 * S * S, pick("4 5 6 7 8 9 12 16 17 36 49 64 65 100 256 1024 2048 3000 4096")
    }
    if (rand() < 0.3) printf "point_light { position %s power %g }\n", W(r(-3, 3), 4, r(-3, 3)), 10 * S * S
    if (rand() < 0.8) printf "plane { point %s normal %s %s }\n", W(0, 0, 0), pick("[0,1,0] [0,1,0] [0.01,1,0] [0,1,1e-7]"), mat()
    n = ri(1, 6)
    for (i = 0; i < n; i++) {
        k = pick("sphere sphere box tri")
        if (k == "sphere") printf "sphere { center %s radius %.17g %s }\n", W(r(-2, 2), r(0, 2), r(-2, 2)), r(0.05, 1.2) * S, mat()
        else if (k == "box") { x = r(-2, 1); y = r(-0.5, 1); z = r(-2, 1); printf "box { from %s to %s %s }\n", W(x, y, z), W(x + r(0.1, 1.5), y + r(0.05, 1.5), z + r(0.1, 1.5)), mat() }
        else printf "triangle { vertices %s %s %s %s }\n", W(r(-2, 2), r(0, 2), r(-2, 2)), W(r(-2, 2), r(0, 2), r(-2, 2)), W(r(-2, 2), r(0, 2), r(-2, 2)), mat()
    }
}
