/*
 * shade.h - the seed's shading formulas, one small pure function each.
 *
 * Every function here is a formula of spec/shading.md and nothing more: no
 * scene, no rays, no recursion (trace.c puts them together).  All vectors
 * are in world space; "unit" means length 1 up to rounding.  Colours are rgb
 * (vec3 read as r,g,b) and every colour formula works channel by channel.
 *
 * Conventions shared by all functions (spec/shading.md, "Conventions"):
 *   n  unit shading normal, already turned to face the viewer;
 *   l  unit vector from the surface point TOWARD the light;
 *   v  unit vector from the surface point toward the viewer (V = -D);
 *   d  unit direction a ray travels (incoming: pointing INTO the surface).
 */
#ifndef REFRAY_SHADE_H
#define REFRAY_SHADE_H

#include "base/vec.h"
#include "scene/scene.h"

/*
 * The formulas in the exact (real-number) arithmetic of the contracts in
 * shade.c (spec/proofs.md); what a lemma states WP proves once.
 */
/*@
  // First: a lemma is proved with the lemmas before it as hypotheses, and
  // quantified ones keep Z3 from its nonlinear procedure.  Every block has
  // a symbol of its own: WP gives a block's lemmas only to the goals that
  // use one of its symbols, and those of a block without any to every goal.
  axiomatic Unit {
  predicate unit_pair(vec3 v, vec3 r) = vnorm2(v) == 1 && vnorm2(r) == 1;
  // |V - R|^2 = 2 - 2 V.R for unit V, R: lobe_cosine's h is then 1 - V.R
  // (written out: through vnorm2 and vdot the provers do not close it)
  lemma unit_difference:
      \forall vec3 d, v, r; d.x == v.x - r.x && d.y == v.y - r.y && d.z == v.z - r.z &&
          v.x * v.x + v.y * v.y + v.z * v.z == 1 && r.x * r.x + r.y * r.y + r.z * r.z == 1 ==>
          d.x * d.x + d.y * d.y + d.z * d.z == 2 - 2 * (v.x * r.x + v.y * r.y + v.z * r.z);
  }

  // [SHADE-FALLOFF-1, 2]; s = d + d0 (the code caps it at DBL_MAX, [SHADE-FALLOFF-5]).
  // (Each axiomatic block holds definitions and lemmas, no axiom: WP gives
  // its lemmas as hypotheses only to goals that use its symbols.)
  axiomatic Falloff {
  logic mreal falloff_of(mreal e, mreal s, integer kind) =
      kind == FALLOFF_LINEAR ? e / s : e / s / s;

  lemma half_ratio: \forall mreal e, s; s > 0 ==> (0.5 * e) / (0.5 * s) == e / s;

  lemma falloff_positive:
      \forall mreal e, s, integer kind; e > 0 && s > 0 ==> falloff_of(e, s, kind) > 0;
  lemma falloff_nonincreasing:
      \forall mreal e, s1, s2, integer kind; e >= 0 && 0 < s1 <= s2 ==>
          falloff_of(e, s2, kind) <= falloff_of(e, s1, kind);
  }

  // n2^2 cos^2 th2 (Snell, [SHADE-SNELL-2]): negative exactly on total internal reflection
  axiomatic Snell {
  logic mreal snell_k(mreal n1, mreal n2, mreal c) = (n1 * c) * (n1 * c) - (n1 * n1 - n2 * n2);

  lemma snell_k_rescaled:
      \forall mreal n1, n2, s1, s2, c; s1 * n2 == s2 * n1 ==>
          snell_k(s1, s2, c) * (n1 * n1) == snell_k(n1, n2, c) * (s1 * s1);
  lemma same_sign:
      \forall mreal a, b, p, q; p > 0 && q > 0 && a * p == b * q ==> (a < 0 <==> b < 0);
  lemma snell_k_scaled:
      \forall mreal n1, n2, s1, s2, c; n1 > 0 && s1 > 0 && s1 * n2 == s2 * n1 ==>
          (snell_k(s1, s2, c) < 0 <==> snell_k(n1, n2, c) < 0);
  }

  // k grows with the cosine: below a cosine that reflects, every one
  // reflects (written out first: among Snell's lemmas the provers do not
  // close it from the helpers).  step_below(c): at
  // most one nextafter step below c (tests/prove/libm.c), or 0.
  axiomatic SnellMonotone {
  logic mreal step_below(mreal c) = \max(0, c - 0x1p-52 * c - 0x1p-1074);
  lemma square_monotone: \forall mreal a, b; 0 <= a <= b ==> a * a <= b * b;
  lemma scaled_monotone: \forall mreal x, p, q; p <= q ==> (x * x) * p <= (x * x) * q;
  lemma snell_poly_monotone:
      \forall mreal n1, n2, a, b; 0 <= a <= b ==>
          (n1 * a) * (n1 * a) - (n1 * n1 - n2 * n2) <= (n1 * b) * (n1 * b) - (n1 * n1 - n2 * n2);
  lemma snell_k_monotone:
      \forall mreal n1, n2, a, b; 0 <= a <= b ==> snell_k(n1, n2, a) <= snell_k(n1, n2, b);
  }

  // [SHADE-PHONG-1..4] x^y, kept abstract: no axiom, and outside Why3's
  // power theory, whose presence stalls Z3 and CVC4 on the callers' goals
  // (spec/proofs.md).  tests/prove/libm.c declares it too (the same block)
  // and ties pow to it; the lobe is (V.R)^n, the cosine at most 1, flushed
  // to 0 below DBL_MIN and capped at 1 as the code does.
  axiomatic RealPow {
  logic mreal real_pow(mreal x, mreal y);
  }
  logic mreal phong_of(mreal c, mreal n) =
      real_pow(\min(c, 1), n) >= DBL_MIN ? \min(real_pow(\min(c, 1), n), 1) : 0;

  // cos th1 = -N.D, clamped to [0, 1]
  logic mreal incidence(vec3 d, vec3 n) = \max(0, \min(1, -vdot(n, d)));

  // [SHADE-REFLECT-1] R = 2(N.L)N - L
  logic vec3 reflected(vec3 l, vec3 n) =
      {l \with .x = (real)(2 * vdot(n, l) * n.x - l.x), .y = (real)(2 * vdot(n, l) * n.y - l.y),
                .z = (real)(2 * vdot(n, l) * n.z - l.z)};

  // [SHADE-MIRROR-1]
  predicate is_mirror(vec3 t, vec3 d, vec3 n) =
      t.x == d.x - 2 * vdot(n, d) * n.x && t.y == d.y - 2 * vdot(n, d) * n.y && t.z == d.z - 2 * vdot(n, d) * n.z;

  // [SHADE-LOCAL-1] with [SHADE-SAT-1]: a sum of colours is exact unless it
  // passes DBL_MAX, and never larger than exact (in exact arithmetic a sum
  // of reals may pass DBL_MAX where one of doubles cannot: the cap itself,
  // and that the result is finite, are shown by Eva for the doubles)
  predicate capped(mreal c, mreal sum) = c <= sum && (sum <= DBL_MAX ==> c == sum);
  predicate is_local(vec3 c, vec3 body, vec3 highlight, mreal t) =
      capped(c.x, highlight.x + (1 - t) * body.x) && capped(c.y, highlight.y + (1 - t) * body.y) &&
      capped(c.z, highlight.z + (1 - t) * body.z);
  // [SHADE-BLEND-1]
  predicate blended(vec3 c, vec3 front, vec3 back, mreal t) =
      capped(c.x, (1 - t) * front.x + t * back.x) && capped(c.y, (1 - t) * front.y + t * back.y) &&
      capped(c.z, (1 - t) * front.z + t * back.z);
  // [SHADE-HIT-1]
  predicate is_combined(vec3 c, vec3 body, vec3 highlight, vec3 ks, mreal t, vec3 m, vec3 tr) =
      capped(c.x, highlight.x + (1 - t) * body.x + ks.x * m.x + t * tr.x) &&
      capped(c.y, highlight.y + (1 - t) * body.y + ks.y * m.y + t * tr.y) &&
      capped(c.z, highlight.z + (1 - t) * body.z + ks.z * m.z + t * tr.z);
*/

/* One light's share of a hit's colour, kept in the two parts the
 * transparency blend treats differently (local = (1 - t) * body + highlight). */
typedef struct shade_terms {
    rgb body;       /* diffuse: Kd * I * max(0, N.L); scaled by (1 - t) later */
    rgb highlight;  /* specular: Ks * I * max(0, V.R)^n; never scaled by (1 - t) */
} shade_terms;

/* [SHADE-AMBIENT-1] R_a = Kd * I_a per channel (slide 11). */
rgb shade_ambient(rgb kd, rgb ia);

/*
 * [SHADE-FALLOFF-1..5] Light arriving from a source of power E at distance d:
 * linear E/(d+d0) (slides 16-17, the default), inverse square E/(d+d0)^2
 * (slide 16 with slide 17's d0 guard), none E.  Defensive: when d + d0 is not
 * > 0 (or is NaN) the power is returned unchanged, and a result too large for
 * a double is clamped to DBL_MAX, so the result is never Inf or NaN.
 */
rgb shade_falloff(rgb power, real d, real d0, scene_falloff falloff);

/* [SHADE-SAMPLE-1] Power of one of `samples` >= 1 point sources of a
 * distributed light (slides 3, 5): E/samples. */
rgb shade_sample_power(rgb power, int samples);

/* [SHADE-FACE-1] N turned toward v: n when n.v >= 0, else -n (surfaces are lit on the side seen). */
vec3 shade_face_forward(vec3 n, vec3 v);

/* [SHADE-LAMBERT-1,2] max(0, N.L) clamped to [0, 1]: exactly 0 at and below
 * the horizon (slide 13).  A NaN dot product gives 0. */
real shade_lambert(vec3 n, vec3 l);

/* [SHADE-DIFFUSE-1] Kd * I * max(0, N.L) (slides 17-19, k_d not slide 19's k_s). */
rgb shade_diffuse(rgb kd, rgb intensity, vec3 n, vec3 l);

/* [SHADE-REFLECT-1] R = 2(N.L)N - L: the light vector mirrored about n
 * (slides 24-28).  Both arguments unit; the result is unit. */
vec3 shade_reflect_about(vec3 l, vec3 n);

/* [SHADE-MIRROR-1] The mirror direction of a travelling direction d:
 * D - 2(N.D)N.  Works for either orientation of n. */
vec3 shade_mirror(vec3 d, vec3 n);

/*
 * [SHADE-PHONG-1..4] The Phong lobe max(0, V.R)^shininess (slides 25-28):
 * 0 when V.R <= 0 (or NaN), whatever the exponent (so shininess 0 gives 1 in
 * front and 0 behind); V.R >= 1 (rounding) gives exactly 1; results below
 * DBL_MIN are flushed to 0, so no subnormal leaves here.  shininess >= 0.
 */
real shade_phong_lobe(vec3 v, vec3 r, real shininess);

/* [SHADE-SPEC-1] Ks * I * lobe(V, R) with R = shade_reflect_about(l, n);
 * exactly 0 when N.L <= 0 (slide 47). */
rgb shade_specular(rgb ks, rgb intensity, vec3 v, vec3 n, vec3 l, real shininess);

/*
 * [SHADE-DIRECT-1] One light's term of the comprehensive formula (slides
 * 29-33, with slide 28's attenuation of both parts): body = shade_diffuse,
 * highlight = shade_specular.  `intensity` is what reaches the point: the
 * falloff times the shadow transmission S.  Both parts are 0 when N.L <= 0.
 */
shade_terms shade_direct(rgb kd, rgb ks, real shininess, rgb intensity, vec3 n, vec3 l,
                         vec3 v);

/*
 * [SHADE-SNELL-1..4] Snell refraction n1 sin(th1) = n2 sin(th2) (slide 36).
 * d: unit incoming direction; n: unit normal facing against d (n.d <= 0; a
 * slightly positive n.d from rounding counts as grazing); n1: index on d's
 * side, n2 on the far side, both > 0 and finite.  Returns 1 and the unit
 * transmitted direction in *t; returns 0 on total internal reflection and
 * puts the mirror direction shade_mirror(d, n) in *t.  The TIR decision is
 * the sign of (n1 cos th1)^2 - (n1^2 - n2^2) evaluated in twice the working precision (double-double), so
 * cos th1 >= shade_critical_angle_cos(n1, n2) refracts and anything smaller
 * reflects, to the last bit.  n1 == n2 returns 1 with *t = d bit for bit.
 */
int shade_refract(vec3 d, vec3 n, real n1, real n2, vec3 *t);

/*
 * [SHADE-CRIT-1] The critical cosine rounded up: the least real c (the working type) in
 * [0, 1] for which shade_refract refracts a ray with cos th1 = c.  0 when
 * n1 <= n2 (no total internal reflection is possible).
 */
real shade_critical_angle_cos(real n1, real n2);

/* [SHADE-BLEND-1] (1 - t) * front + t * back (slide 37 with t = transparency:
 * 0 opaque, 1 clear).  Exactly front at t = 0 and exactly back at t = 1. */
rgb shade_transmit_blend(rgb front, rgb back, real t);

/* [SHADE-LOCAL-1] The local colour (1 - t) * body + highlight: what a hit
 * shows without secondary rays, and what is kept past max_depth. */
rgb shade_local(rgb body, rgb highlight, real t);

/*
 * [SHADE-HIT-1] The whole per-hit colour of the model:
 *   (1 - t) * body + highlight + Ks * mirrored + t * transmitted
 * where mirrored is the colour traced along the mirror ray and transmitted
 * the colour along the refracted ray (or along the mirror ray on total
 * internal reflection).  Pass zero for a ray not traced (past max_depth,
 * Ks = 0, t = 0): the result is then exactly shade_local.  Saturated
 * ([SHADE-SAT-1]): four terms of up to DBL_MAX each cannot overflow to Inf.
 */
rgb shade_combine(rgb body, rgb highlight, rgb ks, real t, rgb mirrored, rgb transmitted);

/* [SHADE-SAT-1] Saturation: a channel above DBL_MAX (that is, +Inf from a
 * sum of large finite terms) becomes DBL_MAX; NaN is kept, so the tracer's
 * non-finite counter still sees it.  shade_local and shade_combine
 * saturate their result; the tracer saturates its own sums with this. */
rgb shade_saturate(rgb c);

/* [SHADE-SHADOW-1] Shadow transmission product rule (slide 47): what is left
 * of `carried` after crossing one more surface of transparency t_occluder in
 * [0, 1].  Start from 1; an opaque crossing gives 0 and the rest stays 0. */
real shade_shadow_transmission(real carried, real t_occluder);

#endif
