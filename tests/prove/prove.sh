#!/usr/bin/env bash
# make prove (spec/proofs.md): Frama-C's Eva shows that no run-time error
# and no non-finite double can happen in the shading formulas under their
# preconditions, and checks the clauses that hold of the doubles; WP proves
# every contract clause in exact (real-number) arithmetic with Z3 and CVC4
# through Why3.  Prints, per function, WP goals proved / total and the Eva
# alarms and unproved clauses; exits 1 on any alarm, unproved clause or goal.
#
#   tests/prove/prove.sh [wp|eva|quick|isect|isect-eva|isect-sphere|isect-tri|isect-shapes|gappa]
#   (all but isect-shapes when no argument; isect: WP on the hit tests alone,
#   isect-eva: Eva on them; isect-sphere: Eva on isect_sphere_roots alone;
#   isect-tri: Eva on triangle_solve and the shear alone, a run of minutes;
#   isect-shapes: Eva on the cylinder, cone and torus alone;
#   PROVE_EVA_SHAPES: which of them it runs, default the torus)
# quick: the one Eva run of the shading formulas that uses vec_length,
# vec_normalize, saturating_div and scale_indices through their contracts,
# and the hit tests', the cylinder's, the cone's and the torus's (seconds; what CI runs), without
# the runs that check the functions they use by contract.
# Environment: PROVE_OUT (logs, default build/prove), PROVE_TIMEOUT (seconds
# a prover gets per goal, default 30: the slowest goal takes 0.5 s alone,
# but a loaded machine stretches wall-clock limits), PROVE_SRC (the source tree, default
# src: tests/prove/mutants.sh points it at a mutated copy), PROVE_FCT (WP
# only these functions, comma-separated), PROVE_WP_PROP (WP only these
# properties, -wp-prop), PROVE_WP_SPLIT (empty: one goal a clause, not one
# a conjunct), PROVE_WP (which WP runs: shade,
# rays or both, the default), PROVE_EVA (only the Eva runs whose names it
# lists, comma-separated), PROVE_RTE (default -wp-rte: WP proves too that
# no run-time error happens in the functions it proves; empty: not).
set -u
cd "$(dirname "$0")/../.."
out=${PROVE_OUT:-build/prove}
src=${PROVE_SRC:-src}
timeout=${PROVE_TIMEOUT:-30}
what=${1:-all}
mkdir -p "$out"
rte=()
[ -n "${PROVE_RTE--wp-rte}" ] && rte=(${PROVE_RTE--wp-rte})
# rte_for FILES: the -wp-rte options for WP on FILES.  cancel.h's polls come
# with some headers but are no function this proves (their int countdown is
# the caller's business: spec/proofs.md, "Not proved"); Frama-C stops on a
# -wp-skip-fct of a function the files do not have.
rte_for() {
    rte_opts=("${rte[@]}")
    [ ${#rte[@]} -gt 0 ] && cc -E -I"$src" -I"$out" -Itests/prove -DNDEBUG "$@" 2>/dev/null | grep -q 'cancel_stopped' &&
        rte_opts+=(-wp-skip-fct cancel_steps,cancel_now,cancel_stopped)
    return 0
}

if ! why3 config list-provers 2>/dev/null | grep -q '^Z3'; then
    why3 config detect >/dev/null 2>&1
fi

fc() { frama-c -cpp-extra-args="-I$src -I$out -Itests/prove -DNDEBUG $1" "${@:2}"; }
status=0
# The hit tests WP checks (their contracts: src/render/isect_common.h, intersect.c).
ISECT_FCT=ray_at,nearest,isect_cylinder,isect_cone,isect_torus,isect_quotient,held_root,isect_sphere_roots,sphere_refine,isect_hit_set,in_interval,plane_t,plane_point,disk_hits,box_slabs,shear_ratio,shear_set,isect_shear_make,lemma_dot_difference,lemma_plane_gap,lemma_dist_expand,lemma_square_line,lemma_dist_line,lemma_foot_scalar,lemma_foot_norm,lemma_product_square,lemma_abs_square,lemma_c_norm,lemma_norms_scalar,lemma_quadratic_scalar,lemma_quotient_times,lemma_root_qa,lemma_root_cq_ring,lemma_root_cq_cancel,lemma_root_cq,lemma_on_sphere,lemma_held_qa,lemma_held_cq,lemma_sphere_roots,lemma_product_zero,lemma_zero_gap,lemma_equal_square,lemma_graze_scalar,lemma_sphere_graze
# The cylinder, cone and torus (intersect_quadric.c, intersect_torus.c):
# the entry points and the helpers they call (their assigns clauses);
# torus_distance and torus_quartic since round 9, whose calls of hypot
# have their bounds from in_range (spec/proofs.md, "Round 9").
SHAPES_FCT=held,vec_held,in_range,axis_length,axial_of,slope_step,cone_slope,far_quotient,box_held,near_shape,cone_origin,discriminant,cone_equation,across_step,root_unscaled,cylinder_roots,side_roots,side_span,slab,solid_crossings,open_crossings,side_refine,side_normal,crossing_hit,quadric_hits,isect_cylinder_hits,isect_cone_hits,poly_eval,poly_derive,monotone_root,poly_roots,torus_distance,torus_polish,torus_quartic,isect_torus_hits

# What the shapes' Eva runs (eva_quadric.c) use by contract: proved by the
# quotient and sphere runs and eva_vec.c.
SHAPES_SPEC=isect_quotient,isect_sphere_roots,held_root,vec_length,vec_length_fast,vec_normalize

# The torus's run (tests/prove/eva_quadric.c): poly_roots' recursion
# unrolled (its calls go from degree 4 to 1), and WP on the driver after
# Eva, for the call's precondition minor < major, a relation Eva's
# intervals do not keep (the driver's test gives it).
shape_opts() {
    [ "$1" = torus ] && echo "-eva-unroll-recursive-calls 4 -then -wp -wp-fct eva_torus -wp-model real -wp-prover z3 -wp-timeout $timeout"
    return 0
}

# Eva: one driver a run.  An alarm is an assertion Eva adds; a clause is one
# of the contracts' properties in src/ that the run analyses (its status is
# then Valid, or Unknown/Invalid, which fails).  Functions a driver uses
# through their contract (-eva-use-spec) are checked by another driver.
eva_run() {   # name main skip cpp files... [-- options]; skip: functions used by contract
    local name=$1 main=$2 skip=$3 cpp=$4; shift 4
    local files=() opts=()
    while [ $# -gt 0 ] && [ "$1" != -- ]; do files+=("$1"); shift; done
    [ $# -gt 0 ] && shift
    opts=("$@")
    # before the options: a run's own options may end in -then (torus)
    [ -n "$skip" ] && opts=(-eva-use-spec "$skip" "${opts[@]}")
    fc "-DREFRAY_PROVE_EVA $cpp" "${files[@]}" tests/prove/libm.c -eva -main "$main" \
        -warn-special-float non-finite -eva-precision 3 -eva-no-show-progress \
        "${opts[@]}" -then -report-csv "$out/eva_$name.csv" >"$out/eva_$name.log" 2>&1
    local rc=$?
    local alarms
    alarms=$(sed -n 's/^ *\([0-9]*\) alarms\{0,1\} generated by the analysis.*/\1/p' "$out/eva_$name.log")
    if [ $rc -ne 0 ] || [ -z "$alarms" ]; then
        echo "eva $name: frama-c failed (exit $rc), see $out/eva_$name.log"
        return 1
    fi
    # Per function of src/ this run analyses: its contracts' clauses Eva
    # shows valid / total (Dead: never reached; Considered valid: admitted,
    # listed at the end; both count as shown), and
    # the alarms, the assertions Eva adds where it cannot exclude an error.
    awk -F'\t' -v run="$name" -v skip=",$skip," -v total="$alarms" -v badf="$out/eva_$name.bad" '
        BEGIN { alarm_kinds = "^(is_nan|division_by_zero|mem_access|index_bound|.*overflow|float_to_int|initialization|dangling|pointer_value|separation|bool_value|shift|.*pointer)" }
        NR > 1 && $1 ~ /(^|\/)src(\/|$)/ && $4 != "" && index(skip, "," $4 ",") == 0 {
            f = $4; good = $6 ~ /^(Valid|Dead|Considered valid)/
            if ($6 !~ /^Dead/) seen[f] = 1   # a function never reached is not listed
            if ($5 ~ alarm_kinds) { al[f]++; if (good) alok[f]++; else print > badf }
            else { n[f]++; if (good) ok[f]++; else print > badf }
        }
        END {
            for (f in seen) printf "  eva %-6s %-28s clauses %3d/%-3d alarms %d\n", run, f, ok[f], n[f], al[f] - alok[f]
            printf "  eva %-6s %-28s alarms %d\n", run, "(whole run)", total
        }' "$out/eva_$name.csv" | sort -k3
    if [ "$alarms" != 0 ] || [ -s "$out/eva_$name.bad" ]; then
        echo "eva $name: $alarms alarms; not shown: $(cat "$out/eva_$name.bad" 2>/dev/null | cut -f3-7)"
        rm -f "$out/eva_$name.bad"
        return 1
    fi
}

if [ "$what" = all ] || [ "$what" = eva ] || [ "$what" = quick ]; then
    start=$(date +%s)
    # The binades of the positive doubles, for the drivers that split, dealt
    # round-robin into $jobs parts analysed side by side (one frama-c each).
    jobs=${PROVE_JOBS:-2}
    for j in $(seq 1 "$jobs"); do mkdir -p "$out/part$j"; : >"$out/part$j/boxes.h"; done
    n=0
    # PROVE_KMIN, PROVE_KMAX: fewer binades (tests/prove/mutants.sh: a
    # mutant needs one box that shows it).
    { for k in $(seq "${PROVE_KMIN:--1074}" "${PROVE_KMAX:-1022}"); do echo "BOX(0x1p$k, 0x1p$((k + 1)))"; done
      [ "${PROVE_KMAX:-1022}" = 1022 ] && echo "BOX(0x1p1023, DBL_MAX)"; } | while read -r box; do
        echo "$box" >>"$out/part$((n % jobs + 1))/boxes.h"; n=$((n + 1))
    done
    # light_concentric's boxes (tests/prove/eva_render.c): s = 1/2, and
    # 1/2 -+ [2^-(m+1), 2^-m].
    # PROVE_CONCENTRIC_M: fewer (mutants.sh).
    cm=${PROVE_CONCENTRIC_M:-53}
    { echo "CBOX(0.5, 0.5)"
      for m in $(seq 1 "$cm"); do echo "CBOX(0.5 - 0x1p-$m, 0.5 - 0x1p-$((m + 1)))"; done
      for m in $(seq 1 "$((cm < 52 ? cm : 52))"); do echo "CBOX(0.5 + 0x1p-$((m + 1)), 0.5 + 0x1p-$m)"; done; } >"$out/concentric.h"
    echo "== Eva (-warn-special-float non-finite)"
    runs=("shade eva_shade saturating_div,scale_indices,vec_length,vec_normalize - $src/render/shade.c tests/prove/eva_shade.c")
    # The ray spawn functions, the camera ray, the light samples
    # (eva_render.c): helpers and samples; the functions returning a ray
    # (tmax = +Inf by design: NaN is the alarm there, every other field's
    # finiteness a clause), helpers by contract.
    runs+=("render eva_render vec_length,vec_normalize,unit_toward - tests/prove/eva_render.c $src/render/lightsample.c"
           "rays eva_rays vec_length,vec_normalize,spawn_offset,spawn_origin,shadow_tmin,screen_offset - tests/prove/eva_render.c $src/render/lightsample.c -- -warn-special-float nan"
           "hits eva_hits vec_length,vec_normalize,unit_toward,isect_part_magnitude - tests/prove/eva_render.c $src/render/lightsample.c -- -warn-special-float nan")
    [ "$what" = quick ] && jobs=0
    [ "$what" = quick ] || runs+=("concentric eva_concentric vec_length,vec_normalize - tests/prove/eva_render.c $src/render/lightsample.c")
    for j in $(seq 1 "$jobs"); do
        runs+=("split$j eva_split - -I$out/part$j tests/prove/eva_split.c" "vec$j eva_vec - -I$out/part$j tests/prove/eva_vec.c"
               "toward$j eva_toward vec_length,vec_length_fast,vec_normalize -I$out/part$j tests/prove/eva_toward.c")
    done
    if [ -n "${PROVE_EVA:-}" ]; then
        kept=()
        for r in "${runs[@]}"; do case ",$PROVE_EVA," in *",${r%% *},"*) kept+=("$r") ;; esac; done
        runs=("${kept[@]}")
    fi
    while read -r name main skip cpp files; do
        [ "$skip" = - ] && skip=""; [ "$cpp" = - ] && cpp=""
        # shellcheck disable=SC2086 # files is a list
        { eva_run "$name" "$main" "$skip" "$cpp" $files >"$out/eva_$name.sum" 2>&1
          echo $? >"$out/eva_$name.rc"; } &
        while [ "$(jobs -r | wc -l)" -ge "${PROVE_JOBS:-2}" ]; do sleep 1; done
    done < <(printf '%s\n' "${runs[@]}")
    wait
    for r in "${runs[@]}"; do
        name=${r%% *}
        cat "$out/eva_$name.sum"
        [ "$(cat "$out/eva_$name.rc" 2>/dev/null)" = 0 ] || status=1
    done
    echo "   ($(( $(date +%s) - start )) s)"
fi

# WP in the real model (floating-point operations as exact real ones; the
# doubles are Eva's).  Goal names are typed_real_<function>_<clause>,
# typed_real_lemma_<name>.  wp_run NAME PROVERS FCT FILES... (FCT: only
# these functions, or empty for all); the functions of FILES name the lines.
wp_run() {
    local name=$1 provers=$2 fct=$3; shift 3
    local start log=$out/$name.log
    start=$(date +%s)
    echo "== WP $name (-wp-model real; $provers; ${timeout} s a goal${rte:+; ${rte[0]}})"
    fct=${PROVE_FCT:-$fct}
    rte_for "$@"
    fc "" "$@" tests/prove/libm.c -wp "${rte_opts[@]}" -wp-model real ${PROVE_WP_SPLIT--wp-split} \
        -wp-prover "$provers" -wp-timeout "$timeout" -wp-par 2 ${fct:+-wp-fct "$fct"} \
        ${slow_fct:+-wp-fct-timeout "$slow_fct"} ${PROVE_WP_PROP:+-wp-prop "$PROVE_WP_PROP"} >"$log" 2>&1
    local rc=$?
    local fns
    fns=$(grep -ho '^[A-Za-z][A-Za-z0-9_ ]* \**[a-z_][a-z0-9_]*(' "$@" "$src/base/vec.h" |
          sed 's/.*[ *]\([a-z_0-9]*\)($/\1/' | sort -u | tr '\n' ' ')
    awk -v fns="$fns" '
        BEGIN { split(fns, list, " ") }
        /^\[wp\] \[[^]]*\] Goal / {
            match($0, /Goal [^ ]+/); name = substr($0, RSTART + 5, RLENGTH - 5)
            g = name; sub(/^typed_real_/, "", g); best = ""
            if (g ~ /^lemma_/) best = "(lemmas)"
            else for (i in list) if (index(g, list[i] "_") == 1 && length(list[i]) > length(best)) best = list[i]
            if (best == "") best = "(other)"
            total[best]++
            if ($0 ~ / : Valid/) ok[best]++
            else { failed = failed "    unproved: " name "\n" }
        }
        END {
            for (f in total) printf "  wp  %-30s goals %3d/%-3d\n", f, ok[f], total[f]
            printf "%s", failed
        }' "$log" | sort
    local summary proved all
    summary=$(grep 'Proved goals:' "$log")
    echo "  wp  total: ${summary#*Proved goals:}   ($(( $(date +%s) - start )) s)"
    read -r proved _ all <<<"${summary#*Proved goals:}"
    if [ $rc -ne 0 ] || [ -z "$summary" ] || [ "$proved" != "$all" ]; then
        echo "wp $name: unproved goals or frama-c failed (exit $rc), see $log"
        return 1
    fi
}

# Every goal of shade.c and of the vec.h functions it uses.
if { [ "$what" = all ] || [ "$what" = wp ]; } && [ "${PROVE_WP:-shade}" != rays ]; then
    wp_run wp z3,cvc4,cvc4-strings "" "$src/render/shade.c" || status=1
fi

# The hit tests (spec/proofs.md, "Hit tests"): CVC4 in its strings mode
# closes the nonlinear identities plain CVC4 and Z3 leave open here.
# wants LIST: PROVE_FCT is unset or names a function of LIST (a run with
# none of its functions is skipped: Frama-C stops on an unknown -wp-fct).
wants() {
    [ -z "${PROVE_FCT:-}" ] && return 0
    local f
    for f in ${PROVE_FCT//,/ }; do case ",$1," in *",$f,"*) return 0 ;; esac; done
    return 1
}
if [ "$what" = all ] || [ "$what" = isect ]; then
    if wants "$ISECT_FCT"; then
        wp_run wp_isect z3,cvc4,cvc4-strings "$ISECT_FCT" "$src/render/isect_common.c" "$src/render/intersect.c" || status=1
    fi
    # One goal a clause (PROVE_WP_SPLIT empty unless set): split, the
    # quadric's helpers alone make 1536 goals, where the whole run has 611.
    if wants "$SHAPES_FCT"; then
        # Three times the timeout for isect_torus_hits: its copy loop's
        # invariant took past 30 s at a load of 14 and 7 s of CVC4 alone
        # (spec/proofs.md, "Round 9 (proofs9-torus)"), as spawn_to_by's below.
        slow=isect_torus_hits:$((3 * timeout))
        case ",${PROVE_FCT:-isect_torus_hits}," in *,isect_torus_hits,*) ;; *) slow= ;; esac
        slow_fct=$slow PROVE_WP_SPLIT=${PROVE_WP_SPLIT-} wp_run wp_shapes z3,cvc4,cvc4-strings "$SHAPES_FCT" \
            "$src/render/intersect_quadric.c" "$src/render/intersect_torus.c" || status=1
    fi
fi

# Eva on the hit tests (spec/proofs.md, "Hit tests"; tests/prove/eva_isect.c):
# the tests with isect_quotient by its contract, and isect_quotient over
# every binade of its divisor, and isect_sphere_roots over binades of its
# direction (isect-sphere: that run alone).  isect-tri: triangle_solve
# and the shear over factor-8 boxes, minutes (not in all or quick).
if [ "$what" = all ] || [ "$what" = quick ] || [ "$what" = isect-eva ] || [ "$what" = isect-tri ] ||
    [ "$what" = isect-sphere ] || [ "$what" = isect-shapes ]; then
    start=$(date +%s)
    { for k in $(seq -1074 1022); do echo "BOX(0x1p$k, 0x1p$((k + 1)))"; done
      echo "BOX(0x1p1023, DBL_MAX)"; } >"$out/isect_boxes.h"
    # isect_sphere_roots' d: one binade a box up to 64, then 64 alone
    # (binades all the way: over a factor 8, |l| reaches 2^513 for |f| = 2^505)
    { for k in $(seq -538 5); do echo "SBOX(0x1p$k, 0x1p$((k + 1)))"; done
      echo "SBOX(64, 64)"; } >"$out/sphere_boxes.h"
    echo "== Eva, hit tests (-warn-special-float non-finite)"
    # triangle_solve and the shear (minutes): isect-tri, and all and
    # isect-eva unless PROVE_EVA leaves out tri.
    tri=0
    case "$what,${PROVE_EVA:-tri}," in isect-tri,* | all,*,tri,* | isect-eva,*,tri,* | all,tri,* | isect-eva,tri,*) tri=1 ;; esac
    if [ $tri = 1 ]; then
        for k in $(seq -1074 3 1); do echo "TBOX(0x1p$k, 0x1p$((k + 3)))"; done >"$out/shear_boxes.h"
        eva_run isect_tri eva_isect_triangle isect_quotient,vec_length,vec_length_fast,vec_normalize -DEVA_ISECT_TRIANGLE \
            tests/prove/eva_isect.c || status=1
    fi
    if [ "$what" = isect-tri ]; then
        :
    elif [ "$what" = isect-shapes ]; then
        # The shapes' runs alone (tests/prove/eva_quadric.c), as below.
        for run in ${PROVE_EVA_SHAPES:-torus}; do
            eva_run "$run" "eva_$run" "$SHAPES_SPEC" "" tests/prove/eva_quadric.c -- $(shape_opts "$run") || status=1
        done
    else
        # PROVE_EVA (names, comma-separated) keeps some of them; quick runs
        # isect alone (seconds): the binade splits take minutes.
        keep=${PROVE_EVA:-isect,quotient,sphere,cylinder,cone,torus}
        [ "$what" = quick ] && keep=${PROVE_EVA:-isect,cylinder,cone,torus}
        [ "$what" = isect-sphere ] && keep=sphere
        while read -r name main skip; do
            case ",$keep," in *",$name,"*) ;; *) continue ;; esac
            eva_run "$name" "$main" "${skip#-}" "" tests/prove/eva_isect.c || status=1
        done <<RUNS
isect eva_isect isect_quotient,vec_length,vec_length_fast,vec_normalize
quotient eva_isect_quotient -
sphere eva_isect_sphere held_root,vec_length,vec_length_fast,vec_normalize
RUNS
        # The cylinder, cone and torus (tests/prove/eva_quadric.c, seconds
        # each): 0 alarms since round 8 (the cone's since round 8d, the
        # torus's since round 9).
        for run in cylinder cone torus; do
            case ",$keep," in
            *,"$run",*) eva_run "$run" "eva_$run" "$SHAPES_SPEC" "" tests/prove/eva_quadric.c -- $(shape_opts "$run") ||
                status=1 ;;
            esac
        done
    fi
    echo "   ($(( $(date +%s) - start )) s)"
fi

# Gappa: rounding bounds of the doubles (spec/proofs.md, "Rounding bounds").
if [ "$what" = all ] || [ "$what" = quick ] || [ "$what" = gappa ]; then
    echo "== Gappa"
    for g in tests/prove/*.g; do
        name=$(basename "$g" .g)
        if gappa "$g" >"$out/gappa_$name.log" 2>&1; then
            echo "  gappa $name: the bound holds"
        else
            echo "  gappa $name: FAILED, see $out/gappa_$name.log"
            status=1
        fi
    done
fi

# WP on the ray spawn functions (intersect.c), the camera ray (camera.c) and
# the light samples (lightsample.c): only these functions of each file (the
# hit tests of intersect.c have their own run).
wp_fcts() {   # the functions proved in each file: file|functions
    cat <<LIST
$src/render/intersect.c|spawn_offset,offset_coord,spawn_origin,shadow_tmin,spawn_by,spawn,ray_spawn,ray_shadow_along,unit_toward,spawn_to_by,ray_spawn_hit_shadow,ray_spawn_hit_to,ray_shadow_start_sized,ray_shadow_start,ray_spawn_hit_sized,ray_spawn_hit
$src/render/camera.c|screen_offset,camera_half,camera_ray
$src/render/lightsample.c|light_grid_for,light_cell_point,light_concentric,light_frame
LIST
}
if { [ "$what" = all ] || [ "$what" = wp ]; } && [ "${PROVE_WP:-rays}" != shade ]; then
    start=$(date +%s)
    echo "== WP, rays and lights (-wp-model real; Z3, CVC4; ${timeout} s a goal${rte:+; ${rte[0]}})"
    while IFS='|' read -r file list; do
        [ -n "${PROVE_FCT:-}" ] && case ",$list," in *",$PROVE_FCT,"*) list=$PROVE_FCT ;; *) continue ;; esac
        log=$out/wp_$(basename "$file" .c).log
        # Three times the timeout where a clause took 4 s of CVC4 alone and
        # went past 30 s under load (a load of 10 to 17, -wp-rte's
        # assertions among its hypotheses): spawn_to_by's origin,
        # ray_spawn_hit_to's direction.
        ft=
        for f in spawn_to_by ray_spawn_hit_to; do
            case ",$list," in *,$f,*) ft=${ft:+$ft,}$f:$((3 * timeout)) ;; esac
        done
        rte_for "$file"
        fc "" "$file" tests/prove/libm.c -wp "${rte_opts[@]}" -wp-model real ${PROVE_WP_SPLIT--wp-split} -wp-prover z3,cvc4 \
            -wp-timeout "$timeout" ${ft:+-wp-fct-timeout "$ft"} -wp-par 2 -wp-fct "$list" ${PROVE_WP_PROP:+-wp-prop "$PROVE_WP_PROP"} >"$log" 2>&1
        rc=$?
        awk -v fns="${list//,/ }" '
            BEGIN { split(fns, names, " ") }
            /^\[wp\] \[[^]]*\] Goal / {
                match($0, /Goal [^ ]+/); name = substr($0, RSTART + 5, RLENGTH - 5)
                g = name; sub(/^typed_real_/, "", g); best = ""
                for (i in names) if (index(g, names[i] "_") == 1 && length(names[i]) > length(best)) best = names[i]
                if (best == "") best = "(other)"
                total[best]++
                if ($0 ~ / : Valid/) ok[best]++; else failed = failed "    unproved: " name "\n"
            }
            END { for (f in total) printf "  wp  %-30s goals %3d/%-3d\n", f, ok[f], total[f]; printf "%s", failed }' "$log" | sort
        summary=$(grep 'Proved goals:' "$log")
        read -r proved _ all <<<"${summary#*Proved goals:}"
        echo "  wp  $(basename "$file"): ${summary#*Proved goals:}"
        if [ $rc -ne 0 ] || [ -z "$summary" ] || [ "$proved" != "$all" ]; then
            echo "wp: unproved goals or frama-c failed (exit $rc), see $log"
            status=1
        fi
    done < <(wp_fcts)
    echo "   ($(( $(date +%s) - start )) s)"
fi

# Admitted clauses are assumed, not proved: listed so that none hides.
# Every file of src/, not the ones analysed: an admit anywhere is listed.
admitted=$(grep -rc 'admit ' "$src" --include='*.c' --include='*.h' | awk -F: '{n += $2} END {print n}')
echo "== admitted (assumed, not goals; spec/proofs.md): $admitted clauses"
grep -rn 'admit ' "$src" --include='*.c' --include='*.h' | sed 's/^/  /; s/ *admit ensures/ admit ensures/'

[ $status = 0 ] && echo "prove: OK" || echo "prove: FAILED"
exit $status
