# gen13.awk - a random scene for [BVH-BEAM-1]'s claim (ii) (attack 23):
# rays that pass an ancestor's box and miss a leaf's by a hair.  A cluster
# of 2 .. 40 small parts of one or two kinds (balls, kept-frame balls and
# boxes, boxes, disks, tori, cones, cylinders, triangles, meshes) near the
# origin, their boxes touching or nested; the eye far away (1e2 .. 1e12 of
# their size) along an axis, a diagonal or anywhere, looking at the
# cluster's centre with a fov that frames it (the rays graze the boxes'
# faces and edges at the silhouettes), 33 .. 97 pixels wide, 1 .. 3 x 3
# samples.  awk -v seed=N -f ../attack18/common.awk
# -f ../attack19/common19.awk -f gen13.awk
function mm() { return mixed_material(0.2, "0 0.3", "0.5 1", "1 1.5", "0.8 0.5 0", "0 0.2 0.5", "20 1 1000") }
function part(k, x, y, z, s) {
    if (k == "sphere") return sprintf("sphere { center %s radius %.17g %s }", v(x, y, z), s, mm())
    if (k == "fsphere") return sprintf("sphere { center [0, 0, 0] radius %.17g %s rotate %s translate %s }", s, mm(), v(ri(0, 3) * 30, ri(0, 3) * 30, 0), v(x, y, z))
    if (k == "box") return sprintf("box { from %s to %s %s }", v(x - s, y - s, z - s), v(x + s, y + s, z + s), mm())
    if (k == "fbox") return sprintf("box { from %s to %s %s rotate %s translate %s }", v(-s, -s, -s), v(s, s, s), mm(), v(ri(0, 3) * 30, 45, 0), v(x, y, z))
    if (k == "disk") return sprintf("disk { center %s normal %s radius %.17g %s }", v(x, y, z), pick("[0,1,0] [1,0,0] [0,0,1] [1,1,0] [1,2,3]"), s, mm())
    if (k == "torus") return sprintf("torus { center %s axis %s major %.17g minor %.17g %s }", v(x, y, z), pick("[0,1,0] [1,0,0] [0,0,1] [1,1,1]"), s, s * pick("0.1 0.3 0.01"), mm())
    if (k == "cone") return sprintf("cone { from %s to %s radii %.17g %.17g %s }", v(x, y - s, z), v(x + pick("0 0.5") * s, y + s, z), s, pick("0 0.3") * s, mm())
    if (k == "cyl") return sprintf("cylinder { from %s to %s radius %.17g %s }", v(x, y - s, z), v(x, y + s, z + pick("0 0.5") * s), s * 0.5, mm())
    if (k == "tri") return sprintf("triangle { vertices %s %s %s %s }", v(x - s, y, z), v(x + s, y, z), v(x, y + s, z + pick("0 0.3") * s), mm())
    return sprintf("mesh { file \"%s\" %s scale %.17g translate %s }", pick("octa.obj geosphere.obj glass_cube.obj"), mm(), s, v(x, y, z))
}
BEGIN {
    srand(seed)
    D = pick("1e2 1e3 1e4 1e6 1e9 1e12")
    L = pick("1 1e-3 1e3")
    kinds = "sphere fsphere box fbox disk torus cone cyl tri mesh"
    k1 = pick(kinds); k2 = pick(kinds)
    n = ri(2, 40)
    w = pick("33 64 65 97"); h = pick("3 8 17")
    printf "image { width %d height %d max_depth %s samples %s background [0.3, 0.5, 0.8] }\n", w, h, pick("1 2"), pick("1 1 2 3")
    dk = pick("x y z diag free")
    if (dk == "x") d = "1 0 0"; else if (dk == "y") d = "0 1 0"; else if (dk == "z") d = "0 0 -1"
    else if (dk == "diag") d = "1 1 1"; else d = r(-1, 1) " " r(-1, 1) " " r(-1, 1)
    split(d, dd, " ")
    m = sqrt(dd[1] * dd[1] + dd[2] * dd[2] + dd[3] * dd[3])
    up = dk == "y" ? "[1,0,0]" : "[0,1,0]"
    if (dk == "free" && dd[2] * dd[2] > 0.9 * m * m) up = "[1,0,0]"
    fov = 2 * atan2(pick("1 2 4") * L, D * L) * 180 / 3.141592653589793
    printf "camera { perspective eye %s look_at [0, 0, 0] up %s fov %.17g }\n", v(dd[1] / m * D * L, dd[2] / m * D * L, dd[3] / m * D * L), up, fov
    print "ambient { color 0.1 }"
    for (i = 0; i < n; i++) {
        g = pick("0.5 0.25 1")
        x = (ri(0, 6) - 3) * g * L; y = (ri(0, 6) - 3) * g * L; z = (ri(0, 6) - 3) * g * L
        print part(rand() < 0.5 ? k1 : k2, x, y, z, pick("0.25 0.5 0.125 0.3") * L)
    }
    printf "point_light { position %s power %g }\n", v(3 * L, 5 * L, 4 * L), 20 * L * L
}
