#!/bin/sh
# json_read.sh - an independent reading of refray's JSON export: jq takes
# the numbers out of the document, awk composes the transform from the
# .scene's words (spec/language.md 7: first written first; rotate x, then
# y, then z, degrees, right-hand rule), traces camera rays by
# [JSON-CAMERA-1], intersects the sphere in its frame through to_local,
# shades by the conventions of spec/json.md, and compares every pixel with
# refray's render of the scene (PFM floats: 1e-6 relative).
# Run from the repository root:  sh tests/attack12/json_read.sh   # exit 1 on a mismatch
set -u
B=${B:-build/refray}
S=${S:-tests/attack12/json_ellipsoid.scene}
D=$(mktemp -d)
"$B" export "$S" --to json -o "$D/s.json" || exit 2
"$B" render "$S" -q -o "$D/r.pfm" || exit 2
J=$D/s.json
{
  jq -r '.image | "IMG \(.width) \(.height) \(.background|join(" "))"' "$J"
  jq -r '.camera | "CAM \(.eye|join(" ")) \(.fov) \(.basis.forward|join(" ")) \(.basis.right|join(" ")) \(.basis.up|join(" "))"' "$J"
  jq -r '"AMB \(.ambient|join(" "))"' "$J"
  jq -r '.materials[0] | "MAT \(.Kd|join(" ")) \(.Ks|join(" ")) \(.n)"' "$J"
  jq -r '.lights[] | select(.kind=="point") | "PL \(.position|join(" ")) \(.power|join(" ")) \(.d0) \(.falloff)"' "$J"
  jq -r '.lights[] | select(.kind=="distant") | "DL \(.direction|join(" ")) \(.power|join(" "))"' "$J"
  jq -r '.primitives[0].transform.to_world[] | "TW \(join(" "))"' "$J"
  jq -r '.primitives[0].transform.to_local[] | "TL \(join(" "))"' "$J"
  od -An -v -tf4 -w4 -j "$(($(wc -c < "$D/r.pfm") - 16*12*12))" "$D/r.pfm" | awk '{print "PX", $1}'
} | awk -v CONVFMT=%.17g -v OFMT=%.17g '
function dot(a, b) { return a[1]*b[1] + a[2]*b[2] + a[3]*b[3] }
function mul(A, B, C,   i, j, k) { for (i = 1; i <= 3; i++) for (j = 1; j <= 3; j++) { C[i, j] = 0; for (k = 1; k <= 3; k++) C[i, j] += A[i, k] * B[k, j] } }
function copy(A, B,   i, j) { for (i = 1; i <= 3; i++) for (j = 1; j <= 3; j++) B[i, j] = A[i, j] }
function rot(axis, deg, R,   c, s, i, j) {
    for (i = 1; i <= 3; i++) for (j = 1; j <= 3; j++) R[i, j] = (i == j)
    c = cos(deg * PI / 180); s = sin(deg * PI / 180)
    if (axis == 1) { R[2,2] = c; R[2,3] = -s; R[3,2] = s; R[3,3] = c }
    if (axis == 2) { R[1,1] = c; R[1,3] = s; R[3,1] = -s; R[3,3] = c }
    if (axis == 3) { R[1,1] = c; R[1,2] = -s; R[2,1] = s; R[2,2] = c }
}
BEGIN { PI = atan2(0, -1); np = 0 }
$1 == "IMG" { W = $2; H = $3; bg[1] = $4; bg[2] = $5; bg[3] = $6 }
$1 == "CAM" { for (i = 1; i <= 3; i++) { eye[i] = $(1+i); fw[i] = $(5+i); rt[i] = $(8+i); up[i] = $(11+i) } fov = $5 }
$1 == "AMB" { for (i = 1; i <= 3; i++) Ia[i] = $(1+i) }
$1 == "MAT" { for (i = 1; i <= 3; i++) { Kd[i] = $(1+i); Ks[i] = $(4+i) } nexp = $8 }
$1 == "PL" { for (i = 1; i <= 3; i++) { lp[i] = $(1+i); lE[i] = $(4+i) } d0 = $8; fall = $9 }
$1 == "DL" { for (i = 1; i <= 3; i++) { dd[i] = $(1+i); dE[i] = $(4+i) } }
$1 == "TW" { tw++; for (j = 1; j <= 4; j++) TW[tw, j] = $(1+j) }
$1 == "TL" { tl++; for (j = 1; j <= 4; j++) TL[tl, j] = $(1+j) }
$1 == "PX" { px[np++] = $2 }
END {
    # the matrix from the scene words: scale [1.5, 0.7, 1], rotate [20, 30, 10], translate [0.2, 0.1, 0]
    for (i = 1; i <= 3; i++) for (j = 1; j <= 3; j++) Sm[i, j] = 0
    Sm[1,1] = 1.5; Sm[2,2] = 0.7; Sm[3,3] = 1
    rot(1, 20, R); mul(R, Sm, T1); rot(2, 30, R); mul(R, T1, T2); rot(3, 10, R); mul(R, T2, M)
    tr[1] = 0.2; tr[2] = 0.1; tr[3] = 0; worst = 0
    for (i = 1; i <= 3; i++) { for (j = 1; j <= 3; j++) { e = M[i, j] - TW[i, j]; if (e < 0) e = -e; if (e > worst) worst = e }
        e = tr[i] - TW[i, 4]; if (e < 0) e = -e; if (e > worst) worst = e }
    printf "to_world against the scene words: max difference %.3g\n", worst
    # ambient: the two blocks summed
    printf "ambient %s %s %s (expected 0.07 0.08 0.09)\n", Ia[1], Ia[2], Ia[3]
    half = sin(0.5 * fov * PI / 180) / cos(0.5 * fov * PI / 180); aspect = H / W
    bad = 0; maxrel = 0
    for (j = 0; j < H; j++) for (i = 0; i < W; i++) {
        sx = 2 * (i + 0.5) / W - 1; sy = 1 - 2 * (j + 0.5) / H
        for (c = 1; c <= 3; c++) d[c] = fw[c] + rt[c] * sx * half + up[c] * sy * half * aspect
        l = sqrt(dot(d, d)); for (c = 1; c <= 3; c++) d[c] /= l
        for (r = 1; r <= 3; r++) { o2[r] = TL[r,4]; d2[r] = 0; for (c = 1; c <= 3; c++) { o2[r] += TL[r,c] * eye[c]; d2[r] += TL[r,c] * d[c] } }
        a = dot(d2, d2); b = dot(o2, d2); cc = dot(o2, o2) - 1; disc = b * b - a * cc
        for (c = 1; c <= 3; c++) col[c] = bg[c]
        if (disc > 0) {
            t = (-b - sqrt(disc)) / a
            if (t > 0) {
                for (c = 1; c <= 3; c++) { P[c] = eye[c] + t * d[c]; nl[c] = o2[c] + t * d2[c] }
                for (c = 1; c <= 3; c++) { N[c] = 0; for (r = 1; r <= 3; r++) N[c] += TL[r, c] * nl[r] }
                l = sqrt(dot(N, N)); for (c = 1; c <= 3; c++) { N[c] /= l; V[c] = -d[c] }
                if (dot(N, V) < 0) for (c = 1; c <= 3; c++) N[c] = -N[c]
                for (c = 1; c <= 3; c++) col[c] = Kd[c] * Ia[c]
                # point light
                for (c = 1; c <= 3; c++) L[c] = lp[c] - P[c]
                dist = sqrt(dot(L, L)); for (c = 1; c <= 3; c++) L[c] /= dist
                nd = dot(N, L)
                if (nd > 0) for (c = 1; c <= 3; c++) {
                    I = (lE[c] / (dist + d0)) / (dist + d0)
                    for (q = 1; q <= 3; q++) Rf[q] = 2 * nd * N[q] - L[q]
                    vr = dot(V, Rf); if (vr < 0) vr = 0
                    col[c] += Kd[c] * I * nd + Ks[c] * I * vr ^ nexp
                }
                for (c = 1; c <= 3; c++) L[c] = -dd[c]
                nd = dot(N, L)
                if (nd > 0) for (c = 1; c <= 3; c++) {
                    for (q = 1; q <= 3; q++) Rf[q] = 2 * nd * N[q] - L[q]
                    vr = dot(V, Rf); if (vr < 0) vr = 0
                    col[c] += Kd[c] * dE[c] * nd + Ks[c] * dE[c] * vr ^ nexp
                }
            }
        }
        for (c = 1; c <= 3; c++) {
            got = px[3 * ((H - 1 - j) * W + i) + c - 1]
            e = got - col[c]; if (e < 0) e = -e
            rel = e / (col[c] > 1e-3 ? col[c] : 1e-3)
            if (rel > maxrel) { maxrel = rel; wi = i; wj = j }
            if (rel > 1e-5) bad++
        }
    }
    printf "pixels: %d channel values off by more than 1e-5 relative; worst %.3g at (%d, %d)\n", bad, maxrel, wi, wj
    exit (bad > 0 || worst > 1e-12)
}'
rc=$?
rm -rf "$D"
exit $rc
