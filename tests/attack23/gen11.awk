# gen11.awk - a random scene for [BVH-BEAM-1] (attack 23): perspective
# cameras looking exactly along an axis (+-x, +-y, +-z: a direction
# component 0 on the centre column or row), nearly along one (1e-9 .. 1e-300
# off: a tiny or subnormal component), along a diagonal, or anywhere; fov
# 0.01 .. 179 (the octant changing inside a run of 32 pixels, or 1/d nearly
# equal over a run); the eye inside a box or ball (opaque or glass), on a
# box's face, on a grid corner; widths 1, 31 .. 33, 63 .. 65, 97; k x k
# samples 1 .. 4, sometimes 16 (runs of one pixel); a grid of up to 20 x 20
# small balls (trees that pass the pruned tree's 64 records), boxes,
# meshes, tori, cylinders, cones, disks, triangles, planes, kept frames;
# scale 1e-6 .. 1e6, moved by up to 1e12.  awk -v seed=N
# -f ../attack18/common.awk -f ../attack19/common19.awk -f gen11.awk
function W(x, y, z) { return v(TX + x * S, TY + y * S, TZ + z * S) }
function mm() { return mixed_material(0.25, "0 0.3", "0.5 1 0.9", "1 1.5", "0.8 0.5 0", "0 0.2 0.5", "20 1 1000") }
function axisdir(   k, e) {
    k = pick("x -x y -y z -z")
    e = pick("0 0 0 1e-9 1e-17 1e-300 -1e-300 1e-12")
    if (k == "x") return v(1, e, e * pick("0 1 -1"))
    if (k == "-x") return v(-1, e, e * pick("0 1"))
    if (k == "y") return v(e, 1, e * pick("0 1"))
    if (k == "-y") return v(e * pick("0 -1"), -1, e)
    if (k == "z") return v(e, e * pick("0 1"), 1)
    return v(e * pick("0 1"), e, -1)
}
BEGIN {
    srand(seed)
    S = pick("1 1 1 1 0.5 1e-3 1e3 1e6 1e-6")
    T = pick("0 0 0 0 1 0.25 1e3 1e6 1e12")
    TX = T * pick("1 0 -1"); TY = T * pick("0 1"); TZ = T * pick("1 0 0.5")
    w = pick("1 31 32 33 63 64 65 97 40"); h = pick("1 2 5 9 16")
    k = pick("1 1 1 2 2 3 4 16")
    printf "image { width %d height %d max_depth %s samples %d background [0.3, 0.5, 0.8] }\n", w, h, pick("1 2 3 5"), k
    ek = pick("free free grid inbox inball face")
    if (ek == "free") { ex = r(-4, 4); ey = r(-1, 4); ez = r(-4, 6) }
    else if (ek == "grid") { ex = ri(-8, 8) * 0.5; ey = ri(-2, 8) * 0.5; ez = ri(-8, 8) * 0.5 }
    else { ex = ri(-4, 4) * 0.5; ey = ri(0, 4) * 0.5; ez = ri(-4, 4) * 0.5 }
    dk = pick("axis axis axis diag free")
    if (dk == "axis") d = axisdir()
    else if (dk == "diag") d = v(pick("1 -1"), pick("1 -1 0"), pick("1 -1"))
    else d = v(r(-1, 1), r(-1, 1), r(-1, 1))
    split(substr(d, 2, length(d) - 2), dd, ", ")
    up = (dd[2] * dd[2] > 0.5 * (dd[1] * dd[1] + dd[3] * dd[3])) ? "[1,0,0]" : pick("[0,1,0] [0,1,0] [0,-1,0] [1,1,0]")
    if (up == "[1,1,0]" && dd[1] == dd[2] && dd[3] == 0) up = "[0,0,1]"
    printf "camera { perspective eye %s look_at %s up %s fov %s }\n", W(ex, ey, ez), W(ex + dd[1], ey + dd[2], ez + dd[3]), up, pick("0.01 1 20 40 60 90 120 170 179")
    print "ambient { color 0.05 }"
    if (ek == "inbox") printf "box { from %s to %s %s }\n", W(ex - 0.25, ey - 0.25, ez - 0.25), W(ex + pick("0.25 0.5 3"), ey + 0.25, ez + 0.25), mm()
    if (ek == "inball") printf "sphere { center %s radius %.17g %s }\n", W(ex, ey, ez), pick("0.1 0.5 2") * S, mm()
    if (ek == "face") printf "box { from %s to %s %s }\n", W(ex, ey - 0.5, ez - 0.5), W(ex + 1, ey + 0.5, ez + 0.5), mm()
    if (rand() < 0.5) printf "plane { point %s normal %s %s }\n", W(0, -1, 0), pick("[0,1,0] [0,1,0] [0,1,1e-7] [1,0,0]"), mm()
    g = pick("0 0 3 8 12 20")
    sp = pick("0.5 0.25 1")
    for (a = 0; a < g; a++) for (b = 0; b < g; b++)
        printf "sphere { center %s radius %.17g %s }\n", W((a - g / 2) * sp, pick("0 0.5"), (b - g / 2) * sp), sp * pick("0.2 0.4 0.5") * S, mm()
    n = ri(1, 12)
    for (i = 0; i < n; i++) {
        kk = pick("sphere box box tri mesh mesh torus cyl cone disk plane")
        x = ri(-6, 6) * 0.5; y = ri(-2, 6) * 0.5; z = ri(-6, 6) * 0.5
        if (kk == "sphere") printf "sphere { center %s radius %s %s%s }\n", W(x, y, z), pick("0.25 0.5 0.1 1") * S, mm(), (S == 1 && T == 0 ? frame(1) : "")
        else if (kk == "box") printf "box { from %s to %s %s%s }\n", W(x, y, z), W(x + pick("0.5 0.25 1 1e-3"), y + pick("0.5 0.25 2"), z + pick("0.5 0.25 1")), mm(), (S == 1 && T == 0 ? frame(1) : "")
        else if (kk == "tri") printf "triangle { vertices %s %s %s %s }\n", W(x, y, z), W(x + pick("0.5 1 -1"), y + pick("0 0.5"), z), W(x, y + pick("0.5 1"), z + pick("0.5 -0.5")), mm()
        else if (kk == "plane") printf "plane { point %s normal %s %s }\n", W(x, y, z), pick("[1,0,0] [0,0,1] [1,1,0] [0,-1,0]"), mm()
        else if (kk == "torus") printf "torus { center %s axis %s major %g minor %g %s }\n", W(x, y, z), pick("[0,1,0] [1,0,0] [1,1,1]"), 0.5 * S, pick("0.1 0.2 0.01") * S, mm()
        else if (kk == "cyl") printf "cylinder { from %s to %s radius %g %s }\n", W(x, y, z), W(x, y + 1, z + pick("0 0.5")), 0.3 * S, mm()
        else if (kk == "cone") printf "cone { from %s to %s radii %g %g %s }\n", W(x, y, z), W(x + pick("0 0.5"), y + 1, z), 0.4 * S, pick("0 0.1") * S, mm()
        else if (kk == "disk") printf "disk { center %s normal %s radius %g %s }\n", W(x, y, z), pick("[0,1,0] [1,0,0] [0,0,1] [1,2,3]"), 0.5 * S, mm()
        else printf "mesh { file \"%s\" %s%s scale %g translate %s }\n", pick("octa.obj fan.obj sheet.obj glass_cube.obj geosphere.obj"), mm(), frame(0), pick("1 0.5 2 -1") * S, W(x, y, z)
    }
    nl = ri(1, 3)
    for (i = 0; i < nl; i++)
        printf "point_light { position %s power %g }\n", W(r(-3, 3), r(0.5, 4), r(-3, 3)), 10 * S * S
    if (rand() < 0.2) printf "distant_light { direction %s power 1 }\n", pick("[0,-1,0] [1,-1,0] [0.3,-1,0.2]")
}
