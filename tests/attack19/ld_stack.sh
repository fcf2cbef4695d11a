#!/bin/sh
# ld_stack.sh - the long double build's stated need at the depth ceiling:
# 3 MiB (spec/numerics.md section 1; DEEP_STACK_BYTES in tests/check_trace.c,
# test_trace_depth_1000_fits_a_small_stack).  At ae0ba50 the 999 total
# reflections of that test's glass cube die with SIGSEGV on a 3 MiB stack
# (`make LONG_DOUBLE=1 check` fails that test: chain 1, signal 11), while
# at 61c8111 they fit: shade's frame grew with [SHADE-SHORTCUT-TIR-1]'s
# mirror_trace (gcc 12 -fstack-usage, trace.c: shade 864 -> 1024 bytes).
# Exits 1 while the chain does not render in 3072 KiB.  LD: the long double
# program (default build/refray-ld, made by `make refray-ld` when missing).
# Run from the repository root.
LD=${LD:-build/refray-ld}
[ -x "$LD" ] || nice make -j2 refray-ld >/dev/null || exit 2
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
printf 'image { width 1 height 1 max_depth 1000 }\ncamera { eye [0, 0, 0] look_at [1, 1, 1] fov 0.001 }\nambient { color 1 }\nbox { from [-1, -1, -1] to [1, 1, 1] material { Kd 0.001 Ks 0 t 0.999 ior 1.5 } }\n' > "$D/tir.scene"
(ulimit -s 3072; "$LD" render "$D/tir.scene" -q -o "$D/tir.pfm" >/dev/null 2>&1); e=$?
echo "999 total reflections, long double, 3072 KiB stack: exit $e (0 expected)"
[ "$e" = 0 ]
