# gen_nest.awk - attack 25g: [SHADE-SHORTCUT-GATHER-3] with ordinary
# cameras: world-frame glass balls nested 2 .. 5 deep (shells 0, 1e-12,
# 0.5 .. 2 slacks, 1e-3 apart), touching from inside (tangent), equal
# balls, apart balls nearly touching on a diagonal (boxes overlap), tiny
# balls (1e-9 .. 1e-6) on a big one's shell, centres moved to 1e6 .. 2^400,
# radius scale 2^-400 .. 2^400; a floor plane; mixed iors and t.
# awk -v seed=N -f ../attack18/common.awk -f ../attack19/common19.awk -f gen_nest.awk
function gm() { return sprintf("material { Kd %s Ks %s n 30 t %s ior %s }", pick("0 0 0.2"), pick("0 0.05 0.5"), pick("1 0.95 0.5 0.9"), pick("1.5 1 1.33 1.9 2.4 0.8")) }
function slack(c, R, rr) { return 2 ^ -18 * (c + R + c + rr) / 2 + 2 ^ -30 * (2 * c + R + rr) }
function ball(x, y, z, rad) { printf "sphere { center %s radius %.17g %s }\n", v(T + x * S, T + y * S, T + z * S), rad * S, (rand() < 0.85 ? gm() : "material { Kd 0.6 Ks 0.2 n 20 }") }
BEGIN {
    srand(seed)
    S = 2 ^ pick("0 0 0 0 -10 10 -400 400 -30")
    T = pick("0 0 0 0 1e6 1 -3") * S
    if (rand() < 0.1) T = 2 ^ 400
    image(pick("24 32"), pick("16 24"), pick("3 5 8"))
    printf "camera { perspective eye %s look_at %s up [0, 1, 0] fov %s }\n", v(T + r(-2, 2) * S, T + r(0.5, 3) * S, T + r(3, 6) * S), v(T, T + 0.5 * S, T), pick("30 45 60")
    print "ambient { color 0.1 }"
    printf "point_light { position %s power %s }\n", v(T + 3 * S, T + 6 * S, T + 4 * S), 40 * S * S
    if (rand() < 0.6) printf "plane { point %s normal [0, 1, 0] material { Kd 0.8 } }\n", v(0, T - 1 * S, 0)
    nb = ri(1, 3)
    for (b = 0; b < nb; b++) {
        x = r(-1, 1); y = r(0, 1); z = r(-1, 1)
        R = pick("1 0.5 0.25")
        ball(x, y, z, R)
        k = pick("nest nest nest touch equal apart tiny deep")
        cS = (T > 0 ? T / S : 0) + 2
        if (k == "nest" || k == "deep") {
            m = k == "deep" ? ri(3, 5) : 1
            rr = R
            for (i = 0; i < m; i++) {
                g = pick("0 1e-12 0.5 0.9 1.1 2 4 1e3") * slack(cS, rr, rr)
                off = rand() < 0.3 ? g * r(0, 0.5) : 0
                rr = rr - g - off
                if (rr <= 0) break
                ball(x + off, y, z, rr)
            }
        } else if (k == "touch") {
            rr = R * pick("0.5 0.9 0.999")
            ball(x + (R - rr) * pick("1 1 0.999999 1.000001"), y, z, rr)
        } else if (k == "equal") {
            ball(x, y, z, R)
        } else if (k == "apart") {
            rr = R * pick("1 0.5")
            D = (R + rr + pick("0 0.5 1.1 2 8") * slack(cS, R, rr)) / sqrt(3)
            ball(x + D, y + D, z + D, rr)
        } else {
            rr = pick("1e-9 1e-6 1e-3")
            ball(x + R + rr * pick("1 1.5 -1 -1.5 3"), y, z, rr)
        }
    }
}
