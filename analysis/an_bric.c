/* an_bric.c: brain injury criterion from head angular velocity */
#include "analysis/an_criteria.h"

#include <math.h>

/* critical angular velocities (MPS-based BrIC, Takhounts et al. 2013 via REFERENCES.md) */
an_bric_opts an_bric_opts_default(void)
{
    return (an_bric_opts){.wc = {66.3, 53.8, 41.5}};
}

mcs_status an_bric(const double *wx, const double *wy, const double *wz, int n,
                   const an_bric_opts *o, double *bric, mcs_error *err)
{
    *bric = 0;
    if (n < 1) return MCS_ERR(err, MCS_ERR_RANGE, "BrIC: no samples");
    const double *w[3] = {wx, wy, wz};
    double s = 0;
    for (int k = 0; k < 3; k++) {
        if (!(o->wc[k] > 0)) return MCS_ERR(err, MCS_ERR_RANGE, "BrIC: critical values must be > 0");
        double m = 0;
        for (int i = 0; i < n; i++) m = fmax(m, fabs(w[k][i]));
        s += (m / o->wc[k]) * (m / o->wc[k]);
    }
    *bric = sqrt(s);
    return MCS_OK;
}
