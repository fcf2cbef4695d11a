# common19.awk - helpers of the attack 19 generators (after
# ../attack18/common.awk): kept-frame transforms (each of scale, rotate and,
# with moves, translate with probability 0.3), a transparent material from
# its five values, and the image line.
function frame(moves,   s, k) {
    s = ""
    for (k = 1; k <= (moves ? 3 : 2); k++)
        if (rand() < 0.3) s = s transform(k)
    return s
}
function transform(k) {
    if (k == 1) return " scale " (rand() < 0.5 ? pick("2 0.5 1e-3 1e3 -1") : v(pick("1 2 0.5 -1"), pick("1 3 0.5"), pick("1 -2")))
    if (k == 2) return " rotate " v(pick("0 90 45 30 180"), pick("0 90 45 17"), pick("0 90 60"))
    return " translate " v(pick("0 1 0.5"), pick("0 1 -1"), pick("0 0.25 2"))
}
function glassy(kd, ks, n, t, ior) { return sprintf("material { Kd %s Ks %s n %s t %s ior %s }", kd, ks, n, t, ior) }
function image(w, h, depth) { printf "image { width %d height %d max_depth %d background [0.3, 0.5, 0.8] }\n", w, h, depth }
# A material, glass with probability pg (its Ks, t and ior picked from the
# lists given), else opaque (Kd, Ks, n picked): the generators' one form.
function mixed_material(pg, gks, gt, gior, kd, ks, n) {
    if (rand() < pg) return sprintf("material { Kd 0.2 Ks %s n 30 t %s ior %s }", pick(gks), pick(gt), pick(gior))
    return sprintf("material { Kd %s Ks %s n %s }", pick(kd), pick(ks), pick(n))
}
