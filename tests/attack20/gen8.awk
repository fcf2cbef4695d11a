# gen8.awk - a random scene for [SHADE-SHORTCUT-BUNDLE-1]'s triangles
# (attack 20): meshes (closed octahedron, bipyramid fan, glass cube,
# geosphere; an open lattice sheet), opaque and transparent, turned, scaled
# (mirrored too) and moved, many to a leaf; lone triangles with corners and
# edges on the lights' lattice; rectangle lights flat on an axis, slanted
# (|dx| = |dz|), point-like, and disks; everything scaled 1e-6 .. 1e6.
# awk -v seed=N -f ../attack18/common.awk -f ../attack19/common19.awk -f gen8.awk
function mm() { return mixed_material(0.35, "0 0.3", "0.5 1 0.9", "1 1 1.5", "0.8 0.5", "0 0.2", "20 1") }
BEGIN {
    srand(seed)
    S = pick("1 1 1 1 1e-3 1e3 1e6 1e-6")
    image(pick("16 17 12"), pick("12 13 9"), pick("1 2 3"))
    ex = r(-3, 3) * S; ey = r(0.5, 4) * S; ez = r(3, 7) * S
    printf "camera { perspective eye %s look_at %s up [0, 1, 0] fov %s }\n", v(ex, ey, ez), v(0, 0.5 * S, 0), pick("40 60 90")
    print "ambient { color 0.05 }"
    nl = ri(1, 2)
    for (i = 0; i < nl; i++) {
        px = pick("0 0.5 1 -1 0.25") * S; py = pick("1 2 3 0.75 1.5") * S; pz = pick("0 0.5 -0.5 0.25") * S
        k = pick("flat flat slant point disk any")
        if (k == "flat") printf "distributed_light { rectangle %s %s %s power %g samples %s }\n", v(px, py, pz), (fa = rand() < 0.5) ? pick("[" S ",0,0] [" 0.5 * S ",0,0]") : pick("[0,0," S "] [0," 0.25 * S ",0]"), fa ? pick("[0,0," S "] [0,0," 0.25 * S "] [0," S ",0]") : "[" S ",0,0]", 10 * S * S, pick("1 4 9 16 17")
        else if (k == "slant") printf "distributed_light { rectangle %s %s %s power %g samples %s }\n", v(px, py, pz), v(S, 0, pick("1 -1") * S), v(0, 0.5 * S, 0), 10 * S * S, pick("4 9 16")
        else if (k == "point") printf "distributed_light { rectangle %s %s %s power %g samples %s }\n", v(px, py, pz), v(1e-9 * S, 0, 0), v(0, 0, 1e-9 * S), 10 * S * S, pick("1 4 9")
        else if (k == "disk") printf "distributed_light { disk %s %s %g power %g samples %s }\n", v(px, py, pz), pick("[0,-1,0] [1,-1,0.3] [1,0,1] [0,0,1]"), pick("0.25 0.5 1e-6 1") * S, 10 * S * S, pick("1 4 9 16 17")
        else printf "distributed_light { rectangle %s %s %s power %g samples %s }\n", v(px, py, pz), v(r(-1, 1) * S, r(-1, 1) * S, r(-1, 1) * S), v(r(-1, 1) * S, r(-1, 1) * S, r(-1, 1) * S), 10 * S * S, pick("4 9 16")
    }
    if (rand() < 0.3) printf "point_light { position %s power %g }\n", v(r(-3, 3) * S, 4 * S, r(-3, 3) * S), 10 * S * S
    if (rand() < 0.5) printf "plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0.8 } }\n"
    n = ri(1, 8)
    for (i = 0; i < n; i++) {
        k = pick("octa octa fan sheet sheet cube geo tri tri")
        x = ri(-4, 4) * 0.25; y = ri(0, 8) * 0.25; z = ri(-4, 4) * 0.25
        sc = pick("1 1 0.5 2 -1 0.25")
        if (k == "tri") {
            m = ri(1, 12)
            for (a = 0; a < m; a++) {
                a0 = ri(-2, 2); a1 = ri(0, 4); a2 = ri(-2, 2); b0 = ri(-2, 2); b1 = ri(-1, 4); b2 = 2; c0 = 2; c1 = ri(0, 4); c2 = ri(-2, 2)
                u0 = b0 - a0; u1 = b1 - a1; u2 = b2 - a2; w0 = c0 - a0; w1 = c1 - a1; w2 = c2 - a2
                if (u1 * w2 - u2 * w1 == 0 && u2 * w0 - u0 * w2 == 0 && u0 * w1 - u1 * w0 == 0) continue   # no area: refused
                printf "triangle { vertices %s %s %s %s }\n", v((x + a0 * 0.25) * S, (y + a1 * 0.25) * S, (z + a2 * 0.25) * S), v((x + b0 * 0.25) * S, (y + b1 * 0.25) * S, (z + b2 * 0.25) * S), v((x + c0 * 0.25) * S, (y + c1 * 0.25) * S, (z + c2 * 0.25) * S), mm()
            }
            continue
        }
        f = k == "octa" ? "octa.obj" : k == "fan" ? "fan.obj" : k == "sheet" ? "sheet.obj" : k == "cube" ? "glass_cube.obj" : "geosphere.obj"
        if (k == "geo") sc = 0.25 * sc
        printf "mesh { file \"%s\" %s%s scale %g translate %s }\n", f, mm(), frame(0), sc * S, v(x * S, y * S, z * S)
    }
}
