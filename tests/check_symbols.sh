#!/bin/sh
# tests/check_symbols.sh - what the library shows a host, read with nm,
# readelf and size ([EMBED-SYM-1] [EMBED-SYM-2] [EMBED-SYM-3]
# [EMBED-SYM-4], spec/embedding.md):
#   1. the installed librefray.a and librefray.so define no global symbol
#      without the rf_ / RF_ prefix, and the .so has SONAME librefray.so.ABI;
#   2. the library holds no writable global or static data (.data, .bss,
#      thread-local): it keeps no state between calls;
#   3. the core's objects (base, lang, scene, render, the scanner and the
#      parser) call no allocator but the hook (base/mem.o alone does) and
#      no file or terminal I/O.
# Each check first runs on a probe object built to break it, and must fail
# there, so a check that cannot fail fails the run.
#
# usage: check_symbols.sh LIBDIR ABI CORE_OBJECT...   (CC, NM from the
# environment; DATA_CHECK=0 leaves out check 2, for sanitizer builds, whose
# instrumentation adds globals of its own)
set -eu
libdir=$(cd "$1" && pwd) abi=$2
shift 2
NM=${NM:-nm}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "symbols: FAIL: $*" >&2; exit 1; }

# Defined global symbols of $2 (nm options $1) without the prefix.  The
# i386 compiler's __x86.get_pc_thunk.* are hidden and shared by every
# object of a program (COMDAT), so they clash with nothing.
unprefixed() {
    $NM $1 --defined-only "$2" | awk 'NF >= 3 && $3 !~ /^(rf_|RF_|__x86\.get_pc_thunk\.)/ { print $3 }'
}

# Bytes of writable data in object $1.
writable() {
    size -A "$1" | awk '$1 ~ /^\.(data|bss|tdata|tbss)/ && $1 !~ /^\.data\.rel\.ro/ { n += $2 } END { print n + 0 }'
}

FORBIDDEN='malloc calloc realloc free strdup strndup aligned_alloc posix_memalign
fopen fdopen freopen fclose fread fwrite fgets fgetc getc getchar fputs fputc putc putchar puts
printf fprintf vprintf vfprintf perror stdin stdout stderr open close read write stat fstat lstat
realpath getenv exit _exit system'

# The forbidden functions object $1 calls.
forbidden_calls() {
    for sym in $($NM -u "$1" | awk '{ print $NF }'); do
        for f in $FORBIDDEN; do
            if [ "$sym" = "$f" ]; then echo "$sym"; fi
        done
    done
}

# The probe: a global without the prefix, writable data, a call to printf.
printf 'int probe_count;\nint rf_ok(void);\n#include <stdio.h>\nint probe_talk(void) { return printf("%%d", ++probe_count); }\nint rf_ok(void) { return 0; }\n' > "$tmp/probe.c"
${CC:-cc} -c -o "$tmp/probe.o" "$tmp/probe.c"
[ -n "$(unprefixed -g "$tmp/probe.o")" ] || fail "the prefix check passes a probe that breaks it"
[ "$(writable "$tmp/probe.o")" -gt 0 ] || fail "the data check passes a probe that breaks it"
[ -n "$(forbidden_calls "$tmp/probe.o")" ] || fail "the call check passes a probe that breaks it"

bad=$(unprefixed -g "$libdir/librefray.a")
[ -z "$bad" ] || fail "librefray.a defines global symbols without rf_: $(echo $bad)"
bad=$(unprefixed -D "$libdir/librefray.so")
[ -z "$bad" ] || fail "librefray.so exports symbols without rf_: $(echo $bad)"
count=$($NM -g --defined-only "$libdir/librefray.a" | awk 'NF >= 3 && $3 ~ /^rf_/' | wc -l)
[ "$count" -gt 20 ] || fail "librefray.a defines only $count rf_ symbols"
soname=$(readelf -d "$libdir/librefray.so" | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
[ "$soname" = "librefray.so.$abi" ] || fail "SONAME is '$soname', not librefray.so.$abi"

(cd "$tmp" && ar x "$libdir/librefray.a")
data="no writable data"
[ "${DATA_CHECK:-1}" = 1 ] || data="writable data not checked (DATA_CHECK=0)"
for o in "$tmp"/*.o; do
    [ "${DATA_CHECK:-1}" = 1 ] || break
    [ "$o" = "$tmp/probe.o" ] && continue
    n=$(writable "$o")
    [ "$n" -eq 0 ] || fail "the library holds $n bytes of writable data: $(size -A "$o" | awk '$1 ~ /^\.(data|bss|tdata|tbss)/ && $2 > 0' | tr '\n' ' ')"
done

for o in "$@"; do
    case $o in */base/mem.o) continue ;; esac
    bad=$(forbidden_calls "$o")
    [ -z "$bad" ] || fail "$o calls $(echo $bad)"
done
echo "symbols: $count rf_ symbols, none other; $data; $# core objects free of malloc and I/O"
