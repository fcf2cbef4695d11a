#!/bin/sh
# tests/embed/run.sh - [EMBED-EXAMPLE-1] the embedding examples built against an installed
# refray (make install DESTDIR=...) with pkg-config alone, and run: each
# linked with the shared library and again with the static one.
#
# Environment (set by make test): CC; PKG_CONFIG_PATH holding the installed
# refray.pc; LIBDIR, the installed lib directory (for the shared runs); OUT,
# a directory for programs and images; EXTRA, flags every compile of this
# build needs (-m32, sanitizers); IMAGE_EXT, png or pfm (a build without
# libpng writes PFM).  Runs from the repository root.
set -eu
fail() { echo "embed: FAIL: $*" >&2; exit 1; }

warn="-std=c99 -pedantic -Wall -Wextra -Werror"
cflags=$(pkg-config --cflags refray)
shared=$(pkg-config --libs refray)
# The same link line with the archive named instead of -lrefray.
static=$(pkg-config --static --libs refray | sed 's/-lrefray\( \|$\)/-l:librefray.a\1/')
mkdir -p "$OUT"
for prog in render_string render_file locale_host; do
    $CC $warn $EXTRA $cflags -o "$OUT/$prog" "tests/embed/$prog.c" $shared
    $CC $warn $EXTRA $cflags -o "$OUT/$prog-static" "tests/embed/$prog.c" $static
done
readelf -d "$OUT/render_string" | grep -q 'NEEDED.*librefray\.so\.' || fail "render_string does not use librefray.so"
! readelf -d "$OUT/render_string-static" | grep -q 'librefray' || fail "render_string-static needs librefray.so"

run() { LD_LIBRARY_PATH="$LIBDIR" "$@"; }

# [EMBED-LOCALE-1] A locale whose decimal point is ',', made here from the
# locales package's sources (make deps installs it) into a directory of our
# own: no locale of the system is changed.
mkdir -p "$OUT/locale"
localedef -i de_DE -f UTF-8 "$OUT/locale/de_DE.UTF-8" >/dev/null 2>&1 || true
[ -d "$OUT/locale/de_DE.UTF-8" ] || fail "localedef could not make de_DE.UTF-8 (is the locales package installed?)"

for kind in "" -static; do
    # (a) a scene in a string, a fixed arena: renders with 1 MiB ...
    out=$(run "$OUT/render_string$kind") || fail "render_string$kind: exit $?"
    case $out in "rendered 64x48; centre pixel "*) ;; *) fail "render_string$kind: $out" ;; esac
    # ... and fails cleanly (exit 3, out of memory) when the arena is too
    # small, at every size from nothing up to enough.
    for size in 0 100 1000 4000 16000 24000 32000 48000 64000 96000 128000 1048576; do
        rc=0
        out=$(run "$OUT/render_string$kind" $size 2>/dev/null) || rc=$?
        case $rc:$out in
        0:rendered*|3:"not rendered: out of memory"*) ;;
        *) fail "render_string$kind $size: exit $rc: $out" ;;
        esac
    done
    rc=0
    out=$(run "$OUT/render_string$kind" 4000 2>/dev/null) || rc=$?
    [ "$rc" = 3 ] || fail "render_string$kind 4000: exit $rc, expected 3 (out of memory): $out"

    # (b) a scene file rendered and written.
    img="$OUT/demo$kind.$IMAGE_EXT"
    rm -f "$img"
    run "$OUT/render_file$kind" scenes/demo.scene "$img" 40 25 >/dev/null 2>&1 || fail "render_file$kind: exit $?"
    magic=$(od -An -c -N4 "$img" | tr -d ' ')
    case $IMAGE_EXT:$magic in
    png:*PNG*|pfm:PF*) ;;
    *) fail "$img does not look like a .$IMAGE_EXT file ($magic)" ;;
    esac
    rc=0
    err=$(run "$OUT/render_file$kind" tests/no-such.scene "$img" 2>&1 >/dev/null) || rc=$?
    [ "$rc" = 1 ] || fail "render_file$kind on a missing scene: exit $rc"
    case $err in "refray: error: cannot open 'tests/no-such.scene'"*) ;; *) fail "render_file$kind: $err" ;; esac
    # (c) a host in a locale that writes 0.5 as 0,5 reads the scene's numbers.
    LOCPATH="$OUT/locale" run "$OUT/locale_host$kind" de_DE.UTF-8 >/dev/null || fail "locale_host$kind: exit $?"
done
echo "embed: 2 examples and the locale host, shared and static, built with pkg-config and run"
