#!/usr/bin/env bash
# make prove-mutants (spec/proofs.md, "Mutants"): no contract is vacuous.
# Each line of tests/prove/mutants.txt is one deliberate bug in one
# function (a copy of src/ under build/prove/mutants/<i>) aimed at one of
# its ensures clauses: WP on that function alone (wp), or the Eva run named
# (eva:<run>, on fewer boxes), must then fail that clause's goal.  Prints,
# per mutant, the clause aimed at and every goal that fails; then, per
# ensures clause of the files listed, the mutant that kills it, and the
# clauses no mutant kills.  Exits 1 if a mutant misses its clause.
#   PROVE_JOBS (mutants at once, default 2), PROVE_TIMEOUT (s a goal, 5:
#   unmutated, the slowest takes 0.5 s),
#   PROVE_MUTANTS (only these numbers, e.g. "3 7 12"), PROVE_KEEP_BASELINE
#   (set: reuse the last run's list of clauses WP proves only split).
set -u
cd "$(dirname "$0")/../.."
out=${PROVE_OUT:-build/prove}
base=$out/mutants
list=tests/prove/mutants.txt

mutant() {   # i: run mutant i, write $base/<i>/result
    local i=$1 file fn k how subst bug dir broken goal
    IFS='|' read -r file fn k how subst bug < <(sed -n "${i}p" "$base/list")
    dir=$base/$i
    rm -rf "$dir"
    mkdir -p "$dir"
    cp -r src "$dir/src"
    perl -0pi -e "$subst" "$dir/src/$file"
    # k: an ensures clause (its number), another goal (its name's tail), or
    # `any`: the goal is then the pattern ${fn}_*, any goal of the function
    # (a mutant that shows the contract as a whole is not vacuous, aimed at
    # no one clause).  A goal is a glob pattern matched against whole names.
    case $k in
    1) goal=${fn}_ensures prop=@ensures ;;
    [0-9]*) goal=${fn}_ensures_$k prop=@ensures ;;
    any) goal="${fn}_*" prop= ;;
    *) goal=${fn}_$k prop= ;;
    esac
    if cmp -s "src/$file" "$dir/src/$file"; then
        echo "MISSED|$i|$file|$fn|$goal|$bug|the substitution did not apply" >"$dir/result"
        return
    fi
    case $how in
    wp)
        case $file in render/shade.c|base/vec.h) wp=shade ;; *) wp=rays ;; esac
        # One goal a clause (fast), but split where the unmutated clause
        # needs it to be proved (the baseline's list): else a clause the
        # provers cannot close whole would pass for killed.
        split=
        [ -n "$prop" ] && grep -qx "$goal" "$base/hard" && split=-wp-split
        [ -z "$prop" ] && split=-wp-split
        PROVE_SRC=$dir/src PROVE_OUT=$dir PROVE_FCT=$fn PROVE_WP=$wp PROVE_WP_PROP=$prop PROVE_WP_SPLIT=$split \
            PROVE_TIMEOUT=${PROVE_TIMEOUT:-5} \
            bash tests/prove/prove.sh wp >"$dir/prove.log" 2>&1
        broken=$(sed -n 's/^ *unproved: typed_real_//p' "$dir/prove.log" | sed 's/_part[0-9]*$//' | sort -u | tr '\n' ' ')
        ;;
    isect)
        # The hit tests' run (prove.sh isect: CVC4's strings mode too).
        PROVE_SRC=$dir/src PROVE_OUT=$dir PROVE_FCT=$fn PROVE_TIMEOUT=${PROVE_TIMEOUT:-10} \
            bash tests/prove/prove.sh isect >"$dir/prove.log" 2>&1
        broken=$(sed -n 's/^ *unproved: typed_real_//p' "$dir/prove.log" | sed 's/_part[0-9]*$//' | sort -u | tr '\n' ' ')
        ;;
    eva:*)
        run=${how#eva:}
        PROVE_SRC=$dir/src PROVE_OUT=$dir PROVE_EVA=${run}1,$run PROVE_JOBS=1 PROVE_KMIN=-4 PROVE_KMAX=4 \
            PROVE_CONCENTRIC_M=2 bash tests/prove/prove.sh eva >"$dir/prove.log" 2>&1
        # Eva's clauses that fail, as WP names them (by their line), and alarms
        broken=$(awk -F'\t' -v fn="$fn" -v base="$(basename "$file")" '
            NR == FNR { if ($1 == fn) k[$3] = $2; next }
            $1 ~ /(^|\/)src(\/|$)/ && $6 !~ /^(Valid|Dead|Considered valid)/ {
                if ($2 == base && $4 == fn && $5 == "postcondition" && ($3 in k)) print fn "_ensures" (k[$3] == 1 ? "" : "_" k[$3])
                else if ($2 == base && $4 == fn || $5 == "is_nan_or_infinite") print $4 "_" $5 "@" $3
            }' <(awk -f tests/prove/ensures.awk "$dir/src/$file" | tr ' ' '\t') "$dir"/eva_*.csv 2>/dev/null |
            sort -u | tr '\n' ' ')
        ;;
    esac
    # An alarm (the runs have none) is where Eva cannot show a double
    # finite: it kills the clause that says the result is finite.
    clause=$(awk -f tests/prove/ensures.awk "$dir/src/$file" | awk -v fn="$fn" -v k="$k" '$1 == fn && $2 == k {print $3}')
    if [[ $how == eva:* && " $broken " == *_is_nan_or_infinite@* ]] &&
        sed -n "${clause:-0}p" "$dir/src/$file" | grep -q 'finite\|vcolour'; then
        broken="$goal(by the alarm) $broken"
    fi
    # shellcheck disable=SC2053 # $goal is a pattern
    if [[ " $broken " == *" "$goal[\ \(]* ]]; then
        echo "KILLED|$i|$file|$fn|$goal|$bug|$broken" >"$dir/result"
    else
        echo "MISSED|$i|$file|$fn|$goal|$bug|${broken:-nothing fails} (see $dir/prove.log)" >"$dir/result"
    fi
}

if [ "${1:-}" = --one ]; then
    mutant "$2"
    exit 0
fi

start=$(date +%s)
mkdir -p "$base"
# Mutant i is line i; a line @N numbers the next one N, the lines between
# reserved (sessions working side by side each take their own numbers).
grep -v '^#' "$list" | grep -v '^ *$' | awk '
    /^@[0-9]+$/ { want = substr($0, 2) - 1
                  if (n > want) { print "mutants.txt: " $0 " but " n " mutants before it" > "/dev/stderr"; exit 1 }
                  while (n < want) { print "-|-|-|reserved|-|-"; n++ }
                  next }
    { print; n++ }' >"$base/list" || exit 1
numbers=$(grep -vn '^-|-|-|reserved|' "$base/list" | cut -d: -f1 | tr '\n' ' ')
# Baseline: the ensures clauses WP does not prove unmutated when each is
# one goal (not split into its conjuncts); their mutants run split.
if [ ! -f "$base/hard" ] || [ -z "${PROVE_KEEP_BASELINE:-}" ]; then
    PROVE_OUT=$base/baseline PROVE_WP_SPLIT= PROVE_WP_PROP=@ensures PROVE_TIMEOUT=${PROVE_TIMEOUT:-5} \
        bash tests/prove/prove.sh wp >"$base/baseline.log" 2>&1
    sed -n 's/^ *unproved: typed_real_//p' "$base/baseline.log" | sort -u >"$base/hard"
fi
# shellcheck disable=SC2086 # a list of numbers
printf '%s\n' ${PROVE_MUTANTS:-$numbers} | xargs -P "${PROVE_JOBS:-2}" -I{} bash "$0" --one {}
missed=0 total=0
for i in ${PROVE_MUTANTS:-$numbers}; do
    IFS='|' read -r verdict _ file fn goal bug broken <"$base/$i/result"
    total=$((total + 1))
    [ "$verdict" = KILLED ] || missed=$((missed + 1))
    printf 'mutant %3d %s: %s %s (%s): %s\n' "$i" "$verdict" "$file" "$goal" "$bug" "$broken"
done
# Coverage: every ensures clause (admitted ones have no goal) of the files
# that have mutants, and the mutant that kills it.
echo "== ensures clauses and their mutants"
files=$(grep -v '^#' "$list" | grep -v '^ *$' | grep -v '^@' | cut -d'|' -f1 | sort -u)
covered=0 clauses=0
for f in $files; do
    while read -r fn k _ kind; do
        [ "$kind" = admitted ] && continue
        # k: an ensures clause (its number), or another goal (its name's tail)
    case $k in
    1) goal=${fn}_ensures prop=@ensures ;;
    [0-9]*) goal=${fn}_ensures_$k prop=@ensures ;;
    *) goal=${fn}_$k prop= ;;
    esac
        clauses=$((clauses + 1))
        killers=$(grep -l "^KILLED|[0-9]*|$f|[^|]*|$goal|" "$base"/*/result 2>/dev/null | sed 's|.*/\([0-9]*\)/result|\1|' | sort -n | tr '\n' ' ')
        if [ -n "$killers" ]; then covered=$((covered + 1)); else killers="NONE"; fi
        printf '  %-24s %-34s %-7s mutant %s\n' "$f" "$goal" "$kind" "$killers"
    done < <(awk -f tests/prove/ensures.awk "src/$f")
done
echo "prove-mutants: $((total - missed)) of $total mutants kill their clause; $covered of $clauses ensures clauses killed ($(( $(date +%s) - start )) s)"
[ $missed = 0 ]
