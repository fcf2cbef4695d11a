# gen7.awk - a random scene of Kd = 0 surfaces (glass and bare mirrors)
# with extreme Phong exponents under distributed and point lights (attack
# 19: the lobe floors made once a material, [SHADE-SHORTCUT-LOBE-2], the
# flattened light sample, the TIR shortcut's keyed bail-out).
# awk -v seed=N -f ../attack18/common.awk -f common19.awk -f gen7.awk
function km() {
    return glassy(pick("0 0 0 0.2"), pick("0.3 1 0.05 0"), pick("0 5e-324 1e-300 1e-3 1 30 300 1e5 1e300 1030 0.5"),
                  pick("0 0 0.5 1 0.9"), pick("1 1.5 2.4"))
}
BEGIN {
    srand(seed)
    S = pick("1 1 1 1e-3 1e3")
    image(pick("20 24"), pick("15 18"), pick("1 2 3 4"))
    printf "camera { perspective eye %s look_at %s up [0, 1, 0] fov %s }\n", v(r(-3, 3) * S, r(0.5, 4) * S, r(3, 6) * S), v(0, 0.5 * S, 0), pick("40 60")
    if (rand() < 0.5) print "ambient { color 0.1 }"
    nl = ri(1, 3)
    for (i = 0; i < nl; i++) {
        k = pick("rect disk point distant")
        if (k == "rect") printf "distributed_light { rectangle %s %s %s power %g samples %s }\n", v(r(-2, 1) * S, r(1, 4) * S, r(-2, 1) * S), v(pick("1 0.1 3") * S, 0, 0), v(0, pick("0 0.5") * S, pick("1 0.1") * S), 20 * S * S, pick("1 4 16 64 130")
        else if (k == "disk") printf "distributed_light { disk %s %s %g power %g samples %s }\n", v(r(-2, 2) * S, r(1, 4) * S, r(-2, 2) * S), pick("[0,-1,0] [1,-1,0] [0,1,0]"), pick("0.1 1 2") * S, 20 * S * S, pick("1 4 16 64")
        else if (k == "point") printf "point_light { position %s power %g }\n", v(r(-3, 3) * S, r(1, 5) * S, r(-3, 3) * S), 20 * S * S
        else printf "distant_light { direction %s power 0.5 }\n", v(r(-1, 1), -1, r(-1, 1))
    }
    if (rand() < 0.7) printf "plane { point [0, 0, 0] normal [0, 1, 0] %s }\n", (rand() < 0.5 ? "material { Kd 0.7 }" : km())
    n = ri(1, 12)
    for (i = 0; i < n; i++) {
        k = pick("sph box mesh cyl tor tri")
        x = ri(-2, 2) * 0.6; y = ri(0, 2) * 0.5; z = ri(-2, 2) * 0.6
        if (k == "sph") printf "sphere { center %s radius %g %s }\n", v(x * S, (y + 0.5) * S, z * S), pick("0.5 0.3") * S, km()
        else if (k == "box") printf "box { from %s to %s %s }\n", v(x * S, y * S, z * S), v((x + 0.5) * S, (y + 0.5) * S, (z + 0.5) * S), km()
        else if (k == "mesh") printf "mesh { file \"glass_cube.obj\" %s scale %g translate %s }\n", km(), 0.4 * S, v(x * S, (y + 0.4) * S, z * S)
        else if (k == "cyl") printf "cylinder { from %s to %s radius %g %s }\n", v(x * S, y * S, z * S), v(x * S, (y + 1) * S, z * S), 0.3 * S, km()
        else if (k == "tor") printf "torus { major %g minor %g %s translate %s }\n", 0.4 * S, 0.1 * S, km(), v(x * S, (y + 0.2) * S, z * S)
        else printf "triangle { vertices %s %s %s %s }\n", v(x * S, y * S, z * S), v((x + 1) * S, y * S, z * S), v(x * S, (y + 1) * S, z * S), km()
    }
}
