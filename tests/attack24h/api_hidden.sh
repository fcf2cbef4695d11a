#!/bin/sh
# api_hidden.sh - attack 24h: api_hidden.c built against this tree's
# library (build/librefray-internal.a) and the base's (BASELIB, default
# /tmp/base24/build/librefray-internal.a); exit 1 when their outputs differ
# (the number of cancel polls, or where a stop at poll k lands).
set -u
BASELIB=${BASELIB:-/tmp/base24/build/librefray-internal.a}
D=$(mktemp -d)
cc -std=c99 -O2 -Iinclude -o $D/new tests/attack24h/api_hidden.c build/librefray-internal.a -ljansson -lm || exit 2
cc -std=c99 -O2 -Iinclude -o $D/base tests/attack24h/api_hidden.c "$BASELIB" -ljansson -lm || exit 2
$D/new > $D/new.txt; $D/base > $D/base.txt
head -1 $D/new.txt; head -1 $D/base.txt
if cmp -s $D/new.txt $D/base.txt; then echo "api_hidden: $(wc -l < $D/new.txt) lines, the same"; rm -rf $D; exit 0; fi
diff $D/base.txt $D/new.txt | head -20
echo "api_hidden: $(diff $D/base.txt $D/new.txt | grep -c '^>') lines differ (base <, new >)"
rm -rf $D
exit 1
