# gen12.awk - (with -v ortho=1: gen14, an orthographic camera of width 2, 4 or 8
# of the scale) a random scene for [SHADE-SHORTCUT-ANY-1], the blocker hints
# and [SHADE-SHORTCUT-ABSORB-1] (attack 23): mostly all-opaque scenes (t = 0
# everywhere, sometimes with an ior; a glass part in one case of five, and
# then sometimes glass inside glass), Kd = 0 highlight materials (n 1 ..
# 1e6, fractional, below 1; Ks 1e-12 .. 1, per channel) beside Lambert ones;
# 1 .. 12 point lights of powers 1e-12 .. 1e12 (several lights, one bright
# one dim: the dim one's highlight absorbed), on a surface (a ball's top, a
# box's face, a plane), in a part, on a grid corner, far away; d0 and the
# falloffs; distant lights; balls, boxes, triangles, disks, meshes, tori,
# cylinders, planes; a ball coincident with a light; scale 1e-6 .. 1e6,
# moved by up to 1e9.  awk -v seed=N -f ../attack18/common.awk
# -f ../attack19/common19.awk -f gen12.awk
function W(x, y, z) { return v(TX + x * S, TY + y * S, TZ + z * S) }
function col(s) { return rand() < 0.7 ? pick(s) : "[" pick(s) ", " pick(s) ", " pick(s) "]" }
function mm(   k) {
    k = pick("spec spec spec lam lam ior glass")
    if (k == "glass" && GLASS) return sprintf("material { Kd %s Ks %s n %s t %s ior %s }", pick("0 0.2"), pick("0.3 1 0"), pick("30 1000"), pick("0.5 1 0.9"), pick("1 1.5"))
    if (k == "ior") return sprintf("material { Kd %s Ks %s n %s t 0 ior %s }", pick("0 0.5"), col("0.5 1"), pick("20 1e4"), pick("1.5 1"))
    if (k == "lam") return sprintf("material { Kd %s Ks %s n %s }", col("0.8 0.3 1e-9"), pick("0 0.3"), pick("1 20 1000"))
    return sprintf("material { Kd 0 Ks %s n %s }", col("1 0.5 1e-9 1e-12 0.999"), pick("1 1.5 2 5 30 300 1000 1e4 1e5 1e6 1048575 1048576 0.5 0.999 7.25"))
}
BEGIN {
    srand(seed)
    GLASS = rand() < 0.2
    S = pick("1 1 1 1 0.5 1e-3 1e3 1e6 1e-6")
    T = pick("0 0 0 0 1 1e3 1e6 1e9")
    TX = T * pick("1 0 -1"); TY = T * pick("0 1"); TZ = T * pick("1 0 0.5")
    image(pick("16 17 24 33"), pick("12 13 18"), pick("1 2 3 5"))
    if (ortho)   # gen14: the same scenes through an orthographic camera
        printf "camera { orthographic eye %s look_at %s up [0, 1, 0] width %s }\n", W(r(-3, 3), r(0.5, 4), r(3, 7)), W(0, 0.5, 0), pick("2 4 8") * S
    else
        printf "camera { perspective eye %s look_at %s up [0, 1, 0] fov %s }\n", W(r(-3, 3), r(0.5, 4), r(3, 7)), W(0, 0.5, 0), pick("40 60 90")
    print "ambient { color " pick("0.05 0 0") " }"
    fl = pick("box box plane none")
    if (fl == "box") printf "box { from %s to %s %s }\n", W(-4, -1, -4), W(4, 0, 4), mm()
    if (fl == "plane") printf "plane { point %s normal [0, 1, 0] %s }\n", W(0, 0, 0), mm()
    if (GLASS && rand() < 0.5) {
        printf "sphere { center %s radius %s %s }\n", W(0, 1, 0), 1 * S, "material { Kd 0 Ks 0.5 n 200 t 0.9 ior 1.5 }"
        printf "sphere { center %s radius %s %s }\n", W(0, 1, 0), 0.5 * S, "material { Kd 0 Ks 1 n 2000 t 0.8 ior 1.3 }"
    }
    n = ri(1, 12)
    for (i = 0; i < n; i++) {
        k = pick("sphere sphere box box tri mesh disk torus cyl plane")
        x = ri(-6, 6) * 0.25; y = ri(0, 10) * 0.25; z = ri(-6, 6) * 0.25
        P[i] = x " " y " " z
        if (k == "sphere") printf "sphere { center %s radius %s %s }\n", W(x, y, z), pick("0.25 0.5 0.1 1") * S, mm()
        else if (k == "box") printf "box { from %s to %s %s }\n", W(x, y, z), W(x + pick("0.5 0.25 1 1e-3"), y + pick("0.5 0.25 2"), z + pick("0.5 0.25 1")), mm()
        else if (k == "tri") printf "triangle { vertices %s %s %s %s }\n", W(x, y, z), W(x + pick("0.5 1 -1"), y + pick("0 0.5"), z), W(x, y + pick("0.5 1"), z + pick("0.5 -0.5")), mm()
        else if (k == "disk") printf "disk { center %s normal %s radius %g %s }\n", W(x, y, z), pick("[0,1,0] [1,0,0] [0,-1,0] [1,2,3]"), 0.5 * S, mm()
        else if (k == "torus") printf "torus { center %s axis %s major %g minor %g %s }\n", W(x, y, z), pick("[0,1,0] [1,0,0]"), 0.5 * S, 0.15 * S, mm()
        else if (k == "cyl") printf "cylinder { from %s to %s radius %g %s }\n", W(x, y, z), W(x, y + 1, z), 0.3 * S, mm()
        else if (k == "plane") printf "plane { point %s normal %s %s }\n", W(x, y, z), pick("[1,0,0] [0,0,1] [1,1,0] [0,-1,0]"), mm()
        else printf "mesh { file \"%s\" %s%s scale %g translate %s }\n", pick("octa.obj fan.obj sheet.obj glass_cube.obj geosphere.obj"), mm(), frame(0), pick("1 0.5 2 -1") * S, W(x, y, z)
    }
    nl = ri(1, 12)
    for (i = 0; i < nl; i++) {
        k = pick("in in grid surf surf part far near")
        if (k == "in") p = W(r(-3, 3), r(0.1, 3), r(-3, 3))
        else if (k == "grid") p = W(ri(-8, 8) * 0.25, ri(0, 8) * 0.25, ri(-8, 8) * 0.25)
        else if (k == "surf") p = W(r(-3, 3), fl == "none" ? 1 : 0, r(-3, 3))
        else if (k == "part") { split(P[ri(0, n - 1)], q, " "); p = W(q[1], q[2] + pick("0 0.25 0.5 1"), q[3]) }
        else if (k == "far") p = W(r(-1, 1) * pick("1e3 1e6"), pick("1e3 1e6"), r(-1, 1) * pick("1e3 1e6"))
        else p = W(r(-2, 2), pick("1e-9 1e-12 0.001"), r(-2, 2))
        f = k == "far" ? pick("1e6 1e12") : 1
        printf "point_light { position %s power %s%s }\n", p, col("1e-12 1e-6 1 10 1e3 1e12") * S * S * f, rand() < 0.3 ? sprintf(" d0 %g falloff %s", pick("0 1 1e-9 100") * S, pick("linear inverse_square none")) : ""
    }
    if (rand() < 0.3) printf "distant_light { direction %s power %s }\n", pick("[0,-1,0] [1,-1,0] [0.3,-1,0.2] [0,1,0]"), pick("1 1e-9 1e6")
    if (rand() < 0.15) printf "distributed_light { disk %s [0, -1, 0] %g power %g samples %s }\n", W(0, 3, 0), 0.5 * S, 10 * S * S, pick("4 9")
}
