/* an_resample.c: linear resampling of two channels onto their common uniform grid */
#include "analysis/an_resample.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void an_pair_free(an_pair *p)
{
    if (!p) return;
    free(p->ref);
    free(p->cmp);
    memset(p, 0, sizeof *p);
}

mcs_status an_samples_check(const double *t, const double *y, int n, const char *what,
                            mcs_error *err)
{
    if (!t || !y || n < 2)
        return MCS_ERR(err, MCS_ERR_RANGE, "%s: needs at least 2 samples, has %d", what,
                       t && y ? n : 0);
    for (int i = 0; i < n; i++) {
        if (!isfinite(t[i]) || !isfinite(y[i]))
            return MCS_ERR(err, MCS_ERR_RANGE, "%s: sample %d is not a finite number", what,
                           i + 1);
        if (i > 0 && !(t[i] > t[i - 1]))
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "%s: time is not strictly increasing at sample %d (%.9g s after "
                           "%.9g s)",
                           what, i + 1, t[i], t[i - 1]);
    }
    return MCS_OK;
}

/* index k with t[k] <= tq < t[k+1], clamped to [0, n-2] (binary search) */
static int bracket(const double *t, int n, double tq)
{
    int lo = 0, hi = n - 1;
    while (hi - lo > 1) {
        int mid = lo + (hi - lo) / 2;
        if (t[mid] <= tq)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

double an_interp_linear(const double *t, const double *y, int n, double tq)
{
    if (n == 1 || tq <= t[0]) return y[0];
    if (tq >= t[n - 1]) return y[n - 1];
    int k = bracket(t, n, tq);
    double w = (tq - t[k]) / (t[k + 1] - t[k]);
    return y[k] + w * (y[k + 1] - y[k]);
}

/* out[j] = interpolant at t0 + j*dt, j < m; a sweeping index keeps it O(n + m) */
static void resample_onto(const double *t, const double *y, int n, double t0, double dt, int m,
                          double *out)
{
    int k = 0;
    for (int j = 0; j < m; j++) {
        double tq = t0 + j * dt;
        while (k < n - 2 && t[k + 1] <= tq) k++;
        if (tq <= t[0])
            out[j] = y[0];
        else if (tq >= t[n - 1])
            out[j] = y[n - 1];
        else
            out[j] = y[k] + (tq - t[k]) / (t[k + 1] - t[k]) * (y[k + 1] - y[k]);
    }
}

mcs_status an_resample_pair(const double *t1, const double *y1, int n1, const double *t2,
                            const double *y2, int n2, double rate, int min_samples, an_pair *out,
                            mcs_error *err)
{
    memset(out, 0, sizeof *out);
    if (!(rate > 0) || !isfinite(rate))
        return MCS_ERR(err, MCS_ERR_RANGE, "resampling rate must be > 0 Hz, got %g", rate);
    mcs_status st = an_samples_check(t1, y1, n1, "reference", err);
    if (st) return st;
    st = an_samples_check(t2, y2, n2, "comparison", err);
    if (st) return st;

    double ta = fmax(t1[0], t2[0]), tb = fmin(t1[n1 - 1], t2[n2 - 1]);
    double dt = 1.0 / rate;
    /* the last grid point may sit on tb up to rounding: allow 1e-9 of a step */
    double span = (tb - ta) / dt;
    long m = tb > ta ? (long)floor(span + 1e-9) + 1 : (tb == ta ? 1 : 0);
    if (m < (long)(min_samples < 2 ? 2 : min_samples)) {
        if (tb < ta)
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "the channels do not overlap in time: reference %.6g..%.6g s, "
                           "comparison %.6g..%.6g s",
                           t1[0], t1[n1 - 1], t2[0], t2[n2 - 1]);
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "common time span %.6g..%.6g s gives only %ld samples at %g Hz "
                       "(need %d)",
                       ta, tb, m, rate, min_samples < 2 ? 2 : min_samples);
    }
    if (m > 100000000L)
        return MCS_ERR(err, MCS_ERR_RANGE, "common span %.6g s at %g Hz is %ld samples: too many",
                       tb - ta, rate, m);

    out->ref = malloc((size_t)m * sizeof(double));
    out->cmp = malloc((size_t)m * sizeof(double));
    if (!out->ref || !out->cmp) {
        an_pair_free(out);
        return MCS_ERR(err, MCS_ERR_NOMEM, "resampling: %ld samples", m);
    }
    out->n = (int)m;
    out->t0 = ta;
    out->dt = dt;
    resample_onto(t1, y1, n1, ta, dt, out->n, out->ref);
    resample_onto(t2, y2, n2, ta, dt, out->n, out->cmp);
    return MCS_OK;
}
