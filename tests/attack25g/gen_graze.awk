# gen_graze.awk - attack 25g: two concentric (or nearly) world-frame glass
# spheres whose shells are just wider apart than spheres_apart's slack,
# seen at the limb by an orthographic camera very far away (|eye| ~ L), so
# that the first solve's hit points (o + t d, rounded at ulp(L)) are off
# the shells by more than glass_near's 2^-20 pad and sphere_refine's second
# solve can miss (point = o2).  seed picks L, the gap (in slacks), the view
# direction and the zoom.  awk -v seed=N -f ../attack18/common.awk -f gen_graze.awk
BEGIN {
    srand(seed)
    R = pick("1 1 1 0.5 2 1e-3 1e3")
    C = pick("0 0 0 0 1 1e3")
    g = pick("1.01 1.05 1.2 1.5 2 4 8") * 4.0000001 * R * 2 ^ -20
    if (rand() < 0.3) g = pick("1.01 1.1 2") * 4.0000001 * (R + C) * 2 ^ -20
    Lk = ri(30, 44)
    L = 2 ^ Lk * R * r(1, 2)
    # view direction: a random unit vector, not near an axis
    do { dx = r(-1, 1); dy = r(-1, 1); dz = r(-1, 1); n = sqrt(dx*dx + dy*dy + dz*dz) } while (n < 0.3 || n > 1)
    dx /= n; dy /= n; dz /= n
    # a unit vector u perpendicular to d: the limb direction
    ax = 0; ay = 1; az = 0
    if (dy * dy > 0.8) { ax = 1; ay = 0 }
    ux = ay * dz - az * dy; uy = az * dx - ax * dz; uz = ax * dy - ay * dx
    n = sqrt(ux*ux + uy*uy + uz*uz); ux /= n; uy /= n; uz /= n
    rho = R - g * r(0, 3)
    px = C + rho * ux; py = C + rho * uy; pz = C + rho * uz
    W = g * pick("4 8 16 64") + 2 ^ (Lk - 52) * R * 4
    printf "image { width %d height %d max_depth %d background [0.3, 0.5, 0.8] }\n", pick("48 64"), pick("48 64"), pick("2 4 6")
    printf "camera { orthographic width %.17g eye %s look_at %s up %s }\n", W, v(px - L * dx, py - L * dy, pz - L * dz), v(px, py, pz), v(ux, uy, uz)
    print "ambient { color 0.1 }"
    print "point_light { position [3, 6, 4] power 40 }"
    printf "sphere { center %s radius %.17g material { Kd 0 Ks 0.05 n 30 t 0.95 ior 1.5 } }\n", v(C, C, C), R
    oc = C + (rand() < 0.3 ? g * 0.25 : 0)
    printf "sphere { center %s radius %.17g material { Kd 0 Ks 0.1 n 30 t 0.9 ior %s } }\n", v(oc, C, C), R - g - (oc - C), pick("1.9 1.0 2.4")
    if (rand() < 0.5) printf "sphere { center %s radius %.17g material { Kd 0.5 Ks 0 n 30 } }\n", v(C, C, C), (R - g) * 0.5
}
