/* Roots by isolation: between two consecutive roots of the derivative a
 * polynomial is monotonic, so it crosses zero at most once there, and a
 * sign change brackets that crossing for bisection. */
#include "polynomial.h"

#include <math.h>

static double evaluate(const double *c, int n, double x)
{
    double v = c[0];
    for (int i = 1; i <= n; i++)
        v = v * x + c[i];
    return v;
}

/* The one root of the monotonic polynomial in [a, b], where its values
 * fa, fb there differ in sign: bisected until the interval cannot shrink. */
static double bisect(const double *c, int n, double a, double b, double fa)
{
    for (int i = 0; i < 2200; i++) {
        double m = 0.5 * (a + b);
        if (m <= a || m >= b)
            break;
        double fm = evaluate(c, n, m);
        if (fm == 0.0)
            return m;
        if ((fm < 0.0) == (fa < 0.0)) {
            a = m;
            fa = fm;
        } else {
            b = m;
        }
    }
    return 0.5 * (a + b);
}

int polynomial_roots(const double *c, int n, double lo, double hi, double *roots)
{
    if (n <= 0 || !(lo <= hi))
        return 0;
    if (n == 1) {
        double x = -c[1] / c[0];
        if (x >= lo && x <= hi) {
            roots[0] = x;
            return 1;
        }
        return 0;
    }
    /* the derivative's roots split [lo, hi] into monotonic pieces */
    double d[POLYNOMIAL_MAX_DEGREE];
    for (int i = 0; i < n; i++)
        d[i] = c[i] * (double)(n - i);
    double split[POLYNOMIAL_MAX_DEGREE + 1];
    int ns = polynomial_roots(d, n - 1, lo, hi, split + 1);
    split[0] = lo;
    double ends[POLYNOMIAL_MAX_DEGREE + 2];
    for (int i = 0; i <= ns; i++)
        ends[i] = split[i];
    ends[ns + 1] = hi;
    int count = 0;
    double fa = evaluate(c, n, ends[0]);
    for (int k = 0; k <= ns; k++) {
        double a = ends[k], b = ends[k + 1];
        double fb = evaluate(c, n, b);
        if (fa == 0.0) {
            if (count == 0 || roots[count - 1] != a)
                roots[count++] = a;
        } else if (fb != 0.0 && (fa < 0.0) != (fb < 0.0)) {
            roots[count++] = bisect(c, n, a, b, fa);
        }
        if (fb == 0.0 && k == ns && (count == 0 || roots[count - 1] != b))
            roots[count++] = b;
        fa = fb;
    }
    return count;
}
