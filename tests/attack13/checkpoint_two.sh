#!/bin/sh
# checkpoint_two.sh - the same command twice at once with one --checkpoint
# DIR (a re-run started while the first still runs; attack 12 recorded
# "both exit 0" on aebfd84): B, started 1 s after A, loads A's finished
# tiles, renders the rest, writes its output and removes DIR; A, still
# rendering, then cannot save its next tile: exit 74, "nothing written".
# Exits 1 when either render fails or an output differs from the one-piece
# render.
#   sh tests/attack13/checkpoint_two.sh
set -u
B=${B:-build/refray}
T=$(mktemp -d)
S="scenes/demo.scene --width 160 --height 120 -q"
nice $B render $S -o $T/ref.pfm || exit 2
(nice $B render $S --jobs 2 --checkpoint $T/ck -o $T/a.pfm; echo $? > $T/a.rc) &
sleep 1
nice $B render $S --jobs 2 --checkpoint $T/ck -o $T/b.pfm; echo $? > $T/b.rc
wait
ra=$(cat $T/a.rc) rb=$(cat $T/b.rc)
ca=$(cmp -s $T/a.pfm $T/ref.pfm && echo same || echo "not the same or missing")
cb=$(cmp -s $T/b.pfm $T/ref.pfm && echo same || echo "not the same or missing")
echo "A: exit $ra, output $ca; B: exit $rb, output $cb"
rm -rf $T
[ "$ra" = 0 ] && [ "$rb" = 0 ] && [ "$ca" = same ] && [ "$cb" = same ] && exit 0
exit 1
