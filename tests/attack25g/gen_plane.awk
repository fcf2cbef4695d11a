# gen_plane.awk - attack 25g: [NUM-PLANE-AWAY-1] in the nearest walk.
# World-frame planes seen edge-on (the eye on the plane, exactly or 1e-300
# .. 1e-9 off it), from behind, with extreme normals ([1, 1e-300, 0]-like,
# checked unit by the loader), points near 2^500 or 1e8, a plane tied with
# a box face, a triangle or a second plane at the same place (the tie
# window, [BVH-TIE-ORDER-1]), mirror and glass floors that send rays away
# from them, glass balls resting on the floor (rays inside moving up), and
# framed planes (rotate/translate kept) for contrast.
# awk -v seed=N -f ../attack18/common.awk -f ../attack19/common19.awk -f gen_plane.awk
function mat() { return pick("mirror glass lam lam") }
function nrm() { return pick("[0,1,0] [0,1,0] [0,-1,0] [1,1e-300,0] [1e-17,1,0] [0.6,0.8,0] [1,1,1] [-0,1,-0] [1e-9,1,1e-9] [0,1,1e-16]") }
BEGIN {
    srand(seed)
    print "material mirror { Kd 0.1 Ks 0.8 n 40 }"
    print "material glass { Kd 0 Ks 0.1 n 30 t 0.9 ior 1.5 }"
    print "material lam { Kd 0.7 Ks 0.1 n 10 }"
    Y = pick("0 0 0 1 1e8 -3 1e-300 2.5")
    image(pick("24 32 17"), pick("16 24 13"), pick("1 2 3 5"))
    ek = pick("on on near above below far")
    ey = ek == "on" ? Y : ek == "near" ? Y + pick("1e-300 -1e-300 1e-9 -1e-9 1e-16") : ek == "above" ? Y + 2 : ek == "below" ? Y - 2 : Y + 1e6
    printf "camera { %s eye %s look_at %s up [0, 1, 0]%s }\n", rand() < 0.7 ? "perspective fov " pick("40 90 150") : "orthographic width " pick("4 1e-6 100"), v(r(-1, 1), ey, 5 + r(0, 2)), v(0, Y + pick("0 0 1 -1 1e-9"), 0), ""
    print "ambient { color 0.1 }"
    printf "point_light { position %s power 40 }\n", v(r(-3, 3), Y + pick("3 -3 0 1e-9"), r(-3, 3))
    if (rand() < 0.5) printf "distant_light { direction %s power 0.5 }\n", pick("[0,-1,0] [0,1,0] [1,0,0] [1,-1e-9,0]")
    np = ri(1, 4)
    for (i = 0; i < np; i++) {
        k = pick("plain plain tied framed")
        n = nrm()
        yy = Y + (i == 0 ? 0 : pick("0 0 1 -1 1e-300 2"))
        if (k == "framed") printf "plane { point %s normal %s material %s%s }\n", v(0, yy, 0), n, mat(), " rotate " v(pick("0 90 45"), 0, pick("0 30")) " translate " v(0, pick("0 0.5"), 0)
        else printf "plane { point %s normal %s material %s }\n", v(pick("0 0 3 1e8 -1e150"), yy, pick("0 0 -2 1e150")), n, mat()
        if (k == "tied") {
            t = pick("box tri plane")
            if (t == "box") printf "box { from %s to %s material %s }\n", v(-1, yy - 1, -1), v(1, yy, 1), mat()
            else if (t == "tri") printf "triangle { vertices %s %s %s material %s }\n", v(-3, yy, -3), v(3, yy, -3), v(0, yy, 4), mat()
            else printf "plane { point %s normal %s material %s }\n", v(1, yy, 1), pick("[0,1,0] [0,-1,0]"), mat()
        }
    }
    nb = ri(0, 4)
    for (i = 0; i < nb; i++) {
        rad = pick("0.5 1 0.25 1e-3")
        printf "sphere { center %s radius %s material %s }\n", v(r(-2, 2), Y + rad * pick("1 1 -1 0 1.000001"), r(-2, 2)), rad, mat()
    }
}
