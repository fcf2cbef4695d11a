# gen10.awk - a random scene for [SHADE-SHORTCUT-BUNDLE-2] (attack 22):
# point lights (1 .. 12, past TRACE_BLOCKERS' 8) inside the scene's box,
# on a corner of the root box, on multiples of the cell edge 0.5, far
# outside (1e3 .. 1e8 of the scale), 1e-9 off a surface; a floor box whose
# top lies on a cell border (the root box's corner on the grid), walls,
# transparent and opaque occluders (spheres, boxes, triangles, meshes),
# planes (unbounded); scale 1e-6 .. 1e6, moved by up to 1e9; sometimes a
# disk light beside.  awk -v seed=N -f ../attack18/common.awk
# -f ../attack19/common19.awk -f gen10.awk
function W(x, y, z) { return v(TX + x * S, TY + y * S, TZ + z * S) }
function mm() { return mixed_material(0.4, "0 0.3", "0.5 1 0.9 0.3", "1 1 1.5", "0.8 0.5 0", "0 0.2 0.5", "20 1 1000") }
BEGIN {
    srand(seed)
    S = pick("1 1 1 1 1 0.5 2 1e-3 1e3 1e6 1e-6")
    T = pick("0 0 0 0 1 0.25 1e3 1e6 1e9")
    TX = T * pick("1 0 -1"); TY = T * pick("0 1"); TZ = T * pick("1 0 0.5")
    image(pick("16 17 24"), pick("12 13 18"), pick("1 2 3 5"))
    printf "camera { perspective eye %s look_at %s up [0, 1, 0] fov %s }\n", W(r(-3, 3), r(0.5, 4), r(3, 7)), W(0, 0.5, 0), pick("40 60 90")
    print "ambient { color 0.05 }"
    fl = pick("box box plane none")
    if (fl == "box") printf "box { from %s to %s %s }\n", W(-4, -1, -4), W(4, 0, 4), mm()
    if (fl == "plane") printf "plane { point %s normal [0, 1, 0] %s }\n", W(0, 0, 0), mm()
    if (rand() < 0.3) printf "box { from %s to %s %s }\n", W(-4, 0, -4), W(-3.5, 3, 4), mm()
    n = ri(1, 10)
    for (i = 0; i < n; i++) {
        k = pick("sphere sphere box box tri mesh plane")
        x = ri(-6, 6) * 0.25; y = ri(0, 10) * 0.25; z = ri(-6, 6) * 0.25
        if (k == "sphere") printf "sphere { center %s radius %s %s }\n", W(x, y, z), pick("0.25 0.5 0.1 1") * S, mm()
        else if (k == "box") printf "box { from %s to %s %s }\n", W(x, y, z), W(x + pick("0.5 0.25 1 1e-3"), y + pick("0.5 0.25 2"), z + pick("0.5 0.25 1")), mm()
        else if (k == "tri") printf "triangle { vertices %s %s %s %s }\n", W(x, y, z), W(x + pick("0.5 1 -1"), y + pick("0 0.5"), z), W(x, y + pick("0.5 1"), z + pick("0.5 -0.5")), mm()
        else if (k == "plane") printf "plane { point %s normal %s %s }\n", W(x, y, z), pick("[1,0,0] [0,0,1] [1,1,0] [0,-1,0]"), mm()
        else printf "mesh { file \"%s\" %s%s scale %g translate %s }\n", pick("octa.obj fan.obj sheet.obj glass_cube.obj"), mm(), frame(0), pick("1 0.5 2 -1") * S, W(x, y, z)
    }
    nl = ri(1, 12)
    for (i = 0; i < nl; i++) {
        k = pick("in in grid corner far near")
        if (k == "in") p = W(r(-3, 3), r(0.1, 3), r(-3, 3))
        else if (k == "grid") p = W(ri(-8, 8) * 0.5, ri(0, 8) * 0.5, ri(-8, 8) * 0.5)
        else if (k == "corner") p = W(pick("-4 4"), pick("-1 0 3"), pick("-4 4"))
        else if (k == "far") p = W(r(-1, 1) * pick("1e3 1e6 1e8"), pick("1e3 1e6 1e8"), r(-1, 1) * pick("1e3 1e8"))
        else p = W(r(-2, 2), pick("1e-9 1e-12 0.001"), r(-2, 2))
        f = k == "far" ? pick("1e6 1e12 1e16") : 1
        printf "point_light { position %s power %g }\n", p, 10 * S * S * f
    }
    if (rand() < 0.2) printf "distributed_light { disk %s [0, -1, 0] %g power %g samples %s }\n", W(0, 3, 0), 0.5 * S, 10 * S * S, pick("4 9")
}
