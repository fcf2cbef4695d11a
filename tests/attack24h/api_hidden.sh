#!/bin/sh
# api_hidden.sh - attack 24h: api_hidden.c built against this tree's
# library (build/librefray-internal.a) and the base's (BASELIB, default
# /tmp/base24/build/librefray-internal.a); exit 1 when their whole renders
# differ or a stop does not cancel
# (the number of cancel polls, or how many pixels a stop at poll k leaves
# written; their bytes go to stderr: not specified, spec/embedding.md).
set -u
BASELIB=${BASELIB:-/tmp/base24/build/librefray-internal.a}
D=$(mktemp -d)
cc -std=c99 -O2 -Iinclude -o $D/new tests/attack24h/api_hidden.c build/librefray-internal.a -ljansson -lm || exit 2
cc -std=c99 -O2 -Iinclude -o $D/base tests/attack24h/api_hidden.c "$BASELIB" -ljansson -lm || exit 2
$D/new > $D/new.txt 2>/dev/null; $D/base > $D/base.txt 2>/dev/null
# Since the tiles (attack 24) a band polls once for its rows, so the polls
# and where a stop lands are not compared with the base; the whole render
# is (pixels, samples), and every stop must cancel.
bad=0
a=$(grep '^whole' $D/new.txt | sed 's/ polls [0-9]*//') b=$(grep '^whole' $D/base.txt | sed 's/ polls [0-9]*//')
echo "new:  $a"; echo "base: $b"
[ -n "$a" ] && [ "$a" = "$b" ] || { echo "api_hidden: the whole render differs"; bad=1; }
# (a stop at a poll past the render's last is no stop)
polls=$(grep '^whole' $D/new.txt | sed 's/.* polls \([0-9]*\).*/\1/')
n=$(awk -v p="$polls" '/^stop at poll/ { k = $4 + 0; if (k <= p) n++ } END { print n + 0 }' $D/new.txt)
c=$(awk -v p="$polls" '/^stop at poll/ { k = $4 + 0; if (k <= p && $6 == 6) c++ } END { print c + 0 }' $D/new.txt)
[ "$n" -gt 0 ] && [ "$n" = "$c" ] || { echo "api_hidden: $c of $n stops cancelled"; bad=1; }
grep -q FAIL $D/new.txt && { grep FAIL $D/new.txt; bad=1; }
[ $bad = 0 ] && echo "api_hidden: the same whole render as the base, $n stops all cancelled"
rm -rf $D
exit $bad
