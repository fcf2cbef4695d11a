# gen5.awk - a random scene where total reflection is common (attack 19,
# [SHADE-SHORTCUT-TIR-1]): one to three large dense glass solids in view
# (ball, box, kept-frame box, glass mesh, cylinder), things inside them
# (air bubbles, denser cores, opaque cores, coincident faces), a floor
# plane or a glass plane, point and distant lights only, depths 1 to 8,
# the camera outside or inside the glass.  awk -v seed=N -f
# ../attack18/common.awk -f common19.awk -f gen5.awk
function gm() {
    return sprintf("material { Kd %s Ks %s n %s t %s ior %s }", pick("0 0 0 0.1"), pick("0.05 0.3 1 0.5 0 0.1"),
                   pick("1 20 300 1e-3 1e5"), pick("1 1 0.9 0.5"), pick("1.5 2.4 2.4 3 1.33 1.9"))
}
function solid(x, y, z, R,   k) {
    k = pick("sph sph box box fbox mesh cyl")
    if (k == "sph") return sprintf("sphere { center %s radius %.17g %s }", v(x, y, z), R, gm())
    if (k == "box") return sprintf("box { from %s to %s %s }", v(x - R, y - R, z - R), v(x + R, y + R, z + R), gm())
    if (k == "fbox") return sprintf("box { from %s to %s %s rotate %s scale %s translate %s }", v(-R, -R, -R), v(R, R, R), gm(), v(pick("0 30 45"), pick("0 30 45 90"), pick("0 17")), v(pick("1 -1 2"), 1, pick("1 0.5")), v(x, y, z))
    if (k == "mesh") return sprintf("mesh { file \"glass_cube.obj\" %s scale %.17g translate %s }", gm(), R, v(x, y, z))
    return sprintf("cylinder { from %s to %s radius %.17g %s }", v(x, y - R, z), v(x, y + R, z), R, gm())
}
BEGIN {
    srand(seed)
    printf "image { width %d height %d max_depth %d background [0.3, 0.5, 0.8] }\n", pick("24 25 32"), pick("18 19 24"), pick("1 2 2 3 3 4 5 8")
    if (rand() < 0.25) printf "camera { perspective eye %s look_at %s up [0, 1, 0] fov %s }\n", v(r(-0.3, 0.3), r(0.7, 1.3), r(-0.3, 0.3)), v(r(-3, 3), r(-1, 3), r(-3, 3)), pick("60 90 150")
    else if (rand() < 0.3) printf "camera { orthographic eye %s look_at [0, 1, 0] up [0, 1, 0] width %s }\n", v(r(-4, 4), r(0, 4), r(3, 6)), pick("3 4 1")
    else printf "camera { perspective eye %s look_at [0, 1, 0] up [0, 1, 0] fov %s }\n", v(r(-4, 4), r(-1, 4), r(3, 6) * pick("1 -1")), pick("30 45 60")
    if (rand() < 0.6) print "ambient { color 0.1 }"
    printf "point_light { position %s power %g }\n", v(r(-3, 3), r(2, 5), r(-3, 3)), pick("20 40")
    if (rand() < 0.5) printf "distant_light { direction %s power 0.5 }\n", v(r(-1, 1), -1, r(-1, 1))
    if (rand() < 0.2) printf "point_light { position %s power 5 }\n", v(r(-0.5, 0.5), r(0.5, 1.5), r(-0.5, 0.5))
    if (rand() < 0.7) printf "plane { point [0, %s, 0] normal [0, 1, 0] %s }\n", pick("0 -0.5 0.0001"), (rand() < 0.7 ? "material { Kd 0.8 }" : gm())
    n = ri(1, 3)
    for (i = 0; i < n; i++) {
        x = pick("0 0 1 -1 0.5"); y = pick("1 1 0.5 1.5"); z = pick("0 0 -1 0.5"); R = pick("1 1 0.5 1.5")
        print solid(x, y, z, R)
        m = ri(0, 3)
        for (j = 0; j < m; j++) {
            k = pick("air core opq same half plane")
            if (k == "air") printf "sphere { center %s radius %.17g material { Kd 0 Ks %s t 1 ior 1 } }\n", v(x + r(-0.2, 0.2) * R, y, z), R * pick("0.3 0.5"), pick("0 0.1")
            else if (k == "core") print solid(x, y, z, R * pick("0.5 0.3 0.999999"))
            else if (k == "opq") printf "sphere { center %s radius %.17g material { Kd 0.6 Ks 0.2 n 10 } }\n", v(x, y, z), R * 0.2
            else if (k == "same") print solid(x, y, z, R)
            else if (k == "half") printf "box { from %s to %s %s }\n", v(x - R, y - R, z - R), v(x + R, y, z + R), gm()
            else printf "plane { point %s normal %s %s }\n", v(x, y, z), pick("[0,1,0] [1,0,0] [0,0,1] [0,-1,0]"), gm()
        }
    }
}
