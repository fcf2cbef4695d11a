#!/bin/sh
# tests/scaling/figures.sh REFRAY [RENDER OPTION...] - the figures of
# spec/scaling.md ("Figures"): the wall and processor time of one render
# with --jobs 1 and each --jobs N of JOBS, of the GNU parallel recipe over
# TILES tiles, of the merge alone, and of a --checkpoint render killed by
# SIGKILL halfway and then resumed; every output compared byte for byte
# with the one of --jobs 1.  A table in Markdown on standard output; exit
# 1 when an output differs.  Figures, not a test: `make scaling-figures`.
#
# Environment: SCENE (scenes/demo.scene), SIZE (1920x1080), JOBS ("2 4"),
# TILES (16), KILL_AT (0.5: the fraction of the --jobs 2 time, or of
# --jobs 1's when JOBS lacks 2, after which the checkpointed render is
# killed).  Times come from GNU time
# (/usr/bin/time, Debian's time), so they hold the workers' time too.
set -eu

if [ $# -lt 1 ]; then
    echo "usage: figures.sh REFRAY [RENDER OPTION...]" >&2
    exit 64
fi
refray=$1
shift
scene=${SCENE:-scenes/demo.scene}
size=${SIZE:-1920x1080}
jobs=${JOBS:-"2 4"}
tiles=${TILES:-16}
kill_at=${KILL_AT:-0.5}
work=$(mktemp -d "${TMPDIR:-/tmp}/refray-figures.XXXXXX")
trap 'rm -rf "$work"' EXIT
trap 'exit 130' INT TERM HUP
view="--width ${size%x*} --height ${size#*x}"

# Display output and tile format this refray can write.
ext=png
"$refray" render -q "$scene" --width 2 --height 2 -o "$work/probe.png" 2>/dev/null || ext=ppm
tile_ext=exr
"$refray" render -q "$scene" --width 2 --height 2 --tile 0/1 -o "$work/probe.exr" 2>/dev/null || tile_ext=pfm

# timed COMMAND...: runs it under GNU time; its wall and cpu seconds into
# $wall and $cpu (user + system, with every process it waited for).
timed() {
    /usr/bin/time -f '%e %U %S' -o "$work/time" "$@"
    read -r wall user sys <"$work/time"
    cpu=$(awk "BEGIN { printf \"%.1f\", $user + $sys }")
}

# row LABEL FILE [-]: a table row against --jobs 1's bytes and time (no
# speed-up with -: a part of a run, or a run that resumes).
row() {
    same=yes
    cmp -s "$work/j1.$ext" "$2" || { same=NO; status=1; }
    speedup=$(awk "BEGIN { printf \"%.2f\", $wall1 / $wall }")
    [ $# -lt 3 ] || speedup=-
    printf '| %s | %s | %s | %s | %s |\n' "$1" "$wall" "$cpu" "$speedup" "$same"
}

status=0
echo "$scene at $size, $(nproc) processors; $(uname -m)"
echo
echo "| run | wall s | cpu s | speed-up | bytes of --jobs 1 |"
echo "|---|---|---|---|---|"
# shellcheck disable=SC2086
timed "$refray" render -q "$scene" $view "$@" --jobs 1 -o "$work/j1.$ext"
wall1=$wall
row "render --jobs 1" "$work/j1.$ext"
wall2=$wall
for n in $jobs; do
    # shellcheck disable=SC2086
    timed "$refray" render -q "$scene" $view "$@" --jobs "$n" -o "$work/j$n.$ext"
    row "render --jobs $n" "$work/j$n.$ext"
    [ "$n" != 2 ] || wall2=$wall
done

if command -v parallel >/dev/null 2>&1; then
    mkdir "$work/tiles"
    # shellcheck disable=SC2086
    timed env REFRAY="$refray" TILES="$work/tiles" TILE_EXT=$tile_ext PARALLEL_OPTS="-j $(nproc)" \
        sh examples/scaling/parallel-tiles.sh "$scene" "$work/par.$ext" "$tiles" $view "$@"
    row "GNU parallel -j $(nproc): $tiles tiles, then merge" "$work/par.$ext"
    timed "$refray" merge "$work/tiles"/tile-*."$tile_ext" -o "$work/merged.$ext"
    row "merge of the $tiles $tile_ext tiles alone" "$work/merged.$ext" -
fi

# A render with a checkpoint killed at KILL_AT of the --jobs 2 time (a
# power cut: SIGKILL), then the same command again.
ck="$work/ck"
start=$(date +%s.%N)
# shellcheck disable=SC2086
"$refray" render -q "$scene" $view "$@" --jobs 2 --checkpoint "$ck" -o "$work/resumed.$ext" &
pid=$!
sleep "$(awk "BEGIN { print $wall2 * $kill_at }")"
kill -KILL "$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
killed=$(awk "BEGIN { printf \"%.2f\", $(date +%s.%N) - $start }")
kept=$(find "$ck" -name 'tile-*.pfm.tile' | wc -l)
bands=$(sed -n 's/^bands //p' "$ck/refray-checkpoint")
# shellcheck disable=SC2086
timed "$refray" render -q "$scene" $view "$@" --jobs 2 --checkpoint "$ck" -o "$work/resumed.$ext"
row "--jobs 2 --checkpoint resumed after SIGKILL at ${killed} s ($kept of $bands tiles kept)" "$work/resumed.$ext" -
echo
echo "killed run + resumed run: $(awk "BEGIN { printf \"%.2f\", $killed + $wall }") s of wall time"
exit $status
