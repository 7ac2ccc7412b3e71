/* an_spline.c: natural cubic spline (tridiagonal system for the knot second derivatives) */
#include "analysis/an_spline.h"

#include <stdlib.h>
#include <string.h>

void an_spline_free(an_spline *s)
{
    if (!s) return;
    free(s->x), free(s->y), free(s->m);
    memset(s, 0, sizeof *s);
}

mcs_status an_spline_natural(const double *x, const double *y, int n, an_spline *s,
                             mcs_error *err)
{
    memset(s, 0, sizeof *s);
    if (n < 2) return MCS_ERR(err, MCS_ERR_RANGE, "spline: %d points, need at least 2", n);
    for (int i = 1; i < n; i++)
        if (!(x[i] > x[i - 1]))
            return MCS_ERR(err, MCS_ERR_RANGE, "spline: abscissa %d (%g) not after %g", i, x[i],
                           x[i - 1]);
    s->x = malloc((size_t)n * sizeof(double));
    s->y = malloc((size_t)n * sizeof(double));
    s->m = calloc((size_t)n, sizeof(double));
    double *c = malloc((size_t)n * sizeof(double)); /* eliminated super-diagonal */
    if (!s->x || !s->y || !s->m || !c) {
        free(c);
        an_spline_free(s);
        return MCS_ERR(err, MCS_ERR_NOMEM, "spline: out of memory (%d points)", n);
    }
    memcpy(s->x, x, (size_t)n * sizeof(double));
    memcpy(s->y, y, (size_t)n * sizeof(double));
    s->n = n;
    /* continuity of y' at interior knots:
     * h0 M[i-1] + 2(h0 + h1) M[i] + h1 M[i+1] = 6((y[i+1]-y[i])/h1 - (y[i]-y[i-1])/h0),
     * M[0] = M[n-1] = 0; Thomas algorithm (diagonally dominant, no pivoting needed) */
    c[0] = 0;
    for (int i = 1; i < n - 1; i++) {
        double h0 = x[i] - x[i - 1], h1 = x[i + 1] - x[i];
        double rhs = 6.0 * ((y[i + 1] - y[i]) / h1 - (y[i] - y[i - 1]) / h0);
        double diag = 2.0 * (h0 + h1) - h0 * c[i - 1];
        c[i] = h1 / diag;
        s->m[i] = (rhs - h0 * s->m[i - 1]) / diag;
    }
    for (int i = n - 3; i >= 1; i--) s->m[i] -= c[i] * s->m[i + 1];
    free(c);
    return MCS_OK;
}

/* interval k with x[k] <= v < x[k+1] (end intervals outside), by bisection */
static int find(const an_spline *s, double v)
{
    int lo = 0, hi = s->n - 1;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (s->x[mid] <= v) lo = mid;
        else hi = mid;
    }
    return lo;
}

/* on [x_k, x_k+1] with A = (x_k+1 - v)/h, B = 1 - A:
 * S = A y_k + B y_k+1 + ((A^3 - A) M_k + (B^3 - B) M_k+1) h^2 / 6 */
double an_spline_eval(const an_spline *s, double v)
{
    int k = find(s, v);
    double h = s->x[k + 1] - s->x[k], A = (s->x[k + 1] - v) / h, B = 1.0 - A;
    return A * s->y[k] + B * s->y[k + 1] +
           ((A * A * A - A) * s->m[k] + (B * B * B - B) * s->m[k + 1]) * h * h / 6.0;
}

double an_spline_deriv(const an_spline *s, double v)
{
    int k = find(s, v);
    double h = s->x[k + 1] - s->x[k], A = (s->x[k + 1] - v) / h, B = 1.0 - A;
    return (s->y[k + 1] - s->y[k]) / h -
           (3.0 * A * A - 1.0) / 6.0 * h * s->m[k] + (3.0 * B * B - 1.0) / 6.0 * h * s->m[k + 1];
}

double an_spline_deriv2(const an_spline *s, double v)
{
    int k = find(s, v);
    double h = s->x[k + 1] - s->x[k], A = (s->x[k + 1] - v) / h, B = 1.0 - A;
    return A * s->m[k] + B * s->m[k + 1];
}
