# gen_apart.awk - attack 25g: [SHADE-SHORTCUT-GATHER-3] where its premise
# (a hit point lies within e = 2^-20 (|c|max + R) of its sphere) fails:
# world-frame glass spheres far from the origin (C = 2^Ck: e ~ 2^-20 C),
# apart along a diagonal (their padded boxes overlap, so boxes_apart keeps
# them neighbours and only spheres_apart leaves them out) or nested, their
# gap 1.01 .. 1.5 times the slack, seen by an orthographic camera at
# 2^35 .. 2^38 C along the line of the centres: o + t d rounds at ulp(L),
# several slacks, so both spheres' first solves can round to one t and
# sphere_refine's second solve miss both (the point is o2 for both).
# awk -v seed=N -f ../attack18/common.awk -f ../attack19/common19.awk -f gen_apart.awk
BEGIN {
    srand(seed)
    Ck = ri(10, 24)
    C = 2 ^ Ck
    e = 2 ^ -20 * C
    S = 4 * e                                  # about the slack
    R = S * pick("0.25 0.5 1 2 4 8")
    kind = pick("apart apart nested")
    # direction of the centres: near the diagonal
    dx = 1 + r(-0.2, 0.2); dy = 1 + r(-0.2, 0.2); dz = 1 + r(-0.2, 0.2)
    n = sqrt(dx*dx + dy*dy + dz*dz); dx /= n; dy /= n; dz /= n
    if (kind == "apart") {
        rr = R * pick("1 0.5 2")
        D = R + rr + S * pick("1.01 1.05 1.1 1.3 1.5") * (1 + 2 ^ -10)
    } else {
        rr = R - S * pick("1.01 1.05 1.1 1.3 1.5") * (1 + 2 ^ -10)
        if (rr <= 0) { R = 16 * S; rr = R - 1.05 * S }
        D = 0
        if (rand() < 0.3) { D = S * 0.1; rr -= D }
    }
    ox = C + D * dx; oy = C + D * dy; oz = C + D * dz
    L = 2 ^ (Ck + ri(34, 38)) * r(1, 2)
    # the camera looks along the centres' line (off by a little)
    ex = dx + r(-0.05, 0.05); ey = dy + r(-0.05, 0.05); ez = dz + r(-0.05, 0.05)
    n = sqrt(ex*ex + ey*ey + ez*ez); ex /= n; ey /= n; ez /= n
    W = 2 ^ -52 * L * pick("4 8 16 32") + 2 * (R + rr + D)
    printf "image { width 64 height 64 max_depth %d background [0.3, 0.5, 0.8] }\n", pick("2 3 5")
    printf "camera { orthographic width %.17g eye %s look_at %s up [0, 1, 0] }\n", W, v(C - L * ex, C - L * ey, C - L * ez), v(C + D * dx / 2, C + D * dy / 2, C + D * dz / 2)
    print "ambient { color 0.1 }"
    printf "point_light { position %s power 40 }\n", v(C, C + 10 * R, C)
    printf "sphere { center %s radius %.17g material { Kd 0 Ks 0.05 n 30 t 0.95 ior 1.5 } }\n", v(C, C, C), R
    printf "sphere { center %s radius %.17g material { Kd 0 Ks 0.1 n 30 t %s ior %s } }\n", v(ox, oy, oz), rr, pick("0.9 0.5 1"), pick("1.9 1.0 1.5")
}
