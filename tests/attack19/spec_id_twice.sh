#!/bin/sh
# spec_id_twice.sh - at ae0ba50 `make check` fails in check_spec
# (test_spec_no_id_defined_twice: "**[SHADE-SHORTCUT-TIR-1]** is defined
# twice in spec/"): the session's glass branch bolded the id both where
# spec/shading.md defines it and in spec/performance.md's seventeenth round
# (performance.md:2003; a mention there is plain [SHADE-SHORTCUT-TIR-1]).
# Exits 1 while an id of this round is defined (in bold) more than once.
# Run from the repository root.
bad=0
for id in SHADE-SHORTCUT-TIR-1 SHADE-SHORTCUT-BUNDLE-1 SHADE-SHORTCUT-LOBE-2; do
    n=$(grep -o "\*\*\[$id\]\*\*" spec/*.md | wc -l)
    echo "$id: defined $n times"
    [ "$n" -le 1 ] || bad=1
done
exit $bad
