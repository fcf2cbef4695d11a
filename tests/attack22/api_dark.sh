#!/bin/sh
# api_dark.sh - builds api_dark.c against build/librefray-internal.a and
# against the old main's (OLDLIB, default /tmp/old-main/build/
# librefray-internal.a), runs both, and exits 1 when either fails its own
# checks or their printed hashes and counts differ.  From the repository
# root after `make build/librefray-internal.a`.
set -u
OLDLIB=${OLDLIB:-/tmp/old-main/build/librefray-internal.a}
D=$(mktemp -d)
cc -std=c99 -O2 -Iinclude -o "$D/new" tests/attack22/api_dark.c build/librefray-internal.a -ljansson -lm 2>/dev/null &&
cc -std=c99 -O2 -Iinclude -o "$D/old" tests/attack22/api_dark.c "$OLDLIB" -ljansson -lm 2>/dev/null || { echo "api_dark: build failed"; exit 1; }
"$D/new" > "$D/new.txt"; e1=$?
"$D/old" > "$D/old.txt"; e2=$?
bad=0
[ $e1 = 0 ] && [ $e2 = 0 ] || { echo "api_dark: exit $e1 (old $e2)"; bad=1; }
diff "$D/old.txt" "$D/new.txt" || bad=1
[ $bad = 0 ] && echo "api_dark: same pixels and counts as the old library ($(grep -c . "$D/new.txt") lines)"
rm -rf "$D"
exit $bad
