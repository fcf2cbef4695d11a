#!/bin/sh
# mutants.sh WORK - attack 25g: each mutant of this round's new code (a
# sed on a copy of the sources in WORK, made by `git archive HEAD`) built
# as build/check_refray there and run on the shortcuts and intersect
# suites; prints which suites catch each mutant (KILLED) or none (SURVIVED).
# Run from the repository root.
set -u
# the CLI test needs a refray binary; the worktree's (not the mutant's)
export REFRAY_BIN=${REFRAY_BIN:-$(pwd)/build/refray}
ONLY=${ONLY:-}
W=${1:-/tmp/a25g_mut}
[ -d "$W" ] || { mkdir -p "$W" && git archive HEAD | tar -x -C "$W"; }
G=src/render/gather_alone.c I=src/render/intersect.c F=src/render/interface.c
run() {  # name file sed-expression
    [ -z "$ONLY" ] || echo " $ONLY " | grep -q " $1 " || return 0
    cp "$W/$2" "$W/$2.orig"
    sed -i "$3" "$W/$2"
    if cmp -s "$W/$2" "$W/$2.orig"; then echo "$1: sed did not apply"; mv "$W/$2.orig" "$W/$2"; return; fi
    (cd "$W" && make -j2 build/check_refray >/dev/null 2>&1) || { echo "$1: build failed"; mv "$W/$2.orig" "$W/$2"; return; }
    k=""
    for s in shortcuts intersect; do
        (cd "$W" && CK_RUN_SUITE=$s ./build/check_refray >"$W/$1.$s.log" 2>&1) || k="$k $s($(grep -o '[a-z_]*:[0-9]*:F\|:[a-z_]*:[A-Za-z_]*' "$W/$1.$s.log" | head -3 | tr '\n' ' '))"
    done
    [ -n "$k" ] && echo "$1: KILLED by$k" || echo "$1: SURVIVED"
    mv "$W/$2.orig" "$W/$2" && touch "$W/$2"  # newer than the mutant's object
}
run slack_halved $G 's/real slack = 2 \* pads/real slack = pads/'
run slack_no_pads $G 's/real slack = 2 \* pads + /real slack = 0 * pads + 4 * reach + /'
run slack_no_reach $G 's/+ 2 \* reach;/+ 0 * reach;/'
run nested_gap_plus_r $G 's/big - d - small > slack/big - d + small > slack/'
run no_frame_test $G 's/p->kind != PRIM_SPHERE || p->frame || o->kind != PRIM_SPHERE || o->frame/p->kind != PRIM_SPHERE || o->kind != PRIM_SPHERE/'
run away_tmin_gt $I 's/return r->tmin >= 0.0 \&\& (num < 0.0) != (dn < 0.0);/return r->tmin > 0.0 \&\& (num < 0.0) != (dn < 0.0);/'
run away_num_le $I 's/return r->tmin >= 0.0 \&\& (num < 0.0) != (dn < 0.0);/return r->tmin >= 0.0 \&\& (num <= 0.0) != (dn < 0.0);/'
run away_dn_le $I 's/return r->tmin >= 0.0 \&\& (num < 0.0) != (dn < 0.0);/return r->tmin >= 0.0 \&\& (num < 0.0) != (dn <= 0.0);/'
run away_tmin_gt_m1 $I 's/return r->tmin >= 0.0 \&\& (num < 0.0) != (dn < 0.0);/return r->tmin > -1.0 \&\& (num < 0.0) != (dn < 0.0);/'
run slack_no_2m30 $G 's/real slack = 2 \* pads + 0x1p-30 \*/real slack = 2 * pads + 0 */'
run pad_p_only $G 's/+ 0x1p-20 \* (vec_max_abs(oc) + small)/+ 0 * (vec_max_abs(oc) + small)/'
run apart_ge $G 's/d - big - small > slack || big - d - small > slack || small - d - big > slack/d - big - small >= slack || big - d - small >= slack || small - d - big >= slack/'
run away_no_tmin $I 's/return r->tmin >= 0.0 \&\& (num < 0.0) != (dn < 0.0);/return (num < 0.0) != (dn < 0.0);/'
run no_far_guard $G 's/t->frame_shift <= 0x1p15 \* vec_max_abs(at);/t->frame_shift <= INFINITY + vec_max_abs(at);/'
run away_same_sign $I 's/return r->tmin >= 0.0 \&\& (num < 0.0) != (dn < 0.0);/return r->tmin >= 0.0 \&\& (num < 0.0) == (dn < 0.0);/'
