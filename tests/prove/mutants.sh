#!/usr/bin/env bash
# make prove-mutants (spec/proofs.md, "Mutants"): the contracts are not
# vacuous.  Each mutant is one deliberate bug in one function of
# src/render/shade.c (a copy under build/prove/mutants); WP on that function
# must then leave at least one goal unproved.  Prints the goals each mutant
# breaks; exits 1 if a mutant survives (every goal still proved).
set -u
cd "$(dirname "$0")/../.."
base=${PROVE_OUT:-build/prove}/mutants
survivors=0

# function | perl substitution on shade.c (one line, -0: may span lines) | bug
mutants=$(cat <<'LIST'
shade_lambert|s/(real c = vec_dot\(n, l\);\n)    if \(!\(c > 0\.0\)\)\n        return 0\.0;\n/$1/|the N.L > 0 gate removed
shade_refract|s/if \(!\(k >= 0\.0\)\) \{/if (0) {/|the TIR test removed
shade_refract|s/if \(!\(k >= 0\.0\)\) \{/if (!(k > 0x1p-20)) {/|TIR also for 0 <= k <= 2^-20
shade_phong_lobe|s/(real c = vec_dot\(v, r\), rel;\n)    if \(!\(c > 0\.0\)\)\n        return 0\.0;\n/$1/|the V.R > 0 gate removed
shade_specular|s/if \(!\(vec_dot\(n, l\) > 0\.0\)\)/if (0)/|the N.L > 0 gate removed
shade_specular|s/vec3 r = shade_reflect_about\(l, n\);/vec3 r = l;/|the lobe taken about L, not R
shade_falloff|s/s = d \+ d0;/s = d + d0 + 1;/|d0 counted twice
shade_ambient|s/return vec_mul\(kd, ia\);/return vec_add(kd, ia);/|Kd + Ia for Kd Ia
shade_diffuse|s/vec_scale\(vec_mul\(kd, intensity\), shade_lambert\(n, l\)\)/vec_scale(vec_mul(kd, intensity), vec_dot(n, l))/|N.L unclamped
shade_face_forward|s/vec_dot\(n, v\) < 0\.0 \?/vec_dot(n, v) > 0.0 ?/|flipped the wrong way
shade_mirror|s/vec_madd\(d, n, -2\.0 \* vec_dot\(n, d\)\)/vec_madd(d, n, -1.0 * vec_dot(n, d))/|half the normal part
shade_reflect_about|s/vec_scale\(n, 2\.0 \* vec_dot\(n, l\)\)/vec_scale(n, vec_dot(n, l))/|half the normal part
shade_sample_power|s/power\.y \/ samples/power.y \/ (samples + 1)/|one sample too many
shade_critical_angle_cos|s/c = below;/c = 0.5 * below;/|steps past the critical cosine
shade_transmit_blend|s/vec_scale\(front, 1\.0 - t\)/vec_scale(front, t)/|front weighted by t
shade_local|s/saturating_sum\(highlight, vec_scale\(body, 1\.0 - t\)\)/saturating_sum(highlight, body)/|body not scaled by 1 - t
shade_combine|s/vec_mul\(ks, mirrored\)/mirrored/|mirror term without Ks
saturate1|s/return x > DBL_MAX \? DBL_MAX : x;/return x;/|no cap in shade_saturate's channel
shade_shadow_transmission|s/return carried \* t_occluder;/return carried + t_occluder;/|sum for product
LIST
)

i=0
while IFS='|' read -r fn subst bug; do
    i=$((i + 1))
    dir=$base/$i
    rm -rf "$dir"
    mkdir -p "$dir"
    cp -r src "$dir/src"
    perl -0pi -e "$subst" "$dir/src/render/shade.c"
    if cmp -s src/render/shade.c "$dir/src/render/shade.c"; then
        echo "mutant $i ($fn): the substitution did not apply"
        survivors=$((survivors + 1))
        continue
    fi
    PROVE_SRC=$dir/src PROVE_OUT=$dir PROVE_FCT=$fn PROVE_TIMEOUT=${PROVE_TIMEOUT:-5} \
        bash tests/prove/prove.sh wp >"$dir/prove.log" 2>&1
    broken=$(sed -n 's/^ *unproved: typed_real_//p' "$dir/prove.log" | tr '\n' ' ')
    if [ -n "$broken" ]; then
        echo "mutant $i killed: $fn, $bug: $broken"
    else
        echo "mutant $i SURVIVED: $fn, $bug (see $dir/prove.log)"
        survivors=$((survivors + 1))
    fi
done <<<"$mutants"

[ $survivors = 0 ] && echo "prove-mutants: OK ($i killed)" || echo "prove-mutants: $survivors of $i survived"
[ $survivors = 0 ]
