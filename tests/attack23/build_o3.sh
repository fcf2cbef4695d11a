#!/bin/sh
# build_o3.sh - builds the objects of src/scene/lower.c and of this round's
# files (trace.c, bvh.c, bvh_beam.c, intersect.c, render.c) through the
# Makefile (its warnings and -Werror) with CFLAGS "-O3 -g", in a build
# directory of its own.  Before the fix gcc 12 reported `from' "may be used
# uninitialized" in lower_for (a false alarm: loop_bound sets it where it is
# read) and -Werror stopped the build; the base 08143cd had it too.  Exit 1
# when an object fails.  From the repository root.
set -u
D=$(mktemp -d)
bad=0
for f in scene/lower render/trace render/bvh render/bvh_beam render/intersect render/render; do
    if make BUILD="$D" CFLAGS="-O3 -g" "$D/obj/src/$f.o" >"$D/log" 2>&1; then
        echo "build_o3: $f.o builds"
    else
        echo "build_o3: $f.o fails:"
        grep 'error:' "$D/log" | sed 's/^/  /'
        bad=1
    fi
done
rm -rf "$D"
exit $bad
