#!/bin/sh
# ld_images.sh - what ld_build.sh's defect does to the images when the
# build is let through: this tree built with LONG_DOUBLE=1 and
# CFLAGS="-O2 -g -Wno-error=array-bounds" (trace_lobe_above then reads 16
# bytes out of an 8-byte integer and takes them for an x87 long double), and
# the round's base 08143cd built with LONG_DOUBLE=1 (LDBASE, made here from
# `git archive 08143cd` when not given); hand_absorb.sh run with the first
# as B and the second as OLD and BASE.  Exit 1 when some image differs
# (at 1c0d4b9: 23 of the 70 hand scenes, each also against --no-shortcuts);
# with `double b` in trace_lobe_above, 0.  Slow: two full builds (about 3
# minutes each on this machine).  From the repository root.
set -u
D=$(mktemp -d)
make LONG_DOUBLE=1 LTO=0 CFLAGS="-O2 -g -Wno-error=array-bounds" BUILD="$D/new" "$D/new/refray" >"$D/new.log" 2>&1 ||
    { echo "ld_images: the LD build failed"; exit 1; }
if [ -z "${LDBASE:-}" ]; then
    mkdir -p "$D/base" && git archive 08143cd | tar -x -C "$D/base" &&
        make -C "$D/base" LONG_DOUBLE=1 LTO=0 BUILD="$D/base/b" "$D/base/b/refray" >"$D/base.log" 2>&1 ||
        { echo "ld_images: the base's LD build failed"; exit 1; }
    LDBASE=$D/base/b/refray
fi
B="$D/new/refray" OLD="$LDBASE" BASE="$LDBASE" sh tests/attack23/hand_absorb.sh; bad=$?
rm -rf "$D"
exit $bad
