#!/bin/sh
# checkpoint_lost.sh - [SCALE-RESUME-5]: a band that cannot be saved gives
# up the checkpoint, not the render.  The checkpoint DIR of a running
# render is replaced by a regular file of the same name (so no band can be
# saved any more) 1 s in; the render must still exit 0 and write the bytes
# of the render without --checkpoint (PFM and 16-bit PNG).  Exit 1 when it
# fails or an output differs.
#   sh tests/attack15/checkpoint_lost.sh
set -u
B=${B:-build/refray}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
S="scenes/demo.scene --width 160 --height 120 -q"
bad=0
for ext in pfm png; do
    nice $B render $S -o $T/ref.$ext || exit 2
    rm -rf $T/ck
    (nice $B render $S --jobs 2 --checkpoint $T/ck -o $T/a.$ext 2> $T/err; echo $? > $T/a.rc) &
    sleep 1
    rm -rf $T/ck && echo x > $T/ck
    wait
    ra=$(cat $T/a.rc)
    c=$(cmp -s $T/a.$ext $T/ref.$ext && echo same || echo "not the same or missing")
    echo "$ext: exit $ra, output $c; stderr: $(head -c 300 $T/err)"
    [ "$ra" = 0 ] && [ "$c" = same ] || bad=1
done
exit $bad
