# gen_graze.awk - attack 25g: two concentric (or nearly) world-frame glass
# spheres whose shells are just wider apart than spheres_apart's slack,
# seen at the limb by an orthographic camera very far away (|eye| ~ L), so
# that the first solve's hit points (o + t d, rounded at ulp(L)) are off
# the shells by more than glass_near's 2^-20 pad and sphere_refine's second
# solve can miss (point = o2).  seed % 1000 picks L, the gap (in slacks),
# the view direction and the zoom; seed / 1000 the variant:
#   0: L at 2^30..2^44 R, a view of a few gaps, 48 or 64 pixels a side;
#   1: L at 2^42..2^47 R (ulp(L) near the limb annulus where both spheres'
#      first-solve t round alike), a view of 2..16 ulp(L), 96 x 96 pixels;
#   2: as 1, the inner sphere first (it wins the tie of equal t, so the
#      gather runs on it and the outer one is the neighbour whose shell o2
#      may lie just outside of);
#   3: as 1, plus 8 .. 11 small balls well inside (nested, so
#      [SHADE-SHORTCUT-GATHER-3] drops them from the lists: at 34a5772 they
#      made the two shells' lists longer than GATHER_NEAR_MAX, no hit on
#      them was ever alone, and the gather walked the tree).
# (The round's README named variants 1-3 gen_graze2..4 with seeds 1..999.)
# awk -v seed=N -f ../attack18/common.awk -f gen_graze.awk
function outer_sphere() {
    printf "sphere { center %s radius %.17g material { Kd 0 Ks 0.05 n 30 t 0.95 ior 1.5 } }\n", v(C, C, C), R
}
BEGIN {
    variant = int(seed / 1000)
    srand(seed % 1000)
    R = pick("1 1 1 0.5 2 1e-3 1e3")
    C = pick("0 0 0 0 1 1e3")
    g = pick("1.01 1.05 1.2 1.5 2 4 8") * 4.0000001 * R * 2 ^ -20
    if (rand() < 0.3) g = pick("1.01 1.1 2") * 4.0000001 * (R + C) * 2 ^ -20
    Lk = variant ? ri(42, 47) : ri(30, 44)
    L = 2 ^ Lk * R * r(1, 2)
    # view direction: a random unit vector, not near an axis
    do { dx = r(-1, 1); dy = r(-1, 1); dz = r(-1, 1); n = sqrt(dx*dx + dy*dy + dz*dz) } while (n < 0.3 || n > 1)
    dx /= n; dy /= n; dz /= n
    # a unit vector u perpendicular to d: the limb direction
    ax = 0; ay = 1; az = 0
    if (dy * dy > 0.8) { ax = 1; ay = 0 }
    ux = ay * dz - az * dy; uy = az * dx - ax * dz; uz = ax * dy - ay * dx
    n = sqrt(ux*ux + uy*uy + uz*uz); ux /= n; uy /= n; uz /= n
    rho = variant ? R - 2 ^ (Lk - 52) * R * r(0, 4) : R - g * r(0, 3)
    px = C + rho * ux; py = C + rho * uy; pz = C + rho * uz
    if (variant) {
        W = 2 ^ (Lk - 52) * R * pick("2 4 8 16")
        width = height = 96
    } else {
        W = g * pick("4 8 16 64") + 2 ^ (Lk - 52) * R * 4
        width = pick("48 64"); height = pick("48 64")
    }
    printf "image { width %d height %d max_depth %d background [0.3, 0.5, 0.8] }\n", width, height, pick("2 4 6")
    printf "camera { orthographic width %.17g eye %s look_at %s up %s }\n", W, v(px - L * dx, py - L * dy, pz - L * dz), v(px, py, pz), v(ux, uy, uz)
    print "ambient { color 0.1 }"
    print "point_light { position [3, 6, 4] power 40 }"
    if (variant != 2)
        outer_sphere()
    oc = C + (rand() < 0.3 ? g * 0.25 : 0)
    printf "sphere { center %s radius %.17g material { Kd 0 Ks 0.1 n 30 t 0.9 ior %s } }\n", v(oc, C, C), R - g - (oc - C), pick("1.9 1.0 2.4")
    if (variant == 2)
        outer_sphere()
    if (rand() < 0.5) printf "sphere { center %s radius %.17g material { Kd 0.5 Ks 0 n 30 } }\n", v(C, C, C), (R - g) * 0.5
    if (variant == 3) {
        nk = ri(8, 11)
        for (k = 0; k < nk; k++)
            printf "sphere { center %s radius %.17g material { Kd 0.5 Ks 0.2 n 30%s } }\n", v(C + (k % 3 - 1) * R * 0.3, C + (int(k / 3) % 3 - 1) * R * 0.3, C + (k >= 9 ? R * 0.3 : 0)), R * 0.1, (k % 2 ? " t 0.5 ior 1.2" : "")
    }
}
