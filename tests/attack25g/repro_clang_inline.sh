#!/bin/sh
# repro_clang_inline.sh - attack 25g finding 1: `make CC=clang` (and so
# `make check CC=clang`) stops at shade.o and intersect.o: clang 14's
# -Wstatic-in-inline (on by default, an error under -Werror) fires on
# shade_combine and ray_spawn_hit_sized, now `HINT_IN_LINE inline` with
# external linkage, which call static functions (saturating_sum, vec_mul,
# spawn, keep_inside...).  Exits 1 when either object fails to build.
# Run from the repository root.
bad=0
for o in shade intersect; do
    make CC=clang build/variant-clang/obj/src/render/$o.o >/tmp/repro_clang_$o.log 2>&1 ||
        { echo "CC=clang: src/render/$o.c fails: $(grep -m1 'error:' /tmp/repro_clang_$o.log)"; bad=1; }
done
[ $bad = 0 ] && echo "CC=clang: shade.o and intersect.o build"
exit $bad
