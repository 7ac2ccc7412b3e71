/* an_ti.c: tibia index */
#include "analysis/an_criteria.h"

#include <math.h>

/* Hybrid III 50th critical values (REFERENCES.md): 225 N*m, 35.9 kN */
an_ti_opts an_ti_opts_hybrid3_50m(void)
{
    return (an_ti_opts){.mc = 225.0, .fc = 35900.0};
}

mcs_status an_tibia_index(const double *t, const double *mx, const double *my, const double *fz,
                          int n, const an_ti_opts *o, double *ti, double *time, mcs_error *err)
{
    *ti = 0, *time = n > 0 ? t[0] : 0;
    if (n < 1) return MCS_ERR(err, MCS_ERR_RANGE, "tibia index: no samples");
    if (!(o->mc > 0 && o->fc > 0))
        return MCS_ERR(err, MCS_ERR_RANGE, "tibia index: critical values must be > 0");
    for (int i = 0; i < n; i++) {
        double mr = hypot(mx[i], my[i]);
        double v = fabs(mr / o->mc) + fabs(fz[i] / o->fc);
        if (v > *ti) *ti = v, *time = t[i];
    }
    return MCS_OK;
}
