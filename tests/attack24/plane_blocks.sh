#!/bin/sh
# plane_blocks.sh - attack 24, test gap of [SHADE-SHORTCUT-PLANE-1]: a
# ceiling plane between the floor and a rectangle light, and a ball off to
# the side (so the tree has a node and the floor's bundles keep none of it).
# Every floor point's bundle keeps nothing and crosses the ceiling, so
# crosses_nothing must be 0.  The mutant "ignore the planes"
# (trace.c `if (bundle && bundle->count == 0)` without
# `&& bundle->crosses_nothing`) lights the floor through the ceiling and
# passes the bundle, trace, shortcuts and random_scenes suites; this image
# against the old binary's catches it.  Exit 1 when the images differ.
B=${B:-build/refray}
OLD=${OLD:-/tmp/old-main/build/refray}
T=$(mktemp -d)
$B render tests/attack24/plane_blocks.scene -q -o $T/new.pfm || exit 1
$OLD render tests/attack24/plane_blocks.scene -q -o $T/old.pfm || exit 2
$B render tests/attack24/plane_blocks.scene -q --no-shortcuts -o $T/off.pfm || exit 1
cmp -s $T/new.pfm $T/old.pfm && cmp -s $T/new.pfm $T/off.pfm; e=$?
rm -rf $T
exit $e
