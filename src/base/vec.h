/*
 * vec.h - 3-vectors of the tracer's floating type `real`, used for points,
 * directions and RGB colours alike.  Everything here is a pure static
 * inline function so that the hot paths of the tracer inline it; nothing
 * here allocates or touches global state.
 *
 * Colours reuse vec3 with x,y,z read as r,g,b (see rgb below) because the
 * shading formulas are the same channel-wise products and sums.
 *
 * `real` is double.  Built with -DREFRAY_LONG_DOUBLE (make LONG_DOUBLE=1,
 * spec/numerics.md "The stability tool") it is long double, so the same
 * source computes the same picture with a 64-bit significand, and
 * `refray stability` compares the two.  <tgmath.h> makes sqrt, fabs, pow,
 * fma, nextafter, ... follow the type of their arguments; a literal such as
 * 0.5 is a double and is promoted exactly.  Constants that must carry more
 * digits than a double in the long double build are written REAL_C(...).
 */
#ifndef REFRAY_VEC_H
#define REFRAY_VEC_H

#include <float.h>
#include <tgmath.h>

#ifdef REFRAY_LONG_DOUBLE
typedef long double real;
#define REAL_C(x) x##L
#define REAL_EPSILON LDBL_EPSILON
#define REAL_MIN LDBL_MIN
#define REAL_MAX LDBL_MAX
#define REAL_MANT_DIG LDBL_MANT_DIG
#else
typedef double real;
#define REAL_C(x) x
#define REAL_EPSILON DBL_EPSILON
#define REAL_MIN DBL_MIN
#define REAL_MAX DBL_MAX
#define REAL_MANT_DIG DBL_MANT_DIG
#endif

/* pi to more digits than any real holds. */
#define REAL_PI REAL_C(3.14159265358979323846264338327950288)

typedef struct vec3 {
    real x, y, z;
} vec3;

/* An RGB triple of linear radiometric values; x=r, y=g, z=b. */
typedef vec3 rgb;

static inline vec3 vec_make(real x, real y, real z)
{
    vec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

static inline vec3 vec_splat(real s) { return vec_make(s, s, s); }
static inline vec3 vec_add(vec3 a, vec3 b) { return vec_make(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec3 vec_sub(vec3 a, vec3 b) { return vec_make(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec3 vec_neg(vec3 a) { return vec_make(-a.x, -a.y, -a.z); }
static inline vec3 vec_scale(vec3 a, real s) { return vec_make(a.x * s, a.y * s, a.z * s); }

/* Channel-wise product: a colour filtered by a coefficient. */
static inline vec3 vec_mul(vec3 a, vec3 b) { return vec_make(a.x * b.x, a.y * b.y, a.z * b.z); }

/* a + b*s, the accumulation step of every shading sum. */
static inline vec3 vec_madd(vec3 a, vec3 b, real s)
{
    return vec_make(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s);
}

static inline real vec_dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

static inline vec3 vec_cross(vec3 a, vec3 b)
{
    return vec_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

static inline real vec_length2(vec3 a) { return vec_dot(a, a); }

/* hypot-style length: no overflow for components near DBL_MAX/2 and no
 * underflow to 0 for denormal components, which plain sqrt(dot) suffers. */
static inline real vec_length(vec3 a)
{
    real m = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
    if (m == 0 || !isfinite(m))
        return m;
    /* Divide rather than multiply by 1/m: 1/m overflows for denormal m. */
    a = vec_make(a.x / m, a.y / m, a.z / m);
    return m * sqrt(vec_dot(a, a));
}

/* |a| as sqrt(a.a) when a.a neither overflowed nor lost precision to
 * underflow (one square root, no divisions), else vec_length's scaled form;
 * the two may differ in the last bit. */
static inline real vec_length_fast(vec3 a)
{
    real d = vec_dot(a, a);
    return d >= REAL_MIN && d <= REAL_MAX ? sqrt(d) : vec_length(a);
}

/* Unit vector along a; returns the zero vector for a zero input so that a
 * caller that validated its input never sees NaN from here. */
static inline vec3 vec_normalize(vec3 a)
{
    real len = vec_length(a);
    return len > 0 ? vec_make(a.x / len, a.y / len, a.z / len) : vec_make(0, 0, 0);
}

static inline real vec_max_component(vec3 a) { return fmax(a.x, fmax(a.y, a.z)); }
static inline real vec_min_component(vec3 a) { return fmin(a.x, fmin(a.y, a.z)); }

static inline vec3 vec_min(vec3 a, vec3 b) { return vec_make(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z)); }
static inline vec3 vec_max(vec3 a, vec3 b) { return vec_make(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z)); }

static inline int vec_is_finite(vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }

static inline real vec_component(vec3 a, int axis) { return axis == 0 ? a.x : axis == 1 ? a.y : a.z; }

#endif
