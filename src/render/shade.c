/*
 * shade.c - the seed's shading formulas (spec/shading.md has the table of
 * slide -> formula -> function -> test).
 *
 * Invariants: every function is pure (no state, no allocation); inputs the
 * scene validator proves (0 <= Kd, Ks, t <= 1, shininess >= 0, ior > 0) are
 * asserted; conditions that can still happen in a stiff scene (a light at
 * the hit point, a dot product a hair outside [-1, 1]) are handled by
 * defensive checks named as such, never by NaN or Inf.
 */
#include <assert.h>
#include <float.h>
#include <math.h>
#include "render/shade.h"

rgb shade_ambient(rgb kd, rgb ia)
{
    return vec_mul(kd, ia);
}

/* Defensive: an intensity too large for a double becomes DBL_MAX rather than
 * Inf, so that a zero Kd or shadow factor later gives 0, not Inf*0 = NaN. */
static rgb clamp_finite(rgb c)
{
    return vec_min(c, vec_splat(DBL_MAX));
}

rgb shade_falloff(rgb power, real d, real d0, scene_falloff falloff)
{
    real s = d + d0;
    if (falloff == FALLOFF_NONE)
        return power;
    /* Defensive: the validator (d0 >= 0) and the tracer (hits leave the
     * light) keep s > 0; a light exactly on the surface with d0 = 0 gives
     * s = 0, where L is undefined anyway: return E rather than Inf. */
    if (!(s > 0.0))
        return power;
    /* E/s/s, not E/(s*s): s*s underflows to 0 for s < 1e-162. */
    rgb linear = vec_make(power.x / s, power.y / s, power.z / s);
    if (falloff == FALLOFF_LINEAR)
        return clamp_finite(linear);
    return clamp_finite(vec_make(linear.x / s, linear.y / s, linear.z / s));
}

rgb shade_sample_power(rgb power, int samples)
{
    assert(samples >= 1);
    return vec_make(power.x / samples, power.y / samples, power.z / samples);
}

vec3 shade_face_forward(vec3 n, vec3 v)
{
    return vec_dot(n, v) < 0.0 ? vec_neg(n) : n;
}

/* `c > 0` is false for NaN too, so a degenerate L (the zero vector that
 * vec_normalize returns for a light at the point) contributes nothing. */
real shade_lambert(vec3 n, vec3 l)
{
    real c = vec_dot(n, l);
    if (!(c > 0.0))
        return 0.0;
    return c < 1.0 ? c : 1.0;
}

rgb shade_diffuse(rgb kd, rgb intensity, vec3 n, vec3 l)
{
    return vec_scale(vec_mul(kd, intensity), shade_lambert(n, l));
}

/* R = 2(N.L)N - L: the component of L along N is kept, the rest negated. */
vec3 shade_reflect_about(vec3 l, vec3 n)
{
    return vec_sub(vec_scale(n, 2.0 * vec_dot(n, l)), l);
}

/* D - 2(N.D)N: the component of D along N is negated, the rest kept.  The
 * sign of n cancels ((-N.D)(-N) = (N.D)N), so either orientation works. */
vec3 shade_mirror(vec3 d, vec3 n)
{
    return vec_madd(d, n, -2.0 * vec_dot(n, d));
}

/*
 * The lobe is cos^n of the angle between v and r.  For a large n every ulp
 * of the cosine is n ulps of the lobe, and the plain dot product V.R carries
 * the rounding of the unit vectors' lengths (|V| = 1 +- eps moves V.R by
 * eps), which has nothing to do with the angle: with n = 1e6 that alone is
 * a relative error of 1e-10.  So for angles below 41 degrees (h < 1/4) the
 * cosine is formed from h = 1 - cos = |V - R|^2 / (2 |V| |R|), in which the lengths
 * cancel to second order and V - R is exact (Sterbenz) for nearby vectors,
 * and kept as a sum c_hi + c_lo = 1 - h held exactly; then
 *   (c_hi + c_lo)^n = c_hi^n (1 + c_lo/c_hi)^n = pow(c_hi, n) exp(n c_lo/c_hi)
 * to first order in c_lo/c_hi < 2^-52.  pow of a double that is exactly the
 * cosine (V = R: c_hi = 1, c_lo = 0) stays exact.  Measured in
 * spec/numerics.md ("Phong lobe").
 */
static void lobe_cosine(vec3 v, vec3 r, real c, real *c_hi, real *c_lo)
{
    vec3 d = vec_sub(v, r);
    real h = vec_dot(d, d) / (2 * sqrt(vec_dot(v, v) * vec_dot(r, r)));
    if (h < 0.25) {
        *c_hi = 1 - h;
        *c_lo = (1 - *c_hi) - h;   /* exact: 1 - c_hi is (Sterbenz) */
    } else {
        *c_hi = c;                 /* far from the peak V.R is as good */
        *c_lo = 0;
    }
}

real shade_phong_lobe(vec3 v, vec3 r, real shininess)
{
    assert(shininess >= 0.0);
    real c = vec_dot(v, r), c_hi, c_lo;
    if (!(c > 0.0))
        return 0.0;
    if (shininess == 0)
        return 1.0;
    lobe_cosine(v, r, c, &c_hi, &c_lo);
    /* Subnormal results (below 2.2e-308) are invisible and slow: flush. */
    real p = pow(c_hi, shininess);
    if (c_lo != 0)
        p *= exp(shininess * (c_lo / c_hi));
    return p >= DBL_MIN ? p : 0.0;
}

rgb shade_specular(rgb ks, rgb intensity, vec3 v, vec3 n, vec3 l, real shininess)
{
    if (!(vec_dot(n, l) > 0.0))
        return vec_splat(0.0);
    vec3 r = shade_reflect_about(l, n);
    return vec_scale(vec_mul(ks, intensity), shade_phong_lobe(v, r, shininess));
}

shade_terms shade_direct(rgb kd, rgb ks, real shininess, rgb intensity, vec3 n, vec3 l,
                         vec3 v)
{
    shade_terms s;
    s.body = shade_diffuse(kd, intensity, n, l);
    s.highlight = shade_specular(ks, intensity, v, n, l, shininess);
    return s;
}

/* Error-free product (fma rounds once): a*b == result + *err exactly. */
static real two_prod(real a, real b, real *err)
{
    real p = a * b;
    *err = fma(a, b, -p);
    return p;
}

/* Error-free sum (Knuth's TwoSum, no ordering needed): a+b == result + *err. */
static real two_sum(real a, real b, real *err)
{
    real s = a + b;
    real bb = s - a;
    *err = (a - (s - bb)) + (b - bb);
    return s;
}

/* Scales n1, n2 by one power of two so that the larger lies in [0.5, 1):
 * exact, so it changes no sign or ratio, and the squares below cannot
 * overflow for any finite index. */
static void scale_indices(real n1, real n2, real *s1, real *s2)
{
    int e;
    (void)frexp(fmax(n1, n2), &e);
    *s1 = ldexp(n1, -e);
    *s2 = ldexp(n2, -e);
}

/*
 * k = (n1 c)^2 - (n1^2 - n2^2) = n2^2 cos^2(th2), from Snell:
 *   cos^2 th2 = 1 - (n1/n2)^2 (1 - c^2)   => multiply by n2^2.
 * k < 0 is total internal reflection.  Near the critical angle k is the
 * difference of two nearly equal numbers, so each product is split exactly
 * (two_prod) and the three heads summed exactly (two_sum); only the small
 * tails are rounded: absolute error about 2^-104 * max(n1, n2)^2, against
 * 2^-52 for the textbook 1 - eta^2 (1 - c^2).  This makes the sign exact
 * for every c a whole ulp away from the critical cosine.
 */
static real refract_discriminant(real n1, real n2, real c, real c_lo)
{
    real e_p, e_pp, e_a, e_b, e_1, e_2;
    real p = two_prod(n1, c, &e_p);      /* n1 c  = p + e_p */
    e_p += n1 * c_lo;                    /* n1 (c + c_lo) = p + e_p, to 2^-104 */
    real pp = two_prod(p, p, &e_pp);     /* p^2   = pp + e_pp */
    real a = two_prod(n1, n1, &e_a);     /* n1^2  = a + e_a */
    real b = two_prod(n2, n2, &e_b);     /* n2^2  = b + e_b */
    real h = two_sum(pp, -a, &e_1);
    h = two_sum(h, b, &e_2);
    /* (p + e_p)^2 = p^2 + 2 p e_p + e_p^2 */
    real tail = e_pp + 2.0 * p * e_p + e_p * e_p - e_a + e_b + e_1 + e_2;
    return h + tail;
}

/*
 * cos th1 = -N.D as an unevaluated sum c + *lo, exact to about 2^-104:
 * near the critical angle cos th2 = sqrt(k)/n2 has the slope
 * n1^2 c / sqrt(k) in c, so the one rounding of a plain dot product
 * (2^-53) would be amplified without bound, and would flip the decision
 * for angles within about 1e-16 rad of the critical one (spec/numerics.md,
 * "Refraction").  Products split exactly by two_prod, summed by two_sum.
 * Clamped: a hair outside [0, 1] from rounding is grazing or normal
 * incidence, not an error.
 */
static real incidence_cos(vec3 d, vec3 n, real *lo)
{
    real e0, e1, e2, s0, s1;
    real p0 = two_prod(n.x, d.x, &e0), p1 = two_prod(n.y, d.y, &e1), p2 = two_prod(n.z, d.z, &e2);
    real h = two_sum(p0, p1, &s0);
    h = two_sum(h, p2, &s1);
    real c = -h, c_lo = -(e0 + e1 + e2 + s0 + s1);
    real sum = c + c_lo;
    *lo = 0;
    if (!(sum > 0.0))
        return 0.0;
    if (!(sum < 1.0))
        return 1.0;
    real hi = two_sum(c, c_lo, lo);   /* renormalised: |lo| <= ulp(hi)/2 */
    return hi;
}

/*
 * With c = cos th1, the part of d along the surface is d + c n (length
 * sin th1).  Snell keeps its direction and scales it by eta = n1/n2; the
 * part along -n has length cos th2 = sqrt(k)/n2 (see refract_discriminant):
 *   t = eta (d + c n) - cos th2 n.
 * Written this way the normal component of t is computed from k alone,
 * which stays accurate near the critical angle (cos th2 -> 0) and near
 * grazing incidence (sin th1 -> 1), where eta d + (eta c - cos th2) n
 * cancels.
 */
int shade_refract(vec3 d, vec3 n, real n1, real n2, vec3 *t)
{
    assert(n1 > 0.0 && n2 > 0.0 && isfinite(n1) && isfinite(n2));
    /* Equal indices: no boundary at all.  The general formula would return
     * d only up to rounding, and an index-matched interface (touching
     * glass, a medium left into the same medium) must not move a ray. */
    if (n1 == n2) {
        *t = d;
        return 1;
    }
    real s1, s2;
    scale_indices(n1, n2, &s1, &s2);
    real c_lo, c = incidence_cos(d, n, &c_lo);
    real k = refract_discriminant(s1, s2, c, c_lo);
    if (!(k >= 0.0)) {
        *t = shade_mirror(d, n);
        return 0;
    }
    real cos_t = fmin(sqrt(k) / s2, 1.0);
    vec3 along = vec_madd(d, n, c);
    *t = vec_normalize(vec_madd(vec_scale(along, n1 / n2), n, -cos_t));
    return 1;
}

/*
 * sqrt((n1 - n2)(n1 + n2)) / n1 is within a few ulps of the critical cosine
 * (each factor has one rounding; n1 - n2 is exact when n2 >= n1/2); the two
 * loops then step to the least value whose discriminant is >= 0, using the
 * same test as shade_refract, so the two agree to the bit.  The discriminant
 * increases with c, and the estimate is a few ulps off: the loops run a few
 * times.
 */
real shade_critical_angle_cos(real n1, real n2)
{
    assert(n1 > 0.0 && n2 > 0.0 && isfinite(n1) && isfinite(n2));
    if (n1 <= n2)
        return 0.0;
    real s1, s2;
    scale_indices(n1, n2, &s1, &s2);
    real c = fmin(sqrt((s1 - s2) * (s1 + s2)) / s1, 1.0);
    while (c < 1.0 && !(refract_discriminant(s1, s2, c, 0) >= 0.0))
        c = nextafter(c, 2.0);
    while (c > 0.0 && refract_discriminant(s1, s2, nextafter(c, 0.0), 0) >= 0.0)
        c = nextafter(c, 0.0);
    return c;
}

/* Two products rather than front + t (back - front): the endpoints are then
 * exact (1 * front + 0 * back, 0 * front + 1 * back). */
rgb shade_transmit_blend(rgb front, rgb back, real t)
{
    assert(t >= 0.0 && t <= 1.0);
    return vec_add(vec_scale(front, 1.0 - t), vec_scale(back, t));
}

/* Comparisons, not fmin: fmin(NaN, x) is x, and a NaN must stay visible. */
static real saturate1(real x) { return x > DBL_MAX ? DBL_MAX : x; }

rgb shade_saturate(rgb c)
{
    return vec_make(saturate1(c.x), saturate1(c.y), saturate1(c.z));
}

rgb shade_local(rgb body, rgb highlight, real t)
{
    assert(t >= 0.0 && t <= 1.0);
    return shade_saturate(vec_madd(highlight, body, 1.0 - t));
}

rgb shade_combine(rgb body, rgb highlight, rgb ks, real t, rgb mirrored, rgb transmitted)
{
    rgb c = shade_local(body, highlight, t);
    c = vec_add(c, vec_mul(ks, mirrored));
    return shade_saturate(vec_madd(c, transmitted, t));
}

real shade_shadow_transmission(real carried, real t_occluder)
{
    assert(carried >= 0.0 && carried <= 1.0);
    assert(t_occluder >= 0.0 && t_occluder <= 1.0);
    return carried * t_occluder;
}
