#!/bin/sh
# tests/report.sh REFRAY OUTDIR SCENE... - the error-against-cost report of
# `make report` (spec/verify.md, "make report").
#
# For every scene: `refray verify --sweep` with the light samples
# 1, 2, 4, ..., 1024 when the scene has a distributed light, else with the
# camera grid k = 1..4; one verify per kind, its scenes on REPORT_JOBS
# worker processes (default 0: one per processor; each render is still on
# one thread, and 1 times them without a neighbour); one TSV per scene
# under OUTDIR/tsv/ and the tables under OUTDIR/log/.  Scene paths must not
# hold white space.  Then, with gnuplot, in OUTDIR:
#   error_vs_n.png/.svg      sampled scenes: RMS error against light samples N
#   error_vs_time.png/.svg   sampled scenes: RMS error against render seconds
#   deterministic.png/.svg   exact scenes: RMS error against k*k (round-off)
#   summary.md               per scene: family, tolerance, final error,
#                            fitted and expected slope, time
# Log-log axes, one curve per scene, the fitted slope in the legend.  Each
# step's time is the median of REPORT_RUNS (3) renders; REPORT_LIGHT_STEPS and
# REPORT_PIXEL_STEPS override the sweeps.
set -eu

if [ $# -lt 3 ]; then
    echo "usage: tests/report.sh REFRAY OUTDIR SCENE..." >&2
    exit 64
fi
refray=$1
out=$2
shift 2
light_steps=${REPORT_LIGHT_STEPS:-1,2,4,8,16,32,64,128,256,512,1024}
pixel_steps=${REPORT_PIXEL_STEPS:-1,2,3,4}
runs=${REPORT_RUNS:-3}
jobs=${REPORT_JOBS:-0}
[ "$jobs" != 0 ] || jobs=$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)
tab=$(printf '\t')

case $out in
    "" | / | . | ..) echo "tests/report.sh: refusing to write into '$out'" >&2; exit 64 ;;
esac
rm -rf "$out"
mkdir -p "$out/tsv" "$out/log"
start=$(date +%s)
: > "$out/sampled.list"
: > "$out/deterministic.list"
: > "$out/sampled.scenes"
: > "$out/deterministic.scenes"
failed=0

for scene in "$@"; do
    name=$(basename "$scene" .scene)
    if "$refray" check -W "$scene" | grep -q 'sampled-lights'; then
        kind=sampled
    else
        kind=deterministic
    fi
    echo "$name" >> "$out/$kind.list"
    echo "$scene" >> "$out/$kind.scenes"
done

# The sweeps of one kind of scene, then its TSV split into one per scene
# (a "# fit" row names its scene in field 2, a step row in field 1).  A
# scene that misses its tolerance (exit 1) is counted, one that cannot be
# run (65, 66, 70) stops the report.
sweep_kind() {
    [ -s "$out/$1.scenes" ] || return 0
    printf 'report: %s scenes, sweep %s, %s at a time\n' "$(wc -l < "$out/$1.scenes")" "$2" "$jobs"
    status=0
    # shellcheck disable=SC2046
    "$refray" verify -W --jobs "$jobs" --runs "$runs" --sweep "$2" --tsv "$out/tsv/$1.all" \
        $(cat "$out/$1.scenes") > "$out/log/$1.txt" || status=$?
    case $status in
        0 | 1) ;;
        *) echo "report: refray verify exited $status" >&2; cat "$out/log/$1.txt" >&2; exit "$status" ;;
    esac
    awk -F"$tab" -v dir="$out/tsv" 'NR == 1 { header = $0; next }
        { scene = $1 == "# fit" ? $2 : $1; n = scene; sub(/.*\//, "", n); sub(/\.scene$/, "", n)
          f = dir "/" n ".tsv"; if (!(f in seen)) { print header > f; seen[f] = 1 } print > f }' "$out/tsv/$1.all"
    over=$(awk -F"$tab" '$1 !~ /^#/ && $21 == "FAIL" { print $1 }' "$out/tsv/$1.all" | sort -u | wc -l)
    [ "$over" -eq 0 ] || echo "report: $over $1 scenes missed their tolerance at some step (see $out/log/$1.txt)"
    failed=$((failed + over))
    rm -f "$out/tsv/$1.all" "$out/$1.scenes"
}
sweep_kind sampled "samples=$light_steps"
sweep_kind deterministic "pixel-samples=$pixel_steps"

# A "# fit" line's field for one scene: fit FILE AGAINST FIELD
# (fields: 6 slope, 7 standard error, 10 meaningful, 11 expected, 12 note).
fit() {
    awk -F"$tab" -v a="$2" -v f="$3" '$1 == "# fit" && $5 == a { print $f; exit }' "$1"
}

# The legend of a curve: "name: slope -0.98 ± 0.01", or "not meaningful".
legend() {
    if [ "$(fit "$1" "$2" 10)" = 1 ]; then
        printf '%s: slope %.2f ± %.2f' "$3" "$(fit "$1" "$2" 6)" "$(fit "$1" "$2" 7)"
    else
        printf '%s (round-off)' "$3"
    fi
}

# One gnuplot "plot" clause per scene of a list: plot_list LIST XCOL AGAINST
plot_list() {
    sep=""
    while read -r name; do
        file="$out/tsv/$name.tsv"
        printf '%s"%s" skip 1 using %s:($13 > 0 ? $13 : 1e-18) with linespoints title "%s"' \
            "$sep" "$file" "$2" "$(legend "$file" "$3" "$name")"
        sep=", \\
    "
    done < "$1"
}

# Plots a list into OUTDIR/BASE.png and .svg:
#   plot_file LIST BASE XCOL AGAINST XLABEL TITLE KEY [REFERENCE]
plot_file() {
    [ -s "$1" ] || return 0
    for term in png svg; do
        if [ $term = png ]; then setterm="set terminal pngcairo size 1100,750 noenhanced"; else setterm="set terminal svg size 1100,750 noenhanced"; fi
        # pngcairo is not in gnuplot-nox: fall back to the gd png terminal.
        if [ $term = png ] && ! gnuplot -e 'set terminal pngcairo' >/dev/null 2>&1; then
            setterm="set terminal png size 1100,750 noenhanced"
        fi
        {
            echo "$setterm"
            echo "set output \"$out/$2.$term\""
            echo "set datafile separator \"\\t\""
            echo "set logscale xy"
            echo "set format y \"%.0e\""
            echo "set grid"
            echo "set key $7"
            echo "set xlabel \"$5\""
            echo "set ylabel \"RMS error against the exact image\""
            echo "set title \"$6\""
            printf 'plot '
            plot_list "$1" "$3" "$4"
            if [ -n "${8:-}" ]; then
                printf ', \\\n    %s' "$8"
            fi
            echo
        } > "$out/$2.$term.gp"
        gnuplot "$out/$2.$term.gp"
    done
}

reference='x >= 1 && x <= 1024 ? 0.2 * x**-1 : 1/0 with lines dashtype 2 lc "black" title "N^-1", x >= 1 && x <= 1024 ? 0.3 * x**-0.75 : 1/0 with lines dashtype 3 lc "gray40" title "N^-3/4"'
inside="inside bottom left box opaque"
plot_file "$out/sampled.list" error_vs_n 5 n "light samples N per distributed light" \
    "Sampled scenes: error against light samples (stratified)" "$inside" "$reference"
plot_file "$out/sampled.list" error_vs_time 18 seconds "render seconds (wall, 1 thread)" \
    "Sampled scenes: error against run time" "$inside"
plot_file "$out/deterministic.list" deterministic 5 n "camera rays per pixel k*k" \
    "Exact scenes: error at round-off at every k (0 drawn at 1e-18)" "outside right top"

# One summary row per scene from the last step of its TSV and its fits.
summary_row() {
    file="$out/tsv/$1.tsv"
    last=$(awk -F"$tab" 'NR > 1 && $1 !~ /^#/ { line = $0 } END { print line }' "$file")
    echo "$last" | awk -F"$tab" -v name="$1" -v sn="$2" -v st="$3" -v ex="$4" -v ok="$5" '{
        printf "| %s | %s | %s=%s | %.3g | %.3g | %.3g | %s | %s | %s | %s | %.3f | %s |\n",
            name, $2, $3, $4, $17, $12, $13, sn, st, ex, ok, $18, $21 }'
}

# Whether a fitted slope (with 3 standard errors and 0.05 of slack) reaches
# the expected band [-1, -0.75] of stratified sampling.
agrees() {
    awk -v s="$1" -v e="$2" 'BEGIN { lo = s - 3 * e - 0.05; hi = s + 3 * e + 0.05;
        print (hi >= -1 && lo <= -0.75) ? "yes" : "**no**" }'
}

{
    echo "# refray: error against cost over the analytic suite"
    echo
    echo "Made by \`make report\` (tests/report.sh) on $(date -u '+%Y-%m-%d %H:%M UTC') with $refray."
    echo "Sampled scenes sweep the light samples N = $light_steps; exact scenes the camera"
    echo "grid k = $pixel_steps (N = k*k); times are medians of $runs renders on one thread, with"
    echo "$jobs scenes checked side by side (REPORT_JOBS)."
    echo "Errors are against the exact image at the last step;"
    echo "slopes are least-squares fits of log RMS against log N (± one standard error)."
    echo "Expected for stratified light samples: -1 for a light seen whole (smooth integrand),"
    echo "-0.75 where a shadow edge crosses the light (Mitchell 1996); exact scenes stay at"
    echo "round-off, so their slope means nothing.  Plots: error_vs_n, error_vs_time, deterministic"
    echo "(.png, .svg); per-scene TSVs in tsv/ (columns: spec/verify.md)."
    echo
    echo "| scene | family | last step | tolerance | max abs | RMS | slope vs N | slope vs time | expected | agrees | seconds | verdict |"
    echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
    for list in sampled deterministic; do
        while read -r name; do
            file="$out/tsv/$name.tsv"
            if [ "$(fit "$file" n 10)" = 1 ]; then
                sn=$(printf '%.3f ± %.3f' "$(fit "$file" n 6)" "$(fit "$file" n 7)")
                st=$(printf '%.3f ± %.3f' "$(fit "$file" seconds 6)" "$(fit "$file" seconds 7)")
                ok=$(agrees "$(fit "$file" n 6)" "$(fit "$file" n 7)")
                ex="-1 (smooth) .. -0.75 (shadow edge)"
            else
                sn="not meaningful"
                st="not meaningful"
                ok="n/a"
                ex="none (exact)"
            fi
            summary_row "$name" "$sn" "$st" "$ex" "$ok"
        done < "$out/$list.list"
    done
    echo
    echo "Scenes over their tolerance at some step: $failed.  Report time: $(( $(date +%s) - start )) s."
} > "$out/summary.md"

rm -f "$out/sampled.list" "$out/deterministic.list"
echo "report: wrote $out/summary.md, $out/error_vs_n.{png,svg}, $out/error_vs_time.{png,svg}, $out/deterministic.{png,svg} in $(( $(date +%s) - start )) s"
