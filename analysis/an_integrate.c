/* an_integrate.c: cumulative trapezoid integration */
#include "analysis/an_integrate.h"

void an_integrate_trapz(const double *t, const double *f, int n, double y0, double *out)
{
    if (n < 1) return;
    out[0] = y0;
    for (int i = 1; i < n; i++) out[i] = out[i - 1] + 0.5 * (f[i] + f[i - 1]) * (t[i] - t[i - 1]);
}

mcs_status an_integrate_accel(const double *t, const double *a, int n, double v0, double x0,
                              double *v, double *x, mcs_error *err)
{
    if (n < 2) return MCS_ERR(err, MCS_ERR_RANGE, "integration: %d samples, need 2", n);
    for (int i = 1; i < n; i++)
        if (!(t[i] > t[i - 1]))
            return MCS_ERR(err, MCS_ERR_RANGE, "integration: time %d (%g s) not after %g s", i,
                           t[i], t[i - 1]);
    an_integrate_trapz(t, a, n, v0, v);
    an_integrate_trapz(t, v, n, x0, x);
    return MCS_OK;
}
