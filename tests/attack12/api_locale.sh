#!/bin/sh
# api_locale.sh - builds api_locale.c against build/lib/librefray.a, makes
# a de_DE.UTF-8 locale with localedef (Debian's locales package; no system
# locale is changed: it goes to a temporary LOCPATH) and runs it.
# Run from the repository root after nice make -j2 build/lib/librefray.a:
#   sh tests/attack12/api_locale.sh     # exit 1: the load in de_DE reads other numbers
set -u
D=$(mktemp -d)
cc -std=c99 -Iinclude tests/attack12/api_locale.c build/lib/librefray.a \
   $(pkg-config --libs jansson libpng) -lOpenEXRCore -lm -lpthread -o "$D/api_locale" || exit 2
mkdir -p "$D/loc" && localedef -i de_DE -f UTF-8 "$D/loc/de_DE.UTF-8" 2>/dev/null
[ -d "$D/loc/de_DE.UTF-8" ] || { echo "localedef failed"; exit 2; }
LOCPATH=$D/loc "$D/api_locale" de_DE.UTF-8
rc=$?
rm -rf "$D"
exit $rc
