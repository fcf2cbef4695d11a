#!/bin/sh
# api_two_locales.sh - builds api_two_locales.c against build/lib/librefray.a,
# makes de_DE.UTF-8 with localedef into a temporary LOCPATH and runs it.
#   sh tests/attack14/api_two_locales.sh     # exit 1: a load in one thread's locale went wrong
set -u
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
cc -std=c99 -Iinclude tests/attack14/api_two_locales.c build/lib/librefray.a \
   $(pkg-config --libs jansson libpng) -lOpenEXRCore -lm -lpthread -o "$D/t" || exit 2
mkdir -p "$D/loc" && localedef -i de_DE -f UTF-8 "$D/loc/de_DE.UTF-8" 2>/dev/null
[ -d "$D/loc/de_DE.UTF-8" ] || { echo "localedef failed"; exit 2; }
LOCPATH=$D/loc "$D/t" de_DE.UTF-8
