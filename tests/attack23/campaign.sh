#!/bin/sh
# campaign.sh GEN FIRST LAST [OPTION...] - attack 23: scenes of GEN.awk
# (this folder's gen11/gen12, or an earlier round's gen3..gen10) for seeds
# FIRST..LAST, each rendered by the new binary (B, default build/refray)
# with and without --no-shortcuts, by the old one (OLD, default
# /tmp/old-main/build/refray) and by this round's base (BASE, default
# /tmp/attack23-base/build/refray), all with the same OPTIONs.  A seed is
# printed when the images or exit codes differ, or when the counts that
# this round must not move differ from BASE's: the camera, reflection,
# refraction and total-internal-reflection rays and the light samples
# (the shadow rays move: [SHADE-SHORTCUT-ABSORB-1] sends fewer; the node
# visits and primitive tests move: beams, the any-crossing walk).  With
# REGION=1 the new binary also renders the image as --region bands (x0 at
# 7, 33, and a 1-column and 1-row band) and with --jobs 2: each compared
# with its whole-image pixels (through refray merge for the regions).
# Run from the repository root after `make build/refray`.  OUT: the
# directory kept.  COUNTS=0: the counts are not compared (a BASE older
# than the round's, whose shortcuts counted other rays).  Exits 1 when
# some seed differed.
set -u
B=${B:-build/refray}
OLD=${OLD:-/tmp/old-main/build/refray}
BASE=${BASE:-/tmp/attack23-base/build/refray}
REGION=${REGION:-0}
D=${OUT:-$(mktemp -d)}
gen=$1 s=$2 last=$3
shift 3
mkdir -p "$D"
cp scenes/models/sphere_12x8.obj scenes/stress/glass_cube.obj tests/attack20/*.obj scenes/stress/geosphere.obj "$D/"
# GEN_DIRS: folders searched for GEN.awk before this one and the earlier
# rounds' (attack 24's and 24h's campaign.sh put theirs there).
dir=tests/attack23
# gen14 is gen12 through an orthographic camera.
file=$gen ortho=0
[ "$gen" = gen14 ] && file=gen12 ortho=1
for d in tests/attack22 tests/attack19 tests/attack20; do [ -f "$dir/$file.awk" ] || dir=$d; done
for d in ${GEN_DIRS:-}; do [ -f "$d/$file.awk" ] && dir=$d && break; done
counts() { sed -n 's/^  rays: \([0-9]*\) camera, [0-9]* shadow, \(.*\); [0-9]* in all/\1 \2/p; /^  light samples:/p' "$1"; }
bad=0 n=0 ok=0 fewer=0
shadows() { sed -n "s/.*camera, \([0-9]*\) shadow.*/\1/p" "$1"; }
while [ "$s" -le "$last" ]; do
    f="$D/$gen-$s.scene"
    awk -v seed="$s" -v ortho=$ortho -f tests/attack18/common.awk -f tests/attack19/common19.awk -f "$dir/$file.awk" > "$f"
    timeout 120 nice $B render "$f" -q --stats "$@" -o "$D/on.pfm" >/dev/null 2>"$D/on.st"; e1=$?
    timeout 120 nice $B render "$f" -q --no-shortcuts "$@" -o "$D/off.pfm" >/dev/null 2>&1; e2=$?
    timeout 120 nice $OLD render "$f" -q "$@" -o "$D/old.pfm" >/dev/null 2>&1; e3=$?
    timeout 120 nice $BASE render "$f" -q --stats "$@" -o "$D/base.pfm" >/dev/null 2>"$D/base.st"; e4=$?
    n=$((n + 1))
    if [ $e1 = 0 ] && [ $e4 = 0 ]; then ok=$((ok + 1)); [ "$(shadows "$D/on.st")" = "$(shadows "$D/base.st")" ] || fewer=$((fewer + 1)); fi
    msg=""
    [ $e1 = $e2 ] && [ $e1 = $e3 ] && [ $e1 = $e4 ] || msg="exit $e1 off $e2 old $e3 base $e4"
    if [ $e1 = 0 ] && [ $e2 = 0 ]; then cmp -s "$D/on.pfm" "$D/off.pfm" || msg="$msg on/off differ"; fi
    if [ $e1 = 0 ] && [ $e3 = 0 ]; then cmp -s "$D/on.pfm" "$D/old.pfm" || msg="$msg new/old differ"; fi
    if [ $e1 = 0 ] && [ $e4 = 0 ]; then
        cmp -s "$D/on.pfm" "$D/base.pfm" || msg="$msg new/base differ"
        [ "${COUNTS:-1}" = 0 ] || [ "$(counts "$D/on.st")" = "$(counts "$D/base.st")" ] || msg="$msg counts differ from BASE"
    fi
    if [ "$REGION" = 1 ] && [ $e1 = 0 ]; then
        W=$(sed -n 's/^stats: \([0-9]*\)x\([0-9]*\) .*/\1/p' "$D/on.st")
        H=$(sed -n 's/^stats: \([0-9]*\)x\([0-9]*\) .*/\2/p' "$D/on.st")
        timeout 120 nice $B render "$f" -q --jobs 2 "$@" -o "$D/jobs.pfm" >/dev/null 2>&1 || msg="$msg jobs failed"
        cmp -s "$D/on.pfm" "$D/jobs.pfm" || msg="$msg jobs differ"
        rm -f "$D"/reg*.pfm "$D"/reg*.pfm.tile
        x=7; [ "$x" -lt "$W" ] || x=0
        y=1; [ "$y" -lt "$H" ] || y=0
        timeout 120 nice $B render "$f" -q --region 0 0 "$W" "$y" "$@" -o "$D/reg0.pfm" >/dev/null 2>&1
        timeout 120 nice $B render "$f" -q --region 0 "$y" "$x" "$H" "$@" -o "$D/reg1.pfm" >/dev/null 2>&1
        timeout 120 nice $B render "$f" -q --region "$x" "$y" "$W" "$H" "$@" -o "$D/reg2.pfm" >/dev/null 2>&1
        ls "$D"/reg*.pfm > "$D/regs.txt"
        $B merge $(cat "$D/regs.txt") -o "$D/merged.pfm" >/dev/null 2>&1 || msg="$msg merge failed"
        cmp -s "$D/on.pfm" "$D/merged.pfm" || msg="$msg regions differ"
    fi
    if [ -n "$msg" ]; then
        echo "$gen seed $s: $msg"; cp "$f" "$D/bad-$gen-$s.scene"; bad=1
    fi
    s=$((s + 1))
done
echo "campaign $gen: $n scenes $*; $ok rendered, $fewer with other shadow-ray counts than BASE"
exit $bad
