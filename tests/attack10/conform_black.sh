#!/bin/sh
# conform_black.sh - a "renderer" that writes an all-black PFM passes the
# conformance kit of disk_light_1sample.scene: the disk_light family's
# tolerance for one light sample is 5.86 (relative), and [VERIFY-INEXACT-1]
# refuses only a tolerance that is not finite.  Expected: a refusal (a
# tolerance >= 1 cannot tell any image from black), not "pass".
# Run from the repository root after nice make -j2 build/refray:
#   sh tests/attack10/conform_black.sh    # prints the verdict; exit 1 when black passes
#   SCENE=tests/attack10/disk_occluded_64.scene sh tests/attack10/conform_black.sh
set -u
B=${B:-build/refray}
K=$(mktemp -d)/kit
"$B" kit -q -o "$K" "${SCENE:-tests/attack10/disk_light_1sample.scene}" || exit 2
"$B" conform --kit "$K" --format pfm \
    --cmd '{ printf "PF\n%s %s\n-1\n" {width} {height}; head -c $(expr {width} \* {height} \* 12) /dev/zero; } > {out}'
rc=$?
rm -rf "$(dirname "$K")"
[ $rc -ne 0 ] && exit 0
echo "black image passed (exit $rc)"
exit 1
