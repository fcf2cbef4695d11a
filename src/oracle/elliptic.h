/*
 * elliptic.h - elliptic integrals in Carlson's symmetric form, for the
 * solid angle of a disk seen off its axis (Paxton 1959).
 *
 * Carlson, "Numerical computation of real or complex elliptic integrals",
 * Numerical Algorithms 10 (1995); DLMF 19.16, 19.25, 19.36.  The duplication
 * theorem shrinks the arguments toward their mean by a factor 4 per step;
 * the remainder is a fifth-order series.  Relative error ~1e-16 for the
 * arguments used here (non-negative, at most one zero).
 */
#ifndef REFRAY_ELLIPTIC_H
#define REFRAY_ELLIPTIC_H

/* R_F(x, y, z), x, y, z >= 0, at most one of them 0. */
double elliptic_rf(double x, double y, double z);

/* R_D(x, y, z), x, y >= 0 not both 0, z > 0. */
double elliptic_rd(double x, double y, double z);

/* Complete integrals of the first and second kind, modulus k in [0, 1). */
double elliptic_k(double k);
double elliptic_e(double k);

/* Incomplete integrals F(phi, k), E(phi, k), 0 <= phi <= pi/2, k in [0, 1]. */
double elliptic_f_inc(double phi, double k);
double elliptic_e_inc(double phi, double k);

/* Heuman's Lambda_0(xi, k) = (2/pi)[E(k) F(xi,k') + K(k) E(xi,k') - K(k) F(xi,k')],
 * k' = sqrt(1 - k^2) (Byrd & Friedman 150.03). */
double elliptic_heuman_lambda(double xi, double k);

#endif
