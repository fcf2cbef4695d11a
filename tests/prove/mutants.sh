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
tried=0

# function | perl substitution (one line, -0: may span lines; \x7c for a
# bar) | bug [| file under src/, render/shade.c when left out]
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
isect_sphere_roots|s/    return 2;\n\}/    return 3;\n}/|three roots|render/isect_common.c
isect_sphere_roots|s/t\[0\] = t0 < t1 \? t0 : t1;\n    t\[1\] = t0 < t1 \? t1 : t0;/t[0] = t0 < t1 ? t1 : t0;\n    t[1] = t0 < t1 ? t0 : t1;/|roots in decreasing order|render/isect_common.c
isect_sphere_roots|s/t\[0\] = -b \/ a;/t[0] = b \/ a;/|a graze on the wrong side|render/isect_common.c
isect_hit_set|s/h->shading_normal = n;/h->shading_normal = p;/|the point for the shading normal|render/isect_common.c
isect_hit_set|s/h->prim = -1;/h->prim = 0;/|prim 0|render/isect_common.c
isect_hit_set|s/vec_dot\(dir, n\) < 0\.0;/vec_dot(dir, n) <= 0.0;/|a grazing ray counted as entering|render/isect_common.c
in_interval|s/return t > r->tmin &&/return t >= r->tmin \&\&/|closed at tmin|render/intersect.c
plane_t|s/\*t = vec_dot\(n, w\) \/ dn;/*t = vec_dot(n, w) \/ (2 * dn);/|t halved|render/intersect.c
plane_t|s/return in_interval\(r, \*t\);/return in_interval(r, *t) \&\& *t > 1;/|hits before t = 1 dropped|render/intersect.c
plane_t|s/return in_interval\(r, \*t\);/return 1;/|no interval test|render/intersect.c
plane_point|s/if \(!plane_t\(p0, n, r, t\)\)\n        return 0;\n//|plane_t's answer ignored|render/intersect.c
disk_hits|s/if \(!\(vec_length2\(w\) <= radius \* radius\)\)/if (!(vec_length2(w) <= 2 * radius * radius))/|radius sqrt 2|render/intersect.c
disk_hits|s/(<= R \*\/\n    isect_hit_set\(out, )t,/$1t + 1,/|t moved after the test|render/intersect.c
box_slabs|s/ \x7c\x7c tt\[1\] <= r->tmin//|exit before tmin kept|render/intersect.c
box_slabs|s/return axis\[0\] >= 0 && tt\[0\] <= tt\[1\];/return tt[0] <= tt[1];/|a ray with no slab crossed|render/intersect.c
LIST
)

i=0
while IFS='|' read -r fn subst bug file; do
    file=${file:-render/shade.c}
    mode=wp
    [ "$file" = render/shade.c ] || mode=isect
    i=$((i + 1))
    [[ $fn =~ ${MUTANTS:-.} ]] || continue   # MUTANTS: only functions matching this
    tried=$((tried + 1))
    dir=$base/$i
    rm -rf "$dir"
    mkdir -p "$dir"
    cp -r src "$dir/src"
    perl -0pi -e "$subst" "$dir/src/$file"
    if cmp -s "src/$file" "$dir/src/$file"; then
        echo "mutant $i ($fn): the substitution did not apply"
        survivors=$((survivors + 1))
        continue
    fi
    PROVE_SRC=$dir/src PROVE_OUT=$dir PROVE_FCT=$fn PROVE_TIMEOUT=${PROVE_TIMEOUT:-5} \
        bash tests/prove/prove.sh "$mode" >"$dir/prove.log" 2>&1
    broken=$(sed -n 's/^ *unproved: typed_real_//p' "$dir/prove.log" | tr '\n' ' ')
    if [ -n "$broken" ]; then
        echo "mutant $i killed: $fn, $bug: $broken"
    else
        echo "mutant $i SURVIVED: $fn, $bug (see $dir/prove.log)"
        survivors=$((survivors + 1))
    fi
done <<<"$mutants"

[ $survivors = 0 ] && echo "prove-mutants: OK ($tried killed)" || echo "prove-mutants: $survivors of $tried survived"
[ $survivors = 0 ]
