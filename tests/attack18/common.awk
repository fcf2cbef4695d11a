# common.awk - the helpers of gen.awk and gen2.awk (attack 18): random
# numbers, picks, vectors and materials.  awk -f common.awk -f gen.awk
function r(a, b) { return a + (b - a) * rand() }
function ri(a, b) { return a + int((b - a + 1) * rand()) }
function pick(s,   n, a) { n = split(s, a, " "); return a[ri(1, n)] }
function v(x, y, z) { return sprintf("[%.17g, %.17g, %.17g]", x, y, z) }
# Transparent with probability p (an ior from iors), else opaque with Kd
# below kd and Ks below ks.
function material(p, iors, kd, ks) {
    if (rand() < p) return sprintf("material { Kd %.3g Ks %.3g n %d t %.3g ior %s }", r(0, 0.3), r(0, 0.4), ri(1, 80), r(0.3, 1), pick(iors))
    return sprintf("material { Kd %.3g Ks %.3g n 20 }", r(0.2, kd), r(0, ks))
}
