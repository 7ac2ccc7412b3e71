/* an_vc.c: viscous criterion of the chest */
#include "analysis/an_criteria.h"

#include <math.h>

/* Hybrid III 50th: scale 1.3, chest depth 0.229 m (REFERENCES.md; limit 1.0 m/s unverified) */
an_vc_opts an_vc_opts_hybrid3_50m(void)
{
    return (an_vc_opts){.scale = 1.3, .depth = 0.229};
}

mcs_status an_vc(const double *t, const double *d, int n, const an_vc_opts *o, double *vc,
                 double *time, double *vc_out, mcs_error *err)
{
    *vc = 0, *time = n > 0 ? t[0] : 0;
    if (n < 5) return MCS_ERR(err, MCS_ERR_RANGE, "VC: %d samples, need at least 5", n);
    if (!(o->depth > 0)) return MCS_ERR(err, MCS_ERR_RANGE, "VC: chest depth must be > 0");
    double dt = (t[n - 1] - t[0]) / (n - 1);
    for (int i = 0; i < n; i++)
        /* 1e-6 of a step: the difference formula assumes a constant step */
        if (!(fabs(t[i] - (t[0] + i * dt)) <= 1e-6 * dt))
            return MCS_ERR(err, MCS_ERR_RANGE, "VC: needs uniform sampling (sample %d at %g s)",
                           i, t[i]);
    int first = 1;
    for (int i = 0; i < n; i++) {
        if (i < 2 || i > n - 3) {
            if (vc_out) vc_out[i] = 0;
            continue;
        }
        /* 4th-order central difference, exact for polynomials up to degree 4 */
        double v = (8.0 * (d[i + 1] - d[i - 1]) - (d[i + 2] - d[i - 2])) / (12.0 * dt);
        double x = o->scale * v * d[i] / o->depth;
        if (vc_out) vc_out[i] = x;
        if (first || x > *vc) *vc = x, *time = t[i], first = 0;
    }
    return MCS_OK;
}
