#!/bin/bash
# diff_render.sh DIR: renders every scene of DIR with two refray binaries
# (OLD, NEW: main's and the candidate's), with and without the shortcuts,
# at 32 x 24, and logs DIR/../<name>.log: "same" or "DIFF" per render (an
# image or exit status that differs; for a refused scene, its messages),
# with the number of floats of main's image that differ from its first
# pixel (0: a flat image, the shape not seen).
NEW=${NEW:-build/refray}; OLD=${OLD:-/tmp/lead-old/build/refray}
PFMVAR=${PFMVAR:-/tmp/a8/pfmvar}   # any tool printing that count; cc tests/attack8/pfmvar.c
d=$1; log=$d/../$(basename $d).log; : > $log
for s in $d/*.scene; do
  for flag in "" "--no-shortcuts"; do
    rm -f $d/o.pfm $d/n.pfm
    nice $OLD render $s --width 32 --height 24 -q -o $d/o.pfm $flag 2>$d/o.err; ro=$?
    nice $NEW render $s --width 32 --height 24 -q -o $d/n.pfm $flag 2>$d/n.err; rn=$?
    if [ $ro != $rn ]; then echo "DIFF $s $flag rc $ro $rn" >> $log
    elif [ $ro != 0 ]; then cmp -s $d/o.err $d/n.err && echo "same $s $flag rc $ro" >> $log || echo "DIFFERR $s $flag rc $ro" >> $log
    elif ! cmp -s $d/o.pfm $d/n.pfm; then echo "DIFF $s $flag rc 0" >> $log
    else echo "same $s $flag rc 0 var $($PFMVAR $d/o.pfm)" >> $log; fi
  done
done
echo DONE >> $log
