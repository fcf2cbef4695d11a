#!/bin/sh
# ld_build.sh - builds src/render/trace.c through the Makefile with
# LONG_DOUBLE=1 (the tracer's `real` is long double; its warnings and
# -Werror), in a build directory of its own.  Since 0511779
# (trace_lobe_above without pow or loop, [SHADE-SHORTCUT-ABSORB-1]) it copies sizeof(real) = 16
# bytes out of the 8-byte uint64_t `bits` (memcpy(&b, &bits, sizeof b) with
# `real b`): gcc 12 reports -Werror=array-bounds and the build stops; were
# it built, the copy would read past `bits` and take a double's bit pattern
# for an x87 long double's.  Exit 1 when the build fails.  From the
# repository root.
set -u
D=$(mktemp -d)
if make LONG_DOUBLE=1 LTO=0 BUILD="$D" "$D/obj/src/render/trace.o" >"$D/log" 2>&1; then
    echo "ld_build: LONG_DOUBLE=1: trace.o builds"; bad=0
else
    echo "ld_build: LONG_DOUBLE=1: trace.o fails:"; grep 'error:' "$D/log" | sed 's/^/  /'; bad=1
fi
rm -rf "$D"
exit $bad
