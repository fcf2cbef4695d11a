# gen6.awk - a random scene of many axis-aligned boxes per BVH leaf under
# rectangle and disk lights (attack 19, [SHADE-SHORTCUT-BUNDLE-1]'s box
# parts and runs): grids and stacks of boxes touching each other and the
# light's plane, transparent boxes, lights among or inside the boxes, all
# moved by T and scaled by S.  awk -v seed=N -f ../attack18/common.awk -f common19.awk -f gen6.awk
function bm() {
    if (rand() < 0.3) return sprintf("material { Kd 0.3 Ks %s n 30 t %s ior %s }", pick("0 0.3"), pick("0.5 1 0.9 0.2"), pick("1 1.5"))
    return sprintf("material { Kd %s Ks %s n %s }", pick("0.8 0.5 0"), pick("0 0.2"), pick("20 1 1e4"))
}
function P(x, y, z) { return v(x * S + T, y * S, z * S) }
BEGIN {
    srand(seed)
    S = pick("1 1 1 1e-3 1e3 1e-6 1e5")
    T = pick("0 0 0 1e3 1e6 -1e8 0.1")
    printf "image { width %d height %d max_depth %d background [0.3, 0.5, 0.8] }\n", pick("20 21 24"), pick("15 16 18"), pick("1 2 3")
    ex = r(-3, 3); ey = r(0.5, 4); ez = r(3, 7)
    if (rand() < 0.2) printf "camera { orthographic eye %s look_at %s up [0, 1, 0] width %g }\n", P(ex, ey, ez), P(0, 0.5, 0), 5 * S
    else printf "camera { perspective eye %s look_at %s up [0, 1, 0] fov %s }\n", P(ex, ey, ez), P(0, 0.5, 0), pick("40 60 90")
    print "ambient { color 0.05 }"
    nl = ri(1, 3)
    for (i = 0; i < nl; i++) {
        h = pick("1 1 0.5 2 1.5 0.25 3")
        px = pick("0 0.5 -1 0.25 -0.25"); pz = pick("0 0.5 -0.5 0.25")
        eu = pick("1 0.5 0.25 2 1e-6")
        if (rand() < 0.6) printf "distributed_light { rectangle %s %s %s power %g samples %s }\n", P(px, h, pz), pick("[" eu * S ",0,0] [0," eu * S ",0] [" -eu * S ",0,0]"), v(0, 0, pick("1 0.5 -1") * S), 10 * S * S, pick("1 4 9 16 17 25")
        else printf "distributed_light { disk %s %s %g power %g samples %s }\n", P(px, h, pz), pick("[0,-1,0] [0,1,0] [1,0,0] [1,-1,0.3] [0,0,1]"), eu * S, 10 * S * S, pick("1 4 9 16 17")
    }
    if (rand() < 0.5) printf "plane { point %s normal [0, 1, 0] material { Kd 0.8 } }\n", P(0, 0, 0)
    n = ri(1, 6)
    for (i = 0; i < n; i++) {
        k = pick("grid grid stack wall ring")
        x = ri(-4, 4) * 0.25; y = ri(0, 4) * 0.25; z = ri(-4, 4) * 0.25
        w = pick("0.25 0.125 0.1 0.5"); g = pick("0 0 0.05 0.25")
        m = ri(2, 7)
        if (k == "grid") { for (a = 0; a < m; a++) for (b = 0; b < m; b++) printf "box { from %s to %s %s }\n", P(x + a * (w + g), y, z + b * (w + g)), P(x + a * (w + g) + w, y + w * pick("1 2 4"), z + b * (w + g) + w), bm() }
        else if (k == "stack") { for (a = 0; a < m; a++) printf "box { from %s to %s %s }\n", P(x, y + a * w, z), P(x + w, y + (a + 1) * w, z + w), bm() }
        else if (k == "wall") { for (a = 0; a < m * 3; a++) printf "box { from %s to %s %s }\n", P(x + a * 0.1, 0, z), P(x + a * 0.1 + 0.1, pick("0.5 1 2 3"), z + 0.05), bm() }
        else { for (a = 0; a < m * 2; a++) { ang = a * 6.2831853 / (m * 2); printf "box { from %s to %s %s }\n", P(cos(ang) - w / 2, y, sin(ang) - w / 2), P(cos(ang) + w / 2, y + w, sin(ang) + w / 2), bm() } }
    }
}
