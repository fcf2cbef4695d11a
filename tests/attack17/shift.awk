# shift.awk -v t=T: adds T to the x and z of every `eye`, `look_at`,
# `position`, `point` and `center` vector of a scene, so the picture stays
# the same while its coordinates grow (the reproducers of this folder).
BEGIN { n = split("eye look_at position point center", keys, " ") }
{
    for (k = 1; k <= n; k++) {
        if (!match($0, keys[k] " \\[[^]]*\\]"))
            continue
        head = substr($0, 1, RSTART - 1); tail = substr($0, RSTART + RLENGTH)
        inner = substr($0, RSTART + length(keys[k]) + 2, RLENGTH - length(keys[k]) - 3)
        split(inner, c, ",")
        $0 = head keys[k] sprintf(" [%.17g, %.17g, %.17g]", c[1] + t, c[2], c[3] + t) tail
    }
    print
}
