# gen15.awk - attack 24h: random scenes for [SHADE-SHORTCUT-HIDDEN-1] (a
# Kd = 0 point's light loop left out where a bound on its highlight cannot
# change its colour).  Kd 0 mirrors (t 0, -0 and small t) and glass (t 1,
# 0.05 .. 0.9, nested) with n 0, 0.5, 1, 1.5, 30 .. 1048576 and Ks per
# channel (one channel 0, 1e-300, 1); backgrounds black, dim or bright; 1 ..
# 9 lights: point lights with d0 0 / tiny / large and the three falloffs,
# at the surface (1e-9 .. 1e-3 off it: balls that nearly touch the point),
# far away, powers 0 .. 1e300; distant lights at grazing angles; disks of
# radius 1e-6 .. 2 with 1 .. 64 samples; rectangles long and thin (1e-6 x
# 5, slanted, parallelograms); smooth meshes (sphere_12x8.obj); scale 1e-6
# .. 1e6 moved up to 1e8; max_depth 1 .. 6.
# awk -v seed=N -f tests/attack18/common.awk -f tests/attack19/common19.awk -f gen15.awk
function W(x, y, z) { return v(TX + x * S, TY + y * S, TZ + z * S) }
function col(s) { return rand() < 0.6 ? pick(s) : "[" pick(s) ", " pick(s) ", " pick(s) "]" }
# a colour of channels picked from s, each times f
function colf(s, f) { return rand() < 0.6 ? pick(s) * f : "[" pick(s) * f ", " pick(s) * f ", " pick(s) * f "]" }
function nn() { return pick("0 0.5 1 1 1.5 2 7.25 30 300 1000 1e4 1e5 1e6 1048575 1048576 1048576") }
function mm(   k) {
    k = pick("mirror mirror glass glass weak lam")
    if (k == "mirror") return sprintf("material { Kd 0 Ks %s n %s t %s }", col("1 1 0.5 0 1e-300 0.999"), nn(), pick("0 0 -0 0.3"))
    if (k == "glass") return sprintf("material { Kd 0 Ks %s n %s t %s ior %s }", col("1 0.5 0.04 0"), nn(), pick("1 1 0.9 0.5"), pick("1.5 1 1.33 2.4 0.7"))
    if (k == "weak") return sprintf("material { Kd 0 Ks %s n %s t %s ior %s }", col("0.9 1 0.1"), nn(), pick("0.05 0.01 1"), pick("1.5 1"))
    return sprintf("material { Kd %s Ks %s n %s }", col("0.8 0.3"), pick("0 0.3"), pick("1 20"))
}
function light(   k, p, f) {
    k = pick("point point near near far distant graze disk disk tiny rect thin")
    f = rand() < 0.4 ? sprintf(" d0 %s falloff %s", pick("0 0 1e-300 1e-9 1 100") * S, pick("linear inverse_square none")) : ""
    if (k == "point") p = W(r(-3, 3), r(0.5, 4), r(-3, 3))
    else if (k == "near") { split(P[ri(0, NP - 1)], q, " "); p = W(q[1] + pick("0 1e-9 1e-6"), q[2] + q[4] + pick("1e-9 1e-6 1e-3 0"), q[3]) }
    else if (k == "far") p = W(r(-1, 1) * 1e6, 1e6, r(-1, 1) * 1e6)
    if (k == "point" || k == "near" || k == "far")
        return sprintf("point_light { position %s power %s%s }", p, colf("0 1e-12 1 10 10 1e3 1e3 1e12 1e300", S * S * (k == "far" ? 1e12 : 1)), f)
    if (k == "distant") return sprintf("distant_light { direction %s power %s }", pick("[0,-1,0] [1,-1,0] [0.3,-1,0.2] [0,1,0]"), col("1 1e-9 1e6 1e300"))
    if (k == "graze") return sprintf("distant_light { direction %s power %s }", pick("[1,-1e-9,0] [1,-1e-3,0.2] [0,-0.01,1] [-1,-1e-15,0]"), col("1 1e6"))
    if (k == "disk" || k == "tiny")
        return sprintf("distributed_light { disk %s %s %s power %s samples %s%s }", W(r(-2, 2), r(1, 4), r(-2, 2)), pick("[0,-1,0] [1,-1,0.3] [0,0,1]"), (k == "tiny" ? pick("1e-6 1e-3 0.001") : pick("0.1 0.5 2")) * S, colf("1 10 100 1e6", S * S), pick("1 4 9 16 36 64"), f)
    if (k == "rect")
        return sprintf("distributed_light { rectangle %s %s %s power %s samples %s%s }", W(r(-2, 2), r(1, 4), r(-2, 2)), v(S, 0, 0), v(0, 0, S), colf("1 10 100 1e6", S * S), pick("1 4 9 16"), f)
    return sprintf("distributed_light { rectangle %s %s %s power %s samples %s%s }", W(r(-2, 2), r(1, 4), r(-2, 2)), v(pick("5 3 -4") * S, pick("0 1e-3") * S, 0), v(pick("1e-6 1e-3 0.01") * S, 0, pick("1e-6 1e-9 0.5") * S), colf("1 10 100 1e6", S * S), pick("1 4 9 16 25"), f)
}
BEGIN {
    srand(seed)
    S = pick("1 1 1 1 0.5 1e-3 1e3 1e6 1e-6")
    T = pick("0 0 0 0 1 1e3 1e6 1e8")
    TX = T * pick("1 0 -1"); TY = T * pick("0 1"); TZ = T * pick("1 0 0.5")
    printf "image { width %d height %d max_depth %d background %s }\n", pick("16 17 24"), pick("12 13"), pick("1 2 3 4 6"), pick("[0,0,0] [0,0,0] [0.1,0.1,0.1] [0.3,0.5,0.8] [1e-300,0,1]")
    printf "camera { perspective eye %s look_at %s up [0, 1, 0] fov %s }\n", W(r(-3, 3), r(0.5, 4), r(3, 7)), W(0, 0.5, 0), pick("40 60 90")
    print "ambient { color " pick("0.05 0 0 [0,0.1,0]") " }"
    fl = pick("box plane plane none")
    if (fl == "box") printf "box { from %s to %s %s }\n", W(-4, -1, -4), W(4, 0, 4), mm()
    if (fl == "plane") printf "plane { point %s normal [0, 1, 0] %s }\n", W(0, 0, 0), mm()
    if (rand() < 0.4) {
        printf "sphere { center %s radius %s %s }\n", W(0, 1, 0), 1 * S, "material { Kd 0 Ks 0.5 n " nn() " t 0.9 ior 1.5 }"
        printf "sphere { center %s radius %s %s }\n", W(0, 1, 0), 0.5 * S, "material { Kd 0 Ks 1 n " nn() " t 1 ior 1.3 }"
    }
    NP = ri(1, 8)
    for (i = 0; i < NP; i++) {
        k = pick("sphere sphere box tri mesh smooth disk cyl")
        x = ri(-6, 6) * 0.25; y = ri(0, 8) * 0.25; z = ri(-6, 6) * 0.25; h = 0.5
        if (k == "sphere") { h = pick("0.25 0.5 0.1 1"); printf "sphere { center %s radius %s %s }\n", W(x, y, z), h * S, mm(); }
        else if (k == "box") printf "box { from %s to %s %s }\n", W(x, y, z), W(x + 0.5, y + 0.5, z + 0.5), mm()
        else if (k == "tri") printf "triangle { vertices %s %s %s %s }\n", W(x, y, z), W(x + 1, y, z), W(x, y + 1, z + 0.5), mm()
        else if (k == "disk") printf "disk { center %s normal %s radius %g %s }\n", W(x, y, z), pick("[0,1,0] [1,0,0] [1,2,3]"), 0.5 * S, mm()
        else if (k == "cyl") printf "cylinder { from %s to %s radius %g %s }\n", W(x, y, z), W(x, y + 1, z), 0.3 * S, mm()
        else if (k == "smooth") printf "mesh { file \"sphere_12x8.obj\" %s scale %g translate %s }\n", mm(), 0.5 * S, W(x, y, z)
        else printf "mesh { file \"%s\" %s scale %g translate %s }\n", pick("octa.obj geosphere.obj glass_cube.obj"), mm(), 0.5 * S, W(x, y, z)
        P[i] = x " " y " " z " " h
    }
    nl = ri(1, 9)
    for (i = 0; i < nl; i++) print light()
}
