/* Real roots of polynomials of low degree, for the shapes whose surfaces
 * are polynomials along a ray (the torus's quartic). */
#ifndef HST_POLYNOMIAL_H
#define HST_POLYNOMIAL_H

#define POLYNOMIAL_MAX_DEGREE 4

/* The real roots in [lo, hi] of c[0] x^n + c[1] x^(n-1) + ... + c[n]
 * (n <= POLYNOMIAL_MAX_DEGREE, c[0] != 0), ascending, each found to the
 * last bit by bisection between the roots of the derivative (so a root
 * is never lost to cancellation, as a closed formula's can be); a double
 * root, where the polynomial touches zero without crossing it, is found
 * only where rounding makes it cross. Returns how many. */
int polynomial_roots(const double *c, int n, double lo, double hi, double *roots);

#endif
