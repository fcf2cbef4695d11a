#!/bin/sh
# build_o1.sh - builds src/render/trace.c through the Makefile (its
# warnings and -Werror) with CFLAGS "-O1 -g" and "-Os -g" (gcc; CFLAGS is
# the Makefile's `?=` default, meant to be overridden), in a build
# directory of its own.  Since dd3427b ([SHADE-SHORTCUT-DARK-2]'s view made
# inside light_dark) gcc 12 reports `view.lobe', `view.n_lim', ... "may be
# used uninitialized" in add_distributed (light_cell_dark inlined; a false
# alarm: they are read only where light_dark set `some'), and -Werror
# stops the build; a6e27ad, 957466a and f275342 build.  Exit 1 when either
# build fails.  From the repository root.
set -u
bad=0
for o in -O1 -Os; do
    D=$(mktemp -d)
    if make BUILD="$D" CFLAGS="$o -g" "$D/obj/src/render/trace.o" >"$D/log" 2>&1; then
        echo "build_o1: CFLAGS=\"$o -g\": trace.o builds"
    else
        echo "build_o1: CFLAGS=\"$o -g\": trace.o fails:"
        grep 'error:' "$D/log" | sed 's/^/  /'
        bad=1
    fi
    rm -rf "$D"
done
exit $bad
