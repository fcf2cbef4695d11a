# Gappa (make prove, spec/proofs.md "Rounding bounds"): the rounding error
# of refract_discriminant (src/render/shade.c), the compensated
#   k = n1^2 (c + c_lo)^2 - n1^2 + n2^2
# of shade_refract, before its last rounding.  Inputs as the code gets them:
# n1, n2 scaled by scale_indices into [0, 1]; c, c_lo the unevaluated sum of
# incidence_cos, c in [0, 1], |c_lo| <= half an ulp of 1.
# Assumed, not proved here (classical theorems, each an identity of real
# numbers, stated as one below): the remainder fma(x, y, -rnd(x y)) of
# two_prod is the exact x y - rnd(x y) (it is a double; Boldo, Muller), and
# two_sum's error term is the exact a + b - rnd(a + b) (Knuth, TAOCP 4.2.2).
@rnd = float<ieee_64, ne>;

n1 = rnd(N1);
n2 = rnd(N2);
c = rnd(C);
clo = rnd(CLO);

p = rnd(n1 * c);
ep0 = n1 * c - p;                 # two_prod(n1, c): exact remainder
ep = rnd(ep0 + rnd(n1 * clo));    # e_p += n1 * c_lo
pp = rnd(p * p);
epp = p * p - pp;
a = rnd(n1 * n1);
ea = n1 * n1 - a;
b = rnd(n2 * n2);
eb = n2 * n2 - b;
h1 = rnd(pp - a);
e1 = pp - a - h1;                 # two_sum: exact error
h2 = rnd(h1 + b);
e2 = h1 + b - h2;
# e_pp + 2.0 * p * e_p + e_p * e_p - e_a + e_b + e_1 + e_2, left to right
tail = rnd(rnd(rnd(rnd(rnd(rnd(epp + rnd(rnd(2 * p) * ep)) + rnd(ep * ep)) - ea) + eb) + e1) + e2);

# The same sum of the exact terms, and k itself.
EP = ep0 + n1 * clo;
T = epp + 2 * p * EP + EP * EP - ea + eb + e1 + e2;
K = n1 * n1 * (c + clo) * (c + clo) - n1 * n1 + n2 * n2;

# k = rnd(h2 + tail): one more rounding, relative, which keeps the sign.
{ n1 in [0, 1] /\ n2 in [0, 1] /\ c in [0, 1] /\ clo in [-1b-53, 1b-53]
  -> h2 + tail - K in [-1b-101, 1b-101] }

K -> h2 + T;
h2 + tail - K -> tail - T;
