# gen15.awk - attack 24: a random scene for [SHADE-SHORTCUT-PLANE-1] and
# [SHADE-SHORTCUT-OPEN-1]: distributed lights (rectangles and disks, 1 .. 3,
# 1 .. 16 samples) seen from points on meshes and triangles (leaves of
# triangles alone: open bundles), and 0 .. 40 planes (past the 32 the
# bundle looks at): through a light's centre or corner, holding a light
# (its normal in the light's plane: the light straddles it), through a
# shaded point (a box's face, the floor), nearly parallel to a light's
# direction (normals 1e-9 .. 1e-15 off an axis), under kept frames
# (transformed planes are never passed), anywhere; opaque or glass;
# degenerate and huge triangles; scale 1e-6 .. 1e6, moved up to 1e9 and
# sometimes 1e120 (past 2^400 the planes are not looked at).
# awk -v seed=N -f ../attack18/common.awk -f ../attack19/common19.awk -f gen15.awk
function W(x, y, z) { return v(TX + x * S, TY + y * S, TZ + z * S) }
function mat() {
    if (GLASS && rand() < 0.3) return glassy(pick("0 0.2"), pick("0.3 0"), "30", pick("0.5 1 0.9"), pick("1 1.5"))
    return sprintf("material { Kd %s Ks %s n %s }", pick("0.8 0.5 1"), pick("0 0.3"), pick("1 20"))
}
function nrm(   k) {
    k = pick("ax ax ax tilt tilt near near any")
    if (k == "ax") return pick("[0,1,0] [1,0,0] [0,0,1] [0,-1,0] [-1,0,0]")
    if (k == "tilt") return pick("[1,1,0] [1,0,1] [0,1,1] [1,2,3] [-1,1,0]")
    if (k == "near") return v(pick("1e-9 1e-12 1e-15 -1e-9 0"), pick("1 -1"), pick("1e-9 0 1e-15"))
    return v(r(-1, 1), r(-1, 1), r(-1, 1))
}
BEGIN {
    srand(seed)
    FR[1] = " rotate [0, 0, 1e-9]"; FR[2] = " rotate [90, 0, 0]"; FR[3] = " scale 2"; FR[4] = " translate [0, -3, 0]"
    GLASS = rand() < 0.3
    S = pick("1 1 1 1 0.5 1e-3 1e3 1e6 1e-6")
    T = pick("0 0 0 0 1 1e3 1e6 1e9 1e120")
    TX = T * pick("1 0 -1"); TY = T * pick("0 1"); TZ = T * pick("1 0 0.5")
    image(pick("16 17 24 33"), pick("12 13 18"), pick("1 2 3 5"))
    printf "camera { perspective eye %s look_at %s up [0, 1, 0] fov %s }\n", W(r(-3, 3), r(0.5, 4), r(3, 7)), W(0, 0.5, 0), pick("40 60 90")
    print "ambient { color " pick("0.05 0") " }"
    fl = pick("plane plane box none")
    if (fl == "box") printf "box { from %s to %s %s }\n", W(-4, -1, -4), W(4, 0, 4), mat()
    if (fl == "plane") printf "plane { point %s normal [0, 1, 0] %s }\n", W(0, 0, 0), mat()
    # lights
    nl = ri(1, 3)
    for (i = 0; i < nl; i++) {
        LX[i] = ri(-8, 8) * 0.25; LY[i] = pick("3 2 1 0.5 0.25 0 1e-9"); LZ[i] = ri(-8, 8) * 0.25
        sz = pick("0.5 1 0.25 1e-6 2")
        if (rand() < 0.5) {
            ax = pick("y y y x z")
            if (ax == "y") printf "distributed_light { rectangle %s %s %s power %g samples %s }\n", W(LX[i] - sz / 2, LY[i], LZ[i] - sz / 2), v(sz * S, 0, 0), v(0, 0, sz * S), 10 * S * S, pick("1 4 9 16")
            else if (ax == "x") printf "distributed_light { rectangle %s %s %s power %g samples %s }\n", W(LX[i], LY[i], LZ[i] - sz / 2), v(0, sz * S, 0), v(0, 0, sz * S), 10 * S * S, pick("1 4 9 16")
            else printf "distributed_light { rectangle %s %s %s power %g samples %s }\n", W(LX[i] - sz / 2, LY[i], LZ[i]), v(sz * S, 0, 0), v(0, sz * S, 0), 10 * S * S, pick("1 4 9 16")
        } else {
            printf "distributed_light { disk %s %s %g power %g samples %s }\n", W(LX[i], LY[i], LZ[i]), pick("[0,-1,0] [0,1,0] [1,0,0] [1,-1,0] [0.3,-1,0.2]"), sz * S / 2, 10 * S * S, pick("1 4 9 16")
        }
    }
    if (rand() < 0.3) printf "point_light { position %s power %g }\n", W(r(-2, 2), r(1, 3), r(-2, 2)), 10 * S * S
    # triangle-only parts: meshes, triangles (degenerate, huge)
    n = ri(1, 8)
    for (i = 0; i < n; i++) {
        k = pick("mesh mesh mesh tri tri degen huge sphere box")
        x = ri(-6, 6) * 0.25; y = ri(0, 8) * 0.25; z = ri(-6, 6) * 0.25
        P[i] = x " " y " " z
        if (k == "mesh") printf "mesh { file \"%s\" %s%s scale %g translate %s }\n", pick("octa.obj fan.obj sheet.obj glass_cube.obj geosphere.obj"), mat(), frame(0), pick("1 0.5 2 -1") * S, W(x, y, z)
        else if (k == "tri") printf "triangle { vertices %s %s %s %s }\n", W(x, y, z), W(x + pick("0.5 1 -1"), y + pick("0 0.5"), z), W(x, y + pick("0.5 1 0"), z + pick("0.5 -0.5")), mat()
        else if (k == "degen") printf "triangle { vertices %s %s %s %s }\n", W(x, y, z), W(x + 1e-12, y + 1e-12, z), W(x, y + pick("0.5 1"), z + pick("0.5 1e-15")), mat()
        else if (k == "huge") printf "triangle { vertices %s %s %s %s }\n", W(x - 1e6, y, z - 1e6), W(x + 1e6, y, z - 1e6), W(x, y + pick("0 1e-6 1"), z + 1e6), mat()
        else if (k == "sphere") printf "sphere { center %s radius %s %s }\n", W(x, y, z), pick("0.25 0.5") * S, mat()
        else printf "box { from %s to %s %s }\n", W(x, y, z), W(x + 0.5, y + 0.5, z + 0.5), mat()
    }
    # planes
    np = pick("0 1 2 3 5 8 31 32 33 40")
    for (i = 0; i < np; i++) {
        k = pick("light light corner hold shade near any frame")
        j = ri(0, nl - 1)
        if (k == "light") printf "plane { point %s normal %s %s }\n", W(LX[j], LY[j] + pick("0 0 1e-9 -1e-9 0.1"), LZ[j]), nrm(), mat()
        else if (k == "corner") printf "plane { point %s normal %s %s }\n", W(LX[j] + 0.25, LY[j], LZ[j] + 0.25), nrm(), mat()
        else if (k == "hold") printf "plane { point %s normal %s %s }\n", W(LX[j], LY[j], LZ[j]), pick("[1,0,0] [0,0,1] [1,0,1] [1e-12,0,1]"), mat()
        else if (k == "shade") { split(P[ri(0, n - 1)], q, " "); printf "plane { point %s normal %s %s }\n", W(q[1], q[2], q[3]), nrm(), mat() }
        else if (k == "near") printf "plane { point %s normal %s %s }\n", W(r(-3, 3), pick("-1 -0.5 4 5"), r(-3, 3)), nrm(), mat()
        else if (k == "frame") printf "plane { point %s normal %s %s%s }\n", W(0, pick("-2 -1 5"), 0), nrm(), mat(), FR[ri(1, 4)]
        else printf "plane { point %s normal %s %s }\n", W(r(-9, 9), r(-9, 9), r(-9, 9)), nrm(), mat()
    }
}
