# ensures.awk - the ensures clauses of the ACSL contracts of a C file, one
# line each: "function k line kind", k counted as WP numbers them (goal
# <function>_ensures for k = 1, <function>_ensures_<k> after), kind "exact"
# (EXACT: WP only), "doubles" (DOUBLES: Eva only), "both" (a bare clause),
# or "admitted" (assumed, no goal).  Used by tests/prove/mutants.sh.
/\/\*@/ { incontract = 1; n = 0; delete cl; delete kind_of }
incontract && /^[ \t]*(\/\*@)?[ \t]*(admit[ \t]+)?ensures/ {
    n++; cl[n] = FNR
    kind_of[n] = $0 ~ /admit[ \t]+ensures/ ? "admitted" : $0 ~ /ensures[ \t]+EXACT\(/ ? "exact" : \
                 $0 ~ /ensures[ \t]+DOUBLES\(/ ? "doubles" : "both"
}
incontract && /\*\// { incontract = 0; pending = n }
!incontract && pending && /^[a-z][a-z0-9_ ]*[ *]+[a-z_][a-z0-9_]*\(/ {
    name = $0; sub(/\(.*/, "", name); sub(/.*[ *]/, "", name)
    for (k = 1; k <= pending; k++) printf "%s %d %d %s\n", name, k, cl[k], kind_of[k]
    pending = 0
}
!incontract && pending && /^}/ { pending = 0 }
