/* an_a3ms.c: the level held for 3 ms (paper Eq. 8) and its cumulative variant */
#include "analysis/an_criteria.h"

#include <math.h>

/* time above level L of the piecewise-linear signal: the longest contiguous run (and where it
 * starts/ends) when contiguous, else the total */
static double time_above(const double *t, const double *a, int n, double L, int contiguous,
                         double *t1, double *t2)
{
    double best = 0, run = 0, total = 0, start = t[0];
    *t1 = *t2 = t[0];
    for (int i = 0; i + 1 < n; i++) {
        double h = t[i + 1] - t[i], a0 = a[i], a1 = a[i + 1];
        int in0 = a0 >= L, in1 = a1 >= L;
        if (in0 && in1) {
            if (run == 0) start = t[i];
            run += h, total += h;
        } else if (in0) { /* leaves the set inside this segment */
            double f = (a0 - L) / (a0 - a1);
            if (run == 0) start = t[i];
            run += f * h, total += f * h;
            if (run > best) best = run, *t1 = start, *t2 = start + run;
            run = 0;
        } else if (in1) { /* enters */
            double f = (a1 - L) / (a1 - a0);
            run = f * h, total += f * h;
            start = t[i + 1] - run;
        } else {
            run = 0;
        }
        if (run > best) best = run, *t1 = start, *t2 = start + run;
    }
    return contiguous ? best : total;
}

/* largest L with time_above(L) >= dur, by bisection on [min a, max a]: time_above is
 * non-increasing in L, so the sup is bracketed; 200 halvings or 1e-12 of the range */
static mcs_status level_held(const double *t, const double *a, int n, double dur, int contiguous,
                             an_a3ms_result *r, mcs_error *err)
{
    r->level = 0, r->t1 = r->t2 = n > 0 ? t[0] : 0;
    if (n < 2) return MCS_ERR(err, MCS_ERR_RANGE, "a3ms: %d samples, need at least 2", n);
    if (!(dur > 0)) return MCS_ERR(err, MCS_ERR_RANGE, "a3ms: duration %g s must be > 0", dur);
    if (t[n - 1] - t[0] < dur)
        return MCS_ERR(err, MCS_ERR_RANGE, "a3ms: the signal lasts %g s, shorter than %g s",
                       t[n - 1] - t[0], dur);
    double lo = a[0], hi = a[0], t1, t2;
    for (int i = 1; i < n; i++) lo = fmin(lo, a[i]), hi = fmax(hi, a[i]);
    double tol = 1e-12 * fmax(hi - lo, fabs(hi));
    if (time_above(t, a, n, hi, contiguous, &t1, &t2) >= dur * (1 - 1e-12)) {
        lo = hi; /* held at the maximum itself (a plateau of at least dur) */
    } else {
        for (int k = 0; k < 200 && hi - lo > tol; k++) {
            double mid = 0.5 * (lo + hi);
            if (time_above(t, a, n, mid, contiguous, &t1, &t2) >= dur) lo = mid;
            else hi = mid;
        }
    }
    r->level = lo;
    time_above(t, a, n, lo, contiguous, &r->t1, &r->t2);
    return MCS_OK;
}

mcs_status an_a3ms(const double *t, const double *a, int n, double dur, an_a3ms_result *r,
                   mcs_error *err)
{
    return level_held(t, a, n, dur, 1, r, err);
}

mcs_status an_a3ms_cumulative(const double *t, const double *a, int n, double dur,
                              an_a3ms_result *r, mcs_error *err)
{
    return level_held(t, a, n, dur, 0, r, err);
}
