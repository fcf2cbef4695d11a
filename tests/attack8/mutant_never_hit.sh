#!/bin/bash
# Finding 4 of tests/attack8/README.md: the shapes' contracts accept a hit
# test that never reports a hit.  Copies src/ with isect_cone (intersect.c)
# returning nearest(0, r, h) and isect_cylinder_hits (intersect_quadric.c)
# returning 0, and runs WP on each with prove.sh: every goal is proved.
# Usage (from the repository root): bash tests/attack8/mutant_never_hit.sh [WORKDIR]
set -eu
w=${1:-/tmp/attack8-mutant}
rm -rf "$w" && mkdir -p "$w" && cp -r src "$w/src"
perl -0pi -e 's/    return nearest\(isect_cone_hits\(from, to, r0, r1, open, r, h, 1\), r, h\);/    (void)from, (void)to, (void)r0, (void)r1, (void)open;\n    return nearest(0, r, h);/' "$w/src/render/intersect.c"
perl -0pi -e 's/    quadric s = \{from, to, radius, radius, 0, 0\};\n    return quadric_hits\(&s, open, r, out, max\);/    (void)from, (void)to, (void)radius, (void)open, (void)r, (void)out, (void)max;\n    return 0;/' "$w/src/render/intersect_quadric.c"
grep -q "return nearest(0, r, h);" "$w/src/render/intersect.c"
grep -q "(void)max;" "$w/src/render/intersect_quadric.c"
for f in isect_cone isect_cylinder_hits; do
    PROVE_SRC="$w/src" PROVE_OUT="$w/prove_$f" PROVE_FCT=$f nice bash tests/prove/prove.sh isect > "$w/prove_$f.log" 2>&1 || true
    echo "$f (never a hit): $(grep -h 'Proved goals' "$w/prove_$f"/*.log | tr -s ' ')"
done
