/* an_nij.c: neck injury criterion Nij (four modes) and upper-neck load peaks */
#include "analysis/an_criteria.h"

#include <math.h>

/* FMVSS 208 S6.6 / REFERENCES.md: Hybrid III 50th male in-position intercepts */
an_nij_opts an_nij_opts_hybrid3_50m(void)
{
    return (an_nij_opts){.fz_tension = 6806, .fz_compression = 6160, .my_flexion = 310,
                         .my_extension = 135, .condyle_offset = 0.01778};
}

/* Hybrid III 5th female in-position intercepts (REFERENCES.md) */
an_nij_opts an_nij_opts_hybrid3_05f(void)
{
    return (an_nij_opts){.fz_tension = 4287, .fz_compression = 3880, .my_flexion = 155,
                         .my_extension = 67, .condyle_offset = 0.01778};
}

/* Hybrid III 95th male in-position intercepts: UNVERIFIED (Eppinger et al., NHTSA 1999/2000,
 * "Development of improved injury criteria ... II", as commonly cited; the primary table was not
 * retrieved). They are the 50th's scaled by Mertz's lambda^2 (forces) and lambda^3 (moments)
 * with lambda = 1.099 to 0.3 % (tests/test_rider_sizes.c) */
an_nij_opts an_nij_opts_hybrid3_95m(void)
{
    return (an_nij_opts){.fz_tension = 8216, .fz_compression = 7440, .my_flexion = 415,
                         .my_extension = 179, .condyle_offset = 0.01778};
}

an_nij_opts an_nij_opts_dummy(an_dummy d)
{
    if (d == AN_DUMMY_H3_05F) return an_nij_opts_hybrid3_05f();
    if (d == AN_DUMMY_H3_95M) return an_nij_opts_hybrid3_95m();
    return an_nij_opts_hybrid3_50m();
}

const char *an_nij_mode_name(an_nij_mode m)
{
    static const char *const names[] = {"TF", "TE", "CF", "CE"};
    return m >= 0 && m < AN_NIJ_NMODES ? names[m] : "?";
}

mcs_status an_nij(const double *t, const double *fx, const double *fz, const double *my, int n,
                  const an_nij_opts *o, an_nij_result *r, mcs_error *err)
{
    *r = (an_nij_result){0};
    if (n < 1) return MCS_ERR(err, MCS_ERR_RANGE, "Nij: no samples");
    if (!(o->fz_tension > 0 && o->fz_compression > 0 && o->my_flexion > 0 && o->my_extension > 0))
        return MCS_ERR(err, MCS_ERR_RANGE, "Nij: intercepts must be positive");
    r->time = t[0];
    for (int m = 0; m < AN_NIJ_NMODES; m++) r->mode_time[m] = t[0];
    for (int i = 0; i < n; i++) {
        /* moment about the occipital condyle */
        double moc = my[i] - o->condyle_offset * fx[i];
        int tension = fz[i] >= 0, flexion = moc >= 0;
        an_nij_mode m = tension ? (flexion ? AN_NIJ_TF : AN_NIJ_TE)
                                : (flexion ? AN_NIJ_CF : AN_NIJ_CE);
        double v = fabs(fz[i]) / (tension ? o->fz_tension : o->fz_compression) +
                   fabs(moc) / (flexion ? o->my_flexion : o->my_extension);
        if (v > r->mode_max[m]) r->mode_max[m] = v, r->mode_time[m] = t[i];
        if (v > r->nij) r->nij = v, r->mode = m, r->time = t[i];
    }
    return MCS_OK;
}

mcs_status an_neck_peaks_compute(const double *fx, const double *fz, const double *my, int n,
                                 double condyle_offset, an_neck_peaks *p, mcs_error *err)
{
    *p = (an_neck_peaks){0};
    if (n < 1) return MCS_ERR(err, MCS_ERR_RANGE, "neck peaks: no samples");
    p->fx_max = p->fx_min = fx[0];
    for (int i = 0; i < n; i++) {
        double moc = my[i] - condyle_offset * fx[i];
        p->fx_max = fmax(p->fx_max, fx[i]);
        p->fx_min = fmin(p->fx_min, fx[i]);
        p->fz_tension = fmax(p->fz_tension, fz[i]);
        p->fz_compression = fmax(p->fz_compression, -fz[i]);
        p->my_flexion = fmax(p->my_flexion, moc);
        p->my_extension = fmax(p->my_extension, -moc);
    }
    return MCS_OK;
}
